/* SPDX-License-Identifier: MIT */
/*
 * DBC signal layouts (firmware/protocol/can_signal.c), both numeric builds:
 * Intel and Motorola bit numbering, sign extension, the smallest DLC that
 * holds a signal, overlap, put as the inverse of get.
 *
 * Every expected value is derived by hand from the DBC conventions in
 * firmware/protocol/can_signal.h (worked in the comments), never from the code under test.
 * Contracts: NULL pointers and a bad descriptor given to get/value/put/raw_of
 * go to hal_contract_failed (caught with expect_assert_failure,
 * tests/support/test_contract.c); the validation functions answer for a bad
 * descriptor.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "can_signal.h"

static can_signal_t sig(uint16_t start, uint8_t len, uint8_t order, uint8_t sgn)
{
	return (can_signal_t){ start, len, order, sgn };
}

static void test_intel_16_bit(void **state)
{
	const can_signal_t s = sig(8, 16, CAN_SIGNAL_INTEL, 0);
	const uint8_t d[8] = { 0xFF, 0x34, 0x12, 0xFF };

	(void)state;
	assert_int_equal(can_signal_get(&s, d), 0x1234);
	assert_int_equal(can_signal_min_dlc(&s), 3);
}

static void test_intel_14_bit_between_other_bits(void **state)
{
	/* 2|14@1+: bits 2..7 of byte 0 (raw bits 0..5), byte 1 (raw 6..13) */
	const can_signal_t s = sig(2, 14, CAN_SIGNAL_INTEL, 0);
	const uint8_t ones[8] = { 0xFC, 0xFF };
	const uint8_t ends[8] = { 0x07, 0x80 }; /* bit 2 -> raw 1, bit 15 -> raw 2^13; bits 0,1 not ours */

	(void)state;
	assert_int_equal(can_signal_get(&s, ones), 0x3FFF);
	assert_int_equal(can_signal_get(&s, ends), 0x2001);
	assert_int_equal(can_signal_min_dlc(&s), 2);
}

static void test_motorola_sawtooth(void **state)
{
	/* 22|15@0+: 22..16 (byte 2 bits 6..0, the raw's top 7 bits), then
	 * 31..24 (byte 3, the low 8): raw = (b2 & 0x7F) << 8 | b3 */
	const can_signal_t s = sig(22, 15, CAN_SIGNAL_MOTOROLA, 0);
	const uint8_t d[8] = { 0, 0, 0xD5, 0xAA };

	(void)state;
	assert_int_equal(can_signal_get(&s, d), 0x55AA);
	assert_int_equal(can_signal_min_dlc(&s), 4);
}

static void test_motorola_big_endian_16_and_32(void **state)
{
	const can_signal_t s16 = sig(7, 16, CAN_SIGNAL_MOTOROLA, 0);
	const can_signal_t s32 = sig(7, 32, CAN_SIGNAL_MOTOROLA, 0);
	const can_signal_t i32 = sig(32, 32, CAN_SIGNAL_INTEL, 0);
	const uint8_t d[8] = { 0x12, 0x34, 0x56, 0x78, 0x78, 0x56, 0x34, 0x12 };

	(void)state;
	assert_int_equal(can_signal_get(&s16, d), 0x1234);
	assert_int_equal(can_signal_get(&s32, d), 0x12345678U);
	assert_int_equal(can_signal_get(&i32, d), 0x12345678U);
	assert_int_equal(can_signal_min_dlc(&s32), 4);
	assert_int_equal(can_signal_min_dlc(&i32), 8);
}

static void test_motorola_short_in_one_byte(void **state)
{
	/* 5|3@0+: bits 5,4,3 of byte 0; 0x28 = 0b00101000 -> 101 = 5 */
	const can_signal_t s = sig(5, 3, CAN_SIGNAL_MOTOROLA, 0);
	const uint8_t d[8] = { 0x28 };

	(void)state;
	assert_int_equal(can_signal_get(&s, d), 5);
	assert_int_equal(can_signal_min_dlc(&s), 1);
}

/* An Intel signal whose last bit is bit 0 of a byte needs that byte:
 * 0|9@1+ takes bits 0..8 (bytes 0 and 1), 7|2@1+ bits 7 and 8; 0|8@1+
 * only byte 0. (min_dlc is what a short frame is counted against.) */
static void test_intel_min_dlc_at_byte_edges(void **state)
{
	const can_signal_t nine = sig(0, 9, CAN_SIGNAL_INTEL, 0);
	const can_signal_t two = sig(7, 2, CAN_SIGNAL_INTEL, 0);
	const can_signal_t eight = sig(0, 8, CAN_SIGNAL_INTEL, 0);
	const uint8_t d[8] = { 0x80, 0x01 };

	(void)state;
	assert_int_equal(can_signal_min_dlc(&nine), 2);
	assert_int_equal(can_signal_min_dlc(&two), 2);
	assert_int_equal(can_signal_min_dlc(&eight), 1);
	assert_int_equal(can_signal_get(&two, d), 3);      /* bit 7 and bit 8 set */
	assert_int_equal(can_signal_get(&nine, d), 0x180); /* 1 1000 0000 */
}

static void test_signed_values(void **state)
{
	const can_signal_t s = sig(0, 12, CAN_SIGNAL_INTEL, 1);
	const uint8_t minus1[8] = { 0xFF, 0x0F };
	const uint8_t most_neg[8] = { 0x00, 0x08 };
	const uint8_t most_pos[8] = { 0xFF, 0x07 };
	const can_signal_t s32 = sig(0, 32, CAN_SIGNAL_INTEL, 1);
	const uint8_t m32[8] = { 0x00, 0x00, 0x00, 0x80 };

	(void)state;
	assert_int_equal(can_signal_value(&s, can_signal_get(&s, minus1)), -1);
	assert_int_equal(can_signal_value(&s, can_signal_get(&s, most_neg)), -2048);
	assert_int_equal(can_signal_value(&s, can_signal_get(&s, most_pos)), 2047);
	assert_true(can_signal_value(&s32, can_signal_get(&s32, m32)) == -2147483648LL);
	assert_int_equal(can_signal_raw_of(&s, -1), 0xFFF);
}

