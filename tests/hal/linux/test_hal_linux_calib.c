/* SPDX-License-Identifier: MIT */
/*
 * hal/linux's calibration file and reset reason (hal_linux_calib.c) on the
 * build host: round trip, erased-flash padding, a stale temporary file,
 * empty and oversized files, an unwritable place (SQ_EIO, the error text
 * and the CALIB_STORAGE fault), the reset reason's default.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "hal_linux.h"

static char tmpdir[64];
static char calib_file[128];

static int calib_setup(void **state)
{
	(void)state;
	(void)snprintf(tmpdir, sizeof(tmpdir), "/tmp/sq-calib.XXXXXX");
	if (mkdtemp(tmpdir) == NULL) {
		return -1;
	}
	(void)snprintf(calib_file, sizeof(calib_file), "%s/calib.bin", tmpdir);
	return hal_linux_set_calib_path(calib_file) == SQ_OK ? 0 : -1;
}

static int calib_teardown(void **state)
{
	char cmd[128];

	(void)state;
	(void)snprintf(cmd, sizeof(cmd), "rm -rf '%s'", tmpdir);
	return system(cmd) == 0 ? 0 : -1;
}

static void write_raw(const char *path, const uint8_t *buf, size_t len)
{
	FILE *f = fopen(path, "wb");

	assert_non_null(f);
	assert_int_equal(fwrite(buf, 1U, len, f), len);
	assert_int_equal(fclose(f), 0);
}

static long file_size(const char *path)
{
	struct stat st;

	if (stat(path, &st) != 0) {
		return -1;
	}
	return (long)st.st_size;
}

static void test_calib_file_roundtrip_and_errors(void **state)
{
	uint8_t a[100];
	uint8_t b[100];
	uint8_t big[HAL_CALIB_MAX_LEN + 50U];
	uint8_t rd[120];
	char stale[160];
	size_t i;

	(void)state;
	for (i = 0; i < sizeof(a); i++) {
		a[i] = (uint8_t)(i * 7U + 1U);
		b[i] = (uint8_t)(255U - i);
	}
	assert_int_equal(hal_calib_read(rd, 100U), SQ_ENOENT);
	assert_int_equal(hal_calib_read(NULL, 100U), SQ_EINVAL);
	assert_int_equal(hal_calib_read(rd, 0U), SQ_EINVAL);
	assert_int_equal(hal_calib_read(rd, HAL_CALIB_MAX_LEN + 1U), SQ_EINVAL);
	assert_int_equal(hal_calib_write(a, 0U), SQ_EINVAL);
	assert_int_equal(hal_calib_write(NULL, 10U), SQ_EINVAL);
	assert_int_equal(hal_calib_write(big, HAL_CALIB_MAX_LEN + 1U), SQ_EINVAL);

	assert_int_equal(hal_calib_write(a, sizeof(a)), SQ_OK);
	assert_int_equal(file_size(calib_file), 100);
	memset(rd, 0, sizeof(rd));
	assert_int_equal(hal_calib_read(rd, 100U), SQ_OK);
	assert_memory_equal(rd, a, 100U);
	/* Longer than stored: the rest reads as erased flash. */
	assert_int_equal(hal_calib_read(rd, 120U), SQ_OK);
	assert_memory_equal(rd, a, 100U);
	for (i = 100; i < 120; i++) {
		assert_int_equal(rd[i], 0xFF);
	}

	/* An interrupted earlier write left its temporary file: ignored,
	 * then replaced. */
	(void)snprintf(stale, sizeof(stale), "%s.tmp.%ld", calib_file, (long)getpid());
	write_raw(stale, b, 10U);
	assert_int_equal(hal_calib_read(rd, 100U), SQ_OK);
	assert_memory_equal(rd, a, 100U);
	assert_int_equal(hal_calib_write(b, sizeof(b)), SQ_OK);
	assert_int_equal(hal_calib_read(rd, 100U), SQ_OK);
	assert_memory_equal(rd, b, 100U);
	assert_int_equal(file_size(stale), -1);

	/* Empty file: nothing stored. Too big: not a calibration block. */
	write_raw(calib_file, b, 0U);
	assert_int_equal(hal_calib_read(rd, 100U), SQ_ENOENT);
	memset(big, 0x5A, sizeof(big));
	write_raw(calib_file, big, sizeof(big));
	assert_int_equal(hal_calib_read(rd, 100U), SQ_EIO);
}

static void test_calib_unwritable_place_is_eio_and_a_fault(void **state)
{
	uint8_t a[16] = { 1, 2, 3 };
	char path[160];

	(void)state;
	(void)snprintf(path, sizeof(path), "%s/no/such/dir/calib.bin", tmpdir);
	assert_int_equal(hal_linux_set_calib_path(path), SQ_OK);
	assert_int_equal(hal_calib_write(a, sizeof(a)), SQ_EIO);
	assert_non_null(strstr(hal_linux_strerror(), "calibration file"));
	assert_true((hal_platform_faults() & HAL_FAULT_CALIB_STORAGE) != 0U);
	assert_int_equal(hal_calib_read(a, sizeof(a)), SQ_ENOENT);
	assert_int_equal(hal_linux_set_calib_path(NULL), SQ_OK);
	assert_int_equal(hal_calib_write(a, sizeof(a)), SQ_EIO);
	assert_int_equal(hal_calib_read(a, sizeof(a)), SQ_ENOENT);
	assert_int_equal(hal_linux_set_calib_path(calib_file), SQ_OK);
}

static void test_reset_reason_defaults_to_power_on(void **state)
{
	(void)state;
	assert_int_equal(hal_reset_reason(), HAL_RESET_POWER_ON);
	hal_linux_set_reset_reason(HAL_RESET_SOFTWARE);
	assert_int_equal(hal_reset_reason(), HAL_RESET_SOFTWARE);
	hal_linux_set_reset_reason(HAL_RESET_POWER_ON);
}


SQ_CMOCKA_MAIN(
	cmocka_unit_test(test_reset_reason_defaults_to_power_on),
	cmocka_unit_test_setup_teardown(test_calib_file_roundtrip_and_errors, calib_setup,
					calib_teardown),
	cmocka_unit_test_setup_teardown(test_calib_unwritable_place_is_eio_and_a_fault,
					calib_setup, calib_teardown))
