/* SPDX-License-Identifier: MIT */
/*
 * AUTOSAR E2E Profile 5 (firmware/protocol/e2e_p05.c) against independent
 * references (its CRC-16 alone: test_crc16_ccitt.c):
 *   - the published P05 example (8 zero bytes, Data ID 0x1234 -> CRC bytes
 *     1c ca; counter 1 -> cf 8d);
 *   - random frames of every FD length, offsets and Data IDs protected by
 *     Python's binascii.crc_hqx (gen_e2e_p05_vectors.py -> e2e_p05_ref.h);
 *   - a 24-byte FD wheel-speed frame in a maker's layout (CRC bytes 0-1,
 *     counter byte 2, Data ID = CAN id XOR 0xF800), bytes from Python.
 * The receiver's sequence statuses are derived by hand from P01's machine
 * (e2e_p01.h) with 256 counter values.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "can_signal.h"
#include "crc16_ccitt.h"
#include "e2e_p05.h"
#include "e2e_p05_ref.h"
#include "sq_status.h"

#define N_OF(a) (sizeof(a) / sizeof((a)[0]))

/* The specification's example: 8 bytes, offset 0, Data ID 0x1234. */
static void test_published_example(void **state)
{
	const e2e_p05_config_t cfg = { 0x1234U, 8U, 0U, 1U };
	e2e_p01_tx_t tx;
	uint8_t d[8] = { 0 };

	(void)state;
	e2e_p01_tx_init(&tx);
	assert_int_equal(e2e_p05_protect(&cfg, &tx, d, 8U), SQ_OK);
	assert_int_equal(d[0], 0x1C);
	assert_int_equal(d[1], 0xCA);
	assert_int_equal(d[2], 0x00);
	assert_int_equal(tx.counter, 1);
	memset(d, 0, sizeof(d));
	assert_int_equal(e2e_p05_protect(&cfg, &tx, d, 8U), SQ_OK);
	assert_int_equal(d[0], 0xCF);
	assert_int_equal(d[1], 0x8D);
	assert_int_equal(d[2], 0x01);
}

/* Random frames: protect writes Python's bytes, the check accepts them,
 * any flipped bit (CRC, counter, data) is WRONGCRC. */
static void test_random_frames_equal_python(void **state)
{
	size_t i;

	(void)state;
	for (i = 0; i < N_OF(p05_refs); i++) {
		const p05_ref_t *r = &p05_refs[i];
		const e2e_p05_config_t cfg = { r->data_id, r->len, r->off, 1U };
		e2e_p01_tx_t tx = { r->counter };
		e2e_p01_rx_t rx;
		uint8_t d[64];
		uint32_t bit;

		memcpy(d, r->plain, sizeof(d));
		assert_int_equal(e2e_p05_protect(&cfg, &tx, d, r->len), SQ_OK);
		if (memcmp(d, r->protected_, r->len) != 0) {
			fail_msg("vector %zu (len %u off %u id 0x%04X): protected differently", i, r->len,
				 r->off, r->data_id);
		}
		assert_int_equal(e2e_p05_crc(&cfg, d, r->len), r->crc);
		assert_int_equal(tx.counter, (uint8_t)(r->counter + 1U));
		e2e_p01_rx_init(&rx);
		assert_int_equal(e2e_p05_check(&cfg, &rx, d, r->len), E2E_P01_STATUS_INITIAL);
		bit = (uint32_t)((i * 37U) % (8U * r->len));
		d[bit / 8U] ^= (uint8_t)(1U << (bit % 8U));
		assert_int_equal(e2e_p05_check(&cfg, &rx, d, r->len), E2E_P01_STATUS_WRONGCRC);
	}
}

