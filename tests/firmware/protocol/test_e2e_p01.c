/* SPDX-License-Identifier: MIT */
/*
 * E2E Profile 1 variant 1A protect and check (firmware/protocol/e2e_p01.c)
 * on this project's messages, both numeric builds. Expected bytes are
 * literals derived outside the code under test: the CRCs by an independent
 * bitwise CRC in Python (poly 0x1D, start 0, no final XOR, over data ID
 * low, data ID high, bytes 1..n-1), the payloads by packing the raw values
 * into a little-endian integer in Python (tests/support/p01_frames.c).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "e2e_p01.h"
#include "p01_frames.h"
#include "sq_status.h"
#include "squeal_msgs.h"

/* ---- E2E protect --------------------------------------------------------- */

static const e2e_p01_config_t cfg_st = { MSG_SQUEAL_STATUS_DATA_ID, MSG_SQUEAL_STATUS_DLC, 1 };

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

int main(void)
{
	const struct CMUnitTest tests[] = {
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
	};

	return cmocka_run_group_tests_name("e2e_p01", tests, NULL, NULL);
}
