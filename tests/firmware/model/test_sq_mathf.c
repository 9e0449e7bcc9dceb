/* SPDX-License-Identifier: MIT */
/*
 * The float build's elementary functions (firmware/model/sq_mathf.c)
 * against the host's double-precision libm as the independent reference,
 * in units in the last place of the float result, over each documented
 * argument range (logarithmic and linear sweeps, subnormals included);
 * the documented answers outside the ranges; the extended-range numbers
 * m * 2^e against exact powers of two and ldexp. sq_mathf.h promises "a
 * few ulp"; the bounds held here: 4 ulp (ln, log1p, expm1), 2 ulp (exp),
 * 1 ulp (sqrt). The fixed build has no such functions (sq_mathf.c is empty
 * there), so this program is built for the float build only.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>
#include <float.h>
#include <math.h>

#include "sq_mathf.h"

/* |got - ref| in ulp of ref rounded to float (the smallest subnormal at 0) */
static double ulp_error(float got, double ref)
{
	const float rf = fabsf((float)ref);
	const double ulp = (rf == 0.0f) ? (double)nextafterf(0.0f, 1.0f) :
		(double)nextafterf(rf, INFINITY) - (double)rf;

	return fabs((double)got - ref) / ulp;
}

typedef float (*f_fn)(float);
typedef double (*d_fn)(double);

/* n + 1 points from lo to hi, spaced evenly in log(x) when log_spaced */
static double max_ulp(f_fn f, d_fn ref, double lo, double hi, int n, int log_spaced, double sign)
{
	double worst = 0.0;

	for (int i = 0; i <= n; i++) {
		const double t = (double)i / (double)n;
		const double xd = log_spaced ? exp(log(lo) + t * (log(hi) - log(lo))) : lo + t * (hi - lo);
		const float x = (float)(sign * xd);
		const double e = ulp_error(f(x), ref((double)x));

		worst = (e > worst) ? e : worst;
	}
	return worst;
}

#define SWEEP_POINTS 100000

static void test_lnf_within_4_ulp(void **state)
{
	(void)state;
	assert_true(max_ulp(sq_lnf, log, 1.2e-38, 3.4e38, SWEEP_POINTS, 1, 1.0) <= 4.0);
	assert_true(max_ulp(sq_lnf, log, 1.5e-45, 1.1e-38, SWEEP_POINTS / 10, 1, 1.0) <= 4.0);
	assert_true(max_ulp(sq_lnf, log, 0.5, 2.0, SWEEP_POINTS, 0, 1.0) <= 4.0);
	assert_true(sq_lnf(1.0f) == 0.0f);
	/* outside: x <= 0, infinite, NaN */
	assert_true(sq_lnf(0.0f) == -FLT_MAX);
	assert_true(sq_lnf(-1.0f) == -FLT_MAX);
	assert_true(sq_lnf(INFINITY) == -FLT_MAX);
	assert_true(sq_lnf(NAN) == -FLT_MAX);
}

static void test_log1pf_within_4_ulp(void **state)
{
	(void)state;
	assert_true(max_ulp(sq_log1pf, log1p, -0.999, 10.0, SWEEP_POINTS, 0, 1.0) <= 4.0);
	assert_true(max_ulp(sq_log1pf, log1p, 1e-30, 0.5, SWEEP_POINTS, 1, 1.0) <= 4.0);
	assert_true(max_ulp(sq_log1pf, log1p, 1e-30, 0.5, SWEEP_POINTS, 1, -1.0) <= 4.0);
	assert_true(max_ulp(sq_log1pf, log1p, 10.0, 3e38, SWEEP_POINTS / 10, 1, 1.0) <= 4.0);
	assert_true(sq_log1pf(-1.0f) == -FLT_MAX);
	assert_true(sq_log1pf(-2.0f) == -FLT_MAX);
	assert_true(sq_log1pf(INFINITY) == -FLT_MAX);
}

static void test_expf_within_2_ulp_and_clamps(void **state)
{
	(void)state;
	assert_true(max_ulp(sq_expf, exp, -86.9, 88.0, SWEEP_POINTS, 0, 1.0) <= 2.0);
	assert_true(max_ulp(sq_expf, exp, 1e-30, 1.0, SWEEP_POINTS, 1, -1.0) <= 2.0);
	assert_true(sq_expf(0.0f) == 1.0f);
	assert_true(sq_expf(-87.0f) == 0.0f);
	assert_true(sq_expf(-1000.0f) == 0.0f);
	assert_true(sq_expf(100.0f) == sq_expf(88.0f)); /* clamped at 88 */
	assert_true(ulp_error(sq_expf(88.0f), exp(88.0)) <= 2.0);
}

static void test_expm1f_within_4_ulp(void **state)
{
	(void)state;
	assert_true(max_ulp(sq_expm1f, expm1, -20.0, 88.0, SWEEP_POINTS, 0, 1.0) <= 4.0);
	assert_true(max_ulp(sq_expm1f, expm1, 1e-30, 0.34, SWEEP_POINTS, 1, 1.0) <= 4.0);
	assert_true(max_ulp(sq_expm1f, expm1, 1e-30, 0.34, SWEEP_POINTS, 1, -1.0) <= 4.0);
	assert_true(sq_expm1f(0.0f) == 0.0f);
}

