/* SPDX-License-Identifier: MIT */
/*
 * The monitor through its real interfaces: protected frames into the test
 * HAL's RX queue, squeal_app_init()/squeal_app_poll() every virtual
 * millisecond, frames out of the TX log decoded by hand from the DBC layout.
 *
 * Expected values are independent of the firmware:
 *   - border speeds from tests/support/reference/squeal_reference.py (scipy) via
 *     tests/firmware/monitor/gen_monitor_expect.py -> build/monitor/monitor_expect.h;
 *   - data IDs and cycle times parsed from squeal.dbc by the same script;
 *   - the force border N_H = 2 D w0 m exp(a v0) / (a dmu) in double here.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <math.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "calib.h"
#include "e2e_p01.h"
#include "monitor.h"
#include "monitor_expect.h"
#include "sq_status.h"
#include "squeal_app.h"
#include "test_hal.h"

#define T0_US 1000000ULL     /* the clock starts at 1 s */
#define IN_OFFSET_US 5000ULL /* inputs arrive 5 ms after the status phase */
#define IN_PERIOD_US 10000ULL
#define FORCE_9KN_RAW 18000U /* 0.5 N per bit */
#define UMPS_PER_RAW 1200LL  /* 0.01 rad/s x r_p 0.12 m = 1200 um/s */

/* ---- helpers ---------------------------------------------------------------- */

static void store_calib(const calib_t *cal)
{
	uint8_t buf[CALIB_BLOCK_LEN];

	assert_int_equal(calib_encode(cal, buf, sizeof(buf)), SQ_OK);
	test_hal_calib_store(buf, sizeof(buf));
}

static void boot(const calib_t *cal)
{
	test_hal_reset();
	test_hal_set_time_us(T0_US);
	if (cal != NULL) {
		store_calib(cal);
	}
	assert_int_equal(squeal_app_init(), SQ_OK);
	(void)squeal_app_poll();
}

/* one poll per virtual millisecond up to and including t_us */
static void run_to(uint64_t t_us)
{
	while (hal_time_us() < t_us) {
		test_hal_advance_us(1000U);
		(void)squeal_app_poll();
	}
}

static uint64_t in_time(uint32_t k)
{
	return T0_US + IN_OFFSET_US + IN_PERIOD_US * k;
}

typedef struct {
	uint64_t t_us;
	uint8_t state;
	uint8_t warning;
	uint16_t basin;
	int16_t margin;
} status_rec_t;

#define MAX_STATUS 4096U
static status_rec_t recs[MAX_STATUS];

static uint32_t collect_status(void)
{
	uint32_t n = 0U;
	int32_t i = -1;

	while ((i = test_hal_tx_find(EXP_DBC_SQUEALSTATUS_ID, (uint32_t)(i + 1))) >= 0) {
		const hal_can_frame_t *f = test_hal_tx_frame((uint32_t)i);

		assert_int_equal(f->dlc, 8);
		assert_true(n < MAX_STATUS);
		recs[n].t_us = f->timestamp_us;
		recs[n].state = (uint8_t)test_frame_sig(f->data, 12, 4);
		recs[n].warning = (uint8_t)test_frame_sig(f->data, 16, 4);
		recs[n].basin = (uint16_t)test_frame_sig(f->data, 24, 16);
		recs[n].margin = (int16_t)(uint16_t)test_frame_sig(f->data, 40, 16);
		n++;
	}
	return n;
}

/*
 * Every frame the monitor sent: E2E P01 check with the DBC's data ID passes
 * (INITIAL for the first one, OK after), and the counter goes +1 mod 15.
 */
