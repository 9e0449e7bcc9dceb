/* SPDX-License-Identifier: MIT */
/*
 * A scenario file's rows (host-sim/plant_scenario.c): a negative force is
 * refused with NAME:LINE however small (-0.5 N), 0 N is taken; at a row's
 * own time the values are that row's, exactly (force 0.1 N after 3000 N:
 * interpolating from the row before would give 3000 + (0.1 - 3000) =
 * 0.09999999999990905 in doubles).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "plant_scenario.h"

static int parse(const char *text, plant_scenario_t *sc, char *err, size_t errlen)
{
	FILE *f = fmemopen((void *)(uintptr_t)text, strlen(text), "r");
	int rc;

	assert_non_null(f);
	rc = plant_scenario_parse(f, "s.txt", sc, err, errlen);
	fclose(f);
	return rc;
}

static void test_negative_force_refused(void **state)
{
	static plant_scenario_t sc;
	char err[200] = "";

	(void)state;
	assert_int_equal(parse("0 1.0 0\n1 1.0 100\n", &sc, err, sizeof(err)), 0);
	assert_int_equal(parse("0 1.0 100\n1 1.0 -0.5\n", &sc, err, sizeof(err)), -1);
	assert_string_equal(err, "s.txt:2: force_n must be >= 0");
}

static void test_a_rows_time_gives_its_values(void **state)
{
	static plant_scenario_t sc;
	char err[200] = "";
	double v;
	double n;

	(void)state;
	assert_int_equal(parse("0 1.0 3000\n1 2.0 0.1\n2 3.0 5\n", &sc, err, sizeof(err)), 0);
	plant_scenario_eval(&sc, 1.0, &v, &n);
	assert_true(v == 2.0);
	assert_true(n == 0.1);
	plant_scenario_eval(&sc, 0.0, &v, &n);
	assert_true((v == 1.0) && (n == 3000.0));
	plant_scenario_eval(&sc, 2.0, &v, &n);
	assert_true((v == 3.0) && (n == 5.0));
	plant_scenario_eval(&sc, 0.5, &v, &n); /* halfway: (3000 + 0.1) / 2 */
	assert_true((v == 1.5) && (n > 1500.0499) && (n < 1500.0501));
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_negative_force_refused),
		cmocka_unit_test(test_a_rows_time_gives_its_values),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
