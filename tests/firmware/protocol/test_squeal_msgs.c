/* SPDX-License-Identifier: MIT */
/*
 * Unit tests of firmware/protocol: CRC-8 (P01), E2E P01 1A protect/check,
 * pack/unpack of every message in squeal.dbc.
 *
 * Expected bytes are literals derived outside the code under test: the CRCs
 * were computed by an independent bitwise CRC in Python (poly 0x1D, start 0,
 * no final XOR, over data ID low, data ID high, bytes 1..n-1), the layouts
 * by packing the raw values into a little-endian integer in Python. The
 * DBC <-> C agreement itself is proven by tests/protocol/.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "crc8_p01.h"
#include "e2e_p01.h"
#include "sq_status.h"
#include "squeal_msgs.h"

/* ---- CRC ----------------------------------------------------------------- */

static const uint8_t check_string[9] = { '1', '2', '3', '4', '5', '6', '7', '8', '9' };

/* Reference: the CRC's definition, one bit at a time. */
static uint8_t ref_crc8(const uint8_t *d, size_t n, uint8_t init, uint8_t xorout)
{
	uint8_t c = init;

	for (size_t i = 0; i < n; i++) {
		c ^= d[i];
		for (int k = 0; k < 8; k++) {
			c = (uint8_t)((c & 0x80U) != 0U ? (((unsigned int)c << 1) ^ 0x1DU) : ((unsigned int)c << 1));
		}
	}
	return (uint8_t)(c ^ xorout);
}

static void test_crc8_p01_check_value_is_0x37(void **state)
{
	(void)state;
	assert_int_equal(crc8_p01(check_string, sizeof(check_string)), 0x37);
	assert_int_equal(CRC8_P01_CHECK, 0x37);
}

static void test_crc8_sae_j1850_check_value_is_0x4b(void **state)
{
	(void)state;
	assert_int_equal(crc8_sae_j1850(check_string, sizeof(check_string)), 0x4B);
	/* and the two variants really differ, so the tests tell them apart */
	assert_int_not_equal(crc8_p01(check_string, 9), crc8_sae_j1850(check_string, 9));
}

static void test_crc8_table_matches_bitwise_definition(void **state)
{
	uint8_t buf[64];

	(void)state;
	for (unsigned int b = 0; b < 256U; b++) {
		uint8_t one = (uint8_t)b;

		assert_int_equal(crc8_p01(&one, 1), ref_crc8(&one, 1, 0x00, 0x00));
		assert_int_equal(crc8_sae_j1850(&one, 1), ref_crc8(&one, 1, 0xFF, 0xFF));
	}
	for (size_t i = 0; i < sizeof(buf); i++) {
		buf[i] = (uint8_t)(i * 37U + 11U);
	}
	for (size_t n = 0; n <= sizeof(buf); n++) {
		assert_int_equal(crc8_p01(buf, n), ref_crc8(buf, n, 0x00, 0x00));
	}
	/* update() continues a register: split anywhere gives the same */
	assert_int_equal(crc8_p01_update(crc8_p01(buf, 10), &buf[10], 20),
			 crc8_p01(buf, 30));
}

static void test_crc8_empty_and_null(void **state)
{
	(void)state;
	assert_int_equal(crc8_p01(NULL, 0), 0x00);
	expect_assert_failure(crc8_p01(NULL, 5)); /* contract: NULL with data */
	assert_int_equal(crc8_sae_j1850(check_string, 0), 0x00); /* 0xFF ^ 0xFF */
}

/* ---- E2E protect --------------------------------------------------------- */

static const e2e_p01_config_t cfg_ds = { MSG_DISC_SPEED_DATA_ID, MSG_DISC_SPEED_DLC, 1 };
static const e2e_p01_config_t cfg_pf = { MSG_PAD_FORCE_DATA_ID, MSG_PAD_FORCE_DLC, 1 };
static const e2e_p01_config_t cfg_st = { MSG_SQUEAL_STATUS_DATA_ID, MSG_SQUEAL_STATUS_DLC, 1 };

/* DiscSpeed_radps = 123.45 rad/s (raw 12345) with counter c: bytes 1..3 are
 * c, 0x39, 0x30; CRC over 51 2C c 39 30 (Python, see file header). */
static const uint8_t ds_crc_by_counter[15] = {
	0x1E, 0x91, 0x1D, 0x92, 0x18, 0x97, 0x1B, 0x94,
	0x12, 0x9D, 0x11, 0x9E, 0x14, 0x9B, 0x17,
};

static void ds_frame(uint8_t counter, uint8_t f[4])
{
	f[0] = ds_crc_by_counter[counter % 15U];
	f[1] = counter;
	f[2] = 0x39;
	f[3] = 0x30;
}

static void test_e2e_protect_disc_speed_matches_hand_derived_frame(void **state)
{
	static const uint8_t expect[4] = { 0x1E, 0x00, 0x39, 0x30 };
	msg_disc_speed_t m = { .disc_speed_radps = 12345 };
	e2e_p01_tx_t tx;
	uint8_t d[8];
	uint8_t dlc = 0;

	(void)state;
	e2e_p01_tx_init(&tx);
	assert_int_equal(msg_disc_speed_pack(&m, d, &dlc), SQ_OK);
	assert_int_equal(dlc, 4);
	assert_int_equal(e2e_p01_protect(&cfg_ds, &tx, d, dlc), SQ_OK);
	assert_memory_equal(d, expect, 4);
	assert_int_equal(tx.counter, 1);
}

static void test_e2e_protect_pad_force_counter_14_then_wraps_to_0(void **state)
{
	/* 9000 N = raw 18000 = 0x4650, counter 14: CRC over 52 2C 0E 50 46 */
	static const uint8_t expect[4] = { 0x37, 0x0E, 0x50, 0x46 };
	msg_pad_force_t m = { .pad_force_n = 18000 };
	e2e_p01_tx_t tx = { 14 };
	uint8_t d[8];
	uint8_t dlc = 0;

	(void)state;
	assert_int_equal(msg_pad_force_pack(&m, d, &dlc), SQ_OK);
	assert_int_equal(e2e_p01_protect(&cfg_pf, &tx, d, dlc), SQ_OK);
	assert_memory_equal(d, expect, 4);
	assert_int_equal(tx.counter, 0); /* 14 -> 0, never 15 */
}

static void test_e2e_protect_squeal_status_matches_hand_derived_frame(void **state)
{
	/* unstable, critical, basin n/a, margin -1.23 m/s (raw -123), counter 7;
	 * CRC over 01 3A 27 03 FF FF 85 FF 00 */
	static const uint8_t expect[8] = { 0xC5, 0x27, 0x03, 0xFF, 0xFF, 0x85, 0xFF, 0x00 };
	msg_squeal_status_t m = {
		.squeal_state = MSG_SQUEAL_STATE_UNSTABLE,
		.warning_level = MSG_WARNING_LEVEL_CRITICAL,
		.basin_ratio = MSG_BASIN_RATIO_NA,
		.hopf_margin_mps = -123,
	};
	e2e_p01_tx_t tx = { 7 };
	uint8_t d[8];
	uint8_t dlc = 0;

	(void)state;
	assert_int_equal(msg_squeal_status_pack(&m, d, &dlc), SQ_OK);
	assert_int_equal(dlc, 8);
	assert_int_equal(e2e_p01_protect(&cfg_st, &tx, d, dlc), SQ_OK);
	assert_memory_equal(d, expect, 8);
}

