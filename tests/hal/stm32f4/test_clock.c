/* SPDX-License-Identifier: MIT */
/*
 * STM32F405 clock start-up (hal/stm32f4/clock.c) on the host, its
 * registers in plain arrays (tests/support/regsim/f4/chip.h). The "hardware" answers each bounded wait
 * the way RM0090 says: HSERDY once HSEON is set and a crystal is fitted,
 * PLLRDY after PLLON, SWS following SW, and TIM11 capturing every IC1PSC-th
 * edge of HSE / RTCPRE on the HSI-clocked counter, only when the driver has
 * routed HSE_RTC to TI1 (TIM11_OR) and enabled the channel. Expected values
 * come from RM0090's formulas (f_VCO = f_HSE / M * N, SYSCLK = f_VCO / P,
 * USB = f_VCO / Q). Crystal measured before the switch, M = 4, CSS, BOR
 * level. The watchdog: test_iwdg.c.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "chip.h"
/* TIM11's capture registers (RM0090 18.5), which hse_meter.c drives */
#define TIM11_CR1   REG32(TIM11_BASE + 0x00U)
#define TIM11_SR    REG32(TIM11_BASE + 0x10U)
#define TIM11_CCMR1 REG32(TIM11_BASE + 0x18U)
#define TIM11_CCER  REG32(TIM11_BASE + 0x20U)
#define TIM11_CCR1  REG32(TIM11_BASE + 0x34U)
#include "sq_status.h"
#include "stm32_board.h"
#include "stm32_time.h"

static bool crystal_fitted;
static uint32_t crystal_hz;
static bool tim11_edges;
static uint64_t capture_num; /* HSI ticks * crystal_hz since the first edge */

void stm32_time_early_init(uint32_t core_hz)
{
	(void)core_hz;
}

/* TIM11 CH1 sees HSE / RTCPRE; IC1PSC captures every 1, 2, 4 or 8 edges. */
static void tim11_capture(void)
{
	uint32_t rtcpre = (RCC_CFGR >> 16) & 0x1FU;
	uint32_t psc = 1U << ((TIM11_CCMR1 >> 2) & 3U);
	bool routed = (RCC_APB2ENR & (1U << 18)) != 0U && (TIM11_CR1 & 1U) != 0U &&
		      (TIM11_OR & 3U) == 2U && (TIM11_CCMR1 & 3U) == 1U && (TIM11_CCER & 1U) != 0U;

	if (!routed || !crystal_fitted || !tim11_edges || rtcpre < 2U) {
		return;
	}
	capture_num += (uint64_t)16000000U * rtcpre * psc; /* timer on the 16 MHz HSI */
	TIM11_CCR1 = (uint32_t)((capture_num / crystal_hz) & 0xFFFFU);
	TIM11_SR |= 1U << 1; /* CC1IF */
}

int stm32_wait_reg(volatile const uint32_t *reg, uint32_t mask, uint32_t value, uint32_t timeout_us)
{
	(void)timeout_us;
	if (reg == &RCC_CR) {
		RCC_CR = (RCC_CR & ~((1U << 17) | (1U << 25))) |
			 (((RCC_CR & (1U << 16)) != 0U && crystal_fitted) ? (1U << 17) : 0U) |
			 ((RCC_CR & (1U << 24)) != 0U ? (1U << 25) : 0U);
	} else if (reg == &RCC_CFGR) {
		RCC_CFGR = (RCC_CFGR & ~(3U << 2)) | ((RCC_CFGR & 3U) << 2);
	} else if (reg == &TIM11_SR) {
		tim11_capture();
	}
	return ((*reg & mask) == value) ? SQ_OK : SQ_EAGAIN;
}

static int setup(void **state)
{
	(void)state;
	regsim_f4_reset();
	crystal_fitted = true;
	crystal_hz = 8000000U;
	tim11_edges = true;
	capture_num = 0U;
	return 0;
}

static void assert_on_hsi(void)
{
	assert_int_equal(RCC_CFGR & 3U, 0U);        /* SW = HSI  */
	assert_int_equal(RCC_CR & (1U << 24), 0U);  /* PLL off   */
	assert_int_equal(RCC_CR & (1U << 16), 0U);  /* HSE off   */
	assert_int_equal(RCC_CR & (1U << 19), 0U);  /* CSS off   */
	assert_int_equal(chip_core_hz(), 16000000U);
	assert_int_equal(chip_apb1_hz(), 16000000U);
}

