/* SPDX-License-Identifier: MIT */
/*
 * The calibration block (firmware/monitor/calib.c): CRC-32, the stored
 * layout of calib.h, defaults = docs/model.md section 8 as hand-computed
 * Q integers, whole-block rejection of any corruption, every field's range.
 *
 * The layout table below is written from calib.h's description (header 8
 * bytes, the fields of calib_t in declaration order, little-endian, CRC-32
 * last), not taken from calib.c; the CRC reference is the bitwise
 * definition (reflected polynomial 0xEDB88320, init and xorout 0xFFFFFFFF).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "calib.h"
#include "sq_status.h"

static uint32_t ref_crc32(const uint8_t *d, size_t n)
{
	uint32_t c = 0xFFFFFFFFU;

	for (size_t i = 0; i < n; i++) {
		c ^= d[i];
		for (int k = 0; k < 8; k++) {
			c = (c & 1U) ? ((c >> 1) ^ 0xEDB88320U) : (c >> 1);
		}
	}
	return ~c;
}

static void put_le(uint8_t *p, uint32_t v, uint32_t size)
{
	for (uint32_t i = 0; i < size; i++) {
		p[i] = (uint8_t)(v >> (8U * i));
	}
}

static uint32_t get_le(const uint8_t *p, uint32_t size)
{
	uint32_t v = 0;

	for (uint32_t i = 0; i < size; i++) {
		v |= (uint32_t)p[i] << (8U * i);
	}
	return v;
}

static void reseal(uint8_t *buf)
{
	put_le(&buf[CALIB_BLOCK_LEN - 4U], ref_crc32(buf, CALIB_BLOCK_LEN - 4U), 4U);
}

/* name, offset in the block, size, signed, valid range, default */
typedef struct {
	const char *name;
	uint32_t off;
	uint32_t size;
	int is_signed;
	int64_t min;
	int64_t max;
	int64_t def;
} field_t;

static const field_t fields[] = {
	/* model: docs/model.md section 8 in the fixed build's Q formats:
	 * m 1 kg Q16 = 65536; w0 5000 rad/s Q12 = 20480000;
	 * D 0.023 Q30 = 24696061.95 -> 24696062; mu_inf 0.25 Q30 = 268435456;
	 * dmu 0.15 Q30 = 161061273.6 -> 161061274; a 2 s/m Q24 = 33554432 */
	{ "mass_q16", 8, 4, 1, 1, 10000LL << 16, 65536 },
	{ "omega0_q12", 12, 4, 1, 1, 500000LL << 12, 20480000 },
	{ "damping_q30", 16, 4, 1, 1, 1LL << 30, 24696062 },
	{ "mu_inf_q30", 20, 4, 1, 0, 3LL << 29, 268435456 },
	{ "delta_mu_q30", 24, 4, 1, -(3LL << 29), 3LL << 29, 161061274 },
	{ "slope_q24", 28, 4, 1, 0, 20LL << 24, 33554432 },
	{ "criterion", 32, 1, 0, 0, 1, 0 },           /* exact */
	{ "pad_radius_um", 33, 4, 0, 10000, 1000000, 120000 },
	{ "wheel_radius_um", 37, 4, 0, 10000, 2000000, 300000 },
	{ "bitrate_kbps", 41, 2, 0, 10, 1000, 500 },
	{ "disc_speed_id", 43, 2, 0, 0, 0x7FF, 0x110 },
	{ "pad_force_id", 45, 2, 0, 0, 0x7FF, 0x111 },
	{ "status_id", 47, 2, 0, 0, 0x7FF, 0x300 },
	{ "detail_id", 49, 2, 0, 0, 0x7FF, 0x301 },
	{ "diag_id", 51, 2, 0, 0, 0x7FF, 0x302 },
	{ "detail2_id", 53, 2, 0, 0, 0x7FF, 0x303 },
	{ "e2e_check_inputs", 55, 1, 0, 0, 1, 1 },
	{ "e2e_max_delta_counter", 56, 1, 0, 1, 14, 2 },
	{ "input_period_ms", 57, 2, 0, 1, 1000, 10 },
	{ "status_period_ms", 59, 2, 0, 1, 1000, 10 },
	{ "detail_period_ms", 61, 2, 0, 1, 10000, 100 },
	{ "diag_period_ms", 63, 2, 0, 100, 10000, 1000 },
	{ "stale_cycles", 65, 1, 0, 1, 100, 3 },
	{ "speed_max_raw", 66, 2, 0, 1, 65534, 40000 },
	{ "speed_step_max_raw", 68, 2, 0, 1, 65535, 1000 },
	{ "force_max_raw", 70, 2, 0, 1, 65534, 60000 },
	{ "force_step_max_raw", 72, 2, 0, 1, 65535, 20000 },
	{ "lowpass_alpha_q15", 74, 2, 0, 1, 32768, 32768 },
	{ "v0_min_umps", 76, 4, 0, 0, 10000000, 10000 },
	{ "force_min_mn", 80, 4, 0, 0, 100000000, 100000 },
	{ "debounce_count", 84, 1, 0, 1, 50, 3 },
	{ "hyst_lnq_micro", 85, 4, 0, 0, 5000000, 20000 },
	{ "hyst_rho_ppm", 89, 4, 0, 0, 1000000, 20000 },
	{ "rho_warn_ppm", 93, 4, 0, 0, 1000000, 500000 },
	{ "watchdog_ms", 97, 2, 0, 10, 10000, 100 },
	{ "input_bus", 99, 1, 0, 0, 1, 0 },
	{ "output_bus", 100, 1, 0, 0, 1, 0 },
	{ "input_listen_only", 101, 1, 0, 0, 1, 0 },
};

