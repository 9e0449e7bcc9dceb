/* SPDX-License-Identifier: MIT */
/*
 * The scheduler (firmware/app/squeal_app.c) on the test HAL: calibration
 * from storage (absent, valid, corrupt, unreadable, out of range), CAN
 * filters, watchdog, task timing, platform faults, bus-off and recovery,
 * TX queue full, RX budget. Outputs are read from the TX log and decoded
 * by hand from the DBC layout.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "calib.h"
#include "e2e_p01.h"
#include "monitor.h"
#include "monitor_expect.h"
#include "sq_status.h"
#include "squeal_app.h"
#include "test_hal.h"

#define T0_US 1000000ULL
#define IN_OFFSET_US 5000ULL
#define IN_PERIOD_US 10000ULL
#define SPEED_RAW 2500U  /* v0 3 m/s: stable at 9 kN */
#define FORCE_RAW 18000U

static test_sender_t snd;

static uint64_t in_time(uint32_t k)
{
	return T0_US + IN_OFFSET_US + IN_PERIOD_US * k;
}

static void run_to(uint64_t t_us)
{
	while (hal_time_us() < t_us) {
		test_hal_advance_us(1000U);
		(void)squeal_app_poll();
	}
}

static void steady(uint32_t k_from, uint32_t k_to)
{
	for (uint32_t k = k_from; k < k_to; k++) {
		assert_int_equal(test_send_pair(&snd, SPEED_RAW, FORCE_RAW, in_time(k)), SQ_OK);
	}
}

static void fresh(void)
{
	test_hal_reset();
	test_hal_set_time_us(T0_US);
	test_sender_init(&snd);
}

static void store(const calib_t *cal)
{
	uint8_t buf[CALIB_BLOCK_LEN];

	assert_int_equal(calib_encode(cal, buf, sizeof(buf)), SQ_OK);
	test_hal_calib_store(buf, sizeof(buf));
}

/* The app's calibration, as the block it would store. */
static void app_block(uint8_t *buf)
{
	assert_int_equal(calib_encode(squeal_app_monitor()->cal, buf, CALIB_BLOCK_LEN), SQ_OK);
}

static void default_block(uint8_t *buf)
{
	calib_t cal;

	calib_default(&cal);
	assert_int_equal(calib_encode(&cal, buf, CALIB_BLOCK_LEN), SQ_OK);
}

/* fault bits of the SquealDiag frame sent at t_us (the first step sends
 * one at once) */
static uint16_t diag_faults_at(uint64_t t_us, const uint8_t **data)
{
	const hal_can_frame_t *f = test_hal_tx_at(EXP_DBC_SQUEALDIAG_ID, t_us);

	if (f == NULL) {
		fail_msg("no SquealDiag at %llu us", (unsigned long long)t_us);
		return 0U;
	}
	if (data != NULL) {
		*data = f->data;
	}
	return (uint16_t)test_frame_sig(f->data, 16, 11);
}

/* ---- calibration from storage ---------------------------------------------- */

static void test_no_calibration_stored_defaults_without_fault(void **state)
{
	uint8_t a[CALIB_BLOCK_LEN];
	uint8_t b[CALIB_BLOCK_LEN];

	(void)state;
	fresh();
	test_hal_calib_absent();
	assert_int_equal(squeal_app_init(), SQ_OK);
	assert_int_equal(squeal_app_init_status(), SQ_OK);
	(void)squeal_app_poll();
	app_block(a);
	default_block(b);
	assert_memory_equal(a, b, CALIB_BLOCK_LEN);
	assert_int_equal(diag_faults_at(T0_US, NULL) & MSG_FAULT_CALIB_INVALID, 0U);
	assert_false(squeal_app_monitor()->calib_invalid);
}

