/* SPDX-License-Identifier: MIT */
/*
 * FDCAN bit timing (hal/stm32g4/fdcan_timing.c) on the host. The expected
 * register values are derived by hand here from RM0440's FDCAN_NBTP /
 * FDCAN_DBTP / FDCAN_TDCR descriptions (each field = value - 1):
 *   bit time = BRP x (1 + TSEG1 + TSEG2) kernel clocks,
 *   sample point = (1 + TSEG1) / (1 + TSEG1 + TSEG2),
 *   nominal: BRP 1..512, TSEG1 2..256, TSEG2 2..128, 8..385 quanta;
 *   data:    BRP 1..32,  TSEG1 2..32,  TSEG2 1..16,  5..49 quanta;
 * the smallest BRP with the sample point quantum nearest 87.5 % (nominal)
 * or 75 % (data), ties to the later one, SJW = TSEG2, TDCO = DBRP x
 * (1 + DTSEG1) <= 127. Every result is also decoded and its rate checked
 * against the formula.
 *
 * 170 MHz, 500 kbit/s: 340 clocks. BRP 1: 340 quanta, 87.5 % = 297.5 ->
 *   298 (tie: later), TSEG1 297 > 256: out of range. BRP 2: 170 quanta,
 *   148.75 -> 149: TSEG1 148, TSEG2 21 (87.6 %).
 * 170 MHz, 2 Mbit/s: 85 clocks. BRP 1: 85 > 49; BRP 2, 3, 4 do not divide
 *   85; BRP 5: 17 quanta, 12.75 -> 13: TSEG1 12, TSEG2 4 (76.5 %);
 *   TDCO 5 x 13 = 65.
 * 160 MHz: 320 clocks -> BRP 1 280/320: TSEG1 279 > 256; BRP 2 160 quanta:
 *   140 exactly: TSEG1 139, TSEG2 20. 2 Mbit/s: 80 clocks, BRP 1 80 > 49,
 *   BRP 2 40 quanta: 30: TSEG1 29, TSEG2 10; TDCO 2 x 30 = 60.
 * 80 MHz: 160 clocks -> BRP 1 160 quanta: 139/20. 2 Mbit/s: 40 clocks, BRP
 *   1: 29/10; TDCO 30.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "fdcan.h"
#include "sq_status.h"

typedef struct {
	uint32_t brp, tseg1, tseg2, sjw;
} fields_t;

static fields_t nominal_of(uint32_t nbtp)
{
	const fields_t f = { ((nbtp >> 16) & 0x1FFU) + 1U, ((nbtp >> 8) & 0xFFU) + 1U, (nbtp & 0x7FU) + 1U,
			     ((nbtp >> 25) & 0x7FU) + 1U };
	return f;
}

static fields_t data_of(uint32_t dbtp)
{
	const fields_t f = { ((dbtp >> 16) & 0x1FU) + 1U, ((dbtp >> 8) & 0x1FU) + 1U, ((dbtp >> 4) & 0xFU) + 1U,
			     (dbtp & 0xFU) + 1U };
	return f;
}

typedef struct {
	uint32_t kernel_hz, nominal_bps, data_bps;
	fields_t n, d;
	uint32_t tdco;
} timing_case_t;

static void expect_case(const timing_case_t *c)
{
	fdcan_timing_t t;
	fields_t n;
	fields_t d;

	assert_int_equal(fdcan_bit_timing(c->kernel_hz, c->nominal_bps, c->data_bps, &t), SQ_OK);
	n = nominal_of(t.nbtp);
	d = data_of(t.dbtp);
	assert_int_equal(n.brp, c->n.brp);
	assert_int_equal(n.tseg1, c->n.tseg1);
	assert_int_equal(n.tseg2, c->n.tseg2);
	assert_int_equal(n.sjw, c->n.sjw);
	assert_int_equal(d.brp, c->d.brp);
	assert_int_equal(d.tseg1, c->d.tseg1);
	assert_int_equal(d.tseg2, c->d.tseg2);
	assert_int_equal(d.sjw, c->d.sjw);
	/* exact rates, from the fields alone */
	assert_int_equal(c->kernel_hz % (n.brp * (1U + n.tseg1 + n.tseg2)), 0U);
	assert_int_equal(c->kernel_hz / (n.brp * (1U + n.tseg1 + n.tseg2)), c->nominal_bps);
	assert_int_equal(c->kernel_hz % (d.brp * (1U + d.tseg1 + d.tseg2)), 0U);
	assert_int_equal(c->kernel_hz / (d.brp * (1U + d.tseg1 + d.tseg2)), c->data_bps);
	/* TDC on, TDCO in TDCR bits 14:8, TDCF 0 */
	assert_true((t.dbtp & (1U << 23)) != 0U);
	assert_int_equal(t.tdcr, c->tdco << 8);
	assert_int_equal(t.tdco_mtq, c->tdco);
	assert_int_equal(t.nominal_tq, 1U + c->n.tseg1 + c->n.tseg2);
	assert_int_equal(t.data_tq, 1U + c->d.tseg1 + c->d.tseg2);
}

