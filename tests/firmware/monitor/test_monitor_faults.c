/* SPDX-License-Identifier: MIT */
/*
 * Every input fault of the monitor, provoked with frames as a faulty sender
 * or a disturbed bus would deliver them, through the test HAL and
 * squeal_app_poll() (one poll per virtual millisecond). The operating point
 * is v0 = 3 m/s (Omega 25 rad/s), N = 9000 N: stable (the stable border is
 * at 2.07 m/s), so a healthy input gives SquealState 0 and a fault 15.
 *
 * Timing contract (monitor.h, calib defaults): an input is stale when no
 * usable frame came for stale_cycles x input_period = 30 ms; the 1 ms task
 * notices it in the first step after that, so FAULT appears within
 * 30 ms + 1 ms of the last used frame, never earlier than 30 ms.
 * (Measured: exactly 30 ms, because monitor_on_frame() runs before the
 * step that advances the monitor's clock, so a frame's timestamp counts
 * as "in the future" and is replaced by the previous step's time.)
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "calib.h"
#include "e2e_p01.h"
#include "fault_drive.h"
#include "monitor.h"
#include "monitor_expect.h"
#include "sq_status.h"
#include "squeal_app.h"
#include "test_app_drive.h"
#include "test_hal.h"

static test_sender_t snd;

static void boot(const calib_t *cal)
{
	test_app_boot(cal, T0_US);
	test_sender_init(&snd);
}

static void pair(uint32_t k, uint16_t speed_raw, uint16_t force_raw)
{
	assert_int_equal(test_send_pair(&snd, speed_raw, force_raw, in_time(k)), SQ_OK);
}

static void steady(uint32_t k_from, uint32_t k_to)
{
	uint32_t k;

	for (k = k_from; k < k_to; k++) {
		pair(k, SPEED_RAW, FORCE_RAW);
	}
}

/* The first SquealStatus sent at or after t_us with state (want == true)
 * or not (want == false) equal to st; its time, or 0 if none. */
static uint64_t first_status(uint64_t t_us, uint8_t st, bool want)
{
	return test_app_tx_first(EXP_DBC_SQUEALSTATUS_ID, t_us, 12, 4, st, want);
}

/* state and level of the last SquealStatus sent */
static uint8_t last_state(uint8_t *warning)
{
	if (warning != NULL) {
		*warning = (uint8_t)test_app_tx_last_sig(EXP_DBC_SQUEALSTATUS_ID, 16, 4);
	}
	return (uint8_t)test_app_tx_last_sig(EXP_DBC_SQUEALSTATUS_ID, 12, 4);
}

/* The SquealDiag frame sent at t_us (exactly): fault bits and page. */
static uint16_t diag_faults_at(uint64_t t_us, uint32_t *page, const uint8_t **data)
{
	return test_app_diag_at(EXP_DBC_SQUEALDIAG_ID, t_us, page, data);
}

static const monitor_t *mon(void)
{
	return squeal_app_monitor();
}

/* At the k-th input pair: the last SquealStatus says want; fault_at: says
 * FAULT, with exactly these fault bits. */
static void state_at(uint32_t k, uint8_t want)
{
	test_app_run_to(in_time(k));
	assert_int_equal(last_state(NULL), want);
}

static void fault_at(uint32_t k, uint32_t bits)
{
	state_at(k, MSG_SQUEAL_STATE_FAULT);
	assert_int_equal(monitor_fault_bits(mon()), bits);
}

/* healthy start: stable after the first pair */
static void healthy_until(uint32_t k_end)
{
	steady(0U, k_end);
	test_app_run_to(in_time(k_end - 1U));
	assert_int_equal(last_state(NULL), MSG_SQUEAL_STATE_STABLE);
	assert_int_equal(monitor_fault_bits(mon()), 0U);
}

/* ---- staleness ------------------------------------------------------------- */

