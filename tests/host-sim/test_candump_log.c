/* SPDX-License-Identifier: MIT */
/*
 * Unit tests of host-sim/candump_log: every form of the candump log format
 * (can-utils' candump -L, as docs/commands.md uses it; expected values
 * written by hand from the grammar),
 * many malformed lines (each with its reason), bytes that are not text at
 * all, and the writer (exact strings; parse(format(f)) == f for random
 * frames). Runs under ASan+UBSan: a read outside the given length fails.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "candump_log.h"

/* Parse a copy of s that has no terminating NUL in its heap block, so ASan
 * catches any read past len. */
static candump_line_t parse_n(const char *s, size_t len, candump_frame_t *f,
			      candump_err_t *err)
{
	char *copy = malloc(len > 0U ? len : 1U);
	candump_line_t k;

	assert_non_null(copy);
	memcpy(copy, s, len);
	k = candump_parse_line(copy, len, f, err, NULL);
	free(copy);
	return k;
}

static candump_line_t parse(const char *s, candump_frame_t *f, candump_err_t *err)
{
	return parse_n(s, strlen(s), f, err);
}

static void expect_frame(const char *s, candump_frame_t *f)
{
	candump_err_t err = CANDUMP_ERR_COUNT;

	if (parse(s, f, &err) != CANDUMP_LINE_FRAME) {
		fail_msg("'%s' not a frame: %s", s, candump_strerror(err));
	}
	assert_int_equal(err, CANDUMP_OK);
}

static void expect_error(const char *s, candump_err_t want)
{
	candump_frame_t f;
	candump_err_t err = CANDUMP_OK;

	if (parse(s, &f, &err) != CANDUMP_LINE_MALFORMED) {
		fail_msg("'%s' accepted", s);
	}
	if (err != want) {
		fail_msg("'%s': got '%s', want '%s'", s, candump_strerror(err),
			 candump_strerror(want));
	}
}

/* ---- valid forms ------------------------------------------------------------ */

static void test_classic_standard_frame(void **state)
{
	candump_frame_t f;
	const uint8_t d[4] = { 0x5A, 0x03, 0xE8, 0x03 };

	(void)state;
	expect_frame("(1700000000.123456) can0 110#5A03E803", &f);
	assert_true(f.t_ns == 1700000000123456000ULL);
	assert_string_equal(f.iface, "can0");
	assert_int_equal(f.kind, CANDUMP_KIND_CLASSIC);
	assert_int_equal(f.id, 0x110);
	assert_false(f.ext);
	assert_int_equal(f.len, 4);
	assert_memory_equal(f.data, d, 4);
	assert_int_equal(f.len8_dlc, 0);
	assert_int_equal(f.dir, 0);
}

static void test_empty_frame_and_max_standard_id(void **state)
{
	candump_frame_t f;

	(void)state;
	expect_frame("(0000000000.000000) vcan0 7FF#", &f);
	assert_int_equal(f.id, 0x7FF);
	assert_int_equal(f.len, 0);
	assert_true(f.t_ns == 0U);
	expect_frame("(0.000001) x 000#", &f); /* any seconds width */
	assert_true(f.t_ns == 1000U);
}

static void test_extended_id_is_marked_by_eight_digits(void **state)
{
	candump_frame_t f;

	(void)state;
	expect_frame("(1.000000) can0 00000123#11", &f);
	assert_true(f.ext);
	assert_int_equal(f.id, 0x123);
	assert_int_equal(f.kind, CANDUMP_KIND_CLASSIC);
	expect_frame("(1.000000) can0 1FFFFFFF#", &f);
	assert_true(f.ext);
	assert_int_equal(f.id, 0x1FFFFFFF);
}

static void test_nanosecond_timestamp(void **state)
{
	candump_frame_t f;

	(void)state;
	expect_frame("(1700000000.123456789) can0 123#00", &f);
	assert_true(f.t_ns == 1700000000123456789ULL);
	/* largest representable: 18446744073.709551615 s */
	expect_frame("(18446744073.709551615) can0 123#", &f);
	assert_true(f.t_ns == UINT64_MAX);
}

static void test_lowercase_and_dot_separators(void **state)
{
	candump_frame_t f;
	const uint8_t d[8] = { 0xAB, 0xCD, 0xEF, 0x01, 0x23, 0x45, 0x67, 0x89 };

	(void)state;
	expect_frame("(1.000000) can0 1ab#ab.cd.ef.01.23.45.67.89", &f);
	assert_int_equal(f.id, 0x1AB);
	assert_int_equal(f.len, 8);
	assert_memory_equal(f.data, d, 8);
	expect_frame("(1.000000) can0 1AB#.AbCd.", &f); /* can-utils: a dot before any byte */
	assert_int_equal(f.len, 2);
	assert_int_equal(f.data[0], 0xAB);
	assert_int_equal(f.data[1], 0xCD);
}

static void test_len8_dlc_codes(void **state)
{
	candump_frame_t f;
	char line[64];
	int x;

	(void)state;
	for (x = 9; x <= 15; x++) {
		(void)snprintf(line, sizeof(line), "(1.000000) can0 123#0102030405060708_%X", x);
		expect_frame(line, &f);
		assert_int_equal(f.len, 8);
		assert_int_equal(f.len8_dlc, x);
	}
	expect_frame("(1.000000) can0 123#0102030405060708_c", &f);
	assert_int_equal(f.len8_dlc, 12);
}

static void test_remote_frames(void **state)
{
	candump_frame_t f;

	(void)state;
	expect_frame("(1.000000) can0 123#R", &f);
	assert_int_equal(f.kind, CANDUMP_KIND_RTR);
	assert_int_equal(f.len, 0);
	expect_frame("(1.000000) can0 123#R5", &f);
	assert_int_equal(f.kind, CANDUMP_KIND_RTR);
	assert_int_equal(f.len, 5);
	expect_frame("(1.000000) can0 00000123#R8_F", &f);
	assert_int_equal(f.kind, CANDUMP_KIND_RTR);
	assert_true(f.ext);
	assert_int_equal(f.len, 8);
	assert_int_equal(f.len8_dlc, 15);
	expect_frame("(1.000000) can0 123#r0", &f);
	assert_int_equal(f.kind, CANDUMP_KIND_RTR);
}

