/* SPDX-License-Identifier: MIT */
/*
 * The monitor's rules exactly at their bounds, through protected frames into
 * the test HAL and frames out of its TX log (both numeric builds). Each test
 * pins one bound that the other monitor tests cross only by a wide margin
 * (found by make mutate: the mutant named in each comment survived them):
 *   - an input is stale in the first 1 ms tick after its timeout, even when
 *     its frames are not on the tick grid (mon-3);
 *   - after a real outage the E2E receiver starts over: the first frame is
 *     used whatever its counter, even the counter of the last frame (mon-4);
 *   - v0 and force exactly at their calibrated minimum are classified (mon-9);
 *   - HopfForce_N is rounded to the nearest newton, not truncated (mon-8);
 *   - SquealDiag's 16-bit counters saturate at 65535, and 65535 itself is
 *     sent as 65535 (mon-12);
 *   - a BISTABLE basin ratio exactly at rho_warn is an ADVISORY, one ppm
 *     below it a WARNING (mon-13);
 *   - the transmit queue holds MONITOR_TX_QUEUE_LEN (8) frames: the ninth,
 *     with nothing sent, is dropped and counted, never written over the
 *     oldest.
 * Expected values are hand-derived from the DBC scaling and the calibration.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "calib.h"
#include "monitor.h"
#include "monitor_expect.h"
#include "sq_status.h"
#include "squeal_app.h"
#include "test_app_drive.h"
#include "test_hal.h"

#define T0_US 1000000ULL
#define IN_PERIOD_US 10000ULL
#define SPEED_RAW 2500U   /* 25 rad/s x r_p 0.12 m: v0 = 3 m/s = 3000000 um/s */
#define FORCE_RAW 18000U  /* 0.5 N per bit: 9000 N = 9000000 mN */
#define STALE_US 30000ULL /* 3 x 10 ms (default calibration) */

static test_sender_t snd;

static void boot(const calib_t *cal)
{
	test_app_boot(cal, T0_US);
	test_sender_init(&snd);
}

static void run_to(uint64_t t_us)
{
	test_app_run_to(t_us);
}

/* The first SquealStatus (state: bits 12..15) at or after t_us whose state
 * is (want) or is not (!want) st; its time, or 0. */
static uint64_t first_status(uint64_t t_us, uint8_t st, bool want)
{
	return test_app_tx_first(EXP_DBC_SQUEALSTATUS_ID, t_us, 12U, 4U, st, want);
}

static uint8_t last_state(void)
{
	return (uint8_t)test_app_tx_last_sig(EXP_DBC_SQUEALSTATUS_ID, 12U, 4U);
}

/* Inputs off the 1 ms grid (+500 us). A frame handled before the next tick
 * counts from that tick's time; one handled late (here after a burst) keeps
 * its own time stamp: the last speed frame at t_last, the tick at
 * t_last + 30.5 ms is the first with age > 30 ms. */
static void test_stale_in_first_tick_after_timeout(void **state)
{
	const uint64_t t0 = T0_US + 5500U;
	uint64_t t_last = 0U;
	uint64_t t_fault;
	hal_can_frame_t last_force = { 0 };

	(void)state;
	boot(NULL);

	for (uint32_t k = 0U; k < 20U; k++) {
		const uint64_t t = t0 + IN_PERIOD_US * k;
		hal_can_frame_t fs = test_frame_speed(&snd, SPEED_RAW, t);
		hal_can_frame_t ff;

		if (k == 9U) {
			/* a burst of 100 repeats of the last force frame just
			 * before: the app drains 64 frames per poll, so the last
			 * speed frame is handled after the next tick, with its
			 * own time stamp (off the 1 ms grid) */
			for (uint32_t r = 0U; r < 100U; r++) {
				last_force.timestamp_us = t - 100U;
				assert_int_equal(test_hal_rx_push(&last_force), SQ_OK);
			}
		}
		ff = test_frame_force(&snd, FORCE_RAW, t);
		if (k < 10U) {
			assert_int_equal(test_hal_rx_push(&fs), SQ_OK);
			t_last = t;
		}
		assert_int_equal(test_hal_rx_push(&ff), SQ_OK);
		last_force = ff;
	}
	/* not stale in the last tick before the timeout, stale in the first after */
	run_to(t_last + STALE_US - 500U);
	assert_int_equal(monitor_fault_bits(squeal_app_monitor()), 0U);
	run_to(t_last + STALE_US + 500U);
	assert_int_equal(monitor_fault_bits(squeal_app_monitor()), MSG_FAULT_SPEED_STALE);
	run_to(t0 + IN_PERIOD_US * 19U);
	t_fault = first_status(t_last, MSG_SQUEAL_STATE_FAULT, true);
	print_message("  last speed frame +%llu us, FAULT %llu us later\n",
		      (unsigned long long)(t_last - T0_US), (unsigned long long)(t_fault - t_last));
	assert_true(t_fault > t_last + STALE_US);
	assert_true(t_fault <= t_last + STALE_US + 1000U);
}

/* Speed silent for 500 ms, then back with the counter of its last frame
 * (a restarted sender may start anywhere): used at once (INITIAL), not
 * dropped as REPEATED. */
