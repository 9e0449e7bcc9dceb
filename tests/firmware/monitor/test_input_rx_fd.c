/* SPDX-License-Identifier: MIT */
/*
 * The input stage on CAN FD messages (input_rx.c, calib_map.c):
 *   - calib_input_check() refuses impossible FD configurations with a
 *     reason (fd = no with min_dlc > 8 or a signal beyond byte 8, a length
 *     no DLC code has, a signal beyond min_dlc, P05's header beyond
 *     min_dlc, P01/P02 on an FD message);
 *   - input_rx_judge(): a frame of the wrong format (classic where fd =
 *     yes and FD where fd = no) or shorter than min_dlc is the dlc verdict;
 *     a wrong P05 CRC the crc verdict, a counter jump the counter verdict.
 * Frames are protected with the CRC-16/CCITT-FALSE computed here bitwise
 * from its definition (poly 0x1021, init 0xFFFF), not with e2e_p05.c.
 * Frames longer than this build's HAL_CAN_MAX_DLEN cannot exist here; those
 * cases run where the host backend carries 64 bytes.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "calib_map.h"
#include "input_rx.h"
#include "sq_status.h"

static uint16_t ref_crc16(const uint8_t *d, size_t n, uint16_t c)
{
	for (size_t i = 0; i < n; i++) {
		c = (uint16_t)(c ^ ((uint32_t)d[i] << 8));
		for (int k = 0; k < 8; k++) {
			c = ((c & 0x8000U) != 0U) ? (uint16_t)(((uint32_t)c << 1) ^ 0x1021U) :
				(uint16_t)((uint32_t)c << 1);
		}
	}
	return c;
}

/* P05 by its definition: CRC over bytes but off, off+1, then ID lo, hi. */
static void ref_p05(uint8_t *d, uint8_t len, uint8_t off, uint16_t id, uint8_t counter)
{
	const uint8_t idb[2] = { (uint8_t)(id & 0xFFU), (uint8_t)(id >> 8) };
	uint16_t c;

	d[off + 2] = counter;
	c = ref_crc16(d, off, 0xFFFFU);
	c = ref_crc16(&d[off + 2], (size_t)len - off - 2U, c);
	c = ref_crc16(idb, 2U, c);
	d[off] = (uint8_t)(c & 0xFFU);
	d[off + 1] = (uint8_t)(c >> 8);
}

/* A speed at byte 4..5 of an FD message of 8 bytes, P05 at offset 1. */
static calib_input_t fd_input(void)
{
	calib_input_t in;

	memset(&in, 0, sizeof(in));
	in.id = 0x0A0U;
	in.fd = 1U;
	in.min_dlc = 8U;
	in.sig = (can_signal_t){ 32U, 16U, (uint8_t)CAN_SIGNAL_INTEL, 0U };
	in.factor = (calib_dec_t){ 1, -2 };
	in.unit = (uint8_t)INPUT_UNIT_RADPS;
	in.protection = (uint8_t)CALIB_PROT_P05;
	in.data_id = 0xF8A0U;
	in.e2e_offset_byte = 1U;
	in.max_delta_counter = 1U;
	in.period_ms = 10U;
	in.stale_cycles = 3U;
	in.max = (calib_dec_t){ 400, 0 };
	in.step_max = (calib_dec_t){ 655, 0 };
	return in;
}

static const char *why_of(const calib_input_t *in)
{
	const char *why = NULL;

	return (calib_input_check(in, &why) == SQ_OK) ? "ok" : why;
}

