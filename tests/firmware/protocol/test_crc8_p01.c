/* SPDX-License-Identifier: MIT */
/*
 * CRC-8 of E2E Profile 1 (firmware/protocol/crc8_p01.c) and the SAE J1850
 * variant beside it, both numeric builds: the check values of the CRC
 * catalogue ("123456789" -> 0x37 and 0x4B) and every input against the
 * CRC's bitwise definition (tests/support/p01_frames.c, poly 0x1D).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "crc8_p01.h"
#include "p01_frames.h"

static const uint8_t check_string[9] = { '1', '2', '3', '4', '5', '6', '7', '8', '9' };

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

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_crc8_p01_check_value_is_0x37),
		cmocka_unit_test(test_crc8_sae_j1850_check_value_is_0x4b),
		cmocka_unit_test(test_crc8_table_matches_bitwise_definition),
		cmocka_unit_test(test_crc8_empty_and_null),
	};

	return cmocka_run_group_tests_name("crc8_p01", tests, NULL, NULL);
}
