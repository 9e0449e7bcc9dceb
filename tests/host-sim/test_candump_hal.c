/* SPDX-License-Identifier: MIT */
/*
 * CAN FD lines of candump -L (host-sim/candump_log.c) and their HAL frames
 * (host-sim/candump_hal.c): every FD data length with every flags digit,
 * both flag conventions (can-utils before 2023 write BRS|ESI, newer ones add
 * FDF), lengths that are no DLC code (a counted malformed line), and the
 * writer against can-utils itself: a log of FD frames of every length and
 * flag written here is read by log2long (id, length, bytes), log2asc (BRS,
 * ESI, DLC code) and, through log2asc | asc2log, rewritten by can-utils'
 * own writer, which must give the same frame text byte for byte but the
 * FDF bit (ASC has none; the live candump check with FDF is
 * tests/system/run-fd-log.sh). Expected
 * values are written by hand from the grammar or come from can-utils; runs
 * under ASan+UBSan.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "candump_hal.h"
#include "candump_log.h"

static const uint8_t fd_lens[] = { 0, 1, 2, 3, 4, 5, 6, 7, 8, 12, 16, 20, 24, 32, 48, 64 };
#define N_LENS (sizeof(fd_lens) / sizeof(fd_lens[0]))

static uint32_t rnd_state = 12345U;
static uint32_t rnd(void)
{
	rnd_state = rnd_state * 1103515245U + 12345U;
	return rnd_state >> 8;
}

/* "(1700000000.123456) can0 0A0##F" + len bytes 00 11 22 ... */
static void fd_line(char *buf, size_t size, const char *id, unsigned flags, unsigned len)
{
	unsigned i;
	int n = snprintf(buf, size, "(1700000000.123456) can0 %s##%X", id, flags);

	for (i = 0U; i < len; i++) {
		n += snprintf(buf + n, size - (size_t)n, "%02X", (unsigned)((i * 0x11U + 3U) & 0xFFU));
	}
}

static void parse_ok(const char *line, candump_frame_t *f)
{
	candump_err_t err = CANDUMP_ERR_COUNT;

	if (candump_parse_line(line, strlen(line), f, &err, NULL) != CANDUMP_LINE_FRAME) {
		fail_msg("'%s' not a frame: %s", line, candump_strerror(err));
	}
}

static void test_every_fd_length_and_flags_digit_round_trips(void **state)
{
	char line[256];
	char out[CANDUMP_FORMAT_MAX + 2U];
	candump_frame_t f;
	unsigned k;
	unsigned fl;
	unsigned i;

	(void)state;
	for (k = 0U; k < N_LENS; k++) {
		for (fl = 0U; fl < 16U; fl++) {
			fd_line(line, sizeof(line), (fl & 1U) ? "1ABCDEF0" : "0A0", fl, fd_lens[k]);
			parse_ok(line, &f);
			assert_int_equal(f.kind, CANDUMP_KIND_FD);
			assert_int_equal(f.len, fd_lens[k]);
			assert_int_equal(f.fd_flags, fl);
			assert_int_equal(f.ext, (fl & 1U) != 0U);
			assert_int_equal(f.id, (fl & 1U) ? 0x1ABCDEF0U : 0xA0U);
			for (i = 0U; i < f.len; i++) {
				assert_int_equal(f.data[i], (i * 0x11U + 3U) & 0xFFU);
			}
			assert_int_equal(candump_format_frame(&f, false, out, sizeof(out)),
					 (int)strlen(line));
			assert_string_equal(out, line);
		}
	}
}

