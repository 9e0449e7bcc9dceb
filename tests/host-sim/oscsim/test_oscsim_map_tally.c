/* SPDX-License-Identifier: MIT */
/*
 * The map's tallies (host-sim/oscsim/oscsim_map.c): the statistics that
 * oscsim_map_run sums over the (a, v0) plane, recomputed here from every
 * point it reports (its callback) by the definitions of oscsim_map.h:
 *   points, truth_count[] per class, amp_points (truth-bistable points with
 *   a simulated cycle), and per criterion the worst relative amplitude
 *   error |x_model - x_sim| / x_sim over them, with the ln Q where it is,
 *   and the worst only counting points off the Hopf border (|ln Q - ln 1/2|
 *   > border_margin).
 * A 12 x 12 grid of the default brake, no basin tests (the float model).
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "oscsim/oscsim_map.h"
#include "squeal_model.h"

#define GRID 12U

typedef struct {
	double border_margin;
	uint32_t points;
	uint32_t truth_count[4];
	uint32_t amp_points;
	double err[2];
	double err_at_q[2];
	double err_far[2];
} expect_t;

static void amp(double x_model, const oscsim_map_point_t *pt, double margin, double *err, double *at_q,
		double *far)
{
	double e;

	if (!isfinite(x_model)) {
		return;
	}
	e = fabs(x_model - pt->sim_x) / pt->sim_x;
	if (e > *err) {
		*err = e;
		*at_q = pt->ln_q;
	}
	if (fabs(pt->ln_q - log(0.5)) > margin) {
		*far = fmax(*far, e);
	}
}

static void collect(void *ctx, const oscsim_variation_t *var, const oscsim_map_point_t *pt)
{
	expect_t *x = ctx;

	(void)var;
	x->points++;
	if ((unsigned int)pt->truth < 4U) {
		x->truth_count[pt->truth]++;
	}
	if ((pt->truth == OSCSIM_TRUTH_BISTABLE) && isfinite(pt->sim_x)) {
		x->amp_points++;
		amp(pt->exact_x, pt, x->border_margin, &x->err[0], &x->err_at_q[0], &x->err_far[0]);
		amp(pt->cubic_x, pt, x->border_margin, &x->err[1], &x->err_at_q[1], &x->err_far[1]);
	}
}

static void test_tallies_are_the_points_sums(void **state)
{
	const oscsim_variation_t *v = oscsim_variation_find("default");
	oscsim_map_opts_t o;
	oscsim_map_stats_t st;
	expect_t x;

	(void)state;
	assert_non_null(v);
	oscsim_map_default_opts(&o);
	o.n_a = GRID;
	o.n_v = GRID;
	o.border_margin = 0.01;
	o.basin_every = 0U;
	memset(&x, 0, sizeof(x));
	x.border_margin = o.border_margin;
	assert_int_equal(oscsim_map_run(v, &o, collect, &x, &st), SQ_OK);
	assert_int_equal(st.points, x.points);
	assert_true(x.points > 0U);
	for (unsigned int k = 0U; k < 4U; k++) {
		assert_int_equal(st.truth_count[k], x.truth_count[k]);
	}
	assert_int_equal(st.amp_points, x.amp_points);
	/* the grid has bistable points with a cycle, and the models err */
	assert_true(x.amp_points >= 3U);
	assert_true(x.err[0] > 0.0);
	assert_true(x.err[1] > 0.0);
	assert_true(st.exact_amp_err == x.err[0]);
	assert_true(st.exact_amp_err_at_q == x.err_at_q[0]);
	assert_true(st.exact_amp_err_far == x.err_far[0]);
	assert_true(st.cubic_amp_err == x.err[1]);
	assert_true(st.cubic_amp_err_at_q == x.err_at_q[1]);
	assert_true(st.cubic_amp_err_far == x.err_far[1]);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_tallies_are_the_points_sums),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
