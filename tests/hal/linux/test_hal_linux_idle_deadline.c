/* SPDX-License-Identifier: MIT */
/*
 * hal/linux's software watchdog (hal_linux_idle.c) at its exact deadline,
 * on a clock this test sets (the link wraps hal_time_us,
 * -Wl,--wrap=hal_time_us): with a timeout of T ms the watchdog has not
 * expired T ms after the last kick, and has 1 us later (hal.h: a missed
 * kick resets, here: is reported). A kick restarts the interval; the
 * timeout's range is 1 .. 60000 ms.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "hal_linux.h"

uint64_t __wrap_hal_time_us(void);

static uint64_t now_us;

uint64_t __wrap_hal_time_us(void)
{
	return now_us;
}

static void test_expires_one_us_after_the_timeout(void **state)
{
	(void)state;
	now_us = 1000000U;
	assert_int_equal(hal_watchdog_start(50U), SQ_OK);
	now_us = 1000000U + 50000U;
	assert_false(hal_linux_watchdog_expired());
	now_us = 1000000U + 50001U;
	assert_true(hal_linux_watchdog_expired());
	assert_int_equal(hal_linux_watchdog_expiries(), 1U);
}

static void test_a_kick_restarts_the_interval(void **state)
{
	(void)state;
	now_us = 5000000U;
	assert_int_equal(hal_watchdog_start(50U), SQ_OK);
	now_us = 5000000U + 40000U;
	hal_watchdog_kick();
	now_us = 5000000U + 90000U; /* 90 ms after the start, 50 after the kick */
	assert_false(hal_linux_watchdog_expired());
	now_us = 5000000U + 90001U;
	assert_true(hal_linux_watchdog_expired());
	assert_int_equal(hal_linux_watchdog_expiries(), 2U);
}

static void test_longest_timeout_60_s(void **state)
{
	(void)state;
	assert_int_equal(hal_watchdog_start(60001U), SQ_EINVAL);
	now_us = 10000000U;
	assert_int_equal(hal_watchdog_start(60000U), SQ_OK);
	now_us = 10000000U + 60000000U;
	assert_false(hal_linux_watchdog_expired());
	now_us = 10000000U + 60000001U;
	assert_true(hal_linux_watchdog_expired());
	assert_int_equal(hal_linux_watchdog_expiries(), 3U);
}

SQ_CMOCKA_MAIN(cmocka_unit_test(test_expires_one_us_after_the_timeout),
	       cmocka_unit_test(test_a_kick_restarts_the_interval),
	       cmocka_unit_test(test_longest_timeout_60_s))
