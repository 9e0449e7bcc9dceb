/* SPDX-License-Identifier: MIT */
/*
 * squeal_app_next_event_us() (firmware/app/squeal_app.c) on the test HAL,
 * with the factory calibration (SquealStatus every 10 ms, SquealDetail
 * every 100 ms, SquealDiag every 1000 ms, inputs every 10 ms, stale after 3
 * missed periods):
 *   - the deadlines by hand: the first tick at init, then the next status
 *     period, the staleness timeout of silent inputs;
 *   - the next tick after a frame was taken;
 *   - a drive (inputs, a silence that makes them stale, inputs again), run
 *     every 1 ms: each tick before the reported time sends nothing and
 *     leaves every monitor as it was (but its clock), and most ticks are such;
 *   - the same drive with those ticks skipped (squeal_app_skip_to_us, as
 *     replay does): after every tick, run or skipped, each monitor's memory
 *     and the frames sent are those of the drive run every 1 ms.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "monitor.h"
#include "sq_status.h"
#include "squeal_app.h"
#include "test_hal.h"

#define T0_US 1000000ULL
#define TICK_US 1000ULL
#define SPEED_RAW 2500U
#define FORCE_RAW 18000U

static test_sender_t snd;

static void start(void)
{
	test_hal_reset();
	test_hal_set_time_us(T0_US);
	test_sender_init(&snd);
	(void)squeal_app_init();
}

static void tick(void)
{
	test_hal_advance_us(TICK_US);
	(void)squeal_app_poll();
}

static void test_deadlines_by_hand(void **state)
{
	(void)state;
	start();
	/* every periodic message is due at start: the first tick */
	assert_int_equal(squeal_app_next_event_us(), T0_US);
	(void)squeal_app_poll();
	assert_true(test_hal_tx_count() > 0U);
	/* the next SquealStatus; the inputs (never seen) go stale later,
	 * 30 ms + 1 us after init */
	assert_int_equal(squeal_app_next_event_us(), T0_US + 10000U);
	while (hal_time_us() < T0_US + 10000U) {
		tick();
	}
	assert_int_equal(squeal_app_next_event_us(), T0_US + 20000U);
	while (hal_time_us() < T0_US + 30000U) {
		tick();
	}
	/* the status at 30 ms has gone; the inputs go stale at 30.001 ms:
	 * never earlier than the next tick, 31 ms, which takes it */
	assert_int_equal(squeal_app_next_event_us(), T0_US + 31000U);
	tick();
	assert_int_equal(squeal_app_monitor()->speed.count.stale_events, 1U);
	assert_int_equal(squeal_app_next_event_us(), T0_US + 40000U);
}

static void test_a_frame_makes_the_next_tick_due(void **state)
{
	(void)state;
	start();
	(void)squeal_app_poll();
	tick();
	assert_int_equal(test_send_pair(&snd, SPEED_RAW, FORCE_RAW, hal_time_us()), SQ_OK);
	/* queued, not yet taken: the caller's event, nothing pending */
	assert_int_equal(squeal_app_next_event_us(), T0_US + 10000U);
	/* a poll between ticks takes the frames in: the next tick is due */
	test_hal_advance_us(300U);
	(void)squeal_app_poll();
	assert_int_equal(squeal_app_next_event_us(), T0_US + 2000U);
	tick(); /* 1.3 ms after the tick: the late tick runs at once */
	assert_true(squeal_app_next_event_us() > hal_time_us());
}

/* Inputs at 5 ms + 10 ms k, but not in [500, 800) ms: stale, then back. */
static bool input_at(uint64_t t_us)
{
	const uint64_t dt = t_us - T0_US;

	return ((dt % 10000U) == 5000U) && ((dt < 500000U) || (dt >= 800000U));
}