static void check_tx_e2e(void)
{
	static const struct {
		uint32_t id;
		uint16_t data_id;
	} msgs[4] = {
		{ EXP_DBC_SQUEALSTATUS_ID, EXP_DBC_SQUEALSTATUS_DATA_ID },
		{ EXP_DBC_SQUEALDETAIL_ID, EXP_DBC_SQUEALDETAIL_DATA_ID },
		{ EXP_DBC_SQUEALDIAG_ID, EXP_DBC_SQUEALDIAG_DATA_ID },
		{ EXP_DBC_SQUEALDETAIL2_ID, EXP_DBC_SQUEALDETAIL2_DATA_ID },
	};
	uint32_t m;
	uint32_t total = 0U;

	for (m = 0U; m < 4U; m++) {
		const e2e_p01_config_t cfg = { msgs[m].data_id, 8U, 1U };
		e2e_p01_rx_t rx;
		int32_t i = -1;
		uint32_t n = 0U;
		uint8_t prev = 0U;

		e2e_p01_rx_init(&rx);
		while ((i = test_hal_tx_find(msgs[m].id, (uint32_t)(i + 1))) >= 0) {
			const hal_can_frame_t *f = test_hal_tx_frame((uint32_t)i);
			const uint8_t ctr = f->data[1] & 0x0FU;
			const e2e_p01_status_t st = e2e_p01_check(&cfg, &rx, f->data, f->dlc);

			assert_int_equal(f->dlc, 8);
			assert_int_equal(st, (n == 0U) ? E2E_P01_STATUS_INITIAL : E2E_P01_STATUS_OK);
			assert_true(ctr <= 14U);
			if (n > 0U) {
				assert_int_equal(ctr, (prev + 1U) % 15U);
			}
			prev = ctr;
			n++;
		}
		total += n;
	}
	assert_true(total > 0U);
	assert_int_equal(total, test_hal_tx_count());
}

/* first ramp frame whose speed is below v_umps */
static uint32_t first_below(const int64_t *v_umps, uint32_t n, int64_t v)
{
	uint32_t k;

	for (k = 0U; k < n; k++) {
		if (v_umps[k] < v) {
			return k;
		}
	}
	return n;
}

/* ---- the braking manoeuvre -------------------------------------------------- */

/*
 * 30 m/s (Omega = 100 rad/s at r_w 0.3 m) to a stop at 9000 N: Omega falls
 * 0.25 rad/s per 10 ms frame (25 rad/s^2, 7.5 m/s^2 at the wheel), then
 * stays 0. v0 = Omega r_p falls 0.03 m/s per frame.
 */
#define RAMP_START_RAW 10000U
#define RAMP_STEP_RAW 25U
#define RAMP_FRAMES (RAMP_START_RAW / RAMP_STEP_RAW + 1U + 20U)

static int64_t ramp_v[RAMP_FRAMES];

static void braking(const calib_t *cal)
{
	test_sender_t snd;
	uint32_t k;

	boot(cal);
	test_sender_init(&snd);
	for (k = 0U; k < RAMP_FRAMES; k++) {
		const uint32_t raw = (k * RAMP_STEP_RAW < RAMP_START_RAW) ?
			RAMP_START_RAW - k * RAMP_STEP_RAW : 0U;

		ramp_v[k] = (int64_t)raw * UMPS_PER_RAW;
		assert_int_equal(test_send_pair(&snd, (uint16_t)raw, FORCE_9KN_RAW, in_time(k)),
				 SQ_OK);
	}
	run_to(in_time(RAMP_FRAMES - 1U) + 20000U);
}

/* The ramp frame index at which the status frame rec was triggered. */
static uint32_t frame_of(const status_rec_t *r)
{
	assert_true(r->t_us >= in_time(0));
	assert_int_equal((r->t_us - in_time(0)) % IN_PERIOD_US, 0);
	return (uint32_t)((r->t_us - in_time(0)) / IN_PERIOD_US);
}

typedef struct {
	uint8_t to;
	uint32_t k;
} transition_t;

static uint32_t transitions(uint32_t n, transition_t *tr, uint32_t max)
{
	uint32_t i;
	uint32_t m = 0U;

	for (i = 1U; i < n; i++) {
		if (recs[i].state != recs[i - 1U].state) {
			assert_true(m < max);
			tr[m].to = recs[i].state;
			tr[m].k = frame_of(&recs[i]);
			/* sent at once: in the same step as the input frame */
			assert_int_equal(recs[i].t_us, in_time(tr[m].k));
			m++;
		}
	}
	return m;
}

static void check_transition_at(const transition_t *t, uint32_t k_border,
				uint32_t k_expected)
{
	print_message("  -> state %u at frame %u (v0 %.4f m/s); border crossed at frame %u, "
		      "debounce rule predicts %u\n", t->to, t->k, (double)ramp_v[t->k] * 1e-6,
		      k_border, k_expected);
	/* never before the model's border */
	assert_true(t->k >= k_border);
	/* and within one input cycle of the prediction */
	assert_true(t->k + 1U >= k_expected);
	assert_true(t->k <= k_expected + 1U);
}