/* The Data ID enters the CRC but is never sent: another ID, another CRC. */
static void test_data_id_matters(void **state)
{
	const p05_ref_t *r = &p05_refs[0];
	const e2e_p05_config_t other = { (uint16_t)(r->data_id ^ 0x0100U), r->len, r->off, 1U };
	const e2e_p05_config_t swapped = { (uint16_t)((r->data_id >> 8) | (r->data_id << 8)), r->len,
					   r->off, 1U };
	e2e_p01_rx_t rx;

	(void)state;
	e2e_p01_rx_init(&rx);
	assert_int_equal(e2e_p05_check(&other, &rx, r->protected_, r->len), E2E_P01_STATUS_WRONGCRC);
	if (swapped.data_id != r->data_id) {
		/* low byte first: the swapped order is a different CRC */
		assert_int_equal(e2e_p05_check(&swapped, &rx, r->protected_, r->len),
				 E2E_P01_STATUS_WRONGCRC);
	}
}

/* The maker's 24-byte FD wheel-speed frame: its checksum is P05 with Data
 * ID id ^ 0xF800 at offset 0; the speeds read back from bit 64. */
static void test_maker_fd_layout(void **state)
{
	const e2e_p05_config_t cfg = { WHEEL_FD_DATA_ID, 24U, 0U, 2U };
	e2e_p01_tx_t tx = { 9U };
	e2e_p01_rx_t rx;
	uint8_t d[24];
	uint32_t w;

	(void)state;
	assert_int_equal(WHEEL_FD_DATA_ID, 0xF8A0); /* 0x0A0 ^ 0xF800 */
	e2e_p01_rx_init(&rx);
	assert_int_equal(e2e_p05_check(&cfg, &rx, wheel_fd_frame, 24U), E2E_P01_STATUS_INITIAL);
	memcpy(d, wheel_fd_frame, sizeof(d));
	d[0] = 0U;
	d[1] = 0U;
	assert_int_equal(e2e_p05_protect(&cfg, &tx, d, 24U), SQ_OK);
	assert_memory_equal(d, wheel_fd_frame, sizeof(d));
	for (w = 0; w < 4U; w++) {
		const can_signal_t s = { (uint16_t)(64U + 14U * w), 14U, (uint8_t)CAN_SIGNAL_INTEL, 0U };

		assert_int_equal(can_signal_get(&s, d), wheel_fd_raws[w]);
	}
}

/* P01's machine with 256 counters: INITIAL, OK, REPEATED, OKSOMELOST,
 * WRONGSEQUENCE then resync (INITIAL), wrap 255 -> 0, NONEWDATA, length. */
static void test_sequence(void **state)
{
	const e2e_p05_config_t cfg = { 0x0BEEU, 16U, 4U, 2U };
	e2e_p01_tx_t tx = { 254U };
	e2e_p01_rx_t rx;
	uint8_t f[10][16];
	uint32_t i;

	(void)state;
	for (i = 0; i < 10U; i++) {
		memset(f[i], (int)(0x11U * i), sizeof(f[i]));
		assert_int_equal(e2e_p05_protect(&cfg, &tx, f[i], 16U), SQ_OK);
	}
	/* counters 254, 255, 0, 1, ... 7; every check first lets the tolerated
	 * jump grow by one (max_delta_counter 2 -> 3 after a frame) */
	assert_int_equal(f[0][6], 254);
	assert_int_equal(f[2][6], 0);
	e2e_p01_rx_init(&rx);
	assert_int_equal(e2e_p05_check(&cfg, &rx, f[0], 16U), E2E_P01_STATUS_INITIAL);
	assert_int_equal(e2e_p05_check(&cfg, &rx, f[1], 16U), E2E_P01_STATUS_OK);
	assert_int_equal(e2e_p05_check(&cfg, &rx, f[1], 16U), E2E_P01_STATUS_REPEATED);
	/* 255 -> 0 over the wrap: delta 1 */
	assert_int_equal(e2e_p05_check(&cfg, &rx, f[2], 16U), E2E_P01_STATUS_OK);
	/* 0 -> 2: one lost, within max_delta_counter 2 */
	assert_int_equal(e2e_p05_check(&cfg, &rx, f[4], 16U), E2E_P01_STATUS_OKSOMELOST);
	assert_int_equal(rx.lost_data, 1);
	/* 2 -> 7: delta 5 > 3: WRONGSEQUENCE, 7 adopted */
	assert_int_equal(e2e_p05_check(&cfg, &rx, f[9], 16U), E2E_P01_STATUS_WRONGSEQUENCE);
	assert_int_equal(e2e_p05_check(&cfg, &rx, NULL, 0U), E2E_P01_STATUS_NONEWDATA);
	/* a restarted sender: the next frame of the adopted sequence is INITIAL */
	tx.counter = 8U;
	memset(f[0], 0x77, sizeof(f[0]));
	assert_int_equal(e2e_p05_protect(&cfg, &tx, f[0], 16U), SQ_OK);
	assert_int_equal(e2e_p05_check(&cfg, &rx, f[0], 16U), E2E_P01_STATUS_INITIAL);
	/* a frame of another length is WRONGCRC, never read beyond len */
	assert_int_equal(e2e_p05_check(&cfg, &rx, f[1], 12U), E2E_P01_STATUS_WRONGCRC);
	assert_int_equal(rx.status_count[E2E_P01_STATUS_INITIAL], 2);
	assert_int_equal(rx.status_count[E2E_P01_STATUS_WRONGCRC], 1);
	assert_int_equal(rx.status_count[E2E_P01_STATUS_WRONGSEQUENCE], 1);
}