static void test_valid_calibration_is_used(void **state)
{
	calib_t cal;
	hal_can_frame_t f;
	uint32_t n_status = 0U;
	int32_t i = -1;

	(void)state;
	fresh();
	calib_default(&cal);
	cal.status_id = 0x310U;
	cal.disc_speed_id = 0x120U;
	cal.status_period_ms = 20U;
	cal.watchdog_ms = 250U;
	store(&cal);
	assert_int_equal(squeal_app_init(), SQ_OK);
	assert_int_equal(test_hal_watchdog_timeout_ms(), 250);
	{
		uint32_t ids[8];

		assert_int_equal(test_hal_rx_filter(ids, 8U), 2);
		assert_int_equal(ids[0], 0x120);
		assert_int_equal(ids[1], EXP_DBC_PADFORCE_ID);
	}
	(void)squeal_app_poll();
	/* speed frames on the calibrated identifier are used */
	for (uint32_t k = 0U; k < 20U; k++) {
		f = test_frame_speed(&snd, SPEED_RAW, in_time(k));
		f.id = 0x120U;
		assert_int_equal(test_hal_rx_push(&f), SQ_OK);
		f = test_frame_force(&snd, FORCE_RAW, in_time(k));
		assert_int_equal(test_hal_rx_push(&f), SQ_OK);
	}
	run_to(T0_US + 200000U);
	assert_int_equal(squeal_app_monitor()->speed.count.used, 20);
	assert_int_equal(squeal_app_monitor()->state, MSG_SQUEAL_STATE_STABLE);
	assert_int_equal(test_hal_tx_find(EXP_DBC_SQUEALSTATUS_ID, 0U), -1);
	while ((i = test_hal_tx_find(0x310U, (uint32_t)(i + 1))) >= 0) {
		const uint64_t t = test_hal_tx_frame((uint32_t)i)->timestamp_us;

		if (t != in_time(0)) { /* the state change is extra */
			assert_int_equal((t - T0_US) % 20000U, 0);
			n_status++;
		}
	}
	assert_int_equal(n_status, 200000U / 20000U + 1U); /* T0 .. T0 + 200 ms */
}

/* Corrupt block: every single-byte corruption (XOR 0x01 and 0xFF at each
 * byte) makes the app start with the defaults and report CalibInvalid. */
static void test_corrupt_calibration_rejected_whole(void **state)
{
	calib_t cal;
	uint8_t good[CALIB_BLOCK_LEN];
	uint8_t bad[CALIB_BLOCK_LEN];
	uint8_t a[CALIB_BLOCK_LEN];
	uint8_t def[CALIB_BLOCK_LEN];
	static const uint8_t pat[2] = { 0x01U, 0xFFU };

	(void)state;
	/* a valid block that differs from the defaults in many fields */
	calib_default(&cal);
	cal.slope_q24 = 3 << 24;
	cal.debounce_count = 7U;
	cal.status_period_ms = 20U;
	cal.rho_warn_ppm = 300000U;
	cal.v0_min_umps = 20000U;
	assert_int_equal(calib_encode(&cal, good, sizeof(good)), SQ_OK);
	default_block(def);
	for (uint32_t i = 0; i < CALIB_BLOCK_LEN; i++) {
		for (uint32_t p = 0; p < 2U; p++) {
			memcpy(bad, good, sizeof(bad));
			bad[i] ^= pat[p];
			fresh();
			test_hal_calib_store(bad, sizeof(bad));
			assert_int_equal(squeal_app_init(), SQ_EBADMSG);
			(void)squeal_app_poll();
			app_block(a);
			if (memcmp(a, def, CALIB_BLOCK_LEN) != 0) {
				fail_msg("byte %u ^ 0x%02x: not the defaults", i, pat[p]);
			}
			assert_true(squeal_app_monitor()->calib_invalid);
			assert_true((diag_faults_at(T0_US, NULL) & MSG_FAULT_CALIB_INVALID) != 0U);
		}
	}
	/* and the good one is taken */
	fresh();
	test_hal_calib_store(good, sizeof(good));
	assert_int_equal(squeal_app_init(), SQ_OK);
	app_block(a);
	assert_memory_equal(a, good, CALIB_BLOCK_LEN);
}

/* An out-of-range field under a correct CRC (e.g. written by a broken
 * tool): rejected whole, defaults, CalibInvalid. */