static void test_e2e_protect_counter_sequence_0_to_14_then_0(void **state)
{
	e2e_p01_tx_t tx;
	uint8_t f[4];

	(void)state;
	e2e_p01_tx_init(&tx);
	for (unsigned int i = 0; i < 31U; i++) {
		uint8_t d[4] = { 0x00, 0x00, 0x39, 0x30 };

		assert_int_equal(e2e_p01_protect(&cfg_ds, &tx, d, 4), SQ_OK);
		ds_frame((uint8_t)(i % 15U), f);
		assert_memory_equal(d, f, 4);
	}
}

static void test_e2e_protect_keeps_high_nibble_and_rejects_bad_args(void **state)
{
	e2e_p01_config_t bad = cfg_ds;
	e2e_p01_tx_t tx = { 3 };
	uint8_t d[4] = { 0xAA, 0xF5, 0x01, 0x02 };
	uint8_t copy[4];

	(void)state;
	assert_int_equal(e2e_p01_protect(&cfg_ds, &tx, d, 4), SQ_OK);
	assert_int_equal(d[1], 0xF3);
	assert_int_equal(d[0], ref_crc8((const uint8_t[]){ 0x51, 0x2C, 0xF3, 0x01, 0x02 }, 5, 0, 0));

	memcpy(copy, d, 4);
	/* programming errors: the contract handler, never an error code */
	expect_assert_failure(e2e_p01_protect(&cfg_ds, &tx, d, 3));
	expect_assert_failure(e2e_p01_protect(&cfg_ds, NULL, d, 4));
	expect_assert_failure(e2e_p01_protect(&cfg_ds, &tx, NULL, 4));
	expect_assert_failure(e2e_p01_protect(NULL, &tx, d, 4));
	tx.counter = 15;
	expect_assert_failure(e2e_p01_protect(&cfg_ds, &tx, d, 4));
	assert_int_equal(tx.counter, 15);
	tx.counter = 4;
	bad.max_delta_counter = 0;
	expect_assert_failure(e2e_p01_protect(&bad, &tx, d, 4));
	bad.max_delta_counter = 15;
	assert_int_equal(e2e_p01_config_check(&bad), SQ_EINVAL);
	bad.max_delta_counter = 14;
	bad.data_len = 1;
	assert_int_equal(e2e_p01_config_check(&bad), SQ_EINVAL);
	bad.data_len = 9;
	assert_int_equal(e2e_p01_config_check(&bad), SQ_EINVAL);
	assert_memory_equal(d, copy, 4);
	assert_int_equal(tx.counter, 4);
}

/* ---- E2E check ----------------------------------------------------------- */

static e2e_p01_status_t chk(e2e_p01_rx_t *rx, uint8_t counter)
{
	uint8_t f[4];

	ds_frame(counter, f);
	return e2e_p01_check(&cfg_ds, rx, f, 4);
}

static void test_e2e_check_initial_then_ok(void **state)
{
	e2e_p01_rx_t rx;

	(void)state;
	e2e_p01_rx_init(&rx);
	assert_int_equal(chk(&rx, 5), E2E_P01_STATUS_INITIAL);
	assert_int_equal(rx.last_valid_counter, 5);
	assert_int_equal(chk(&rx, 6), E2E_P01_STATUS_OK);
	assert_int_equal(chk(&rx, 7), E2E_P01_STATUS_OK);
	assert_int_equal(rx.status, E2E_P01_STATUS_OK);
	assert_int_equal(rx.status_count[E2E_P01_STATUS_INITIAL], 1);
	assert_int_equal(rx.status_count[E2E_P01_STATUS_OK], 2);
}

static void test_e2e_check_counter_wrap_14_to_0_is_ok(void **state)
{
	e2e_p01_rx_t rx;

	(void)state;
	e2e_p01_rx_init(&rx);
	assert_int_equal(chk(&rx, 13), E2E_P01_STATUS_INITIAL);
	assert_int_equal(chk(&rx, 14), E2E_P01_STATUS_OK);
	assert_int_equal(chk(&rx, 0), E2E_P01_STATUS_OK);
	assert_int_equal(chk(&rx, 1), E2E_P01_STATUS_OK);
	/* back to 14 is a jump of 13 */
	assert_int_equal(chk(&rx, 14), E2E_P01_STATUS_WRONGSEQUENCE);
}

static void test_e2e_check_repeated(void **state)
{
	e2e_p01_rx_t rx;

	(void)state;
	e2e_p01_rx_init(&rx);
	assert_int_equal(chk(&rx, 0), E2E_P01_STATUS_INITIAL);
	assert_int_equal(chk(&rx, 1), E2E_P01_STATUS_OK);
	assert_int_equal(chk(&rx, 1), E2E_P01_STATUS_REPEATED);
	assert_false(e2e_p01_status_usable(rx.status));
	assert_int_equal(rx.last_valid_counter, 1);
	assert_int_equal(rx.status_count[E2E_P01_STATUS_REPEATED], 1);
}

static void test_e2e_check_oksomelost_reports_number_lost(void **state)
{
	e2e_p01_config_t cfg = cfg_ds;
	e2e_p01_rx_t rx;
	uint8_t f[4];

	(void)state;
	cfg.max_delta_counter = 3; /* up to 2 lost between two calls */
	e2e_p01_rx_init(&rx);
	ds_frame(2, f);
	assert_int_equal(e2e_p01_check(&cfg, &rx, f, 4), E2E_P01_STATUS_INITIAL);
	ds_frame(4, f); /* 3 lost; this call tolerates a jump of 3 + 1 */
	assert_int_equal(e2e_p01_check(&cfg, &rx, f, 4), E2E_P01_STATUS_OKSOMELOST);
	assert_int_equal(rx.lost_data, 1);
	ds_frame(8, f); /* 5, 6, 7 lost: delta 4 = tolerated 3 + 1 */
	assert_int_equal(e2e_p01_check(&cfg, &rx, f, 4), E2E_P01_STATUS_OKSOMELOST);
	assert_int_equal(rx.lost_data, 3);
	assert_true(e2e_p01_status_usable(rx.status));
	ds_frame(9, f);
	assert_int_equal(e2e_p01_check(&cfg, &rx, f, 4), E2E_P01_STATUS_OK);
	assert_int_equal(rx.lost_data, 0);
	ds_frame(14, f); /* delta 5 > 4 */
	assert_int_equal(e2e_p01_check(&cfg, &rx, f, 4), E2E_P01_STATUS_WRONGSEQUENCE);
	assert_int_equal(rx.status_count[E2E_P01_STATUS_OKSOMELOST], 2);
}

