/* SPDX-License-Identifier: MIT */
/*
 * fuzz_candump: the candump -L log parser (host-sim/candump_log.c) on
 * arbitrary bytes, one line at a time and through the streaming reader.
 *
 * Properties:
 *   - candump_parse_line() reads only the len bytes it is given (the
 *     fuzzer's buffer is exactly that long: ASan checks), returns one of
 *     the five line kinds, an error code only for MALFORMED (with a column
 *     inside the line and a description);
 *   - a parsed frame is well-formed: interface 1..15 characters and
 *     NUL-terminated, identifier in range for its length, a data length
 *     allowed for its kind (classic/RTR 0..8, FD one of the FD lengths),
 *     a DLC code only with 8 bytes;
 *   - round trip: every parsed frame except CAN XL is written by
 *     candump_format_frame() (within CANDUMP_FORMAT_MAX), parses back to
 *     the same frame (time truncated to microseconds), and writing that
 *     again gives the same text;
 *   - the reader splits any byte stream into lines of at most
 *     CANDUMP_LINE_MAX bytes, and ends.
 */
#include "fuzz_common.h"

#include <stdbool.h>

#include "candump_log.h"

static const uint8_t fd_lens[] = { 0, 1, 2, 3, 4, 5, 6, 7, 8, 12, 16, 20, 24, 32, 48, 64 };

static bool fd_len_ok(uint8_t len)
{
	size_t i;

	for (i = 0U; i < sizeof(fd_lens); i++) {
		if (fd_lens[i] == len) {
			return true;
		}
	}
	return false;
}

static void check_frame(const candump_frame_t *f)
{
	const size_t ilen = strnlen(f->iface, sizeof(f->iface));

	FUZZ_REQUIRE((ilen >= 1U) && (ilen <= CANDUMP_IFACE_MAX));
	FUZZ_REQUIRE((f->dir == 0) || (f->dir == 'T') || (f->dir == 'R'));
	switch (f->kind) {
	case CANDUMP_KIND_CLASSIC:
	case CANDUMP_KIND_RTR:
		FUZZ_REQUIRE(f->len <= 8U);
		FUZZ_REQUIRE(f->id <= (f->ext ? CANDUMP_EFF_MAX : CANDUMP_SFF_MAX));
		FUZZ_REQUIRE((f->len8_dlc == 0U) ||
			     ((f->len == 8U) && (f->len8_dlc >= 9U) && (f->len8_dlc <= 15U)));
		break;
	case CANDUMP_KIND_FD:
		FUZZ_REQUIRE(fd_len_ok(f->len));
		FUZZ_REQUIRE(f->fd_flags <= 0x0FU);
		FUZZ_REQUIRE(f->id <= (f->ext ? CANDUMP_EFF_MAX : CANDUMP_SFF_MAX));
		break;
	case CANDUMP_KIND_ERROR:
		FUZZ_REQUIRE(f->len <= 8U);
		FUZZ_REQUIRE(f->id <= CANDUMP_ERR_MASK);
		break;
	case CANDUMP_KIND_XL:
		FUZZ_REQUIRE(f->xl_len <= CANDUMP_XL_DATA_MAX);
		break;
	default:
		FUZZ_REQUIRE(0);
	}
}

static void same_frame(const candump_frame_t *a, const candump_frame_t *b)
{
	FUZZ_REQUIRE(a->t_ns / 1000U == b->t_ns / 1000U);
	FUZZ_REQUIRE(strcmp(a->iface, b->iface) == 0);
	FUZZ_REQUIRE(a->kind == b->kind);
	FUZZ_REQUIRE(a->id == b->id);
	FUZZ_REQUIRE(a->ext == b->ext);
	FUZZ_REQUIRE(a->len == b->len);
	FUZZ_REQUIRE(a->len8_dlc == b->len8_dlc);
	FUZZ_REQUIRE(a->dir == b->dir);
	if (a->kind == CANDUMP_KIND_FD) {
		FUZZ_REQUIRE(a->fd_flags == b->fd_flags);
	}
	if (a->kind != CANDUMP_KIND_RTR) {
		FUZZ_REQUIRE(memcmp(a->data, b->data, a->len) == 0);
	}
}

static void check_line(const char *line, size_t len)
{
	candump_frame_t f;
	candump_frame_t g;
	candump_err_t err = CANDUMP_ERR_COUNT;
	size_t col = (size_t)-1;
	candump_line_t kind;
	char text[CANDUMP_FORMAT_MAX + 1U];
	char text2[CANDUMP_FORMAT_MAX + 1U];
	int n;
	int n2;

	memset(&f, 0, sizeof(f));
	kind = candump_parse_line(line, len, &f, &err, &col);
	FUZZ_REQUIRE((unsigned int)kind <= (unsigned int)CANDUMP_LINE_MALFORMED);
	FUZZ_REQUIRE((unsigned int)err < (unsigned int)CANDUMP_ERR_COUNT);
	FUZZ_REQUIRE((err == CANDUMP_OK) == (kind != CANDUMP_LINE_MALFORMED));
	FUZZ_REQUIRE(candump_strerror(err) != NULL);
	if (kind == CANDUMP_LINE_MALFORMED) {
		FUZZ_REQUIRE(col <= len);
		return;
	}
	FUZZ_REQUIRE(col == 0U);
	if (kind != CANDUMP_LINE_FRAME) {
		return;
	}
	check_frame(&f);
	if (f.kind == CANDUMP_KIND_XL) {
		return;
	}
	n = candump_format_frame(&f, false, text, sizeof(text));
	FUZZ_REQUIRE((n > 0) && ((size_t)n <= CANDUMP_FORMAT_MAX));
	FUZZ_REQUIRE(strlen(text) == (size_t)n);
	memset(&g, 0, sizeof(g));
	FUZZ_REQUIRE(candump_parse_line(text, (size_t)n, &g, &err, &col) == CANDUMP_LINE_FRAME);
	same_frame(&f, &g);
	n2 = candump_format_frame(&g, false, text2, sizeof(text2));
	FUZZ_REQUIRE((n2 == n) && (memcmp(text, text2, (size_t)n) == 0));
	/* a buffer one byte too short is refused, not overrun */
	FUZZ_REQUIRE(candump_format_frame(&f, false, text2, (size_t)n) == -1);
}

static candump_reader_t reader;

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	FILE *mf;
	const char *line;
	size_t len;
	bool too_long;
	int rc;
	uint32_t lines = 0U;

	check_line((const char *)data, size);

	if (size == 0U) {
		return 0;
	}
	mf = fmemopen((void *)(uintptr_t)data, size, "rb");
	if (mf == NULL) {
		return 0;
	}
	candump_reader_init(&reader, mf);
	while ((rc = candump_reader_next(&reader, &line, &len, &too_long)) == 1) {
		FUZZ_REQUIRE(len <= CANDUMP_LINE_MAX);
		FUZZ_REQUIRE(lines <= size);
		check_line(line, len);
		lines++;
	}
	FUZZ_REQUIRE(rc == 0);
	(void)fclose(mf);
	return 0;
}
