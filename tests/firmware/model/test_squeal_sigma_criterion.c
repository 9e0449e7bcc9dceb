/* SPDX-License-Identifier: MIT */
/*
 * squeal_sigma_classify follows the classification's criterion, both
 * numeric builds: with the cubic criterion the stable border it propagates
 * is g_S = ln 2Q - ln(1 + s^2/8) (its class, g, sigma and margin), with the
 * exact one g_S = ln 2Q - ln(2 I1(s)/s); g_H is the same for both.
 *
 * Reference rows: tests/support/reference/sigma_cubic_ref.py (numpy central
 * differences of the border functions themselves, scipy's I1; no
 * closed-form derivative shared), the default brake with deviations
 * m 0.05 kg, w0 50 rad/s, D 0.002, dmu 0.01, a 0.1 s/m, rho(a, dmu) -0.3.
 * At 1.9 m/s and 9000 N the criteria disagree: exact bistable, cubic
 * stable (the cubic border lies at a lower speed: it under-warns).
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include <cmocka.h>

#include "sq_num.h"
#include "squeal_model.h"
#include "squeal_sigma.h"

#if defined(SQUEAL_NUMERIC_FIXED)
#define G_TOL 2e-4
#else
#define G_TOL 1e-4
#endif
#define SIGMA_TOL 1e-3

typedef struct {
	double v0_mps;
	double force_n;
	squeal_criterion_t criterion;
	squeal_state_t state;
	double g_hopf;
	double g_stable;
	double sigma_hopf;
	double sigma_stable;
} row_t;

/* python3 tests/support/reference/sigma_cubic_ref.py */
static const row_t rows[] = {
	{ 1.000, 9000.0, SQUEAL_CRITERION_EXACT, SQUEAL_STATE_UNSTABLE, -0.462927743, -0.927062217, 0.138224025, 0.122139637 },
	{ 1.000, 9000.0, SQUEAL_CRITERION_CUBIC, SQUEAL_STATE_UNSTABLE, -0.462927743, -0.868392851, 0.138224025, 0.124700945 },
	{ 1.500, 9000.0, SQUEAL_CRITERION_EXACT, SQUEAL_STATE_BISTABLE, 0.537072257, -0.432031070, 0.169132732, 0.124168105 },
	{ 1.500, 9000.0, SQUEAL_CRITERION_CUBIC, SQUEAL_STATE_BISTABLE, 0.537072257, -0.216699545, 0.169132732, 0.136758060 },
	{ 1.900, 9000.0, SQUEAL_CRITERION_EXACT, SQUEAL_STATE_BISTABLE, 1.337072257, -0.117916195, 0.199514113, 0.125060943 },
	{ 1.900, 9000.0, SQUEAL_CRITERION_CUBIC, SQUEAL_STATE_STABLE, 1.337072257, 0.305668718, 0.199514113, 0.152823175 },
	{ 3.000, 9000.0, SQUEAL_CRITERION_EXACT, SQUEAL_STATE_STABLE, 3.537072257, 0.519220813, 0.295137055, 0.126102549 },
	{ 3.000, 9000.0, SQUEAL_CRITERION_CUBIC, SQUEAL_STATE_STABLE, 3.537072257, 1.832324165, 0.295137055, 0.222751606 },
	{ 0.600, 4000.0, SQUEAL_CRITERION_EXACT, SQUEAL_STATE_UNSTABLE, -0.451997527, -0.626899881, 0.122905985, 0.119894350 },
	{ 0.600, 4000.0, SQUEAL_CRITERION_CUBIC, SQUEAL_STATE_UNSTABLE, -0.451997527, -0.617511965, 0.122905985, 0.120097122 },
};

/* One row's inputs: the default parameters, fixed deviations, its point. */
typedef struct {
	squeal_params_t p;
	squeal_param_sd_t sd;
	squeal_point_t pt;
} inputs_t;