static void stale_one(bool speed)
{
	uint32_t k;
	uint64_t t_fault;
	uint64_t t_back;
	uint8_t warning = 99U;
	const uint16_t bit = speed ? MSG_FAULT_SPEED_STALE : MSG_FAULT_FORCE_STALE;

	boot(NULL);
	steady(0U, 10U);
	/* k 10..119: only the other input; 120..: both again */
	for (k = 10U; k < 120U; k++) {
		hal_can_frame_t f = speed ? test_frame_force(&snd, FORCE_RAW, in_time(k)) :
			test_frame_speed(&snd, SPEED_RAW, in_time(k));

		test_app_push(&f);
	}
	steady(120U, 220U);
	test_app_run_to(in_time(60U));
	t_fault = first_status(in_time(9U), MSG_SQUEAL_STATE_FAULT, true);
	assert_true(t_fault != 0U);
	print_message("  last frame at +%llu us, FAULT sent %llu us later\n",
		      (unsigned long long)(in_time(9U) - T0_US),
		      (unsigned long long)(t_fault - in_time(9U)));
	assert_true(t_fault - in_time(9U) >= STALE_US);
	assert_true(t_fault - in_time(9U) <= STALE_US + 1000U);
	assert_int_equal(last_state(&warning), MSG_SQUEAL_STATE_FAULT);
	assert_int_equal(warning, 0);
	/* SquealDiag at T0 + 1 s carries the bit, and only that one */
	test_app_run_to(T0_US + 1000000U);
	assert_int_equal(diag_faults_at(T0_US + 1000000U, NULL, NULL), bit);
	/* frames return at k 120: usable at once (E2E starts over) */
	test_app_run_to(T0_US + 2000000U);
	t_back = first_status(in_time(120U), MSG_SQUEAL_STATE_FAULT, false);
	assert_int_equal(t_back, in_time(120U));
	assert_int_equal(last_state(NULL), MSG_SQUEAL_STATE_STABLE);
	assert_int_equal(diag_faults_at(T0_US + 2000000U, NULL, NULL), 0U);
	assert_int_equal(speed ? mon()->speed.count.stale_events : mon()->force.count.stale_events, 1);
	assert_int_equal(speed ? mon()->force.count.stale_events : mon()->speed.count.stale_events, 0);
}

static void test_stale_speed(void **state)
{
	(void)state;
	stale_one(true);
}

static void test_stale_force(void **state)
{
	(void)state;
	stale_one(false);
}

/* Nothing received at all: FAULT from the start, both stale bits. */
static void test_never_seen_is_fault(void **state)
{
	(void)state;
	boot(NULL);
	test_app_run_to(T0_US + 1000000U);
	assert_int_equal(last_state(NULL), MSG_SQUEAL_STATE_FAULT);
	assert_int_equal(first_status(T0_US, MSG_SQUEAL_STATE_FAULT, false), 0U);
	assert_int_equal(diag_faults_at(T0_US, NULL, NULL),
			 MSG_FAULT_SPEED_STALE | MSG_FAULT_FORCE_STALE);
}

/* ---- E2E ---------------------------------------------------------------------- */

static void test_bad_crc(void **state)
{
	hal_can_frame_t f;
	uint32_t page = 9U;
	const uint8_t *d = NULL;

	(void)state;
	boot(NULL);
	healthy_until(5U);
	/* k 5: a speed frame whose CRC byte was hit on the bus */
	f = test_frame_speed(&snd, SPEED_RAW, in_time(5U));
	f.data[0] ^= 0x10U;
	test_app_push(&f);
	f = test_frame_force(&snd, FORCE_RAW, in_time(5U));
	test_app_push(&f);
	/* k 6..: good again (the receiver has lost one counter value) */
	steady(6U, 220U);
	state_at(5U, MSG_SQUEAL_STATE_FAULT);
	assert_int_equal(first_status(in_time(5U), MSG_SQUEAL_STATE_FAULT, true), in_time(5U));
	assert_int_equal(monitor_fault_bits(mon()), MSG_FAULT_E2E_SPEED);
	state_at(6U, MSG_SQUEAL_STATE_STABLE);
	assert_int_equal(mon()->speed.count.e2e_wrong_crc, 1);
	assert_int_equal(mon()->speed.count.e2e_lost, 1);
	assert_int_equal(mon()->force.count.e2e_wrong_crc, 0);
	/* SquealDiag page 2 (at T0 + 2 s) counts it */
	test_app_run_to(T0_US + 2000000U);
	assert_int_equal(diag_faults_at(T0_US + 2000000U, &page, &d), 0U);
	assert_int_equal(page, 2);
	assert_int_equal(test_frame_sig(d, 32, 16), 1); /* E2eErrorCountSpeed */
	assert_int_equal(test_frame_sig(d, 48, 16), 0); /* E2eErrorCountForce */
}

