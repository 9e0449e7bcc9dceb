/* SPDX-License-Identifier: MIT */
/*
 * The STM32F4 flash interface as RM0090 describes it, for the tests that
 * simulate it (tests/hal/stm32f4/test_flash.c, test_chip_common.c): its
 * FLASH_CR and FLASH_SR bits, written here from the manual (not from the
 * chip header the code under test uses), and its answer to a store to
 * FLASH_KEYR (3.5.1): FLASH_CR is locked (LOCK) out of reset; KEY1 then
 * KEY2 unlocks it; any other sequence locks it until the next reset; a key
 * while unlocked does nothing.
 */
#ifndef REGSIM_F4_FLASH_RM0090_H
#define REGSIM_F4_FLASH_RM0090_H

#include <stdbool.h>
#include <stdint.h>

#define RM_KEY1 0x45670123U             /* RM0090 3.5.1 */
#define RM_KEY2 0xCDEF89ABU
#define RM_CR_RESET 0x80000000U         /* RM0090 3.8.5: LOCK */
#define RM_CR_PG (1U << 0)              /* RM0090 3.8.5 */
#define RM_CR_SER (1U << 1)
#define RM_CR_SNB(cr) (((cr) >> 3) & 0xFU)
#define RM_CR_PSIZE(cr) (((cr) >> 8) & 3U) /* 2: x32 */
#define RM_CR_STRT (1U << 16)
#define RM_CR_LOCK (1U << 31)
#define RM_SR_EOP (1U << 0)             /* RM0090 3.8.4 */
#define RM_SR_OPERR (1U << 1)
#define RM_SR_WRPERR (1U << 4)
#define RM_SR_PGAERR (1U << 5)
#define RM_SR_PGPERR (1U << 6)
#define RM_SR_PGSERR (1U << 7)
#define RM_SR_BSY (1U << 16)
#define RM_SR_W1C (RM_SR_EOP | RM_SR_OPERR | RM_SR_WRPERR | RM_SR_PGAERR | RM_SR_PGPERR | RM_SR_PGSERR)

struct regsim_flash_keys {
	bool key1_seen;
	bool locked_until_reset;
};

static inline void regsim_flash_key_store(struct regsim_flash_keys *k, uint32_t *cr, uint32_t key)
{
	if (k->locked_until_reset || (*cr & RM_CR_LOCK) == 0U) {
		return;
	}
	if (!k->key1_seen && key == RM_KEY1) {
		k->key1_seen = true;
	} else if (k->key1_seen && key == RM_KEY2) {
		k->key1_seen = false;
		*cr &= ~RM_CR_LOCK;
	} else {
		k->key1_seen = false;
		k->locked_until_reset = true;
	}
}

#endif /* REGSIM_F4_FLASH_RM0090_H */
