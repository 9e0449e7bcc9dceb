/* SPDX-License-Identifier: MIT */
/*
 * calib_text: the calibration text format. Expected stored values are
 * derived by hand from the units (e.g. 0.12 m = 120000 um, 1.5 kg in Q16 =
 * 98304), never from the parser's own output.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "calib.h"
#include "calib_text.h"
#include "sq_status.h"

static int parse_text(const char *text, calib_t *out, char *err, size_t errlen)
{
	FILE *f = fmemopen((void *)(uintptr_t)text, strlen(text), "r");
	int rc;

	assert_non_null(f);
	rc = calib_text_parse(f, "t.cal", out, err, errlen);
	fclose(f);
	return rc;
}

static void expect_error(const char *text, const char *want)
{
	calib_t cal;
	calib_t before;
	char err[256] = "";

	memset(&cal, 0xA5, sizeof(cal));
	before = cal;
	assert_int_equal(parse_text(text, &cal, err, sizeof(err)), SQ_EBADMSG);
	if (strstr(err, want) == NULL) {
		fail_msg("error '%s' does not contain '%s'", err, want);
	}
	/* never half-applied */
	assert_memory_equal(&cal, &before, sizeof(cal));
}

static void test_empty_file_gives_defaults(void **state)
{
	calib_t cal;
	calib_t def;
	char err[128];
	uint8_t a[CALIB_BLOCK_LEN];
	uint8_t b[CALIB_BLOCK_LEN];

	(void)state;
	calib_default(&def);
	assert_int_equal(parse_text("# nothing\n\n   \n", &cal, err, sizeof(err)), SQ_OK);
	assert_int_equal(calib_encode(&cal, a, sizeof(a)), SQ_OK);
	assert_int_equal(calib_encode(&def, b, sizeof(b)), SQ_OK);
	assert_memory_equal(a, b, sizeof(a));
}

static void test_values_in_physical_units(void **state)
{
	calib_t cal;
	char err[128] = "";

	(void)state;
	assert_int_equal(parse_text(
		"mass_kg = 1.5          # kg\n"
		"omega0_radps=2500\n"
		"  damping = 0.05\n"
		"slope_spm = 4\n"
		"mu_inf = 0.3\n"
		"delta_mu = -0.125\n"
		"criterion = cubic\n"
		"pad_radius_m = 0.125\n"
		"wheel_radius_m = 0.31\n"
		"disc_speed_id = 0x120\n"
		"pad_force_id = 291\n"
		"e2e_check_inputs = no\n"
		"speed_max_radps = 300.5\n"
		"force_max_n = 20000.5\n"
		"lowpass_alpha = 0.5\n"
		"v0_min_mps = 0.02\n"
		"force_min_n = 50.5\n"
		"hyst_lnq = 0.03\n"
		"rho_warn = 0.4\n"
		"debounce_count = 5\n"
		"watchdog_ms = 250\n", &cal, err, sizeof(err)), SQ_OK);
	assert_int_equal(cal.mass_q16, 98304);          /* 1.5 * 65536 */
	assert_int_equal(cal.omega0_q12, 2500 * 4096);
	assert_int_equal(cal.damping_q30, 53687091);    /* round(0.05 * 2^30) */
	assert_int_equal(cal.slope_q24, 4 << 24);
	assert_int_equal(cal.mu_inf_q30, 322122547);    /* round(0.3 * 2^30) */
	assert_int_equal(cal.delta_mu_q30, -(1 << 27)); /* -0.125 exactly */
	assert_int_equal(cal.criterion, SQUEAL_CRITERION_CUBIC);
	assert_int_equal(cal.pad_radius_um, 125000);
	assert_int_equal(cal.wheel_radius_um, 310000);
	assert_int_equal(cal.disc_speed_id, 0x120);
	assert_int_equal(cal.pad_force_id, 0x123);
	assert_int_equal(cal.e2e_check_inputs, 0);
	assert_int_equal(cal.speed_max_raw, 30050);     /* 0.01 rad/s steps */
	assert_int_equal(cal.force_max_raw, 40001);     /* 0.5 N steps */
	assert_int_equal(cal.lowpass_alpha_q15, 16384);
	assert_int_equal(cal.v0_min_umps, 20000);
	assert_int_equal(cal.force_min_mn, 50500);
	assert_int_equal(cal.hyst_lnq_micro, 30000);
	assert_int_equal(cal.rho_warn_ppm, 400000);
	assert_int_equal(cal.debounce_count, 5);
	assert_int_equal(cal.watchdog_ms, 250);
	/* untouched keys keep the defaults */
	assert_int_equal(cal.status_id, 0x300);
	assert_int_equal(cal.diag_period_ms, 1000);
}