static void test_lengths_without_a_dlc_code_are_malformed(void **state)
{
	char line[256];
	candump_frame_t f;
	candump_err_t err;
	unsigned len;

	(void)state;
	for (len = 9U; len <= 65U; len++) {
		if (hal_can_len_to_dlc((uint8_t)len) != 0xFFU) {
			continue;
		}
		fd_line(line, sizeof(line), "0A0", 5U, len);
		err = CANDUMP_OK;
		assert_int_equal(candump_parse_line(line, strlen(line), &f, &err, NULL),
				 CANDUMP_LINE_MALFORMED);
		assert_int_equal(err, (len > 64U) ? CANDUMP_ERR_DATA_LEN : CANDUMP_ERR_FD_LEN);
	}
	/* no flags digit, a remote FD frame, an error frame in FD form, _X */
	err = CANDUMP_OK;
	assert_int_equal(candump_parse_line("(1.000000) can0 0A0##", 21U, &f, &err, NULL),
			 CANDUMP_LINE_MALFORMED);
	assert_int_equal(err, CANDUMP_ERR_FD_FLAGS);
	assert_int_equal(candump_parse_line("(1.000000) can0 0A0##1R", 23U, &f, &err, NULL),
			 CANDUMP_LINE_MALFORMED);
	assert_int_equal(err, CANDUMP_ERR_DATA_HEX);
	assert_int_equal(candump_parse_line("(1.000000) can0 20000004##100", 29U, &f, &err, NULL),
			 CANDUMP_LINE_MALFORMED);
	assert_int_equal(err, CANDUMP_ERR_ERROR_FRAME);
	assert_int_equal(candump_parse_line("(1.000000) can0 0A0##10011223344556677_9", 40U, &f,
					    &err, NULL),
			 CANDUMP_LINE_MALFORMED);
	assert_int_equal(err, CANDUMP_ERR_DLC_CODE);
}

/* ##0..3 (older can-utils) and ##4..7 (FDF set) are the same HAL frame. */
static void test_both_flag_conventions_give_the_same_hal_frame(void **state)
{
	static const uint8_t want[4] = {
		HAL_CAN_FLAG_FDF, HAL_CAN_FLAG_FDF | HAL_CAN_FLAG_BRS,
		HAL_CAN_FLAG_FDF | HAL_CAN_FLAG_ESI,
		HAL_CAN_FLAG_FDF | HAL_CAN_FLAG_BRS | HAL_CAN_FLAG_ESI,
	};
	char line[256];
	candump_frame_t f;
	hal_can_frame_t h;
	unsigned fl;

	(void)state;
	for (fl = 0U; fl < 8U; fl++) {
		fd_line(line, sizeof(line), "12345678", fl, 8U);
		parse_ok(line, &f);
		assert_int_equal(candump_to_hal(&f, &h), SQ_OK);
		assert_int_equal(h.flags, want[fl & 3U] | HAL_CAN_FLAG_EXT);
		assert_int_equal(h.id, 0x12345678U);
		assert_int_equal(h.dlc, 8U);
		assert_int_equal(h.data[7], (7U * 0x11U + 3U) & 0xFFU);
	}
	/* a classic frame has no FD flag */
	parse_ok("(1.000000) can0 0A0#0102", &f);
	assert_int_equal(candump_to_hal(&f, &h), SQ_OK);
	assert_int_equal(h.flags, 0U);
	assert_int_equal(h.dlc, 2U);
}

/* Every FD length: a HAL frame where this build's HAL holds it, else
 * SQ_ENOTSUP (a classic-only build); XL never. */
static void test_fd_frames_longer_than_the_hal_frame_are_refused(void **state)
{
	char line[256];
	candump_frame_t f;
	hal_can_frame_t h;
	unsigned k;

	(void)state;
	for (k = 0U; k < N_LENS; k++) {
		fd_line(line, sizeof(line), "0A0", 1U, fd_lens[k]);
		parse_ok(line, &f);
		if (fd_lens[k] <= HAL_CAN_MAX_DLEN) {
			assert_int_equal(candump_to_hal(&f, &h), SQ_OK);
			assert_int_equal(h.dlc, fd_lens[k]);
			if (fd_lens[k] > 0U) {
				assert_memory_equal(h.data, f.data, fd_lens[k]);
			}
		} else {
			assert_int_equal(candump_to_hal(&f, &h), SQ_ENOTSUP);
			assert_int_equal(h.dlc, 0U);
		}
	}
	parse_ok("(1.000000) can0 45110#81:00:12345678#00112233", &f);
	assert_int_equal(candump_to_hal(&f, &h), SQ_ENOTSUP);
}