static void test_fd_frames_every_flags_nibble(void **state)
{
	candump_frame_t f;
	char line[256];
	int fl;
	size_t i;

	(void)state;
	for (fl = 0; fl <= 15; fl++) {
		(void)snprintf(line, sizeof(line), "(1.000000) can0 123##%X112233", fl);
		expect_frame(line, &f);
		assert_int_equal(f.kind, CANDUMP_KIND_FD);
		assert_int_equal(f.fd_flags, fl);
		assert_int_equal(f.len, 3);
		assert_int_equal(f.data[2], 0x33);
	}
	/* 64 bytes, extended id */
	strcpy(line, "(1.000000) can1 12345678##5");
	for (i = 0; i < 64U; i++) {
		(void)snprintf(line + strlen(line), 3, "%02X", (unsigned)i);
	}
	expect_frame(line, &f);
	assert_int_equal(f.len, 64);
	assert_true(f.ext);
	assert_int_equal(f.id, 0x12345678);
	assert_int_equal(f.data[63], 63);
	expect_frame("(1.000000) can0 123##4", &f);
	assert_int_equal(f.len, 0);
}

static void test_error_frames(void **state)
{
	candump_frame_t f;

	(void)state;
	expect_frame("(1.000000) can0 20000004#0004000000000000", &f);
	assert_int_equal(f.kind, CANDUMP_KIND_ERROR);
	assert_int_equal(f.id, 0x4); /* CAN_ERR_CRTL */
	assert_int_equal(f.len, 8);
	assert_int_equal(f.data[1], 0x04);
	expect_frame("(1.000000) can0 3FFFFFFF#", &f);
	assert_int_equal(f.kind, CANDUMP_KIND_ERROR);
	assert_int_equal(f.id, 0x1FFFFFFF);
	expect_error("(1.000000) can0 20000004#R", CANDUMP_ERR_ERROR_FRAME);
	expect_error("(1.000000) can0 20000004##100", CANDUMP_ERR_ERROR_FRAME);
}

static void test_direction_crlf_and_blanks(void **state)
{
	candump_frame_t f;

	(void)state;
	expect_frame("(1.000000) can0 123#11 T", &f);
	assert_int_equal(f.dir, 'T');
	expect_frame("(1.000000) can0 123#11 R\n", &f);
	assert_int_equal(f.dir, 'R');
	expect_frame("(1.000000)\tcan0  123#11  \r\n", &f);
	assert_int_equal(f.len, 1);
	assert_int_equal(f.dir, 0);
}

static void test_xl_frames_are_recognised_not_decoded(void **state)
{
	candump_frame_t f;

	(void)state;
	expect_frame("(1.000000) can0 45123#81:00:12345678#11223344.556677", &f);
	assert_int_equal(f.kind, CANDUMP_KIND_XL);
	assert_int_equal(f.id, 0x123);
	assert_int_equal(f.xl_len, 7);
	expect_error("(1.000000) can0 45123#81:00:1234567#11", CANDUMP_ERR_XL);
	expect_error("(1.000000) can0 45123#81:00:12345678#", CANDUMP_ERR_XL);
	expect_error("(1.000000) can0 45123#8X:00:12345678#11", CANDUMP_ERR_XL);
	expect_error("(1.000000) can0 45123#81", CANDUMP_ERR_ID_DIGITS);
}

static void test_other_lines(void **state)
{
	candump_frame_t f;

	(void)state;
	assert_int_equal(parse("", &f, NULL), CANDUMP_LINE_BLANK);
	assert_int_equal(parse("   \t\r\n", &f, NULL), CANDUMP_LINE_BLANK);
	assert_int_equal(parse("# recorded on the rig", &f, NULL), CANDUMP_LINE_COMMENT);
	assert_int_equal(parse("  ; note", &f, NULL), CANDUMP_LINE_COMMENT);
	assert_int_equal(parse("DROPCOUNT: dropped 3 CAN frames on 'can0' socket (total drops 7)",
			       &f, NULL), CANDUMP_LINE_DROPCOUNT);
	assert_int_equal(f.dropped, 3);
	assert_int_equal(parse("DROPCOUNT: something else", &f, NULL), CANDUMP_LINE_DROPCOUNT);
	assert_int_equal(f.dropped, 0);
	assert_int_equal(candump_parse_line(NULL, 0U, &f, NULL, NULL), CANDUMP_LINE_BLANK);
	assert_int_equal(candump_parse_line("x", 1U, NULL, NULL, NULL), CANDUMP_LINE_MALFORMED);
}

/* ---- malformed lines -------------------------------------------------------- */