/* A corrupted payload byte (CRC still the old one) is caught too, and a
 * sender that keeps failing shows E2E and stale in SquealDiag. */
static void test_bad_crc_persistent(void **state)
{
	uint32_t k;

	(void)state;
	boot(NULL);
	healthy_until(10U);
	for (k = 10U; k < 120U; k++) {
		hal_can_frame_t f = test_frame_force(&snd, FORCE_RAW, in_time(k));

		test_app_push(&f);
		f = test_frame_speed(&snd, SPEED_RAW, in_time(k));
		f.data[2] ^= 0x01U; /* payload bit flip */
		test_app_push(&f);
	}
	test_app_run_to(T0_US + 1000000U);
	assert_int_equal(diag_faults_at(T0_US + 1000000U, NULL, NULL),
			 MSG_FAULT_E2E_SPEED | MSG_FAULT_SPEED_STALE);
	assert_int_equal(mon()->speed.count.e2e_wrong_crc, 90); /* k 10..99 */
	assert_int_equal(mon()->speed.count.used, 10);
	assert_int_equal(last_state(NULL), MSG_SQUEAL_STATE_FAULT);
}

/* A frozen sender: the same frame (same counter) again and again. */
static uint64_t frozen_sender(void)
{
	hal_can_frame_t frozen;
	uint32_t k;
	uint64_t t_fault;

	boot(NULL);
	steady(0U, 9U);
	frozen = test_frame_speed(&snd, SPEED_RAW, in_time(9U));
	test_app_push(&frozen);
	for (k = 9U; k < 30U; k++) {
		hal_can_frame_t f = test_frame_force(&snd, FORCE_RAW, in_time(k));

		if (k > 9U) {
			frozen.timestamp_us = in_time(k);
			test_app_push(&frozen);
		}
		test_app_push(&f);
	}
	test_app_run_to(in_time(29U));
	t_fault = first_status(in_time(9U), MSG_SQUEAL_STATE_FAULT, true);
	assert_true(t_fault != 0U);
	return t_fault;
}

/* REPEATED frames are not used, so the input goes stale after 30 ms. */
static void test_repeated_counter_goes_stale(void **state)
{
	const uint64_t t_fault = frozen_sender();

	(void)state;
	assert_true(t_fault - in_time(9U) >= STALE_US);
	assert_true(t_fault - in_time(9U) <= STALE_US + 1000U);
	assert_true(mon()->speed.count.e2e_repeated > 0U);
	assert_int_equal(mon()->force.count.e2e_repeated, 0);
}

/*
 * ... and stays FAULT while the sender is frozen: the E2E reference is kept
 * when frames keep arriving (only real silence resets the receiver), so the
 * frozen frame stays REPEATED and is never used again.
 */
static void test_frozen_counter_stays_fault(void **state)
{
	uint64_t t_fault;
	uint64_t t_ok;

	(void)state;
	t_fault = frozen_sender();
	t_ok = first_status(t_fault, MSG_SQUEAL_STATE_FAULT, false);
	if (t_ok != 0U) {
		print_message("  frozen sender: FAULT at +%llu us after its last new frame, "
			      "not FAULT again at +%llu us (frozen frame used %u times in all, "
			      "stale events %u)\n",
			      (unsigned long long)(t_fault - in_time(9U)),
			      (unsigned long long)(t_ok - in_time(9U)),
			      mon()->speed.count.used - 10U, mon()->speed.count.stale_events);
	}
	assert_int_equal(t_ok, 0U);
	assert_int_equal(mon()->speed.count.used, 10);
	assert_int_equal(mon()->speed.count.stale_events, 1);
}

/* A counter jump beyond MaxDeltaCounter (2) is WRONGSEQUENCE: FAULT at
 * that frame; the next frame continuing the new sequence is usable. */
