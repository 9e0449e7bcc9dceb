/* SPDX-License-Identifier: MIT */
/*
 * bxCAN bit timing (hal/stm32f4/bxcan_timing.c) on the host. Expected
 * register values are derived by hand from RM0090 32.7.7:
 *   bit time = (BRP+1) * (1 + (TS1+1) + (TS2+1)) APB clocks,
 *   sample point = (1 + TS1+1) / (1 + TS1+1 + TS2+1),
 * with 8..25 quanta, BS1 <= 16, BS2 <= 8, the sample point nearest 87.5 %,
 * and every result is also decoded and checked against the formula.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "bxcan.h"
#include "sq_status.h"

static uint32_t brp(uint32_t btr) { return (btr & 0x3FFU) + 1U; }
static uint32_t ts1(uint32_t btr) { return ((btr >> 16) & 0xFU) + 1U; }
static uint32_t ts2(uint32_t btr) { return ((btr >> 20) & 0x7U) + 1U; }
static uint32_t sjw(uint32_t btr) { return ((btr >> 24) & 0x3U) + 1U; }

static void expect_timing(uint32_t apb_hz, uint32_t bps, uint32_t want_brp,
			  uint32_t want_ts1, uint32_t want_ts2)
{
	uint32_t btr = 0xFFFFFFFFU;

	assert_int_equal(bxcan_bit_timing(apb_hz, bps, &btr), SQ_OK);
	assert_int_equal(brp(btr), want_brp);
	assert_int_equal(ts1(btr), want_ts1);
	assert_int_equal(ts2(btr), want_ts2);
	assert_int_equal(sjw(btr), 1);
	assert_int_equal(btr & 0xFC80FC00U, 0U); /* no stray bits, no loopback/silent */
	/* the formula gives the bit rate back exactly */
	assert_int_equal(apb_hz % (brp(btr) * (1U + ts1(btr) + ts2(btr))), 0U);
	assert_int_equal(apb_hz / (brp(btr) * (1U + ts1(btr) + ts2(btr))), bps);
}

/* 42 MHz APB1 (168 MHz core), 500 kbit/s: 84 clocks per bit; 14 quanta of
 * 6 clocks, 1 + 11 + 2 -> sample point 85.7 % (21 quanta cannot reach: BS1
 * would be 17 > 16; 12 quanta give 83.3 %). */
static void test_500k_at_42mhz(void **state)
{
	(void)state;
	expect_timing(42000000U, 500000U, 6U, 11U, 2U);
}

/* 250 kbit/s: 168 clocks; 8 quanta of 21, 1 + 6 + 1 = 87.5 % exactly
 * (24 and 21 quanta: BS1 > 16 near 87.5 %; 14 quanta: 85.7 %). */
static void test_250k_at_42mhz(void **state)
{
	(void)state;
	expect_timing(42000000U, 250000U, 21U, 6U, 1U);
}

/* 125 kbit/s: 336 clocks; 16 quanta of 21, 1 + 13 + 2 = 87.5 %, chosen over
 * 8 quanta of 42 (same sample point, coarser resynchronisation). */
static void test_125k_at_42mhz(void **state)
{
	(void)state;
	expect_timing(42000000U, 125000U, 21U, 13U, 2U);
}

/* 1 Mbit/s: 42 clocks; 14 quanta of 3, 1 + 11 + 2 = 85.7 %. */
static void test_1m_at_42mhz(void **state)
{
	(void)state;
	expect_timing(42000000U, 1000000U, 3U, 11U, 2U);
}

/* HSI fallback (APB1 = 16 MHz): 32 clocks; 16 quanta of 2, 1 + 13 + 2. */
static void test_500k_on_hsi(void **state)
{
	(void)state;
	expect_timing(16000000U, 500000U, 2U, 13U, 2U);
}

/* STM32F103: APB1 36 MHz, 500 kbit/s: 72 clocks; 24 quanta: BS1 > 16 near
 * 87.5 %; 18 quanta of 4: 88.9 % at best; 9 quanta: 88.9 %; 8 quanta of 9:
 * 1 + 6 + 1 = 87.5 % exactly. */
static void test_500k_at_36mhz(void **state)
{
	(void)state;
	expect_timing(36000000U, 500000U, 9U, 6U, 1U);
}

static void test_rejects_inexact_and_bad(void **state)
{
	uint32_t btr = 0x12345678U;

	(void)state;
	assert_int_equal(bxcan_bit_timing(42000000U, 33333U, &btr), SQ_EINVAL);
	assert_int_equal(bxcan_bit_timing(42000000U, 0U, &btr), SQ_EINVAL);
	assert_int_equal(bxcan_bit_timing(42000000U, 2000000U, &btr), SQ_EINVAL);
	assert_int_equal(bxcan_bit_timing(0U, 500000U, &btr), SQ_EINVAL);
	assert_int_equal(bxcan_bit_timing(42000000U, 500000U, NULL), SQ_EINVAL);
	/* 1 kbit/s at 42 MHz: 42000 clocks per bit need BRP >= 42000 / 25 > 1024 */
	assert_int_equal(bxcan_bit_timing(42000000U, 1000U, &btr), SQ_EINVAL);
	assert_int_equal(btr, 0x12345678U); /* untouched on failure */
}

/* The largest prescaler, BRP field 0x3FF = 1024 clocks per quantum
 * (RM0090 32.9.2: BRP[9:0], tq = (BRP+1) tPCLK), is usable: 1 kbit/s at
 * 25.6 MHz is 25600 = 2^10 * 25 clocks per bit, which 8..25 quanta divide
 * at 8, 10, 16, 20 and 25 quanta into prescalers 3200, 2560, 1600, 1280
 * and 1024: only 25 quanta of 1024 fit; BS1 + BS2 = 24 with BS1 <= 16 and
 * BS2 <= 8 leaves 1 + 16 + 8 (sample point 68 %). One clock more per
 * quantum is beyond the field: 1 kbit/s at 25.625 MHz (25625 = 5^4 * 41
 * clocks, divisible by 25 only: prescaler 1025) has no timing. */
static void test_largest_prescaler_1024(void **state)
{
	uint32_t btr = 0x12345678U;

	(void)state;
	expect_timing(25600000U, 1000U, 1024U, 16U, 8U);
	assert_int_equal(bxcan_bit_timing(25600000U, 1000U, &btr), SQ_OK);
	assert_int_equal(btr, 0x007F03FFU); /* TS2 7, TS1 15, BRP 1023 */
	btr = 0x12345678U;
	assert_int_equal(bxcan_bit_timing(25625000U, 1000U, &btr), SQ_EINVAL);
	assert_int_equal(btr, 0x12345678U);
}

SQ_CMOCKA_MAIN(
	cmocka_unit_test(test_500k_at_42mhz),
	cmocka_unit_test(test_250k_at_42mhz),
	cmocka_unit_test(test_125k_at_42mhz),
	cmocka_unit_test(test_1m_at_42mhz),
	cmocka_unit_test(test_500k_on_hsi),
	cmocka_unit_test(test_500k_at_36mhz),
	cmocka_unit_test(test_rejects_inexact_and_bad),
	cmocka_unit_test(test_largest_prescaler_1024))
