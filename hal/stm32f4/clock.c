/* SPDX-License-Identifier: MIT */
/*
 * STM32F405 clocks (RM0090 section 7): HSE 8 MHz -> PLL -> 168 MHz, flash
 * wait states, bus prescalers. Before the switch the crystal is measured
 * against the HSI (TIM11 input capture of HSE_RTC = HSE / 31): a crystal
 * that is not CHIP_HSE_HZ (+-10 %, the HSI's own error over temperature
 * included) would run the core and CAN at the wrong rate, so the chip
 * stays on the HSI and reports the fallback. After the switch the clock
 * security system (CSS) watches the crystal: if it stops, the NMI records
 * the fault and resets, and the next start falls back to the HSI. Each step waits for its ready flag with a
 * bound in real time; if one does not come, the chip stays on (or returns
 * to) the 16 MHz HSI and the caller reports HAL_FAULT_CLOCK_FALLBACK. The
 * firmware still runs, slower and with the HSI's 1 % tolerance (too loose
 * for a reliable CAN bit timing, hence the fault).
 */
#include <stddef.h>

#include "chip.h"
#include "stm32_hse_meter.h"
#include "stm32_time.h"
#include "sq_status.h"

/* Bounds, from the datasheet with margin: HSE start-up is typically 2 ms
 * (crystal dependent), PLL lock 100..200 us, a clock switch a few cycles. */
#define HSE_TIMEOUT_US    100000U
#define PLL_TIMEOUT_US      5000U
#define SWITCH_TIMEOUT_US   5000U
/* HSE measurement: HSE_RTC = HSE/31 into TIM11 CH1 (stm32_hse_meter.h);
 * 16 captures of 8 * 31 HSE periods each (496 HSI ticks at 8 MHz: 7936 in
 * all, resolution 0.013 %). */
#define MEAS_RTCPRE 31U

static uint32_t hse_measured_hz;

/* The HSE in Hz, timed by TIM11 on the HSI (APB2 = 16 MHz now); 0 if no
 * edge comes. The HSE is running (HSERDY), the PLL is not in use yet. */
static uint32_t hse_measure(void)
{
	uint32_t hz;

	RCC_APB2ENR |= RCC_APB2ENR_TIM11EN;
	(void)RCC_APB2ENR;
	RCC_CFGR = (RCC_CFGR & ~RCC_CFGR_RTCPRE_MSK) | (MEAS_RTCPRE << RCC_CFGR_RTCPRE_SHIFT);
	TIM11_OR = TIM11_OR_TI1_HSE_RTC;
	hz = stm32_hse_meter_run(TIM11_BASE, MEAS_RTCPRE, CHIP_HSI_HZ);
	RCC_APB2ENR &= ~RCC_APB2ENR_TIM11EN;
	return hz;
}

uint32_t chip_hse_measured_hz(void)
{
	return hse_measured_hz;
}

uint32_t chip_bor_level(void)
{
	/* BOR_LEV 00 = level 3 ... 11 = off (level "0" here) */
	return 3U - ((FLASH_OPTCR & FLASH_OPTCR_BOR_LEV_MSK) >> FLASH_OPTCR_BOR_LEV_SHIFT);
}

static void f4_clock_back_to_hsi(void)
{
	RCC_CFGR &= ~(RCC_CFGR_SW_MSK | RCC_CFGR_HPRE_MSK | RCC_CFGR_PPRE1_MSK | RCC_CFGR_PPRE2_MSK);
	(void)stm32_wait_reg(&RCC_CFGR, RCC_CFGR_SWS_MSK, 0U, SWITCH_TIMEOUT_US);
	RCC_CR &= ~(RCC_CR_CSSON | RCC_CR_PLLON | RCC_CR_HSEON);
	FLASH_ACR = FLASH_ACR_PRFTEN | FLASH_ACR_ICEN | FLASH_ACR_DCEN; /* 0 WS at 16 MHz */
	chip_clock_rates_set(false);
}

int chip_clock_init(void)
{
	uint32_t acr;

	chip_clock_rates_set(false);
	hse_measured_hz = 0U;
	stm32_time_early_init(CHIP_HSI_HZ);

	RCC_CR |= RCC_CR_HSEON;
	if (stm32_wait_reg(&RCC_CR, RCC_CR_HSERDY, RCC_CR_HSERDY, HSE_TIMEOUT_US) != SQ_OK) {
		f4_clock_back_to_hsi();
		return SQ_EAGAIN;
	}
	hse_measured_hz = hse_measure();
	if (!stm32_hse_in_tolerance(hse_measured_hz, CHIP_HSE_HZ)) {
		f4_clock_back_to_hsi();
		return SQ_EAGAIN;
	}
	/* Regulator scale 1: needed above 144 MHz. */
	RCC_APB1ENR |= RCC_APB1ENR_PWREN;
	(void)RCC_APB1ENR; /* read back: the enable needs two cycles */
	PWR_CR |= PWR_CR_VOS;

	RCC_PLLCFGR = (4U << RCC_PLLCFGR_PLLM_SHIFT) | (168U << RCC_PLLCFGR_PLLN_SHIFT) |
		      (0U << RCC_PLLCFGR_PLLP_SHIFT) | RCC_PLLCFGR_PLLSRC_HSE |
		      (7U << RCC_PLLCFGR_PLLQ_SHIFT);
	RCC_CR |= RCC_CR_PLLON;
	if (stm32_wait_reg(&RCC_CR, RCC_CR_PLLRDY, RCC_CR_PLLRDY, PLL_TIMEOUT_US) != SQ_OK) {
		f4_clock_back_to_hsi();
		return SQ_EAGAIN;
	}
	/* Wait states first, checked by reading back (RM0090 3.5.1). */
	acr = FLASH_ACR_LATENCY_5WS | FLASH_ACR_PRFTEN | FLASH_ACR_ICEN | FLASH_ACR_DCEN;
	FLASH_ACR = acr;
	if ((FLASH_ACR & FLASH_ACR_LATENCY_MSK) != FLASH_ACR_LATENCY_5WS) {
		f4_clock_back_to_hsi();
		return SQ_EAGAIN;
	}
	RCC_CFGR = (RCC_CFGR & ~(RCC_CFGR_HPRE_MSK | RCC_CFGR_PPRE1_MSK | RCC_CFGR_PPRE2_MSK)) |
		   RCC_CFGR_PPRE1_DIV4 | RCC_CFGR_PPRE2_DIV2;
	RCC_CFGR = (RCC_CFGR & ~RCC_CFGR_SW_MSK) | RCC_CFGR_SW_PLL;
	if (stm32_wait_reg(&RCC_CFGR, RCC_CFGR_SWS_MSK, RCC_CFGR_SWS_PLL, SWITCH_TIMEOUT_US) != SQ_OK) {
		f4_clock_back_to_hsi();
		return SQ_EAGAIN;
	}
	/* A crystal that stops from now on: NMI (startup.c records it). */
	RCC_CR |= RCC_CR_CSSON;
	chip_clock_rates_set(true);
	return SQ_OK;
}