static void test_rejects_with_line_numbers(void **state)
{
	(void)state;
	expect_error("mass_kg = 1\n\nfoo = 3\n", "t.cal:3: unknown key 'foo'");
	expect_error("# c\nmass_kg = 1\nmass_kg = 2\n",
		     "t.cal:3: duplicate key 'mass_kg' (first set on line 2)");
	expect_error("mass_kg = 1\nmass_kg = 2\n",
		     "t.cal:2: duplicate key 'mass_kg' (first set on line 1)");
	expect_error("damping = 0.0x\n", "t.cal:1: damping needs a number");
	expect_error("damping = nan\n", "t.cal:1: damping needs a number");
	expect_error("damping = inf\n", "t.cal:1: damping needs a number");
	expect_error("damping = \n", "t.cal:1: damping has no value");
	expect_error("damping 0.1\n", "t.cal:1: expected 'key = value'");
	expect_error("= 0.1\n", "t.cal:1: missing key");
	expect_error("damping = 0.1 0.2\n", "t.cal:1: damping: one value expected");
	expect_error("damping = 1.5\n", "t.cal:1: damping = 1.5 is out of range");
	expect_error("\n\nomega0_radps = -1\n", "t.cal:3: omega0_radps = -1 is out of range");
	expect_error("disc_speed_id = 0x800\n", "t.cal:1: disc_speed_id = 0x800 is out of range");
	expect_error("disc_speed_id = 0x\n", "t.cal:1: disc_speed_id needs an integer");
	expect_error("debounce_count = 2.5\n", "t.cal:1: debounce_count needs an integer");
	expect_error("debounce_count = 0\n", "t.cal:1: debounce_count = 0 is out of range");
	expect_error("criterion = quartic\n", "t.cal:1: criterion must be 'exact' or 'cubic'");
	expect_error("e2e_check_inputs = maybe\n", "t.cal:1: e2e_check_inputs must be yes/no");
	expect_error("pad_radius_m = 0.1234567\n",
		     "t.cal:1: pad_radius_m = 0.1234567 is not a whole multiple of its resolution 0.000001 m");
	expect_error("force_max_n = 100.25\n", "resolution 0.5 N");
	expect_error("speed_max_radps = 655.35\n", "t.cal:1: speed_max_radps = 655.35 is out of range");
	/* whole-file checks */
	expect_error("status_id = 0x110\n", "t.cal: the six CAN identifiers");
	expect_error("mu_inf = 0.1\ndelta_mu = -0.2\n", "t.cal:2: mu_inf + delta_mu");
}

static void test_long_line_rejected(void **state)
{
	char text[700];

	(void)state;
	memset(text, ' ', sizeof(text));
	memcpy(text, "# ", 2);
	text[sizeof(text) - 2] = '\n';
	text[sizeof(text) - 1] = '\0';
	expect_error(text, "t.cal:1: line longer than");
}

static void test_last_line_without_newline(void **state)
{
	calib_t cal;
	char err[128];

	(void)state;
	assert_int_equal(parse_text("watchdog_ms = 300", &cal, err, sizeof(err)), SQ_OK);
	assert_int_equal(cal.watchdog_ms, 300);
}

/* A standard deviation's maximum is its parameter's: the line that sets the
 * parameter there (NULL: not a deviation bounded by its parameter). */
static const char *sd_param_max(const char *key)
{
	static const char *const rows[][2] = {
		{ "mass_kg_sd", "mass_kg = 10000" },
		{ "omega0_radps_sd", "omega0_radps = 500000" },
		{ "damping_sd", "damping = 1" },
		{ "delta_mu_sd", "delta_mu = 1.5" },
		{ "slope_spm_sd", "slope_spm = 20" },
	};
	size_t i;

	for (i = 0; i < sizeof(rows) / sizeof(rows[0]); i++) {
		if (strcmp(rows[i][0], key) == 0) {
			return rows[i][1];
		}
	}
	return NULL;
}

