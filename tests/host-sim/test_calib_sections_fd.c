/* SPDX-License-Identifier: MIT */
/*
 * The calibration text keys of CAN FD inputs (host-sim/calib_sections.c):
 * fd = yes|no, protection = p05, data_id, e2e_offset_byte, min_dlc up to 64
 * and start bits up to 511; parsed into calib_input_t, written back by
 * calib_text_write_map() to the same calibration, stored in the v4 block
 * and refused with FILE:LINE where they cannot work. Expected fields are
 * the text's own numbers; the default min_dlc of an FD message is the next
 * FD length above the bytes its bits need (hand-derived).
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

static const char fd_map[] =
	"[input WS]\n"              /* 1 */
	"id = 0xA0\n"               /* 2 */
	"fd = yes\n"                /* 3 */
	"start_bit = 64\n"          /* 4 */
	"length = 14\n"             /* 5 */
	"byte_order = intel\n"      /* 6 */
	"factor = 0.03125\n"        /* 7 */
	"unit = km/h\n"             /* 8 */
	"protection = p05\n"        /* 9 */
	"data_id = 0xF8A0\n"        /* 10 */
	"max_delta_counter = 200\n" /* 11 */
	"period_ms = 10\n"          /* 12 */
	"max = 300\n"               /* 13 */
	"step_max = 20\n"           /* 14 */
	"[input PR]\n"              /* 15 */
	"id = 0x1A000000\n"         /* 16 */
	"extended = yes\n"          /* 17 */
	"fd = yes\n"                /* 18 */
	"min_dlc = 64\n"            /* 19 */
	"start_bit = 503\n"         /* 20 */
	"length = 16\n"             /* 21 */
	"byte_order = motorola\n"   /* 22 */
	"factor = 0.1\n"            /* 23 */
	"unit = bar\n"              /* 24 */
	"protection = p05\n"        /* 25 */
	"data_id = 0x1234\n"        /* 26 */
	"e2e_offset_byte = 32\n"    /* 27 */
	"qualifier_bit = 300\n"     /* 28 */
	"period_ms = 20\n"          /* 29 */
	"max = 200\n"               /* 30 */
	"step_max = 50\n"           /* 31 */
	"[corner FL]\n"
	"speed = WS\n"
	"force = PR\n"
	"piston_area_mm2 = 1500\n";

static int parse(const char *text, calib_t *out, char *err, size_t errlen)
{
	FILE *f = fmemopen((void *)(uintptr_t)text, strlen(text), "r");
	int rc;

	assert_non_null(f);
	rc = calib_text_parse_map(f, "fd.cal", out, NULL, err, errlen);
	fclose(f);
	return rc;
}

static void test_fd_keys_parsed(void **state)
{
	calib_t cal;
	char err[300] = "";
	const calib_input_t *ws;
	const calib_input_t *pr;

	(void)state;
	if (parse(fd_map, &cal, err, sizeof(err)) != SQ_OK) {
		fail_msg("%s", err);
	}
	ws = &cal.inputs[0];
	pr = &cal.inputs[1];
	assert_int_equal(ws->fd, 1);
	assert_int_equal(ws->min_dlc, 12);   /* bits 64..77: 10 bytes -> FD length 12 */
	assert_int_equal(ws->protection, CALIB_PROT_P05);
	assert_int_equal(ws->data_id, 0xF8A0);
	assert_int_equal(ws->e2e_offset_byte, 0);
	assert_int_equal(ws->max_delta_counter, 200);
	assert_int_equal(pr->fd, 1);
	assert_int_equal(pr->min_dlc, 64);
	assert_int_equal(pr->sig.start_bit, 503);
	assert_int_equal(pr->sig.byte_order, CAN_SIGNAL_MOTOROLA);
	assert_int_equal(pr->e2e_offset_byte, 32);
	assert_int_equal(pr->qualifier_bit, 300);
	assert_int_equal(calib_validate(&cal), SQ_OK);
}

