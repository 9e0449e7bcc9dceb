/* SPDX-License-Identifier: MIT */
/*
 * Unit tests of the input map's building blocks, both numeric builds:
 * can_signal (DBC bit layouts), E2E P02 (CRC-8H2F) and the counter machine
 * with a modulus, input_conv (units to v0 [um/s] and N [mN]).
 *
 * Every expected value is derived by hand from the DBC conventions in
 * shared/vehicle-bus.md or from the formulas there (worked in the comments),
 * never from the code under test. The P02 vector is the AUTOSAR PRS E2E
 * protocol's Profile 2 example (DataIDList 0x01..0x10, bytes 1..7 =
 * 01 00 00 00 00 00 00 -> CRC 0x1B), which a bitwise Python CRC
 * (poly 0x2F, init 0xFF, xorout 0xFF) reproduces.
 *
 * Contracts (issue 10 item 4): NULL pointers, a bad descriptor given to
 * get/value/put/raw_of, a P02 configuration its check refuses, a conversion
 * not built by input_conv_make go to hal_contract_failed (caught with
 * expect_assert_failure, tests/support/test_contract.c); bad data (a short
 * or corrupted frame, an unknown unit string, a bad descriptor given to the
 * validation functions) keeps its error code.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "can_signal.h"
#include "e2e_p02.h"
#include "input_conv.h"
#include "sq_status.h"

/* ---- can_signal ---------------------------------------------------------- */

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

/* ---- E2E P02 --------------------------------------------------------------- */

static const uint8_t check_string[9] = { '1', '2', '3', '4', '5', '6', '7', '8', '9' };

static e2e_p02_config_t p02_cfg(void)
{
	e2e_p02_config_t c = { { 0 }, 8U, 1U };
	uint8_t i;

	for (i = 0U; i < 16U; i++) {
		c.data_id_list[i] = (uint8_t)(i + 1U);
	}
	return c;
}

static void test_crc8_h2f_check_value(void **state)
{
	(void)state;
	assert_int_equal(crc8_h2f(check_string, 9), 0xDF);
}

static void test_p02_spec_example(void **state)
{
	const e2e_p02_config_t c = p02_cfg();
	e2e_p01_tx_t tx = { 1U };
	uint8_t d[8] = { 0 };
	e2e_p01_rx_t rx;

	(void)state;
	assert_int_equal(e2e_p02_protect(&c, &tx, d, 8), SQ_OK);
	assert_int_equal(d[1], 0x01);
	assert_int_equal(d[0], 0x1B);
	assert_int_equal(tx.counter, 2);
	e2e_p01_rx_init(&rx);
	assert_int_equal(e2e_p02_check(&c, &rx, d, 8), E2E_P01_STATUS_INITIAL);
	d[0] ^= 1U;
	assert_int_equal(e2e_p02_check(&c, &rx, d, 8), E2E_P01_STATUS_WRONGCRC);
}

static void test_p02_sequence_wraps_at_16(void **state)
{
	const e2e_p02_config_t c = p02_cfg();
	e2e_p01_tx_t tx = { 14U };
	e2e_p01_rx_t rx;
	uint8_t d[8] = { 0, 0, 0x12, 0x34 };
	uint8_t saved[8];

	(void)state;
	e2e_p01_rx_init(&rx);
	assert_int_equal(e2e_p02_protect(&c, &tx, d, 8), SQ_OK);
	assert_int_equal(e2e_p02_check(&c, &rx, d, 8), E2E_P01_STATUS_INITIAL);
	assert_int_equal(e2e_p02_protect(&c, &tx, d, 8), SQ_OK); /* counter 15 is valid */
	assert_int_equal(d[1] & 0x0F, 15);
	assert_int_equal(e2e_p02_check(&c, &rx, d, 8), E2E_P01_STATUS_OK);
	memcpy(saved, d, 8);
	assert_int_equal(e2e_p02_check(&c, &rx, saved, 8), E2E_P01_STATUS_REPEATED);
	assert_int_equal(e2e_p02_protect(&c, &tx, d, 8), SQ_OK);   /* 0: lost one? no, next */
	assert_int_equal(d[1] & 0x0F, 0);
	assert_int_equal(e2e_p02_check(&c, &rx, d, 8), E2E_P01_STATUS_OK);
	/* one frame lost: counter 2 after 0 with the jump grown by the cycle */
	assert_int_equal(e2e_p02_protect(&c, &tx, d, 8), SQ_OK);
	assert_int_equal(e2e_p02_protect(&c, &tx, d, 8), SQ_OK);
	assert_int_equal(e2e_p02_check(&c, &rx, NULL, 0), E2E_P01_STATUS_NONEWDATA);
	assert_int_equal(e2e_p02_check(&c, &rx, d, 8), E2E_P01_STATUS_OKSOMELOST);
	assert_int_equal(rx.lost_data, 1);
}

