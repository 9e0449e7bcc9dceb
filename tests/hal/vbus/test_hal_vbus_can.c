/* SPDX-License-Identifier: MIT */
/*
 * The in-memory backend's own CAN promises (hal/vbus/hal_vbus.h), both
 * numeric builds, ASan+UBSan. The rules every backend shares
 * (hal/hal_can_common.h): tests/hal/common/test_hal_can_common.c.
 *
 * The status a test injects is built from zero, as the bus would make it:
 * it says mode NORMAL and carries no refusals, so a backend that copied
 * the mode or the counts from it would be caught.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "hal_can_common.h"
#include "hal_vbus.h"

static int set_up(void **state)
{
	(void)state;
	hal_vbus_reset();
	hal_vbus_set_time_us(1000U);
	return 0;
}

static hal_can_status_t bus_made(hal_can_state_t state, uint8_t tec)
{
	hal_can_status_t st;

	memset(&st, 0, sizeof(st)); /* mode NORMAL, no refusals, no counts */
	st.state = state;
	st.tx_error_count = tec;
	return st;
}

static hal_can_frame_t std_frame(uint32_t id)
{
	hal_can_frame_t f;

	memset(&f, 0, sizeof(f));
	f.id = id;
	f.dlc = 2U;
	f.data[0] = 0xA5U;
	return f;
}

static void test_listen_only_survives_an_injected_status(void **state)
{
	const hal_can_frame_t f = std_frame(0x123U);
	hal_can_status_t in = bus_made(HAL_CAN_STATE_BUS_OFF, 255U);
	hal_can_status_t st;
	hal_can_frame_t got;
	uint8_t bus;

	(void)state;
	for (bus = 0U; bus < HAL_CAN_BUSES; bus++) {
		assert_int_equal(hal_can_set_mode(bus, HAL_CAN_MODE_LISTEN_ONLY), SQ_OK);
		assert_int_equal(hal_can_send(bus, &f), SQ_EPERM);
		hal_vbus_set_status(bus, &in); /* bus-off, the bus says NORMAL */
		assert_int_equal(hal_can_get_status(bus, &st), SQ_OK);
		assert_int_equal(st.mode, HAL_CAN_MODE_LISTEN_ONLY);
		assert_int_equal(st.tx_refused_listen_only, 1U);
		assert_int_equal(hal_can_send(bus, &f), SQ_EPERM); /* listen-only first */
		in = bus_made(HAL_CAN_STATE_ERROR_ACTIVE, 0U); /* recovered */
		hal_vbus_set_status(bus, &in);
		assert_int_equal(hal_can_send(bus, &f), SQ_EPERM);
		assert_int_equal(hal_can_get_status(bus, &st), SQ_OK);
		assert_int_equal(st.mode, HAL_CAN_MODE_LISTEN_ONLY);
		assert_int_equal(st.state, HAL_CAN_STATE_ERROR_ACTIVE);
		assert_int_equal(st.tx_refused_listen_only, 3U);
		assert_int_equal(hal_vbus_tx_pop(bus, &got), SQ_EAGAIN); /* nothing sent */
		in = bus_made(HAL_CAN_STATE_BUS_OFF, 255U);
	}
	/* and NORMAL again sends: the mode is the firmware's alone */
	assert_int_equal(hal_can_set_mode(0U, HAL_CAN_MODE_NORMAL), SQ_OK);
	assert_int_equal(hal_can_send(0U, &f), SQ_OK);
	assert_int_equal(hal_vbus_tx_pop(0U, &got), SQ_OK);
	assert_int_equal(got.id, 0x123U);
}

static void test_injected_status_counts_are_the_backends(void **state)
{
	hal_can_status_t in = bus_made(HAL_CAN_STATE_BUS_OFF, 255U);
	hal_can_status_t st;

	(void)state;
	in.bus_off_count = 99U; /* made up by the injector: not taken */
	in.state_changes = 99U;
	in.rx_error_count = 7U;
	in.rx_overruns = 5U;
	in.error_frames = 3U;
	in.tx_dropped = 2U;
	hal_vbus_set_status(0U, &in);
	assert_int_equal(hal_can_get_status(0U, &st), SQ_OK);
	assert_int_equal(st.state, HAL_CAN_STATE_BUS_OFF);
	assert_int_equal(st.bus_off_count, 1U);
	assert_int_equal(st.state_changes, 1U);
	assert_int_equal(st.tx_error_count, 255U); /* the bus's counters: taken */
	assert_int_equal(st.rx_error_count, 7U);
	assert_int_equal(st.rx_overruns, 5U);
	assert_int_equal(st.error_frames, 3U);
	assert_int_equal(st.tx_dropped, 2U);
	hal_vbus_set_status(0U, &in); /* still bus-off: no new entry */
	assert_int_equal(hal_can_get_status(0U, &st), SQ_OK);
	assert_int_equal(st.bus_off_count, 1U);
	assert_int_equal(st.state_changes, 1U);
	in = bus_made(HAL_CAN_STATE_ERROR_PASSIVE, 130U);
	hal_vbus_set_status(0U, &in);
	in = bus_made(HAL_CAN_STATE_BUS_OFF, 255U);
	hal_vbus_set_status(0U, &in);
	assert_int_equal(hal_can_get_status(0U, &st), SQ_OK);
	assert_int_equal(st.bus_off_count, 2U);
	assert_int_equal(st.state_changes, 3U);
	assert_int_equal(hal_can_get_status(1U, &st), SQ_OK); /* the other bus untouched */
	assert_int_equal(st.bus_off_count, 0U);
	assert_int_equal(st.state_changes, 0U);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup(test_listen_only_survives_an_injected_status, set_up),
		cmocka_unit_test_setup(test_injected_status_counts_are_the_backends, set_up),
	};

	return cmocka_run_group_tests_name("vbus", tests, NULL, NULL);
}
