/* SPDX-License-Identifier: MIT */
/*
 * The calibration's standard deviations in the monitor, through
 * its real interfaces as in test_monitor.c: protected frames in, the app
 * polled every virtual millisecond, frames out decoded by hand from the
 * DBC layout (SquealStatus: SquealState 12|4, WarningLevel 16|4,
 * BorderMargin_sigma 56|8 = byte 7, raw x 0.1 - 0.1 sigma, 0 n/a, 255 sat).
 *
 *   - zero deviations: every frame of a braking drive is today's (a second
 *     run with deviations but k = 0 differs only in BorderMargin_sigma and
 *     the E2E CRC over it; the zero run sends BorderMargin_sigma 0);
 *   - BorderMargin_sigma equals squeal_sigma_margin() of the debounced class
 *     at the classified point (squeal_sigma is checked against Monte Carlo
 *     by test_sigma);
 *   - the uncertain rule: within k sigma of the border to the more severe
 *     neighbour, that neighbour's level (stable -> advisory, bistable ->
 *     critical); beyond it, today's level.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "calib.h"
#include "calib_map.h"
#include "model_adapter.h"
#include "monitor_expect.h"
#include "sq_status.h"
#include "squeal_app.h"
#include "squeal_sigma.h"
#include "test_hal.h"

#define T0_US 1000000ULL
#define IN_OFFSET_US 5000ULL
#define IN_PERIOD_US 10000ULL
#define FORCE_9KN_RAW 18000U /* 0.5 N per bit */
#define FORCE_MN 9000000
#define UMPS_PER_RAW 1200    /* 0.01 rad/s x r_p 0.12 m */
#define RAMP_START_RAW 10000U
#define RAMP_STEP_RAW 25U
#define RAMP_FRAMES (RAMP_START_RAW / RAMP_STEP_RAW + 1U + 20U)
#define MAX_TX 8192U

static hal_can_frame_t run_a[MAX_TX];
static hal_can_frame_t run_b[MAX_TX];

static uint64_t in_time(uint32_t k)
{
	return T0_US + IN_OFFSET_US + IN_PERIOD_US * k;
}

static uint32_t ramp_raw(uint32_t k)
{
	return (k * RAMP_STEP_RAW < RAMP_START_RAW) ? RAMP_START_RAW - k * RAMP_STEP_RAW : 0U;
}

/* relative deviations of the Monte Carlo file's first set (tests/support/golden):
 * m 2 %, w0 1.5 %, D 10 %, dmu 4 %, a 5 %, corr(a, dmu) 0.85, in Q formats */
static void with_deviations(calib_t *cal)
{
	calib_default(cal);
	cal->sd.mass_sd_q16 = 1311;                /* 0.02 kg       */
	cal->sd.omega0_sd_q12 = 75 * 4096;         /* 75 rad/s      */
	cal->sd.damping_sd_q30 = 2469606;          /* 0.0023        */
	cal->sd.delta_mu_sd_q30 = 6442451;         /* 0.006         */
	cal->sd.slope_sd_q24 = 1677722;            /* 0.1 s/m       */
	cal->sd.slope_delta_mu_corr_q30 = 912680550; /* 0.85        */
}

/* the braking manoeuvre of test_monitor.c: 30 m/s to a stop at 9 kN */
static uint32_t braking(const calib_t *cal, hal_can_frame_t *out)
{
	uint8_t buf[CALIB_BLOCK_LEN];
	test_sender_t snd;
	uint32_t k;
	uint32_t n;

	test_hal_reset();
	test_hal_set_time_us(T0_US);
	assert_int_equal(calib_encode(cal, buf, sizeof(buf)), SQ_OK);
	test_hal_calib_store(buf, sizeof(buf));
	assert_int_equal(squeal_app_init(), SQ_OK);
	(void)squeal_app_poll();
	test_sender_init(&snd);
	for (k = 0U; k < RAMP_FRAMES; k++) {
		assert_int_equal(test_send_pair(&snd, (uint16_t)ramp_raw(k), FORCE_9KN_RAW,
						in_time(k)), SQ_OK);
	}
	while (hal_time_us() < in_time(RAMP_FRAMES - 1U) + 20000U) {
		test_hal_advance_us(1000U);
		(void)squeal_app_poll();
	}
	n = test_hal_tx_count();
	assert_true(n <= MAX_TX);
	for (k = 0U; k < n; k++) {
		out[k] = *test_hal_tx_frame(k);
	}
	return n;
}

/* the input pair a status frame reports (the last classified before it) */
static uint32_t pair_of(const hal_can_frame_t *f)
{
	assert_true(f->timestamp_us >= in_time(0));
	return (uint32_t)((f->timestamp_us - in_time(0)) / IN_PERIOD_US);
}

/* squeal_sigma at pair k: the result, and the margin of `state` as the
 * bus carries it (sigmas x 2^16 -> tenths, rounded, + 1; 255 from 25.4) */
static void sigma_at(const calib_t *cal, uint32_t k, squeal_sigma_result_t *r)
{
	squeal_params_t p;
	squeal_param_sd_t sd;
	calib_corner_t c;

	calib_model_params(cal, &p);
	calib_corner_defaults(cal, 0U, &c);
	calib_corner_sd(&c, &sd);
	assert_int_equal(model_adapter_sigma(&p, &sd, (int32_t)(ramp_raw(k) * UMPS_PER_RAW),
					     FORCE_MN, r), SQ_OK);
}

static int64_t q16_of(squeal_num_t m)
{
#if defined(SQUEAL_NUMERIC_FIXED)
	return m;
#else
	const double x = (double)m * 65536.0;

	return (int64_t)(x + 0.5);
#endif
}