#define NFIELDS (sizeof(fields) / sizeof(fields[0]))

static void encode_default(uint8_t *buf)
{
	calib_t cal;

	calib_default(&cal);
	assert_int_equal(calib_encode(&cal, buf, CALIB_BLOCK_LEN), SQ_OK);
}

/* ---- CRC-32 ------------------------------------------------------------------ */

static void test_crc32_check_value(void **state)
{
	static const uint8_t s[9] = { '1', '2', '3', '4', '5', '6', '7', '8', '9' };
	uint8_t buf[300];

	(void)state;
	assert_int_equal(calib_crc32(0U, s, 9U), 0xCBF43926U);
	assert_int_equal(ref_crc32(s, 9U), 0xCBF43926U);
	/* continuation, and agreement with the definition on other data */
	assert_int_equal(calib_crc32(calib_crc32(0U, s, 4U), &s[4], 5U), 0xCBF43926U);
	for (uint32_t i = 0; i < sizeof(buf); i++) {
		buf[i] = (uint8_t)(i * 37U + 11U);
	}
	for (uint32_t n = 0; n <= sizeof(buf); n += 23U) {
		assert_int_equal(calib_crc32(0U, buf, n), ref_crc32(buf, n));
	}
	assert_int_equal(calib_crc32(0U, buf, 0U), 0U);
}

/* ---- defaults and layout -------------------------------------------------- */

static void test_defaults_validate_and_match_model_md(void **state)
{
	calib_t cal;
	uint8_t buf[CALIB_BLOCK_LEN];

	(void)state;
	calib_default(&cal);
	assert_int_equal(calib_validate(&cal), SQ_OK);
	assert_int_equal(cal.mass_q16, 65536);
	assert_int_equal(cal.omega0_q12, 20480000);
	assert_int_equal(cal.damping_q30, 24696062);
	assert_int_equal(cal.mu_inf_q30, 268435456);
	assert_int_equal(cal.delta_mu_q30, 161061274);
	assert_int_equal(cal.slope_q24, 33554432);
	assert_int_equal(cal.criterion, SQUEAL_CRITERION_EXACT);
	assert_int_equal(cal.pad_radius_um, 120000);
	assert_int_equal(cal.wheel_radius_um, 300000);
	/* and every stored field has the documented default */
	assert_int_equal(calib_encode(&cal, buf, sizeof(buf)), SQ_OK);
	for (uint32_t i = 0; i < NFIELDS; i++) {
		uint32_t raw = get_le(&buf[fields[i].off], fields[i].size);
		int64_t v = raw;

		if (fields[i].is_signed && (raw & 0x80000000U)) {
			v = (int64_t)raw - 4294967296LL;
		}
		if (v != fields[i].def) {
			fail_msg("default %s = %lld, expected %lld", fields[i].name,
				 (long long)v, (long long)fields[i].def);
		}
	}
}

