/* SPDX-License-Identifier: MIT */
/*
 * host-sim/plant_scenario.c: the built-in scenarios as plant_scenario.h
 * describes them, a scenario file's rows, its interpolation, and the one
 * FILE:LINE error of every refusal, against values worked out by hand.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "plant_scenario.h"
#include "sq_cmocka.h"

static plant_scenario_t sc; /* 100 kB: not on the stack */

static int parse_text(const char *text, char *err, size_t errlen)
{
	FILE *f = fmemopen((void *)(uintptr_t)text, strlen(text), "r");
	int rc;

	assert_non_null(f);
	rc = plant_scenario_parse(f, "s.txt", &sc, err, errlen);
	assert_int_equal(fclose(f), 0);
	return rc;
}

static void at(double t_s, double want_speed_mps, double want_force_n)
{
	double v = -1.0;
	double n = -1.0;

	plant_scenario_eval(&sc, t_s, &v, &n);
	assert_true(fabs(v - want_speed_mps) <= 1e-12);
	assert_true(fabs(n - want_force_n) <= 1e-9);
}

/* Each built-in scenario as plant_scenario.h describes it: its end and its
 * values at a few times (worked out from the description). */
static void test_builtins(void **state)
{
	static const struct {
		const char *name;
		double point_speed_mps, point_force_n, end_s;
		unsigned int n;
		plant_row_t at[6]; /* time, vehicle speed, force */
	} cases[] = {
		/* 30 m/s held 0.5 s, -6 m/s^2 for 5 s, held 0.5 s; 9 kN */
		{ "stop", 0.0, 0.0, 6.0, 4U,
		  { { 0.25, 30.0, 9000.0 }, { 2.5, 30.0 - 6.0 * 2.0, 9000.0 },
		    { 5.5, 0.0, 9000.0 }, { 100.0, 0.0, 9000.0 } } },
		/* 1.0 -> 0.4 -> 1.0 m/s in 6 s each at 1500 N */
		{ "creep", 0.0, 0.0, 12.0, 3U,
		  { { 3.0, 0.7, 1500.0 }, { 6.0, 0.4, 1500.0 }, { 9.0, 0.7, 1500.0 } } },
		/* 8 s per force (3, 6, 9, 12 kN): 10 -> 0.5 m/s in 4 s, back */
		{ "sweep", 0.0, 0.0, 32.0, 6U,
		  { { 0.0, 10.0, 3000.0 }, { 4.0, 0.5, 3000.0 }, { 6.0, 5.25, 3000.0 },
		    { 12.0, 0.5, 6000.0 }, { 28.0, 0.5, 12000.0 }, { 32.0, 10.0, 12000.0 } } },
		/* the point given, for 10 s */
		{ "point", 1.25, 4000.0, 10.0, 2U,
		  { { 0.0, 1.25, 4000.0 }, { 7.5, 1.25, 4000.0 } } },
	};
	size_t i;
	unsigned int k;

	(void)state;
	for (i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
		assert_int_equal(plant_scenario_builtin(cases[i].name, cases[i].point_speed_mps,
							cases[i].point_force_n, &sc), 0);
		assert_string_equal(sc.name, cases[i].name);
		assert_true(plant_scenario_end_s(&sc) == cases[i].end_s);
		for (k = 0; k < cases[i].n; k++) {
			at(cases[i].at[k].time_s, cases[i].at[k].speed_mps, cases[i].at[k].force_n);
		}
	}
	assert_int_equal(plant_scenario_builtin("point", -1.0, 4000.0, &sc), -1);
	assert_int_equal(plant_scenario_builtin("point", 1.0, NAN, &sc), -1);
	assert_int_equal(plant_scenario_builtin("brake", 1.0, 1.0, &sc), -1);
	assert_int_equal(plant_scenario_builtin(NULL, 1.0, 1.0, &sc), -1);
}

static void test_names(void **state)
{
	static const char *const want[] = { "stop", "creep", "sweep", "point" };
	size_t i;

	(void)state;
	for (i = 0; i < 4U; i++) {
		assert_non_null(plant_scenario_names[i]);
		assert_string_equal(plant_scenario_names[i], want[i]);
	}
	assert_null(plant_scenario_names[4]);
}