static void test_e2e_check_wrong_sequence_then_resync(void **state)
{
	e2e_p01_rx_t rx;

	(void)state;
	e2e_p01_rx_init(&rx);
	assert_int_equal(chk(&rx, 0), E2E_P01_STATUS_INITIAL);
	assert_int_equal(chk(&rx, 1), E2E_P01_STATUS_OK);
	/* MaxDeltaCounterInit 1: this call tolerates a jump of 2, 1 -> 4 is 3 */
	assert_int_equal(chk(&rx, 4), E2E_P01_STATUS_WRONGSEQUENCE);
	assert_false(e2e_p01_status_usable(rx.status));
	/* 5 confirms the adopted sequence: usable again, reported INITIAL */
	assert_int_equal(chk(&rx, 5), E2E_P01_STATUS_INITIAL);
	assert_true(e2e_p01_status_usable(rx.status));
	assert_int_equal(chk(&rx, 6), E2E_P01_STATUS_OK);
	/* a sender restart (counter back to 0) costs exactly one frame */
	assert_int_equal(chk(&rx, 0), E2E_P01_STATUS_WRONGSEQUENCE);
	assert_int_equal(chk(&rx, 1), E2E_P01_STATUS_INITIAL);
	assert_int_equal(chk(&rx, 2), E2E_P01_STATUS_OK);
	/* a stray frame discards itself and the good frame after it */
	assert_int_equal(chk(&rx, 10), E2E_P01_STATUS_WRONGSEQUENCE);
	assert_int_equal(chk(&rx, 3), E2E_P01_STATUS_WRONGSEQUENCE);
	assert_int_equal(chk(&rx, 4), E2E_P01_STATUS_INITIAL);
	assert_int_equal(rx.status_count[E2E_P01_STATUS_WRONGSEQUENCE], 4);
}

static void test_e2e_check_wrong_crc(void **state)
{
	e2e_p01_config_t other_id = cfg_ds;
	e2e_p01_rx_t rx;
	uint8_t f[4];

	(void)state;
	e2e_p01_rx_init(&rx);
	ds_frame(0, f);
	f[0] ^= 0x01; /* CRC byte */
	assert_int_equal(e2e_p01_check(&cfg_ds, &rx, f, 4), E2E_P01_STATUS_WRONGCRC);
	ds_frame(0, f);
	f[3] ^= 0x80; /* payload */
	assert_int_equal(e2e_p01_check(&cfg_ds, &rx, f, 4), E2E_P01_STATUS_WRONGCRC);
	ds_frame(0, f);
	f[1] = 0x10; /* high nibble of byte 1 is covered too */
	assert_int_equal(e2e_p01_check(&cfg_ds, &rx, f, 4), E2E_P01_STATUS_WRONGCRC);
	ds_frame(0, f);
	assert_int_equal(e2e_p01_check(&cfg_ds, &rx, f, 3), E2E_P01_STATUS_WRONGCRC);
	/* same bytes, another message's data ID: a masquerade is caught */
	other_id.data_id = MSG_PAD_FORCE_DATA_ID;
	assert_int_equal(e2e_p01_check(&other_id, &rx, f, 4), E2E_P01_STATUS_WRONGCRC);
	other_id.data_id = (uint16_t)(MSG_DISC_SPEED_DATA_ID ^ 0x0100U); /* high byte */
	assert_int_equal(e2e_p01_check(&other_id, &rx, f, 4), E2E_P01_STATUS_WRONGCRC);
	assert_int_equal(rx.status_count[E2E_P01_STATUS_WRONGCRC], 6);
	assert_true(rx.wait_for_first_data);
	/* none of that disturbed the sequence: the good frame is the first */
	assert_int_equal(e2e_p01_check(&cfg_ds, &rx, f, 4), E2E_P01_STATUS_INITIAL);
	/* an invalid config or a NULL state is a programming error: the
	 * contract handler, never a wrong CRC; the state is untouched */
	other_id = cfg_ds;
	other_id.data_len = 0;
	expect_assert_failure(e2e_p01_check(&other_id, &rx, f, 4));
	other_id.data_len = 9;
	expect_assert_failure(e2e_p01_check(&other_id, &rx, f, 4));
	other_id = cfg_ds;
	other_id.max_delta_counter = 0;
	expect_assert_failure(e2e_p01_check(&other_id, &rx, f, 4));
	other_id.max_delta_counter = 15;
	expect_assert_failure(e2e_p01_check(&other_id, &rx, f, 4));
	expect_assert_failure(e2e_p01_check(NULL, &rx, f, 4));
	expect_assert_failure(e2e_p01_check(&cfg_ds, NULL, f, 4));
	assert_int_equal(rx.status_count[E2E_P01_STATUS_WRONGCRC], 6);
}

static void test_e2e_check_nonewdata_grows_tolerated_jump(void **state)
{
	e2e_p01_rx_t rx;

	(void)state;
	e2e_p01_rx_init(&rx);
	assert_int_equal(e2e_p01_check(&cfg_ds, &rx, NULL, 0), E2E_P01_STATUS_NONEWDATA);
	assert_int_equal(chk(&rx, 0), E2E_P01_STATUS_INITIAL);
	/* three cycles without a frame, then counter 4: 3 lost, tolerated */
	for (int i = 0; i < 3; i++) {
		assert_int_equal(e2e_p01_check(&cfg_ds, &rx, NULL, 0),
				 E2E_P01_STATUS_NONEWDATA);
	}
	assert_int_equal(chk(&rx, 4), E2E_P01_STATUS_OKSOMELOST);
	assert_int_equal(rx.lost_data, 3);
	/* without the empty cycles the same jump is a wrong sequence */
	assert_int_equal(chk(&rx, 8), E2E_P01_STATUS_WRONGSEQUENCE);
	assert_int_equal(rx.status_count[E2E_P01_STATUS_NONEWDATA], 4);
	/* the tolerated jump saturates at 14 */
	for (int i = 0; i < 40; i++) {
		(void)e2e_p01_check(&cfg_ds, &rx, NULL, 0);
	}
	assert_int_equal(rx.max_delta_counter, 14);
}

static void test_e2e_check_counter_15_is_rejected(void **state)
{
	e2e_p01_rx_t rx;
	uint8_t f[4] = { 0, 0x0F, 0x39, 0x30 };
	uint8_t crc = 0;

	(void)state;
	/* CRC over 51 2C 0F 39 30 computed independently */
	assert_int_equal(e2e_p01_crc(&cfg_ds, f, 4, &crc), SQ_OK);
	assert_int_equal(crc, ref_crc8((const uint8_t[]){ 0x51, 0x2C, 0x0F, 0x39, 0x30 }, 5, 0, 0));
	f[0] = crc;
	e2e_p01_rx_init(&rx);
	/* even as the first frame: a good CRC does not make 15 valid */
	assert_int_equal(e2e_p01_check(&cfg_ds, &rx, f, 4), E2E_P01_STATUS_WRONGSEQUENCE);
	assert_true(rx.wait_for_first_data);
	assert_int_equal(chk(&rx, 14), E2E_P01_STATUS_INITIAL);
	assert_int_equal(e2e_p01_check(&cfg_ds, &rx, f, 4), E2E_P01_STATUS_WRONGSEQUENCE);
	/* 15 was not adopted: 14 -> 0 still continues the sequence */
	assert_int_equal(chk(&rx, 0), E2E_P01_STATUS_OK);
	/* and unpack refuses it too */
	msg_disc_speed_t m;
	assert_int_equal(msg_disc_speed_unpack(f, 4, &m), SQ_EBADMSG);
}