/* Every key's range ends (as calib_text's table has them) are accepted by
 * the firmware's own calib_validate, and one step beyond is refused by the
 * parser: the two tables agree. */
static void test_range_ends_agree_with_calib_validate(void **state)
{
	size_t i;

	(void)state;
	for (i = 0; i < calib_text_key_count(); i++) {
		const char *key = calib_text_key_name(i);
		calib_t cal;
		char in[512];
		char err[256];
		char *text = NULL;
		size_t len = 0;
		FILE *out;
		char *p;
		char minv[64];
		char maxv[64];

		/* the writer prints "range MIN .. MAX" for each key */
		calib_default(&cal);
		out = open_memstream(&text, &len);
		assert_non_null(out);
		assert_int_equal(calib_text_write(out, &cal), SQ_OK);
		fclose(out);
		snprintf(in, sizeof(in), "\n%s = ", key);
		p = strstr(text, in);
		assert_non_null(p);
		p = strstr(p, "range ");
		assert_non_null(p);
		assert_int_equal(sscanf(p, "range %63s .. %63s", minv, maxv), 2);
		free(text);
		if ((strcmp(minv, "exact") == 0) || (strcmp(minv, "no") == 0)) {
			continue; /* enumerations: covered elsewhere */
		}
		if (strstr(key, "_id") != NULL) {
			continue; /* identifiers: checked together with the others */
		}
		if (strcmp(key, "delta_mu") == 0) {
			/* needs mu_inf >= -delta_mu to validate */
			snprintf(in, sizeof(in), "mu_inf = 1.5\n%s = %s\n", key, minv);
		} else {
			snprintf(in, sizeof(in), "%s = %s\n", key, minv);
		}
		if (parse_text(in, &cal, err, sizeof(err)) != SQ_OK) {
			fail_msg("%s: %s", in, err);
		}
		assert_int_equal(calib_validate(&cal), SQ_OK);
		if (sd_param_max(key) != NULL) {
			/* sd <= |param|: the parameter at its own maximum */
			snprintf(in, sizeof(in), "%s\n%s = %s\n", sd_param_max(key), key, maxv);
		} else {
			snprintf(in, sizeof(in), "%s = %s\n", key, maxv);
		}
		if (parse_text(in, &cal, err, sizeof(err)) != SQ_OK) {
			fail_msg("%s: %s", in, err);
		}
		assert_int_equal(calib_validate(&cal), SQ_OK);
	}
}

/* Beyond the ends: the firmware refuses the raw value the parser would have
 * stored, and the parser refuses the text (hand-picked per key family). */
static void test_one_step_beyond_rejected(void **state)
{
	(void)state;
	expect_error("mass_kg = 10000.0001\n", "out of range");
	expect_error("mass_kg = 0\n", "out of range");
	expect_error("omega0_radps = 500000.001\n", "out of range");
	expect_error("mu_inf = 1.5000001\n", "out of range");
	expect_error("slope_spm = 20.0000001\n", "out of range");
	expect_error("pad_radius_m = 0.009999\n", "out of range");
	expect_error("wheel_radius_m = 2.000001\n", "out of range");
	expect_error("diag_period_ms = 99\n", "out of range");
	expect_error("e2e_max_delta_counter = 15\n", "out of range");
	expect_error("lowpass_alpha = 1.0001\n", "out of range");
	expect_error("v0_min_mps = 10.000001\n", "out of range");
	expect_error("hyst_lnq = 5.000001\n", "out of range");
	expect_error("rho_warn = 1.000001\n", "out of range");
	expect_error("watchdog_ms = 9\n", "out of range");
	/* 0.7 of a resolution step beyond the end (raw 65534.7): out of
	 * range, not "not a whole multiple" of the nearest step beyond */
	expect_error("speed_max_radps = 655.347\n", "speed_max_radps = 655.347 is out of range");
}

