/* SPDX-License-Identifier: MIT */
/*
 * Unit tests of the input map's building blocks, both numeric builds:
 * E2E P02 (CRC-8H2F) and the counter machine with a modulus, input_conv
 * (units to v0 [um/s] and N [mN]). The DBC bit layouts (can_signal):
 * tests/firmware/protocol/test_can_signal.c.
 *
 * Every expected value is derived by hand from the DBC conventions (bit
 * numbering in firmware/protocol/can_signal.h) or from the conversions of
 * docs/vehicle.md (worked in the comments),
 * never from the code under test. The P02 vector is the AUTOSAR PRS E2E
 * protocol's Profile 2 example (DataIDList 0x01..0x10, bytes 1..7 =
 * 01 00 00 00 00 00 00 -> CRC 0x1B), which a bitwise Python CRC
 * (poly 0x2F, init 0xFF, xorout 0xFF) reproduces.
 *
 * Contracts: NULL pointers, a P02 configuration its check
 * refuses, a conversion not built by input_conv_make go to
 * hal_contract_failed (caught with expect_assert_failure,
 * tests/support/test_contract.c); bad data (a short or corrupted frame, an
 * unknown unit string) keeps its error code.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "can_signal.h"
#include "e2e_p02.h"
#include "input_conv.h"
#include "sq_status.h"

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
	/* 40 bar x 2290 mm^2 = 9.16 kN (a 54 mm piston at 40 bar) */
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

SQ_CMOCKA_MAIN(
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
	cmocka_unit_test(test_torque_to_force))