static void test_outage_restarts_e2e(void **state)
{
	const uint64_t t0 = T0_US + 5000U;
	uint8_t last_counter = 0U;
	uint64_t t_back;

	(void)state;
	boot(NULL);
	for (uint32_t k = 0U; k < 80U; k++) {
		const uint64_t t = t0 + IN_PERIOD_US * k;

		if ((k < 10U) || (k >= 60U)) {
			if (k == 60U) {
				snd.speed_counter = last_counter;
			}
			last_counter = snd.speed_counter;
			assert_int_equal(test_send_pair(&snd, SPEED_RAW, FORCE_RAW, t), SQ_OK);
		} else {
			hal_can_frame_t f = test_frame_force(&snd, FORCE_RAW, t);

			assert_int_equal(test_hal_rx_push(&f), SQ_OK);
		}
	}
	run_to(t0 + IN_PERIOD_US * 79U);
	assert_true(first_status(t0, MSG_SQUEAL_STATE_FAULT, true) != 0U);
	t_back = first_status(t0 + IN_PERIOD_US * 60U, MSG_SQUEAL_STATE_FAULT, false);
	assert_int_equal(t_back, t0 + IN_PERIOD_US * 60U);
	assert_int_equal(last_state(), MSG_SQUEAL_STATE_STABLE);
	assert_int_equal(squeal_app_monitor()->speed.count.e2e_repeated, 0);
}

/* steady inputs with cal; the state after 100 ms */
static uint8_t state_with(const calib_t *cal)
{
	boot(cal);
	for (uint32_t k = 0U; k < 10U; k++) {
		assert_int_equal(test_send_pair(&snd, SPEED_RAW, FORCE_RAW,
						T0_US + 5000U + IN_PERIOD_US * k), SQ_OK);
	}
	run_to(T0_US + 100000U);
	return last_state();
}

static void test_minimum_speed_and_force_inclusive(void **state)
{
	calib_t cal;

	(void)state;
	calib_default(&cal);
	cal.v0_min_umps = 3000000U;   /* exactly v0 */
	assert_int_equal(state_with(&cal), MSG_SQUEAL_STATE_STABLE);
	cal.v0_min_umps = 3000001U;
	assert_int_equal(state_with(&cal), MSG_SQUEAL_STATE_NOT_SLIDING);
	calib_default(&cal);
	cal.force_min_mn = 9000000U;  /* exactly the force */
	assert_int_equal(state_with(&cal), MSG_SQUEAL_STATE_STABLE);
	cal.force_min_mn = 9000001U;
	assert_int_equal(state_with(&cal), MSG_SQUEAL_STATE_NOT_SLIDING);
}

/* warning level of the last SquealStatus (bits 16..19) at 1.8 m/s, 9 kN
 * (BISTABLE with the default brake), with rho_warn = rho_warn_ppm */
static uint8_t warning_at_1_8mps(uint32_t rho_warn_ppm, int32_t *ratio_ppm)
{
	calib_t cal;
	const hal_can_frame_t *f;

	calib_default(&cal);
	cal.rho_warn_ppm = rho_warn_ppm;
	boot(&cal);
	for (uint32_t k = 0U; k < 12U; k++) {
		assert_int_equal(test_send_pair(&snd, 1500U, FORCE_RAW,
						T0_US + 5000U + IN_PERIOD_US * k), SQ_OK);
	}
	run_to(T0_US + 120000U);
	assert_int_equal(last_state(), MSG_SQUEAL_STATE_BISTABLE);
	*ratio_ppm = squeal_app_monitor()->eval.basin_ratio_ppm;
	f = test_hal_tx_last(EXP_DBC_SQUEALSTATUS_ID);
	assert_non_null(f);
	return (uint8_t)test_frame_sig(f->data, 16, 4);
}

static void test_rho_warn_threshold_exclusive(void **state)
{
	int32_t rho;
	int32_t again;

	(void)state;
	(void)warning_at_1_8mps(500000U, &rho);
	assert_true((rho > 0) && (rho < 1000000));
	assert_int_equal(warning_at_1_8mps((uint32_t)rho, &again), MSG_WARNING_LEVEL_ADVISORY);
	assert_int_equal(again, rho);
	assert_int_equal(warning_at_1_8mps((uint32_t)rho + 1U, &again), MSG_WARNING_LEVEL_WARNING);
}

/* HopfForce_N (1 N per bit, SquealDetail2 bits 32..47) is the model's
 * border force in mN rounded to the nearest N: over a few speeds around
 * 0.5 m/s (N_H about 2 kN there, inside the signal's range), at least one
 * whose fraction is >= 0.5 N must round up. */