static void roundtrip(const calib_t *cal)
{
	char *text = NULL;
	size_t len = 0;
	FILE *out = open_memstream(&text, &len);
	calib_t back;
	char err[256] = "";
	uint8_t a[CALIB_BLOCK_LEN];
	uint8_t b[CALIB_BLOCK_LEN];

	assert_non_null(out);
	assert_int_equal(calib_text_write(out, cal), SQ_OK);
	fclose(out);
	memset(&back, 0, sizeof(back));
	if (parse_text(text, &back, err, sizeof(err)) != SQ_OK) {
		fail_msg("round trip parse failed: %s\n%s", err, text);
	}
	/* compare the stored blocks (no padding bytes involved) */
	assert_int_equal(calib_encode(cal, a, sizeof(a)), SQ_OK);
	assert_int_equal(calib_encode(&back, b, sizeof(b)), SQ_OK);
	assert_memory_equal(a, b, sizeof(a));
	free(text);
}

static void test_write_parse_round_trip(void **state)
{
	calib_t cal;
	uint32_t seed = 12345U;
	int n;

	(void)state;
	calib_default(&cal);
	roundtrip(&cal);
	/* awkward Q values: odd raw numbers use all the bits */
	cal.mass_q16 = 65537;
	cal.omega0_q12 = 123456789;
	cal.damping_q30 = 1;
	cal.mu_inf_q30 = (3 << 29);
	cal.delta_mu_q30 = -(3 << 29);
	cal.slope_q24 = 20 << 24;
	cal.criterion = SQUEAL_CRITERION_CUBIC;
	cal.pad_radius_um = 123457U;
	cal.speed_max_raw = 65534U;
	cal.force_step_max_raw = 65535U;
	cal.lowpass_alpha_q15 = 1U;
	cal.v0_min_umps = 0U;
	cal.force_min_mn = 99999999U;
	cal.e2e_check_inputs = 0U;
	cal.detail2_id = 0x7FFU;
	roundtrip(&cal);
	/* random Q values in range */
	for (n = 0; n < 200; n++) {
		calib_default(&cal);
		seed = seed * 1103515245U + 12345U;
		cal.damping_q30 = (int32_t)(1U + (seed >> 2) % (1U << 30));
		seed = seed * 1103515245U + 12345U;
		cal.mass_q16 = (int32_t)(1U + seed % (10000U << 16));
		seed = seed * 1103515245U + 12345U;
		cal.slope_q24 = (int32_t)(seed % (20U << 24));
		seed = seed * 1103515245U + 12345U;
		cal.hyst_rho_ppm = seed % 1000001U;
		roundtrip(&cal);
	}
}

static void test_write_defaults_is_readable(void **state)
{
	calib_t cal;
	char *text = NULL;
	size_t len = 0;
	FILE *out;

	(void)state;
	calib_default(&cal);
	out = open_memstream(&text, &len);
	assert_non_null(out);
	assert_int_equal(calib_text_write(out, &cal), SQ_OK);
	fclose(out);
	/* the natural short forms, not 0.0229999...*/
	assert_non_null(strstr(text, "\ndamping = 0.023 "));
	assert_non_null(strstr(text, "\nmass_kg = 1 "));
	assert_non_null(strstr(text, "\ndelta_mu = 0.15 "));
	assert_non_null(strstr(text, "\npad_radius_m = 0.12 "));
	assert_non_null(strstr(text, "\ndisc_speed_id = 0x110 "));
	assert_non_null(strstr(text, "\ncriterion = exact "));
	free(text);
	/* an invalid calibration is not written */
	cal.disc_speed_id = cal.status_id;
	out = open_memstream(&text, &len);
	assert_int_equal(calib_text_write(out, &cal), SQ_EINVAL);
	fclose(out);
	free(text);
}

static void test_load_missing_file(void **state)
{
	calib_t cal;
	char err[256] = "";

	(void)state;
	assert_int_equal(calib_text_load("/nonexistent/x.cal", &cal, err, sizeof(err)),
			 SQ_ENOENT);
	assert_non_null(strstr(err, "/nonexistent/x.cal: cannot open"));
}