static void inputs(const row_t *r, inputs_t *in)
{
	squeal_params_t *p = &in->p;
	squeal_param_sd_t *sd = &in->sd;
	squeal_point_t *pt = &in->pt;

	squeal_model_default_params(p);
	squeal_sigma_sd_zero(sd);
	sd->mass_kg_sd = sq_num_from_double(0.05, SQUEAL_Q_MASS);
	sd->omega0_radps_sd = sq_num_from_double(50.0, SQUEAL_Q_OMEGA0);
	sd->damping_sd = sq_num_from_double(0.002, SQUEAL_Q_DAMPING);
	sd->delta_mu_sd = sq_num_from_double(0.01, SQUEAL_Q_MU);
	sd->slope_spm_sd = sq_num_from_double(0.1, SQUEAL_Q_SLOPE);
	sd->slope_delta_mu_corr = sq_num_from_double(-0.3, SQUEAL_Q_CORR);
	pt->v0_mps = sq_num_from_double(r->v0_mps, SQUEAL_Q_V0);
	pt->force_n = sq_num_from_double(r->force_n, SQUEAL_Q_FORCE);
}

static double margin_of(squeal_state_t st, double gh, double gs, double sh, double ss)
{
	const double to_h = fabs(gh) / sh;
	const double to_s = fabs(gs) / ss;

	if (st == SQUEAL_STATE_UNSTABLE) {
		return to_h;
	}
	return (st == SQUEAL_STATE_STABLE) ? to_s : fmin(to_h, to_s);
}

static void test_borders_follow_the_criterion(void **state)
{
	(void)state;
	for (size_t i = 0; i < sizeof(rows) / sizeof(rows[0]); i++) {
		const row_t *r = &rows[i];
		inputs_t in;
		squeal_result_t res;
		squeal_result_t alone;
		squeal_sigma_result_t sig;
		double got;
		double want;

		inputs(r, &in);
		assert_int_equal(squeal_sigma_classify(&in.p, &in.sd, &in.pt, r->criterion, &res, &sig), SQ_OK);
		/* the classification is squeal_model_classify's, unchanged */
		assert_int_equal(squeal_model_classify(&in.p, &in.pt, r->criterion, &alone), SQ_OK);
		assert_int_equal(res.state, alone.state);
		assert_true(res.flags == alone.flags && res.basin_ratio == alone.basin_ratio);
		assert_int_equal(res.state, r->state);
		assert_int_equal(sig.state, r->state);
		assert_true((sig.flags & SQUEAL_SIGMA_HAS_BORDERS) != 0U);
		if ((fabs(sq_num_to_double(sig.g_stable, SQUEAL_Q_LNQ) - r->g_stable) > G_TOL) ||
		    (fabs(sq_num_to_double(sig.sigma_stable, SQUEAL_Q_SIGMA) / r->sigma_stable - 1.0) >
		     SIGMA_TOL)) {
			fprintf(stderr, "row %zu: g_S %.9f (want %.9f), sigma_S %.9f (want %.9f)\n", i,
				sq_num_to_double(sig.g_stable, SQUEAL_Q_LNQ), r->g_stable,
				sq_num_to_double(sig.sigma_stable, SQUEAL_Q_SIGMA), r->sigma_stable);
		}
		assert_true(fabs(sq_num_to_double(sig.g_hopf, SQUEAL_Q_LNQ) - r->g_hopf) <= G_TOL);
		assert_true(fabs(sq_num_to_double(sig.g_stable, SQUEAL_Q_LNQ) - r->g_stable) <= G_TOL);
		assert_true(fabs(sq_num_to_double(sig.sigma_hopf, SQUEAL_Q_SIGMA) / r->sigma_hopf - 1.0) <=
			    SIGMA_TOL);
		assert_true(fabs(sq_num_to_double(sig.sigma_stable, SQUEAL_Q_SIGMA) / r->sigma_stable -
				 1.0) <= SIGMA_TOL);
		/* the margin of the class, from the reference's g and sigma */
		want = margin_of(r->state, r->g_hopf, r->g_stable, r->sigma_hopf, r->sigma_stable);
		got = sq_num_to_double(sig.margin_sigma, SQUEAL_Q_MARGIN);
		assert_true(fabs(got - want) <= 2e-3 * want + 4.0 * sq_num_lsb(SQUEAL_Q_MARGIN));
		/* the exact criterion's uncertainty alone: squeal_sigma_eval */
		if (r->criterion == SQUEAL_CRITERION_EXACT) {
			squeal_sigma_result_t ex;

			assert_int_equal(squeal_sigma_eval(&in.p, &in.sd, &in.pt, &ex), SQ_OK);
			assert_int_equal(ex.state, sig.state);
			assert_true(ex.g_stable == sig.g_stable && ex.sigma_stable == sig.sigma_stable &&
				    ex.margin_sigma == sig.margin_sigma);
		}
	}
}