static void test_model_params_from_defaults(void **state)
{
	calib_t cal;
	squeal_params_t p;

	(void)state;
	calib_default(&cal);
	calib_model_params(&cal, &p);
#if defined(SQUEAL_NUMERIC_FIXED)
	assert_int_equal(p.mass_kg, 65536);
	assert_int_equal(p.omega0_radps, 20480000);
	assert_int_equal(p.damping, 24696062);
	assert_int_equal(p.mu_inf, 268435456);
	assert_int_equal(p.delta_mu, 161061274);
	assert_int_equal(p.slope_spm, 33554432);
#else
	assert_true(p.mass_kg == 1.0f);
	assert_true(p.omega0_radps == 5000.0f);
	assert_true(fabsf(p.damping - 0.023f) <= 1e-9f);
	assert_true(p.mu_inf == 0.25f);
	assert_true(fabsf(p.delta_mu - 0.15f) <= 1e-8f);
	assert_true(p.slope_spm == 2.0f);
#endif
}

/* squeal_app's load_calibration reads the stored block into the calib_t
 * it decodes into (calib_decode allows it): the block must fit in one. */
_Static_assert(sizeof(calib_t) >= CALIB_BLOCK_LEN, "a calib_t holds the stored block");

static void test_block_layout(void **state)
{
	uint8_t buf[CALIB_BLOCK_LEN];

	(void)state;
	/* version 4: the 99 bytes of v1 (header + fields), then input_bus,
	 * output_bus, input_listen_only, n_inputs, n_corners, the flat
	 * deviations (7 x 4) and k (4), 8 inputs x 125 (v2's 82, the five
	 * decimals' mantissas 4 bytes wider, mux_value_max, the second
	 * selector's 4 bytes and its two range ends; v4: the four start bits
	 * and the qualifier bit 1 byte wider, fd, e2e_offset_byte) and 4
	 * corners x 89 bytes (57 + torque share 4 + their deviations 28), then
	 * the CRC: 99 + 3 + 2 + 32 + 1000 + 356 = 1492, block 1496 */
	assert_int_equal(CALIB_VERSION, 4);
	assert_int_equal(CALIB_BLOCK_LEN, 1496);
	encode_default(buf);
	assert_memory_equal(buf, "SQCB", 4);
	assert_int_equal(get_le(&buf[4], 2U), CALIB_VERSION);
	assert_int_equal(get_le(&buf[6], 2U), CALIB_BLOCK_LEN);
	assert_int_equal(buf[99], 0);  /* input bus 0 */
	assert_int_equal(buf[100], 0); /* output bus 0 */
	assert_int_equal(buf[101], 0); /* normal mode */
	assert_int_equal(buf[102], 0); /* no input map: the legacy corner */
	assert_int_equal(buf[103], 0);
	for (unsigned i = 104U; i < 132U; i++) {
		assert_int_equal(buf[i], 0); /* no deviations */
	}
	assert_int_equal(get_le(&buf[132], 4U), 2U << 16); /* k = 2 sigma, Q16 */
	assert_int_equal(get_le(&buf[1492], 4U), ref_crc32(buf, 1492U));
}

/* ---- round trip ---------------------------------------------------------------- */

static void check_round_trip(const calib_t *in)
{
	uint8_t a[CALIB_BLOCK_LEN];
	uint8_t b[CALIB_BLOCK_LEN];
	calib_t out;
	calib_error_t why = CALIB_ERR_MAGIC;

	memset(&out, 0x5A, sizeof(out));
	assert_int_equal(calib_encode(in, a, sizeof(a)), SQ_OK);
	assert_int_equal(calib_decode(a, sizeof(a), &out, &why), SQ_OK);
	assert_int_equal(why, CALIB_OK);
	assert_int_equal(calib_encode(&out, b, sizeof(b)), SQ_OK);
	assert_memory_equal(a, b, sizeof(a));
}