static void test_fd_configs_refused(void **state)
{
	calib_input_t in = fd_input();

	(void)state;
	assert_string_equal(why_of(&in), "ok");
	/* classic message with more than 8 bytes */
	in.fd = 0U;
	in.min_dlc = 12U;
	assert_string_equal(why_of(&in), "min_dlc above 8 needs fd = yes (a classic frame has at most 8 bytes)");
	/* classic message, value beyond byte 8 */
	in.min_dlc = 8U;
	in.sig.start_bit = 64U;
	assert_string_equal(why_of(&in),
			    "start_bit: the value runs beyond the 8 bytes of a classic frame (an FD message needs fd = yes)");
	/* no DLC code has 13 bytes */
	in = fd_input();
	in.min_dlc = 13U;
	assert_string_equal(why_of(&in), "min_dlc: above 8 an FD frame has 12, 16, 20, 24, 32, 48 or 64 bytes");
	in.min_dlc = 65U;
	assert_string_equal(why_of(&in), "min_dlc: above 8 an FD frame has 12, 16, 20, 24, 32, 48 or 64 bytes");
	/* a signal beyond min_dlc: bits 200..215 need 27 bytes */
	in.min_dlc = 24U;
	in.sig.start_bit = 200U;
	assert_string_equal(why_of(&in), "a signal beyond min_dlc");
	in.min_dlc = 32U;
	assert_string_equal(why_of(&in), "ok");
	/* P05 header (offset 22: bytes 22..24) beyond min_dlc 24 */
	in = fd_input();
	in.min_dlc = 24U;
	in.e2e_offset_byte = 22U;
	assert_string_equal(why_of(&in),
			    "e2e_offset_byte: the P05 CRC and counter (3 bytes from it) run beyond min_dlc");
	in.e2e_offset_byte = 21U;
	assert_string_equal(why_of(&in), "ok");
	/* the value inside the P05 header */
	in.e2e_offset_byte = 4U;
	assert_string_equal(why_of(&in), "signal overlaps the P05 CRC or counter (e2e_offset_byte .. +2)");
	/* P01 / P02 protect classic frames only */
	in = fd_input();
	in.protection = (uint8_t)CALIB_PROT_P01;
	in.data_id = 1U;
	assert_string_equal(why_of(&in),
			    "protection p01 and p02 protect classic frames: fd = yes needs p05, counter or none");
	/* P05 on a classic frame is fine */
	in = fd_input();
	in.fd = 0U;
	assert_string_equal(why_of(&in), "ok");
	in.max_delta_counter = 0U;
	assert_string_equal(why_of(&in), "max_delta_counter out of range (p05 1..255)");
}

/* The default min_dlc of an FD message: the next FD length. */
static void test_frame_len(void **state)
{
	calib_input_t in = fd_input();

	(void)state;
	in.sig.start_bit = 64U;     /* bits 64..79: 10 bytes */
	assert_int_equal(calib_input_needed_dlc(&in), 10);
	assert_int_equal(calib_input_frame_len(&in), 12);
	in.sig.start_bit = 400U;    /* 51 bytes */
	assert_int_equal(calib_input_frame_len(&in), 64);
	in.sig.start_bit = 32U;     /* 6 bytes: classic lengths as they are */
	assert_int_equal(calib_input_frame_len(&in), 6);
	in.fd = 0U;
	in.sig.start_bit = 64U;
	assert_int_equal(calib_input_frame_len(&in), 10); /* refused by the check */
}

static void setup_rx(const calib_input_t *in, input_rx_cfg_t *cfg, input_rx_state_t *st)
{
	const input_geom_t g = { 120000U, 300000U, 0U, 1000000U, 1000000U };

	assert_int_equal(input_rx_setup(in, &g, cfg), SQ_OK);
	input_rx_state_init(st);
}

static hal_can_frame_t frame(uint8_t flags, uint8_t len, uint8_t counter, uint16_t raw)
{
	hal_can_frame_t f;

	memset(&f, 0, sizeof(f));
	f.id = 0x0A0U;
	f.flags = flags;
	f.dlc = len;
	f.data[4] = (uint8_t)(raw & 0xFFU);
	f.data[5] = (uint8_t)(raw >> 8);
	ref_p05(f.data, len, 1U, 0xF8A0U, counter);
	return f;
}

static void test_verdicts_fd_message(void **state)
{
	const calib_input_t in = fd_input();
	input_rx_cfg_t cfg;
	input_rx_state_t st;
	hal_can_frame_t f;
	input_rx_result_t r;
	bool id_only = true;

	(void)state;
	setup_rx(&in, &cfg, &st);
	f = frame(HAL_CAN_FLAG_FDF, 8U, 0U, 1234U);
	assert_true(input_rx_matches(&cfg, &f, &id_only));
	r = input_rx_judge(&cfg, &st, &f);
	assert_int_equal(r.reason, INPUT_RX_OK);
	assert_int_equal(r.e2e_status, E2E_P01_STATUS_INITIAL);
	assert_int_equal(r.raw, 1234);
	/* the same bytes as a classic frame: wrong format = the dlc verdict,
	 * and it still matches (counted as this input's dlc, not id_only) */
	f = frame(0U, 8U, 1U, 1240U);
	assert_true(input_rx_matches(&cfg, &f, &id_only));
	assert_false(id_only);
	r = input_rx_judge(&cfg, &st, &f);
	assert_int_equal(r.reason, INPUT_RX_DLC);
	assert_int_equal(r.e2e_status, E2E_P01_STATUS_WRONGCRC);
	/* FD but shorter than min_dlc */
	f = frame(HAL_CAN_FLAG_FDF | HAL_CAN_FLAG_BRS, 7U, 1U, 1240U);
	r = input_rx_judge(&cfg, &st, &f);
	assert_int_equal(r.reason, INPUT_RX_DLC);
	/* a flipped data bit: crc */
	f = frame(HAL_CAN_FLAG_FDF, 8U, 1U, 1240U);
	f.data[6] ^= 0x10U;
	r = input_rx_judge(&cfg, &st, &f);
	assert_int_equal(r.reason, INPUT_RX_CRC);
	/* counter 1 after three failed cycles: OKSOMELOST? no: delta 1 -> OK */
	f = frame(HAL_CAN_FLAG_FDF, 8U, 1U, 1240U);
	r = input_rx_judge(&cfg, &st, &f);
	assert_int_equal(r.reason, INPUT_RX_OK);
	assert_int_equal(r.e2e_status, E2E_P01_STATUS_OK);
	/* repeated counter */
	r = input_rx_judge(&cfg, &st, &f);
	assert_int_equal(r.reason, INPUT_RX_REPEATED);
	/* counter jump 1 -> 100 beyond the tolerated jump: counter */
	f = frame(HAL_CAN_FLAG_FDF, 8U, 100U, 1240U);
	r = input_rx_judge(&cfg, &st, &f);
	assert_int_equal(r.reason, INPUT_RX_COUNTER);
	assert_int_equal(st.e2e.status_count[E2E_P01_STATUS_WRONGCRC], 3);
}