static void test_counter_jump(void **state)
{
	(void)state;
	boot(NULL);
	healthy_until(10U);
	snd.speed_counter = (uint8_t)((snd.speed_counter + 5U) % 15U); /* skips 5 */
	steady(10U, 12U);
	test_app_run_to(in_time(10U));
	assert_int_equal(first_status(in_time(10U), MSG_SQUEAL_STATE_FAULT, true), in_time(10U));
	assert_int_equal(monitor_fault_bits(mon()), MSG_FAULT_E2E_SPEED);
	assert_int_equal(mon()->speed.count.e2e_wrong_sequence, 1);
	state_at(11U, MSG_SQUEAL_STATE_STABLE);
	assert_int_equal(monitor_fault_bits(mon()), 0U);
	/* a jump within the tolerance (one frame lost) is fine */
	snd.force_counter = (uint8_t)((snd.force_counter + 1U) % 15U);
	steady(12U, 30U);
	test_app_run_to(in_time(29U));
	assert_int_equal(first_status(in_time(11U), MSG_SQUEAL_STATE_FAULT, true), 0U);
	assert_int_equal(mon()->force.count.e2e_lost, 1);
	assert_int_equal(mon()->force.count.e2e_wrong_sequence, 0);
}

/* Counter 15 is never sent by a P01 sender: rejected even with a good CRC. */
static void test_counter_15_rejected(void **state)
{
	hal_can_frame_t f;
	const e2e_p01_config_t cfg = { EXP_DBC_DISCSPEED_DATA_ID, 4U, 1U };
	uint8_t crc = 0U;

	(void)state;
	boot(NULL);
	healthy_until(10U);
	f = test_frame_speed(&snd, SPEED_RAW, in_time(10U));
	f.data[1] = (uint8_t)((f.data[1] & 0xF0U) | 0x0FU);
	assert_int_equal(e2e_p01_crc(&cfg, f.data, 4U, &crc), SQ_OK);
	f.data[0] = crc;
	test_app_push(&f);
	f = test_frame_force(&snd, FORCE_RAW, in_time(10U));
	test_app_push(&f);
	fault_at(10U, MSG_FAULT_E2E_SPEED);
}

/* ---- plausibility -------------------------------------------------------------- */

static void test_speed_out_of_range(void **state)
{
	calib_t cal;

	(void)state;
	calib_default(&cal);
	cal.speed_max_raw = 5000U; /* 50 rad/s */
	boot(&cal);
	pair(0U, 4990U, FORCE_RAW);
	pair(1U, 5000U, FORCE_RAW); /* the limit itself is plausible */
	pair(2U, 5001U, FORCE_RAW); /* one above: implausible */
	pair(3U, 4995U, FORCE_RAW);
	pair(4U, 0xFFFFU, FORCE_RAW); /* "not available" */
	pair(5U, 4995U, FORCE_RAW);
	state_at(1U, MSG_SQUEAL_STATE_STABLE);
	fault_at(2U, MSG_FAULT_SPEED_IMPLAUSIBLE);
	state_at(3U, MSG_SQUEAL_STATE_STABLE);
	fault_at(4U, MSG_FAULT_SPEED_IMPLAUSIBLE);
	state_at(5U, MSG_SQUEAL_STATE_STABLE);
	assert_int_equal(mon()->speed.count.implausible, 2);
}

static void test_force_out_of_range(void **state)
{
	(void)state;
	boot(NULL);
	pair(0U, SPEED_RAW, 59990U);
	pair(1U, SPEED_RAW, 60000U); /* default limit 30 kN */
	pair(2U, SPEED_RAW, 60001U);
	pair(3U, SPEED_RAW, 59999U);
	test_app_run_to(in_time(1U));
	assert_true(last_state(NULL) != MSG_SQUEAL_STATE_FAULT);
	fault_at(2U, MSG_FAULT_FORCE_IMPLAUSIBLE);
	test_app_run_to(in_time(3U));
	assert_true(last_state(NULL) != MSG_SQUEAL_STATE_FAULT);
	assert_int_equal(mon()->force.count.implausible, 1);
}

/* Rate limit (default 1000 raw = 10 rad/s per frame): a step of exactly
 * the limit passes; one more is implausible for one frame (a real step
 * then continues from the new value). */
static void test_speed_rate_limit(void **state)
{
	(void)state;
	boot(NULL);
	pair(0U, 2500U, FORCE_RAW);
	pair(1U, 3500U, FORCE_RAW); /* +1000 */
	pair(2U, 4501U, FORCE_RAW); /* +1001 */
	pair(3U, 4501U, FORCE_RAW);
	pair(4U, 3500U, FORCE_RAW); /* -1001 */
	pair(5U, 3400U, FORCE_RAW);
	state_at(1U, MSG_SQUEAL_STATE_STABLE);
	fault_at(2U, MSG_FAULT_SPEED_IMPLAUSIBLE);
	state_at(3U, MSG_SQUEAL_STATE_STABLE);
	assert_int_equal(mon()->speed.value, 4501 * 1200);
	state_at(4U, MSG_SQUEAL_STATE_FAULT);
	state_at(5U, MSG_SQUEAL_STATE_STABLE);
	assert_int_equal(mon()->speed.count.implausible, 2);
}