static void test_sqrtf_within_1_ulp(void **state)
{
	(void)state;
	assert_true(max_ulp(sq_sqrtf, sqrt, 1.4e-45, 3.4e38, SWEEP_POINTS, 1, 1.0) <= 1.0);
	assert_true(max_ulp(sq_sqrtf, sqrt, 1.0, 4.0, SWEEP_POINTS, 0, 1.0) <= 1.0);
	assert_true(sq_sqrtf(0.0f) == 0.0f);
	assert_true(sq_sqrtf(-4.0f) == 0.0f);
	assert_true(sq_sqrtf(INFINITY) == 0.0f);
	assert_true(sq_sqrtf(NAN) == 0.0f);
}

static void test_isfinitef(void **state)
{
	(void)state;
	assert_true(sq_isfinitef(0.0f));
	assert_true(sq_isfinitef(FLT_MAX));
	assert_true(sq_isfinitef(-FLT_MAX));
	assert_true(sq_isfinitef(1.4e-45f));
	assert_false(sq_isfinitef(INFINITY));
	assert_false(sq_isfinitef(-INFINITY));
	assert_false(sq_isfinitef(NAN));
}

static void test_extended_range_numbers(void **state)
{
	sq_xf_t a;
	sq_xf_t b;
	bool sat = true;

	(void)state;
	a = sq_xf_from(3.0f); /* 1.5 * 2^1 */
	assert_true(a.m == 1.5f);
	assert_int_equal(a.e, 1);
	a = sq_xf_from(1.4e-45f); /* the smallest subnormal, 2^-149 */
	assert_true(a.m == 1.0f);
	assert_int_equal(a.e, -149);
	a = sq_xf_from(0.0f);
	assert_true(a.m == 0.0f);
	a = sq_xf_from(-2.0f);
	assert_true(a.m == 0.0f);
	assert_true(sq_xf_to_float(a, &sat) == 0.0f);
	assert_false(sat);

	/* e^100 = 2^144.27: beyond float, kept as m * 2^e */
	a = sq_xf_exp(100.0f);
	assert_int_equal(a.e, 144);
	assert_true(a.m >= 1.0f && a.m < 2.0f);
	assert_true(fabs(ldexp((double)a.m, a.e) / exp(100.0) - 1.0) < 4.0 * (double)FLT_EPSILON);
	(void)sq_xf_to_float(a, &sat);
	assert_true(sat);
	assert_true(sq_xf_to_float(a, &sat) == FLT_MAX);
	/* e^100 / e^90 = e^10, back in range */
	b = sq_xf_div(a, sq_xf_exp(90.0f));
	assert_true(ulp_error(sq_xf_to_float(b, &sat), exp(10.0)) <= 8.0);
	assert_false(sat);
	/* 1.5 * 2^-100 / 2^50 = 0.75 * 2^-149: rounds once to 2^-149 */
	b = sq_xf_div(sq_xf_mul(sq_xf_from(1.5f), (sq_xf_t){ 1.0f, -100 }), (sq_xf_t){ 1.0f, 50 });
	assert_true(sq_xf_to_float(b, &sat) == 1.4e-45f);
	/* 2^100 * 2^100 = 2^200 saturates; 2^-200 is 0 */
	b = sq_xf_mul((sq_xf_t){ 1.0f, 100 }, (sq_xf_t){ 1.0f, 100 });
	assert_int_equal(b.e, 200);
	assert_true(sq_xf_to_float(b, &sat) == FLT_MAX);
	assert_true(sat);
	assert_true(sq_xf_to_float((sq_xf_t){ 1.0f, -200 }, &sat) == 0.0f);
	assert_false(sat);
	/* 1.5 * 1.5 = 2.25 = 1.125 * 2^1: renormalized */
	b = sq_xf_mul(sq_xf_from(1.5f), sq_xf_from(1.5f));
	assert_true(b.m == 1.125f);
	assert_int_equal(b.e, 1);
	/* a division by zero is the largest number, never a NaN */
	b = sq_xf_div(sq_xf_from(1.0f), sq_xf_from(0.0f));
	assert_true(sq_xf_to_float(b, &sat) == FLT_MAX);
	assert_true(sat);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_lnf_within_4_ulp),
		cmocka_unit_test(test_log1pf_within_4_ulp),
		cmocka_unit_test(test_expf_within_2_ulp_and_clamps),
		cmocka_unit_test(test_expm1f_within_4_ulp),
		cmocka_unit_test(test_sqrtf_within_1_ulp),
		cmocka_unit_test(test_isfinitef),
		cmocka_unit_test(test_extended_range_numbers),
	};

	return cmocka_run_group_tests_name("sq_mathf", tests, NULL, NULL);
}