static void test_malformed_lines_each_with_its_reason(void **state)
{
	static const struct {
		const char *line;
		candump_err_t err;
	} cases[] = {
		{ "hello", CANDUMP_ERR_NOT_A_FRAME },
		{ "can0 123#00", CANDUMP_ERR_NOT_A_FRAME },
		{ "(", CANDUMP_ERR_TIMESTAMP },
		{ "(1700000000.123456", CANDUMP_ERR_TIMESTAMP },
		{ "(1700000000.12345) can0 123#", CANDUMP_ERR_TIMESTAMP },
		{ "(1700000000.1234567) can0 123#", CANDUMP_ERR_TIMESTAMP },
		{ "(1700000000.1234567890) can0 123#", CANDUMP_ERR_TIMESTAMP },
		{ "(1700000000) can0 123#", CANDUMP_ERR_TIMESTAMP },
		{ "(.123456) can0 123#", CANDUMP_ERR_TIMESTAMP },
		{ "(-1.123456) can0 123#", CANDUMP_ERR_TIMESTAMP },
		{ "(1,123456) can0 123#", CANDUMP_ERR_TIMESTAMP },
		{ "(1.12a456) can0 123#", CANDUMP_ERR_TIMESTAMP },
		{ "(18446744074.000000) can0 123#", CANDUMP_ERR_TIME_RANGE },
		{ "(18446744073.709551616) can0 123#", CANDUMP_ERR_TIME_RANGE },
		{ "(123456789012345678901.000000) can0 123#", CANDUMP_ERR_TIME_RANGE },
		{ "(1.000000)can0 123#", CANDUMP_ERR_IFACE },
		{ "(1.000000) ", CANDUMP_ERR_IFACE },
		{ "(1.000000) averyveryverylongname 123#", CANDUMP_ERR_IFACE },
		{ "(1.000000) can0", CANDUMP_ERR_NO_FRAME },
		{ "(1.000000) can0   ", CANDUMP_ERR_NO_FRAME },
		{ "(1.000000) can0 123", CANDUMP_ERR_NO_HASH },
		{ "(1.000000) can0 12345678", CANDUMP_ERR_NO_HASH },
		{ "(1.000000) can0 123 11", CANDUMP_ERR_NO_HASH },
		{ "(1.000000) can0 1234#11", CANDUMP_ERR_ID_DIGITS },
		{ "(1.000000) can0 12#11", CANDUMP_ERR_ID_DIGITS },
		{ "(1.000000) can0 #11", CANDUMP_ERR_ID_DIGITS },
		{ "(1.000000) can0 123456789#11", CANDUMP_ERR_ID_DIGITS },
		{ "(1.000000) can0 0000000123#11", CANDUMP_ERR_ID_DIGITS },
		{ "(1.000000) can0 12G#11", CANDUMP_ERR_ID_HEX },
		{ "(1.000000) can0 xyz", CANDUMP_ERR_ID_HEX },
		{ "(1.000000) can0 800#11", CANDUMP_ERR_ID_RANGE },
		{ "(1.000000) can0 FFF#", CANDUMP_ERR_ID_RANGE },
		{ "(1.000000) can0 40000000#", CANDUMP_ERR_ID_RANGE },
		{ "(1.000000) can0 FFFFFFFF#", CANDUMP_ERR_ID_RANGE },
		{ "(1.000000) can0 123#1", CANDUMP_ERR_DATA_ODD },
		{ "(1.000000) can0 123#112", CANDUMP_ERR_DATA_ODD },
		{ "(1.000000) can0 123#1.1", CANDUMP_ERR_DATA_ODD },
		{ "(1.000000) can0 123#GG", CANDUMP_ERR_DATA_HEX },
		{ "(1.000000) can0 123#1G", CANDUMP_ERR_DATA_HEX },
		{ "(1.000000) can0 123#11..22", CANDUMP_ERR_DATA_HEX },
		{ "(1.000000) can0 123#11-22", CANDUMP_ERR_DATA_HEX },
		{ "(1.000000) can0 123#001122334455667788", CANDUMP_ERR_DATA_LEN },
		{ "(1.000000) can0 123##5", CANDUMP_OK },
		{ "(1.000000) can0 123##", CANDUMP_ERR_FD_FLAGS },
		{ "(1.000000) can0 123##G00", CANDUMP_ERR_FD_FLAGS },
		{ "(1.000000) can0 123##5001122334455667788", CANDUMP_ERR_FD_LEN },
		{ "(1.000000) can0 123##50011", CANDUMP_OK },
		{ "(1.000000) can0 123#0011223344556677_8", CANDUMP_ERR_DLC_CODE },
		{ "(1.000000) can0 123#0011223344556677_", CANDUMP_ERR_DLC_CODE },
		{ "(1.000000) can0 123#00112233445566_9", CANDUMP_ERR_DLC_CODE },
		{ "(1.000000) can0 123#0011223344556677_G", CANDUMP_ERR_DLC_CODE },
		{ "(1.000000) can0 123#R9", CANDUMP_ERR_RTR_LEN },
		{ "(1.000000) can0 123#RA", CANDUMP_ERR_RTR_LEN },
		{ "(1.000000) can0 123#R5_9", CANDUMP_ERR_DLC_CODE },
		{ "(1.000000) can0 123#R11", CANDUMP_ERR_TRAILING },
		{ "(1.000000) can0 123#11 X", CANDUMP_ERR_TRAILING },
		{ "(1.000000) can0 123#11 TT", CANDUMP_ERR_TRAILING },
		{ "(1.000000) can0 123#11 T R", CANDUMP_ERR_TRAILING },
		{ "(1.000000) can0 123#0011223344556677_9Z", CANDUMP_ERR_TRAILING },
		{ "(1.000000) can0 123#11\r22", CANDUMP_ERR_TRAILING },
	};
	size_t i;

	(void)state;
	for (i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
		if (cases[i].err == CANDUMP_OK) {
			continue; /* spacer rows, valid lines */
		}
		expect_error(cases[i].line, cases[i].err);
	}
	expect_error("(1.000000) can0 123##500112233445566778899", CANDUMP_ERR_FD_LEN);
}

static void test_embedded_nul_is_an_error_not_an_end(void **state)
{
	static const char line[] = "(1.000000) can0 123#11\0garbage";
	candump_frame_t f;
	candump_err_t err = CANDUMP_OK;
	size_t col = 0;

	(void)state;
	assert_int_equal(candump_parse_line(line, sizeof(line) - 1U, &f, &err, &col),
			 CANDUMP_LINE_MALFORMED);
	assert_int_equal(err, CANDUMP_ERR_NUL);
	assert_int_equal(col, 22);
}

/* A NUL is looked for only when a line is no frame or blank line (see
 * candump_log.c), yet it comes first wherever it is: one in any column of
 * any kind of line, even after what is already an error, is reported
 * there. */
