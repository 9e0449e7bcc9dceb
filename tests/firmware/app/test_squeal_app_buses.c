/* SPDX-License-Identifier: MIT */
/*
 * The scheduler with two buses (calibration input_bus, output_bus,
 * input_listen_only) on the in-memory backend: inputs are taken from the
 * input bus only, outputs go out on the output bus only, a listen-only input
 * bus never sees a send attempt, and listen-only on the output bus refuses
 * (and counts) every frame. Bus 0 is read through the test layer's TX log,
 * bus 1 straight from the backend (hal_vbus.h).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "calib.h"
#include "hal_vbus.h"
#include "monitor.h"
#include "monitor_expect.h"
#include "sq_status.h"
#include "squeal_app.h"
#include "test_hal.h"

#define T0_US 1000000ULL
#define IN_OFFSET_US 5000ULL
#define IN_PERIOD_US 10000ULL
#define SPEED_RAW 2500U
#define FORCE_RAW 18000U
#define PAIRS 30U

static test_sender_t snd;

static uint64_t in_time(uint32_t k)
{
	return T0_US + IN_OFFSET_US + IN_PERIOD_US * k;
}

static void boot(uint8_t in, uint8_t out, uint8_t listen_only)
{
	calib_t cal;
	uint8_t buf[CALIB_BLOCK_LEN];

	test_hal_reset();
	test_hal_apply_rx_filter(true); /* the controller's filters, as on the bus */
	test_hal_set_time_us(T0_US);
	test_sender_init(&snd);
	calib_default(&cal);
	cal.input_bus = in;
	cal.output_bus = out;
	cal.input_listen_only = listen_only;
	assert_int_equal(calib_encode(&cal, buf, sizeof(buf)), SQ_OK);
	test_hal_calib_store(buf, sizeof(buf));
	assert_int_equal(squeal_app_init(), SQ_OK);
}

/* PAIRS input pairs on `bus`, and the same identifiers with garbage on the
 * other bus (must never count as inputs), then 100 ms more. */
static void drive(uint8_t bus)
{
	for (uint32_t k = 0U; k < PAIRS; k++) {
		hal_can_frame_t f = test_frame_speed(&snd, SPEED_RAW, in_time(k));
		hal_can_frame_t g = f;

		assert_int_equal(hal_vbus_rx_push(bus, &f), SQ_OK);
		g.data[0] ^= 0xFFU; /* wrong CRC if it were ever checked */
		(void)hal_vbus_rx_push((uint8_t)(1U - bus), &g);
		f = test_frame_force(&snd, FORCE_RAW, in_time(k));
		assert_int_equal(hal_vbus_rx_push(bus, &f), SQ_OK);
	}
	while (hal_time_us() < in_time(PAIRS) + 100000U) {
		test_hal_advance_us(1000U);
		(void)squeal_app_poll();
	}
}

/* boot, drive the input bus, check every input was used; the input bus's
 * status afterwards */
static hal_can_status_t run(uint8_t in, uint8_t out, uint8_t listen_only)
{
	const monitor_t *m = squeal_app_monitor();
	hal_can_status_t st;

	boot(in, out, listen_only);
	drive(in);
	assert_int_equal(m->speed.count.used, PAIRS);
	assert_int_equal(m->force.count.used, PAIRS);
	assert_int_equal(m->speed.count.e2e_wrong_crc, 0);
	assert_int_equal(hal_can_get_status(in, &st), SQ_OK);
	assert_int_equal(st.mode, (listen_only != 0U) ? HAL_CAN_MODE_LISTEN_ONLY : HAL_CAN_MODE_NORMAL);
	return st;
}

static uint32_t sent_on_bus1(uint32_t id)
{
	hal_can_frame_t f;
	uint32_t n = 0U;

	while (hal_vbus_tx_pop(1U, &f) == SQ_OK) {
		n += (f.id == id) ? 1U : 0U;
	}
	return n;
}

static void test_inputs_on_bus1_listen_only_outputs_on_bus0(void **state)
{
	const hal_can_status_t st = run(1U, 0U, 1U);
	hal_vbus_stats_t vs;

	(void)state;
	assert_true(test_hal_tx_find(EXP_DBC_SQUEALSTATUS_ID, 0U) >= 0);
	/* the listen-only input bus is never asked to send */
	assert_int_equal(st.tx_refused_listen_only, 0);
	hal_vbus_get_stats(1U, &vs);
	assert_int_equal(vs.tx_frames, 0);
	assert_int_equal(vs.tx_refused, 0);
	assert_int_equal(squeal_app_monitor()->count.tx_errors, 0);
}

static void test_inputs_on_bus0_listen_only_outputs_on_bus1(void **state)
{
	const hal_can_status_t st = run(0U, 1U, 1U);

	(void)state;
	assert_int_equal(st.tx_refused_listen_only, 0);
	assert_int_equal(test_hal_tx_count(), 0);    /* nothing on bus 0 */
	assert_int_equal(test_hal_tx_rejected(), 0); /* not even tried   */
	/* SquealStatus every 10 ms from T0 (status_period_ms 10, hand count) */
	assert_true(sent_on_bus1(EXP_DBC_SQUEALSTATUS_ID) >= (PAIRS * IN_PERIOD_US + 100000U) / 10000U);
	assert_int_equal(squeal_app_monitor()->count.tx_errors, 0);
}

static void test_listen_only_output_bus_refuses_and_counts(void **state)
{
	/* a configuration that cannot send: counted, never silent */
	const hal_can_status_t st = run(0U, 0U, 1U);

	(void)state;
	assert_int_equal(test_hal_tx_count(), 0);
	assert_true(st.tx_refused_listen_only > 0U);
	assert_int_equal(squeal_app_monitor()->count.tx_errors, st.tx_refused_listen_only);
}

static void test_defaults_are_one_bus_in_normal_mode(void **state)
{
	hal_can_filter_t f[HAL_CAN_MAX_FILTERS];

	(void)state;
	(void)run(0U, 0U, 0U);
	assert_true(test_hal_tx_find(EXP_DBC_SQUEALSTATUS_ID, 0U) >= 0);
	assert_int_equal(sent_on_bus1(EXP_DBC_SQUEALSTATUS_ID), 0);
	assert_int_equal(hal_vbus_rx_filters(1U, f, HAL_CAN_MAX_FILTERS), 0); /* bus 1 untouched */
}

SQ_CMOCKA_MAIN(
	cmocka_unit_test(test_inputs_on_bus1_listen_only_outputs_on_bus0),
	cmocka_unit_test(test_inputs_on_bus0_listen_only_outputs_on_bus1),
	cmocka_unit_test(test_listen_only_output_bus_refuses_and_counts),
	cmocka_unit_test(test_defaults_are_one_bus_in_normal_mode))
