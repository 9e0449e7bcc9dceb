/* SPDX-License-Identifier: MIT */
/*
 * Time on the STM32F4 (hal/stm32f4/systick.c) on the host: SysTick, SCB and
 * DWT on the register simulation (tests/support/regsim/f4/chip.h), the two
 * counters driven by this test. Expected values by hand from PM0214
 * (SysTick counts down from RVR to 0 and reloads: RVR = ticks - 1; CSR bit 0
 * ENABLE, 1 TICKINT, 2 CLKSOURCE; ICSR bit 26 PENDSTSET; SHPR3 bits 31:24
 * SysTick's priority; DEMCR bit 24 TRCENA; DWT_CTRL bit 0 CYCCNTENA, lock
 * key 0xC5ACCE55): at 168 MHz one millisecond is 168000 ticks, hal_time_us
 * = ms * 1000 + (167999 - CVR) / 168. The tests run in order: the module's
 * state (the millisecond count, the last reading) carries from one to the
 * next as on the chip. systick.c is included here, not linked: the last
 * test sets its millisecond count 2 ms before the 32-bit wrap (49.7 days
 * of ticks, 7 s of calls under the sanitizers) to see the time go on past
 * it.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "chip.h"
#include "hal.h"
#include "sq_status.h"
#include "stm32_time.h"

#include "../../../hal/stm32f4/systick.c"

uint32_t regsim_syst[3], regsim_scb_icsr, regsim_scb_shpr3, regsim_demcr, regsim_dwt[3];

/* SysTick's current value: a script of successive reads, then steady. */
static uint32_t cvr_cell;
static uint32_t cvr_script[4];
static uint32_t cvr_script_len, cvr_script_next;

volatile uint32_t *regsim_syst_cvr(void)
{
	if (cvr_script_next < cvr_script_len) {
		cvr_cell = cvr_script[cvr_script_next++];
	}
	return &cvr_cell;
}

static void cvr_reads(uint32_t first, uint32_t second)
{
	cvr_script[0] = first;
	cvr_script[1] = second;
	cvr_script_len = 2U;
	cvr_script_next = 0U;
}

static void cvr_steady(uint32_t v)
{
	cvr_script_len = 0U;
	cvr_cell = v;
}

/* DWT CYCCNT: counts 10 cycles between accesses when it runs (a debug set-up
 * or QEMU may leave it at 0) */
static uint32_t cyccnt_cell;
static bool cyccnt_runs;

volatile uint32_t *regsim_dwt_cyccnt(void)
{
	if (cyccnt_runs) {
		cyccnt_cell += 10U;
	}
	return &cyccnt_cell;
}

static uint32_t primask;

uint32_t cm_irq_save(void)
{
	uint32_t was = primask;

	primask = 1U;
	return was;
}

void cm_irq_restore(uint32_t was)
{
	primask = was;
}

#define TICKS_168 168000U /* per ms at 168 MHz */

static uint32_t cvr_at_us(uint32_t us_into_ms)
{
	return TICKS_168 - 1U - us_into_ms * 168U;
}

static void test_early_free_running_and_zero_before_start(void **state)
{
	stm32_timeout_t t;

	(void)state;
	assert_int_equal(hal_time_us(), 0U); /* before stm32_time_start() */
	stm32_time_early_init(16000000U);
	assert_int_equal(regsim_syst[0], 0x5U);        /* CLKSOURCE | ENABLE, no TICKINT */
	assert_int_equal(regsim_syst[1], 0x00FFFFFFU); /* the largest reload */
	assert_int_equal(cvr_cell, 0U);
	assert_int_equal(hal_cycles_per_us(), 16U);
	stm32_timeout_start(&t, 100U);
	assert_int_equal(t.limit_ticks, 1600U); /* 100 us at 16 MHz */
}

static void test_start_programs_systick_and_dwt(void **state)
{
	(void)state;
	cyccnt_runs = true;
	regsim_scb_shpr3 = 0x00123456U;
	stm32_time_start(168000000U);
	assert_int_equal(regsim_syst[1], 167999U);
	assert_int_equal(cvr_cell, 0U);
	assert_int_equal(regsim_syst[0], 0x7U);
	assert_int_equal(regsim_scb_shpr3, 0x40123456U); /* only SysTick's byte */
	assert_true((regsim_demcr & (1UL << 24)) != 0U);
	assert_int_equal(regsim_dwt[2], 0xC5ACCE55U);
	assert_true((regsim_dwt[0] & 1U) != 0U);
	assert_int_equal(hal_cycles_per_us(), 168U);
	assert_int_equal(stm32_uptime_ms(), 0U);
}

static void test_time_is_milliseconds_plus_counter_position(void **state)
{
	(void)state;
	cvr_steady(cvr_at_us(50U));
	assert_int_equal(hal_time_us(), 50U);
	SysTick_Handler();
	SysTick_Handler();
	SysTick_Handler();
	assert_int_equal(stm32_uptime_ms(), 3U);
	cvr_steady(cvr_at_us(100U));
	assert_int_equal(hal_time_us(), 3100U);
}