static void test_nul_at_any_column_comes_first(void **state)
{
	static const char *const lines[] = {
		"(1700000000.123456) can0 110#5A03E803",
		"(0000000012.340000) vcan0 18FEF100#0102030405060708_C",
		"(1700000000.123456789) can0 123#R8 T",
		"(1700000000.123456) can0 123##5112233",
		"(1700000000.123456) can0 20000004#0004000000000000",
		"(1.000000) can0 45123#81:00:12345678#11223344.556677",
		"(1.000000)  long_name_of_15\t7FF#11.22\tR\t",
		"   ",
		"# a comment",
		"DROPCOUNT: dropped 3 CAN frame(s) on 'can0' socket (total drops 3)",
		"(1.000000) can0 123#1G22",
		"(1.000000) can0 800#",
		"no frame at all",
		"(1.000000) can0 123#11\r\n",
	};
	candump_frame_t f;
	candump_err_t err;
	size_t col;
	size_t i;
	size_t at;

	(void)state;
	for (i = 0; i < sizeof(lines) / sizeof(lines[0]); i++) {
		const size_t len = strlen(lines[i]);

		for (at = 0; at < len; at++) {
			char *copy = malloc(len);

			assert_non_null(copy);
			memcpy(copy, lines[i], len);
			copy[at] = '\0';
			err = CANDUMP_OK;
			col = (size_t)-1;
			assert_int_equal(candump_parse_line(copy, len, &f, &err, &col),
					 CANDUMP_LINE_MALFORMED);
			assert_int_equal(err, CANDUMP_ERR_NUL);
			assert_int_equal(col, at);
			free(copy);
		}
	}
}

/* The usual forms of the fields (ten.six digits of time, a short name, a
 * three-digit identifier, data without '.') and lines a byte away from
 * them: the same kind, error, column and values as the general rules give.
 * Each expected value follows from the grammar in candump_log.h, the
 * column counted by hand from the line's first byte (0): where parsing
 * stops, e.g. at the ')' where a sixth fraction digit is wanted, at the
 * ninth data byte of a classic frame, or back at the first identifier
 * digit of a 3-digit identifier above 0x7FF. */