static void test_file_rows(void **state)
{
	char err[200] = "";

	(void)state;
	assert_int_equal(parse_text("# a ramp\n"
				    "\n"
				    "  1.0  20  1000   # from 1 s\n"
				    "3\t10\t3000\r\n"
				    "4e0 10 3000\n", err, sizeof(err)), 0);
	assert_string_equal(sc.name, "s.txt");
	assert_int_equal(sc.count, 3);
	at(0.0, 20.0, 1000.0);     /* before the first row: its values */
	at(2.5, 12.5, 2500.0);     /* 3/4 of the way from row 1 to row 2 */
	at(3.5, 10.0, 3000.0);
	at(9.0, 10.0, 3000.0);     /* after the last row: its values */
	assert_true(plant_scenario_end_s(&sc) == 4.0);
}

static void test_file_refusals(void **state)
{
	static const struct {
		const char *text;
		const char *err;
	} cases[] = {
		{ "", "s.txt: no rows (expected lines 'time_s speed_mps force_n')" },
		{ "# only a comment\n", "s.txt: no rows (expected lines 'time_s speed_mps force_n')" },
		{ "0 1\n", "s.txt:1: expected 3 columns (time_s speed_mps force_n), missing force_n" },
		{ "0 1 x\n", "s.txt:1: force_n is not a number: 'x'" },
		{ "0 0x10 1\n", "s.txt:1: speed_mps is not a number: '0x10'" },
		{ "0 inf 1\n", "s.txt:1: speed_mps is not a number: 'inf'" },
		{ "0 1 2 3\n", "s.txt:1: more than 3 columns (time_s speed_mps force_n)" },
		{ "-1 1 2\n", "s.txt:1: time_s must be >= 0" },
		{ "0 1 2\n\n2 1 2\n2 1 2\n", "s.txt:4: time_s 2 is not after the previous row's 2" },
		{ "0 -0.5 2\n", "s.txt:1: speed_mps must be >= 0" },
		{ "0 1 -2\n", "s.txt:1: force_n must be >= 0" },
	};
	char err[200];
	size_t i;

	(void)state;
	for (i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
		memset(err, 0, sizeof(err));
		assert_int_equal(parse_text(cases[i].text, err, sizeof(err)), -1);
		assert_string_equal(err, cases[i].err);
	}
}

static void test_file_limits(void **state)
{
	static char text[PLANT_SCENARIO_MAX_ROWS * 16U + 1024U];
	char long_line[600];
	char err[200] = "";
	size_t len = 0;
	unsigned int i;

	(void)state;
	/* 4096 rows fit, the 4097th is refused on its own line */
	for (i = 0; i <= PLANT_SCENARIO_MAX_ROWS; i++) {
		len += (size_t)snprintf(text + len, sizeof(text) - len, "%u 1 1\n", i);
	}
	assert_int_equal(parse_text(text, err, sizeof(err)), -1);
	assert_string_equal(err, "s.txt:4097: more than 4096 rows");
	text[len - strlen("4096 1 1\n")] = '\0';
	assert_int_equal(parse_text(text, err, sizeof(err)), 0);
	assert_int_equal(sc.count, PLANT_SCENARIO_MAX_ROWS);
	at(4095.0, 1.0, 1.0);

	/* a line longer than the reader's 511 characters */
	memset(long_line, ' ', sizeof(long_line));
	memcpy(long_line, "0 1 1", 5);
	long_line[sizeof(long_line) - 2U] = '\n';
	long_line[sizeof(long_line) - 1U] = '\0';
	assert_int_equal(parse_text(long_line, err, sizeof(err)), -1);
	assert_string_equal(err, "s.txt:1: line too long");

	assert_int_equal(plant_scenario_load("/nonexistent/s.txt", &sc, err, sizeof(err)), -1);
	assert_string_equal(err, "/nonexistent/s.txt: cannot open: No such file or directory");
}

SQ_CMOCKA_MAIN(
	cmocka_unit_test(test_builtins),
	cmocka_unit_test(test_names),
	cmocka_unit_test(test_file_rows),
	cmocka_unit_test(test_file_refusals),
	cmocka_unit_test(test_file_limits))
