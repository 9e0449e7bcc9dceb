/* SPDX-License-Identifier: MIT */
/*
 * e2e_p02_protect keeps what a calibration may place in byte 1's high
 * nibble (signal bits 12-15: the counter only owns bits 8-11), both numeric
 * builds. Frames: bytes 2..7 = 12 34 56 78 9A BC, DataIDList 0x01..0x10 (the
 * AUTOSAR PRS example's), byte 1's high nibble set before protecting.
 *
 * Expected CRCs from two independent references, which agree: a bitwise
 * CRC-8H2F in Python (MSB first, poly 0x2F, init 0xFF, xorout 0xFF; check
 * value 0xDF over "123456789", the PRS example 0x1B) and
 * crcmod.mkCrcFun(0x12F, initCrc=0x00, rev=False, xorOut=0xFF), each over
 * bytes 1..7 then DataIDList[counter]:
 *   byte 1 0xA5 (nibble A, counter 5, ID 0x06) -> CRC 0xB4
 *   byte 1 0xF0 (nibble F, counter 0, ID 0x01) -> CRC 0xD6
 *   byte 1 0x3F (nibble 3, counter 15, ID 0x10) -> CRC 0x40
 * (dropping the nibble would give 0x5C, 0x4A, 0x89).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "e2e_p01.h"
#include "e2e_p02.h"
#include "sq_status.h"

static e2e_p02_config_t prs_config(void)
{
	e2e_p02_config_t c;

	for (uint32_t i = 0U; i < E2E_P02_DATA_ID_COUNT; i++) {
		c.data_id_list[i] = (uint8_t)(i + 1U);
	}
	c.data_len = 8U;
	c.max_delta_counter = 1U;
	return c;
}

static void test_protect_keeps_byte1_high_nibble(void **state)
{
	static const struct {
		uint8_t nibble;
		uint8_t counter;
		uint8_t byte1;
		uint8_t crc;
	} rows[] = {
		{ 0xAU, 5U, 0xA5U, 0xB4U },
		{ 0xFU, 0U, 0xF0U, 0xD6U },
		{ 0x3U, 15U, 0x3FU, 0x40U },
	};
	const e2e_p02_config_t cfg = prs_config();

	(void)state;
	for (size_t i = 0; i < sizeof(rows) / sizeof(rows[0]); i++) {
		uint8_t d[8] = { 0x00, 0x00, 0x12, 0x34, 0x56, 0x78, 0x9A, 0xBC };
		e2e_p01_tx_t tx;
		e2e_p01_rx_t rx;

		e2e_p01_tx_init(&tx);
		tx.counter = rows[i].counter;
		/* a stale counter in the low nibble is overwritten, the high
		 * nibble kept */
		d[1] = (uint8_t)((rows[i].nibble << 4) | 0x0CU);
		assert_int_equal(e2e_p02_protect(&cfg, &tx, d, 8U), SQ_OK);
		assert_int_equal(d[1], rows[i].byte1);
		assert_int_equal(d[0], rows[i].crc);
		assert_int_equal(tx.counter, (rows[i].counter + 1U) % 16U);
		/* the receiver accepts it (first frame) */
		e2e_p01_rx_init(&rx);
		assert_int_equal(e2e_p02_check(&cfg, &rx, d, 8U), E2E_P01_STATUS_INITIAL);
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_protect_keeps_byte1_high_nibble),
	};

#if defined(SQUEAL_NUMERIC_FIXED)
	return cmocka_run_group_tests_name("e2e p02 (fixed)", tests, NULL, NULL);
#else
	return cmocka_run_group_tests_name("e2e p02 (float)", tests, NULL, NULL);
#endif
}