static void test_usual_forms_and_near_misses(void **state)
{
	static const struct {
		const char *line;
		candump_err_t err; /* CANDUMP_OK: a frame with these values */
		size_t col;
		uint64_t t_ns;
		const char *iface;
		uint32_t id;
		uint8_t len;
	} cases[] = {
		{ "(1700000000.123456) can0 123#11", CANDUMP_OK, 0U, 1700000000123456000ULL, "can0", 0x123U, 1 },
		{ "(1700000000.12345) can0 123#11", CANDUMP_ERR_TIMESTAMP, 17U, 0U, "", 0U, 0U },
		{ "(1700000000.1234567) can0 123#11", CANDUMP_ERR_TIMESTAMP, 19U, 0U, "", 0U, 0U },
		{ "(1700000000.123456789) can0 123#11", CANDUMP_OK, 0U, 1700000000123456789ULL, "can0", 0x123U, 1 },
		{ "(1700000000.123456 can0 123#11", CANDUMP_ERR_TIMESTAMP, 18U, 0U, "", 0U, 0U },
		{ "(1700000000.123456]can0 123#11", CANDUMP_ERR_TIMESTAMP, 18U, 0U, "", 0U, 0U },
		{ "(170000000.123456) can0 123#11", CANDUMP_OK, 0U, 170000000123456000ULL, "can0", 0x123U, 1 },
		{ "(17000000000.123456) can0 123#11", CANDUMP_OK, 0U, 17000000000123456000ULL, "can0", 0x123U, 1 },
		{ "(1700000000,123456) can0 123#11", CANDUMP_ERR_TIMESTAMP, 11U, 0U, "", 0U, 0U },
		{ "(1700000000.123456)can0 123#11", CANDUMP_ERR_IFACE, 19U, 0U, "", 0U, 0U },
		{ "(1700000000.12345a) can0 123#11", CANDUMP_ERR_TIMESTAMP, 17U, 0U, "", 0U, 0U },
		{ "(170000000/.123456) can0 123#11", CANDUMP_ERR_TIMESTAMP, 10U, 0U, "", 0U, 0U },
		{ "(17000000:0.123456) can0 123#11", CANDUMP_ERR_TIMESTAMP, 9U, 0U, "", 0U, 0U },
		{ "(9999999999.999999) can0 123#11", CANDUMP_OK, 0U, 9999999999999999000ULL, "can0", 0x123U, 1 },
		{ "(0000000000.000000) can0 123#11", CANDUMP_OK, 0U, 0ULL, "can0", 0x123U, 1 },
		{ "(1700000000.123456)", CANDUMP_ERR_IFACE, 19U, 0U, "", 0U, 0U },
		{ "(1700000000.123456) ", CANDUMP_ERR_IFACE, 20U, 0U, "", 0U, 0U },
		{ "(1700000000.123456)\tcan0 123#11", CANDUMP_OK, 0U, 1700000000123456000ULL, "can0", 0x123U, 1 },
		{ "(1.000000) vcan0123 123#11", CANDUMP_OK, 0U, 1000000000ULL, "vcan0123", 0x123U, 1 },
		{ "(1.000000) abcdefghijklmno 123#11", CANDUMP_OK, 0U, 1000000000ULL, "abcdefghijklmno", 0x123U, 1 },
		{ "(1.000000) abcdefghijklmnop 123#11", CANDUMP_ERR_IFACE, 26U, 0U, "", 0U, 0U },
		{ "(1.000000) can\x01" "x 123#11", CANDUMP_OK, 0U, 1000000000ULL, "can\x01" "x", 0x123U, 1 },
		{ "(1.000000) can!x 123#11", CANDUMP_OK, 0U, 1000000000ULL, "can!x", 0x123U, 1 },
		{ "(1.000000) c 123#11", CANDUMP_OK, 0U, 1000000000ULL, "c", 0x123U, 1 },
		{ "(1.000000) can0\t123#11", CANDUMP_OK, 0U, 1000000000ULL, "can0", 0x123U, 1 },
		{ "(1.000000) can0", CANDUMP_ERR_NO_FRAME, 15U, 0U, "", 0U, 0U },
		{ "(1.000000) can0 ", CANDUMP_ERR_NO_FRAME, 16U, 0U, "", 0U, 0U },
		{ "(1.000000) can0 7FF#11", CANDUMP_OK, 0U, 1000000000ULL, "can0", 0x7FFU, 1 },
		{ "(1.000000) can0 800#11", CANDUMP_ERR_ID_RANGE, 16U, 0U, "", 0U, 0U },
		{ "(1.000000) can0 7ab#", CANDUMP_OK, 0U, 1000000000ULL, "can0", 0x7ABU, 0 },
		{ "(1.000000) can0 12G#11", CANDUMP_ERR_ID_HEX, 18U, 0U, "", 0U, 0U },
		{ "(1.000000) can0 12#11", CANDUMP_ERR_ID_DIGITS, 18U, 0U, "", 0U, 0U },
		{ "(1.000000) can0 1234#11", CANDUMP_ERR_ID_DIGITS, 20U, 0U, "", 0U, 0U },
		{ "(1.000000) can0 /12#11", CANDUMP_ERR_ID_HEX, 16U, 0U, "", 0U, 0U },
		{ "(1.000000) can0 12:#11", CANDUMP_ERR_ID_HEX, 18U, 0U, "", 0U, 0U },
		{ "(1.000000) can0 123", CANDUMP_ERR_NO_HASH, 19U, 0U, "", 0U, 0U },
		{ "(1.000000) can0 123#0011223344556677", CANDUMP_OK, 0U, 1000000000ULL, "can0", 0x123U, 8 },
		{ "(1.000000) can0 123#001122334455667788", CANDUMP_ERR_DATA_LEN, 36U, 0U, "", 0U, 0U },
		{ "(1.000000) can0 123#00112233445566G7", CANDUMP_ERR_DATA_HEX, 34U, 0U, "", 0U, 0U },
		{ "(1.000000) can0 123#0011223344556", CANDUMP_ERR_DATA_ODD, 33U, 0U, "", 0U, 0U },
		{ "(1.000000) can0 123#00112233 T", CANDUMP_OK, 0U, 1000000000ULL, "can0", 0x123U, 4 },
		{ "(1.000000) can0 123#00112233\tR", CANDUMP_OK, 0U, 1000000000ULL, "can0", 0x123U, 4 },
		{ "(1.000000) can0 123#0011.2233", CANDUMP_OK, 0U, 1000000000ULL, "can0", 0x123U, 4 },
		{ "(1.000000) can0 123#001122.33", CANDUMP_OK, 0U, 1000000000ULL, "can0", 0x123U, 4 },
		{ "(1.000000) can0 123#aAbBcCdDeEfF0011", CANDUMP_OK, 0U, 1000000000ULL, "can0", 0x123U, 8 },
		{ "(1.000000) can0 123#0011223344556677_9", CANDUMP_OK, 0U, 1000000000ULL, "can0", 0x123U, 8 },
		{ "(1.000000) can0 123#00112233_9", CANDUMP_ERR_DLC_CODE, 28U, 0U, "", 0U, 0U },
		{ "(1.000000) can0 123#001122334455667`", CANDUMP_ERR_DATA_HEX, 35U, 0U, "", 0U, 0U },
		{ "(1.000000) can0 123#001122334455667@", CANDUMP_ERR_DATA_HEX, 35U, 0U, "", 0U, 0U },
		{ "(1.000000) can0 123#001122334455667g", CANDUMP_ERR_DATA_HEX, 35U, 0U, "", 0U, 0U },
		{ "(1.000000) can0 123#001122334455667G", CANDUMP_ERR_DATA_HEX, 35U, 0U, "", 0U, 0U },
		{ "(1.000000) can0 123#001122334455667/", CANDUMP_ERR_DATA_HEX, 35U, 0U, "", 0U, 0U },
		{ "(1.000000) can0 123#001122334455667:", CANDUMP_ERR_DATA_HEX, 35U, 0U, "", 0U, 0U },
		{ "(1.000000) can0 123#0011223344556677\r", CANDUMP_OK, 0U, 1000000000ULL, "can0", 0x123U, 8 },
		{ "(1.000000) can0 123#00112233445566\n", CANDUMP_OK, 0U, 1000000000ULL, "can0", 0x123U, 7 },
		{ "(1.000000) can0 123##100112233445566778899AABB", CANDUMP_OK, 0U, 1000000000ULL, "can0", 0x123U, 12 },
		{ "(1.000000) can0 123##1001122334455667788", CANDUMP_ERR_FD_LEN, 40U, 0U, "", 0U, 0U },
		{ "(1.000000) can0 123##1000102030405060708090A0B0C0D0E0F101112131415161718191A1B1C1D1E1F202122232425262728292A2B2C2D2E2F303132333435363738393A3B3C3D3E3F", CANDUMP_OK, 0U, 1000000000ULL, "can0", 0x123U, 64 },
		{ "(1.000000) can0 123##1000102030405060708090A0B0C0D0E0F101112131415161718191A1B1C1D1E1F202122232425262728292A2B2C2D2E2F303132333435363738393A3B3C3D3E3F40", CANDUMP_ERR_DATA_LEN, 150U, 0U, "", 0U, 0U },
		{ "(1.000000) can0 12345678#0011223344556677", CANDUMP_OK, 0U, 1000000000ULL, "can0", 0x12345678U, 8 },
		{ "(1.000000) can0 20000004#0004000000000000", CANDUMP_OK, 0U, 1000000000ULL, "can0", 0x4U, 8 },
	};
	candump_frame_t f;
	candump_err_t err;
	size_t col;
	size_t i;

	(void)state;
	for (i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
		const size_t len = strlen(cases[i].line);
		char *copy = malloc(len);
		candump_line_t k;

		assert_non_null(copy);
		memcpy(copy, cases[i].line, len);
		err = CANDUMP_ERR_COUNT;
		col = (size_t)-1;
		k = candump_parse_line(copy, len, &f, &err, &col);
		free(copy);
		if (err != cases[i].err) {
			fail_msg("'%s': got '%s', want '%s'", cases[i].line, candump_strerror(err),
				 candump_strerror(cases[i].err));
		}
		if (cases[i].err != CANDUMP_OK) {
			assert_int_equal(k, CANDUMP_LINE_MALFORMED);
			assert_int_equal(col, cases[i].col);
			continue;
		}
		assert_int_equal(k, CANDUMP_LINE_FRAME);
		assert_true(f.t_ns == cases[i].t_ns);
		assert_string_equal(f.iface, cases[i].iface);
		assert_int_equal(f.id, cases[i].id);
		assert_int_equal(f.len, cases[i].len);
	}
}