/* Every field at its minimum and at its maximum (the other fields default,
 * except where a cross-field rule needs a partner), encoded and decoded. */
static void test_round_trip_every_field_at_limits(void **state)
{
	uint8_t buf[CALIB_BLOCK_LEN];
	calib_t out;
	calib_t def;

	(void)state;
	calib_default(&def);
	check_round_trip(&def);
	for (uint32_t i = 0; i < NFIELDS; i++) {
		for (int end = 0; end < 2; end++) {
			const int64_t v = end ? fields[i].max : fields[i].min;
			calib_error_t why = CALIB_ERR_MAGIC;

			encode_default(buf);
			put_le(&buf[fields[i].off], (uint32_t)(v & 0xFFFFFFFFLL), fields[i].size);
			if (strcmp(fields[i].name, "delta_mu_q30") == 0 && v < 0) {
				/* mu_0 = mu_inf + dmu must stay >= 0 */
				put_le(&buf[20], (uint32_t)(3U << 29), 4U);
			}
			if (strstr(fields[i].name, "_id") != NULL) {
				/* identifiers must stay distinct: move the
				 * default that would collide */
				for (uint32_t j = 10; j < 16; j++) {
					if (j != i && get_le(&buf[fields[j].off], 2U) == (uint32_t)v) {
						put_le(&buf[fields[j].off], 0x400U, 2U);
					}
				}
			}
			reseal(buf);
			if (calib_decode(buf, sizeof(buf), &out, &why) != SQ_OK) {
				fail_msg("%s = %lld (limit) rejected: %s", fields[i].name,
					 (long long)v, calib_error_name(why));
			}
			assert_int_equal(calib_validate(&out), SQ_OK);
			check_round_trip(&out);
		}
	}
}

/* One beyond each limit (where the stored size can hold it), with a
 * correct CRC: rejected whole, reason "range", output untouched. */
static void test_out_of_range_field_with_good_crc_rejected(void **state)
{
	uint8_t buf[CALIB_BLOCK_LEN];
	calib_t out;
	calib_t sentinel;
	uint32_t tried = 0;

	(void)state;
	memset(&sentinel, 0x5A, sizeof(sentinel));
	for (uint32_t i = 0; i < NFIELDS; i++) {
		const int64_t full = (fields[i].size == 4U) ? (int64_t)0xFFFFFFFFLL :
			(((int64_t)1 << (8U * fields[i].size)) - 1);
		const int64_t lo = fields[i].is_signed ? INT32_MIN : 0;
		const int64_t hi = fields[i].is_signed ? INT32_MAX : full;
		const int64_t cand[2] = { fields[i].min - 1, fields[i].max + 1 };

		for (int c = 0; c < 2; c++) {
			calib_error_t why = CALIB_OK;

			if (cand[c] < lo || cand[c] > hi) {
				continue; /* not storable: the size is the limit */
			}
			encode_default(buf);
			put_le(&buf[fields[i].off], (uint32_t)(cand[c] & 0xFFFFFFFFLL), fields[i].size);
			reseal(buf);
			memcpy(&out, &sentinel, sizeof(out));
			if (calib_decode(buf, sizeof(buf), &out, &why) != SQ_EBADMSG) {
				fail_msg("%s = %lld accepted", fields[i].name, (long long)cand[c]);
			}
			assert_int_equal(why, CALIB_ERR_RANGE);
			assert_memory_equal(&out, &sentinel, sizeof(out));
			tried++;
		}
	}
	assert_true(tried >= 50U);
}

/* RM0090 32.7.7: a bit of 1 + BS1 + BS2 quanta (8..25, BS1 <= 16, BS2 <= 8)
 * of BRP (1..1024) clocks; exact when clock = rate * quanta * BRP. */
static bool bxcan_exact(uint32_t clock_hz, uint32_t bps)
{
	for (uint32_t ntq = 8U; ntq <= 25U; ntq++) {
		if (clock_hz % (bps * ntq) == 0U && clock_hz / (bps * ntq) <= 1024U) {
			return true;
		}
	}
	return false;
}

