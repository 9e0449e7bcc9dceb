/* SPDX-License-Identifier: MIT */
/*
 * hal/linux's calibration write (hal_linux_calib.c) on storage that says a
 * write succeeded but keeps other bytes (a failing card, a full overlay
 * that truncates silently): the read-back after the rename must see the
 * difference and refuse the write (SQ_EIO, "read-back differs", the
 * CALIB_STORAGE fault), so the firmware never believes a block is stored
 * when the file holds something else. The link wraps write()
 * (-Wl,--wrap=write): while armed, the first byte of every write to the
 * calibration's temporary file reaches the file with its lowest bit flipped.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "hal_linux.h"

ssize_t __real_write(int fd, const void *buf, size_t n);
ssize_t __wrap_write(int fd, const void *buf, size_t n);

static bool corrupt_writes;
static unsigned int corrupted;

ssize_t __wrap_write(int fd, const void *buf, size_t n)
{
	uint8_t copy[HAL_CALIB_MAX_LEN];

	if (corrupt_writes && fd > 2 && n > 0U && n <= sizeof(copy)) {
		memcpy(copy, buf, n);
		copy[0] ^= 0x01U;
		corrupted++;
		return __real_write(fd, copy, n);
	}
	return __real_write(fd, buf, n);
}

static char tmpdir[64];
static char calib_file[128];

static int calib_setup(void **state)
{
	(void)state;
	(void)snprintf(tmpdir, sizeof(tmpdir), "/tmp/sq-calibv.XXXXXX");
	if (mkdtemp(tmpdir) == NULL) {
		return -1;
	}
	(void)snprintf(calib_file, sizeof(calib_file), "%s/calib.bin", tmpdir);
	corrupt_writes = false;
	corrupted = 0U;
	return hal_linux_set_calib_path(calib_file) == SQ_OK ? 0 : -1;
}

static int calib_teardown(void **state)
{
	char cmd[128];

	(void)state;
	corrupt_writes = false;
	(void)snprintf(cmd, sizeof(cmd), "rm -rf '%s'", tmpdir);
	return system(cmd) == 0 ? 0 : -1;
}

static void test_read_back_that_differs_is_eio_and_a_fault(void **state)
{
	uint8_t a[64];
	uint8_t rd[64];
	size_t i;

	(void)state;
	for (i = 0; i < sizeof(a); i++) {
		a[i] = (uint8_t)(0x40U + i);
	}
	/* faithful storage: stored and read back as written */
	assert_int_equal(hal_calib_write(a, sizeof(a)), SQ_OK);
	assert_int_equal(corrupted, 0U);
	assert_true((hal_platform_faults() & HAL_FAULT_CALIB_STORAGE) == 0U);

	corrupt_writes = true;
	a[0] = 0x10U;
	assert_int_equal(hal_calib_write(a, sizeof(a)), SQ_EIO);
	corrupt_writes = false;
	assert_int_equal(corrupted, 1U);
	assert_non_null(strstr(hal_linux_strerror(), "read-back differs from what was written"));
	assert_true((hal_platform_faults() & HAL_FAULT_CALIB_STORAGE) != 0U);
	/* what the file holds: the block with byte 0 = 0x10 ^ 0x01 */
	assert_int_equal(hal_calib_read(rd, sizeof(rd)), SQ_OK);
	assert_int_equal(rd[0], 0x11U);
	assert_memory_equal(&rd[1], &a[1], sizeof(a) - 1U);
}

SQ_CMOCKA_MAIN(cmocka_unit_test_setup_teardown(test_read_back_that_differs_is_eio_and_a_fault,
					       calib_setup, calib_teardown))