static void test_a_wrap_not_yet_served_counts_the_millisecond(void **state)
{
	(void)state;
	/* the first read just before the wrap, the pending bit, the second
	 * read 1 us after it: ms 3 + 1 */
	regsim_scb_icsr = 1UL << 26;
	cvr_reads(0U, cvr_at_us(1U));
	assert_int_equal(hal_time_us(), 4001U);
	regsim_scb_icsr = 0U;
	SysTick_Handler(); /* served: ms 4 */
	cvr_steady(cvr_at_us(2U));
	assert_int_equal(hal_time_us(), 4002U);
	/* the counter reloaded, neither interrupt nor pending bit shows it
	 * (QEMU): a position below the last one in the same ms is that wrap */
	cvr_steady(cvr_at_us(1U));
	assert_int_equal(hal_time_us(), 5001U);
	SysTick_Handler(); /* ms 5 */
	cvr_steady(cvr_at_us(3U));
	assert_int_equal(hal_time_us(), 5003U);
}

static void test_cycles_from_dwt_or_from_systick(void **state)
{
	uint32_t c0;
	uint32_t c1;

	(void)state;
	c0 = hal_cycles();
	c1 = hal_cycles();
	assert_int_equal(c1 - c0, 10U); /* the counter, not SysTick */
	/* a CYCCNT that stays at 0: SysTick-derived cycles, ms * 168000 + position */
	cyccnt_runs = false;
	stm32_time_start(168000000U);
	cvr_steady(cvr_at_us(10U));
	assert_int_equal(hal_cycles(), 5U * TICKS_168 + 1680U);
}

static void test_timeout_counts_ticks_across_the_reload(void **state)
{
	stm32_timeout_t t;

	(void)state;
	cvr_steady(1000U);
	stm32_timeout_start(&t, 10U); /* 1680 ticks */
	assert_int_equal(t.limit_ticks, 1680U);
	cvr_steady(500U);
	assert_false(stm32_timeout_expired(&t)); /* 500 */
	/* reloaded: 500 down to 0, then 168000 - 167500 from the reload on */
	cvr_steady(167500U);
	assert_false(stm32_timeout_expired(&t)); /* 500 + 1000 = 1500 */
	cvr_steady(167300U);
	assert_true(stm32_timeout_expired(&t));  /* 1700 >= 1680 */
	assert_int_equal(t.elapsed_ticks, 1700U);
	/* 2^32 us saturates the limit instead of wrapping */
	stm32_timeout_start(&t, 0xFFFFFFFFU);
	assert_int_equal(t.limit_ticks, 0xFFFFFFFFU);
}

static void test_a_stopped_systick_still_ends_the_wait(void **state)
{
	uint32_t flag = 0U;
	uint32_t polls = 0U;
	stm32_timeout_t t;

	(void)state;
	cvr_steady(1234U); /* never moves */
	stm32_timeout_start(&t, 1U); /* 168 ticks: 168 polls at most */
	while (!stm32_timeout_expired(&t)) {
		polls++;
		assert_true(polls < 1000U);
	}
	assert_int_equal(t.polls, 168U);
	assert_int_equal(stm32_wait_reg(&flag, 1U, 1U, 1U), SQ_EAGAIN);
	flag = 1U;
	assert_int_equal(stm32_wait_reg(&flag, 1U, 1U, 1U), SQ_OK);
	assert_int_equal(stm32_wait_reg(&flag, 3U, 0U, 1U), SQ_EAGAIN);
}

/* After 2^32 ms (49.7 days) the 32-bit count wraps to 0, and the 64-bit
 * time goes on: 4294967296 ms is 4294967296000 us. */
static void test_time_goes_on_past_the_32_bit_millisecond_wrap(void **state)
{
	(void)state;
	tick_ms = 0xFFFFFFFEU;
	cvr_steady(cvr_at_us(10U));
	assert_int_equal(hal_time_us(), 4294967294010ULL);
	SysTick_Handler();
	assert_int_equal(stm32_uptime_ms(), 0xFFFFFFFFU);
	assert_int_equal(hal_time_us(), 4294967295010ULL);
	SysTick_Handler();
	assert_int_equal(stm32_uptime_ms(), 0U);
	assert_int_equal(hal_time_us(), 4294967296010ULL);
	SysTick_Handler();
	cvr_steady(cvr_at_us(20U));
	assert_int_equal(hal_time_us(), 4294967297020ULL);
}

SQ_CMOCKA_MAIN(
	cmocka_unit_test(test_early_free_running_and_zero_before_start),
	cmocka_unit_test(test_start_programs_systick_and_dwt),
	cmocka_unit_test(test_time_is_milliseconds_plus_counter_position),
	cmocka_unit_test(test_a_wrap_not_yet_served_counts_the_millisecond),
	cmocka_unit_test(test_cycles_from_dwt_or_from_systick),
	cmocka_unit_test(test_timeout_counts_ticks_across_the_reload),
	cmocka_unit_test(test_a_stopped_systick_still_ends_the_wait),
	cmocka_unit_test(test_time_goes_on_past_the_32_bit_millisecond_wrap))