static void test_out_of_range_calibration_rejected(void **state)
{
	calib_t cal;
	uint8_t buf[CALIB_BLOCK_LEN];
	uint8_t a[CALIB_BLOCK_LEN];
	uint8_t def[CALIB_BLOCK_LEN];

	(void)state;
	calib_default(&cal);
	cal.debounce_count = 9U;
	assert_int_equal(calib_encode(&cal, buf, sizeof(buf)), SQ_OK);
	buf[56] = 15U; /* e2e_max_delta_counter: 1..14 */
	buf[99] = 0U;  /* CRC recomputed below with the firmware's own CRC,
			* which test_calib checks against the definition */
	{
		const uint32_t crc = calib_crc32(0U, buf, 99U);

		buf[99] = (uint8_t)crc;
		buf[100] = (uint8_t)(crc >> 8);
		buf[101] = (uint8_t)(crc >> 16);
		buf[102] = (uint8_t)(crc >> 24);
	}
	fresh();
	test_hal_calib_store(buf, sizeof(buf));
	assert_int_equal(squeal_app_init(), SQ_EBADMSG);
	(void)squeal_app_poll();
	app_block(a);
	default_block(def);
	assert_memory_equal(a, def, CALIB_BLOCK_LEN); /* debounce 9 not taken */
	assert_true((diag_faults_at(T0_US, NULL) & MSG_FAULT_CALIB_INVALID) != 0U);
}

static void test_calibration_read_error(void **state)
{
	calib_t cal;
	uint8_t a[CALIB_BLOCK_LEN];
	uint8_t def[CALIB_BLOCK_LEN];

	(void)state;
	fresh();
	calib_default(&cal);
	cal.debounce_count = 9U;
	store(&cal);
	test_hal_calib_read_error(true);
	assert_int_equal(squeal_app_init(), SQ_EBADMSG);
	(void)squeal_app_poll();
	app_block(a);
	default_block(def);
	assert_memory_equal(a, def, CALIB_BLOCK_LEN);
	assert_true((diag_faults_at(T0_US, NULL) & MSG_FAULT_CALIB_INVALID) != 0U);
	/* the monitor still works on the defaults */
	steady(0U, 3U);
	run_to(in_time(2U));
	assert_int_equal(squeal_app_monitor()->state, MSG_SQUEAL_STATE_STABLE);
}

/* ---- scheduler --------------------------------------------------------------- */

static void test_watchdog_kicked_every_tick(void **state)
{
	(void)state;
	fresh();
	assert_int_equal(squeal_app_init(), SQ_OK);
	assert_int_equal(test_hal_watchdog_timeout_ms(), 100); /* default */
	(void)squeal_app_poll();
	run_to(T0_US + 500000U);
	assert_int_equal(test_hal_watchdog_kicks(), 501);
	/* polling again within the same millisecond does no task */
	(void)squeal_app_poll();
	(void)squeal_app_poll();
	assert_int_equal(test_hal_watchdog_kicks(), 501);
	/* the returned deadline is the next tick */
	assert_int_equal(squeal_app_poll(), T0_US + 501000U);
}

/* squeal_main: init, then poll + idle until *stop (the test HAL's idle
 * jumps the clock, so a stopped loop returns at once). */
static void test_squeal_main_returns_init_status(void **state)
{
	static volatile bool stop = true;

	(void)state;
	fresh();
	test_hal_calib_read_error(true);
	assert_int_equal(squeal_main(&stop), SQ_EBADMSG);
}

/* Task time through hal_cycles(): reported as WorstTaskTime_us (page 1). */
static void test_worst_task_time_reported(void **state)
{
	const uint8_t *d = NULL;

	(void)state;
	fresh();
	/* every hal_cycles() call costs 42 us worth of cycles */
	test_hal_set_cycles_per_call(42U * TEST_HAL_CYCLES_PER_US);
	assert_int_equal(squeal_app_init(), SQ_OK);
	(void)squeal_app_poll();
	run_to(T0_US + 1000000U);
	(void)diag_faults_at(T0_US + 1000000U, &d);
	assert_int_equal(test_frame_sig(d, 12, 4), 1); /* page 1 */
	assert_int_equal(test_frame_sig(d, 32, 16), 42);
	assert_int_equal(squeal_app_monitor()->worst_task_us, 42);
}

static void test_platform_faults_reported(void **state)
{
	(void)state;
	fresh();
	test_hal_set_platform_faults(HAL_FAULT_CLOCK_FALLBACK | HAL_FAULT_CAN_INIT);
	assert_int_equal(squeal_app_init(), SQ_OK);
	(void)squeal_app_poll();
	assert_int_equal(diag_faults_at(T0_US, NULL),
			 MSG_FAULT_CLOCK_FALLBACK | MSG_FAULT_CAN_INIT |
			 MSG_FAULT_SPEED_STALE | MSG_FAULT_FORCE_STALE);
}

