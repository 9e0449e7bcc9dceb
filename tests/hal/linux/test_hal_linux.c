/* SPDX-License-Identifier: MIT */
/*
 * test_hal_linux_host: the parts of hal/linux that need no CAN bus, on the
 * build host itself: the "kernel without CAN" message (when this host's
 * kernel really has none), the closed-socket contract, the time base against
 * clock_gettime, idle, SIGTERM wake-up, the software watchdog, and the
 * calibration file. The CAN socket itself is tested on vcan in the guest
 * (selftest_hal_linux.c).
 */
#include <errno.h>
#include <fcntl.h>
#include <setjmp.h>
#include <signal.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <cmocka.h>

#include "hal_linux.h"

static int64_t ref_mono_us(void)
{
	struct timespec ts;

	assert_int_equal(clock_gettime(CLOCK_MONOTONIC, &ts), 0);
	return (int64_t)ts.tv_sec * 1000000 + ts.tv_nsec / 1000;
}

static void test_open_on_kernel_without_can_names_the_remedy(void **state)
{
	int fd;
	int rc;

	(void)state;
	fd = socket(PF_CAN, SOCK_RAW, 1 /* CAN_RAW */);
	if (fd >= 0 || errno != EAFNOSUPPORT) {
		if (fd >= 0) {
			(void)close(fd);
		}
		printf("# this host's kernel has CAN: the no-CAN message is not testable here\n");
		skip();
	}
	rc = hal_linux_open(0U, "vcan0", NULL);
	assert_int_equal(rc, SQ_ENOTSUP);
	assert_non_null(strstr(hal_linux_strerror(), "this kernel has no CAN support"));
	assert_non_null(strstr(hal_linux_strerror(), "modprobe can-raw / vcan"));
	assert_true((hal_platform_faults() & HAL_FAULT_CAN_INIT) != 0U);
}

static void test_closed_can_reports_stopped_and_checks_arguments(void **state)
{
	hal_can_frame_t f = { .id = 0x123U, .dlc = 1U };
	hal_can_status_t st;
	hal_can_filter_t flt[HAL_CAN_MAX_FILTERS + 1U] = {
		{ 0x100U, HAL_CAN_STD_ID_MAX, 0U }, { 0x101U, HAL_CAN_STD_ID_MAX, 0U }
	};

	(void)state;
	hal_linux_close();
	assert_int_equal(hal_linux_can_fd(0U), -1);
	assert_int_equal(hal_can_send(0U, &f), SQ_ENETDOWN);
	assert_int_equal(hal_can_receive(0U, &f), SQ_ENETDOWN);
	/* programming errors go to the contract handler, not to a return code */
	expect_assert_failure(hal_can_receive(0U, NULL));
	expect_assert_failure(hal_can_send(0U, NULL));
	expect_assert_failure(hal_can_get_status(0U, NULL));
	expect_assert_failure(hal_can_send(HAL_CAN_BUSES, &f));
	assert_int_equal(hal_can_get_status(0U, &st), SQ_OK);
	assert_int_equal(st.state, HAL_CAN_STATE_STOPPED);
	f.dlc = 9U;
	assert_int_equal(hal_can_send(0U, &f), SQ_EINVAL);
	f.dlc = 1U;
	f.id = 0x800U;
	assert_int_equal(hal_can_send(0U, &f), SQ_EINVAL);
	f.flags = HAL_CAN_FLAG_EXT;
	f.id = 0x20000000U;
	assert_int_equal(hal_can_send(0U, &f), SQ_EINVAL);
	expect_assert_failure(hal_can_set_rx_filter(0U, flt, HAL_CAN_MAX_FILTERS + 1U));
	expect_assert_failure(hal_can_set_rx_filter(0U, NULL, 1U));
	flt[1].id = 0x800U;
	assert_int_equal(hal_can_set_rx_filter(0U, flt, 2U), SQ_EINVAL);
	flt[1].id = 0x7FFU;
	/* Kept for the next open. */
	assert_int_equal(hal_can_set_rx_filter(0U, flt, 2U), SQ_OK);
	assert_int_equal(hal_linux_can_accept_all(0U), SQ_OK);
	assert_int_equal(hal_linux_open(0U, NULL, NULL), SQ_EINVAL);
	assert_int_equal(hal_linux_open(0U, "", NULL), SQ_EINVAL);
	assert_int_equal(hal_linux_open(0U, "a-name-longer-than-ifnamsiz", NULL), SQ_EINVAL);
}

static void test_time_is_clock_monotonic_in_us(void **state)
{
	int64_t ref = ref_mono_us();
	int64_t t = (int64_t)hal_time_us();
	uint32_t c0;
	uint32_t c1;
	int64_t m0;
	int64_t m1;
	int64_t cyc_us;

	(void)state;
	assert_true(t >= ref && t - ref < 1000);
	m0 = ref_mono_us();
	c0 = hal_cycles();
	(void)usleep(20000);
	c1 = hal_cycles();
	m1 = ref_mono_us();
	assert_int_equal(hal_cycles_per_us(), 1000U);
	cyc_us = (int64_t)((uint32_t)(c1 - c0) / hal_cycles_per_us());
	assert_true(cyc_us >= 20000 && cyc_us <= m1 - m0 + 1);
}