/* A classic message: an FD frame with its id is of the wrong format. */
static void test_verdicts_classic_message(void **state)
{
	calib_input_t in = fd_input();
	input_rx_cfg_t cfg;
	input_rx_state_t st;
	hal_can_frame_t f;
	input_rx_result_t r;

	(void)state;
	in.fd = 0U;
	setup_rx(&in, &cfg, &st);
	f = frame(0U, 8U, 0U, 100U);
	assert_int_equal(input_rx_judge(&cfg, &st, &f).reason, INPUT_RX_OK);
	f = frame(HAL_CAN_FLAG_FDF, 8U, 1U, 100U);
	r = input_rx_judge(&cfg, &st, &f);
	assert_int_equal(r.reason, INPUT_RX_DLC);
	f = frame(0U, 8U, 1U, 100U);
	assert_int_equal(input_rx_judge(&cfg, &st, &f).reason, INPUT_RX_OK);
}

/* A frame whose length field exceeds this build's buffer is never read. */
static void test_length_beyond_buffer(void **state)
{
	const calib_input_t in = fd_input();
	input_rx_cfg_t cfg;
	input_rx_state_t st;
	hal_can_frame_t f;

	(void)state;
	setup_rx(&in, &cfg, &st);
	f = frame(HAL_CAN_FLAG_FDF, 8U, 0U, 100U);
	f.dlc = (uint8_t)(HAL_CAN_MAX_DLEN + 1U);
	assert_int_equal(input_rx_judge(&cfg, &st, &f).reason, INPUT_RX_DLC);
	f.dlc = 200U;
	assert_int_equal(input_rx_judge(&cfg, &st, &f).reason, INPUT_RX_DLC);
}

#if HAL_CAN_MAX_DLEN >= 24U
/* 24 bytes: a speed at bit 64, P05 at offset 0; 20 bytes is too short. */
static void test_verdicts_24_bytes(void **state)
{
	calib_input_t in = fd_input();
	input_rx_cfg_t cfg;
	input_rx_state_t st;
	hal_can_frame_t f;
	input_rx_result_t r;
	uint8_t c;

	(void)state;
	in.min_dlc = 24U;
	in.sig.start_bit = 64U;
	in.e2e_offset_byte = 0U;
	setup_rx(&in, &cfg, &st);
	for (c = 0U; c < 3U; c++) {
		memset(&f, 0, sizeof(f));
		f.id = 0x0A0U;
		f.flags = HAL_CAN_FLAG_FDF;
		f.dlc = 24U;
		f.data[8] = 0x40U;
		f.data[9] = 0x06U; /* 1600 */
		f.data[23] = c;    /* covered by the CRC */
		ref_p05(f.data, 24U, 0U, 0xF8A0U, c);
		r = input_rx_judge(&cfg, &st, &f);
		assert_int_equal(r.reason, INPUT_RX_OK);
		assert_int_equal(r.raw, 1600);
	}
	f.dlc = 20U;
	assert_int_equal(input_rx_judge(&cfg, &st, &f).reason, INPUT_RX_DLC);
	f.dlc = 24U;
	f.data[23] ^= 1U;
	assert_int_equal(input_rx_judge(&cfg, &st, &f).reason, INPUT_RX_CRC);
}
#endif

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_fd_configs_refused),
		cmocka_unit_test(test_frame_len),
		cmocka_unit_test(test_verdicts_fd_message),
		cmocka_unit_test(test_verdicts_classic_message),
		cmocka_unit_test(test_length_beyond_buffer),
#if HAL_CAN_MAX_DLEN >= 24U
		cmocka_unit_test(test_verdicts_24_bytes),
#endif
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
