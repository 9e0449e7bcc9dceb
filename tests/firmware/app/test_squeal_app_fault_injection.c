/* SPDX-License-Identifier: MIT */
/*
 * Fault injection through the whole firmware (squeal_app_init/poll on the
 * test HAL, one poll per virtual millisecond), beyond the single faults of
 * test_monitor_faults.c and test_app.c: dropouts of every length, the alive
 * counter wrapping and jumping by every size, CRC storms, every wrong DLC,
 * bus-off with frames waiting in the queue, the TX queue full for 5 s, a
 * clock jump of 10 s, frame timestamps in the future, and 10^6 healthy
 * steps. Every scenario checks the fault bit, the exact counters, the time
 * the state takes to fall to FAULT (15) and that it recovers.
 *
 * Operating point: v0 = 3 m/s (Omega 25 rad/s at r_p 0.12 m), N = 9000 N:
 * stable (stable border 2.07 m/s), so a healthy input gives SquealState 0.
 *
 * Expected values are derived by hand from the calibration defaults and the
 * DBC periods, never read back from the firmware:
 *   - input period 10 ms, stale_cycles 3: an input is stale when no frame
 *     was used for more than 30 ms; the 1 ms task notices it in the first
 *     step after that, so FAULT is sent 30..31 ms after the last used frame
 *     (the documented stale_cycles x period + 1 ms);
 *   - E2E P01 with MaxDeltaCounterInit 2: the receiver lets the tolerated
 *     jump grow by one on every check (AUTOSAR P01: before the comparison),
 *     and the monitor checks once per received frame, so a counter delta of
 *     2 or 3 (one or two frames lost) is OKSOMELOST and 4..14 is
 *     WRONGSEQUENCE; after a silence longer than the stale timeout the
 *     receiver starts over (the next frame is INITIAL, whatever its counter);
 *   - frames produced by the monitor while every tick runs: SquealStatus at
 *     T0 + n x 10 ms plus one at every state change off that grid,
 *     SquealDetail + SquealDetail2 at T0 + n x 100 ms, SquealDiag at
 *     T0 + n x 1 s (pages 0, 1, 2, 3 in turn, page 0 at T0).
 * Inputs are sent at T0 + 5 ms + k x 10 ms (off the status grid), so every
 * state change adds exactly one status frame.
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
#include "fault_drive.h"
#include "monitor.h"
#include "monitor_expect.h"
#include "sq_status.h"
#include "squeal_app.h"
#include "test_app_drive.h"
#include "test_hal.h"

#define TICK_US 1000ULL
#define STATUS_US 10000ULL
#define DETAIL_US 100000ULL
#define DIAG_US 1000000ULL

#define ST_STABLE 0U
#define ST_FAULT 15U

/* SquealDiag fault bits, bit positions from the DBC (Fault_* signals) */
#define F_SPEED_STALE (1U << 0)
#define F_FORCE_STALE (1U << 1)
#define F_E2E_SPEED (1U << 2)
#define F_E2E_FORCE (1U << 3)
#define F_BUS_OFF_SEEN (1U << 7)
#define F_TX_OVERFLOW (1U << 10)

static test_sender_t snd;

static const monitor_t *mon(void)
{
	return squeal_app_monitor();
}

static void boot(void)
{
	test_app_boot(NULL, T0_US);
	test_sender_init(&snd);
}

static void pair(uint32_t k)
{
	assert_int_equal(test_send_pair(&snd, SPEED_RAW, FORCE_RAW, in_time(k)), SQ_OK);
}

static void steady(uint32_t k_from, uint32_t k_to)
{
	for (uint32_t k = k_from; k < k_to; k++) {
		pair(k);
	}
}

/* one input's frame at k (speed or force), from the shared sender */
static hal_can_frame_t frame_of(bool speed, uint32_t k)
{
	return speed ? test_frame_speed(&snd, SPEED_RAW, in_time(k)) :
		test_frame_force(&snd, FORCE_RAW, in_time(k));
}

static const input_counters_t *cnt(bool speed)
{
	return speed ? &mon()->speed.count : &mon()->force.count;
}

/* Frames the monitor has produced in the ticks T0 .. t_us (every tick run),
 * with `extra` status frames from state changes off the 10 ms grid. */
static uint64_t produced(uint64_t t_us, uint64_t extra)
{
	const uint64_t dt = t_us - T0_US;

	return (dt / STATUS_US + 1U) + extra + 2U * (dt / DETAIL_US + 1U) + (dt / DIAG_US + 1U);
}

/* The first SquealStatus sent at or after t_us whose state is (want) or is
 * not (!want) st: its time, or 0. */
static uint64_t first_status(uint64_t t_us, uint8_t st, bool want)
{
	return test_app_tx_first(EXP_DBC_SQUEALSTATUS_ID, t_us, 12, 4, st, want);
}

static uint8_t last_state(void)
{
	return (uint8_t)test_app_tx_last_sig(EXP_DBC_SQUEALSTATUS_ID, 12, 4);
}

