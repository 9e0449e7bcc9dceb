/* SPDX-License-Identifier: MIT */
/*
 * firmware/model/squeal_sigma.h against Monte Carlo (both numeric builds).
 *
 * tests/support/golden/sigma_vectors.csv (tests/support/reference/gen_sigma_reference.py,
 * numpy/scipy, 20000 samples per row, fixed seed) holds 162 rows: three
 * brakes x 18 operating points x three sets of standard deviations (all
 * relative deviations <= 10 %). Checks:
 *   - sigma of g_H and of g_S within 10 % of the Monte Carlo spread (the
 *     brief's bound; the worst relative error per border is printed);
 *   - the same sigmas within 0.1 % of the reference's
 *     first order from numerical derivatives (no closed form shared), which
 *     pins the closed-form derivatives themselves;
 *   - g_H and g_S within 1e-4 (float) / 2e-4 (fixed), and the class equal to
 *     the model reference wherever both g are farther than 1e-3 from 0;
 *   - the margin: |g| / sigma of the border(s) adjacent to the class;
 *   - zero standard deviations: both sigmas exactly 0, margin
 *     SQUEAL_SIGMA_MARGIN_MAX, class the model's (today's behaviour);
 *   - no border (a = 0, dmu <= 0), not sliding, out-of-domain sd, NULL.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "sq_num.h"
#include "squeal_model.h"
#include "squeal_sigma.h"

#define MAX_ROWS 400
#define MC_TOL 0.10
#if defined(SQUEAL_NUMERIC_FIXED)
#define LIN_TOL 1e-3
#define G_TOL 2e-4
#else
#define LIN_TOL 1e-3
#define G_TOL 1e-4
#endif
#define CLASS_TOL 1e-3

enum col {
	C_ID, C_V0, C_FORCE, C_MASS, C_OMEGA0, C_DAMPING, C_MU_INF, C_DMU, C_SLOPE,
	C_MASS_SD, C_OMEGA0_SD, C_DAMPING_SD, C_DMU_SD, C_SLOPE_SD, C_CORR,
	C_STATE, C_GH, C_GS, C_SH_MC, C_SS_MC, C_SH_LIN, C_SS_LIN, C_DEV, C_COUNT
};

static const char *csv_path = "tests/support/golden/sigma_vectors.csv";
static double rows[MAX_ROWS][C_COUNT];
static int n_rows;

static int setup(void **state)
{
	FILE *fp = fopen(csv_path, "r");
	char line[1024];
	int header_seen = 0;

	(void)state;
	if (fp == NULL) {
		fprintf(stderr, "cannot open %s\n", csv_path);
		return -1;
	}
	n_rows = 0;
	while (fgets(line, sizeof line, fp) != NULL) {
		char *p = line;
		int c;

		if (line[0] == '#') {
			continue;
		}
		if (!header_seen) {
			header_seen = 1;
			continue;
		}
		if (n_rows >= MAX_ROWS) {
			break;
		}
		for (c = 0; c < C_COUNT; c++) {
			char *end;

			rows[n_rows][c] = strtod(p, &end);
			if (end == p) {
				fprintf(stderr, "%s: bad row %d column %d\n", csv_path, n_rows, c);
				fclose(fp);
				return -1;
			}
			p = (*end == ',') ? end + 1 : end;
		}
		n_rows++;
	}
	fclose(fp);
	return (n_rows > 100) ? 0 : -1;
}

static void row_inputs(const double *r, squeal_params_t *p, squeal_param_sd_t *sd,
		       squeal_point_t *pt)
{
	p->mass_kg = sq_num_from_double(r[C_MASS], SQUEAL_Q_MASS);
	p->omega0_radps = sq_num_from_double(r[C_OMEGA0], SQUEAL_Q_OMEGA0);
	p->damping = sq_num_from_double(r[C_DAMPING], SQUEAL_Q_DAMPING);
	p->mu_inf = sq_num_from_double(r[C_MU_INF], SQUEAL_Q_MU);
	p->delta_mu = sq_num_from_double(r[C_DMU], SQUEAL_Q_MU);
	p->slope_spm = sq_num_from_double(r[C_SLOPE], SQUEAL_Q_SLOPE);
	sd->mass_kg_sd = sq_num_from_double(r[C_MASS_SD], SQUEAL_Q_MASS);
	sd->omega0_radps_sd = sq_num_from_double(r[C_OMEGA0_SD], SQUEAL_Q_OMEGA0);
	sd->damping_sd = sq_num_from_double(r[C_DAMPING_SD], SQUEAL_Q_DAMPING);
	sd->mu_inf_sd = sq_num_from_double(0.01, SQUEAL_Q_MU);
	sd->delta_mu_sd = sq_num_from_double(r[C_DMU_SD], SQUEAL_Q_MU);
	sd->slope_spm_sd = sq_num_from_double(r[C_SLOPE_SD], SQUEAL_Q_SLOPE);
	sd->slope_delta_mu_corr = sq_num_from_double(r[C_CORR], SQUEAL_Q_CORR);
	pt->v0_mps = sq_num_from_double(r[C_V0], SQUEAL_Q_V0);
	pt->force_n = sq_num_from_double(r[C_FORCE], SQUEAL_Q_FORCE);
}

static double rel_err(double got, double want)
{
	return fabs(got / want - 1.0);
}

/* Row i through squeal_sigma_eval (must succeed, with borders); its
 * calibration and point into p and pt. */