static void test_braking_default_calibration(void **state)
{
	transition_t tr[8];
	uint32_t n;
	uint32_t m;
	uint32_t k_s;
	uint32_t k_h;
	uint32_t k_ns;
	const uint32_t debounce = 3U; /* default */

	(void)state;
	braking(NULL);
	n = collect_status();
	assert_true(n > 400U);
	assert_int_equal(recs[0].state, MSG_SQUEAL_STATE_FAULT); /* nothing seen yet */
	m = transitions(n, tr, 8U);
	assert_int_equal(m, 4U);
	assert_int_equal(tr[0].to, MSG_SQUEAL_STATE_STABLE);
	assert_int_equal(tr[0].k, 0);
	assert_int_equal(tr[1].to, MSG_SQUEAL_STATE_BISTABLE);
	assert_int_equal(tr[2].to, MSG_SQUEAL_STATE_UNSTABLE);
	assert_int_equal(tr[3].to, MSG_SQUEAL_STATE_NOT_SLIDING);

	/* stable -> bistable: rho crosses 1; the band edge (rho 0.98) lies
	 * more than debounce frames further on, so debounce decides */
	k_s = first_below(ramp_v, RAMP_FRAMES, EXP_V_STABLE_UMPS);
	{
		const uint32_t k_band = first_below(ramp_v, RAMP_FRAMES, EXP_V_RHO_BAND_UMPS);
		const uint32_t k_exp = (k_band < k_s + debounce - 1U) ? k_band : k_s + debounce - 1U;

		check_transition_at(&tr[1], k_s, k_exp);
	}
	/* bistable -> unstable: v_H; the band (|ln 2Q| 0.02 = 0.01 m/s) is
	 * narrower than one frame's 0.03 m/s */
	k_h = first_below(ramp_v, RAMP_FRAMES, EXP_V_HOPF_UMPS);
	{
		const uint32_t k_band = first_below(ramp_v, RAMP_FRAMES, EXP_V_HOPF_BAND_UMPS);
		const uint32_t k_exp = (k_band < k_h + debounce - 1U) ? k_band : k_h + debounce - 1U;

		check_transition_at(&tr[2], k_h, k_exp);
	}
	/* -> not sliding at v0 < v0_min (0.01 m/s): at once */
	k_ns = first_below(ramp_v, RAMP_FRAMES, 10000);
	check_transition_at(&tr[3], k_ns, k_ns);
	assert_int_equal(tr[3].k, k_ns);
	check_tx_e2e();
}

/* Without debounce and hysteresis (calibration), every transition is at
 * the first frame beyond the model's border. */
static void test_braking_no_debounce(void **state)
{
	calib_t cal;
	transition_t tr[8];
	uint32_t n;
	uint32_t k;

	(void)state;
	calib_default(&cal);
	cal.debounce_count = 1U;
	cal.hyst_lnq_micro = 0U;
	cal.hyst_rho_ppm = 0U;
	braking(&cal);
	n = collect_status();
	assert_int_equal(transitions(n, tr, 8U), 4U);
	k = first_below(ramp_v, RAMP_FRAMES, EXP_V_STABLE_UMPS);
	check_transition_at(&tr[1], k, k);
	assert_int_equal(tr[1].to, MSG_SQUEAL_STATE_BISTABLE);
	k = first_below(ramp_v, RAMP_FRAMES, EXP_V_HOPF_UMPS);
	check_transition_at(&tr[2], k, k);
	assert_int_equal(tr[2].to, MSG_SQUEAL_STATE_UNSTABLE);
	k = first_below(ramp_v, RAMP_FRAMES, 10000);
	check_transition_at(&tr[3], k, k);
	assert_int_equal(tr[3].to, MSG_SQUEAL_STATE_NOT_SLIDING);
}

/* Warning levels on every status frame of the manoeuvre, and the level 1 ->
 * 2 change at rho = 0.5 (reference speed). HopfMargin = v0 - v_H. */