static void test_hopf_force_rounded_to_nearest(void **state)
{
	uint32_t rounded_up = 0U;

	(void)state;
	for (uint16_t raw = 400U; raw < 440U; raw = (uint16_t)(raw + 3U)) {
		const monitor_t *m;
		const hal_can_frame_t *f;
		uint32_t mn;

		boot(NULL);
		for (uint32_t k = 0U; k < 12U; k++) {
			assert_int_equal(test_send_pair(&snd, raw, FORCE_RAW,
							T0_US + 5000U + IN_PERIOD_US * k), SQ_OK);
		}
		run_to(T0_US + 120000U);
		m = squeal_app_monitor();
		assert_true(m->have_eval);
		assert_true((m->eval.has & MODEL_EVAL_HAS_HOPF_FORCE) != 0U);
		mn = (uint32_t)m->eval.hopf_force_mn;
		f = test_hal_tx_last(EXP_DBC_SQUEALDETAIL2_ID);
		assert_non_null(f);
		assert_true(mn < 65000000U);
		assert_int_equal(test_frame_sig(f->data, 32, 16), (mn + 500U) / 1000U);
		if ((mn % 1000U) >= 500U) {
			rounded_up++;
		}
	}
	assert_true(rounded_up > 0U);
}

/* RxOverrunCount (SquealDiag page 1, bits 48..63) from the HAL's counter */
static uint64_t rx_overruns_sent(uint32_t hal_count)
{
	hal_can_status_t st;
	int32_t i = -1;
	uint64_t sent = UINT64_MAX;

	boot(NULL);
	memset(&st, 0, sizeof(st));
	st.state = HAL_CAN_STATE_ERROR_ACTIVE;
	st.rx_overruns = hal_count;
	test_hal_set_can_status(&st);
	run_to(T0_US + 4100000U); /* pages 0..3 once each at 1 s */
	while ((i = test_hal_tx_find(EXP_DBC_SQUEALDIAG_ID, (uint32_t)(i + 1))) >= 0) {
		const hal_can_frame_t *f = test_hal_tx_frame((uint32_t)i);

		if (test_frame_sig(f->data, 12, 4) == 1U) {
			sent = test_frame_sig(f->data, 48, 16);
		}
	}
	return sent;
}

static void test_diag_counters_saturate_at_16_bits(void **state)
{
	(void)state;
	assert_int_equal(rx_overruns_sent(65534U), 65534U);
	assert_int_equal(rx_overruns_sent(65535U), 65535U);
	assert_int_equal(rx_overruns_sent(65536U), 65535U);
	assert_int_equal(rx_overruns_sent(4000000000U), 65535U);
}

/* A transmit queue nobody drains (the bus is gone): the default periods
 * (SquealStatus 10 ms, SquealDetail and SquealDetail2 100 ms, SquealDiag
 * 1 s, all due in the first step) queue 0x300, 0x301, 0x303, 0x302 at T0,
 * then 0x300 at T0 + 10, 20, 30, 40 ms: 8 frames, the queue's length. The
 * ninth (0x300 at T0 + 50 ms) is dropped and counted; the eight queued stay
 * as they were, the oldest first. */
static void test_tx_queue_holds_eight(void **state)
{
	static monitor_t m;
	static const uint16_t want_id[MONITOR_TX_QUEUE_LEN] = {
		0x300U, 0x301U, 0x303U, 0x302U, 0x300U, 0x300U, 0x300U, 0x300U
	};
	static const uint64_t want_ms[MONITOR_TX_QUEUE_LEN] = { 0U, 0U, 0U, 0U, 10U, 20U, 30U, 40U };
	calib_t cal;
	hal_can_frame_t f;
	uint32_t n = 0U;

	(void)state;
	calib_default(&cal);
	assert_int_equal(monitor_init(&m, &cal, false, 0U, T0_US), SQ_OK);
	for (uint64_t ms = 0U; ms < 50U; ms++) {
		monitor_step(&m, T0_US + ms * 1000U);
	}
	assert_int_equal(m.count.tx_overflow, 0U);
	monitor_step(&m, T0_US + 50000U);
	assert_int_equal(m.count.tx_overflow, 1U);
	while ((n <= MONITOR_TX_QUEUE_LEN) && (monitor_peek_tx(&m, &f) == SQ_OK)) {
		assert_true(n < MONITOR_TX_QUEUE_LEN);
		assert_int_equal(f.id, want_id[n]);
		assert_true(f.timestamp_us == T0_US + want_ms[n] * 1000U);
		monitor_tx_done(&m, SQ_OK);
		n++;
	}
	assert_int_equal(n, MONITOR_TX_QUEUE_LEN);
	assert_int_equal(m.count.tx_frames, MONITOR_TX_QUEUE_LEN);
	/* emptied, it takes the next frame again */
	monitor_step(&m, T0_US + 60000U);
	assert_int_equal(monitor_peek_tx(&m, &f), SQ_OK);
	assert_int_equal(f.id, 0x300U);
	assert_int_equal(m.count.tx_overflow, 1U);
}

SQ_CMOCKA_MAIN(
	cmocka_unit_test(test_stale_in_first_tick_after_timeout),
	cmocka_unit_test(test_outage_restarts_e2e),
	cmocka_unit_test(test_minimum_speed_and_force_inclusive),
	cmocka_unit_test(test_hopf_force_rounded_to_nearest),
	cmocka_unit_test(test_diag_counters_saturate_at_16_bits),
	cmocka_unit_test(test_rho_warn_threshold_exclusive),
	cmocka_unit_test(test_tx_queue_holds_eight))