static void eval_row(int i, squeal_params_t *p, squeal_point_t *pt,
		     squeal_sigma_result_t *out)
{
	squeal_param_sd_t sd;

	row_inputs(rows[i], p, &sd, pt);
	assert_int_equal(squeal_sigma_eval(p, &sd, pt, out), SQ_OK);
	assert_true((out->flags & SQUEAL_SIGMA_HAS_BORDERS) != 0U);
}

static double sigma_of(squeal_num_t v)
{
	return sq_num_to_double(v, SQUEAL_Q_SIGMA);
}

static void test_sigma_agrees_with_monte_carlo(void **state)
{
	double worst_h = 0.0;
	double worst_s = 0.0;
	int worst_h_id = -1;
	int worst_s_id = -1;
	int bad = 0;
	int i;

	(void)state;
	for (i = 0; i < n_rows; i++) {
		squeal_params_t p;
		squeal_point_t pt;
		squeal_sigma_result_t out;
		double eh;
		double es;

		eval_row(i, &p, &pt, &out);
		eh = rel_err(sigma_of(out.sigma_hopf), rows[i][C_SH_MC]);
		es = rel_err(sigma_of(out.sigma_stable), rows[i][C_SS_MC]);
		if (eh > worst_h) {
			worst_h = eh;
			worst_h_id = (int)rows[i][C_ID];
		}
		if (es > worst_s) {
			worst_s = es;
			worst_s_id = (int)rows[i][C_ID];
		}
		if ((eh > MC_TOL || es > MC_TOL) && bad++ < 10) {
			fprintf(stderr, "row %d: sigma_H %g (MC %g), sigma_S %g (MC %g)\n",
				(int)rows[i][C_ID], sigma_of(out.sigma_hopf), rows[i][C_SH_MC],
				sigma_of(out.sigma_stable), rows[i][C_SS_MC]);
		}
	}
	printf("sigma vs Monte Carlo (%s, %d rows): worst relative error Hopf %.4f (row %d), "
	       "stable %.4f (row %d), bound %.2f\n", sq_num_build_name(), n_rows,
	       worst_h, worst_h_id, worst_s, worst_s_id, MC_TOL);
	assert_int_equal(bad, 0);
}

static void test_sigma_matches_numerical_first_order(void **state)
{
	double worst = 0.0;
	int i;

	(void)state;
	for (i = 0; i < n_rows; i++) {
		squeal_params_t p;
		squeal_point_t pt;
		squeal_sigma_result_t out;
		double e;

		eval_row(i, &p, &pt, &out);
		e = fmax(rel_err(sigma_of(out.sigma_hopf), rows[i][C_SH_LIN]),
			 rel_err(sigma_of(out.sigma_stable), rows[i][C_SS_LIN]));
		worst = fmax(worst, e);
		if (e > LIN_TOL) {
			fprintf(stderr, "row %d: first order off by %g\n", (int)rows[i][C_ID], e);
		}
		assert_true(e <= LIN_TOL);
	}
	printf("sigma vs numerical first order (%s): worst relative error %.2e\n",
	       sq_num_build_name(), worst);
}