static void test_braking_warning_levels(void **state)
{
	uint32_t n;
	uint32_t i;
	uint32_t k_warn = UINT32_MAX;
	uint32_t seen[4] = { 0 };

	(void)state;
	braking(NULL);
	n = collect_status();
	for (i = 0U; i < n; i++) {
		const status_rec_t *r = &recs[i];

		switch (r->state) {
		case MSG_SQUEAL_STATE_UNSTABLE:
			assert_int_equal(r->warning, 3);
			break;
		case MSG_SQUEAL_STATE_BISTABLE:
			if (r->basin == 0xFFFFU) {
				/* no cycle (a pending unstable point): small basin */
				assert_int_equal(r->warning, 2);
			} else if (r->basin < 4999U) {
				assert_int_equal(r->warning, 2);
			} else if (r->basin > 5001U) {
				assert_int_equal(r->warning, 1);
			}
			if ((r->warning == 2U) && (k_warn == UINT32_MAX)) {
				k_warn = frame_of(r);
				assert_int_equal(r->t_us, in_time(k_warn)); /* at once */
			}
			break;
		default: /* stable, not sliding, fault */
			assert_int_equal(r->warning, 0);
			break;
		}
		seen[r->warning]++;
		if ((r->state <= MSG_SQUEAL_STATE_UNSTABLE) && (r->t_us >= in_time(0))) {
			/* HopfMargin_mps (0.01 m/s) against the reference v_H and
			 * the latest input */
			const uint32_t k = (uint32_t)((r->t_us - in_time(0)) / IN_PERIOD_US);
			const double margin = (double)(ramp_v[k] - EXP_V_HOPF_UMPS) * 1e-4;

			assert_true(fabs((double)r->margin - margin) <= 1.0);
		}
		if (r->state == MSG_SQUEAL_STATE_NOT_SLIDING) {
			assert_int_equal(r->margin, -32768);
			assert_int_equal(r->basin, 0xFFFF);
		}
	}
	for (i = 0U; i < 4U; i++) {
		assert_true(seen[i] > 0U);
	}
	{
		const uint32_t k_ref = first_below(ramp_v, RAMP_FRAMES, EXP_V_RHO_WARN_UMPS);

		print_message("  warning 2 from frame %u, rho = 0.5 crossed at frame %u\n",
			      k_warn, k_ref);
		assert_true(k_warn >= k_ref);
		assert_true(k_warn <= k_ref + 1U);
	}
}

/* SquealStatus every 10 ms plus at once on a change; Detail/Detail2 every
 * 100 ms, Diag every 1000 ms with pages 0,1,2,3,4,0,...; contents of the
 * detail frames against the reference. */
