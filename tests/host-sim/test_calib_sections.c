/* SPDX-License-Identifier: MIT */
/*
 * The key table and the section rules of the calibration text
 * (host-sim/calib_sections.c), both numeric builds, at their bounds: each
 * value at its end is taken, one step beyond is refused with FILE:LINE and
 * "out of range" (the ends are the calibration block's documented ranges,
 * docs/calibration.md, written here by hand):
 *
 *   e2e_max_delta_counter  1..14 (KIND_INT: 14 taken, 15 refused)
 *   diag_period_ms         100..  (KIND_INT: 100 taken, 99 refused)
 *   speed_max_radps        raw 1..65534 at 0.01 rad/s: 655.34 taken; 655.347
 *                          (raw 65534.7, 0.7 of a step beyond) is out of
 *                          range, never "not a whole multiple"
 *   an input's length      1..32 bits: 32 taken, 33 refused
 *   data_id_list           16 bytes 0..255: 0xFF taken, 0x100 refused
 *   a decimal (factor)     17 significant digits taken, 18 refused
 *   an input's id          extended: 0x1FFFFFFF taken, 0x20000000 refused
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
	rc = calib_text_parse(f, "b.cal", out, err, errlen);
	fclose(f);
	return rc;
}

static void expect_ok(const char *text)
{
	calib_t cal;
	char err[256] = "";

	if (parse_text(text, &cal, err, sizeof(err)) != SQ_OK) {
		fail_msg("'%s' refused: %s", text, err);
	}
}

static void expect_error(const char *text, const char *want)
{
	calib_t cal;
	char err[256] = "";

	assert_int_equal(parse_text(text, &cal, err, sizeof(err)), SQ_EBADMSG);
	if (strstr(err, want) == NULL) {
		fail_msg("error '%s' does not contain '%s'", err, want);
	}
}

static void test_flat_integer_bounds(void **state)
{
	(void)state;
	expect_ok("e2e_max_delta_counter = 14\n");
	expect_error("e2e_max_delta_counter = 15\n", "b.cal:1: e2e_max_delta_counter = 15 is out of range");
	expect_ok("diag_period_ms = 100\n");
	expect_error("\ndiag_period_ms = 99\n", "b.cal:2: diag_period_ms = 99 is out of range");
}

static void test_flat_scaled_bounds(void **state)
{
	(void)state;
	expect_ok("speed_max_radps = 655.34\n");
	expect_error("speed_max_radps = 655.35\n", "b.cal:1: speed_max_radps = 655.35 is out of range");
	expect_error("speed_max_radps = 655.347\n", "b.cal:1: speed_max_radps = 655.347 is out of range");
	expect_error("speed_max_radps = 655.355\n", "b.cal:1: speed_max_radps = 655.355 is out of range");
}

/* A two-input map: a wheel speed of LENGTH bits with FACTOR on the
 * identifier WS_ID (line 3: "id = ...", with "extended = yes" where it
 * needs one), a P02 pressure with the data ID list's first byte FIRST_ID
 * (the other 15 are 0x22..0xFF). */
static void map_text_of(char *buf, size_t len, unsigned length, const char *first_id,
			const char *factor, const char *ws_id)
{
	snprintf(buf, len,
		 "mass_kg = 1.0\n"                 /* 1 */
		 "[input WS]\n"                    /* 2 */
		 "%s\n"                            /* 3 */
		 "start_bit = 0\n"                 /* 4 */
		 "length = %u\n"                   /* 5 */
		 "byte_order = intel\n"            /* 6 */
		 "factor = %s\n"                   /* 7 */
		 "unit = km/h\n"                   /* 8 */
		 "period_ms = 10\n"                /* 9 */
		 "max = 300\n"                     /* 10 */
		 "step_max = 20\n"                 /* 11 */
		 "[input PR]\n"                    /* 12 */
		 "id = 0x1B0\n"                    /* 13 */
		 "min_dlc = 8\n"                   /* 14 */
		 "start_bit = 16\n"                /* 15 */
		 "length = 12\n"                   /* 16 */
		 "byte_order = intel\n"            /* 17 */
		 "factor = 0.1\n"                  /* 18 */
		 "unit = bar\n"                    /* 19 */
		 "protection = p02\n"              /* 20 */
		 "data_id_list = %s 0x22 0x33 0x44 0x55 0x66 0x77 0x88 0x99 0xAA 0xBB 0xCC 0xDD 0xEE 0xF0 0xFF\n" /* 21 */
		 "period_ms = 20\n"                /* 22 */
		 "max = 250\n"                     /* 23 */
		 "step_max = 100\n"                /* 24 */
		 "[corner FL]\n"                   /* 25 */
		 "speed = WS\n"
		 "force = PR\n"
		 "piston_area_mm2 = 2290\n",
		 ws_id, length, factor, first_id);
}

static void map_text(char *buf, size_t len, unsigned length, const char *first_id)
{
	map_text_of(buf, len, length, first_id, "0.01", "id = 0x1A0");
}

static void test_signal_length_bounds(void **state)
{
	char text[2048];

	(void)state;
	map_text(text, sizeof(text), 32U, "0x11");
	expect_ok(text);
	map_text(text, sizeof(text), 33U, "0x11");
	expect_error(text, "b.cal:5: [input WS] length = 33: zero length or over 32 bits");
	map_text(text, sizeof(text), 0U, "0x11");
	expect_error(text, "b.cal:5: [input WS] length = 0: zero length or over 32 bits");
}

static void test_data_id_list_bounds(void **state)
{
	char text[2048];
	calib_t cal;
	char err[256] = "";

	(void)state;
	map_text(text, sizeof(text), 15U, "0xFF");
	assert_int_equal(parse_text(text, &cal, err, sizeof(err)), SQ_OK);
	assert_int_equal(cal.inputs[1].data_id_list[0], 0xFFU);
	assert_int_equal(cal.inputs[1].data_id_list[15], 0xFFU);
	map_text(text, sizeof(text), 15U, "0x100");
	expect_error(text, "b.cal:21: [input PR] data_id_list: 16 byte values 0..255");
	map_text(text, sizeof(text), 15U, "256");
	expect_error(text, "b.cal:21: [input PR] data_id_list: 16 byte values 0..255");
}

static void test_decimal_digits_and_id_bounds(void **state)
{
	char text[2048];

	(void)state;
	map_text_of(text, sizeof(text), 15U, "0x11", "0.12345678901234567", "id = 0x1A0");
	expect_ok(text);
	map_text_of(text, sizeof(text), 15U, "0x11", "0.123456789012345678", "id = 0x1A0");
	expect_error(text, "b.cal:7: [input WS] factor needs a decimal number (at most 17 significant digits");
	map_text_of(text, sizeof(text), 15U, "0x11", "0.01", "id = 0x1FFFFFFF\nextended = yes");
	expect_ok(text);
	map_text_of(text, sizeof(text), 15U, "0x11", "0.01", "id = 0x20000000\nextended = yes");
	expect_error(text, "b.cal:3: [input WS] id");
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_flat_integer_bounds),
		cmocka_unit_test(test_flat_scaled_bounds),
		cmocka_unit_test(test_signal_length_bounds),
		cmocka_unit_test(test_data_id_list_bounds),
		cmocka_unit_test(test_decimal_digits_and_id_bounds),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