static double expected_margin(double gh, double gs, double sh, double ss, int state)
{
	const double to_h = fabs(gh) / sh;
	const double to_s = fabs(gs) / ss;

	switch (state) {
	case SQUEAL_STATE_UNSTABLE:
		return to_h;
	case SQUEAL_STATE_STABLE:
		return to_s;
	default:
		return fmin(to_h, to_s);
	}
}

static void test_border_values_class_and_margin(void **state)
{
	int i;

	(void)state;
	for (i = 0; i < n_rows; i++) {
		squeal_params_t p;
		squeal_point_t pt;
		squeal_sigma_result_t out;
		squeal_result_t model;
		const double *r = rows[i];
		double gh;
		double gs;
		double want;
		double got;

		eval_row(i, &p, &pt, &out);
		gh = sq_num_to_double(out.g_hopf, SQUEAL_Q_LNQ);
		gs = sq_num_to_double(out.g_stable, SQUEAL_Q_LNQ);
		assert_true(fabs(gh - r[C_GH]) <= G_TOL);
		assert_true(fabs(gs - r[C_GS]) <= G_TOL);
		if (fabs(r[C_GH]) > CLASS_TOL && fabs(r[C_GS]) > CLASS_TOL) {
			assert_int_equal(out.state, (int)r[C_STATE]);
		}
		/* the class is the model's own, always */
		assert_int_equal(squeal_model_classify(&p, &pt, SQUEAL_CRITERION_EXACT, &model), SQ_OK);
		assert_int_equal(out.state, model.state);
		/* margin from the module's own g and sigma (the formula), then
		 * against the reference's g and Monte Carlo sigma (10 %) */
		want = expected_margin(gh, gs, sigma_of(out.sigma_hopf), sigma_of(out.sigma_stable),
				       (int)out.state);
		got = sq_num_to_double(out.margin_sigma, SQUEAL_Q_MARGIN);
		want = fmin(want, sq_num_to_double(SQUEAL_SIGMA_MARGIN_MAX, SQUEAL_Q_MARGIN));
		assert_true(fabs(got - want) <= 1e-3 * want + 4.0 * sq_num_lsb(SQUEAL_Q_MARGIN));
		if (fabs(r[C_GH]) > CLASS_TOL && fabs(r[C_GS]) > CLASS_TOL) {
			const double mc = expected_margin(r[C_GH], r[C_GS], r[C_SH_MC], r[C_SS_MC],
							  (int)r[C_STATE]);

			assert_true(fabs(got - mc) <= MC_TOL * mc + 2e-3);
		}
	}
}

static void test_zero_sd_is_todays_behaviour(void **state)
{
	int i;

	(void)state;
	for (i = 0; i < n_rows; i++) {
		squeal_params_t p;
		squeal_param_sd_t sd;
		squeal_point_t pt;
		squeal_sigma_result_t out;
		squeal_result_t model;
		squeal_state_t st;
		squeal_num_t margin;

		row_inputs(rows[i], &p, &sd, &pt);
		squeal_sigma_sd_zero(&sd);
		assert_int_equal(squeal_sigma_eval(&p, &sd, &pt, &out), SQ_OK);
		assert_true(out.sigma_hopf == 0);
		assert_true(out.sigma_stable == 0);
		assert_true(out.margin_sigma == SQUEAL_SIGMA_MARGIN_MAX);
		assert_int_equal(squeal_model_classify(&p, &pt, SQUEAL_CRITERION_EXACT, &model), SQ_OK);
		assert_int_equal(out.state, model.state);
		for (st = SQUEAL_STATE_STABLE; st <= SQUEAL_STATE_NOT_SLIDING; st++) {
			assert_int_equal(squeal_sigma_margin(&out, st, &margin), SQ_OK);
			assert_true(margin == SQUEAL_SIGMA_MARGIN_MAX);
		}
	}
}