static void test_170mhz_500k_2m(void **state)
{
	const timing_case_t c = { 170000000U, 500000U, 2000000U, { 2U, 148U, 21U, 21U }, { 5U, 12U, 4U, 4U }, 65U };
	fdcan_timing_t t;

	(void)state;
	expect_case(&c);
	/* the register words themselves: NSJW 20, NBRP 1, NTSEG1 147, NTSEG2 20;
	 * TDC, DBRP 4, DTSEG1 11, DTSEG2 3, DSJW 3 */
	assert_int_equal(fdcan_bit_timing(170000000U, 500000U, 2000000U, &t), SQ_OK);
	assert_int_equal(t.nbtp, (20U << 25) | (1U << 16) | (147U << 8) | 20U);
	assert_int_equal(t.dbtp, (1U << 23) | (4U << 16) | (11U << 8) | (3U << 4) | 3U);
}

static void test_160mhz_500k_2m(void **state)
{
	const timing_case_t c = { 160000000U, 500000U, 2000000U, { 2U, 139U, 20U, 20U }, { 2U, 29U, 10U, 10U }, 60U };

	(void)state;
	expect_case(&c);
}

static void test_80mhz_500k_2m(void **state)
{
	const timing_case_t c = { 80000000U, 500000U, 2000000U, { 1U, 139U, 20U, 20U }, { 1U, 29U, 10U, 10U }, 30U };

	(void)state;
	expect_case(&c);
}

/* Rates the clock cannot make exactly, and arguments out of range. */
static void test_impossible_refused(void **state)
{
	fdcan_timing_t t;

	(void)state;
	/* 170e6 / 333e3 and 170e6 / 3e6 are not whole numbers of clocks */
	assert_int_equal(fdcan_bit_timing(170000000U, 333000U, 2000000U, &t), SQ_EINVAL);
	assert_int_equal(fdcan_bit_timing(170000000U, 500000U, 3000000U, &t), SQ_EINVAL);
	/* 170 MHz, 1 Mbit/s data: 170 clocks; BRP 1 (170) and 2 (85) have too
	 * many quanta, BRP 5: 34 quanta, 25.5 -> 26: TDCO 5 x 26 = 130 > 127 */
	assert_int_equal(fdcan_bit_timing(170000000U, 500000U, 1000000U, &t), SQ_EINVAL);
	assert_int_equal(fdcan_bit_timing(170000000U, 0U, 2000000U, &t), SQ_EINVAL);
	assert_int_equal(fdcan_bit_timing(170000000U, 1100000U, 2000000U, &t), SQ_EINVAL);
	assert_int_equal(fdcan_bit_timing(170000000U, 500000U, 250000U, &t), SQ_EINVAL); /* data < nominal */
	assert_int_equal(fdcan_bit_timing(170000000U, 500000U, 10000000U, &t), SQ_EINVAL);
	assert_int_equal(fdcan_bit_timing(0U, 500000U, 2000000U, &t), SQ_EINVAL);
	assert_int_equal(fdcan_bit_timing(170000000U, 500000U, 2000000U, NULL), SQ_EINVAL);
	/* 10 kbit/s at 170 MHz: 17000 clocks; at most 385 quanta needs BRP >= 45,
	 * and no divisor of 17000 lies in 45..49; BRP 50: 340 quanta, TSEG1 297
	 * > 256; BRP 68: 250 quanta, 218.75 -> 219: TSEG1 218, TSEG2 31 (a low
	 * rate is made, not refused) */
	assert_int_equal(fdcan_bit_timing(170000000U, 10000U, 2000000U, &t), SQ_OK);
	assert_int_equal(nominal_of(t.nbtp).brp, 68U);
	assert_int_equal(nominal_of(t.nbtp).tseg1, 218U);
	assert_int_equal(nominal_of(t.nbtp).tseg2, 31U);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_170mhz_500k_2m),
		cmocka_unit_test(test_160mhz_500k_2m),
		cmocka_unit_test(test_80mhz_500k_2m),
		cmocka_unit_test(test_impossible_refused),
	};

	return cmocka_run_group_tests_name("fdcan_timing", tests, NULL, NULL);
}