/* HAL -> log: the digit is FDF|BRS|ESI, as Debian 12's candump writes a
 * received FD frame (measured on vcan0 in the QEMU guest: kernel 6.1.0-57
 * sets FDF). */
static void test_hal_frames_are_written_as_debian_12_candump_writes_them(void **state)
{
	static const struct {
		uint8_t flags;
		uint32_t id;
		uint8_t dlc;
		const char *line;
	} cases[] = {
		{ HAL_CAN_FLAG_FDF, 0xA0U, 2U, "(1700000000.000001) can0 0A0##4A0A1" },
		{ HAL_CAN_FLAG_FDF | HAL_CAN_FLAG_BRS, 0xA0U, 2U, "(1700000000.000001) can0 0A0##5A0A1" },
		{ HAL_CAN_FLAG_FDF | HAL_CAN_FLAG_ESI | HAL_CAN_FLAG_EXT, 0x18DAF110U, 0U,
		  "(1700000000.000001) can0 18DAF110##6" },
		{ HAL_CAN_FLAG_FDF | HAL_CAN_FLAG_BRS | HAL_CAN_FLAG_ESI, 0x7FFU, 1U,
		  "(1700000000.000001) can0 7FF##7A0" },
		{ 0U, 0x110U, 2U, "(1700000000.000001) can0 110#A0A1" },
		{ HAL_CAN_FLAG_RTR, 0x110U, 4U, "(1700000000.000001) can0 110#R4" },
		{ HAL_CAN_FLAG_ERR, 0x4U, 1U, "(1700000000.000001) can0 20000004#A0" },
	};
	char out[CANDUMP_FORMAT_MAX + 2U];
	candump_frame_t f;
	candump_frame_t g;
	hal_can_frame_t h;
	hal_can_frame_t back;
	size_t i;

	(void)state;
	for (i = 0U; i < sizeof(cases) / sizeof(cases[0]); i++) {
		memset(&h, 0, sizeof(h));
		h.id = cases[i].id;
		h.flags = cases[i].flags;
		h.dlc = cases[i].dlc;
		h.data[0] = 0xA0U;
		h.data[1] = 0xA1U;
		candump_from_hal(&h, 1700000000000001000ULL, "can0", &f);
		assert_true(candump_format_frame(&f, false, out, sizeof(out)) > 0);
		assert_string_equal(out, cases[i].line);
		/* and back to the same HAL frame */
		parse_ok(out, &g);
		assert_int_equal(candump_to_hal(&g, &back), SQ_OK);
		assert_int_equal(back.flags, h.flags);
		assert_int_equal(back.id, h.id);
		assert_int_equal(back.dlc, h.dlc);
		if (((h.flags & HAL_CAN_FLAG_RTR) == 0U) && (h.dlc > 0U)) {
			assert_memory_equal(back.data, h.data, h.dlc);
		}
	}
}

/* ---- against can-utils ------------------------------------------------------ */

typedef struct {
	uint32_t id;
	int ext;
	unsigned flags; /* BRS 1, ESI 2 */
	unsigned len;
	uint8_t data[64];
	char text[CANDUMP_FORMAT_MAX + 2U]; /* the frame field we wrote */
} ref_frame_t;

#define N_REF (N_LENS * 4U * 2U)

static ref_frame_t refs[N_REF];

static int hex_digit(char c)
{
	return ((c >= '0') && (c <= '9')) ? (c - '0') : ((c >= 'A') && (c <= 'F')) ? (c - 'A' + 10) : -1;
}

static bool have_tool(const char *name)
{
	char cmd[128];

	(void)snprintf(cmd, sizeof(cmd), "command -v %s >/dev/null 2>&1", name);
	return system(cmd) == 0;
}

/* A log of FD frames of every length, flags 0..3, standard and extended,
 * random data, written by our writer from HAL frames; returns its path. */
