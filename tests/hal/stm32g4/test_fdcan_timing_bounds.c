/* SPDX-License-Identifier: MIT */
/*
 * fdcan_bit_timing's argument bounds (hal/stm32g4/fdcan_timing.c): the
 * data phase is never slower than the nominal one (the FD frame switches
 * up, ISO 11898-1), the nominal rate at most 1 Mbit/s, the data rate at
 * most 8 Mbit/s. Kernel clock 80 MHz (every rate below divides it; the
 * data phases below keep the transceiver delay offset, 0.75 of a data bit
 * in kernel clocks, within its 127: 500 kbit/s is 160 clocks, offset 120).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "fdcan.h"
#include "sq_status.h"

#define KERNEL_HZ 80000000UL

static void test_data_rate_not_below_nominal(void **state)
{
	fdcan_timing_t t;

	(void)state;
	assert_int_equal(fdcan_bit_timing(KERNEL_HZ, 500000UL, 500000UL, &t), SQ_OK);
	assert_int_equal(fdcan_bit_timing(KERNEL_HZ, 500000UL, 2000000UL, &t), SQ_OK);
	assert_int_equal(fdcan_bit_timing(KERNEL_HZ, 1000000UL, 1000000UL, &t), SQ_OK);
	/* 500 kbit/s data works after a 500 kbit/s nominal phase, not after 1 Mbit/s */
	assert_int_equal(fdcan_bit_timing(KERNEL_HZ, 1000000UL, 500000UL, &t), SQ_EINVAL);
}

static void test_rate_ceilings(void **state)
{
	fdcan_timing_t t;

	(void)state;
	assert_int_equal(fdcan_bit_timing(KERNEL_HZ, 1000000UL, 8000000UL, &t), SQ_OK);
	assert_int_equal(fdcan_bit_timing(KERNEL_HZ, 2000000UL, 8000000UL, &t), SQ_EINVAL);
	assert_int_equal(fdcan_bit_timing(KERNEL_HZ, 1000000UL, 10000000UL, &t), SQ_EINVAL);
	assert_int_equal(fdcan_bit_timing(KERNEL_HZ, 0UL, 2000000UL, &t), SQ_EINVAL);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_data_rate_not_below_nominal),
		cmocka_unit_test(test_rate_ceilings),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
