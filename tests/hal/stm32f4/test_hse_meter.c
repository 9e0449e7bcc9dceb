/* SPDX-License-Identifier: MIT */
/*
 * The crystal against the HSI (hal/stm32f4/hse_meter.c) on a timer in an
 * array: this test's crystal answers each capture wait with the counter
 * value 8 edges of HSE/div later, counted in HSI ticks (exact rational
 * arithmetic here). Checked: the timer's set-up (input capture on TI1,
 * every 8th edge, counter running), the frequency within the method's
 * resolution (one HSI tick over the 16 captures), the 16-bit counter's
 * wrap, no crystal (0, the timer stopped), the +-10 % window at its
 * exact edges.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "stm32_hse_meter.h"
#include "stm32_time.h"
#include "sq_status.h"

#define HSI_HZ 16000000U

static uint32_t tim[32]; /* TIMx registers, 4 bytes each */
#define R_CR1 (0x00U / 4U)
#define R_SR (0x10U / 4U)
#define R_CCMR1 (0x18U / 4U)
#define R_CCER (0x20U / 4U)
#define R_CCR1 (0x34U / 4U)

static uint64_t crystal_hz;
static uint32_t div_n;
static uint64_t elapsed_num; /* HSI ticks x crystal_hz since the start */
static uint32_t counter_start;
static uint32_t waits;

int stm32_wait_reg(volatile const uint32_t *reg, uint32_t mask, uint32_t value, uint32_t timeout_us)
{
	(void)timeout_us;
	assert_ptr_equal(reg, &tim[R_SR]);
	assert_int_equal(mask, 1U << 1);
	assert_int_equal(value, 1U << 1);
	/* running, TI1, prescaler 8, capture enabled */
	assert_int_equal(tim[R_CR1] & 1U, 1U);
	assert_int_equal(tim[R_CCMR1], 1U | (3U << 2));
	assert_int_equal(tim[R_CCER] & 1U, 1U);
	waits++;
	if (crystal_hz == 0U) {
		return SQ_EAGAIN;
	}
	/* 8 edges of HSE/div: 8 * div / crystal s = 8 * div * HSI / crystal ticks */
	elapsed_num += (uint64_t)8U * div_n * HSI_HZ;
	tim[R_CCR1] = (uint32_t)((counter_start + elapsed_num / crystal_hz) & 0xFFFFU);
	return SQ_OK;
}

static uint32_t measure(uint64_t hz, uint32_t div, uint32_t start)
{
	crystal_hz = hz;
	div_n = div;
	elapsed_num = 0U;
	counter_start = start;
	waits = 0U;
	return stm32_hse_meter_run((uintptr_t)tim, div, HSI_HZ);
}

/* 16 captures of 8 * div periods: the counter reads floor(k E / hz)
 * (E = 8 div HSI), so the 16 deltas sum to floor(17 E / hz) - floor(E / hz)
 * ticks, and the result is HSI x div x 128 over them, rounded to nearest:
 * within hz / ticks of the crystal. */
static void check_close(uint64_t hz, uint32_t div, uint32_t start)
{
	const uint64_t e = (uint64_t)8U * div * HSI_HZ;
	const uint64_t ticks = (17U * e) / hz - e / hz;
	const uint64_t num = (uint64_t)HSI_HZ * div * 128U;
	const uint64_t tol = hz / ticks + 1U;
	const uint32_t got = measure(hz, div, start);

	assert_int_equal(got, (num + ticks / 2U) / ticks);
	assert_true((uint64_t)got + tol >= hz && (uint64_t)got <= hz + tol);
	assert_int_equal(waits, 17U); /* the first edge, then 16 */
	assert_int_equal(tim[R_CR1], 0U); /* stopped after */
	assert_int_equal(tim[R_CCER], 0U);
}

static void test_f4_and_g4_crystals(void **state)
{
	(void)state;
	check_close(8000000U, 31U, 0U);   /* F4: HSE_RTC = HSE / 31 */
	check_close(24000000U, 32U, 0U);  /* G4: HSE / 32 */
	check_close(25000000U, 32U, 0U);  /* a wrong part reads as itself */
	check_close(8000000U, 31U, 0xFF00U); /* the counter wraps before the first capture */
	/* 496 ticks per capture from 0xF000 (61440): capture 8 reads 65408,
	 * capture 9 reads 65904 - 65536 = 368: the counter wraps between two
	 * captures, and that delta is 368 + 65536 - 65408 = 496 */
	check_close(8000000U, 31U, 0xF000U);
}

static void test_no_crystal(void **state)
{
	(void)state;
	assert_int_equal(measure(0U, 31U, 0U), 0U);
	assert_int_equal(waits, 1U);
	assert_int_equal(tim[R_CR1], 0U);
}

static void test_tolerance_edges(void **state)
{
	(void)state;
	assert_true(stm32_hse_in_tolerance(8000000U, 8000000U));
	assert_true(stm32_hse_in_tolerance(7200000U, 8000000U));
	assert_false(stm32_hse_in_tolerance(7199999U, 8000000U));
	assert_true(stm32_hse_in_tolerance(8800000U, 8000000U));
	assert_false(stm32_hse_in_tolerance(8800001U, 8000000U));
	assert_true(stm32_hse_in_tolerance(26400000U, 24000000U));
	assert_false(stm32_hse_in_tolerance(26400001U, 24000000U));
	assert_false(stm32_hse_in_tolerance(0U, 24000000U));
	assert_false(stm32_hse_in_tolerance(8000000U, 24000000U)); /* an 8 MHz part on the G4 */
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_f4_and_g4_crystals),
		cmocka_unit_test(test_no_crystal),
		cmocka_unit_test(test_tolerance_edges),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
