/* SPDX-License-Identifier: MIT */
/*
 * host-sim/sim_num.c: double <-> squeal_num_t in both numeric builds, the
 * default brake as decimals, and the parameter/point conversions, against
 * values worked out by hand here:
 *   fixed: value * 2^q rounded to nearest (ties to even, the default
 *          rounding mode), saturated to int32 with -1, NaN -> INT32_MIN;
 *   float: (float)value, -1 only when a finite double overflows the float.
 * The default brake is docs/model.md's: m 1 kg, w0 5000 rad/s, D 0.023,
 * mu_inf 0.25, delta_mu 0.15, slope 2 s/m, each as the decimal written.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "sim_num.h"
#include "sq_cmocka.h"

static void test_from_double_exact_and_rounded(void **state)
{
	squeal_num_t n;

	(void)state;
	assert_int_equal(sim_num_from_double(1.5, 16, &n), 0);
#if defined(SQUEAL_NUMERIC_FIXED)
	assert_int_equal(n, 98304);                 /* 1.5 * 65536 */
	assert_int_equal(sim_num_from_double(-2.25, 4, &n), 0);
	assert_int_equal(n, -36);                   /* -2.25 * 16 */
	/* 2.5 and 3.5 units at q 0: ties go to the even neighbour */
	assert_int_equal(sim_num_from_double(2.5, 0, &n), 0);
	assert_int_equal(n, 2);
	assert_int_equal(sim_num_from_double(3.5, 0, &n), 0);
	assert_int_equal(n, 4);
	/* 0.1 at q 20: 104857.6 -> 104858 */
	assert_int_equal(sim_num_from_double(0.1, 20, &n), 0);
	assert_int_equal(n, 104858);
#else
	assert_true(n == 1.5f);
	assert_int_equal(sim_num_from_double(0.1, 20, &n), 0);
	assert_true(n == 0.1f);                     /* nearest float, q ignored */
#endif
}

static void test_from_double_out_of_range(void **state)
{
	squeal_num_t n;

	(void)state;
#if defined(SQUEAL_NUMERIC_FIXED)
	/* 2^31 at q 0 is one past INT32_MAX; -2^31 - 1 one below INT32_MIN */
	assert_int_equal(sim_num_from_double(2147483648.0, 0, &n), -1);
	assert_int_equal(n, INT32_MAX);
	assert_int_equal(sim_num_from_double(2147483647.0, 0, &n), 0);
	assert_int_equal(n, INT32_MAX);
	assert_int_equal(sim_num_from_double(-2147483649.0, 0, &n), -1);
	assert_int_equal(n, INT32_MIN);
	/* 40000 N at q 12 is 1.6e8 counts: fits; 600000 N (2.46e9) does not */
	assert_int_equal(sim_num_from_double(40000.0, SQUEAL_Q_FORCE, &n), 0);
	assert_int_equal(n, 163840000);
	assert_int_equal(sim_num_from_double(600000.0, SQUEAL_Q_FORCE, &n), -1);
	assert_int_equal(n, INT32_MAX);
	assert_int_equal(sim_num_from_double(NAN, 12, &n), -1);
	assert_int_equal(n, INT32_MIN);
#else
	/* FLT_MAX is about 3.4e38: 1e39 overflows, infinity was given as such */
	assert_int_equal(sim_num_from_double(1e39, 0, &n), -1);
	assert_true(isinf(n));
	assert_int_equal(sim_num_from_double(INFINITY, 0, &n), 0);
	assert_true(isinf(n));
	assert_int_equal(sim_num_from_double(NAN, 0, &n), 0);
	assert_true(isnan(n));
#endif
}

static void test_to_double(void **state)
{
	(void)state;
#if defined(SQUEAL_NUMERIC_FIXED)
	assert_true(sim_num_to_double(98304, 16) == 1.5);
	assert_true(sim_num_to_double(-36, 4) == -2.25);
	assert_true(sim_num_to_double(INT32_MIN, 30) == -2.0);
#else
	assert_true(sim_num_to_double(1.5f, 16) == 1.5);
	assert_true(sim_num_to_double(0.1f, 0) == (double)0.1f);
#endif
}

static void test_default_brake_as_decimals(void **state)
{
	sim_params_d_t p;

	(void)state;
	sim_params_default(&p);
	/* exactly the doubles nearest to the written decimals */
	assert_true(p.mass_kg == 1.0);
	assert_true(p.omega0_radps == 5000.0);
	assert_true(p.damping == 0.023);
	assert_true(p.mu_inf == 0.25);
	assert_true(p.delta_mu == 0.15);
	assert_true(p.slope_spm == 2.0);
}

static void test_params_and_point_to_model(void **state)
{
	const sim_params_d_t d = { 2.0, 4096.0, 0.5, 0.25, -0.125, 3.0 };
	sim_params_d_t bad = d;
	squeal_params_t p;
	squeal_point_t pt;

	(void)state;
	assert_int_equal(sim_params_to_model(&d, &p), 0);
	assert_int_equal(sim_point_to_model(0.75, 1000.0, &pt), 0);
#if defined(SQUEAL_NUMERIC_FIXED)
	assert_int_equal(p.mass_kg, 2 << 16);
	assert_int_equal(p.omega0_radps, 4096 << 12);
	assert_int_equal(p.damping, 1 << 29);       /* 0.5 at q 30 */
	assert_int_equal(p.mu_inf, 1 << 28);        /* 0.25 at q 30 */
	assert_int_equal(p.delta_mu, -(1 << 27));   /* -0.125 at q 30 */
	assert_int_equal(p.slope_spm, 3 << 24);
	assert_int_equal(pt.v0_mps, 3 << 18);       /* 0.75 * 2^20 */
	assert_int_equal(pt.force_n, 1000 << 12);
	/* one parameter out of its Q range (mu 2.0 at q 30 = 2^31) makes it -1 */
	bad.mu_inf = 2.0;
	assert_int_equal(sim_params_to_model(&bad, &p), -1);
	assert_int_equal(p.mu_inf, INT32_MAX);
	assert_int_equal(p.mass_kg, 2 << 16);       /* the others still set */
	assert_int_equal(sim_point_to_model(0.5, 1e6, &pt), -1);
	assert_int_equal(pt.v0_mps, 1 << 19);
#else
	assert_true(p.mass_kg == 2.0f && p.omega0_radps == 4096.0f && p.damping == 0.5f);
	assert_true(p.mu_inf == 0.25f && p.delta_mu == -0.125f && p.slope_spm == 3.0f);
	assert_true(pt.v0_mps == 0.75f && pt.force_n == 1000.0f);
	bad.slope_spm = 1e40;
	assert_int_equal(sim_params_to_model(&bad, &p), -1);
	assert_true(p.mass_kg == 2.0f);
#endif
}

SQ_CMOCKA_MAIN(
	cmocka_unit_test(test_from_double_exact_and_rounded),
	cmocka_unit_test(test_from_double_out_of_range),
	cmocka_unit_test(test_to_double),
	cmocka_unit_test(test_default_brake_as_decimals),
	cmocka_unit_test(test_params_and_point_to_model))