/* The SquealDiag sent at t_us: fault bits; page and payload if asked. */
static uint16_t diag_at(uint64_t t_us, uint32_t *page, const uint8_t **data)
{
	return test_app_diag_at(EXP_DBC_SQUEALDIAG_ID, t_us, page, data);
}

static void assert_no_e2e_errors(bool speed)
{
	assert_int_equal(cnt(speed)->e2e_wrong_crc, 0);
	assert_int_equal(cnt(speed)->e2e_wrong_sequence, 0);
	assert_int_equal(cnt(speed)->e2e_repeated, 0);
	assert_int_equal(cnt(speed)->bad_dlc, 0);
	assert_int_equal(cnt(speed)->implausible, 0);
}

/* What both inputs' counters must read; ANY: not checked, a field left out
 * of the initializer: 0. */
#define ANY (-1LL)
typedef struct {
	long long frames, used, lost, stale_events;
	long long wrong_crc, wrong_sequence, repeated, bad_dlc, implausible;
} want_counts_t;

static void expect_count(uint32_t have, long long want)
{
	if (want != ANY) {
		assert_int_equal(have, want);
	}
}

static void expect_counts(want_counts_t w)
{
	for (uint32_t s = 0U; s < 2U; s++) {
		const input_counters_t *c = cnt(s == 0U);

		expect_count(c->frames, w.frames);
		expect_count(c->used, w.used);
		expect_count(c->e2e_lost, w.lost);
		expect_count(c->stale_events, w.stale_events);
		expect_count(c->e2e_wrong_crc, w.wrong_crc);
		expect_count(c->e2e_wrong_sequence, w.wrong_sequence);
		expect_count(c->e2e_repeated, w.repeated);
		expect_count(c->bad_dlc, w.bad_dlc);
		expect_count(c->implausible, w.implausible);
	}
}

/* ---- sensor dropout of N frames ------------------------------------------------ */

/*
 * One input loses N consecutive frames on the bus (the sender's counter
 * goes on). N = 1, 2: the next frame is OKSOMELOST (N lost), the gap is at
 * most 30 ms, never stale. N >= 3: stale 30..31 ms after the last frame,
 * only that input's stale bit, FAULT; the next frame (after a silence) is
 * INITIAL: used at once, the state recovers at that frame.
 */
static void dropout(bool speed, uint32_t n)
{
	const uint32_t k0 = 20U; /* last frame before the dropout */
	const uint32_t k_back = k0 + n + 1U;
	const uint32_t k_end = k_back + 20U;
	const uint16_t bit = speed ? F_SPEED_STALE : F_FORCE_STALE;

	boot();
	for (uint32_t k = 0U; k < k_end; k++) {
		hal_can_frame_t fs = test_frame_speed(&snd, SPEED_RAW, in_time(k));
		hal_can_frame_t ff = test_frame_force(&snd, FORCE_RAW, in_time(k));
		const bool lost = (k > k0) && (k < k_back);

		if (!(lost && speed)) {
			test_app_push(&fs);
		}
		if (!(lost && !speed)) {
			test_app_push(&ff);
		}
	}
	test_app_run_to(in_time(k0));
	assert_int_equal(last_state(), ST_STABLE);
	if (n <= 2U) {
		test_app_run_to(in_time(k_end - 1U));
		assert_int_equal(first_status(in_time(0U), ST_STABLE, false), 0U);
		assert_int_equal(cnt(speed)->e2e_lost, n);
		assert_int_equal(cnt(speed)->stale_events, 0);
		assert_int_equal(mon()->count.state_changes, 1); /* FAULT -> stable at k 0 */
	} else {
		uint64_t t_fault;

		test_app_run_to(in_time(k0) + STALE_US + TICK_US);
		t_fault = first_status(in_time(k0), ST_FAULT, true);
		assert_true(t_fault != 0U);
		assert_true(t_fault - in_time(k0) >= STALE_US);
		assert_true(t_fault - in_time(k0) <= STALE_US + TICK_US);
		assert_int_equal(monitor_fault_bits(mon()), bit);
		assert_int_equal(cnt(speed)->stale_events, 1);
		test_app_run_to(in_time(k_end - 1U));
		/* recovers at the first frame after the dropout */
		assert_int_equal(first_status(t_fault, ST_FAULT, false), in_time(k_back));
		assert_int_equal(last_state(), ST_STABLE);
		assert_int_equal(monitor_fault_bits(mon()), 0U);
		assert_int_equal(cnt(speed)->e2e_lost, 0); /* started over: INITIAL */
		assert_int_equal(mon()->count.state_changes, 3);
	}
	assert_int_equal(cnt(speed)->frames, k_end - n);
	assert_int_equal(cnt(speed)->used, k_end - n);
	assert_int_equal(cnt(!speed)->used, k_end);
	assert_int_equal(cnt(!speed)->e2e_lost, 0);
	assert_int_equal(cnt(!speed)->stale_events, 0);
	assert_no_e2e_errors(speed);
	assert_no_e2e_errors(!speed);
}