/* A rate the ECU's CAN clock cannot make exactly is refused by
 * the calibration, with its own reason; every rate it accepts is exact on
 * each clock the ECU runs on (APB1 42 MHz F4, 36 MHz F103, HSI fallback
 * 16 MHz F4 and 8 MHz F103), so hal_can_set_bitrate() never refuses it. */
static void test_bitrate_must_be_exact(void **state)
{
	static const uint32_t clocks[] = { 42000000U, 36000000U, 16000000U, 8000000U };
	uint8_t buf[CALIB_BLOCK_LEN];
	calib_t out;
	uint32_t accepted = 0U;

	(void)state;
	for (uint32_t kbps = 10U; kbps <= 1000U; kbps++) {
		calib_error_t why = CALIB_OK;
		int rc;

		encode_default(buf);
		put_le(&buf[41], kbps, 2U);
		reseal(buf);
		rc = calib_decode(buf, sizeof(buf), &out, &why);
		if (rc == SQ_OK) {
			accepted++;
			for (uint32_t c = 0U; c < 4U; c++) {
				if (!bxcan_exact(clocks[c], kbps * 1000U)) {
					fail_msg("%u kbit/s accepted but not exact at %u Hz", kbps, clocks[c]);
				}
			}
		} else {
			assert_int_equal(rc, SQ_EBADMSG);
			assert_int_equal(why, CALIB_ERR_BITRATE);
		}
	}
	assert_int_equal(accepted, 8U); /* 10 20 50 100 125 250 500 1000 */
	encode_default(buf);
	put_le(&buf[41], 800U, 2U);
	reseal(buf);
	assert_int_equal(calib_decode(buf, sizeof(buf), &out, NULL), SQ_EBADMSG);
	assert_false(bxcan_exact(42000000U, 800000U)); /* why: 52.5 clocks per bit */
	assert_string_not_equal(calib_error_name(CALIB_ERR_BITRATE), "?");
}

/* Cross-field rules: distinct identifiers, mu_0 >= 0. */
static void test_cross_field_rules(void **state)
{
	calib_t cal;
	uint8_t buf[CALIB_BLOCK_LEN];

	(void)state;
	calib_default(&cal);
	cal.status_id = cal.disc_speed_id;
	assert_int_equal(calib_validate(&cal), SQ_EINVAL);
	assert_int_equal(calib_encode(&cal, buf, sizeof(buf)), SQ_EINVAL);
	/* every pair of the six CAN identifiers, the last ones included */
	for (unsigned int i = 0U; i < 6U; i++) {
		for (unsigned int j = i + 1U; j < 6U; j++) {
			uint16_t *ids[6];

			calib_default(&cal);
			ids[0] = &cal.disc_speed_id;
			ids[1] = &cal.pad_force_id;
			ids[2] = &cal.status_id;
			ids[3] = &cal.detail_id;
			ids[4] = &cal.diag_id;
			ids[5] = &cal.detail2_id;
			*ids[j] = *ids[i];
			if (calib_validate(&cal) != SQ_EINVAL) {
				fail_msg("identifiers %u and %u equal: accepted", i, j);
			}
		}
	}
	calib_default(&cal);
	cal.delta_mu_q30 = -cal.mu_inf_q30 - 1; /* mu_0 < 0 */
	assert_int_equal(calib_validate(&cal), SQ_EINVAL);
	cal.delta_mu_q30 = -cal.mu_inf_q30; /* mu_0 = 0: allowed */
	assert_int_equal(calib_validate(&cal), SQ_OK);
}

/* ---- corruption ------------------------------------------------------------ */

/* Every single-byte corruption (each byte, each of the 255 non-zero XOR
 * patterns) of a valid block is rejected whole. */
