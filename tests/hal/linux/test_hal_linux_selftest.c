/* SPDX-License-Identifier: MIT */
/*
 * The Linux backend's platform faults and self-test (hal/linux/hal_linux.c),
 * no CAN needed: faults raised one after another all stay raised (a later
 * one never clears an earlier), and hal_selftest says a Linux host has no
 * bring-up self-test (SQ_ENOTSUP) with every figure "not measured" and no
 * brown-out level (hal.h's HAL_SELFTEST_NOT_MEASURED, HAL_SELFTEST_NO_BOR),
 * never a passed one.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "hal.h"
#include "hal_linux.h"
#include "sq_status.h"

static void test_faults_accumulate(void **state)
{
	(void)state;
	assert_int_equal(hal_platform_faults(), 0U);
	hal_linux_add_fault(HAL_FAULT_CAN_INIT);
	assert_int_equal(hal_platform_faults(), HAL_FAULT_CAN_INIT);
	hal_linux_add_fault(HAL_FAULT_CLOCK_FALLBACK);
	assert_int_equal(hal_platform_faults(), HAL_FAULT_CAN_INIT | HAL_FAULT_CLOCK_FALLBACK);
	hal_linux_add_fault(HAL_FAULT_CAN_INIT);
	assert_int_equal(hal_platform_faults(), HAL_FAULT_CAN_INIT | HAL_FAULT_CLOCK_FALLBACK);
}

static void test_selftest_is_not_supported(void **state)
{
	hal_selftest_t r;

	(void)state;
	memset(&r, 0x5A, sizeof(r));
	assert_int_equal(hal_selftest(&r), SQ_ENOTSUP);
	assert_int_equal(r.hse_hz, HAL_SELFTEST_NOT_MEASURED);
	assert_int_equal(r.stack_high_water_prev_b, HAL_SELFTEST_NOT_MEASURED);
	assert_int_equal(r.bor_level, HAL_SELFTEST_NO_BOR);
	assert_false(r.failed);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_faults_accumulate),
		cmocka_unit_test(test_selftest_is_not_supported),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