static void test_too_long_line(void **state)
{
	char *line = malloc(CANDUMP_LINE_MAX + 10U);
	candump_frame_t f;
	candump_err_t err = CANDUMP_OK;

	(void)state;
	assert_non_null(line);
	memset(line, '1', CANDUMP_LINE_MAX + 10U);
	memcpy(line, "(1.000000) can0 123#", 20);
	assert_int_equal(candump_parse_line(line, CANDUMP_LINE_MAX + 10U, &f, &err, NULL),
			 CANDUMP_LINE_MALFORMED);
	assert_int_equal(err, CANDUMP_ERR_TOO_LONG);
	free(line);
}

static void test_every_prefix_of_valid_lines_is_safe(void **state)
{
	static const char *const lines[] = {
		"(1700000000.123456789) can0 12345678##5" "00112233445566778899AABB",
		"(1.000000) can0 45123#81:00:12345678#11223344.556677",
		"(1.000000) can0 123#R8_F T",
		"(1.000000) can0 20000004#0004000000000000",
		"(1.000000) can0 123#0102030405060708_C R",
	};
	candump_frame_t f;
	size_t i;
	size_t n;

	(void)state;
	for (i = 0; i < sizeof(lines) / sizeof(lines[0]); i++) {
		const size_t len = strlen(lines[i]);

		for (n = 0; n <= len; n++) {
			candump_line_t k = parse_n(lines[i], n, &f, NULL);

			assert_true(k <= CANDUMP_LINE_MALFORMED);
		}
		assert_int_equal(parse_n(lines[i], len, &f, NULL), CANDUMP_LINE_FRAME);
	}
}

/* xorshift64: deterministic pseudo-random bytes */
static uint64_t rng_state = 0x9E3779B97F4A7C15ULL;

static uint64_t rnd(void)
{
	rng_state ^= rng_state << 13;
	rng_state ^= rng_state >> 7;
	rng_state ^= rng_state << 17;
	return rng_state;
}

static void test_random_bytes_and_mutations_never_crash(void **state)
{
	static const char base[] = "(1700000000.123456) can0 12345678##5001122334455667788990011";
	static const char alphabet[] = "()#._ RT0123456789ABCDEFabcdefG\t\r\n\0:;\xff";
	char buf[128];
	candump_frame_t f;
	int iter;

	(void)state;
	for (iter = 0; iter < 200000; iter++) {
		const size_t len = (size_t)(rnd() % sizeof(buf));
		size_t i;

		if ((iter & 1) != 0) {
			for (i = 0; i < len; i++) {
				buf[i] = (char)(rnd() & 0xFFU);
			}
		} else {
			const size_t n = (len < sizeof(base) - 1U) ? len : sizeof(base) - 1U;

			memcpy(buf, base, n);
			for (i = 0; i < 3U && n > 0U; i++) {
				buf[rnd() % n] = alphabet[rnd() % (sizeof(alphabet) - 1U)];
			}
			(void)parse_n(buf, n, &f, NULL);
			continue;
		}
		(void)parse_n(buf, len, &f, NULL);
	}
}

/* ---- writer ----------------------------------------------------------------- */

static void test_writer_exact_strings(void **state)
{
	candump_frame_t f;
	char out[CANDUMP_FORMAT_MAX + 1U];

	(void)state;
	memset(&f, 0, sizeof(f));
	f.t_ns = 12340000999ULL; /* 12.340000999 s -> truncated to us */
	strcpy(f.iface, "vcan0");
	f.kind = CANDUMP_KIND_CLASSIC;
	f.id = 0x300;
	f.len = 8;
	memcpy(f.data, "\x01\xAB\x00\xff\x10\x20\x30\x40", 8);
	assert_int_equal(candump_format_frame(&f, false, out, sizeof(out)), 46);
	assert_string_equal(out, "(0000000012.340000) vcan0 300#01AB00FF10203040");
	f.len8_dlc = 0xC;
	(void)candump_format_frame(&f, true, out, sizeof(out));
	assert_string_equal(out, "(0000000012.340000) vcan0 300#01AB00FF10203040_C\n");
	f.len8_dlc = 0;
	f.ext = true;
	f.id = 0x123;
	f.len = 0;
	(void)candump_format_frame(&f, false, out, sizeof(out));
	assert_string_equal(out, "(0000000012.340000) vcan0 00000123#");
	f.kind = CANDUMP_KIND_RTR;
	f.ext = false;
	f.len = 3;
	(void)candump_format_frame(&f, false, out, sizeof(out));
	assert_string_equal(out, "(0000000012.340000) vcan0 123#R3");
	f.kind = CANDUMP_KIND_FD;
	f.fd_flags = 5;
	f.len = 2;
	(void)candump_format_frame(&f, false, out, sizeof(out));
	assert_string_equal(out, "(0000000012.340000) vcan0 123##501AB");
	f.kind = CANDUMP_KIND_ERROR;
	f.id = 0x4;
	f.len = 8;
	(void)candump_format_frame(&f, false, out, sizeof(out));
	assert_string_equal(out, "(0000000012.340000) vcan0 20000004#01AB00FF10203040");
	f.t_ns = 12345678901000000000ULL; /* more than 10 digits of seconds */
	f.kind = CANDUMP_KIND_CLASSIC;
	f.id = 0x7FF;
	f.len = 0;
	(void)candump_format_frame(&f, false, out, sizeof(out));
	assert_string_equal(out, "(12345678901.000000) vcan0 7FF#");
}

/* The time as printf's "%010llu.%06llu" (seconds, microseconds truncated)
 * on both sides of ten digits of seconds and at the ends of the range, the
 * interface name of every length, and the bytes of the buffer after the
 * line's NUL left alone. */