static void test_braking_tx_schedule_and_details(void **state)
{
	uint32_t n;
	uint32_t i;
	uint32_t ndet = 0U;
	uint32_t ndet2 = 0U;
	uint32_t ndiag = 0U;
	int32_t j = -1;

	(void)state;
	braking(NULL);
	n = collect_status();
	for (i = 0U; i < n; i++) {
		const bool periodic = ((recs[i].t_us - T0_US) % (EXP_DBC_SQUEALSTATUS_CYCLE_MS * 1000U)) == 0U;

		if (i > 0U) {
			assert_true(recs[i].t_us - recs[i - 1U].t_us <=
				    EXP_DBC_SQUEALSTATUS_CYCLE_MS * 1000U);
		}
		if (!periodic) {
			/* only sent because the state or level changed */
			assert_true(i > 0U);
			assert_true((recs[i].state != recs[i - 1U].state) ||
				    (recs[i].warning != recs[i - 1U].warning));
		}
	}
	/* every periodic slot up to the end has its frame */
	{
		const uint64_t end = hal_time_us();
		uint32_t periodic = 0U;

		for (i = 0U; i < n; i++) {
			periodic += ((recs[i].t_us - T0_US) % 10000U) == 0U;
		}
		assert_int_equal(periodic, (end - T0_US) / 10000U + 1U);
	}
	while ((j = test_hal_tx_find(EXP_DBC_SQUEALDETAIL_ID, (uint32_t)(j + 1))) >= 0) {
		const hal_can_frame_t *f = test_hal_tx_frame((uint32_t)j);
		const uint64_t t = f->timestamp_us;
		const uint32_t v0 = (uint32_t)test_frame_sig(f->data, 12, 14);
		const uint32_t hopf = (uint32_t)test_frame_sig(f->data, 26, 14);
		const uint32_t kph = (uint32_t)test_frame_sig(f->data, 52, 12);

		assert_int_equal((t - T0_US) % (EXP_DBC_SQUEALDETAIL_CYCLE_MS * 1000U), 0);
		assert_int_equal(t - T0_US, (uint64_t)ndet * EXP_DBC_SQUEALDETAIL_CYCLE_MS * 1000U);
		ndet++;
		if (t < in_time(0)) {
			assert_int_equal(v0, 0x3FFF); /* nothing received yet */
			continue;
		}
		{
			const uint32_t k = (uint32_t)((t - in_time(0)) / IN_PERIOD_US);
			const double v0_ref = (double)ramp_v[k] * 1e-4; /* 0.01 m/s */

			assert_true(fabs((double)v0 - v0_ref) <= 0.5 + 1e-9);
			if ((ramp_v[k] >= 10000) && (hopf != 0x3FFFU)) {
				/* v_H 1.2315 m/s; car 1.2315 * 0.3 / 0.12 * 3.6 km/h */
				assert_int_equal(hopf, (uint32_t)lround((double)EXP_V_HOPF_UMPS * 1e-4));
				assert_int_equal(kph, (uint32_t)lround((double)EXP_V_HOPF_UMPS * 1e-6 *
								      2.5 * 3.6 * 10.0));
			}
		}
	}
	j = -1;
	while ((j = test_hal_tx_find(EXP_DBC_SQUEALDETAIL2_ID, (uint32_t)(j + 1))) >= 0) {
		const hal_can_frame_t *f = test_hal_tx_frame((uint32_t)j);
		const uint64_t t = f->timestamp_us;
		const uint32_t force = (uint32_t)test_frame_sig(f->data, 16, 16);
		const uint32_t nh = (uint32_t)test_frame_sig(f->data, 32, 16);

		assert_int_equal(t - T0_US, (uint64_t)ndet2 * EXP_DBC_SQUEALDETAIL2_CYCLE_MS * 1000U);
		ndet2++;
		if (t < in_time(0)) {
			assert_int_equal(force, 0xFFFF);
			continue;
		}
		assert_int_equal(force, FORCE_9KN_RAW);
		if (nh != 0xFFFFU) {
			const uint32_t k = (uint32_t)((t - in_time(0)) / IN_PERIOD_US);
			/* N_H = 2 D w0 m exp(a v0) / (a dmu) */
			const double nh_ref = 2.0 * 0.023 * 5000.0 * 1.0 *
				exp(2.0 * (double)ramp_v[k] * 1e-6) / (2.0 * 0.15);

			if (nh_ref < 65000.0) {
				assert_true(fabs((double)nh - nh_ref) <= 1.0 + 2e-5 * nh_ref);
			} else {
				assert_true(nh >= 65000U);
			}
		}
	}
	j = -1;
	while ((j = test_hal_tx_find(EXP_DBC_SQUEALDIAG_ID, (uint32_t)(j + 1))) >= 0) {
		const hal_can_frame_t *f = test_hal_tx_frame((uint32_t)j);

		assert_int_equal(f->timestamp_us - T0_US,
				 (uint64_t)ndiag * EXP_DBC_SQUEALDIAG_CYCLE_MS * 1000U);
		assert_int_equal(test_frame_sig(f->data, 12, 4), ndiag % MSG_DIAG_PAGE_COUNT);
		if (test_frame_sig(f->data, 12, 4) == 0U) {
			assert_int_equal(test_frame_sig(f->data, 32, 24), ndiag); /* uptime s */
		}
		ndiag++;
	}
	assert_true(ndet >= 40U);
	assert_int_equal(ndet, ndet2);
	assert_true(ndiag >= 4U);
	check_tx_e2e();
}

/* ---- chattering at the Hopf border -------------------------------------- */

/*
 * v_H = 1.231464 m/s = Omega 10.262 rad/s. Raw 1025 (1.2300 m/s, ln 2Q =
 * -0.0029: unstable) and 1028 (1.2336 m/s, ln 2Q = +0.0043: bistable) both
 * lie inside the default band |ln 2Q| <= 0.02.
 */
#define CH_UNSTABLE_RAW 1025U
#define CH_BISTABLE_RAW 1028U

