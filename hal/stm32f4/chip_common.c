/* SPDX-License-Identifier: MIT */
/*
 * The parts of chip_api.h that every chip does the same way, on its own
 * chip.h's register names: the clock rates in use (set by the chip's
 * clock code, read by the HAL) and the flash unlock key sequence.
 */
#include "chip.h"
#include "stm32_time.h"
#include "sq_status.h"

#define IDLE_TIMEOUT_US 10000U /* a flash operation still running */

static uint32_t core_hz = CHIP_HSI_HZ;
static uint32_t apb1_hz = CHIP_HSI_HZ;

void chip_clock_rates_set(bool on_pll)
{
	core_hz = on_pll ? CHIP_SYSCLK_HZ : CHIP_HSI_HZ;
	apb1_hz = on_pll ? CHIP_APB1_HZ : CHIP_HSI_HZ;
}

uint32_t chip_core_hz(void)
{
	return core_hz;
}

uint32_t chip_apb1_hz(void)
{
	return apb1_hz;
}

int chip_flash_unlock(void)
{
	if (stm32_wait_reg(&FLASH_SR, FLASH_SR_BSY, 0U, IDLE_TIMEOUT_US) != SQ_OK) {
		return SQ_EIO;
	}
	if ((FLASH_CR & FLASH_CR_LOCK) != 0U) {
		FLASH_KEYR = FLASH_KEY1;
		FLASH_KEYR = FLASH_KEY2;
	}
	if ((FLASH_CR & FLASH_CR_LOCK) != 0U) {
		return SQ_EIO; /* wrong sequence locks it until reset */
	}
	FLASH_SR = FLASH_SR_ERRORS | FLASH_SR_EOP; /* write 1 to clear */
	return SQ_OK;
}

#if !defined(CHIP_FLASH_HAS_ECC)
/* No flash ECC (F4, F103): a read is a read. */
int chip_flash_read(uint32_t addr, uint8_t *dst, uint32_t n)
{
	const volatile uint8_t *src = (const volatile uint8_t *)(uintptr_t)addr;
	uint32_t i;

	for (i = 0U; i < n; i++) {
		dst[i] = src[i];
	}
	return SQ_OK;
}
#endif

int chip_flash_wait_done(uint32_t timeout_us)
{
	if (stm32_wait_reg(&FLASH_SR, FLASH_SR_BSY, 0U, timeout_us) != SQ_OK) {
		return SQ_EIO;
	}
	return ((FLASH_SR & FLASH_SR_ERRORS) != 0U) ? SQ_EIO : SQ_OK;
}
