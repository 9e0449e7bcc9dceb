/* SPDX-License-Identifier: MIT */
/*
 * CRC-16/CCITT-FALSE (firmware/protocol/crc16_ccitt.c), the CRC of AUTOSAR
 * E2E Profile 5, against independent references: the CRC catalogue's check
 * value 0x29B1 over "123456789", and random data of every FD length whose
 * CRC Python's binascii.crc_hqx(data, 0xFFFF) computed
 * (gen_e2e_p05_vectors.py -> e2e_p05_ref.h). Both numeric builds.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "crc16_ccitt.h"
#include "e2e_p05_ref.h"

#define N_OF(a) (sizeof(a) / sizeof((a)[0]))

static void test_crc16_check_value(void **state)
{
	static const uint8_t s[9] = { '1', '2', '3', '4', '5', '6', '7', '8', '9' };

	(void)state;
	assert_int_equal(crc16_ccitt(s, 9U), 0x29B1);
	assert_int_equal(CRC16_CCITT_CHECK, 0x29B1);
	/* continuation */
	assert_int_equal(crc16_ccitt_update(crc16_ccitt(s, 4U), &s[4], 5U), 0x29B1);
	assert_int_equal(crc16_ccitt(NULL, 0U), 0xFFFF);
}

static void test_crc16_equals_crc_hqx(void **state)
{
	size_t i;

	(void)state;
	for (i = 0; i < N_OF(crc16_refs); i++) {
		assert_int_equal(crc16_ccitt(crc16_refs[i].data, crc16_refs[i].len), crc16_refs[i].crc);
	}
}

SQ_CMOCKA_MAIN(
	cmocka_unit_test(test_crc16_check_value),
	cmocka_unit_test(test_crc16_equals_crc_hqx))