static void test_p02_contracts_and_bad_frames(void **state)
{
	const e2e_p02_config_t c = p02_cfg();
	e2e_p02_config_t short_len = c;
	e2e_p02_config_t no_delta = c;
	e2e_p01_tx_t tx = { 0U };
	e2e_p01_tx_t tx16 = { 16U };
	e2e_p01_rx_t rx;
	uint8_t d[8] = { 0 };

	(void)state;
	short_len.data_len = 1U;
	no_delta.max_delta_counter = 0U;
	e2e_p01_rx_init(&rx);
	/* the configuration check answers for data it is given */
	assert_int_equal(e2e_p02_config_check(&short_len), SQ_EINVAL);
	assert_int_equal(e2e_p02_config_check(&no_delta), SQ_EINVAL);
	assert_int_equal(e2e_p02_config_check(&c), SQ_OK);
	expect_assert_failure(e2e_p02_config_check(NULL));
	/* a NULL or refused configuration is never a wrong CRC */
	expect_assert_failure(e2e_p02_check(NULL, &rx, d, 8));
	expect_assert_failure(e2e_p02_check(&c, NULL, d, 8));
	expect_assert_failure(e2e_p02_check(&short_len, &rx, d, 8));
	expect_assert_failure(e2e_p02_check(&no_delta, &rx, d, 8));
	expect_assert_failure(e2e_p02_protect(NULL, &tx, d, 8));
	expect_assert_failure(e2e_p02_protect(&c, NULL, d, 8));
	expect_assert_failure(e2e_p02_protect(&c, &tx, NULL, 8));
	expect_assert_failure(e2e_p02_protect(&c, &tx, d, 7));   /* not data_len */
	expect_assert_failure(e2e_p02_protect(&c, &tx16, d, 8)); /* counter 16 */
	expect_assert_failure(e2e_p02_protect(&no_delta, &tx, d, 8));
	expect_assert_failure(e2e_p02_crc(NULL, d, 8));
	expect_assert_failure(e2e_p02_crc(&c, NULL, 8));
	expect_assert_failure(e2e_p02_crc(&c, d, 1));
	/* bad data: a frame of another length or a flipped bit is WRONGCRC */
	assert_int_equal(e2e_p02_protect(&c, &tx, d, 8), SQ_OK);
	assert_int_equal(e2e_p02_check(&c, &rx, d, 7), E2E_P01_STATUS_WRONGCRC);
	d[5] ^= 0x10U;
	assert_int_equal(e2e_p02_check(&c, &rx, d, 8), E2E_P01_STATUS_WRONGCRC);
}

static void test_counter_modulus_4(void **state)
{
	e2e_p01_rx_t rx;

	(void)state;
	e2e_p01_rx_init(&rx);
	assert_int_equal(e2e_rx_sequence(&rx, 3, 4, 1), E2E_P01_STATUS_INITIAL);
	assert_int_equal(e2e_rx_sequence(&rx, 0, 4, 1), E2E_P01_STATUS_OK);   /* 3 -> 0 wraps */
	assert_int_equal(e2e_rx_sequence(&rx, 0, 4, 1), E2E_P01_STATUS_REPEATED);
	assert_int_equal(e2e_rx_sequence(&rx, 2, 4, 1), E2E_P01_STATUS_WRONGSEQUENCE);
	assert_int_equal(e2e_rx_sequence(&rx, 3, 4, 1), E2E_P01_STATUS_INITIAL);
	/* the tolerated jump grows by one per cycle, up to modulus - 1 */
	e2e_rx_cycle(&rx, 4);
	e2e_rx_cycle(&rx, 4);
	e2e_rx_cycle(&rx, 4);
	assert_int_equal(rx.max_delta_counter, 3);
}

/* ---- units and conversion ------------------------------------------------ */

static const input_geom_t geom = {
	.pad_radius_um = 120000U, .wheel_radius_um = 300000U,
	.piston_area_cmm2 = 229000U, .efficiency_ppm = 1000000U,
	.axle_factor_ppm = 1000000U,
};

static int32_t conv(int32_t fm, int8_t fe, int32_t om, int8_t oe, const char *unit,
		    const input_geom_t *g, int64_t raw)
{
	input_unit_t u;
	input_conv_t c;

	assert_int_equal(input_unit_parse(unit, &u), SQ_OK);
	assert_int_equal(input_conv_make(fm, fe, om, oe, u, g, &c), SQ_OK);
	return input_conv_apply(&c, raw);
}