static void test_writer_time_digits_and_name_lengths(void **state)
{
	static const uint64_t times[] = {
		0ULL, 999ULL, 1000ULL, 999999999ULL, 1000000000ULL, 1700000000123456789ULL,
		9999999999999999999ULL, 10000000000000000000ULL, 10000000000000000999ULL,
		12345678901234567890ULL, 18446744073709551615ULL,
	};
	static const char name[] = "abcdefghijklmno";
	candump_frame_t f;
	char out[CANDUMP_FORMAT_MAX + 16U];
	char want[CANDUMP_FORMAT_MAX + 16U];
	size_t t;
	size_t n;
	size_t k;

	(void)state;
	for (t = 0; t < sizeof(times) / sizeof(times[0]); t++) {
		for (n = 1; n <= CANDUMP_IFACE_MAX; n++) {
			int w;

			memset(&f, 0, sizeof(f));
			f.t_ns = times[t];
			memcpy(f.iface, name, n);
			f.kind = CANDUMP_KIND_CLASSIC;
			f.id = 0x1A5;
			f.len = 2;
			f.data[0] = 0xC3;
			f.data[1] = 0x0F;
			w = snprintf(want, sizeof(want), "(%010llu.%06llu) %.*s 1A5#C30F",
				     (unsigned long long)(times[t] / 1000000000ULL),
				     (unsigned long long)(times[t] % 1000000000ULL / 1000ULL), (int)n, name);
			memset(out, '~', sizeof(out));
			assert_int_equal(candump_format_frame(&f, false, out, sizeof(out)), w);
			assert_string_equal(out, want);
			for (k = (size_t)w + 1U; k < sizeof(out); k++) {
				assert_int_equal(out[k], '~');
			}
		}
	}
}

static void test_writer_refuses_bad_frames_and_small_buffers(void **state)
{
	candump_frame_t f;
	char out[CANDUMP_FORMAT_MAX + 1U];

	(void)state;
	memset(&f, 0, sizeof(f));
	strcpy(f.iface, "can0");
	f.id = 0x800;
	assert_int_equal(candump_format_frame(&f, false, out, sizeof(out)), -1);
	f.id = 0x123;
	f.len = 9;
	assert_int_equal(candump_format_frame(&f, false, out, sizeof(out)), -1);
	f.len = 7;
	f.len8_dlc = 9;
	assert_int_equal(candump_format_frame(&f, false, out, sizeof(out)), -1);
	f.len8_dlc = 0;
	f.kind = CANDUMP_KIND_FD;
	f.len = 9;
	assert_int_equal(candump_format_frame(&f, false, out, sizeof(out)), -1);
	f.kind = CANDUMP_KIND_XL;
	assert_int_equal(candump_format_frame(&f, false, out, sizeof(out)), -1);
	f.kind = CANDUMP_KIND_CLASSIC;
	f.len = 1;
	f.iface[0] = '\0';
	assert_int_equal(candump_format_frame(&f, false, out, sizeof(out)), -1);
	strcpy(f.iface, "can0");
	assert_int_equal(candump_format_frame(&f, false, out, 20), -1);
	assert_string_equal(out, "");
	/* exactly enough: 31 characters + NUL */
	assert_int_equal(candump_format_frame(&f, false, out, 32), 31);
	assert_string_equal(out, "(0000000000.000000) can0 123#00");
	assert_int_equal(candump_format_frame(&f, false, out, 31), -1);
}

static void test_writer_parser_round_trip_random_frames(void **state)
{
	candump_frame_t f;
	candump_frame_t g;
	char out[CANDUMP_FORMAT_MAX + 1U];
	static const uint8_t fd_lens[] = { 0, 1, 5, 8, 12, 16, 20, 24, 32, 48, 64 };
	int iter;

	(void)state;
	for (iter = 0; iter < 20000; iter++) {
		int n;
		size_t i;

		memset(&f, 0, sizeof(f));
		f.t_ns = (rnd() % 4000000000000000000ULL) / 1000U * 1000U;
		(void)snprintf(f.iface, sizeof(f.iface), "can%u", (unsigned)(rnd() % 100U));
		f.kind = (candump_kind_t)(rnd() % 4U);
		f.ext = (rnd() & 1U) != 0U;
		f.id = (uint32_t)(rnd() & (f.ext ? CANDUMP_EFF_MAX : CANDUMP_SFF_MAX));
		switch (f.kind) {
		case CANDUMP_KIND_FD:
			f.len = fd_lens[rnd() % sizeof(fd_lens)];
			f.fd_flags = (uint8_t)(rnd() & 0xFU);
			break;
		case CANDUMP_KIND_ERROR:
			f.ext = true;
			f.len = (uint8_t)(rnd() % 9U);
			break;
		default:
			f.len = (uint8_t)(rnd() % 9U);
			if ((f.len == 8U) && ((rnd() & 1U) != 0U)) {
				f.len8_dlc = (uint8_t)(9U + rnd() % 7U);
			}
			break;
		}
		if (f.kind != CANDUMP_KIND_RTR) {
			for (i = 0; i < f.len; i++) {
				f.data[i] = (uint8_t)rnd();
			}
		}
		f.dir = ((rnd() % 3U) == 0U) ? 'T' : 0;
		n = candump_format_frame(&f, (rnd() & 1U) != 0U, out, sizeof(out));
		assert_true(n > 0);
		assert_int_equal(parse_n(out, (size_t)n, &g, NULL), CANDUMP_LINE_FRAME);
		assert_true(g.t_ns == f.t_ns);
		assert_string_equal(g.iface, f.iface);
		assert_int_equal(g.kind, f.kind);
		assert_int_equal(g.id, f.id);
		assert_int_equal(g.ext, f.ext);
		assert_int_equal(g.len, f.len);
		assert_int_equal(g.len8_dlc, f.len8_dlc);
		assert_int_equal(g.fd_flags, f.fd_flags);
		assert_int_equal(g.dir, f.dir);
		assert_memory_equal(g.data, f.data, CANDUMP_DATA_MAX);
	}
}

/* ---- reader ------------------------------------------------------------------ */