static void test_force_rate_limit(void **state)
{
	(void)state;
	boot(NULL);
	pair(0U, SPEED_RAW, 18000U);
	pair(1U, SPEED_RAW, 38000U); /* +20000: the limit */
	pair(2U, SPEED_RAW, 17999U); /* -20001 */
	test_app_run_to(in_time(1U));
	assert_int_equal(monitor_fault_bits(mon()), 0U);
	test_app_run_to(in_time(2U));
	assert_int_equal(monitor_fault_bits(mon()), MSG_FAULT_FORCE_IMPLAUSIBLE);
	assert_int_equal(last_state(NULL), MSG_SQUEAL_STATE_FAULT);
}

/* ---- frame format ----------------------------------------------------------- */

static void test_wrong_dlc(void **state)
{
	static const uint8_t dlcs[3] = { 3U, 5U, 8U };
	uint32_t i;

	(void)state;
	boot(NULL);
	healthy_until(5U);
	for (i = 0U; i < 3U; i++) {
		const uint32_t k = 5U + 2U * i;
		hal_can_frame_t f = test_frame_speed(&snd, SPEED_RAW, in_time(k));

		f.dlc = dlcs[i];
		test_app_push(&f);
		f = test_frame_force(&snd, FORCE_RAW, in_time(k));
		test_app_push(&f);
		pair(k + 1U, SPEED_RAW, FORCE_RAW);
		test_app_run_to(in_time(k));
		assert_int_equal(last_state(NULL), MSG_SQUEAL_STATE_FAULT);
		assert_int_equal(monitor_fault_bits(mon()), MSG_FAULT_E2E_SPEED);
		test_app_run_to(in_time(k + 1U));
		assert_int_equal(last_state(NULL), MSG_SQUEAL_STATE_STABLE);
	}
	assert_int_equal(mon()->speed.count.bad_dlc, 3);
	assert_int_equal(mon()->force.count.bad_dlc, 0);
	/* SquealDiag page 3 (T0 + 3 s): RxBadFrameCount */
	steady(11U, 310U);
	test_app_run_to(T0_US + 3000000U);
	{
		uint32_t page = 9U;
		const uint8_t *d = NULL;

		(void)diag_faults_at(T0_US + 3000000U, &page, &d);
		assert_int_equal(page, 3);
		assert_int_equal(test_frame_sig(d, 48, 16), 3);
	}
}

/* Unknown identifiers (the HAL filter off: a backend without one), remote
 * and extended frames on our IDs, error frames: counted, no effect. */
static void test_unknown_id_rtr_ext_error_frames(void **state)
{
	uint32_t k;
	uint32_t n_status_before;
	hal_can_frame_t f;

	(void)state;
	boot(NULL);
	healthy_until(5U);
	for (k = 5U; k < 25U; k++) {
		memset(&f, 0, sizeof(f));
		f.id = 0x123U;
		f.dlc = 8U;
		memset(f.data, 0xA5, 8U);
		f.timestamp_us = in_time(k) - 2000U;
		test_app_push(&f);
		f.id = MSG_DISC_SPEED_ID; /* RTR on our id */
		f.flags = HAL_CAN_FLAG_RTR;
		f.dlc = 0U;
		test_app_push(&f);
		f.flags = HAL_CAN_FLAG_EXT; /* 29-bit id equal to ours */
		f.dlc = 4U;
		test_app_push(&f);
		f.flags = HAL_CAN_FLAG_ERR;
		f.id = 0x4U; /* error class */
		test_app_push(&f);
	}
	steady(5U, 25U);
	n_status_before = mon()->count.state_changes;
	test_app_run_to(in_time(24U));
	assert_int_equal(mon()->count.unknown_id, 20);
	assert_int_equal(mon()->count.rtr_or_ext, 40);
	assert_int_equal(mon()->count.error_frames, 20);
	assert_int_equal(mon()->count.state_changes, n_status_before);
	assert_int_equal(first_status(in_time(4U), MSG_SQUEAL_STATE_STABLE, false), 0U);
	assert_int_equal(monitor_fault_bits(mon()), 0U);
	assert_int_equal(mon()->speed.count.frames, 25);
}