static void write_ref_log(char *path, size_t size)
{
	char line[CANDUMP_FORMAT_MAX + 2U];
	candump_frame_t f;
	hal_can_frame_t h;
	FILE *fp;
	unsigned n = 0U;
	unsigned k;
	unsigned fl;
	unsigned e;
	int fd;

	(void)snprintf(path, size, "/tmp/test_candump_hal.XXXXXX");
	fd = mkstemp(path);
	assert_true(fd >= 0);
	fp = fdopen(fd, "w");
	assert_non_null(fp);
	for (k = 0U; k < N_LENS; k++) {
		for (fl = 0U; fl < 4U; fl++) {
			for (e = 0U; e < 2U; e++) {
				ref_frame_t *r = &refs[n];
				unsigned i;
				char *sp;

				r->ext = (int)e;
				r->id = e ? (rnd() & 0x1FFFFFFFU) : (rnd() & 0x7FFU);
				r->flags = fl;
				r->len = fd_lens[k];
				memset(&h, 0, sizeof(h));
				h.id = r->id;
				h.flags = (uint8_t)(HAL_CAN_FLAG_FDF | (e ? HAL_CAN_FLAG_EXT : 0U) |
						    ((fl & 1U) ? HAL_CAN_FLAG_BRS : 0U) |
						    ((fl & 2U) ? HAL_CAN_FLAG_ESI : 0U));
				for (i = 0U; i < r->len; i++) {
					r->data[i] = (uint8_t)rnd();
				}
				/* the HAL frame of this build holds at most HAL_CAN_MAX_DLEN:
				 * longer ones are written from the log frame directly */
				h.dlc = (uint8_t)((r->len <= HAL_CAN_MAX_DLEN) ? r->len : 0U);
				memcpy(h.data, r->data, h.dlc);
				candump_from_hal(&h, 1700000000000000000ULL + (uint64_t)n * 1000000ULL,
						 "can0", &f);
				f.len = (uint8_t)r->len;
				memcpy(f.data, r->data, r->len);
				assert_true(candump_format_frame(&f, true, line, sizeof(line)) > 0);
				assert_int_equal(fputs(line, fp) >= 0, 1);
				sp = strrchr(line, ' ');
				assert_non_null(sp);
				(void)snprintf(r->text, sizeof(r->text), "%s", sp + 1);
				r->text[strcspn(r->text, "\n")] = '\0';
				n++;
			}
		}
	}
	assert_int_equal(n, N_REF);
	assert_int_equal(fclose(fp), 0);
}

/* s: " XX XX ..." of a can-utils rendering, the frame's data */
static void expect_bytes(const char *s, const ref_frame_t *r)
{
	unsigned i;

	for (i = 0U; i < r->len; i++) {
		unsigned b;
		int m = 0;

		assert_int_equal(sscanf(s, " %2x%n", &b, &m), 1);
		assert_int_equal(b, r->data[i]);
		s += m;
	}
}

/* log2long: "(TS)  can0  ID  [LL]  XX XX ..." (then ASCII for <= 8 bytes) */
static void test_log2long_reads_our_fd_lines(void **state)
{
	char path[64];
	char cmd[160];
	char buf[1024];
	FILE *p;
	unsigned n = 0U;

	(void)state;
	if (!have_tool("log2long")) {
		skip();
	}
	write_ref_log(path, sizeof(path));
	(void)snprintf(cmd, sizeof(cmd), "log2long < %s", path);
	p = popen(cmd, "r");
	assert_non_null(p);
	while (fgets(buf, sizeof(buf), p) != NULL) {
		const ref_frame_t *r = &refs[n];
		char ts[64];
		char dev[32];
		char id[16];
		unsigned len = 999U;
		int used = 0;

		assert_true(n < N_REF);
		assert_int_equal(sscanf(buf, "%63s %31s %15s [%u]%n", ts, dev, id, &len, &used), 4);
		assert_string_equal(dev, "can0");
		assert_int_equal(strtoul(id, NULL, 16), r->id);
		assert_int_equal(strlen(id), r->ext ? 8U : 3U);
		assert_int_equal(len, r->len);
		expect_bytes(buf + used, r);
		n++;
	}
	assert_int_equal(pclose(p), 0);
	assert_int_equal(n, N_REF);
	(void)unlink(path);
}