static void test_chatter_suppressed_at_hopf_border(void **state)
{
	test_sender_t snd;
	uint32_t k;
	uint32_t n;
	uint32_t i;
	uint32_t changes = 0U;
	const uint32_t alternations = 41U; /* U B U B ... U */
	const uint32_t debounce = 3U;

	(void)state;
	assert_true((int64_t)CH_UNSTABLE_RAW * UMPS_PER_RAW < EXP_V_HOPF_UMPS);
	assert_true((int64_t)CH_BISTABLE_RAW * UMPS_PER_RAW > EXP_V_HOPF_UMPS);
	assert_true(EXP_V_HOPF_UMPS - (int64_t)CH_UNSTABLE_RAW * UMPS_PER_RAW < 10000);
	assert_true((int64_t)CH_BISTABLE_RAW * UMPS_PER_RAW - EXP_V_HOPF_UMPS < 10000);
	boot(NULL);
	test_sender_init(&snd);
	for (k = 0U; k < alternations; k++) {
		assert_int_equal(test_send_pair(&snd, (k % 2U) ? CH_BISTABLE_RAW : CH_UNSTABLE_RAW,
						FORCE_9KN_RAW, in_time(k)), SQ_OK);
	}
	for (; k < alternations + 10U; k++) {
		assert_int_equal(test_send_pair(&snd, CH_BISTABLE_RAW, FORCE_9KN_RAW, in_time(k)),
				 SQ_OK);
	}
	run_to(in_time(alternations - 1U) + 9000U);
	n = collect_status();
	for (i = 1U; i < n; i++) {
		if (recs[i].state != recs[i - 1U].state) {
			changes++;
		}
	}
	/* FAULT -> unstable once; the alternation never changes it */
	assert_int_equal(changes, 1U);
	assert_int_equal(recs[n - 1U].state, MSG_SQUEAL_STATE_UNSTABLE);

	/* held just across: the debounce_count-th classification changes it */
	test_hal_tx_clear();
	run_to(in_time(alternations + 9U) + 1000U);
	n = collect_status();
	for (i = 0U; i < n; i++) {
		if (recs[i].state == MSG_SQUEAL_STATE_BISTABLE) {
			break;
		}
		assert_int_equal(recs[i].state, MSG_SQUEAL_STATE_UNSTABLE);
	}
	assert_true(i < n);
	assert_int_equal(recs[i].t_us, in_time(alternations + debounce - 1U));
	for (; i < n; i++) {
		assert_int_equal(recs[i].state, MSG_SQUEAL_STATE_BISTABLE);
	}
	assert_int_equal(squeal_app_monitor()->count.state_changes, 2U);
}

/* The debounce count is the calibration's; a point beyond the band
 * changes the state at once. */
static void test_debounce_count_from_calibration_and_band(void **state)
{
	calib_t cal;
	test_sender_t snd;
	uint32_t k;
	uint32_t n;
	uint32_t i;

	(void)state;
	calib_default(&cal);
	cal.debounce_count = 5U;
	boot(&cal);
	test_sender_init(&snd);
	/* k 0: unstable (out of FAULT at once); 1..5 bistable inside the
	 * band: the 5th changes it; 6: 1.212 m/s (ln 2Q = -0.039, beyond
	 * the band): unstable at once; 7: 1.26 m/s (+0.057): bistable at once */
	static const uint16_t raws[8] = { CH_UNSTABLE_RAW, CH_BISTABLE_RAW, CH_BISTABLE_RAW,
					  CH_BISTABLE_RAW, CH_BISTABLE_RAW, CH_BISTABLE_RAW,
					  1010U, 1050U };
	static const uint8_t want_state[4] = { MSG_SQUEAL_STATE_UNSTABLE, MSG_SQUEAL_STATE_BISTABLE,
					       MSG_SQUEAL_STATE_UNSTABLE, MSG_SQUEAL_STATE_BISTABLE };
	static const uint32_t want_k[4] = { 0U, 5U, 6U, 7U };
	uint32_t m = 0U;

	for (k = 0U; k < 8U; k++) {
		assert_int_equal(test_send_pair(&snd, raws[k], FORCE_9KN_RAW, in_time(k)), SQ_OK);
	}
	run_to(in_time(7U) + 1000U);
	n = collect_status();
	for (i = 1U; i < n; i++) {
		if (recs[i].state != recs[i - 1U].state) {
			assert_true(m < 4U);
			assert_int_equal(recs[i].state, want_state[m]);
			assert_int_equal(recs[i].t_us, in_time(want_k[m]));
			m++;
		}
	}
	assert_int_equal(m, 4U);
}

SQ_CMOCKA_MAIN(
	cmocka_unit_test(test_braking_default_calibration),
	cmocka_unit_test(test_braking_no_debounce),
	cmocka_unit_test(test_braking_warning_levels),
	cmocka_unit_test(test_braking_tx_schedule_and_details),
	cmocka_unit_test(test_chatter_suppressed_at_hopf_border),
	cmocka_unit_test(test_debounce_count_from_calibration_and_band))