static void test_dropout_every_length(void **state)
{
	static const uint32_t lengths[] = { 1U, 2U, 3U, 4U, 5U, 7U, 10U, 14U, 15U, 16U, 29U,
					    30U, 100U, 1000U };

	(void)state;
	for (uint32_t s = 0U; s < 2U; s++) {
		for (uint32_t i = 0U; i < sizeof(lengths) / sizeof(lengths[0]); i++) {
			dropout(s == 0U, lengths[i]);
		}
	}
}

/* ---- counter wrap and jumps ------------------------------------------------------ */

/* 1000 frames of each input: the counter wraps 14 -> 0 66 times; every
 * frame is OK (the first INITIAL), nothing lost, no fault, never FAULT
 * after the first pair. */
static void test_counter_wrap_1000_frames(void **state)
{
	(void)state;
	boot();
	steady(0U, 1000U);
	test_app_run_to(in_time(999U));
	assert_int_equal(first_status(in_time(0U), ST_STABLE, false), 0U);
	assert_int_equal(first_status(T0_US, ST_STABLE, true), in_time(0U));
	expect_counts((want_counts_t){ .frames = ANY, .used = 1000, .lost = 0, .stale_events = 0 });
	for (uint32_t s = 0U; s < 2U; s++) {
		const bool speed = s == 0U;
		const e2e_p01_rx_t *rx = speed ? &mon()->speed.rx.e2e : &mon()->force.rx.e2e;

		assert_int_equal(rx->status_count[E2E_P01_STATUS_INITIAL], 1);
		assert_int_equal(rx->status_count[E2E_P01_STATUS_OK], 999);
		assert_int_equal(rx->last_valid_counter, 999U % 15U);
	}
	assert_int_equal(mon()->count.state_changes, 1);
	assert_int_equal(mon()->count.classifications, 1000);
	assert_int_equal(monitor_fault_bits(mon()), 0U);
}

/*
 * The speed sender's counter jumps by d (2..14) at one frame, with no time
 * gap (e.g. a sender reset or a software fault). d = 2, 3: OKSOMELOST, d - 1
 * lost, no fault. d = 4..14: WRONGSEQUENCE (FAULT with the E2E bit at that
 * frame, counted once), the next frame continues the adopted sequence and
 * is used (INITIAL): stable again one period later. Each d on a fresh boot.
 */
static void test_counter_jump_every_size(void **state)
{
	(void)state;
	for (uint32_t d = 2U; d <= 14U; d++) {
		const uint32_t kj = 10U;

		boot();
		steady(0U, kj);
		snd.speed_counter = (uint8_t)((snd.speed_counter + d - 1U) % 15U);
		steady(kj, kj + 20U);
		test_app_run_to(in_time(kj) - TICK_US);
		assert_int_equal(last_state(), ST_STABLE);
		test_app_run_to(in_time(kj));
		if (d <= 3U) {
			assert_int_equal(last_state(), ST_STABLE);
			assert_int_equal(monitor_fault_bits(mon()), 0U);
			test_app_run_to(in_time(kj + 19U));
			assert_int_equal(first_status(in_time(0U), ST_STABLE, false), 0U);
			assert_int_equal(mon()->speed.count.e2e_lost, d - 1U);
			assert_int_equal(mon()->speed.count.e2e_wrong_sequence, 0);
			assert_int_equal(mon()->speed.count.used, kj + 20U);
		} else {
			assert_int_equal(first_status(in_time(kj), ST_FAULT, true), in_time(kj));
			assert_int_equal(monitor_fault_bits(mon()), F_E2E_SPEED);
			test_app_run_to(in_time(kj + 19U));
			assert_int_equal(first_status(in_time(kj), ST_FAULT, false),
					 in_time(kj + 1U));
			assert_int_equal(last_state(), ST_STABLE);
			assert_int_equal(monitor_fault_bits(mon()), 0U);
			assert_int_equal(mon()->speed.count.e2e_wrong_sequence, 1);
			assert_int_equal(mon()->speed.count.e2e_lost, 0);
			assert_int_equal(mon()->speed.count.used, kj + 19U);
			assert_int_equal(mon()->count.state_changes, 3);
		}
		assert_int_equal(mon()->speed.count.frames, kj + 20U);
		assert_int_equal(mon()->speed.count.stale_events, 0);
		assert_int_equal(mon()->speed.count.e2e_wrong_crc, 0);
		assert_int_equal(mon()->force.count.used, kj + 20U);
		assert_int_equal(mon()->force.count.e2e_lost, 0);
	}
}

/* ---- CRC storms ------------------------------------------------------------------- */

/*
 * Every frame of both inputs has a wrong CRC for 1 s (100 frames each),
 * then all are good. FAULT at the first bad frame (E2E bits), the stale
 * bits 30 ms after the last good frame; both E2E error counters exactly
 * 100 (also in SquealDiag page 2); stable again at the first good pair.
 */
