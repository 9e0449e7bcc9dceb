/* SPDX-License-Identifier: MIT */
/*
 * host-sim/cli_args.c on a table of our own: each kind of option, the
 * forms of an option word, the strict numbers and their ranges, the stored
 * unit, positional words, and the one error line of each refusal (stderr
 * captured), all against values and texts written out here by hand.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "cli_args.h"

typedef struct {
	bool flag;
	bool verbose;
	const char *text;
	const char *name;
	double real;
	double open_real;
	bool real_given;
	uint64_t tail_us;
	uint32_t count;
	int choice;
	bool choice_given;
} vals_t;

static vals_t v;
static const char *const choices[] = { "exact", "cubic", NULL };
static const cli_opt_t opts[] = {
	CLI_OPT_FLAG("flag", 0, &v.flag, "a flag"),
	CLI_OPT_FLAG("verbose", 'v', &v.verbose, "more"),
	CLI_OPT_TEXT("text", &v.text, NULL, "T", "any text"),
	CLI_OPT_NAME("name", &v.name, NULL, 4U, "N", "1..4 characters"),
	CLI_OPT_REAL("real", &v.real, &v.real_given, -1.0, 2.5, 0U, "X", "in [-1, 2.5]"),
	CLI_OPT_REAL("open", &v.open_real, NULL, 0.0, 1.0, CLI_LO_OPEN, "X", "in (0, 1]"),
	CLI_OPT_U64("tail-ms", &v.tail_us, NULL, 0.0, 1000.0, 1000U, "MS", "stored in us"),
	CLI_OPT_U32("count", &v.count, NULL, 1.0, 20.0, "K", "1..20"),
	CLI_OPT_CHOICE("criterion", &v.choice, &v.choice_given, choices, "C", "exact or cubic"),
};
static const cli_spec_t spec = {
	.cmd = "demo",
	.synopsis = "squeal-sim demo [OPTIONS] [FILE]",
	.description = "A table of every kind of option.",
	.closing = "Exit status: 0, 2 bad usage.",
	.opts = opts,
	.n_opts = CLI_COUNT(opts),
	.min_pos = 0U,
	.max_pos = 1U,
};

/* stderr of one parse */
static char err_text[512];

static cli_result_t parse(const char *first, ...)
{
	char *argv[16];
	int argc = 0;
	const char *pos[1] = { NULL };
	size_t n_pos = 0U;
	FILE *saved = stderr;
	FILE *mem = fmemopen(err_text, sizeof(err_text) - 1U, "w");
	va_list ap;
	const char *a;
	cli_result_t r;

	memset(err_text, 0, sizeof(err_text));
	memset(&v, 0, sizeof(v));
	argv[argc++] = (char *)"demo";
	va_start(ap, first);
	for (a = first; a != NULL; a = va_arg(ap, const char *)) {
		assert_true(argc < 15);
		argv[argc++] = (char *)a;
	}
	va_end(ap);
	argv[argc] = NULL;
	assert_non_null(mem);
	stderr = mem;
	r = cli_parse(&spec, argc, argv, pos, &n_pos);
	stderr = saved;
	assert_int_equal(fclose(mem), 0);
	v.text = (n_pos == 1U) ? pos[0] : v.text; /* the positional word, for the checks */
	return r;
}

static void test_values_of_each_kind(void **state)
{
	(void)state;
	assert_int_equal(parse("--flag", "-v", "--name", "can0", "--real", "-0.5", "--open", "1",
			       "--tail-ms", "250", "--count", "0x10", "--criterion", "cubic", NULL),
			 CLI_OK);
	assert_true(v.flag);
	assert_true(v.verbose);
	assert_string_equal(v.name, "can0");
	assert_true(v.real == -0.5);
	assert_true(v.real_given);
	assert_true(v.open_real == 1.0);
	assert_int_equal(v.tail_us, 250000U);
	assert_int_equal(v.count, 16U);
	assert_int_equal(v.choice, 1);
	assert_true(v.choice_given);
	assert_string_equal(err_text, "");
}

static void test_forms_of_an_option_word(void **state)
{
	(void)state;
	/* --opt=VALUE, a unique prefix, a value that starts with '-' */
	assert_int_equal(parse("--real=2.5", "--cri", "exact", "--text", "-x", NULL), CLI_OK);
	assert_true(v.real == 2.5);
	assert_int_equal(v.choice, 0);
	/* a positional word anywhere, '-' is one, '--' ends the options */
	assert_int_equal(parse("--flag", "-", NULL), CLI_OK);
	assert_string_equal(v.text, "-");
	assert_int_equal(parse("--", "--flag", NULL), CLI_OK);
	assert_false(v.flag);
	assert_string_equal(v.text, "--flag");
}

