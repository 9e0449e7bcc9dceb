/* SPDX-License-Identifier: MIT */
/*
 * STM32F405 clocks (RM0090 section 7): HSE 8 MHz -> PLL -> 168 MHz, flash
 * wait states, bus prescalers. Each step waits for its ready flag with a
 * bound in real time; if one does not come, the chip stays on (or returns
 * to) the 16 MHz HSI and the caller reports HAL_FAULT_CLOCK_FALLBACK. The
 * firmware still runs, slower and with the HSI's 1 % tolerance (too loose
 * for a reliable CAN bit timing, hence the fault).
 */
#include "chip.h"
#include "hal_stm32.h"

/* Bounds, from the datasheet with margin: HSE start-up is typically 2 ms
 * (crystal dependent), PLL lock 100..200 us, a clock switch a few cycles. */
#define HSE_TIMEOUT_US    100000UL
#define PLL_TIMEOUT_US      5000UL
#define SWITCH_TIMEOUT_US   5000UL

static uint32_t core_hz = CHIP_HSI_HZ;
static uint32_t apb1_hz = CHIP_HSI_HZ;

static void clock_back_to_hsi(void)
{
	RCC_CFGR &= ~(RCC_CFGR_SW_MSK | RCC_CFGR_HPRE_MSK | RCC_CFGR_PPRE1_MSK | RCC_CFGR_PPRE2_MSK);
	(void)stm32_wait_reg(&RCC_CFGR, RCC_CFGR_SWS_MSK, 0U, SWITCH_TIMEOUT_US);
	RCC_CR &= ~(RCC_CR_PLLON | RCC_CR_HSEON);
	FLASH_ACR = FLASH_ACR_PRFTEN | FLASH_ACR_ICEN | FLASH_ACR_DCEN; /* 0 WS at 16 MHz */
	core_hz = CHIP_HSI_HZ;
	apb1_hz = CHIP_HSI_HZ;
}

int chip_clock_init(void)
{
	uint32_t acr;

	core_hz = CHIP_HSI_HZ;
	apb1_hz = CHIP_HSI_HZ;
	stm32_time_early_init(CHIP_HSI_HZ);

	RCC_CR |= RCC_CR_HSEON;
	if (stm32_wait_reg(&RCC_CR, RCC_CR_HSERDY, RCC_CR_HSERDY, HSE_TIMEOUT_US) != SQ_OK) {
		clock_back_to_hsi();
		return SQ_EAGAIN;
	}
	/* Regulator scale 1: needed above 144 MHz. */
	RCC_APB1ENR |= RCC_APB1ENR_PWREN;
	(void)RCC_APB1ENR; /* read back: the enable needs two cycles */
	PWR_CR |= PWR_CR_VOS;

	RCC_PLLCFGR = (8UL << RCC_PLLCFGR_PLLM_SHIFT) | (336UL << RCC_PLLCFGR_PLLN_SHIFT) |
		      (0UL << RCC_PLLCFGR_PLLP_SHIFT) | RCC_PLLCFGR_PLLSRC_HSE |
		      (7UL << RCC_PLLCFGR_PLLQ_SHIFT);
	RCC_CR |= RCC_CR_PLLON;
	if (stm32_wait_reg(&RCC_CR, RCC_CR_PLLRDY, RCC_CR_PLLRDY, PLL_TIMEOUT_US) != SQ_OK) {
		clock_back_to_hsi();
		return SQ_EAGAIN;
	}
	/* Wait states first, checked by reading back (RM0090 3.5.1). */
	acr = FLASH_ACR_LATENCY_5WS | FLASH_ACR_PRFTEN | FLASH_ACR_ICEN | FLASH_ACR_DCEN;
	FLASH_ACR = acr;
	if ((FLASH_ACR & FLASH_ACR_LATENCY_MSK) != FLASH_ACR_LATENCY_5WS) {
		clock_back_to_hsi();
		return SQ_EAGAIN;
	}
	RCC_CFGR = (RCC_CFGR & ~(RCC_CFGR_HPRE_MSK | RCC_CFGR_PPRE1_MSK | RCC_CFGR_PPRE2_MSK)) |
		   RCC_CFGR_PPRE1_DIV4 | RCC_CFGR_PPRE2_DIV2;
	RCC_CFGR = (RCC_CFGR & ~RCC_CFGR_SW_MSK) | RCC_CFGR_SW_PLL;
	if (stm32_wait_reg(&RCC_CFGR, RCC_CFGR_SWS_MSK, RCC_CFGR_SWS_PLL, SWITCH_TIMEOUT_US) != SQ_OK) {
		clock_back_to_hsi();
		return SQ_EAGAIN;
	}
	core_hz = CHIP_SYSCLK_HZ;
	apb1_hz = CHIP_APB1_HZ;
	return SQ_OK;
}

uint32_t chip_core_hz(void)
{
	return core_hz;
}

uint32_t chip_apb1_hz(void)
{
	return apb1_hz;
}

/* CAN1 on PB8 (RX) / PB9 (TX), alternate function 9 (datasheet table 9). */
void chip_can_pins_init(void)
{
	uint32_t v;

	RCC_AHB1ENR |= RCC_AHB1ENR_GPIOBEN;
	RCC_APB1ENR |= RCC_APB1ENR_CAN1EN;
	(void)RCC_APB1ENR;
	/* AF9 on pins 8 and 9 (AFRH nibbles 0 and 1) */
	v = GPIO_AFRH(GPIOB_BASE) & ~0xFFUL;
	GPIO_AFRH(GPIOB_BASE) = v | (GPIO_AF9_CAN1 << 0) | (GPIO_AF9_CAN1 << 4);
	/* Alternate-function mode, high speed, pull-up on RX (recessive when
	 * no transceiver drives it), push-pull TX */
	v = GPIO_MODER(GPIOB_BASE) & ~((3UL << 16) | (3UL << 18));
	GPIO_MODER(GPIOB_BASE) = v | (GPIO_MODE_AF << 16) | (GPIO_MODE_AF << 18);
	v = GPIO_OSPEEDR(GPIOB_BASE) & ~((3UL << 16) | (3UL << 18));
	GPIO_OSPEEDR(GPIOB_BASE) = v | (GPIO_SPEED_HIGH << 16) | (GPIO_SPEED_HIGH << 18);
	GPIO_OTYPER(GPIOB_BASE) &= ~((1UL << 8) | (1UL << 9));
	v = GPIO_PUPDR(GPIOB_BASE) & ~((3UL << 16) | (3UL << 18));
	GPIO_PUPDR(GPIOB_BASE) = v | (GPIO_PUPD_UP << 16);
}