static void test_crc_storm_1s(void **state)
{
	const uint32_t ks = 50U; /* first bad pair, at T0 + 505 ms */
	const uint32_t ke = ks + 100U;
	uint32_t page = 9U;
	const uint8_t *d = NULL;

	(void)state;
	boot();
	for (uint32_t k = 0U; k < 600U; k++) {
		hal_can_frame_t fs = frame_of(true, k);
		hal_can_frame_t ff = frame_of(false, k);

		if ((k >= ks) && (k < ke)) {
			fs.data[0] ^= (uint8_t)(1U + (k % 255U));
			ff.data[0] ^= (uint8_t)(0x80U >> (k % 8U));
		}
		test_app_push(&fs);
		test_app_push(&ff);
	}
	test_app_run_to(in_time(ks));
	assert_int_equal(first_status(in_time(ks), ST_FAULT, true), in_time(ks));
	assert_int_equal(monitor_fault_bits(mon()), F_E2E_SPEED | F_E2E_FORCE);
	test_app_run_to(in_time(ks - 1U) + STALE_US + TICK_US);
	assert_int_equal(monitor_fault_bits(mon()),
			 F_E2E_SPEED | F_E2E_FORCE | F_SPEED_STALE | F_FORCE_STALE);
	/* SquealDiag at T0 + 1 s (inside the storm): exactly these bits */
	test_app_run_to(T0_US + 1000000U);
	assert_int_equal(diag_at(T0_US + 1000000U, NULL, NULL),
			 F_E2E_SPEED | F_E2E_FORCE | F_SPEED_STALE | F_FORCE_STALE);
	test_app_run_to(in_time(599U));
	assert_int_equal(first_status(in_time(ks), ST_FAULT, false), in_time(ke));
	assert_int_equal(last_state(), ST_STABLE);
	assert_int_equal(monitor_fault_bits(mon()), 0U);
	expect_counts((want_counts_t){ .frames = 600, .used = 500, .lost = 0, .stale_events = 1,
				       .wrong_crc = 100, .wrong_sequence = 0, .repeated = ANY,
				       .bad_dlc = ANY, .implausible = ANY });
	assert_int_equal(mon()->count.state_changes, 3);
	/* SquealDiag page 2 at T0 + 7 s (pages 0..4, one a second):
	 * E2eErrorCountSpeed/Force */
	test_app_run_to(T0_US + 7000000U);
	(void)diag_at(T0_US + 7000000U, &page, &d);
	assert_int_equal(page, 2);
	assert_int_equal(test_frame_sig(d, 32, 16), 100);
	assert_int_equal(test_frame_sig(d, 48, 16), 100);
}

/*
 * Every other speed frame corrupt for 1 s: each bad frame is FAULT at once,
 * each good one after it is OKSOMELOST (one lost) and stable again: 50
 * wrong CRCs, 50 lost, 100 state changes, never stale.
 */
static void test_crc_storm_alternating(void **state)
{
	const uint32_t ks = 20U;
	const uint32_t ke = ks + 100U;

	(void)state;
	boot();
	for (uint32_t k = 0U; k < ke + 20U; k++) {
		hal_can_frame_t fs = frame_of(true, k);
		hal_can_frame_t ff = frame_of(false, k);

		if ((k >= ks) && (k < ke) && (((k - ks) % 2U) == 0U)) {
			fs.data[0] ^= 0x5AU;
		}
		test_app_push(&fs);
		test_app_push(&ff);
	}
	test_app_run_to(in_time(ke + 19U));
	assert_int_equal(mon()->speed.count.e2e_wrong_crc, 50);
	assert_int_equal(mon()->speed.count.e2e_lost, 50);
	assert_int_equal(mon()->speed.count.used, ke + 20U - 50U);
	assert_int_equal(mon()->speed.count.stale_events, 0);
	assert_int_equal(mon()->force.count.used, ke + 20U);
	assert_int_equal(mon()->count.state_changes, 1U + 100U);
	for (uint32_t k = ks; k < ke; k++) {
		const uint8_t want = (((k - ks) % 2U) == 0U) ? ST_FAULT : ST_STABLE;

		assert_int_equal(first_status(in_time(k), want, true), in_time(k));
	}
	assert_int_equal(last_state(), ST_STABLE);
	assert_int_equal(monitor_fault_bits(mon()), 0U);
}

/* ---- DLC errors --------------------------------------------------------------------- */

/*
 * Every DLC 0..8 but the right one (4), on each input in turn, each bad
 * frame followed by good ones: E2E bit and FAULT at the bad frame, stable at
 * the next; bad_dlc counts 8 per input, nothing as a CRC error; each bad
 * frame used up one sender counter value, so the next good frame reports
 * one lost (OKSOMELOST). RxBadFrameCount (SquealDiag page 3) = 16.
 */