static void test_unit_strings(void **state)
{
	input_unit_t u;
	static const char *const good[] = { "km/h", "Km/h", "KPH", "kph", "m/s", "mph",
		"rad/s", "RPM", "1/min", "N", "kn", "bar", "Bar", "kPa", "MPA", "psi", "Nm", "nm" };
	static const input_unit_t want[] = { INPUT_UNIT_KMH, INPUT_UNIT_KMH, INPUT_UNIT_KMH,
		INPUT_UNIT_KMH, INPUT_UNIT_MPS, INPUT_UNIT_MPH, INPUT_UNIT_RADPS, INPUT_UNIT_RPM,
		INPUT_UNIT_RPM, INPUT_UNIT_N, INPUT_UNIT_KN, INPUT_UNIT_BAR, INPUT_UNIT_BAR,
		INPUT_UNIT_KPA, INPUT_UNIT_MPA, INPUT_UNIT_PSI, INPUT_UNIT_NM, INPUT_UNIT_NM };
	size_t i;

	(void)state;
	for (i = 0; i < sizeof(good) / sizeof(good[0]); i++) {
		assert_int_equal(input_unit_parse(good[i], &u), SQ_OK);
		assert_int_equal(u, want[i]);
	}
	assert_int_equal(input_unit_parse("", &u), SQ_ENOENT);
	assert_int_equal(input_unit_parse("%", &u), SQ_ENOENT);
	assert_int_equal(input_unit_parse("km/h ", &u), SQ_ENOENT);
	assert_int_equal(input_unit_qty(INPUT_UNIT_PSI), INPUT_QTY_FORCE);
	assert_int_equal(input_unit_qty(INPUT_UNIT_NM), INPUT_QTY_TORQUE);
	assert_int_equal(input_unit_qty(INPUT_UNIT_RPM), INPUT_QTY_SPEED);
}

static void test_speed_conversions(void **state)
{
	(void)state;
	/* 100 km/h wheel speed: v0 = 100/3.6 x 0.12/0.3 = 11.1111.. m/s */
	assert_int_equal(conv(1, -2, 0, 0, "km/h", &geom, 10000), 11111111);
	assert_int_equal(conv(3125, -5, 0, 0, "kph", &geom, 3200), 11111111); /* 1/32 km/h */
	/* offset -67.67 km/h: raw 16767 x 0.01 - 67.67 = 100 km/h; raw 0:
	 * -67.67/3.6 x 0.4 = -7.518888.. m/s */
	assert_int_equal(conv(1, -2, -6767, -2, "km/h", &geom, 16767), 11111111);
	assert_int_equal(conv(1, -2, -6767, -2, "km/h", &geom, 0), -7518889);
	/* 1/64 m/s: 640 -> 10 m/s -> v0 4 m/s */
	assert_int_equal(conv(15625, -6, 0, 0, "m/s", &geom, 640), 4000000);
	/* 100 mph = 44.704 m/s -> 17.8816 m/s */
	assert_int_equal(conv(1, -2, 0, 0, "mph", &geom, 10000), 17881600);
	/* DiscSpeed: 0.01 rad/s, 100 rad/s x 0.12 m = 12 m/s */
	assert_int_equal(conv(1, -2, 0, 0, "rad/s", &geom, 10000), 12000000);
	/* 955 rpm x 2 pi / 60 x 0.12 m = 12.000883937 m/s */
	assert_int_equal(conv(1, 0, 0, 0, "rpm", &geom, 955), 12000884);
	assert_int_equal(conv(1, 0, 0, 0, "1/min", &geom, 955), 12000884);
}

static void test_force_and_pressure_conversions(void **state)
{
	input_geom_t g = geom;

	(void)state;
	assert_int_equal(conv(5, -1, 0, 0, "N", &geom, 2000), 1000000);     /* PadForce 0.5 N */
	assert_int_equal(conv(1, -3, 0, 0, "kN", &geom, 9160), 9160000);
	/* 40 bar x 2290 mm^2 = 9.16 kN (vehicle-bus.md's example) */
	assert_int_equal(conv(1, -1, 0, 0, "bar", &geom, 400), 9160000);
	assert_int_equal(conv(1, 0, 0, 0, "kPa", &geom, 4000), 9160000);
	assert_int_equal(conv(1, -3, 0, 0, "MPa", &geom, 4000), 9160000);
	/* 100 psi = 689475.7 Pa x 2290e-6 m^2 = 1578.8993 N */
	assert_int_equal(conv(1, 0, 0, 0, "psi", &geom, 100), 1578899);
	/* eta 0.9, axle factor 0.5: 9160 N x 0.45 */
	g.efficiency_ppm = 900000U;
	g.axle_factor_ppm = 500000U;
	assert_int_equal(conv(1, -1, 0, 0, "bar", &g, 400), 4122000);
	/* 0.3 bar with an offset of -3 bar: raw 110 -> 30 bar -> 6870 N */
	assert_int_equal(conv(3, -1, -3, 0, "bar", &geom, 110), 6870000);
}