static void test_every_single_byte_corruption_rejected(void **state)
{
	uint8_t good[CALIB_BLOCK_LEN];
	uint8_t buf[CALIB_BLOCK_LEN];
	calib_t out;
	calib_t sentinel;
	uint32_t n = 0;

	(void)state;
	memset(&sentinel, 0x5A, sizeof(sentinel));
	encode_default(good);
	for (uint32_t i = 0; i < CALIB_BLOCK_LEN; i++) {
		for (uint32_t x = 1; x < 256U; x++) {
			calib_error_t why = CALIB_OK;

			memcpy(buf, good, sizeof(buf));
			buf[i] ^= (uint8_t)x;
			memcpy(&out, &sentinel, sizeof(out));
			if (calib_decode(buf, sizeof(buf), &out, &why) != SQ_EBADMSG) {
				fail_msg("byte %u ^ 0x%02x accepted", i, x);
			}
			assert_true(why != CALIB_OK);
			assert_memory_equal(&out, &sentinel, sizeof(out));
			n++;
		}
	}
	assert_int_equal(n, CALIB_BLOCK_LEN * 255U);
}

static void test_header_errors(void **state)
{
	/* one header field set to a wrong value (little endian), block resealed */
	static const struct {
		size_t off;
		uint32_t value;
		uint32_t size;
		calib_error_t why;
	} bad_header[] = {
		{ 0U, 'X', 1U, CALIB_ERR_MAGIC },
		{ 4U, CALIB_VERSION + 1U, 2U, CALIB_ERR_VERSION },
		{ 4U, CALIB_VERSION - 1U, 2U, CALIB_ERR_VERSION }, /* an older layout: not read as this one */
		{ 6U, CALIB_BLOCK_LEN + 1U, 2U, CALIB_ERR_LENGTH },
	};
	uint8_t buf[CALIB_BLOCK_LEN + 8U];
	calib_t out;
	calib_error_t why = CALIB_OK;

	(void)state;
	encode_default(buf);
	assert_int_equal(calib_decode(buf, CALIB_BLOCK_LEN - 1U, &out, &why), SQ_EBADMSG);
	assert_int_equal(why, CALIB_ERR_LENGTH);
	/* a longer buffer (storage page) is fine: the block says its length */
	memset(&buf[CALIB_BLOCK_LEN], 0xFF, 8U);
	assert_int_equal(calib_decode(buf, sizeof(buf), &out, &why), SQ_OK);
	/* magic, version, length field: with a correct CRC still refused */
	for (size_t i = 0U; i < sizeof(bad_header) / sizeof(bad_header[0]); i++) {
		encode_default(buf);
		put_le(&buf[bad_header[i].off], bad_header[i].value, bad_header[i].size);
		reseal(buf);
		assert_int_equal(calib_decode(buf, CALIB_BLOCK_LEN, &out, &why), SQ_EBADMSG);
		assert_int_equal(why, bad_header[i].why);
	}
	/* erased flash */
	memset(buf, 0xFF, sizeof(buf));
	assert_int_equal(calib_decode(buf, CALIB_BLOCK_LEN, &out, &why), SQ_EBADMSG);
	/* NULLs and a short buffer: programming errors (contract handler) */
	expect_assert_failure(calib_decode(NULL, CALIB_BLOCK_LEN, &out, &why));
	expect_assert_failure(calib_decode(buf, CALIB_BLOCK_LEN, NULL, &why));
	expect_assert_failure(calib_encode(NULL, buf, CALIB_BLOCK_LEN));
	{
		calib_t cal;

		calib_default(&cal);
		expect_assert_failure(calib_encode(&cal, buf, CALIB_BLOCK_LEN - 1U));
	}
	expect_assert_failure(calib_validate(NULL));
}

SQ_CMOCKA_MAIN(
	cmocka_unit_test(test_crc32_check_value),
	cmocka_unit_test(test_defaults_validate_and_match_model_md),
	cmocka_unit_test(test_model_params_from_defaults),
	cmocka_unit_test(test_block_layout),
	cmocka_unit_test(test_round_trip_every_field_at_limits),
	cmocka_unit_test(test_out_of_range_field_with_good_crc_rejected),
	cmocka_unit_test(test_cross_field_rules),
	cmocka_unit_test(test_bitrate_must_be_exact),
	cmocka_unit_test(test_every_single_byte_corruption_rejected),
	cmocka_unit_test(test_header_errors))