static void test_every_wrong_dlc(void **state)
{
	uint32_t k = 0U;
	uint32_t n_bad = 0U;
	uint32_t page = 9U;
	const uint8_t *d = NULL;

	(void)state;
	boot();
	steady(0U, 5U);
	k = 5U;
	for (uint32_t s = 0U; s < 2U; s++) {
		const bool speed = s == 0U;

		for (uint8_t dlc = 0U; dlc <= 8U; dlc++) {
			hal_can_frame_t fb;
			hal_can_frame_t fo;

			if (dlc == (speed ? MSG_DISC_SPEED_DLC : MSG_PAD_FORCE_DLC)) {
				continue;
			}
			fb = frame_of(speed, k);
			fo = frame_of(!speed, k);
			fb.dlc = dlc;
			test_app_push(&fb);
			test_app_push(&fo);
			pair(k + 1U);
			pair(k + 2U);
			test_app_run_to(in_time(k));
			n_bad++;
			assert_int_equal(first_status(in_time(k), ST_FAULT, true), in_time(k));
			assert_int_equal(monitor_fault_bits(mon()), speed ? F_E2E_SPEED : F_E2E_FORCE);
			test_app_run_to(in_time(k + 1U));
			assert_int_equal(last_state(), ST_STABLE);
			assert_int_equal(monitor_fault_bits(mon()), 0U);
			k += 3U;
		}
	}
	assert_int_equal(n_bad, 16);
	test_app_run_to(in_time(k - 1U));
	expect_counts((want_counts_t){ .frames = k, .used = k - 8U, .lost = 8, .stale_events = 0,
				       .wrong_crc = 0, .wrong_sequence = 0, .repeated = ANY, .bad_dlc = 8,
				       .implausible = ANY });
	assert_int_equal(mon()->count.state_changes, 1U + 2U * 16U);
	/* page 3 at T0 + 3 s */
	steady(k, 310U);
	test_app_run_to(T0_US + 3000000U);
	(void)diag_at(T0_US + 3000000U, &page, &d);
	assert_int_equal(page, 3);
	assert_int_equal(test_frame_sig(d, 48, 16), 16);
	assert_int_equal(test_frame_sig(d, 32, 16), 0);
}

/* ---- bus-off during transmission ------------------------------------------------------- */

/* Feed steady pairs up to t_us, then run to it (chunks of 1 s: the test
 * HAL's RX queue holds 4096 frames). */
static uint32_t next_k;

static void run_steady(uint64_t t_us)
{
	while (hal_time_us() < t_us) {
		const uint64_t chunk = (t_us - hal_time_us() > DIAG_US) ? hal_time_us() + DIAG_US : t_us;

		while (in_time(next_k) <= chunk) {
			pair(next_k);
			next_k++;
		}
		test_app_run_to(chunk);
	}
}

static void assert_tx_conserved(uint64_t t_us, uint64_t extra)
{
	const monitor_counters_t *c = &mon()->count;

	assert_int_equal((uint64_t)c->tx_frames + c->tx_errors + c->tx_overflow +
			 mon()->txq_count, produced(t_us, extra));
	assert_int_equal(c->tx_frames, test_hal_tx_count());
}

/*
 * The TX queue is full (8 frames waiting: 100 ms of ENOBUFS) when the
 * controller goes bus-off: every waiting frame and every new one is refused
 * with ENETUNREACH and counted as a TX error, nothing is sent; three
 * bus-off episodes in all. Throughout: every frame produced is sent,
 * counted as a TX error, counted as overflow, or still queued (exactly);
 * RX and classification go on; BusOffSeen latched from the first
 * episode, BusOffCount 3 in SquealDiag page 0.
 */
