/* SPDX-License-Identifier: MIT */
/*
 * The firmware model's exact criterion must agree with simulation of the
 * oscillator at every point of the (a, v0) plane farther than 1 % in ln Q
 * from a border, for the default brake and each of the paper's variations
 * (a 40 x 40 grid here; `make bench` runs 100 x 100), through the map's
 * sweep and tallies (oscsim_map_run). Built against the float and the fixed
 * model (build/host{,-fixed}/tests/host-sim/oscsim/test_oscsim_map_agreement).
 *
 * The truth is oscsim_truth (backward-time search for the unstable sliding
 * cycle, checked against scipy and docs/model.md in the other tests); nothing
 * here uses the model's own formulas.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "oscsim/oscsim_map.h"
#include "squeal_model.h"

#define GRID 40U

static void run_brake(const char *name, oscsim_map_stats_t *st)
{
	const oscsim_variation_t *v = oscsim_variation_find(name);
	oscsim_map_opts_t o;

	assert_non_null(v);
	oscsim_map_default_opts(&o);
	o.n_a = GRID;
	o.n_v = GRID;
	o.border_margin = 0.01;
	o.basin_every = 8U;
	assert_int_equal(oscsim_map_run(v, &o, NULL, NULL, st), SQ_OK);
	printf("  %-8s exact %.2f %% agree (%u far), cubic %.2f %% (%u far), "
	       "cycle error exact %.3f %% cubic %.1f %% (off Hopf), basin %u/%u "
	       "(cubic 0.8 x captured %u/%u), %.2f s\n",
	       name, 100.0 * st->exact_agree / st->points, st->exact_far_disagree,
	       100.0 * st->cubic_agree / st->points, st->cubic_far_disagree,
	       100.0 * st->exact_amp_err_far, 100.0 * st->cubic_amp_err_far,
	       st->basin_ok, st->basin_tested, st->basin_cubic_captured,
	       st->basin_cubic_tested, st->seconds);
	assert_int_equal(st->points, GRID * GRID);
	/* every class occurs, or the test would prove little */
	assert_true(st->truth_count[OSCSIM_TRUTH_UNSTABLE] > 0U);
	assert_true(st->truth_count[OSCSIM_TRUTH_BISTABLE] > 0U);
	assert_true(st->truth_count[OSCSIM_TRUTH_STABLE] > 0U);
	/* most points are far from a border */
	assert_true(st->far_points > GRID * GRID * 9U / 10U);
	/* the claim */
	assert_int_equal(st->exact_far_disagree, 0);
	/* the simulated linear test agrees with Q <= 1/2 */
	assert_int_equal(st->linear_checked, GRID * GRID);
	assert_int_equal(st->linear_mismatch, 0);
	/* the exact cycle is within 1 % of the simulated one (docs/model.md: 0.05 %
	 * at D = 0.023, 0.7 % at D = 0.1) away from the Hopf point, where the
	 * cycle shrinks to nothing */
	assert_true(st->exact_amp_err_far < 0.01);
	/* and physically: the full oscillator with sticking, started inside
	 * the exact model's cycle (0.8 x), settles; outside (1.2 x) it ends
	 * in stick-slip */
	assert_true(st->basin_tested > 0U);
	assert_int_equal(st->basin_wrong, 0);
	assert_int_equal(st->basin_undecided, 0);
	assert_int_equal(st->basin_ok, st->basin_tested);
}

static void test_default_brake(void **state)
{
	oscsim_map_stats_t st;

	(void)state;
	run_brake("default", &st);
	/* the same check rejects the paper's cubic limit, which under-warns
	 * (docs/model.md section 6: about one point in seven): it can fail */
	assert_true(st.cubic_far_disagree > GRID * GRID / 10U);
	assert_true(st.cubic_under > 0U);
	assert_int_equal(st.cubic_over, 0);
}

#define BRAKE_TEST(fn, nm)                                                  \
	static void fn(void **state)                                        \
	{                                                                   \
		oscsim_map_stats_t st;                                      \
		(void)state;                                                \
		run_brake(nm, &st);                                         \
	}

BRAKE_TEST(test_damping_0_05, "d0.05")
BRAKE_TEST(test_damping_0_1, "d0.1")
BRAKE_TEST(test_stiffness_x2, "k2")
BRAKE_TEST(test_stiffness_x0_5, "k0.5")
BRAKE_TEST(test_force_5000, "n5000")
BRAKE_TEST(test_force_20000, "n20000")

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_default_brake),
		cmocka_unit_test(test_damping_0_05),
		cmocka_unit_test(test_damping_0_1),
		cmocka_unit_test(test_stiffness_x2),
		cmocka_unit_test(test_stiffness_x0_5),
		cmocka_unit_test(test_force_5000),
		cmocka_unit_test(test_force_20000),
	};

	printf("model build: %s, grid %u x %u\n", SQUEAL_NUMERIC_NAME, GRID, GRID);
	return cmocka_run_group_tests(tests, NULL, NULL);
}
