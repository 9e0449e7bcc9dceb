/* SPDX-License-Identifier: MIT */
/*
 * STM32F103 specifics for the shared bare-metal HAL: clocks (HSE 8 MHz x 9
 * = 72 MHz, HSI 8 MHz fallback reported by the caller), CAN pins (remapped
 * to PB8 RX / PB9 TX, like the F4 board), and calibration flash: a slot is
 * two 1 KiB pages, erased first page (the slot header) first, and half-word
 * programming (RM0008 / PM0075), every wait bounded.
 */
#include <stddef.h>

#include "chip.h"
#include "stm32_time.h"
#include "sq_status.h"

#define HSE_TIMEOUT_US    100000U
#define PLL_TIMEOUT_US      5000U
#define SWITCH_TIMEOUT_US   5000U
#define ERASE_TIMEOUT_US   100000U /* page erase max 40 ms */
#define PROGRAM_TIMEOUT_US   1000U /* half-word max 70 us  */
#define FLASH_PAGE_BYTES     1024U /* medium density                  */
#define SLOT_PAGES_MAX          4U /* bound of the erase loop          */

extern const uint8_t __calib_start[];
extern const uint8_t __calib_slot_size[];

static void f1_clock_back_to_hsi(void)
{
	RCC_CFGR &= ~(RCC_CFGR_SW_MSK | RCC_CFGR_HPRE_MSK | RCC_CFGR_PPRE1_MSK | RCC_CFGR_PPRE2_MSK);
	(void)stm32_wait_reg(&RCC_CFGR, RCC_CFGR_SWS_MSK, 0U, SWITCH_TIMEOUT_US);
	RCC_CR &= ~(RCC_CR_PLLON | RCC_CR_HSEON);
	FLASH_ACR = FLASH_ACR_PRFTBE; /* 0 WS at 8 MHz */
	chip_clock_rates_set(false);
}

int chip_clock_init(void)
{
	chip_clock_rates_set(false);
	stm32_time_early_init(CHIP_HSI_HZ);

	RCC_CR |= RCC_CR_HSEON;
	if (stm32_wait_reg(&RCC_CR, RCC_CR_HSERDY, RCC_CR_HSERDY, HSE_TIMEOUT_US) != SQ_OK) {
		f1_clock_back_to_hsi();
		return SQ_EAGAIN;
	}
	RCC_CFGR = (RCC_CFGR & ~(RCC_CFGR_PLLMUL_MSK | RCC_CFGR_PLLXTPRE)) |
		   RCC_CFGR_PLLSRC_HSE | RCC_CFGR_PLLMUL9;
	RCC_CR |= RCC_CR_PLLON;
	if (stm32_wait_reg(&RCC_CR, RCC_CR_PLLRDY, RCC_CR_PLLRDY, PLL_TIMEOUT_US) != SQ_OK) {
		f1_clock_back_to_hsi();
		return SQ_EAGAIN;
	}
	FLASH_ACR = FLASH_ACR_PRFTBE | FLASH_ACR_LATENCY_2WS;
	if ((FLASH_ACR & FLASH_ACR_LATENCY_MSK) != FLASH_ACR_LATENCY_2WS) {
		f1_clock_back_to_hsi();
		return SQ_EAGAIN;
	}
	RCC_CFGR = (RCC_CFGR & ~(RCC_CFGR_HPRE_MSK | RCC_CFGR_PPRE1_MSK | RCC_CFGR_PPRE2_MSK)) |
		   RCC_CFGR_PPRE1_DIV2;
	RCC_CFGR = (RCC_CFGR & ~RCC_CFGR_SW_MSK) | RCC_CFGR_SW_PLL;
	if (stm32_wait_reg(&RCC_CFGR, RCC_CFGR_SWS_MSK, RCC_CFGR_SWS_PLL, SWITCH_TIMEOUT_US) != SQ_OK) {
		f1_clock_back_to_hsi();
		return SQ_EAGAIN;
	}
	chip_clock_rates_set(true);
	return SQ_OK;
}

uint32_t chip_hse_measured_hz(void)
{
	return CHIP_HSE_NOT_MEASURED;
}

uint32_t chip_bor_level(void)
{
	return CHIP_BOR_NONE;
}

