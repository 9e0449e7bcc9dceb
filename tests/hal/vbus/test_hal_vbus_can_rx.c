/* SPDX-License-Identifier: MIT */
/*
 * The in-memory bus's receive queue and rate (hal/vbus/hal_vbus_can.c),
 * both numeric builds, as hal_vbus.h states them: HAL_VBUS_RX_LEN (4096)
 * frames queue, the next one is dropped with SQ_ENOBUFS and one overrun
 * counted; a frame arrives at its timestamp, not before; a rate of
 * 1..1000 kbit/s is taken, 1001 refused.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "hal_can_common.h"
#include "hal_vbus.h"

static hal_can_frame_t frame_at(uint32_t id, uint64_t t_us)
{
	hal_can_frame_t f;

	memset(&f, 0, sizeof(f));
	f.id = id;
	f.dlc = 1U;
	f.timestamp_us = t_us;
	return f;
}

static void test_queue_full_drops_and_counts(void **state)
{
	hal_can_frame_t f = frame_at(0x100U, 1000U);
	hal_can_status_t st;
	uint32_t i;

	(void)state;
	hal_vbus_reset();
	hal_vbus_set_time_us(1000U);
	for (i = 0U; i < HAL_VBUS_RX_LEN; i++) {
		assert_int_equal(hal_vbus_rx_push(0U, &f), SQ_OK);
	}
	assert_int_equal(hal_vbus_rx_pending(0U), HAL_VBUS_RX_LEN);
	assert_int_equal(hal_vbus_rx_push(0U, &f), SQ_ENOBUFS);
	assert_int_equal(hal_vbus_rx_pending(0U), HAL_VBUS_RX_LEN);
	assert_int_equal(hal_can_get_status(0U, &st), SQ_OK);
	assert_int_equal(st.rx_overruns, 1U);
}

static void test_frame_arrives_at_its_time(void **state)
{
	const hal_can_frame_t f = frame_at(0x123U, 5000U);
	hal_can_frame_t got;

	(void)state;
	hal_vbus_reset();
	hal_vbus_set_time_us(1000U);
	assert_int_equal(hal_vbus_rx_push(0U, &f), SQ_OK);
	assert_int_equal(hal_can_receive(0U, &got), SQ_EAGAIN);
	hal_vbus_set_time_us(4999U);
	assert_int_equal(hal_can_receive(0U, &got), SQ_EAGAIN);
	hal_vbus_set_time_us(5000U);
	assert_int_equal(hal_can_receive(0U, &got), SQ_OK);
	assert_int_equal(got.id, 0x123U);
}

static void test_rate_bounds(void **state)
{
	(void)state;
	hal_vbus_reset();
	assert_int_equal(hal_can_set_bitrate(0U, 1000U), SQ_OK);
	assert_int_equal(hal_can_set_bitrate(0U, 1U), SQ_OK);
	assert_int_equal(hal_can_set_bitrate(0U, 1001U), SQ_EINVAL);
	assert_int_equal(hal_can_set_bitrate(0U, 0U), SQ_EINVAL);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_queue_full_drops_and_counts),
		cmocka_unit_test(test_frame_arrives_at_its_time),
		cmocka_unit_test(test_rate_bounds),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
