/* SPDX-License-Identifier: MIT */
/*
 * test_squeal_app_fd.c: the scheduler (firmware/app/squeal_app.c) takes CAN
 * FD frames of up to 64 bytes from the HAL and hands every one of them to
 * the monitors, as classic frames are: none is refused, cut or left in the
 * HAL's queue. The monitors decide what a frame is; frames with identifiers
 * no input uses are counted by them as unknown identifiers, one each (the
 * expected count is the number of frames pushed here). On the in-memory
 * backend (64-byte frames), both numeric builds.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "hal_vbus.h"
#include "monitor.h"
#include "sq_status.h"
#include "squeal_app.h"
#include "test_hal.h"

#define T0_US 1000000ULL

/* The data does not matter here: which frames arrive does. */
static hal_can_frame_t fd_frame(uint32_t id, uint8_t flags, uint8_t len, uint64_t t_us)
{
	const hal_can_frame_t f = { .id = id, .flags = flags, .dlc = len, .timestamp_us = t_us,
				    .data = { 0xA5U, [63] = 0x5AU } };

	return f;
}

static void test_fd_frames_reach_the_monitors(void **state)
{
	const hal_can_frame_t frames[5] = {
		fd_frame(0x6A0U, HAL_CAN_FLAG_FDF, 64U, T0_US + 100U),
		fd_frame(0x6A1U, (uint8_t)(HAL_CAN_FLAG_FDF | HAL_CAN_FLAG_BRS), 12U, T0_US + 200U),
		fd_frame(0x1ABCDE00U, (uint8_t)(HAL_CAN_FLAG_FDF | HAL_CAN_FLAG_EXT), 48U, T0_US + 300U),
		fd_frame(0x6A2U, (uint8_t)(HAL_CAN_FLAG_FDF | HAL_CAN_FLAG_ESI), 8U, T0_US + 400U),
		fd_frame(0x6A3U, 0U, 8U, T0_US + 500U), /* and a classic one among them */
	};
	uint32_t unknown0;
	uint32_t i;

	(void)state;
	test_hal_reset();
	test_hal_apply_rx_filter(false); /* promiscuous: the app sees them all */
	test_hal_set_time_us(T0_US);
	test_hal_calib_absent();
	assert_int_equal(squeal_app_init(), SQ_OK);
	unknown0 = squeal_app_monitor()->count.unknown_id;
	for (i = 0U; i < 5U; i++) {
		assert_int_equal(test_hal_rx_push(&frames[i]), SQ_OK);
	}
	test_hal_set_time_us(T0_US + 1000U);
	(void)squeal_app_poll();
	assert_int_equal(hal_vbus_rx_pending(0U), 0U);
	assert_int_equal(squeal_app_monitor()->count.unknown_id, unknown0 + 5U);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_fd_frames_reach_the_monitors),
	};

	return cmocka_run_group_tests_name("squeal_app FD", tests, NULL, NULL);
}