static void test_example_file_parses_to_defaults(void **state)
{
	calib_t cal;
	calib_t def;
	char err[256] = "";
	uint8_t a[CALIB_BLOCK_LEN];
	uint8_t b[CALIB_BLOCK_LEN];
	size_t i;
	FILE *f;
	char *text;
	long n;

	(void)state;
	assert_int_equal(calib_text_load("docs/calib-example.txt", &cal, err, sizeof(err)),
			 SQ_OK);
	calib_default(&def);
	assert_int_equal(calib_encode(&cal, a, sizeof(a)), SQ_OK);
	assert_int_equal(calib_encode(&def, b, sizeof(b)), SQ_OK);
	assert_memory_equal(a, b, sizeof(a));
	/* and it documents every key */
	f = fopen("docs/calib-example.txt", "r");
	assert_non_null(f);
	assert_int_equal(fseek(f, 0, SEEK_END), 0);
	n = ftell(f);
	assert_true(n > 0);
	rewind(f);
	text = calloc(1, (size_t)n + 2U);
	assert_non_null(text);
	text[0] = '\n';
	assert_int_equal(fread(text + 1, 1, (size_t)n, f), (size_t)n);
	fclose(f);
	for (i = 0; i < calib_text_key_count(); i++) {
		char want[64];

		snprintf(want, sizeof(want), "\n%s = ", calib_text_key_name(i));
		if (strstr(text, want) == NULL) {
			fail_msg("docs/calib-example.txt lacks key %s", calib_text_key_name(i));
		}
	}
	free(text);
}

/* The deviations (docs/uncertainty.md): stored in their parameters' Q formats
 * (hand-derived raw values), bounded by their parameters. */
static void test_deviations(void **state)
{
	calib_t cal;
	char err[256] = "";

	(void)state;
	assert_int_equal(parse_text("delta_mu_sd = 0.03\nslope_spm_sd = 0.2\n"
				    "slope_delta_mu_corr = -0.5\nuncertain_k_sigma = 3\n"
				    "mass_kg_sd = 0.01\nomega0_radps_sd = 25\ndamping_sd = 0.002\n"
				    "mu_inf_sd = 0.01\n", &cal, err, sizeof(err)), SQ_OK);
	assert_int_equal(cal.sd.delta_mu_sd_q30, 32212255);   /* 0.03 * 2^30 = 32212254.72 */
	assert_int_equal(cal.sd.slope_sd_q24, 3355443);       /* 0.2 * 2^24 = 3355443.2 */
	assert_int_equal(cal.sd.slope_delta_mu_corr_q30, -536870912);
	assert_int_equal(cal.uncertain_k_q16, 196608);
	assert_int_equal(cal.sd.mass_sd_q16, 655);            /* 655.36 */
	assert_int_equal(cal.sd.omega0_sd_q12, 102400);
	assert_int_equal(cal.sd.damping_sd_q30, 2147484);     /* 2147483.648 */
	assert_int_equal(cal.sd.mu_inf_sd_q30, 10737418);     /* 10737418.24 */
	/* defaults: all 0, k = 2 */
	assert_int_equal(parse_text("", &cal, err, sizeof(err)), SQ_OK);
	assert_int_equal(cal.sd.delta_mu_sd_q30, 0);
	assert_int_equal(cal.uncertain_k_q16, 2 << 16);
	expect_error("slope_delta_mu_corr = 1.01\n", "out of range");
	expect_error("mass_kg_sd = -0.1\n", "out of range");
	expect_error("mass_kg = 1\nmass_kg_sd = 1.5\n", "standard deviation");
	expect_error("delta_mu = 0.1\ndelta_mu_sd = 0.11\n", "standard deviation");
	expect_error("slope_spm = 2\nslope_spm_sd = 2.01\n", "standard deviation");
	expect_error("uncertain_k_sigma = 100.01\n", "out of range");
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_empty_file_gives_defaults),
		cmocka_unit_test(test_deviations),
		cmocka_unit_test(test_values_in_physical_units),
		cmocka_unit_test(test_rejects_with_line_numbers),
		cmocka_unit_test(test_long_line_rejected),
		cmocka_unit_test(test_last_line_without_newline),
		cmocka_unit_test(test_range_ends_agree_with_calib_validate),
		cmocka_unit_test(test_one_step_beyond_rejected),
		cmocka_unit_test(test_write_parse_round_trip),
		cmocka_unit_test(test_write_defaults_is_readable),
		cmocka_unit_test(test_load_missing_file),
		cmocka_unit_test(test_example_file_parses_to_defaults),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