static void test_refused_conversions(void **state)
{
	input_conv_t c;
	input_geom_t g = geom;

	(void)state;
	assert_int_equal(input_conv_make(0, 0, 0, 0, INPUT_UNIT_N, &geom, &c), SQ_EINVAL);
	g.piston_area_cmm2 = 0U;
	assert_int_equal(input_conv_make(1, 0, 0, 0, INPUT_UNIT_BAR, &g, &c), SQ_EINVAL);
	assert_int_equal(input_conv_make(1, 0, 0, 0, INPUT_UNIT_N, &g, &c), SQ_OK);
	assert_int_equal(input_conv_make(1, 0, 0, 0, INPUT_UNIT_COUNT, &geom, &c), SQ_EINVAL);
}

static void test_conversion_contracts(void **state)
{
	input_unit_t u;
	input_conv_t c;
	const input_conv_t unmade = { 1, 0, 0, 0U, 0U, 0, 0U }; /* div 0: not from input_conv_make */

	(void)state;
	expect_assert_failure(input_unit_parse(NULL, &u));
	expect_assert_failure(input_unit_parse("km/h", NULL));
	expect_assert_failure(input_conv_make(1, 0, 0, 0, INPUT_UNIT_N, NULL, &c));
	expect_assert_failure(input_conv_make(1, 0, 0, 0, INPUT_UNIT_N, &geom, NULL));
	expect_assert_failure(input_conv_apply(NULL, 5));
	expect_assert_failure(input_conv_apply(&unmade, 5));
	expect_assert_failure(input_conv_torque_to_force(1000000, 0, 0U, 120000U, 1 << 28,
							 161061274, 2 << 24));
	expect_assert_failure(input_conv_torque_to_force(1000000, 0, 2U, 0U, 1 << 28,
							 161061274, 2 << 24));
	/* data: an unknown unit string is an error code, friction gone saturates */
	assert_int_equal(input_unit_parse("furlong/fortnight", &u), SQ_ENOENT);
	assert_int_equal(input_conv_torque_to_force(1000000, 0, 2U, 120000U, 0, 0, 2 << 24),
			 INT32_MAX);
}

static void test_torque_to_force(void **state)
{
	/* 1000 Nm, 2 faces, r_p 0.12 m; mu(0) = 0.25 + 0.15 = 0.4:
	 * N = 1000 / (2 x 0.4 x 0.12) = 10416.667 N; at high speed mu -> 0.25:
	 * 16666.667 N; a = 2 s/m at v0 = 1 m/s: mu = 0.25 + 0.15 e^-2
	 * = 0.270300083, N = 15414.954 N */
	const int32_t mu_inf = 1 << 28;
	const int32_t dmu = 161061274; /* 0.15 x 2^30 (calib default) */
	const int32_t a = 2 << 24;

	(void)state;
	assert_int_equal(conv(1, 0, 0, 0, "Nm", &geom, 1000), 1000000); /* mNm */
	assert_in_range(input_conv_torque_to_force(1000000, 0, 2, 120000U, mu_inf, dmu, a),
			10416666 - 2, 10416667 + 2);
	assert_in_range(input_conv_torque_to_force(1000000, 100000000, 2, 120000U, mu_inf, dmu, a),
			16666666 - 2, 16666667 + 2);
	assert_in_range(input_conv_torque_to_force(1000000, 1000000, 2, 120000U, mu_inf, dmu, a),
			15414954 - 20, 15414954 + 20);
	assert_int_equal(input_conv_torque_to_force(-5, 0, 2, 120000U, mu_inf, dmu, a), 0);
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
		cmocka_unit_test(test_crc8_h2f_check_value),
		cmocka_unit_test(test_p02_spec_example),
		cmocka_unit_test(test_p02_sequence_wraps_at_16),
		cmocka_unit_test(test_p02_contracts_and_bad_frames),
		cmocka_unit_test(test_counter_modulus_4),
		cmocka_unit_test(test_unit_strings),
		cmocka_unit_test(test_speed_conversions),
		cmocka_unit_test(test_force_and_pressure_conversions),
		cmocka_unit_test(test_refused_conversions),
		cmocka_unit_test(test_conversion_contracts),
		cmocka_unit_test(test_torque_to_force),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