static void test_bus_off_during_transmission(void **state)
{
	/* a tick right before a status is due: every tick of the TX-full
	 * window then has a frame to offer */
	const uint64_t t_full = T0_US + 1999000U;
	const uint64_t t_off = t_full + 100000U;
	uint32_t enobufs;
	uint32_t n_sent;
	const uint8_t *d = NULL;
	uint32_t page = 9U;

	(void)state;
	boot();
	next_k = 0U;
	run_steady(t_full);
	assert_int_equal(mon()->txq_count, 0);
	assert_tx_conserved(t_full, 1U);
	assert_int_equal(diag_at(T0_US + 1000000U, NULL, NULL), 0U);

	test_hal_set_tx_full(true);
	run_steady(t_off);
	enobufs = test_hal_tx_rejected();
	assert_int_equal(enobufs, 100); /* one refusal per tick */
	assert_int_equal(mon()->txq_count, MONITOR_TX_QUEUE_LEN);
	assert_true(mon()->count.tx_overflow > 0U);
	assert_tx_conserved(t_off, 1U);

	/* bus-off with 8 frames waiting (TX-full no longer matters: the
	 * controller refuses everything) */
	test_hal_set_tx_full(false);
	test_hal_bus_off();
	n_sent = test_hal_tx_count();
	run_steady(t_off + 300000U);
	assert_int_equal(test_hal_tx_count(), n_sent);
	assert_int_equal(mon()->count.tx_errors, test_hal_tx_rejected() - enobufs);
	assert_true(mon()->count.tx_errors >= MONITOR_TX_QUEUE_LEN + 30U);
	assert_tx_conserved(t_off + 300000U, 1U);
	assert_true(mon()->bus_off_seen);
	assert_int_equal(mon()->count.bus_off_events, 1);
	assert_int_equal(mon()->state, ST_STABLE);

	test_hal_bus_recover();
	run_steady(t_off + 300000U + STATUS_US);
	/* status frames resume within one period, fresh ones, state stable */
	{
		const int32_t i = test_hal_tx_find(EXP_DBC_SQUEALSTATUS_ID, n_sent);

		assert_true(i >= 0);
		assert_true(test_hal_tx_frame((uint32_t)i)->timestamp_us <=
			    t_off + 300000U + STATUS_US);
		assert_int_equal(test_frame_sig(test_hal_tx_frame((uint32_t)i)->data, 12, 4), ST_STABLE);
	}
	/* two more short episodes: 5 ms and 1 s */
	run_steady(T0_US + 3000000U);
	test_hal_bus_off();
	run_steady(T0_US + 3005000U);
	test_hal_bus_recover();
	run_steady(T0_US + 4500000U);
	test_hal_bus_off();
	run_steady(T0_US + 5500000U);
	test_hal_bus_recover();
	run_steady(T0_US + 8000000U);
	assert_tx_conserved(T0_US + 8000000U, 1U);
	assert_int_equal(mon()->count.tx_errors, test_hal_tx_rejected() - enobufs);
	assert_int_equal(mon()->count.bus_off_events, 3);
	assert_int_equal(mon()->txq_count, 0);
	/* latched in every SquealDiag sent since the first bus-off */
	assert_true((diag_at(T0_US + 7000000U, NULL, NULL) & F_BUS_OFF_SEEN) != 0U);
	assert_int_equal(diag_at(T0_US + 8000000U, &page, &d),
			 F_BUS_OFF_SEEN | F_TX_OVERFLOW);
	/* page 0 (pages 0..4, one a second) at T0 + 10 s: BusOffCount */
	run_steady(T0_US + 10000000U);
	assert_int_equal(diag_at(T0_US + 10000000U, &page, &d),
			 F_BUS_OFF_SEEN | F_TX_OVERFLOW);
	assert_int_equal(page, 0);
	assert_int_equal(test_frame_sig(d, 56, 8), 3); /* BusOffCount */
	assert_int_equal(test_frame_sig(d, 32, 24), 10); /* Uptime_s */
	/* RX never stopped: every pair used and classified, one state change */
	assert_int_equal(mon()->speed.count.used, next_k);
	assert_int_equal(mon()->force.count.used, next_k);
	assert_int_equal(mon()->count.classifications, next_k);
	assert_int_equal(mon()->count.state_changes, 1);
	print_message("  bus-off: %u TX errors (8 waiting frames + every new one), "
		      "%u overflow, %u sent\n", mon()->count.tx_errors,
		      mon()->count.tx_overflow, mon()->count.tx_frames);
}

/* ---- TX queue full for 5 s ------------------------------------------------------------- */

/*
 * hal_can_send refuses (ENOBUFS) for 5 s: no crash, RX and classification
 * go on, 8 frames wait, every other frame produced in the window is counted
 * as overflow (exactly), one refusal per tick; when the controller takes
 * frames again the waiting ones leave at once and status frames follow
 * every 10 ms from then on.
 */
static void test_tx_full_5s(void **state)
{
	const uint64_t t_full = T0_US + 1999000U;
	const uint64_t t_free = t_full + 5000000U;
	uint64_t prev;
	int32_t i;
	uint32_t n_before;
	uint32_t page = 9U;
	const uint8_t *d = NULL;

	(void)state;
	boot();
	next_k = 0U;
	run_steady(t_full);
	assert_int_equal(mon()->txq_count, 0);
	assert_int_equal(mon()->count.tx_overflow, 0);
	n_before = test_hal_tx_count();
	test_hal_set_tx_full(true);
	run_steady(t_free);
	assert_int_equal(test_hal_tx_count(), n_before);
	assert_int_equal(test_hal_tx_rejected(), 5000);
	assert_int_equal(mon()->txq_count, MONITOR_TX_QUEUE_LEN);
	/* produced in (t_full, t_free]: all but the 8 waiting overflowed */
	assert_int_equal(mon()->count.tx_overflow,
			 produced(t_free, 1U) - produced(t_full, 1U) - MONITOR_TX_QUEUE_LEN);
	assert_int_equal(mon()->state, ST_STABLE);
	assert_int_equal(mon()->speed.count.used, next_k);
	assert_int_equal(mon()->count.classifications, next_k);

	test_hal_set_tx_full(false);
	run_steady(t_free + TICK_US);
	/* the 8 waiting frames left in the first free tick */
	assert_int_equal(test_hal_tx_count() - n_before, MONITOR_TX_QUEUE_LEN);
	assert_int_equal(mon()->txq_count, 0);
	run_steady(t_free + 1000000U);
	assert_tx_conserved(t_free + 1000000U, 1U);
	assert_int_equal(mon()->count.tx_errors, 0);
	/* status resumes: the first after the window at once, then every
	 * 10 ms, all stable */
	i = test_hal_tx_find(EXP_DBC_SQUEALSTATUS_ID, n_before);
	assert_true(i >= 0);
	prev = test_hal_tx_frame((uint32_t)i)->timestamp_us;
	assert_int_equal(prev, t_free + TICK_US);
	while ((i = test_hal_tx_find(EXP_DBC_SQUEALSTATUS_ID, (uint32_t)(i + 1))) >= 0) {
		const hal_can_frame_t *f = test_hal_tx_frame((uint32_t)i);

		assert_true(f->timestamp_us - prev <= STATUS_US);
		assert_int_equal(test_frame_sig(f->data, 12, 4), ST_STABLE);
		prev = f->timestamp_us;
	}
	assert_true(prev >= t_free + 1000000U - STATUS_US);
	/* TxOverflow latched; page 3 counts it (T0 + 13 s is page 3 of 0..4) */
	run_steady(T0_US + 13000000U);
	assert_int_equal(diag_at(T0_US + 13000000U, &page, &d), F_TX_OVERFLOW);
	assert_int_equal(page, 3);
	assert_int_equal(test_frame_sig(d, 32, 16), mon()->count.tx_overflow);
	print_message("  TX full 5 s: %u refusals, %u frames overflowed\n",
		      test_hal_tx_rejected(), mon()->count.tx_overflow);
}