static void test_e2e_rx_reset_restarts_but_keeps_counts(void **state)
{
	e2e_p01_rx_t rx;

	(void)state;
	e2e_p01_rx_init(&rx);
	assert_int_equal(chk(&rx, 0), E2E_P01_STATUS_INITIAL);
	assert_int_equal(chk(&rx, 1), E2E_P01_STATUS_OK);
	e2e_p01_rx_reset(&rx);
	assert_int_equal(chk(&rx, 9), E2E_P01_STATUS_INITIAL);
	assert_int_equal(rx.status_count[E2E_P01_STATUS_INITIAL], 2);
	assert_int_equal(rx.status_count[E2E_P01_STATUS_OK], 1);
}

static void test_e2e_status_usable_and_names(void **state)
{
	(void)state;
	assert_true(e2e_p01_status_usable(E2E_P01_STATUS_OK));
	assert_true(e2e_p01_status_usable(E2E_P01_STATUS_OKSOMELOST));
	assert_true(e2e_p01_status_usable(E2E_P01_STATUS_INITIAL));
	assert_false(e2e_p01_status_usable(E2E_P01_STATUS_REPEATED));
	assert_false(e2e_p01_status_usable(E2E_P01_STATUS_WRONGSEQUENCE));
	assert_false(e2e_p01_status_usable(E2E_P01_STATUS_WRONGCRC));
	assert_false(e2e_p01_status_usable(E2E_P01_STATUS_NONEWDATA));
	assert_false(e2e_p01_status_usable(E2E_P01_STATUS_COUNT));
	assert_string_equal(e2e_p01_status_name(E2E_P01_STATUS_OKSOMELOST), "OKSOMELOST");
	assert_string_equal(e2e_p01_status_name(E2E_P01_STATUS_WRONGCRC), "WRONGCRC");
	assert_string_equal(e2e_p01_status_name(E2E_P01_STATUS_COUNT), "?");
}

static void test_receive_writes_msg_only_for_usable_frames(void **state)
{
	e2e_p01_rx_t rx;
	msg_disc_speed_t m = { 0xEE, 0xEE, 0xEEEE };
	uint8_t f[4];

	(void)state;
	e2e_p01_rx_init(&rx);
	ds_frame(0, f);
	f[2] ^= 1U;
	assert_int_equal(msg_disc_speed_receive(&cfg_ds, &rx, f, 4, &m), SQ_EBADMSG);
	assert_int_equal(rx.status, E2E_P01_STATUS_WRONGCRC);
	assert_int_equal(m.disc_speed_radps, 0xEEEE);
	assert_int_equal(msg_disc_speed_receive(&cfg_ds, &rx, NULL, 0, &m), SQ_EAGAIN);
	assert_int_equal(m.disc_speed_radps, 0xEEEE);
	ds_frame(0, f);
	assert_int_equal(msg_disc_speed_receive(&cfg_ds, &rx, f, 4, &m), SQ_OK);
	assert_int_equal(m.disc_speed_radps, 12345);
	assert_int_equal(m.counter, 0);
	m.disc_speed_radps = 0xEEEE;
	assert_int_equal(msg_disc_speed_receive(&cfg_ds, &rx, f, 4, &m), SQ_EBADMSG);
	assert_int_equal(rx.status, E2E_P01_STATUS_REPEATED);
	assert_int_equal(m.disc_speed_radps, 0xEEEE);
	expect_assert_failure(msg_disc_speed_receive(&cfg_ds, &rx, f, 4, NULL));

	/* PadForce: the hand-derived frame from above */
	{
		static const uint8_t pf[4] = { 0x37, 0x0E, 0x50, 0x46 };
		msg_pad_force_t p = { 0, 0, 0 };

		e2e_p01_rx_init(&rx);
		assert_int_equal(msg_pad_force_receive(&cfg_pf, &rx, pf, 4, &p), SQ_OK);
		assert_int_equal(p.pad_force_n, 18000);
		assert_int_equal(p.counter, 14);
		assert_int_equal(msg_pad_force_receive(&cfg_pf, &rx, pf, 3, &p), SQ_EBADMSG);
	}
}

/* ---- layout: hand-derived frames ----------------------------------------- */

static void test_layout_squeal_detail(void **state)
{
	/* 12.34 m/s, 1.23 m/s, 0.50 m/s, 11.1 km/h, counter 3, crc field 0xAB */
	static const uint8_t expect[8] = { 0xAB, 0x23, 0x4D, 0xEC, 0x01, 0x32, 0xF0, 0x06 };
	msg_squeal_detail_t m = { 0xAB, 3, 1234, 123, 50, 111 };
	msg_squeal_detail_t u;
	uint8_t d[8];
	uint8_t dlc = 0;

	(void)state;
	assert_int_equal(msg_squeal_detail_pack(&m, d, &dlc), SQ_OK);
	assert_int_equal(dlc, 8);
	assert_memory_equal(d, expect, 8);
	assert_int_equal(msg_squeal_detail_unpack(expect, 8, &u), SQ_OK);
	assert_int_equal(u.crc, 0xAB);
	assert_int_equal(u.counter, 3);
	assert_int_equal(u.v0_mps, 1234);
	assert_int_equal(u.hopf_speed_mps, 123);
	assert_int_equal(u.trigger_velocity_mps, 50);
	assert_int_equal(u.vehicle_speed_border_kph, 111);
}

static void test_layout_squeal_detail2(void **state)
{
	static const uint8_t expect[8] = { 0x5A, 0x05, 0x50, 0x46, 0xE0, 0x2E, 0xD2, 0x04 };
	msg_squeal_detail2_t m = { 0x5A, 5, 18000, 12000, 1234 };
	msg_squeal_detail2_t u;
	uint8_t d[8];
	uint8_t dlc = 0;

	(void)state;
	assert_int_equal(msg_squeal_detail2_pack(&m, d, &dlc), SQ_OK);
	assert_memory_equal(d, expect, 8);
	assert_int_equal(msg_squeal_detail2_unpack(expect, 8, &u), SQ_OK);
	assert_int_equal(u.force_n, 18000);
	assert_int_equal(u.hopf_force_n, 12000);
	assert_int_equal(u.lc_amplitude_um, 1234);
}

static void test_layout_squeal_status_extremes(void **state)
{
	/* fault, warning none, basin 1.0, margin +327.67, counter 1 */
	static const uint8_t expect[8] = { 0x00, 0xF1, 0x00, 0x10, 0x27, 0xFF, 0x7F, 0x00 };
	msg_squeal_status_t m = { 0, 1, MSG_SQUEAL_STATE_FAULT, 0, 10000, 32767, 0 };
	uint8_t d[8];
	uint8_t dlc = 0;

	(void)state;
	assert_int_equal(msg_squeal_status_pack(&m, d, &dlc), SQ_OK);
	assert_memory_equal(d, expect, 8);
}

