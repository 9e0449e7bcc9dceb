/* SPDX-License-Identifier: MIT */
/*
 * hal/linux's idle, stop signals and software watchdog (hal_linux_idle.c)
 * on the build host: idle sleeps to its deadline, SIGTERM sets the stop
 * flag and wakes the idle, a missed kick is reported once, and an expiry
 * can stop the loop. The two watchdog tests run in this order (the second
 * counts the first's expiry).
 */
#include <setjmp.h>
#include <signal.h>
#include <stdarg.h>
#include <stddef.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "hal_linux.h"

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

SQ_CMOCKA_MAIN(
	cmocka_unit_test(test_idle_sleeps_to_the_deadline_without_can),
	cmocka_unit_test(test_sigterm_sets_stop_and_wakes_idle),
	cmocka_unit_test(test_watchdog_reports_a_missed_kick),
	cmocka_unit_test(test_watchdog_expiry_can_stop_the_loop))
