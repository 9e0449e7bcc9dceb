/* SPDX-License-Identifier: MIT */
/*
 * The in-memory backend's clock, idle, calibration storage, watchdog, reset
 * reason, platform faults and self-test (hal/vbus/hal_vbus_sys.c), both
 * numeric builds, ASan+UBSan. Every expected value is written out by hand
 * from hal_vbus.h's promises (168 cycles per virtual microsecond plus a
 * fixed amount per call; idle to the deadline or the next arrival; bytes
 * beyond the stored block read as erased flash 0xFF; power-on state: reset
 * reason POWER_ON, watchdog stopped, no fault, no self-test).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "hal_vbus.h"

static int set_up(void **state)
{
	(void)state;
	hal_vbus_reset();
	return 0;
}

static void test_clock_is_monotonic_and_cycles_follow_it(void **state)
{
	(void)state;
	assert_int_equal(hal_time_us(), 0U);
	hal_vbus_set_time_us(2500U);
	assert_int_equal(hal_time_us(), 2500U);
	hal_vbus_set_time_us(1000U); /* never back */
	assert_int_equal(hal_time_us(), 2500U);
	assert_int_equal(hal_cycles_per_us(), 168U);
	assert_int_equal(hal_cycles(), 2500U * 168U); /* 420000, nothing per call */
	hal_vbus_set_cycles_per_call(7U);
	assert_int_equal(hal_cycles(), 420007U);
	assert_int_equal(hal_cycles(), 420014U);
	hal_vbus_reset();
	assert_int_equal(hal_time_us(), 0U);
	assert_int_equal(hal_cycles(), 0U);
}

static void test_idle_goes_to_the_deadline_or_the_next_arrival(void **state)
{
	hal_can_frame_t f;

	(void)state;
	hal_idle_until(1000U);
	assert_int_equal(hal_time_us(), 1000U);
	hal_idle_until(500U); /* a deadline passed: the clock stays */
	assert_int_equal(hal_time_us(), 1000U);
	memset(&f, 0, sizeof(f));
	f.id = 0x123U;
	f.dlc = 1U;
	f.timestamp_us = 1700U;
	assert_int_equal(hal_vbus_rx_push(0U, &f), SQ_OK);
	hal_idle_until(5000U);
	assert_int_equal(hal_time_us(), 1700U); /* woken by the frame */
	assert_int_equal(hal_can_receive(0U, &f), SQ_OK);
	hal_idle_until(5000U);
	assert_int_equal(hal_time_us(), 5000U);
}

static void test_calibration_storage(void **state)
{
	uint8_t block[40];
	uint8_t rd[64];
	uint8_t big[HAL_CALIB_MAX_LEN + 1U];
	size_t i;

	(void)state;
	for (i = 0; i < sizeof(block); i++) {
		block[i] = (uint8_t)(3U * i + 1U);
	}
	assert_int_equal(hal_calib_read(rd, sizeof(rd)), SQ_ENOENT);
	assert_int_equal(hal_vbus_calib_stored(NULL, 0U), 0U);
	assert_int_equal(hal_calib_read(NULL, 4U), SQ_EINVAL);
	assert_int_equal(hal_calib_read(rd, HAL_CALIB_MAX_LEN + 1U), SQ_EINVAL);
	assert_int_equal(hal_calib_write(NULL, 4U), SQ_EINVAL);
	assert_int_equal(hal_calib_write(big, sizeof(big)), SQ_EINVAL);
	assert_int_equal(hal_vbus_calib_store(NULL, 4U), SQ_EINVAL);

	assert_int_equal(hal_calib_write(block, sizeof(block)), SQ_OK);
	memset(rd, 0, sizeof(rd));
	assert_int_equal(hal_calib_read(rd, sizeof(rd)), SQ_OK);
	assert_memory_equal(rd, block, sizeof(block));
	for (i = sizeof(block); i < sizeof(rd); i++) {
		assert_int_equal(rd[i], 0xFF); /* erased flash beyond the block */
	}
	memset(rd, 0, sizeof(rd));
	assert_int_equal(hal_vbus_calib_stored(rd, 10U), 40U); /* 10 copied */
	assert_memory_equal(rd, block, 10U);
	assert_int_equal(rd[10], 0U);

	hal_vbus_calib_set_unreadable(true);
	assert_int_equal(hal_calib_read(rd, sizeof(rd)), SQ_EIO);
	hal_vbus_calib_set_unreadable(false);
	assert_int_equal(hal_calib_read(rd, sizeof(rd)), SQ_OK);

	/* an empty block is present, every byte erased */
	assert_int_equal(hal_vbus_calib_store(NULL, 0U), SQ_OK);
	assert_int_equal(hal_calib_read(rd, 4U), SQ_OK);
	assert_int_equal(rd[0], 0xFF);
	assert_int_equal(rd[3], 0xFF);
	hal_vbus_calib_erase();
	assert_int_equal(hal_calib_read(rd, 4U), SQ_ENOENT);
	assert_int_equal(hal_vbus_calib_stored(rd, 4U), 0U);
}

