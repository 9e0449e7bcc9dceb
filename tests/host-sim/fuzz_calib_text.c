/* SPDX-License-Identifier: MIT */
/*
 * fuzz_calib_text: the calibration text parser (host-sim/calib_text.c,
 * `squeal-sim ecu --calib FILE`) on arbitrary file contents.
 *
 * Properties:
 *   - calib_text_parse() returns SQ_OK or SQ_EBADMSG (SQ_EIO cannot happen
 *     on a memory stream); on failure *out is untouched and the message is
 *     a NUL-terminated string inside the given buffer, whatever its size
 *     (the error buffer is an exactly-sized heap block: ASan checks);
 *   - an accepted file gives a calibration that validates, whose stored
 *     block encodes, and whose calib_text_write() output parses back to the
 *     identical block (the writer's "shortest form that parses back");
 *   - an accepted file sets up: every corner's inputs through
 *     input_rx_setup() (as calib_corner_view() gives them) and every
 *     corner's monitor (monitor_init_corner() keeps the calibration, no
 *     fall-back to the factory defaults). Built for both numeric builds
 *     (fuzz_calib_text, fuzz_calib_text_fixed).
 */
#include "fuzz_common.h"

#include "calib.h"
#include "calib_map.h"
#include "calib_text.h"
#include "input_rx.h"
#include "monitor.h"
#include "sq_status.h"

/* What validates sets up: the monitor's path for every corner. */
static void check_sets_up(const calib_t *cal)
{
	static monitor_t mon;
	uint32_t k;

	for (k = 0U; k < calib_corner_count(cal); k++) {
		calib_corner_t c;
		calib_input_t sp;
		calib_input_t fo;
		input_rx_cfg_t rx;
		input_geom_t g;

		FUZZ_REQUIRE(calib_corner_view(cal, k, &c, &sp, &fo) == SQ_OK);
		g = calib_corner_geom(&c);
		FUZZ_REQUIRE(input_rx_setup(&sp, &g, &rx) == SQ_OK);
		FUZZ_REQUIRE(input_rx_setup(&fo, &g, &rx) == SQ_OK);
		FUZZ_REQUIRE(monitor_init_corner(&mon, cal, k, false, 0U, 0U) == SQ_OK);
		FUZZ_REQUIRE(mon.cal == cal);
	}
}

static void check_roundtrip(const calib_t *cal)
{
	uint8_t blk1[CALIB_BLOCK_LEN];
	uint8_t blk2[CALIB_BLOCK_LEN];
	char *text = NULL;
	size_t text_len = 0U;
	FILE *w;
	FILE *r;
	calib_t back;
	char err[256];

	FUZZ_REQUIRE(calib_validate(cal) == SQ_OK);
	FUZZ_REQUIRE(calib_encode(cal, blk1, sizeof(blk1)) == SQ_OK);
	w = open_memstream(&text, &text_len);
	FUZZ_REQUIRE(w != NULL);
	FUZZ_REQUIRE(calib_text_write(w, cal) == SQ_OK);
	FUZZ_REQUIRE(fclose(w) == 0);
	r = fmemopen(text, text_len, "r");
	FUZZ_REQUIRE(r != NULL);
	err[0] = '\0';
	if (calib_text_parse(r, "written", &back, err, sizeof(err)) != SQ_OK) {
		(void)fprintf(stderr, "re-parse failed: %s\n---\n%s---\n", err, text);
		FUZZ_REQUIRE(0);
	}
	(void)fclose(r);
	free(text);
	FUZZ_REQUIRE(calib_encode(&back, blk2, sizeof(blk2)) == SQ_OK);
	FUZZ_REQUIRE(memcmp(blk1, blk2, sizeof(blk1)) == 0);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	FILE *f;
	calib_t cal;
	calib_t sentinel;
	char *err;
	size_t errlen;
	int rc;

	if (size == 0U) {
		return 0;
	}
	/* the last byte picks the error buffer's size (1..64) */
	errlen = 1U + (size_t)(data[size - 1U] % 64U);
	err = malloc(errlen);
	if (err == NULL) {
		return 0;
	}
	memset(err, 'x', errlen);
	f = fmemopen((void *)(uintptr_t)data, size, "r");
	if (f == NULL) {
		free(err);
		return 0;
	}
	memset(&sentinel, 0x5C, sizeof(sentinel));
	cal = sentinel;
	rc = calib_text_parse(f, "fuzz", &cal, err, errlen);
	(void)fclose(f);
	FUZZ_REQUIRE((rc == SQ_OK) || (rc == SQ_EBADMSG));
	if (rc != SQ_OK) {
		FUZZ_REQUIRE(memcmp(&cal, &sentinel, sizeof(cal)) == 0);
		FUZZ_REQUIRE(memchr(err, '\0', errlen) != NULL);
	} else {
		check_roundtrip(&cal);
		check_sets_up(&cal);
	}
	free(err);
	return 0;
}