static void test_ticks_before_the_event_change_nothing(void **state)
{
	static monitor_t before[CALIB_MAX_CORNERS];
	uint32_t idle = 0U;
	uint32_t ticks = 0U;
	uint32_t k;

	(void)state;
	start();
	(void)squeal_app_poll();
	while (hal_time_us() < T0_US + 1500000U) {
		const uint64_t ev = squeal_app_next_event_us();
		const uint64_t now = hal_time_us() + TICK_US;
		const uint32_t sent = test_hal_tx_count();
		const bool frame = input_at(now);

		if (frame) {
			assert_int_equal(test_send_pair(&snd, SPEED_RAW, FORCE_RAW, now), SQ_OK);
		}
		for (k = 0U; k < squeal_app_corner_count(); k++) {
			before[k] = *squeal_app_corner(k);
		}
		tick();
		ticks++;
		if (frame || (now >= ev)) {
			continue;
		}
		idle++;
		assert_int_equal(test_hal_tx_count(), sent);
		for (k = 0U; k < squeal_app_corner_count(); k++) {
			before[k].now_us = squeal_app_corner(k)->now_us;
			assert_memory_equal(&before[k], squeal_app_corner(k), sizeof(before[k]));
		}
	}
	/* the inputs went stale once (the silence) and came back */
	assert_int_equal(squeal_app_monitor()->speed.count.stale_events, 1U);
	assert_int_equal(squeal_app_monitor()->state != MONITOR_STATE_FAULT, true);
	/* frames every 10 ms, statuses every 10 ms: 8 of 10 ticks are idle */
	assert_true(idle * 10U >= ticks * 7U);
}

#define DRIVE_TICKS 1500U

/* FNV-1a over every corner's monitor: the state after one tick. */
static uint64_t monitors_hash(void)
{
	uint64_t h = 14695981039346656037ULL;
	uint32_t k;

	for (k = 0U; k < squeal_app_corner_count(); k++) {
		const uint8_t *p = (const uint8_t *)squeal_app_corner(k);
		size_t i;

		for (i = 0U; i < sizeof(monitor_t); i++) {
			h = (h ^ p[i]) * 1099511628211ULL;
		}
	}
	return h;
}

/* The drive of test_ticks_before_the_event_change_nothing, each tick run
 * (skip false) or, before the reported event, skipped; the state and the
 * frames sent so far after each tick. */
static void drive(bool skip, uint64_t hash[DRIVE_TICKS], uint32_t sent[DRIVE_TICKS],
		  uint32_t *skipped)
{
	uint32_t i;

	start();
	(void)squeal_app_poll();
	*skipped = 0U;
	for (i = 0U; i < DRIVE_TICKS; i++) {
		const uint64_t ev = squeal_app_next_event_us();
		const uint64_t now = hal_time_us() + TICK_US;
		const bool frame = input_at(now);

		if (frame) {
			assert_int_equal(test_send_pair(&snd, SPEED_RAW, FORCE_RAW, now), SQ_OK);
		}
		if (skip && !frame && (now < ev)) {
			test_hal_set_time_us(now);
			squeal_app_skip_to_us(now);
			(*skipped)++;
		} else {
			tick();
		}
		hash[i] = monitors_hash();
		sent[i] = test_hal_tx_count();
	}
}

static void test_skipped_ticks_leave_what_running_them_leaves(void **state)
{
	static uint64_t hash[2][DRIVE_TICKS];
	static uint32_t sent[2][DRIVE_TICKS];
	uint32_t skipped[2];
	uint32_t i;

	(void)state;
	drive(false, hash[0], sent[0], &skipped[0]);
	drive(true, hash[1], sent[1], &skipped[1]);
	for (i = 0U; i < DRIVE_TICKS; i++) {
		assert_int_equal(hash[1][i], hash[0][i]);
		assert_int_equal(sent[1][i], sent[0][i]);
	}
	assert_int_equal(skipped[0], 0U);
	assert_true(skipped[1] * 10U >= DRIVE_TICKS * 7U);
	/* a time before the last tick run changes nothing */
	squeal_app_skip_to_us(hal_time_us() - 5U * TICK_US);
	assert_int_equal(monitors_hash(), hash[0][DRIVE_TICKS - 1U]);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_deadlines_by_hand),
		cmocka_unit_test(test_a_frame_makes_the_next_tick_due),
		cmocka_unit_test(test_ticks_before_the_event_change_nothing),
		cmocka_unit_test(test_skipped_ticks_leave_what_running_them_leaves),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