/* ---- clock jumps -------------------------------------------------------------------------- */

/*
 * The clock jumps 10 s forward between two ticks (the HAL clock never goes
 * back). The first tick after the jump finds both inputs 10 s old: stale,
 * FAULT at once, one tick (no burst of the 10,000 missed ticks). The pair
 * stamped at the jump's tick is delivered before that step and is "in the
 * future" for the monitor: it is taken as received at the monitor's last
 * time, so it does not hide the staleness. The next pair is used at once
 * (the E2E receiver started over): stable again 10 ms after the jump.
 */
static void test_clock_jump_10s(void **state)
{
	const uint64_t t1 = in_time(99U) + 2000U; /* T0 + 0.997 s */
	const uint64_t tj = t1 + 10000000U;
	uint32_t kicks;
	uint32_t page = 9U;
	const uint8_t *d = NULL;

	(void)state;
	boot();
	steady(0U, 100U);
	test_app_run_to(t1);
	assert_int_equal(last_state(), ST_STABLE);
	kicks = test_hal_watchdog_kicks();
	/* the senders go on in the new time base, counters continuing */
	for (uint32_t j = 0U; j < 300U; j++) {
		assert_int_equal(test_send_pair(&snd, SPEED_RAW, FORCE_RAW, tj + IN_PERIOD_US * j),
				 SQ_OK);
	}
	test_hal_advance_us(tj - t1);
	(void)squeal_app_poll();
	assert_int_equal(test_hal_watchdog_kicks(), kicks + 1U);
	assert_int_equal(last_state(), ST_FAULT);
	assert_int_equal(first_status(tj, ST_FAULT, true), tj);
	assert_int_equal(monitor_fault_bits(mon()), F_SPEED_STALE | F_FORCE_STALE);
	assert_int_equal(mon()->speed.count.stale_events, 1);
	assert_int_equal(mon()->force.count.stale_events, 1);
	test_app_run_to(tj + IN_PERIOD_US);
	assert_int_equal(first_status(tj, ST_FAULT, false), tj + IN_PERIOD_US);
	test_app_run_to(tj + 299U * IN_PERIOD_US);
	assert_int_equal(first_status(tj + IN_PERIOD_US, ST_STABLE, false), 0U);
	assert_int_equal(monitor_fault_bits(mon()), 0U);
	expect_counts((want_counts_t){ .frames = 400, .used = 400, .lost = 0, .stale_events = ANY });
	/* the pair at the jump was used but never classified */
	assert_int_equal(mon()->count.classifications, 399);
	assert_int_equal(mon()->count.state_changes, 3);
	/* SquealDiag: one frame for the missed seconds (the second one, page
	 * 1), then every second from the jump on; Uptime_s jumped too */
	(void)diag_at(tj, &page, &d);
	assert_int_equal(page, 1);
	test_app_run_to(tj + 4U * DIAG_US);
	(void)diag_at(tj + 4U * DIAG_US, &page, &d);
	assert_int_equal(page, 0); /* pages 0..4 */
	assert_int_equal(test_frame_sig(d, 32, 24), (tj + 4U * DIAG_US - T0_US) / 1000000U); /* Uptime_s */
}

/* what the scheduler does with the queue, the bus taking every frame */
static void drain(monitor_t *m)
{
	hal_can_frame_t f;

	while (monitor_peek_tx(m, &f) == SQ_OK) {
		monitor_tx_done(m, SQ_OK);
	}
}

/*
 * A frame timestamp far in the future (a HAL clock glitch) cannot keep an
 * input alive: it counts as received at the monitor's current time, so the
 * input still goes stale 30 ms later. The test HAL never delivers a frame
 * before its timestamp, so this drives the monitor (monitor.h) directly.
 * Timestamp 0 (none) also means "now".
 */