/* With the HAL's filter applied, only the two input IDs get through: the
 * app set exactly those. */
static void test_hal_filter_set_by_app(void **state)
{
	uint32_t ids[8] = { 0 };
	hal_can_frame_t f;

	(void)state;
	boot(NULL);
	assert_int_equal(test_hal_rx_filter(ids, 8U), 2);
	assert_int_equal(ids[0], EXP_DBC_DISCSPEED_ID);
	assert_int_equal(ids[1], EXP_DBC_PADFORCE_ID);
	test_hal_apply_rx_filter(true);
	memset(&f, 0, sizeof(f));
	f.id = 0x123U;
	f.dlc = 8U;
	f.timestamp_us = in_time(0U);
	test_app_push(&f);
	steady(0U, 3U);
	test_app_run_to(in_time(2U));
	assert_int_equal(mon()->count.unknown_id, 0);
	assert_int_equal(last_state(NULL), MSG_SQUEAL_STATE_STABLE);
}

/* ---- E2E switched off by calibration ----------------------------------------- */

static hal_can_frame_t plain(uint32_t id, uint16_t raw, uint64_t t_us)
{
	hal_can_frame_t f;

	memset(&f, 0, sizeof(f));
	f.id = id;
	f.dlc = 4U;
	f.data[0] = 0xA5U; /* garbage CRC */
	f.data[1] = 0x0FU; /* counter nibble 15, never changing */
	f.data[2] = (uint8_t)(raw & 0xFFU);
	f.data[3] = (uint8_t)(raw >> 8);
	f.timestamp_us = t_us;
	return f;
}

static void run_plain(void)
{
	uint32_t k;

	for (k = 0U; k < 20U; k++) {
		hal_can_frame_t f = plain(MSG_DISC_SPEED_ID, SPEED_RAW, in_time(k));

		test_app_push(&f);
		f = plain(MSG_PAD_FORCE_ID, FORCE_RAW, in_time(k));
		test_app_push(&f);
	}
	test_app_run_to(in_time(19U));
}

static void test_e2e_off_accepts_plain_frames(void **state)
{
	calib_t cal;

	(void)state;
	calib_default(&cal);
	cal.e2e_check_inputs = 0U;
	boot(&cal);
	run_plain();
	assert_int_equal(last_state(NULL), MSG_SQUEAL_STATE_STABLE);
	assert_int_equal(monitor_fault_bits(mon()), 0U);
	assert_int_equal(mon()->speed.count.used, 20);
	assert_int_equal(mon()->speed.value, SPEED_RAW * 1200);
	assert_int_equal(mon()->force.value, FORCE_RAW * 500);
	/* the same frames with E2E on (default): never used */
	boot(NULL);
	run_plain();
	assert_int_equal(last_state(NULL), MSG_SQUEAL_STATE_FAULT);
	assert_int_equal(mon()->speed.count.used, 0);
	assert_int_equal(mon()->speed.count.e2e_wrong_crc, 20);
}

SQ_CMOCKA_MAIN(
	cmocka_unit_test(test_stale_speed),
	cmocka_unit_test(test_stale_force),
	cmocka_unit_test(test_never_seen_is_fault),
	cmocka_unit_test(test_bad_crc),
	cmocka_unit_test(test_bad_crc_persistent),
	cmocka_unit_test(test_repeated_counter_goes_stale),
	cmocka_unit_test(test_frozen_counter_stays_fault),
	cmocka_unit_test(test_counter_jump),
	cmocka_unit_test(test_counter_15_rejected),
	cmocka_unit_test(test_speed_out_of_range),
	cmocka_unit_test(test_force_out_of_range),
	cmocka_unit_test(test_speed_rate_limit),
	cmocka_unit_test(test_force_rate_limit),
	cmocka_unit_test(test_wrong_dlc),
	cmocka_unit_test(test_unknown_id_rtr_ext_error_frames),
	cmocka_unit_test(test_hal_filter_set_by_app),
	cmocka_unit_test(test_e2e_off_accepts_plain_frames))
