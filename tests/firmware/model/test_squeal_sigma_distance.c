/* SPDX-License-Identifier: MIT */
/*
 * squeal_sigma_distance (firmware/model/squeal_sigma_{float,fixed}.c): a
 * border's distance |g| / sigma in standard deviations, capped at 1000,
 * both numeric builds. Values exact in both (sigma 1/128 = 2^-7; g a
 * multiple of 1/128), so the expected margins are exact by hand:
 *   g  5.46875 (700/128)  -> 700     g -5.46875 -> 700
 *   g  7.8046875 (999/128) -> 999    g  7.8125 (1000/128) -> 1000 (the cap)
 *   g  50                -> 1000 (capped)
 *   sigma 0 (no uncertainty) -> 1000
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "sq_num.h"
#include "squeal_sigma.h"
#include "squeal_sigma_internal.h"

static double distance(double g, double sigma)
{
	return sq_num_to_double(squeal_sigma_distance(sq_num_from_double(g, SQUEAL_Q_LNQ),
						      sq_num_from_double(sigma, SQUEAL_Q_SIGMA)),
				SQUEAL_Q_MARGIN);
}

static void test_distance_in_sigmas(void **state)
{
	const double sigma = 1.0 / 128.0;

	(void)state;
	assert_true(distance(700.0 / 128.0, sigma) == 700.0);
	assert_true(distance(-700.0 / 128.0, sigma) == 700.0);
	assert_true(distance(1.0 / 128.0, sigma) == 1.0);
	assert_true(distance(999.0 / 128.0, sigma) == 999.0);
}

static void test_distance_capped_at_1000(void **state)
{
	const double sigma = 1.0 / 128.0;

	(void)state;
	assert_true(distance(1000.0 / 128.0, sigma) == 1000.0);
	assert_true(distance(50.0, sigma) == 1000.0);
	assert_true(distance(-50.0, sigma) == 1000.0);
	assert_true(distance(1.0, 0.0) == 1000.0);
	assert_true(sq_num_to_double(SQUEAL_SIGMA_MARGIN_MAX, SQUEAL_Q_MARGIN) == 1000.0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_distance_in_sigmas),
		cmocka_unit_test(test_distance_capped_at_1000),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