/* write -> parse gives the same calibration; the v4 block keeps it too */
static void test_write_back_and_block(void **state)
{
	calib_t cal;
	calib_t again;
	calib_t decoded;
	char err[300] = "";
	char *text = NULL;
	size_t len = 0;
	FILE *f;
	uint8_t block[CALIB_BLOCK_LEN];

	(void)state;
	assert_int_equal(parse(fd_map, &cal, err, sizeof(err)), SQ_OK);
	f = open_memstream(&text, &len);
	assert_non_null(f);
	assert_int_equal(calib_text_write_map(f, &cal, NULL), SQ_OK);
	fclose(f);
	assert_non_null(strstr(text, "fd = yes\n"));
	assert_non_null(strstr(text, "protection = p05\n"));
	assert_non_null(strstr(text, "e2e_offset_byte = 32\n"));
	if (parse(text, &again, err, sizeof(err)) != SQ_OK) {
		fail_msg("written back, refused: %s\n%s", err, text);
	}
	free(text);
	assert_memory_equal(&again.inputs[0], &cal.inputs[0], sizeof(cal.inputs[0]));
	assert_memory_equal(&again.inputs[1], &cal.inputs[1], sizeof(cal.inputs[1]));
	assert_int_equal(calib_encode(&cal, block, sizeof(block)), SQ_OK);
	memset(&decoded, 0, sizeof(decoded));
	assert_int_equal(calib_decode(block, sizeof(block), &decoded, NULL), SQ_OK);
	assert_memory_equal(&decoded.inputs[1], &cal.inputs[1], sizeof(cal.inputs[1]));
}

static void refused(const char *from, const char *to, const char *want)
{
	char text[sizeof(fd_map) + 64];
	const char *at = strstr(fd_map, from);
	char err[300] = "";
	calib_t out;

	assert_non_null(at);
	snprintf(text, sizeof(text), "%.*s%s%s", (int)(at - fd_map), fd_map, to, at + strlen(from));
	if ((parse(text, &out, err, sizeof(err)) != SQ_EBADMSG) ||
	    (strncmp(err, want, strlen(want)) != 0)) {
		fail_msg("want '%s...', got '%s'", want, err);
	}
}

static void test_fd_keys_refused(void **state)
{
	(void)state;
	refused("fd = yes\nstart_bit = 64", "fd = no\nstart_bit = 64",
		"fd.cal:4: [input WS] start_bit: the value runs beyond the 8 bytes");
	refused("fd = yes\nstart_bit = 64", "fd = maybe\nstart_bit = 64", "fd.cal:3:");
	refused("min_dlc = 64\n", "min_dlc = 48\n", "fd.cal:19: [input PR] a signal beyond min_dlc 48");
	refused("fd = yes\nstart_bit = 64", "fd = yes\nmin_dlc = 13\nstart_bit = 64",
		"fd.cal:4: [input WS] min_dlc: above 8 an FD frame has 12, 16, 20, 24, 32, 48 or 64 bytes");
	refused("min_dlc = 64\n", "min_dlc = 65\n", "fd.cal:19:");
	refused("e2e_offset_byte = 32\n", "e2e_offset_byte = 62\n", "fd.cal:27:");
	refused("protection = p05\ndata_id = 0x1234\n", "protection = none\n",
		"fd.cal:26: [input PR] e2e_offset_byte is for protection = p05");
	refused("protection = p05\ndata_id = 0xF8A0\n",
		"protection = p02\ndata_id_list = 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16\n",
		"fd.cal:9: [input WS] protection p01 and p02 protect classic frames");
	refused("start_bit = 503\n", "start_bit = 512\n", "fd.cal:20:");
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_fd_keys_parsed),
		cmocka_unit_test(test_write_back_and_block),
		cmocka_unit_test(test_fd_keys_refused),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