/* BorderMargin_sigma (issue 12): bits 56..63, Intel = byte 7 whole; raw
 * 21 = 2.0 sigma (x 0.1 - 0.1) */
static void test_layout_squeal_status_border_margin(void **state)
{
	/* counter 1 | stable 0 << 4 = 0x01; basin NA FF FF; margin NA 00 80 */
	static const uint8_t expect[8] = { 0x00, 0x01, 0x00, 0xFF, 0xFF, 0x00, 0x80, 0x15 };
	msg_squeal_status_t m = { 0, 1, MSG_SQUEAL_STATE_STABLE, 0, 0xFFFFU, -32768, 21 };
	msg_squeal_status_t u;
	uint8_t d[8];
	uint8_t dlc = 0;

	(void)state;
	assert_int_equal(msg_squeal_status_pack(&m, d, &dlc), SQ_OK);
	assert_memory_equal(d, expect, 8);
	assert_int_equal(msg_squeal_status_unpack(expect, 8, &u), SQ_OK);
	assert_int_equal(u.border_margin_sigma, 21);
}

static void test_layout_squeal_diag_every_page(void **state)
{
	/* page 4 by hand: counter 13 | page 4 << 4 = 0x4D; Fault_SelfTest =
	 * bit 27 = byte 3 bit 3; HseFreq 80 (8.0 MHz) = byte 4; ResetCause 4 |
	 * BorLevel 3 << 3 | LoopbackCan1 0 << 6 = 0x1C; LoopbackCan2 2 |
	 * (StackHighWater 480 & 0x3F) << 2 = 0x82, 480 >> 6 = 0x07 */
	static const uint8_t expect[5][8] = {
		{ 0x11, 0x09, 0x21, 0x04, 0x56, 0x34, 0x12, 0x07 },
		{ 0x22, 0x1A, 0xFF, 0x0F, 0x45, 0x03, 0xEF, 0xBE },
		{ 0x33, 0x2B, 0x02, 0x00, 0x01, 0x00, 0xFF, 0xFF },
		{ 0x44, 0x3C, 0x00, 0x04, 0x2C, 0x01, 0x02, 0x00 },
		{ 0x55, 0x4D, 0x00, 0x08, 0x50, 0x1C, 0x82, 0x07 },
	};
	msg_squeal_diag_t m[5];
	uint8_t d[8];
	uint8_t dlc = 0;

	(void)state;
	memset(m, 0, sizeof(m));
	/* every counter filled on every page: pack must send only the page's */
	for (int p = 0; p < 5; p++) {
		m[p].hse_freq_100khz = 80;
		m[p].reset_cause = 4;
		m[p].bor_level = 3;
		m[p].loopback_can1 = 0;
		m[p].loopback_can2 = 2;
		m[p].stack_high_water_b = 480;
		m[p].uptime_s = 0x123456;
		m[p].bus_off_count = 7;
		m[p].worst_task_time_us = 0x0345;
		m[p].rx_overrun_count = 0xBEEF;
		m[p].e2e_error_count_speed = 1;
		m[p].e2e_error_count_force = 65535;
		m[p].tx_overflow_count = 300;
		m[p].rx_bad_frame_count = 2;
		m[p].page = (uint8_t)p;
	}
	m[0].crc = 0x11; m[0].counter = 9;  m[0].fault_bits = 0x421;
	m[1].crc = 0x22; m[1].counter = 10; m[1].fault_bits = MSG_FAULT_ALL;
	m[2].crc = 0x33; m[2].counter = 11; m[2].fault_bits = MSG_FAULT_FORCE_STALE;
	m[3].crc = 0x44; m[3].counter = 12; m[3].fault_bits = MSG_FAULT_TX_OVERFLOW;
	m[4].crc = 0x55; m[4].counter = 13; m[4].fault_bits = MSG_FAULT_SELF_TEST;
	for (int p = 0; p < 5; p++) {
		msg_squeal_diag_t u;

		assert_int_equal(msg_squeal_diag_pack(&m[p], d, &dlc), SQ_OK);
		assert_int_equal(dlc, 8);
		assert_memory_equal(d, expect[p], 8);
		memset(&u, 0xA5, sizeof(u));
		assert_int_equal(msg_squeal_diag_unpack(expect[p], 8, &u), SQ_OK);
		assert_int_equal(u.page, p);
		assert_int_equal(u.fault_bits, m[p].fault_bits);
		assert_int_equal(u.crc, m[p].crc);
		assert_int_equal(u.counter, m[p].counter);
		/* fields of the page decoded, all others 0 */
		assert_int_equal(u.uptime_s, p == 0 ? 0x123456U : 0U);
		assert_int_equal(u.bus_off_count, p == 0 ? 7 : 0);
		assert_int_equal(u.worst_task_time_us, p == 1 ? 0x0345 : 0);
		assert_int_equal(u.rx_overrun_count, p == 1 ? 0xBEEF : 0);
		assert_int_equal(u.e2e_error_count_speed, p == 2 ? 1 : 0);
		assert_int_equal(u.e2e_error_count_force, p == 2 ? 65535 : 0);
		assert_int_equal(u.tx_overflow_count, p == 3 ? 300 : 0);
		assert_int_equal(u.rx_bad_frame_count, p == 3 ? 2 : 0);
		assert_int_equal(u.hse_freq_100khz, p == 4 ? 80 : 0);
		assert_int_equal(u.reset_cause, p == 4 ? 4 : 0);
		assert_int_equal(u.bor_level, p == 4 ? 3 : 0);
		assert_int_equal(u.loopback_can2, p == 4 ? 2 : 0);
		assert_int_equal(u.stack_high_water_b, p == 4 ? 480 : 0);
	}
}

/* ---- round trips at the limits ------------------------------------------- */

static void test_roundtrip_disc_speed_and_pad_force_limits(void **state)
{
	static const uint16_t vals[] = { 0, 1, MSG_DISC_SPEED_RADPS_MAX, MSG_DISC_SPEED_RADPS_NA };
	uint8_t d[8];
	uint8_t dlc;

	(void)state;
	for (size_t i = 0; i < sizeof(vals) / sizeof(vals[0]); i++) {
		for (uint8_t c = 0; c <= 14U; c = (uint8_t)(c + 14U)) {
			msg_disc_speed_t m = { (uint8_t)(0xFFU - c), c, vals[i] };
			msg_disc_speed_t u;
			msg_pad_force_t p = { c, c, vals[i] };
			msg_pad_force_t pu;

			assert_int_equal(msg_disc_speed_pack(&m, d, &dlc), SQ_OK);
			assert_int_equal(dlc, MSG_DISC_SPEED_DLC);
			for (size_t k = dlc; k < 8U; k++) {
				assert_int_equal(d[k], 0); /* beyond the DLC */
			}
			assert_int_equal(msg_disc_speed_unpack(d, dlc, &u), SQ_OK);
			assert_int_equal(u.crc, m.crc);
			assert_int_equal(u.counter, m.counter);
			assert_int_equal(u.disc_speed_radps, m.disc_speed_radps);
			assert_int_equal(msg_pad_force_pack(&p, d, &dlc), SQ_OK);
			assert_int_equal(dlc, MSG_PAD_FORCE_DLC);
			assert_int_equal(msg_pad_force_unpack(d, dlc, &pu), SQ_OK);
			assert_int_equal(pu.crc, p.crc);
			assert_int_equal(pu.counter, p.counter);
			assert_int_equal(pu.pad_force_n, p.pad_force_n);
		}
	}
	assert_int_equal(MSG_PAD_FORCE_N_MAX, 65534);
	assert_int_equal(MSG_PAD_FORCE_N_NA, 0xFFFF);
}

