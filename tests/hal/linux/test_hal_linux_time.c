/* SPDX-License-Identifier: MIT */
/*
 * hal/linux's time base (hal_linux_time.c) on the build host: hal_time_us()
 * against clock_gettime(CLOCK_MONOTONIC), the cycle counter at 1000 per
 * microsecond, a CLOCK_REALTIME stamp converted to the monotonic base.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <time.h>
#include <unistd.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "hal_linux.h"

static int64_t ref_mono_us(void)
{
	struct timespec ts;

	assert_int_equal(clock_gettime(CLOCK_MONOTONIC, &ts), 0);
	return (int64_t)ts.tv_sec * 1000000 + ts.tv_nsec / 1000;
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

SQ_CMOCKA_MAIN(
	cmocka_unit_test(test_time_is_clock_monotonic_in_us),
	cmocka_unit_test(test_realtime_stamp_converts_to_monotonic_base))