/* log2asc: "T CANFD 1 Rx ID[x] BRS ESI DLC LEN DATA... " and, rewritten by
 * asc2log (can-utils' own candump writer), our frame text byte for byte. */
static void test_log2asc_and_asc2log_agree_with_our_fd_lines(void **state)
{
	char path[64];
	char asc[80];
	char cmd[256];
	char buf[1024];
	FILE *p;
	unsigned n = 0U;

	(void)state;
	if (!have_tool("log2asc") || !have_tool("asc2log")) {
		skip();
	}
	write_ref_log(path, sizeof(path));
	(void)snprintf(asc, sizeof(asc), "%s.asc", path);
	(void)snprintf(cmd, sizeof(cmd), "log2asc -I %s -O %s can0", path, asc);
	assert_int_equal(system(cmd), 0);
	(void)snprintf(cmd, sizeof(cmd), "grep CANFD %s", asc);
	p = popen(cmd, "r");
	assert_non_null(p);
	while (fgets(buf, sizeof(buf), p) != NULL) {
		const ref_frame_t *r = &refs[n];
		double t;
		unsigned ch;
		char dir[8];
		char id[16];
		unsigned brs;
		unsigned esi;
		unsigned dlc;
		unsigned len;
		int used = 0;

		assert_true(n < N_REF);
		assert_int_equal(sscanf(buf, "%lf CANFD %u %7s %15s %u %u %x %u%n", &t, &ch, dir, id,
					&brs, &esi, &dlc, &len, &used), 8);
		assert_int_equal(strtoul(id, NULL, 16), r->id);
		assert_int_equal(id[strlen(id) - 1U] == 'x', r->ext);
		assert_int_equal(brs, r->flags & 1U);
		assert_int_equal(esi, (r->flags >> 1) & 1U);
		assert_int_equal(hal_can_dlc_to_len((uint8_t)dlc), r->len);
		assert_int_equal(len, r->len);
		expect_bytes(buf + used, r);
		n++;
	}
	assert_int_equal(pclose(p), 0);
	assert_int_equal(n, N_REF);
	/* can-utils' writer: "(TS) can0 FRAME R"; the FRAME field is ours */
	(void)snprintf(cmd, sizeof(cmd), "asc2log -I %s 2>/dev/null", asc);
	p = popen(cmd, "r");
	assert_non_null(p);
	n = 0U;
	while (fgets(buf, sizeof(buf), p) != NULL) {
		char ts[64];
		char dev[32];
		char frame[512];

		if (buf[0] != '(') {
			continue;
		}
		assert_true(n < N_REF);
		assert_int_equal(sscanf(buf, "%63s %31s %200s", ts, dev, frame), 3);
		/* asc2log knows no FDF (the ASC format has BRS and ESI only): it
		 * writes the older convention, digit & 3; all else is the same */
		{
			char *hh = strstr(frame, "##");
			char want[sizeof(refs[0].text)];
			char *wh;

			(void)snprintf(want, sizeof(want), "%s", refs[n].text);
			wh = strstr(want, "##");
			assert_non_null(hh);
			assert_non_null(wh);
			assert_int_equal(wh[2], "4567"[hex_digit(hh[2]) & 3]);
			wh[2] = hh[2];
			assert_string_equal(frame, want);
		}
		n++;
	}
	assert_int_equal(pclose(p), 0);
	assert_int_equal(n, N_REF);
	(void)unlink(asc);
	(void)unlink(path);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_every_fd_length_and_flags_digit_round_trips),
		cmocka_unit_test(test_lengths_without_a_dlc_code_are_malformed),
		cmocka_unit_test(test_both_flag_conventions_give_the_same_hal_frame),
		cmocka_unit_test(test_fd_frames_longer_than_the_hal_frame_are_refused),
		cmocka_unit_test(test_hal_frames_are_written_as_debian_12_candump_writes_them),
		cmocka_unit_test(test_log2long_reads_our_fd_lines),
		cmocka_unit_test(test_log2asc_and_asc2log_agree_with_our_fd_lines),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