static void test_roundtrip_squeal_status_limits(void **state)
{
	static const uint8_t states[] = { 0, 1, 2, 3, 15 };
	static const uint16_t basins[] = { 0, MSG_BASIN_RATIO_MAX, MSG_BASIN_RATIO_NA };
	static const int16_t margins[] = { MSG_HOPF_MARGIN_MPS_MIN, -1, 0, 1,
					   MSG_HOPF_MARGIN_MPS_MAX, MSG_HOPF_MARGIN_MPS_NA };
	uint8_t d[8];
	uint8_t dlc;

	(void)state;
	for (size_t s = 0; s < sizeof(states); s++) {
		for (uint8_t w = 0; w <= 3U; w++) {
			for (size_t b = 0; b < 3U; b++) {
				for (size_t g = 0; g < sizeof(margins) / sizeof(margins[0]); g++) {
					msg_squeal_status_t m = { (uint8_t)(s * 50U), (uint8_t)(w + s),
								  states[s], w, basins[b], margins[g],
								  (uint8_t)(g * 85U) };
					msg_squeal_status_t u;

					assert_int_equal(msg_squeal_status_pack(&m, d, &dlc), SQ_OK);
					assert_int_equal(msg_squeal_status_unpack(d, dlc, &u), SQ_OK);
					assert_int_equal(u.crc, m.crc);
					assert_int_equal(u.counter, m.counter);
					assert_int_equal(u.squeal_state, m.squeal_state);
					assert_int_equal(u.warning_level, m.warning_level);
					assert_int_equal(u.basin_ratio, m.basin_ratio);
					assert_int_equal(u.hopf_margin_mps, m.hopf_margin_mps);
					assert_int_equal(u.border_margin_sigma, m.border_margin_sigma);
				}
			}
		}
	}
}

static void test_roundtrip_squeal_detail_limits(void **state)
{
	static const uint16_t v14[] = { 0, 1, MSG_V0_MPS_MAX, MSG_V0_MPS_NA };
	static const uint16_t v12[] = { 0, 1, MSG_TRIGGER_VELOCITY_MPS_MAX, MSG_TRIGGER_VELOCITY_MPS_NA };
	uint8_t d[8];
	uint8_t dlc;

	(void)state;
	for (size_t a = 0; a < 4U; a++) {
		for (size_t b = 0; b < 4U; b++) {
			/* neighbours get opposite extremes, so a bit leaking across a
			 * field border would show */
			msg_squeal_detail_t m = { 0xFF, 14, v14[a], v14[3U - a], v12[b], v12[3U - b] };
			msg_squeal_detail_t u;

			assert_int_equal(msg_squeal_detail_pack(&m, d, &dlc), SQ_OK);
			assert_int_equal(msg_squeal_detail_unpack(d, dlc, &u), SQ_OK);
			assert_int_equal(u.crc, m.crc);
			assert_int_equal(u.counter, m.counter);
			assert_int_equal(u.v0_mps, m.v0_mps);
			assert_int_equal(u.hopf_speed_mps, m.hopf_speed_mps);
			assert_int_equal(u.trigger_velocity_mps, m.trigger_velocity_mps);
			assert_int_equal(u.vehicle_speed_border_kph, m.vehicle_speed_border_kph);
		}
	}
	assert_int_equal(MSG_HOPF_SPEED_MPS_NA, MSG_V0_MPS_NA);
	assert_int_equal(MSG_VEHICLE_SPEED_BORDER_KPH_NA, 0xFFF);
}

static void test_roundtrip_squeal_detail2_limits(void **state)
{
	static const uint16_t v[] = { 0, 1, 65534, 0xFFFF };
	uint8_t d[8];
	uint8_t dlc;

	(void)state;
	for (size_t a = 0; a < 4U; a++) {
		for (size_t b = 0; b < 4U; b++) {
			msg_squeal_detail2_t m = { (uint8_t)a, (uint8_t)b, v[a], v[b], v[3U - a] };
			msg_squeal_detail2_t u;

			assert_int_equal(msg_squeal_detail2_pack(&m, d, &dlc), SQ_OK);
			assert_int_equal(msg_squeal_detail2_unpack(d, dlc, &u), SQ_OK);
			assert_int_equal(u.crc, m.crc);
			assert_int_equal(u.counter, m.counter);
			assert_int_equal(u.force_n, m.force_n);
			assert_int_equal(u.hopf_force_n, m.hopf_force_n);
			assert_int_equal(u.lc_amplitude_um, m.lc_amplitude_um);
		}
	}
}

static void test_roundtrip_squeal_diag_limits(void **state)
{
	uint8_t d[8];
	uint8_t dlc;

	(void)state;
	for (int ext = 0; ext < 2; ext++) {
		for (uint8_t p = 0; p < MSG_DIAG_PAGE_COUNT; p++) {
			msg_squeal_diag_t m;
			msg_squeal_diag_t u;
			uint16_t v16 = ext != 0 ? 0xFFFFU : 0U;

			memset(&m, 0, sizeof(m));
			m.page = p;
			m.counter = ext != 0 ? 14 : 0;
			m.crc = ext != 0 ? 0xFF : 0;
			m.fault_bits = ext != 0 ? MSG_FAULT_ALL : 0;
			m.uptime_s = ext != 0 ? MSG_UPTIME_S_MAX : 0;
			m.bus_off_count = ext != 0 ? 0xFF : 0;
			m.worst_task_time_us = v16;
			m.rx_overrun_count = v16;
			m.e2e_error_count_speed = v16;
			m.e2e_error_count_force = v16;
			m.tx_overflow_count = v16;
			m.rx_bad_frame_count = v16;
			assert_int_equal(msg_squeal_diag_pack(&m, d, &dlc), SQ_OK);
			assert_int_equal(msg_squeal_diag_unpack(d, dlc, &u), SQ_OK);
			assert_int_equal(u.page, p);
			assert_int_equal(u.crc, m.crc);
			assert_int_equal(u.counter, m.counter);
			assert_int_equal(u.fault_bits, m.fault_bits);
			assert_int_equal(u.uptime_s, p == 0 ? m.uptime_s : 0U);
			assert_int_equal(u.bus_off_count, p == 0 ? m.bus_off_count : 0);
			assert_int_equal(u.worst_task_time_us, p == 1 ? v16 : 0);
			assert_int_equal(u.rx_overrun_count, p == 1 ? v16 : 0);
			assert_int_equal(u.e2e_error_count_speed, p == 2 ? v16 : 0);
			assert_int_equal(u.e2e_error_count_force, p == 2 ? v16 : 0);
			assert_int_equal(u.tx_overflow_count, p == 3 ? v16 : 0);
			assert_int_equal(u.rx_bad_frame_count, p == 3 ? v16 : 0);
		}
	}
	/* each fault bit alone lands on its own signal */
	for (unsigned int i = 0; i < 11U; i++) {
		msg_squeal_diag_t m;
		msg_squeal_diag_t u;

		memset(&m, 0, sizeof(m));
		m.fault_bits = (uint16_t)(1U << i);
		assert_int_equal(msg_squeal_diag_pack(&m, d, &dlc), SQ_OK);
		assert_int_equal(d[(16U + i) / 8U], (uint8_t)(1U << ((16U + i) % 8U)));
		assert_int_equal(msg_squeal_diag_unpack(d, dlc, &u), SQ_OK);
		assert_int_equal(u.fault_bits, m.fault_bits);
	}
}