static void test_8mhz_crystal_runs_pll_at_168(void **state)
{
	uint32_t pll;
	uint32_t m, n, p, q;

	(void)state;
	assert_int_equal(chip_clock_init(), SQ_OK);
	/* 16 captures x 8 edges x 31 HSE periods = 7936 ticks at 16 MHz */
	assert_int_equal(chip_hse_measured_hz(), 8000000U);
	pll = RCC_PLLCFGR;
	m = pll & 0x3FU;
	n = (pll >> 6) & 0x1FFU;
	p = 2U * (((pll >> 16) & 3U) + 1U);
	q = (pll >> 24) & 0xFU;
	assert_true((pll & (1U << 22)) != 0U);         /* source HSE */
	assert_int_equal(8000000U / m, 2000000U);      /* VCO input 2 MHz (M = 4) */
	assert_int_equal(8000000U / m * n / p, 168000000U);
	assert_int_equal(8000000U / m * n / q, 48000000U);
	assert_int_equal(RCC_CFGR & 3U, 2U);           /* SW = PLL */
	assert_true((RCC_CR & (1U << 19)) != 0U);      /* CSSON */
	assert_int_equal(FLASH_ACR & 7U, 5U);          /* 5 wait states */
	assert_int_equal(chip_core_hz(), 168000000U);
	assert_int_equal(chip_apb1_hz(), 42000000U);
}

static void test_12mhz_crystal_falls_back_to_hsi(void **state)
{
	uint32_t hz;

	(void)state;
	crystal_hz = 12000000U;
	assert_int_equal(chip_clock_init(), SQ_EAGAIN);
	hz = chip_hse_measured_hz();
	assert_true(hz > 11988000U && hz < 12012000U); /* within 0.1 % */
	assert_on_hsi();
}

static void test_crystal_tolerance_window(void **state)
{
	(void)state;
	crystal_hz = 8400000U; /* +5 %: the HSI's own error over temperature */
	assert_int_equal(chip_clock_init(), SQ_OK);
	setup(NULL);
	crystal_hz = 9000000U; /* +12.5 % */
	assert_int_equal(chip_clock_init(), SQ_EAGAIN);
	assert_on_hsi();
	setup(NULL);
	crystal_hz = 7000000U; /* -12.5 % */
	assert_int_equal(chip_clock_init(), SQ_EAGAIN);
	assert_on_hsi();
}

static void test_no_crystal(void **state)
{
	(void)state;
	crystal_fitted = false;
	assert_int_equal(chip_clock_init(), SQ_EAGAIN);
	assert_int_equal(chip_hse_measured_hz(), 0U);
	assert_on_hsi();
}

static void test_no_capture_edges_is_no_switch(void **state)
{
	(void)state;
	tim11_edges = false;
	assert_int_equal(chip_clock_init(), SQ_EAGAIN);
	assert_int_equal(chip_hse_measured_hz(), 0U);
	assert_on_hsi();
	assert_int_equal(RCC_APB2ENR & (1U << 18), 0U); /* TIM11 clock off again */
}

/* FLASH_OPTCR BOR_LEV (bits 3:2): 00 level 3, 01 level 2, 10 level 1, 11 off */
static void test_bor_level(void **state)
{
	(void)state;
	FLASH_OPTCR = 0x0FFFAAEDU; /* factory value: BOR off */
	assert_int_equal(chip_bor_level(), 0U);
	FLASH_OPTCR = 0x0FFFAAE9U;
	assert_int_equal(chip_bor_level(), 1U);
	FLASH_OPTCR = 0x0FFFAAE5U;
	assert_int_equal(chip_bor_level(), 2U);
	FLASH_OPTCR = 0x0FFFAAE1U;
	assert_int_equal(chip_bor_level(), 3U);
}

SQ_CMOCKA_MAIN(
	cmocka_unit_test_setup(test_8mhz_crystal_runs_pll_at_168, setup),
	cmocka_unit_test_setup(test_12mhz_crystal_falls_back_to_hsi, setup),
	cmocka_unit_test_setup(test_crystal_tolerance_window, setup),
	cmocka_unit_test_setup(test_no_crystal, setup),
	cmocka_unit_test_setup(test_no_capture_edges_is_no_switch, setup),
	cmocka_unit_test_setup(test_bor_level, setup))