static void test_bad_descriptors(void **state)
{
	const can_signal_t zero = sig(0, 0, CAN_SIGNAL_INTEL, 0);
	const can_signal_t long33 = sig(0, 33, CAN_SIGNAL_INTEL, 0);
	/* the frame ends at bit 511 (64 bytes of CAN FD) */
	const can_signal_t intel_out = sig(508, 8, CAN_SIGNAL_INTEL, 0);
	const can_signal_t moto_out = sig(511, 16, CAN_SIGNAL_MOTOROLA, 0); /* 511..504, then byte 64 */
	const can_signal_t moto_ok = sig(0, 2, CAN_SIGNAL_MOTOROLA, 0);    /* bit 0, then bit 15 */
	const can_signal_t start64 = sig(512, 1, CAN_SIGNAL_INTEL, 0);

	(void)state;
	assert_int_equal(can_signal_min_dlc(&zero), 0);
	assert_int_equal(can_signal_min_dlc(&long33), 0);
	assert_int_equal(can_signal_min_dlc(&intel_out), 0);
	assert_int_equal(can_signal_min_dlc(&moto_out), 0);
	assert_int_equal(can_signal_min_dlc(&start64), 0);
	assert_int_equal(can_signal_min_dlc(&moto_ok), 2);
}

static void test_signal_contracts(void **state)
{
	const can_signal_t ok = sig(0, 8, CAN_SIGNAL_INTEL, 0);
	const can_signal_t bad = sig(508, 8, CAN_SIGNAL_INTEL, 0); /* beyond bit 511 */
	const can_signal_t order = sig(0, 8, 2U, 0);               /* no such order */
	uint8_t d[8] = { 0 };

	(void)state;
	expect_assert_failure(can_signal_min_dlc(NULL));
	expect_assert_failure(can_signal_valid(NULL));
	expect_assert_failure(can_signal_overlap(NULL, &ok));
	expect_assert_failure(can_signal_overlap(&ok, NULL));
	expect_assert_failure(can_signal_get(&ok, NULL));
	expect_assert_failure(can_signal_get(NULL, d));
	expect_assert_failure(can_signal_get(&bad, d));
	expect_assert_failure(can_signal_get(&order, d));
	expect_assert_failure(can_signal_value(&bad, 1U));
	expect_assert_failure(can_signal_raw_of(&bad, -1));
	expect_assert_failure(can_signal_put(&bad, d, 1U));
	expect_assert_failure(can_signal_put(&ok, NULL, 1U));
	/* the validation functions answer for a bad descriptor */
	assert_false(can_signal_valid(&bad));
	assert_false(can_signal_valid(&order));
	assert_true(can_signal_overlap(&bad, &ok));
}

static void test_overlap(void **state)
{
	const can_signal_t a = sig(22, 15, CAN_SIGNAL_MOTOROLA, 0); /* 16..22, 24..31 */
	const can_signal_t b = sig(23, 1, CAN_SIGNAL_INTEL, 0);     /* the gap     */
	const can_signal_t c = sig(24, 4, CAN_SIGNAL_INTEL, 0);

	(void)state;
	assert_false(can_signal_overlap(&a, &b));
	assert_true(can_signal_overlap(&a, &c));
}

static void test_put_is_the_inverse_and_keeps_other_bits(void **state)
{
	const can_signal_t list[] = {
		sig(22, 15, CAN_SIGNAL_MOTOROLA, 0), sig(2, 14, CAN_SIGNAL_INTEL, 0),
		sig(7, 32, CAN_SIGNAL_MOTOROLA, 0), sig(39, 12, CAN_SIGNAL_MOTOROLA, 1),
	};
	uint8_t d[8];
	size_t i;

	(void)state;
	/* Motorola 22|15 with 0x55AA into a frame of ones: b2 = 0x80|0x55, b3 = 0xAA */
	memset(d, 0xFF, sizeof(d));
	can_signal_put(&list[0], d, 0x55AA);
	assert_int_equal(d[2], 0xD5);
	assert_int_equal(d[3], 0xAA);
	assert_int_equal(d[1], 0xFF);
	assert_int_equal(d[4], 0xFF);
	for (i = 0; i < sizeof(list) / sizeof(list[0]); i++) {
		const uint32_t raw = (uint32_t)(0xA5A5A5A5UL &
			((list[i].length == 32U) ? 0xFFFFFFFFUL : ((1UL << list[i].length) - 1UL)));

		memset(d, 0, sizeof(d));
		can_signal_put(&list[i], d, raw);
		assert_int_equal(can_signal_get(&list[i], d), raw);
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_intel_16_bit),
		cmocka_unit_test(test_intel_14_bit_between_other_bits),
		cmocka_unit_test(test_motorola_sawtooth),
		cmocka_unit_test(test_motorola_big_endian_16_and_32),
		cmocka_unit_test(test_motorola_short_in_one_byte),
		cmocka_unit_test(test_intel_min_dlc_at_byte_edges),
		cmocka_unit_test(test_signed_values),
		cmocka_unit_test(test_bad_descriptors),
		cmocka_unit_test(test_signal_contracts),
		cmocka_unit_test(test_overlap),
		cmocka_unit_test(test_put_is_the_inverse_and_keeps_other_bits),
	};

	return cmocka_run_group_tests_name("can_signal", tests, NULL, NULL);
}