/* Without deviations (sd and sig NULL) the classification alone; one of
 * the two NULL is a programming error. Not sliding: no border. */
static void test_without_deviations_and_not_sliding(void **state)
{
	inputs_t in;
	squeal_result_t res;
	squeal_result_t alone;
	squeal_sigma_result_t sig;

	(void)state;
	inputs(&rows[5], &in);
	assert_int_equal(squeal_sigma_classify(&in.p, NULL, &in.pt, SQUEAL_CRITERION_CUBIC, &res, NULL),
			 SQ_OK);
	assert_int_equal(squeal_model_classify(&in.p, &in.pt, SQUEAL_CRITERION_CUBIC, &alone), SQ_OK);
	assert_int_equal(res.state, alone.state);
	expect_assert_failure(squeal_sigma_classify(&in.p, &in.sd, &in.pt, SQUEAL_CRITERION_CUBIC, &res, NULL));
	expect_assert_failure(squeal_sigma_classify(&in.p, NULL, &in.pt, SQUEAL_CRITERION_CUBIC, &res, &sig));
	expect_assert_failure(squeal_sigma_classify(NULL, &in.sd, &in.pt, SQUEAL_CRITERION_CUBIC, &res, &sig));
	expect_assert_failure(squeal_sigma_classify(&in.p, &in.sd, NULL, SQUEAL_CRITERION_CUBIC, &res, &sig));
	expect_assert_failure(squeal_sigma_classify(&in.p, &in.sd, &in.pt, SQUEAL_CRITERION_CUBIC, NULL, &sig));
	in.pt.v0_mps = 0;
	assert_int_equal(squeal_sigma_classify(&in.p, &in.sd, &in.pt, SQUEAL_CRITERION_CUBIC, &res, &sig),
			 SQ_OK);
	assert_int_equal(sig.state, SQUEAL_STATE_NOT_SLIDING);
	assert_true(sig.flags == 0U && sig.margin_sigma == SQUEAL_SIGMA_MARGIN_MAX);
	/* an unknown criterion is an invalid classification, and so is the
	 * uncertainty */
	inputs(&rows[5], &in);
	assert_int_equal(squeal_sigma_classify(&in.p, &in.sd, &in.pt, (squeal_criterion_t)7, &res, &sig),
			 SQ_EINVAL);
	assert_int_equal(res.state, SQUEAL_STATE_INVALID);
	assert_int_equal(sig.state, SQUEAL_STATE_INVALID);
	/* deviations outside their domain: the classification stands, the
	 * uncertainty is invalid */
	in.sd.damping_sd = in.p.damping + 1;
	assert_int_equal(squeal_sigma_classify(&in.p, &in.sd, &in.pt, SQUEAL_CRITERION_CUBIC, &res, &sig),
			 SQ_OK);
	assert_int_equal(res.state, SQUEAL_STATE_STABLE);
	assert_int_equal(sig.state, SQUEAL_STATE_INVALID);
	assert_true(sig.flags == 0U && sig.margin_sigma == 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_borders_follow_the_criterion),
		cmocka_unit_test(test_without_deviations_and_not_sliding),
	};

	return cmocka_run_group_tests_name(sq_num_is_fixed() ? "sigma criterion (fixed)" :
					   "sigma criterion (float)", tests, NULL, NULL);
}