static void test_reader_lines_numbers_long_lines_and_nul(void **state)
{
	FILE *fp = tmpfile();
	candump_reader_t *r = malloc(sizeof(*r));
	const char *line;
	size_t len;
	bool too_long;
	size_t i;

	(void)state;
	assert_non_null(fp);
	assert_non_null(r);
	fputs("(1.000000) can0 123#11\n\n", fp);
	for (i = 0; i < CANDUMP_LINE_MAX + 100000U; i++) {
		fputc('A', fp);
	}
	fputc('\n', fp);
	fwrite("a\0b\n", 1, 4, fp);
	fputs("last without newline", fp);
	rewind(fp);
	candump_reader_init(r, fp);
	assert_int_equal(candump_reader_next(r, &line, &len, &too_long), 1);
	assert_int_equal(len, 22);
	assert_false(too_long);
	assert_int_equal(candump_reader_next(r, &line, &len, &too_long), 1);
	assert_int_equal(len, 0);
	assert_int_equal(candump_reader_next(r, &line, &len, &too_long), 1);
	assert_true(too_long);
	assert_int_equal(len, CANDUMP_LINE_MAX);
	assert_int_equal(r->line_no, 3);
	assert_int_equal(candump_reader_next(r, &line, &len, &too_long), 1);
	assert_int_equal(len, 3);
	assert_memory_equal(line, "a\0b", 3);
	assert_int_equal(candump_reader_next(r, &line, &len, &too_long), 1);
	assert_string_equal(line, "last without newline");
	assert_int_equal(r->line_no, 5);
	assert_int_equal(candump_reader_next(r, &line, &len, &too_long), 0);
	free(r);
	fclose(fp);
}

static void test_strerror_covers_every_code(void **state)
{
	int e;

	(void)state;
	for (e = 0; e < (int)CANDUMP_ERR_COUNT; e++) {
		assert_true(strlen(candump_strerror((candump_err_t)e)) > 0U);
	}
	assert_string_equal(candump_strerror(CANDUMP_ERR_COUNT), "unknown error");
}

/* What the pending messages wrote to a temporary file, NUL-terminated. */
static void pending_text(FILE *fp, char *buf, size_t len)
{
	size_t n;

	assert_int_equal(fflush(fp), 0);
	rewind(fp);
	n = fread(buf, 1U, len - 1U, fp);
	buf[n] = '\0';
}

static void test_pending_messages_wait_for_the_first_frame(void **state)
{
	static candump_pending_t p;
	FILE *fp = tmpfile();
	char buf[512];

	(void)state;
	assert_non_null(fp);
	candump_pending_init(&p, fp, "x.log");
	candump_pending_report(&p, "x.log:%d: bad", 1);
	candump_pending_report(&p, "x.log:%d: worse", 2);
	pending_text(fp, buf, sizeof(buf));
	assert_string_equal(buf, ""); /* held back */
	candump_pending_frame(&p);
	candump_pending_frame(&p); /* once only */
	candump_pending_report(&p, "x.log:%d: after", 4);
	assert_false(candump_pending_no_frames(&p, 3U));
	pending_text(fp, buf, sizeof(buf));
	assert_string_equal(buf, "x.log:1: bad\nx.log:2: worse\nx.log:4: after\n");
	fclose(fp);
}

static void test_pending_without_a_frame_is_one_line(void **state)
{
	static candump_pending_t p;
	FILE *fp = tmpfile();
	char buf[512];
	unsigned i;

	(void)state;
	assert_non_null(fp);
	candump_pending_init(&p, fp, "README.md");
	for (i = 0U; i < 1000U; i++) {
		candump_pending_report(&p, "README.md:%u: not a frame", i + 1U);
	}
	assert_true(candump_pending_no_frames(&p, 597U));
	pending_text(fp, buf, sizeof(buf));
	assert_string_equal(buf, "README.md: no CAN frame in 597 lines\n");
	fclose(fp);
}

static void test_pending_beyond_its_room_is_counted(void **state)
{
	static candump_pending_t p;
	FILE *fp = tmpfile();
	char buf[4096];
	char want[4096];
	size_t off = 0U;
	unsigned i;

	(void)state;
	assert_non_null(fp);
	candump_pending_init(&p, fp, "y.log");
	for (i = 0U; i < CANDUMP_PENDING_MAX + 3U; i++) {
		candump_pending_report(&p, "y.log:%u: bad", i + 1U);
	}
	candump_pending_frame(&p);
	for (i = 0U; i < CANDUMP_PENDING_MAX; i++) {
		off += (size_t)snprintf(want + off, sizeof(want) - off, "y.log:%u: bad\n", i + 1U);
	}
	(void)snprintf(want + off, sizeof(want) - off,
		       "y.log: 3 more malformed lines before the first frame\n");
	pending_text(fp, buf, sizeof(buf));
	assert_string_equal(buf, want);
	fclose(fp);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_classic_standard_frame),
		cmocka_unit_test(test_empty_frame_and_max_standard_id),
		cmocka_unit_test(test_extended_id_is_marked_by_eight_digits),
		cmocka_unit_test(test_nanosecond_timestamp),
		cmocka_unit_test(test_lowercase_and_dot_separators),
		cmocka_unit_test(test_len8_dlc_codes),
		cmocka_unit_test(test_remote_frames),
		cmocka_unit_test(test_fd_frames_every_flags_nibble),
		cmocka_unit_test(test_error_frames),
		cmocka_unit_test(test_direction_crlf_and_blanks),
		cmocka_unit_test(test_xl_frames_are_recognised_not_decoded),
		cmocka_unit_test(test_other_lines),
		cmocka_unit_test(test_malformed_lines_each_with_its_reason),
		cmocka_unit_test(test_embedded_nul_is_an_error_not_an_end),
		cmocka_unit_test(test_nul_at_any_column_comes_first),
		cmocka_unit_test(test_usual_forms_and_near_misses),
		cmocka_unit_test(test_too_long_line),
		cmocka_unit_test(test_every_prefix_of_valid_lines_is_safe),
		cmocka_unit_test(test_random_bytes_and_mutations_never_crash),
		cmocka_unit_test(test_writer_exact_strings),
		cmocka_unit_test(test_writer_time_digits_and_name_lengths),
		cmocka_unit_test(test_writer_refuses_bad_frames_and_small_buffers),
		cmocka_unit_test(test_writer_parser_round_trip_random_frames),
		cmocka_unit_test(test_reader_lines_numbers_long_lines_and_nul),
		cmocka_unit_test(test_strerror_covers_every_code),
		cmocka_unit_test(test_pending_messages_wait_for_the_first_frame),
		cmocka_unit_test(test_pending_without_a_frame_is_one_line),
		cmocka_unit_test(test_pending_beyond_its_room_is_counted),
	};

	return cmocka_run_group_tests_name("candump_log", tests, NULL, NULL);
}