/* The tolerated jump grows by one per cycle without a frame (P01's rule)
 * and up to 255 with 256 counter values. */
static void test_tolerance_grows_to_255(void **state)
{
	const e2e_p05_config_t cfg = { 1U, 3U, 0U, 1U };
	e2e_p01_rx_t rx;
	uint32_t i;

	(void)state;
	e2e_p01_rx_init(&rx);
	for (i = 0; i < 300U; i++) {
		(void)e2e_p05_check(&cfg, &rx, NULL, 0U);
	}
	assert_int_equal(rx.max_delta_counter, 255);
}

static void test_config_and_contracts(void **state)
{
	e2e_p05_config_t c = { 1U, 64U, 61U, 255U };
	e2e_p01_tx_t tx = { 0U };
	e2e_p01_rx_t rx;
	uint8_t d[64] = { 0 };

	(void)state;
	assert_int_equal(e2e_p05_config_check(&c), SQ_OK);
	c.offset_byte = 62U; /* header beyond the frame */
	assert_int_equal(e2e_p05_config_check(&c), SQ_EINVAL);
	c.offset_byte = 0U;
	c.data_len = 2U;
	assert_int_equal(e2e_p05_config_check(&c), SQ_EINVAL);
	c.data_len = 65U;
	assert_int_equal(e2e_p05_config_check(&c), SQ_EINVAL);
	c.data_len = 8U;
	c.max_delta_counter = 0U;
	assert_int_equal(e2e_p05_config_check(&c), SQ_EINVAL);
	e2e_p01_rx_init(&rx);
	/* a bad configuration is the caller's error, never a wrong CRC */
	expect_assert_failure(e2e_p05_check(&c, &rx, d, 8U));
	expect_assert_failure(e2e_p05_protect(&c, &tx, d, 8U));
	c.max_delta_counter = 1U;
	expect_assert_failure(e2e_p05_protect(&c, &tx, d, 12U)); /* buffer of another length */
	expect_assert_failure(e2e_p05_config_check(NULL));
	expect_assert_failure(e2e_p05_check(&c, NULL, d, 8U));
	expect_assert_failure(e2e_p05_protect(&c, NULL, d, 8U));
	expect_assert_failure(crc16_ccitt(NULL, 1U));
}

SQ_CMOCKA_MAIN(
	cmocka_unit_test(test_published_example),
	cmocka_unit_test(test_random_frames_equal_python),
	cmocka_unit_test(test_data_id_matters),
	cmocka_unit_test(test_maker_fd_layout),
	cmocka_unit_test(test_sequence),
	cmocka_unit_test(test_tolerance_grows_to_255),
	cmocka_unit_test(test_config_and_contracts))