static void test_realtime_stamp_converts_to_monotonic_base(void **state)
{
	struct timespec real;
	uint64_t now;
	uint64_t conv;
	uint64_t past;

	(void)state;
	assert_int_equal(clock_gettime(CLOCK_REALTIME, &real), 0);
	now = hal_time_us();
	conv = hal_linux_realtime_to_mono_us(real.tv_sec, real.tv_nsec);
	assert_true(conv + 1000U > now && conv < now + 1000U);
	past = hal_linux_realtime_to_mono_us(real.tv_sec - 2, real.tv_nsec);
	assert_true(past + 2000000U + 1000U > now && past + 2000000U < now + 1000U);
}

static void test_idle_sleeps_to_the_deadline_without_can(void **state)
{
	uint64_t t0 = hal_time_us();
	uint64_t dt;

	(void)state;
	hal_idle_until(t0 + 30000U);
	dt = hal_time_us() - t0;
	assert_true(dt >= 30000U && dt < 130000U);
	t0 = hal_time_us();
	hal_idle_until(t0 - 1U);
	assert_true(hal_time_us() - t0 < 5000U);
}

static void test_sigterm_sets_stop_and_wakes_idle(void **state)
{
	static volatile bool stop;
	uint64_t t0;
	pid_t child;
	int status;

	(void)state;
	stop = false;
	assert_int_equal(hal_linux_install_signal_handlers(&stop), SQ_OK);
	assert_true(hal_linux_signal_fd() >= 0);
	child = fork();
	assert_true(child >= 0);
	if (child == 0) {
		(void)usleep(100000);
		(void)kill(getppid(), SIGTERM);
		_exit(0);
	}
	t0 = hal_time_us();
	hal_idle_until(t0 + 5000000U);
	assert_true(stop);
	assert_true(hal_time_us() - t0 < 2000000U);
	assert_int_equal(waitpid(child, &status, 0), child);

	/* A signal before the idle: returns at once. */
	stop = false;
	assert_int_equal(raise(SIGINT), 0);
	assert_true(stop);
	t0 = hal_time_us();
	hal_idle_until(t0 + 5000000U);
	assert_true(hal_time_us() - t0 < 100000U);
	signal(SIGINT, SIG_DFL);
	signal(SIGTERM, SIG_DFL);
}

static void test_watchdog_reports_a_missed_kick(void **state)
{
	uint64_t deadline;

	(void)state;
	assert_int_equal(hal_watchdog_start(0U), SQ_EINVAL);
	assert_int_equal(hal_watchdog_start(50U), SQ_OK);
	assert_false(hal_linux_watchdog_expired());
	(void)usleep(30000);
	hal_watchdog_kick();
	(void)usleep(30000);
	assert_false(hal_linux_watchdog_expired());
	deadline = hal_time_us() + 80000U;
	/* hal_idle_until may return early: idle until the deadline. */
	while (hal_time_us() < deadline) {
		hal_idle_until(deadline);
	}
	assert_true(hal_linux_watchdog_expired());
	assert_int_equal(hal_linux_watchdog_expiries(), 1U);
	/* Sticky, counted once. */
	assert_true(hal_linux_watchdog_expired());
	assert_int_equal(hal_linux_watchdog_expiries(), 1U);
}

static void test_watchdog_expiry_can_stop_the_loop(void **state)
{
	static volatile bool stop;
	uint64_t deadline;

	(void)state;
	stop = false;
	assert_int_equal(hal_linux_install_signal_handlers(&stop), SQ_OK);
	hal_linux_watchdog_stop_on_expiry(true);
	/* Restarting re-arms the sticky flag; the count goes on. */
	assert_int_equal(hal_watchdog_start(20U), SQ_OK);
	assert_false(hal_linux_watchdog_expired());
	deadline = hal_time_us() + 3000000U;
	while (!stop && hal_time_us() < deadline) {
		hal_idle_until(deadline);
	}
	assert_true(stop);
	assert_int_equal(hal_linux_watchdog_expiries(), 2U);
	hal_linux_watchdog_stop_on_expiry(false);
	signal(SIGINT, SIG_DFL);
	signal(SIGTERM, SIG_DFL);
}

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

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_reset_reason_defaults_to_power_on),
		cmocka_unit_test(test_open_on_kernel_without_can_names_the_remedy),
		cmocka_unit_test(test_closed_can_reports_stopped_and_checks_arguments),
		cmocka_unit_test(test_time_is_clock_monotonic_in_us),
		cmocka_unit_test(test_realtime_stamp_converts_to_monotonic_base),
		cmocka_unit_test(test_idle_sleeps_to_the_deadline_without_can),
		cmocka_unit_test(test_sigterm_sets_stop_and_wakes_idle),
		cmocka_unit_test(test_watchdog_reports_a_missed_kick),
		cmocka_unit_test(test_watchdog_expiry_can_stop_the_loop),
		cmocka_unit_test_setup_teardown(test_calib_file_roundtrip_and_errors, calib_setup,
						calib_teardown),
		cmocka_unit_test_setup_teardown(test_calib_unwritable_place_is_eio_and_a_fault,
						calib_setup, calib_teardown),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
