/* SPDX-License-Identifier: MIT */
/*
 * sq_expf clamps its argument to [-87, 88] (sq_mathf.h): above 88 it is
 * e^88 (1.6516363e38 by the host's double libm, to 2e-7 relative), below
 * -87 it is 0. The float build only (the fixed build has no float math).
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "sq_mathf.h"

static void near_e88(float got)
{
	const double want = exp(88.0);

	if (!(fabs((double)got - want) <= 2e-7 * want)) {
		fail_msg("%.9g is not e^88 = %.9g", (double)got, want);
	}
}

static void test_exp_clamps_above_88(void **state)
{
	(void)state;
	near_e88(sq_expf(88.0f));
	near_e88(sq_expf(88.5f));
	near_e88(sq_expf(88.99f));
	near_e88(sq_expf(1000.0f));
}

static void test_exp_is_0_below_minus_87(void **state)
{
	(void)state;
	assert_true(sq_expf(-87.5f) == 0.0f);
	assert_true(sq_expf(-1000.0f) == 0.0f);
	assert_true(sq_expf(-86.0f) > 0.0f);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_exp_clamps_above_88),
		cmocka_unit_test(test_exp_is_0_below_minus_87),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