static void default_inputs(squeal_params_t *p, squeal_param_sd_t *sd, squeal_point_t *pt)
{
	squeal_model_default_params(p);
	squeal_sigma_sd_zero(sd);
	sd->damping_sd = sq_num_from_double(0.002, SQUEAL_Q_DAMPING);
	sd->slope_spm_sd = sq_num_from_double(0.1, SQUEAL_Q_SLOPE);
	pt->v0_mps = sq_num_from_double(1.5, SQUEAL_Q_V0);
	pt->force_n = sq_num_from_double(9000.0, SQUEAL_Q_FORCE);
}

static void test_no_border_and_not_sliding(void **state)
{
	squeal_params_t p;
	squeal_param_sd_t sd;
	squeal_point_t pt;
	squeal_sigma_result_t out;

	(void)state;
	default_inputs(&p, &sd, &pt);
	pt.v0_mps = 0;
	assert_int_equal(squeal_sigma_eval(&p, &sd, &pt, &out), SQ_OK);
	assert_int_equal(out.state, SQUEAL_STATE_NOT_SLIDING);
	assert_true(out.flags == 0U && out.margin_sigma == SQUEAL_SIGMA_MARGIN_MAX);

	default_inputs(&p, &sd, &pt);
	pt.force_n = 0;
	assert_int_equal(squeal_sigma_eval(&p, &sd, &pt, &out), SQ_OK);
	assert_int_equal(out.state, SQUEAL_STATE_NOT_SLIDING);

	default_inputs(&p, &sd, &pt);
	p.slope_spm = 0;
	sd.slope_spm_sd = 0;
	assert_int_equal(squeal_sigma_eval(&p, &sd, &pt, &out), SQ_OK);
	assert_int_equal(out.state, SQUEAL_STATE_STABLE);
	assert_true(out.flags == 0U && out.margin_sigma == SQUEAL_SIGMA_MARGIN_MAX);

	default_inputs(&p, &sd, &pt);
	p.delta_mu = sq_num_from_double(-0.05, SQUEAL_Q_MU);
	assert_int_equal(squeal_sigma_eval(&p, &sd, &pt, &out), SQ_OK);
	assert_int_equal(out.state, SQUEAL_STATE_STABLE);
	assert_true(out.flags == 0U && out.margin_sigma == SQUEAL_SIGMA_MARGIN_MAX);
}

static void expect_invalid(const squeal_params_t *p, const squeal_param_sd_t *sd,
			   const squeal_point_t *pt)
{
	squeal_sigma_result_t out;

	assert_int_equal(squeal_sigma_eval(p, sd, pt, &out), SQ_EINVAL);
	assert_int_equal(out.state, SQUEAL_STATE_INVALID);
	assert_true(out.flags == 0U && out.sigma_hopf == 0 && out.margin_sigma == 0);
}

static void test_out_of_domain_and_null(void **state)
{
	squeal_params_t p;
	squeal_param_sd_t sd;
	squeal_point_t pt;
	squeal_sigma_result_t out;
	squeal_num_t margin;

	(void)state;
	default_inputs(&p, &sd, &pt);
	sd.damping_sd = sq_num_from_double(-0.001, SQUEAL_Q_DAMPING);
	expect_invalid(&p, &sd, &pt);
	default_inputs(&p, &sd, &pt);
	sd.damping_sd = sq_num_from_double(0.03, SQUEAL_Q_DAMPING); /* > D */
	expect_invalid(&p, &sd, &pt);
	default_inputs(&p, &sd, &pt);
	sd.slope_spm_sd = sq_num_from_double(2.5, SQUEAL_Q_SLOPE); /* > a */
	expect_invalid(&p, &sd, &pt);
	default_inputs(&p, &sd, &pt);
	sd.slope_delta_mu_corr = sq_num_from_double(1.01, SQUEAL_Q_CORR);
	expect_invalid(&p, &sd, &pt);
	default_inputs(&p, &sd, &pt);
	sd.mu_inf_sd = sq_num_from_double(1.6, SQUEAL_Q_MU);
	expect_invalid(&p, &sd, &pt);
	default_inputs(&p, &sd, &pt);
	pt.v0_mps = sq_num_from_double(-1.0, SQUEAL_Q_V0);
	expect_invalid(&p, &sd, &pt);
	default_inputs(&p, &sd, &pt);
	p.damping = 0;
	expect_invalid(&p, &sd, &pt);
#if !defined(SQUEAL_NUMERIC_FIXED)
	default_inputs(&p, &sd, &pt);
	sd.mass_kg_sd = NAN;
	expect_invalid(&p, &sd, &pt);
#endif
	default_inputs(&p, &sd, &pt);
	out.state = SQUEAL_STATE_BISTABLE;
	/* NULL is a programming error: the contract handler, not a result */
	expect_assert_failure(squeal_sigma_eval(NULL, &sd, &pt, &out));
	expect_assert_failure(squeal_sigma_eval(&p, NULL, &pt, &out));
	expect_assert_failure(squeal_sigma_eval(&p, &sd, NULL, &out));
	assert_int_equal(out.state, SQUEAL_STATE_BISTABLE);
	expect_assert_failure(squeal_sigma_eval(&p, &sd, &pt, NULL));
	expect_assert_failure(squeal_sigma_margin(NULL, SQUEAL_STATE_STABLE, &margin));
	expect_assert_failure(squeal_sigma_margin(&out, SQUEAL_STATE_STABLE, NULL));
	expect_assert_failure(squeal_sigma_sd_check(&p, NULL));
	expect_assert_failure(squeal_sigma_sd_zero(NULL));
}