static uint32_t margin_raw(const squeal_sigma_result_t *r, uint8_t state)
{
	squeal_num_t m;
	int64_t tenths;

	assert_int_equal(squeal_sigma_margin(r, (squeal_state_t)state, &m), SQ_OK);
	if (m >= SQUEAL_SIGMA_MARGIN_MAX) {
		return 0U;
	}
	tenths = ((q16_of(m) * 10) + 32768) >> 16;
	return (tenths >= 254) ? 255U : (uint32_t)(tenths + 1);
}

static void test_zero_deviations_are_todays_frames(void **state)
{
	calib_t zero;
	calib_t sd_k0;
	uint32_t na;
	uint32_t nb;
	uint32_t i;
	uint32_t status = 0U;
	uint32_t differs = 0U;

	(void)state;
	calib_default(&zero);
	with_deviations(&sd_k0);
	sd_k0.uncertain_k_q16 = 0; /* rule off: only the margin is new */
	na = braking(&zero, run_a);
	nb = braking(&sd_k0, run_b);
	assert_int_equal(na, nb);
	assert_true(na > 400U);
	for (i = 0U; i < na; i++) {
		const hal_can_frame_t *a = &run_a[i];
		const hal_can_frame_t *b = &run_b[i];

		assert_int_equal(a->id, b->id);
		assert_int_equal(a->dlc, b->dlc);
		assert_true(a->timestamp_us == b->timestamp_us);
		if (a->id == EXP_DBC_SQUEALSTATUS_ID) {
			status++;
			assert_int_equal(test_frame_sig(a->data, 56, 8), 0); /* n/a */
			/* bytes 1..6 (counter, state, level, basin, Hopf margin) equal */
			assert_memory_equal(&a->data[1], &b->data[1], 6);
			differs += (a->data[7] != b->data[7]) ? 1U : 0U;
		} else {
			assert_memory_equal(a->data, b->data, a->dlc);
		}
	}
	assert_true(status > 400U);
	assert_true(differs > 100U); /* the deviations do reach the bus */
}

/* BorderMargin_sigma, bit 56..63, against squeal_sigma for every classified
 * status frame; and the warning level with the uncertain rule (k = 2). */
static void test_margin_and_uncertain_rule_on_the_bus(void **state)
{
	calib_t cal;
	uint32_t n;
	uint32_t i;
	uint32_t checked = 0U;
	uint32_t raised_stable = 0U;
	uint32_t raised_bistable = 0U;
	uint32_t plain = 0U;

	(void)state;
	with_deviations(&cal);
	n = braking(&cal, run_a);
	for (i = 0U; i < n; i++) {
		const hal_can_frame_t *f = &run_a[i];
		squeal_sigma_result_t r;
		uint8_t st;
		uint8_t level;
		uint32_t raw;
		uint32_t k;

		if (f->id != EXP_DBC_SQUEALSTATUS_ID) {
			continue;
		}
		st = (uint8_t)test_frame_sig(f->data, 12, 4);
		level = (uint8_t)test_frame_sig(f->data, 16, 4);
		raw = (uint32_t)test_frame_sig(f->data, 56, 8);
		if (st > MSG_SQUEAL_STATE_UNSTABLE) {
			assert_int_equal(raw, 0U); /* no class: n/a */
			continue;
		}
		k = pair_of(f);
		sigma_at(&cal, k, &r);
		assert_int_equal(raw, margin_raw(&r, st));
		checked++;
		if (st == MSG_SQUEAL_STATE_STABLE) {
			/* the stable border's distance is the class's own margin */
			if (raw < 21U) {        /* < 2.0 sigma */
				assert_int_equal(level, MSG_WARNING_LEVEL_ADVISORY);
				raised_stable++;
			} else if (raw > 21U) {
				assert_int_equal(level, MSG_WARNING_LEVEL_NONE);
				plain++;
			}
		} else if (st == MSG_SQUEAL_STATE_BISTABLE) {
			const uint32_t to_hopf = margin_raw(&r, MSG_SQUEAL_STATE_UNSTABLE);

			if (to_hopf < 21U) {
				assert_int_equal(level, MSG_WARNING_LEVEL_CRITICAL);
				raised_bistable++;
			} else if (to_hopf > 21U) {
				assert_true((level == MSG_WARNING_LEVEL_ADVISORY) ||
					    (level == MSG_WARNING_LEVEL_WARNING));
				plain++;
			}
		} else {
			assert_int_equal(level, MSG_WARNING_LEVEL_CRITICAL);
		}
	}
	print_message("  %u status frames checked: %u stable raised, %u bistable raised, %u plain\n",
		      checked, raised_stable, raised_bistable, plain);
	assert_true(checked > 300U);
	assert_true(raised_stable > 0U);
	assert_true(raised_bistable > 0U);
	assert_true(plain > 100U);
}

/* The same drive without deviations: the levels never raise (stable is
 * level 0 on every frame, right up to the border). */
static void test_zero_deviations_no_raised_level(void **state)
{
	calib_t cal;
	uint32_t n;
	uint32_t i;

	(void)state;
	calib_default(&cal);
	n = braking(&cal, run_a);
	for (i = 0U; i < n; i++) {
		const hal_can_frame_t *f = &run_a[i];

		if ((f->id == EXP_DBC_SQUEALSTATUS_ID) &&
		    (test_frame_sig(f->data, 12, 4) == MSG_SQUEAL_STATE_STABLE)) {
			assert_int_equal(test_frame_sig(f->data, 16, 4), MSG_WARNING_LEVEL_NONE);
		}
	}
}

SQ_CMOCKA_MAIN(
	cmocka_unit_test(test_zero_deviations_are_todays_frames),
	cmocka_unit_test(test_margin_and_uncertain_rule_on_the_bus),
	cmocka_unit_test(test_zero_deviations_no_raised_level))