static void test_watchdog_reset_reason_faults_and_selftest(void **state)
{
	hal_selftest_t st;
	hal_selftest_t given;

	(void)state;
	assert_int_equal(hal_vbus_watchdog_timeout_ms(), 0U);
	assert_int_equal(hal_watchdog_start(0U), SQ_EINVAL);
	assert_int_equal(hal_vbus_watchdog_timeout_ms(), 0U);
	assert_int_equal(hal_watchdog_start(250U), SQ_OK);
	assert_int_equal(hal_vbus_watchdog_timeout_ms(), 250U);
	hal_watchdog_kick();
	hal_watchdog_kick();
	assert_int_equal(hal_vbus_watchdog_kicks(), 2U);

	assert_int_equal(hal_reset_reason(), HAL_RESET_POWER_ON);
	hal_vbus_set_reset_reason(HAL_RESET_WATCHDOG);
	assert_int_equal(hal_reset_reason(), HAL_RESET_WATCHDOG);
	assert_int_equal(hal_platform_faults(), 0U);
	hal_vbus_set_platform_faults(HAL_FAULT_CAN_INIT | HAL_FAULT_CALIB_STORAGE);
	assert_int_equal(hal_platform_faults(), HAL_FAULT_CAN_INIT | HAL_FAULT_CALIB_STORAGE);

	assert_int_equal(hal_selftest(&st), SQ_ENOTSUP);
	memset(&given, 0, sizeof(given));
	given.hse_hz = 8000000U;
	given.stack_high_water_prev_b = HAL_SELFTEST_NOT_MEASURED;
	given.bor_level = 3U;
	given.failed = true;
	hal_vbus_set_selftest(&given);
	given.hse_hz = 1U; /* copied: a later change is not seen */
	assert_int_equal(hal_selftest(&st), SQ_OK);
	assert_int_equal(st.hse_hz, 8000000U);
	assert_int_equal(st.bor_level, 3U);
	assert_true(st.failed);
	hal_vbus_set_selftest(NULL);
	assert_int_equal(hal_selftest(&st), SQ_ENOTSUP);
	expect_assert_failure(hal_selftest(NULL));

	hal_vbus_reset(); /* all of it back to power-on */
	assert_int_equal(hal_vbus_watchdog_kicks(), 0U);
	assert_int_equal(hal_vbus_watchdog_timeout_ms(), 0U);
	assert_int_equal(hal_reset_reason(), HAL_RESET_POWER_ON);
	assert_int_equal(hal_platform_faults(), 0U);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup(test_clock_is_monotonic_and_cycles_follow_it, set_up),
		cmocka_unit_test_setup(test_idle_goes_to_the_deadline_or_the_next_arrival, set_up),
		cmocka_unit_test_setup(test_calibration_storage, set_up),
		cmocka_unit_test_setup(test_watchdog_reset_reason_faults_and_selftest, set_up),
	};

	return cmocka_run_group_tests_name("vbus_sys", tests, NULL, NULL);
}