void chip_can_pins_init(uint8_t bus)
{
	uint32_t v;

	if (bus != 0U) {
		return; /* CAN1 only */
	}

	RCC_APB2ENR |= RCC_APB2ENR_AFIOEN | RCC_APB2ENR_IOPBEN;
	RCC_APB1ENR |= RCC_APB1ENR_CAN1EN;
	(void)RCC_APB1ENR;
	/* SWJ_CFG (26:24) is write-only and reads back undefined: a plain
	 * read-modify-write could switch SWD off. Mask it and write 000
	 * (full SWJ, the reset state). */
	AFIO_MAPR = (AFIO_MAPR & ~(AFIO_MAPR_CAN_REMAP_MSK | AFIO_MAPR_SWJ_CFG_MSK)) |
		    AFIO_MAPR_CAN_REMAP_PB89 | AFIO_MAPR_SWJ_CFG_FULL;
	/* PB8: input with pull-up (CNF 10, MODE 00); PB9: AF push-pull 50 MHz
	 * (CNF 10, MODE 11) */
	v = GPIO_CRH(GPIOB_BASE) & ~0xFFU;
	GPIO_CRH(GPIOB_BASE) = v | 0x8U | (0xBU << 4);
	GPIO_ODR(GPIOB_BASE) |= 1U << 8;
}

/* chip_flash_wait_done, then EOP cleared (write 1) for the next step */
static int flash_wait_done(uint32_t timeout_us)
{
	if (chip_flash_wait_done(timeout_us) != SQ_OK) {
		return SQ_EIO;
	}
	FLASH_SR = FLASH_SR_EOP;
	return SQ_OK;
}

/* The header is in the slot's first page, erased first: a power cut after
 * it leaves a slot without a valid header (ignored), never a valid header
 * over a half-erased payload. */
int chip_flash_erase_slot(uint32_t slot)
{
	const uint32_t size = (uint32_t)(uintptr_t)__calib_slot_size;
	const uint32_t addr = (uint32_t)(uintptr_t)__calib_start + slot * size;
	const uint32_t pages = size / FLASH_PAGE_BYTES;
	uint32_t page;
	int rc = SQ_OK;

	if ((slot > 1U) || (pages == 0U) || (pages > SLOT_PAGES_MAX) ||
	    ((size % FLASH_PAGE_BYTES) != 0U)) {
		return SQ_EINVAL;
	}
	if (chip_flash_unlock() != SQ_OK) {
		FLASH_CR = FLASH_CR_LOCK;
		return SQ_EIO;
	}
	for (page = 0U; (page < pages) && (rc == SQ_OK); page++) {
		FLASH_CR = FLASH_CR_PER;
		FLASH_AR = addr + (page * FLASH_PAGE_BYTES);
		FLASH_CR = FLASH_CR_PER | FLASH_CR_STRT;
		rc = flash_wait_done(ERASE_TIMEOUT_US);
	}
	FLASH_CR = FLASH_CR_LOCK;
	return rc;
}

/* addr half-word aligned; an odd tail is padded with 0xFF. */
int chip_flash_program(uint32_t addr, const uint8_t *data, uint32_t len)
{
	uint32_t off;
	int rc = SQ_OK;

	if ((addr & 1U) != 0U || data == NULL) {
		return SQ_EINVAL;
	}
	if (chip_flash_unlock() != SQ_OK) {
		FLASH_CR = FLASH_CR_LOCK;
		return SQ_EIO;
	}
	FLASH_CR = FLASH_CR_PG;
	for (off = 0; off < len && rc == SQ_OK; off += 2U) {
		uint16_t hw = (uint16_t)(data[off] | (off + 1U < len ? (uint32_t)data[off + 1U] << 8 : 0xFF00U));

		*(volatile uint16_t *)(uintptr_t)(addr + off) = hw;
		rc = flash_wait_done(PROGRAM_TIMEOUT_US);
		if (rc == SQ_OK && *(volatile const uint16_t *)(uintptr_t)(addr + off) != hw) {
			rc = SQ_EIO;
		}
	}
	FLASH_CR = FLASH_CR_LOCK;
	return rc;
}
