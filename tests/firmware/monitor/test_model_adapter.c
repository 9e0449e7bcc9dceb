/* SPDX-License-Identifier: MIT */
/*
 * firmware/monitor/model_adapter.c, both numeric builds: the integer view of
 * a model result, at the places where a rounding rule decides (found by
 * make mutate; the other tests cross them only by chance):
 *   - ln(2Q) in micro-units is ln Q (the model's own value) plus ln 2 from
 *     the C library, within the rounding of each part;
 *   - a BISTABLE point never reports a basin ratio of 1.000000 (rounding to
 *     ppm must not move rho across 1, where the class changes): checked on
 *     the points next to the bistable/stable border, found by bisection.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <math.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "calib.h"
#include "model_adapter.h"
#include "sq_num.h"
#include "squeal_model.h"

#define FORCE_MN 9000000 /* 9 kN */

static squeal_params_t params;
static squeal_criterion_t criterion;

static void setup_params(void)
{
	calib_t cal;

	calib_default(&cal);
	calib_model_params(&cal, &params);
	criterion = (squeal_criterion_t)cal.criterion;
}

static model_eval_t eval_at(int32_t v0_umps, int32_t force_mn)
{
	model_eval_t e;

	(void)model_adapter_eval(&params, criterion, v0_umps, force_mn, &e);
	return e;
}

static void test_ln_2q_is_ln_q_plus_ln_2(void **state)
{
	/* fixed: ln Q in Q16 converted exactly, then rounded (0.5) plus ln 2
	 * rounded to 693147 (0.18); float: the float product 1e6 ln Q adds
	 * and its rounding add up to two float spacings at its magnitude */
	uint32_t n = 0U;

	(void)state;
	setup_params();
	for (int32_t v = 200000; v < 30000000; v += 377777) {
		squeal_point_t pt;
		squeal_result_t r;
		model_eval_t e = eval_at(v, FORCE_MN);
		double want;

		if ((e.has & MODEL_EVAL_HAS_LNQ) == 0U) {
			continue;
		}
		pt.v0_mps = sq_num_from_double((double)v * 1e-6, SQUEAL_Q_V0);
		pt.force_n = sq_num_from_double((double)FORCE_MN * 1e-3, SQUEAL_Q_FORCE);
		(void)squeal_model_classify(&params, &pt, criterion, &r);
		want = 1e6 * (sq_num_to_double(r.ln_q, SQUEAL_Q_LNQ) + log(2.0));
		const double tol = 0.69 + (sq_num_is_fixed() ? 0.0 :
			ldexp(1.0, ilogb(fabs(want) + 1.0) - 22));
		if (fabs((double)e.ln_2q_micro - want) > tol) {
			fail_msg("v0 %d um/s: ln(2Q) %d micro, ln Q + ln 2 = %.3f", v, e.ln_2q_micro, want);
		}
		n++;
	}
	assert_true(n >= 20U);
}

static void test_bistable_ratio_below_one_at_the_border(void **state)
{
	int32_t lo = 1240000; /* BISTABLE at 9 kN (default calibration) */
	int32_t hi = 2080000; /* STABLE */
	uint32_t bistable = 0U;
	uint32_t at_top = 0U;

	(void)state;
	setup_params();
	assert_int_equal(eval_at(lo, FORCE_MN).state, SQUEAL_STATE_BISTABLE);
	assert_int_equal(eval_at(hi, FORCE_MN).state, SQUEAL_STATE_STABLE);
	while (hi - lo > 1) {
		const int32_t mid = lo + (hi - lo) / 2;

		if (eval_at(mid, FORCE_MN).state == SQUEAL_STATE_BISTABLE) {
			lo = mid;
		} else {
			hi = mid;
		}
	}
	/* the last 200 um/s below the border, and a few forces */
	for (int32_t f = FORCE_MN - 20; f <= FORCE_MN + 20; f += 10) {
		for (int32_t v = lo - 200; v <= lo + 5; v++) {
			const model_eval_t e = eval_at(v, f);

			if ((e.state != SQUEAL_STATE_BISTABLE) || ((e.has & MODEL_EVAL_HAS_BASIN) == 0U)) {
				continue;
			}
			bistable++;
			if (e.basin_ratio_ppm >= 1000000) {
				fail_msg("BISTABLE at %d um/s, %d mN reports ratio %d ppm", v, f,
					 e.basin_ratio_ppm);
			}
			if (e.basin_ratio_ppm == 999999) {
				at_top++;
			}
		}
	}
	print_message("  border at %d um/s: %u bistable points, %u at 999999 ppm\n", lo, bistable,
		      at_top);
	assert_true(bistable > 100U);
	assert_true(at_top > 0U);
}

SQ_CMOCKA_MAIN(
	cmocka_unit_test(test_ln_2q_is_ln_q_plus_ln_2),
	cmocka_unit_test(test_bistable_ratio_below_one_at_the_border))