/* More frames than one poll takes (RX budget): none lost, all handled
 * within a few ticks. */
static void test_rx_burst(void **state)
{
	hal_can_frame_t f;

	(void)state;
	fresh();
	assert_int_equal(squeal_app_init(), SQ_OK);
	memset(&f, 0, sizeof(f));
	f.id = 0x222U;
	f.dlc = 1U;
	f.timestamp_us = T0_US;
	for (uint32_t i = 0; i < 1000U; i++) {
		assert_int_equal(test_hal_rx_push(&f), SQ_OK);
	}
	(void)squeal_app_poll();
	assert_true(squeal_app_monitor()->count.unknown_id < 1000U);
	run_to(T0_US + 20000U);
	assert_int_equal(squeal_app_monitor()->count.unknown_id, 1000);
	assert_int_equal(test_hal_rx_pending(), 0);
}

/* ---- bus-off ----------------------------------------------------------------- */

/*
 * Bus-off for 200 ms: hal_can_send says SQ_ENETUNREACH, the monitor counts
 * TX errors and goes on classifying (RX still works); after recovery the
 * periodic frames go out again, BusOffSeen stays latched, BusOffCount 1.
 */
static void test_bus_off_and_recovery(void **state)
{
	const uint8_t *d = NULL;
	uint32_t n_before;
	uint32_t n_during;

	(void)state;
	fresh();
	assert_int_equal(squeal_app_init(), SQ_OK);
	(void)squeal_app_poll();
	steady(0U, 300U);
	run_to(T0_US + 1500000U);
	assert_int_equal(diag_faults_at(T0_US + 1000000U, NULL), 0U);
	n_before = test_hal_tx_count();
	test_hal_bus_off();
	run_to(T0_US + 1700000U);
	n_during = test_hal_tx_count();
	assert_int_equal(n_during, n_before);
	assert_true(squeal_app_monitor()->count.tx_errors >= 20U);
	assert_true(squeal_app_monitor()->bus_off_seen);
	assert_int_equal(squeal_app_monitor()->state, MSG_SQUEAL_STATE_STABLE);
	assert_true(squeal_app_monitor()->speed.count.used >= 170U);
	print_message("  bus-off 200 ms: %u frames refused by the HAL, monitor tx_errors %u, "
		      "tx_overflow %u\n", test_hal_tx_rejected(),
		      squeal_app_monitor()->count.tx_errors,
		      squeal_app_monitor()->count.tx_overflow);
	test_hal_bus_recover();
	run_to(T0_US + 3000000U);
	assert_true(test_hal_tx_count() > n_during);
	/* status frames resume within one period of recovery */
	{
		const int32_t i = test_hal_tx_find(EXP_DBC_SQUEALSTATUS_ID, n_during);

		assert_true(i >= 0);
		assert_true(test_hal_tx_frame((uint32_t)i)->timestamp_us <= T0_US + 1710000U);
	}
	/* latched; pages: 2 s -> page 2, 3 s -> page 3, 4 s -> page 4 (self-test), 5 s -> page 0 */
	assert_true((diag_faults_at(T0_US + 2000000U, NULL) & MSG_FAULT_BUS_OFF_SEEN) != 0U);
	assert_true((diag_faults_at(T0_US + 3000000U, NULL) & MSG_FAULT_BUS_OFF_SEEN) != 0U);
	steady(300U, 500U);
	run_to(T0_US + 5000000U);
	assert_true((diag_faults_at(T0_US + 5000000U, &d) & MSG_FAULT_BUS_OFF_SEEN) != 0U);
	assert_int_equal(test_frame_sig(d, 12, 4), 0); /* page 0 */
	assert_int_equal(test_frame_sig(d, 56, 8), 1); /* BusOffCount */
	assert_int_equal(test_frame_sig(d, 32, 24), 5); /* Uptime_s */
}

/* ---- TX queue full --------------------------------------------------------------- */

/*
 * hal_can_send returns SQ_ENOBUFS for 100 ms: the frames wait in the
 * monitor's queue (retried every tick), what does not fit is counted as
 * overflow; afterwards the waiting frames go out first, in order, and the
 * monitor carries on. TxOverflow shows in SquealDiag.
 */
