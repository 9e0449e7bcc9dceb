/* SPDX-License-Identifier: MIT */
/*
 * The option parser's numeric bounds (host-sim/cli_args.c), both numeric
 * builds: a whole-number option in lo..hi takes both ends and refuses one
 * beyond each (--count 1..20: 1 and 20 taken, 0 and 21 refused, exit 2);
 * a real option's ends likewise (--real in [-1, 2.5]).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include <cmocka.h>

#include "cli_args.h"

static uint32_t count;
static double real;
static const cli_opt_t opts[] = {
	CLI_OPT_U32("count", &count, NULL, 1.0, 20.0, "K", "1..20"),
	CLI_OPT_REAL("real", &real, NULL, -1.0, 2.5, 0U, "X", "in [-1, 2.5]"),
};
static const cli_spec_t spec = {
	.cmd = "bounds",
	.synopsis = "squeal-sim bounds [OPTIONS]",
	.description = "Numeric options at their ends.",
	.closing = "Exit status: 0, 2 bad usage.",
	.opts = opts,
	.n_opts = CLI_COUNT(opts),
	.min_pos = 0U,
	.max_pos = 0U,
};

static cli_result_t parse2(const char *opt, const char *value)
{
	char *argv[3] = { (char *)"bounds", (char *)opt, (char *)value };
	const char *pos[1] = { NULL };
	size_t n_pos = 0U;

	count = 0U;
	real = 0.0;
	return cli_parse(&spec, 3, argv, pos, &n_pos);
}

static void test_whole_number_ends(void **state)
{
	(void)state;
	assert_int_equal(parse2("--count", "20"), CLI_OK);
	assert_int_equal(count, 20U);
	assert_int_equal(parse2("--count", "1"), CLI_OK);
	assert_int_equal(count, 1U);
	assert_int_equal(parse2("--count", "21"), CLI_USAGE);
	assert_int_equal(parse2("--count", "0"), CLI_USAGE);
}

static void test_real_ends(void **state)
{
	(void)state;
	assert_int_equal(parse2("--real", "2.5"), CLI_OK);
	assert_true(real == 2.5);
	assert_int_equal(parse2("--real", "-1"), CLI_OK);
	assert_true(real == -1.0);
	assert_int_equal(parse2("--real", "2.5001"), CLI_USAGE);
	assert_int_equal(parse2("--real", "-1.0001"), CLI_USAGE);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_whole_number_ends),
		cmocka_unit_test(test_real_ends),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