/* Extreme but valid inputs: relative deviations of 1, s = 2000 (a = 20,
 * v0 = 100): no overflow (UBSan), sigma finite and positive. */
static void test_extremes_do_not_overflow(void **state)
{
	squeal_params_t p;
	squeal_param_sd_t sd;
	squeal_point_t pt;
	squeal_sigma_result_t out;

	(void)state;
	squeal_model_default_params(&p);
	p.slope_spm = sq_num_from_double(20.0, SQUEAL_Q_SLOPE);
	sd.mass_kg_sd = p.mass_kg;
	sd.omega0_radps_sd = p.omega0_radps;
	sd.damping_sd = p.damping;
	sd.mu_inf_sd = 0;
	sd.delta_mu_sd = p.delta_mu;
	sd.slope_spm_sd = p.slope_spm;
	sd.slope_delta_mu_corr = sq_num_from_double(-1.0, SQUEAL_Q_CORR);
	pt.v0_mps = sq_num_from_double(100.0, SQUEAL_Q_V0);
	pt.force_n = sq_num_from_double(500000.0, SQUEAL_Q_FORCE);
	assert_int_equal(squeal_sigma_eval(&p, &sd, &pt, &out), SQ_OK);
	/* sigma_H = sqrt(4 + (s-1)^2 + 2 (s-1)) = sqrt(3 + s^2), s = 2000;
	 * beyond the fixed build's range (128): clamped and flagged there */
	if (sq_num_is_fixed()) {
		assert_true((out.flags & SQUEAL_SIGMA_SAT) != 0U);
	} else {
		assert_true(fabs(sigma_of(out.sigma_hopf) / sqrt(3.0 + 2000.0 * 2000.0) - 1.0) < 1e-4);
	}
	assert_true(out.sigma_stable > 0);
	pt.v0_mps = sq_num_from_double(0.001, SQUEAL_Q_V0);
	assert_int_equal(squeal_sigma_eval(&p, &sd, &pt, &out), SQ_OK);
	assert_true(out.sigma_hopf > 0 && out.sigma_stable > 0);
}

int main(int argc, char **argv)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_sigma_agrees_with_monte_carlo),
		cmocka_unit_test(test_sigma_matches_numerical_first_order),
		cmocka_unit_test(test_border_values_class_and_margin),
		cmocka_unit_test(test_zero_sd_is_todays_behaviour),
		cmocka_unit_test(test_no_border_and_not_sliding),
		cmocka_unit_test(test_out_of_domain_and_null),
		cmocka_unit_test(test_extremes_do_not_overflow),
	};

	if (argc > 1) {
		csv_path = argv[1];
	}
	return cmocka_run_group_tests_name(sq_num_is_fixed() ? "sigma (fixed)" : "sigma (float)",
					   tests, setup, NULL);
}