/* ---- rejection ----------------------------------------------------------- */

static void test_pack_rejects_out_of_range_values(void **state)
{
	uint8_t d[8];
	uint8_t before[8];
	uint8_t dlc = 0x77;

	(void)state;
	memset(d, 0x5C, sizeof(d));
	memcpy(before, d, sizeof(d));
	{
		msg_disc_speed_t m = { 0, 15, 100 };
		assert_int_equal(msg_disc_speed_pack(&m, d, &dlc), SQ_ERANGE);
	}
	{
		msg_squeal_status_t m = { 0, 0, 4, 0, 0, 0, 0 };
		assert_int_equal(msg_squeal_status_pack(&m, d, &dlc), SQ_ERANGE);
		m.squeal_state = 14;
		assert_int_equal(msg_squeal_status_pack(&m, d, &dlc), SQ_ERANGE);
		m.squeal_state = 0;
		m.warning_level = 4;
		assert_int_equal(msg_squeal_status_pack(&m, d, &dlc), SQ_ERANGE);
		m.warning_level = 0;
		m.basin_ratio = MSG_BASIN_RATIO_MAX + 1U;
		assert_int_equal(msg_squeal_status_pack(&m, d, &dlc), SQ_ERANGE);
	}
	{
		msg_squeal_detail_t m = { 0, 0, MSG_V0_MPS_NA + 1U, 0, 0, 0 };
		assert_int_equal(msg_squeal_detail_pack(&m, d, &dlc), SQ_ERANGE);
		m.v0_mps = 0;
		m.vehicle_speed_border_kph = 0x1000;
		assert_int_equal(msg_squeal_detail_pack(&m, d, &dlc), SQ_ERANGE);
	}
	{
		msg_squeal_diag_t m;
		memset(&m, 0, sizeof(m));
		m.page = MSG_DIAG_PAGE_COUNT;
		assert_int_equal(msg_squeal_diag_pack(&m, d, &dlc), SQ_ERANGE);
		m.page = MSG_DIAG_PAGE_UPTIME;
		m.uptime_s = MSG_UPTIME_S_MAX + 1U;
		assert_int_equal(msg_squeal_diag_pack(&m, d, &dlc), SQ_ERANGE);
		m.page = MSG_DIAG_PAGE_TASK; /* uptime not on this page: ignored */
		assert_int_equal(msg_squeal_diag_pack(&m, d, &dlc), SQ_OK);
		memcpy(d, before, sizeof(d));
		dlc = 0x77;
		m.fault_bits = 1U << 12; /* one above Fault_SelfTest */
		assert_int_equal(msg_squeal_diag_pack(&m, d, &dlc), SQ_ERANGE);
		m.fault_bits = 0U;
		m.page = MSG_DIAG_PAGE_SELFTEST; /* page 4: each field in range */
		m.hse_freq_100khz = 255U; /* not available: allowed */
		m.bor_level = 7U;
		m.stack_high_water_b = 16383U;
		assert_int_equal(msg_squeal_diag_pack(&m, d, &dlc), SQ_OK);
		memcpy(d, before, sizeof(d));
		dlc = 0x77;
		m.reset_cause = 7U; /* 0..6 */
		assert_int_equal(msg_squeal_diag_pack(&m, d, &dlc), SQ_ERANGE);
		m.reset_cause = 0U;
		m.bor_level = 4U; /* 0..3 or 7 */
		assert_int_equal(msg_squeal_diag_pack(&m, d, &dlc), SQ_ERANGE);
		m.bor_level = 3U;
		m.stack_high_water_b = 16384U; /* 14 bits */
		assert_int_equal(msg_squeal_diag_pack(&m, d, &dlc), SQ_ERANGE);
	}
	assert_memory_equal(d, before, sizeof(d));
	assert_int_equal(dlc, 0x77);
	expect_assert_failure(msg_disc_speed_pack(NULL, d, &dlc));
	{
		msg_pad_force_t m = { 0, 0, 0 };
		expect_assert_failure(msg_pad_force_pack(&m, NULL, &dlc));
		expect_assert_failure(msg_pad_force_pack(&m, d, NULL));
	}
}

static void test_unpack_rejects_wrong_dlc_for_every_message(void **state)
{
	static const uint8_t zeros[8] = { 0 };
	msg_disc_speed_t ds;
	msg_pad_force_t pf;
	msg_squeal_status_t st;
	msg_squeal_detail_t dt;
	msg_squeal_detail2_t d2;
	msg_squeal_diag_t dg;

	(void)state;
	for (uint8_t dlc = 0; dlc <= 8U; dlc++) {
		int want4 = dlc == 4U ? SQ_OK : SQ_EBADMSG;
		int want8 = dlc == 8U ? SQ_OK : SQ_EBADMSG;

		assert_int_equal(msg_disc_speed_unpack(zeros, dlc, &ds), want4);
		assert_int_equal(msg_pad_force_unpack(zeros, dlc, &pf), want4);
		assert_int_equal(msg_squeal_status_unpack(zeros, dlc, &st), want8);
		assert_int_equal(msg_squeal_detail_unpack(zeros, dlc, &dt), want8);
		assert_int_equal(msg_squeal_detail2_unpack(zeros, dlc, &d2), want8);
		assert_int_equal(msg_squeal_diag_unpack(zeros, dlc, &dg), want8);
	}
	assert_int_equal(msg_squeal_status_unpack(zeros, 15, &st), SQ_EBADMSG);
	assert_int_equal(msg_squeal_status_unpack(NULL, 8, &st), SQ_EBADMSG);
	expect_assert_failure(msg_squeal_status_unpack(zeros, 8, NULL));
	{
		/* diag page 5 does not exist */
		const uint8_t bad_page[8] = { 0, 0x50, 0, 0, 0, 0, 0, 0 };
		memset(&dg, 0x5A, sizeof(dg));
		assert_int_equal(msg_squeal_diag_unpack(bad_page, 8, &dg), SQ_EBADMSG);
		assert_int_equal(dg.page, 0x5A); /* untouched */
	}
}

/* ---- descriptor table ---------------------------------------------------- */

