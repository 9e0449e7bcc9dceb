/* SPDX-License-Identifier: MIT */
/*
 * STM32F4 flash erase and program for the calibration sectors (RM0090
 * section 3.6): unlock with the key sequence, one sector erase, 32-bit
 * programming (2.7..3.6 V), every BSY wait bounded, errors from FLASH_SR,
 * the data cache flushed afterwards so reads see the new contents.
 */
#include <stddef.h>

#include "chip.h"
#include "hal.h"
#include "stm32_time.h"

extern const uint8_t __calib_first_sector[];

/* RM0090 / datasheet: 16 KiB sector erase max 500 ms (x32), word program
 * max 100 us; bounds with margin. */
#define ERASE_TIMEOUT_US  2000000UL
#define PROGRAM_TIMEOUT_US   1000UL

static uint32_t saved_acr;

/* Also turns the data cache off for the operation, so that verify reads
 * come from the array, not from lines cached before. */
static int f4_flash_unlock(void)
{
	saved_acr = FLASH_ACR;
	FLASH_ACR = saved_acr & ~FLASH_ACR_DCEN;
	return chip_flash_unlock();
}

static void flash_lock_and_flush(void)
{
	uint32_t acr = saved_acr;

	FLASH_CR = FLASH_CR_LOCK;
	/* The data cache may still hold the old words (RM0090 3.5.2). */
	FLASH_ACR = acr & ~FLASH_ACR_DCEN;
	FLASH_ACR = (acr & ~FLASH_ACR_DCEN) | FLASH_ACR_DCRST;
	FLASH_ACR = acr;
}

int chip_flash_erase_slot(uint32_t slot)
{
	uint32_t sector = (uint32_t)(uintptr_t)__calib_first_sector + slot;
	int rc;

	if (slot > 1U || sector > 11U) {
		return SQ_EINVAL;
	}
	if (f4_flash_unlock() != SQ_OK) {
		flash_lock_and_flush();
		return SQ_EIO;
	}
	FLASH_CR = FLASH_CR_PSIZE_X32 | FLASH_CR_SER | (sector << FLASH_CR_SNB_SHIFT);
	FLASH_CR |= FLASH_CR_STRT;
	rc = chip_flash_wait_done(ERASE_TIMEOUT_US);
	flash_lock_and_flush();
	return rc;
}

/* addr word-aligned; a tail shorter than a word is padded with 0xFF. */
int chip_flash_program(uint32_t addr, const uint8_t *data, uint32_t len)
{
	uint32_t off;
	int rc = SQ_OK;

	if ((addr & 3U) != 0U || data == NULL) {
		return SQ_EINVAL;
	}
	if (f4_flash_unlock() != SQ_OK) {
		flash_lock_and_flush();
		return SQ_EIO;
	}
	FLASH_CR = FLASH_CR_PSIZE_X32 | FLASH_CR_PG;
	for (off = 0; off < len && rc == SQ_OK; off += 4U) {
		uint32_t w = 0xFFFFFFFFUL;
		uint32_t k;

		for (k = 0; k < 4U && off + k < len; k++) {
			w &= ~(0xFFUL << (8U * k));
			w |= (uint32_t)data[off + k] << (8U * k);
		}
		REG32(addr + off) = w;
		cm_dsb();
		rc = chip_flash_wait_done(PROGRAM_TIMEOUT_US);
		if (rc == SQ_OK && REG32(addr + off) != w) {
			rc = SQ_EIO;
		}
	}
	flash_lock_and_flush();
	return rc;
}