static void test_help(void **state)
{
	FILE *saved = stdout;
	char out[4096] = "";
	FILE *mem = fmemopen(out, sizeof(out) - 1U, "w");
	cli_result_t r;

	(void)state;
	assert_non_null(mem);
	stdout = mem;
	r = parse("--real", "1", "-h", "--bogus", NULL);
	stdout = saved;
	assert_int_equal(fclose(mem), 0);
	assert_int_equal(r, CLI_HELP);
	assert_int_equal(cli_exit_status(r), 0);
	assert_string_equal(err_text, "");
	assert_true(strncmp(out, "usage: squeal-sim demo [OPTIONS] [FILE]\n\nA table", 48) == 0);
	assert_non_null(strstr(out, "\n  --real X       in [-1, 2.5]\n"));
	assert_non_null(strstr(out, "\n  -v, --verbose  more\n"));
	assert_non_null(strstr(out, "\n  -h, --help     this text\n"));
	assert_non_null(strstr(out, "\nExit status: 0, 2 bad usage.\n"));
}

/* Each refusal: CLI_USAGE, exit 2, exactly this one line. */
static const struct {
	const char *args[4];
	const char *line;
} refusals[] = {
	{ { "--real", "abc" }, "squeal-sim demo: --real: needs a number, got 'abc'\n" },
	{ { "--real", "1x" }, "squeal-sim demo: --real: needs a number, got '1x'\n" },
	{ { "--real", "" }, "squeal-sim demo: --real: needs a number, got ''\n" },
	{ { "--real", "nan" }, "squeal-sim demo: --real: needs a number, got 'nan'\n" },
	{ { "--real", "inf" }, "squeal-sim demo: --real: needs a number, got 'inf'\n" },
	{ { "--real", "0x1p1" }, "squeal-sim demo: --real: needs a number, got '0x1p1'\n" },
	{ { "--real", "1e999" }, "squeal-sim demo: --real: needs a number, got '1e999'\n" },
	{ { "--real", "2.6" }, "squeal-sim demo: --real: needs a number in [-1, 2.5], got '2.6'\n" },
	{ { "--open", "0" }, "squeal-sim demo: --open: needs a number in (0, 1], got '0'\n" },
	{ { "--count", "0" }, "squeal-sim demo: --count: needs a whole number in 1..20, got '0'\n" },
	{ { "--count", "1.5" }, "squeal-sim demo: --count: needs a whole number in 1..20, got '1.5'\n" },
	{ { "--tail-ms", "-1" }, "squeal-sim demo: --tail-ms: needs a whole number in 0..1000, got '-1'\n" },
	{ { "--name", "vcan01" }, "squeal-sim demo: --name: needs 1..4 characters without blanks, got 'vcan01'\n" },
	{ { "--name", "a b" }, "squeal-sim demo: --name: needs 1..4 characters without blanks, got 'a b'\n" },
	{ { "--criterion", "quartic" }, "squeal-sim demo: --criterion: is exact or cubic, got 'quartic'\n" },
	{ { "--flag=1" }, "squeal-sim demo: --flag: takes no value, got '--flag=1'\n" },
	{ { "--real" }, "squeal-sim demo: --real: needs a value (X)\n" },
	{ { "--bogus" }, "squeal-sim demo: unknown option '--bogus' (see --help)\n" },
	{ { "-x" }, "squeal-sim demo: unknown option '-x' (see --help)\n" },
	{ { "--t", "1" }, "squeal-sim demo: ambiguous option '--t' (see --help)\n" },
	{ { "one", "two" }, "squeal-sim demo: unexpected argument 'two'\n" },
};

static void test_refusals(void **state)
{
	size_t i;

	(void)state;
	for (i = 0U; i < sizeof(refusals) / sizeof(refusals[0]); i++) {
		const cli_result_t r = parse(refusals[i].args[0], refusals[i].args[1],
					     refusals[i].args[2], NULL);

		assert_int_equal(r, CLI_USAGE);
		assert_int_equal(cli_exit_status(r), 2);
		assert_string_equal(err_text, refusals[i].line);
	}
}

static void test_usage_error_line(void **state)
{
	FILE *saved = stderr;
	FILE *mem = fmemopen(err_text, sizeof(err_text) - 1U, "w");

	(void)state;
	memset(err_text, 0, sizeof(err_text));
	assert_non_null(mem);
	stderr = mem;
	assert_int_equal(cli_usage_error(&spec, "--%s needs --%s", "corner", "calib"), CLI_USAGE);
	stderr = saved;
	assert_int_equal(fclose(mem), 0);
	assert_string_equal(err_text, "squeal-sim demo: --corner needs --calib\n");
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_values_of_each_kind),
		cmocka_unit_test(test_forms_of_an_option_word),
		cmocka_unit_test(test_help),
		cmocka_unit_test(test_refusals),
		cmocka_unit_test(test_usage_error_line),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