static void test_descriptor_table_is_self_consistent(void **state)
{
	(void)state;
	for (size_t i = 0; i < MSG_COUNT; i++) {
		const msg_desc_t *m = &msg_table[i];
		uint8_t used[16][64]; /* per mux page (0 for plain signals) */
		int crc_seen = 0, counter_seen = 0;

		memset(used, 0, sizeof(used));
		assert_ptr_equal(msg_desc_find(m->id), m);
		assert_true(m->id <= 0x7FFU);
		assert_true(m->dlc >= 2U && m->dlc <= 8U);
		for (size_t j = 0; j < m->sig_count; j++) {
			const msg_sig_desc_t *s = &msg_sig_table[m->sig_first + j];

			assert_int_equal(s->msg_id, m->id);
			assert_true(s->length >= 1U && s->length <= 31U);
			assert_true((unsigned int)s->start_bit + s->length <= 8U * m->dlc);
			assert_true(s->factor_den > 0);
			assert_true(s->raw_min <= s->raw_max);
			if ((s->flags & MSG_SIG_HAS_NA) != 0U) {
				assert_true(s->na_raw < s->raw_min || s->na_raw > s->raw_max);
			}
			if ((s->flags & MSG_SIG_E2E) != 0U) {
				if (s->start_bit == 0U) {
					crc_seen = s->length == 8U;
				} else {
					counter_seen = s->start_bit == 8U && s->length == 4U;
				}
			}
			/* no two signals share a bit (on the same page) */
			for (unsigned int b = s->start_bit; b < (unsigned int)s->start_bit + s->length; b++) {
				for (unsigned int p = 0; p < 16U; p++) {
					if ((s->flags & MSG_SIG_MUXED) != 0U && p != s->mux_value) {
						continue;
					}
					assert_int_equal(used[p][b], 0);
					used[p][b] = 1;
				}
			}
		}
		assert_true(crc_seen);
		assert_true(counter_seen);
	}
	assert_int_equal(msg_table[MSG_COUNT - 1U].sig_first + msg_table[MSG_COUNT - 1U].sig_count,
			 MSG_SIG_COUNT);
	assert_null(msg_desc_find(0x7FF));
}

static void test_sig_get_raw_sign_extends_and_respects_mux(void **state)
{
	const msg_sig_desc_t *margin = NULL;
	const msg_sig_desc_t *uptime = NULL;
	const msg_desc_t *st = msg_desc_find(MSG_SQUEAL_STATUS_ID);
	const msg_desc_t *dg = msg_desc_find(MSG_SQUEAL_DIAG_ID);
	static const uint8_t f_st[8] = { 0xC5, 0x27, 0x03, 0xFF, 0xFF, 0x85, 0xFF, 0x00 };
	static const uint8_t f_dg0[8] = { 0x11, 0x09, 0x21, 0x04, 0x56, 0x34, 0x12, 0x07 };
	static const uint8_t f_dg1[8] = { 0x22, 0x1A, 0xFF, 0x07, 0x45, 0x03, 0xEF, 0xBE };
	int32_t raw = 0;

	(void)state;
	assert_non_null(st);
	assert_non_null(dg);
	for (size_t j = 0; j < st->sig_count; j++) {
		if (strcmp(msg_sig_table[st->sig_first + j].name, "HopfMargin_mps") == 0) {
			margin = &msg_sig_table[st->sig_first + j];
		}
	}
	for (size_t j = 0; j < dg->sig_count; j++) {
		if (strcmp(msg_sig_table[dg->sig_first + j].name, "Uptime_s") == 0) {
			uptime = &msg_sig_table[dg->sig_first + j];
		}
	}
	assert_non_null(margin);
	assert_non_null(uptime);
	assert_int_equal(msg_sig_get_raw(margin, f_st, 8, &raw), SQ_OK);
	assert_int_equal(raw, -123);
	assert_int_equal(msg_sig_get_raw(margin, f_st, 7, &raw), SQ_EBADMSG);
	assert_int_equal(msg_sig_get_raw(uptime, f_dg0, 8, &raw), SQ_OK);
	assert_int_equal(raw, 0x123456);
	assert_int_equal(msg_sig_get_raw(uptime, f_dg1, 8, &raw), SQ_ENOENT);
	expect_assert_failure(msg_sig_get_raw(NULL, f_dg1, 8, &raw));
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_crc8_p01_check_value_is_0x37),
		cmocka_unit_test(test_crc8_sae_j1850_check_value_is_0x4b),
		cmocka_unit_test(test_crc8_table_matches_bitwise_definition),
		cmocka_unit_test(test_crc8_empty_and_null),
		cmocka_unit_test(test_e2e_protect_disc_speed_matches_hand_derived_frame),
		cmocka_unit_test(test_e2e_protect_pad_force_counter_14_then_wraps_to_0),
		cmocka_unit_test(test_e2e_protect_squeal_status_matches_hand_derived_frame),
		cmocka_unit_test(test_e2e_protect_counter_sequence_0_to_14_then_0),
		cmocka_unit_test(test_e2e_protect_keeps_high_nibble_and_rejects_bad_args),
		cmocka_unit_test(test_e2e_check_initial_then_ok),
		cmocka_unit_test(test_e2e_check_counter_wrap_14_to_0_is_ok),
		cmocka_unit_test(test_e2e_check_repeated),
		cmocka_unit_test(test_e2e_check_oksomelost_reports_number_lost),
		cmocka_unit_test(test_e2e_check_wrong_sequence_then_resync),
		cmocka_unit_test(test_e2e_check_wrong_crc),
		cmocka_unit_test(test_e2e_check_nonewdata_grows_tolerated_jump),
		cmocka_unit_test(test_e2e_check_counter_15_is_rejected),
		cmocka_unit_test(test_e2e_rx_reset_restarts_but_keeps_counts),
		cmocka_unit_test(test_e2e_status_usable_and_names),
		cmocka_unit_test(test_receive_writes_msg_only_for_usable_frames),
		cmocka_unit_test(test_layout_squeal_detail),
		cmocka_unit_test(test_layout_squeal_detail2),
		cmocka_unit_test(test_layout_squeal_status_extremes),
		cmocka_unit_test(test_layout_squeal_status_border_margin),
		cmocka_unit_test(test_layout_squeal_diag_every_page),
		cmocka_unit_test(test_roundtrip_disc_speed_and_pad_force_limits),
		cmocka_unit_test(test_roundtrip_squeal_status_limits),
		cmocka_unit_test(test_roundtrip_squeal_detail_limits),
		cmocka_unit_test(test_roundtrip_squeal_detail2_limits),
		cmocka_unit_test(test_roundtrip_squeal_diag_limits),
		cmocka_unit_test(test_pack_rejects_out_of_range_values),
		cmocka_unit_test(test_unpack_rejects_wrong_dlc_for_every_message),
		cmocka_unit_test(test_descriptor_table_is_self_consistent),
		cmocka_unit_test(test_sig_get_raw_sign_extends_and_respects_mux),
	};

	return cmocka_run_group_tests_name("protocol", tests, NULL, NULL);
}
