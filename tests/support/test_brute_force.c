/* SPDX-License-Identifier: MIT */
/*
 * The brute-force reference of the benchmark (brute_force.c) against the
 * simulated cycle maxima of docs/model.md section 6 (an independent
 * simulation) and against the classification rule of section 4, so that
 * the bench compares the model with a simulation that is itself right.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "brute_force.h"

/* The brief's bound; the measured errors are below 0.01 %. */
#define TABLE_REL_TOL 0.002

static void check_cycle(double damping, double q, double expected)
{
	bf_result_t r;

	assert_int_equal(bf_decide(damping, q, HUGE_VAL, &r), 0);
	assert_int_equal(r.decision, BF_BISTABLE);
	assert_true(fabs(r.cycle_max_du / expected - 1.0) <= TABLE_REL_TOL);
}

static void test_cycle_d0023_q1_matches_model_md(void **state)
{
	(void)state;
	check_cycle(0.023, 1.0, 2.4874);
}

static void test_cycle_d01_q3_matches_model_md(void **state)
{
	(void)state;
	check_cycle(0.1, 3.0, 4.3368);
}

static void test_cycle_other_rows_match_model_md(void **state)
{
	(void)state;
	check_cycle(0.023, 0.6, 1.2260);
	check_cycle(0.023, 2.0, 3.6936);
	check_cycle(0.023, 3.0, 4.3102);
	check_cycle(0.1, 1.0, 2.4982);
}

/* A stick line just above the cycle (max u' 2.4874 at D = 0.023, Q = 1)
 * leaves it intact: bistable; just below it: the run reaches the stick
 * line first: stable. */
static void test_decision_follows_stick_line(void **state)
{
	bf_result_t r;

	(void)state;
	assert_int_equal(bf_decide(0.023, 1.0, 2.55, &r), 0);
	assert_int_equal(r.decision, BF_BISTABLE);
	assert_true(fabs(r.cycle_max_du - 2.4874) < 0.005);
	assert_int_equal(bf_decide(0.023, 1.0, 2.43, &r), 0);
	assert_int_equal(r.decision, BF_STABLE);
}

/* Deliberately wrong expectation must fail the tolerance: the check has
 * teeth (cubic x3 = 2.8284 instead of the simulated 2.4874). */
static void test_tolerance_rejects_cubic_value(void **state)
{
	bf_result_t r;

	(void)state;
	assert_int_equal(bf_decide(0.023, 1.0, HUGE_VAL, &r), 0);
	assert_false(fabs(r.cycle_max_du / 2.8284 - 1.0) <= TABLE_REL_TOL);
}

static void test_rejects_outside_domain(void **state)
{
	bf_result_t r;

	(void)state;
	assert_int_equal(bf_decide(0.023, 0.5, 1.0, &r), -1); /* unstable: linear test */
	assert_int_equal(bf_decide(0.023, nan(""), 1.0, &r), -1);
	assert_int_equal(bf_decide(0.0, 1.0, 1.0, &r), -1);
	assert_int_equal(bf_decide(0.023, 1.0, 0.0, &r), -1);
	assert_int_equal(bf_decide(0.023, 1.0, 1.0, NULL), -1);
}

SQ_CMOCKA_MAIN(
	cmocka_unit_test(test_cycle_d0023_q1_matches_model_md),
	cmocka_unit_test(test_cycle_d01_q3_matches_model_md),
	cmocka_unit_test(test_cycle_other_rows_match_model_md),
	cmocka_unit_test(test_decision_follows_stick_line),
	cmocka_unit_test(test_tolerance_rejects_cubic_value),
	cmocka_unit_test(test_rejects_outside_domain))