static void test_future_timestamp_does_not_break_staleness(void **state)
{
	static monitor_t m;
	calib_t cal;
	uint64_t t = T0_US;
	uint64_t t_last;

	(void)state;
	calib_default(&cal);
	test_sender_init(&snd);
	assert_int_equal(monitor_init(&m, &cal, false, 0U, T0_US), SQ_OK);
	monitor_step(&m, t);
	drain(&m);
	for (uint32_t k = 0U; k < 10U; k++) {
		hal_can_frame_t fs = test_frame_speed(&snd, SPEED_RAW, t);
		hal_can_frame_t ff = test_frame_force(&snd, FORCE_RAW, t);

		monitor_on_frame(&m, &fs);
		monitor_on_frame(&m, &ff);
		for (uint32_t i = 0U; i < 10U; i++) {
			t += TICK_US;
			monitor_step(&m, t);
			drain(&m);
		}
	}
	assert_int_equal(m.state, ST_STABLE);
	/* the next speed frame claims to come from 10 s in the future; the
	 * force frame has no timestamp */
	{
		hal_can_frame_t fs = test_frame_speed(&snd, SPEED_RAW, t + 10000000U);
		hal_can_frame_t ff = test_frame_force(&snd, FORCE_RAW, 0U);

		monitor_on_frame(&m, &fs);
		monitor_on_frame(&m, &ff);
	}
	assert_int_equal(m.speed.last_used_us, t);
	assert_int_equal(m.force.last_used_us, t);
	t_last = t;
	while (m.state != ST_FAULT) {
		t += TICK_US;
		monitor_step(&m, t);
		drain(&m);
		assert_true(t - t_last <= STALE_US + TICK_US);
	}
	assert_true(t - t_last > STALE_US);
	assert_int_equal(monitor_fault_bits(&m), F_SPEED_STALE | F_FORCE_STALE);
	assert_int_equal(m.speed.count.stale_events, 1);
	assert_int_equal(m.speed.count.used, 11);
}

/* ---- long run ------------------------------------------------------------------------------ */

/*
 * 10^6 steps of 1 ms (1000 s) with valid inputs: never FAULT after the
 * first pair, no fault bit in any SquealDiag after T0, nothing lost, every
 * counter exact: 10^5 pairs used and classified, every produced frame sent
 * (hand-counted schedule), SquealStatus alive counters consecutive across
 * the whole run, one watchdog kick per tick.
 */
static void test_long_run_1e6_steps(void **state)
{
	const uint64_t t_end = T0_US + 1000000000ULL;
	uint32_t n_status = 0U;
	uint32_t n_diag = 0U;
	int last_ctr = -1;

	(void)state;
	boot();
	next_k = 0U;
	while (hal_time_us() < t_end) {
		int32_t i = -1;

		run_steady(hal_time_us() + DIAG_US);
		while ((i = test_hal_tx_find(EXP_DBC_SQUEALSTATUS_ID, (uint32_t)(i + 1))) >= 0) {
			const hal_can_frame_t *f = test_hal_tx_frame((uint32_t)i);
			const int ctr = f->data[1] & 0x0F;

			if (f->timestamp_us >= in_time(0U)) {
				assert_int_equal(test_frame_sig(f->data, 12, 4), ST_STABLE);
			}
			if (last_ctr >= 0) {
				assert_int_equal(ctr, (last_ctr + 1) % 15);
			}
			last_ctr = ctr;
			n_status++;
		}
		i = -1;
		while ((i = test_hal_tx_find(EXP_DBC_SQUEALDIAG_ID, (uint32_t)(i + 1))) >= 0) {
			const hal_can_frame_t *f = test_hal_tx_frame((uint32_t)i);

			if (f->timestamp_us > T0_US) {
				assert_int_equal(test_frame_sig(f->data, 16, 11), 0U);
			}
			n_diag++;
		}
		test_hal_tx_clear();
		/* the count check compares with the HAL's log: keep a total */
	}
	assert_int_equal(hal_time_us(), t_end);
	assert_int_equal(test_hal_watchdog_kicks(), 1000001U);
	assert_int_equal(next_k, 100000U);
	expect_counts((want_counts_t){ .frames = 100000, .used = 100000, .lost = 0, .stale_events = 0 });
	assert_int_equal(mon()->count.classifications, 100000);
	assert_int_equal(mon()->count.state_changes, 1);
	assert_int_equal(mon()->count.model_invalid, 0);
	assert_int_equal(mon()->count.tx_frames, produced(t_end, 1U));
	assert_int_equal(mon()->count.tx_errors, 0);
	assert_int_equal(mon()->count.tx_overflow, 0);
	assert_int_equal(n_status, 100000U + 1U + 1U);
	assert_int_equal(n_diag, 1001);
	assert_int_equal(monitor_fault_bits(mon()), 0U);
	assert_int_equal(mon()->state, ST_STABLE);
}

SQ_CMOCKA_MAIN(
	cmocka_unit_test(test_dropout_every_length),
	cmocka_unit_test(test_counter_wrap_1000_frames),
	cmocka_unit_test(test_counter_jump_every_size),
	cmocka_unit_test(test_crc_storm_1s),
	cmocka_unit_test(test_crc_storm_alternating),
	cmocka_unit_test(test_every_wrong_dlc),
	cmocka_unit_test(test_bus_off_during_transmission),
	cmocka_unit_test(test_tx_full_5s),
	cmocka_unit_test(test_clock_jump_10s),
	cmocka_unit_test(test_future_timestamp_does_not_break_staleness),
	cmocka_unit_test(test_long_run_1e6_steps))