static void test_tx_queue_full(void **state)
{
	uint8_t last_ctr;
	int32_t i;
	uint32_t n_before;
	const uint8_t *d = NULL;

	(void)state;
	fresh();
	assert_int_equal(squeal_app_init(), SQ_OK);
	(void)squeal_app_poll();
	steady(0U, 400U);
	run_to(T0_US + 1500000U);
	n_before = test_hal_tx_count();
	/* the last status frame before the queue fills */
	i = -1;
	{
		int32_t j = -1;

		while ((j = test_hal_tx_find(EXP_DBC_SQUEALSTATUS_ID, (uint32_t)(j + 1))) >= 0) {
			i = j;
		}
	}
	assert_true(i >= 0);
	last_ctr = test_hal_tx_frame((uint32_t)i)->data[1] & 0x0FU;
	test_hal_set_tx_full(true);
	run_to(T0_US + 1600000U);
	assert_int_equal(test_hal_tx_count(), n_before);
	assert_int_equal(squeal_app_monitor()->txq_count, MONITOR_TX_QUEUE_LEN);
	assert_true(squeal_app_monitor()->count.tx_overflow > 0U);
	/* retried every tick from the first due frame (T0 + 1.51 s) on */
	assert_true(test_hal_tx_rejected() >= 90U);
	test_hal_set_tx_full(false);
	run_to(T0_US + 1601000U);
	/* the queued frames went out first: the first status frame now is the
	 * one protected right after the last one sent (nothing lost before
	 * the queue was full) */
	i = test_hal_tx_find(EXP_DBC_SQUEALSTATUS_ID, n_before);
	assert_true(i >= 0);
	assert_int_equal(test_hal_tx_frame((uint32_t)i)->data[1] & 0x0FU, (last_ctr + 1U) % 15U);
	assert_true(test_hal_tx_count() - n_before >= MONITOR_TX_QUEUE_LEN);
	run_to(T0_US + 3000000U);
	assert_true((diag_faults_at(T0_US + 2000000U, NULL) & MSG_FAULT_TX_OVERFLOW) != 0U);
	(void)diag_faults_at(T0_US + 3000000U, &d);
	assert_int_equal(test_frame_sig(d, 12, 4), 3); /* page 3 */
	assert_int_equal(test_frame_sig(d, 32, 16), squeal_app_monitor()->count.tx_overflow);
	assert_int_equal(squeal_app_monitor()->state, MSG_SQUEAL_STATE_STABLE);
	print_message("  TX full 100 ms: %u HAL refusals, %u frames dropped as overflow\n",
		      test_hal_tx_rejected(), squeal_app_monitor()->count.tx_overflow);
}

/* A stopped controller: receive says ENETDOWN; the app keeps its tick. */
static void test_can_stopped(void **state)
{
	(void)state;
	fresh();
	assert_int_equal(squeal_app_init(), SQ_OK);
	test_hal_set_can_stopped(true);
	steady(0U, 10U);
	run_to(T0_US + 100000U);
	assert_int_equal(test_hal_tx_count(), 0);
	assert_int_equal(test_hal_watchdog_kicks(), 100);
	assert_int_equal(squeal_app_monitor()->state, MSG_SQUEAL_STATE_FAULT);
	test_hal_set_can_stopped(false);
	steady(10U, 20U);
	run_to(in_time(19U));
	assert_int_equal(squeal_app_monitor()->state, MSG_SQUEAL_STATE_STABLE);
}

SQ_CMOCKA_MAIN(
	cmocka_unit_test(test_no_calibration_stored_defaults_without_fault),
	cmocka_unit_test(test_valid_calibration_is_used),
	cmocka_unit_test(test_corrupt_calibration_rejected_whole),
	cmocka_unit_test(test_out_of_range_calibration_rejected),
	cmocka_unit_test(test_calibration_read_error),
	cmocka_unit_test(test_watchdog_kicked_every_tick),
	cmocka_unit_test(test_squeal_main_returns_init_status),
	cmocka_unit_test(test_worst_task_time_reported),
	cmocka_unit_test(test_platform_faults_reported),
	cmocka_unit_test(test_rx_burst),
	cmocka_unit_test(test_bus_off_and_recovery),
	cmocka_unit_test(test_tx_queue_full),
	cmocka_unit_test(test_can_stopped))
