/* SPDX-License-Identifier: MIT */
/*
 * The real STM32G474 chip header with the peripherals chip_g4.c touches
 * moved into plain arrays (tests/hal/stm32g4/test_chip_g4.c), like
 * regsim/f4. Two registers are the test's functions: FLASH_KEYR appends to
 * a log (the unlock sequence is checked), FLASH_CR is handed out by the
 * test, which clears LOCK once the log ends in KEY1, KEY2 (RM0440 3.3),
 * and FLASH_SR too, so that a write clears the flags it has 1s for; the
 * flash's bytes are read through the test (regsim_flash_load8).
 * Built without PIE: the calibration's addresses fit in 32 bits as on the
 * chip.
 */
#ifndef REGSIM_G4_CHIP_H
#define REGSIM_G4_CHIP_H

#include "../../../../hal/stm32g4/stm32g474/chip.h"

#include <stdint.h>

extern uint32_t regsim_rcc[64], regsim_pwr[40], regsim_flash[16], regsim_tim17[32], regsim_gpioa[16],
	regsim_gpiob[16], regsim_keyr_log[8], regsim_keyr_n;
volatile uint32_t *regsim_flash_cr(void);
volatile uint32_t *regsim_flash_sr(void);
extern uint8_t regsim_flash_mem[];
#undef RCC_BASE
#undef IWDG_BASE
#undef PWR_BASE
#undef FLASH_R_BASE
#undef TIM17_BASE
#undef GPIOA_BASE
#undef GPIOB_BASE
#undef FLASH_KEYR
#undef FLASH_CR
#undef FLASH_SR
#undef CHIP_FLASH_BASE
#undef CHIP_FLASH_BANK2
#undef CHIP_FLASH_LOAD8
#define RCC_BASE ((uintptr_t)regsim_rcc)
extern uint32_t regsim_iwdg[4];
#define IWDG_BASE ((uintptr_t)regsim_iwdg) /* kicked by calib_flash.c */
#define PWR_BASE ((uintptr_t)regsim_pwr)
#define FLASH_R_BASE ((uintptr_t)regsim_flash)
#define TIM17_BASE ((uintptr_t)regsim_tim17)
#define GPIOA_BASE ((uintptr_t)regsim_gpioa)
#define GPIOB_BASE ((uintptr_t)regsim_gpiob)
#define FLASH_KEYR regsim_keyr_log[(regsim_keyr_n++) & 7U]
#define FLASH_CR (*regsim_flash_cr())
#define FLASH_SR (*regsim_flash_sr())
/* 512 KiB of flash would be a large array: the test's 8 KiB (the two
 * calibration slots, which are all it holds) sit regsim_flash_mem_at bytes
 * from the flash's start, 0x7E000 (its last 8 KiB) unless a test moves
 * them. */
extern uint32_t regsim_flash_mem_at;
#define CHIP_FLASH_BASE ((uint32_t)(uintptr_t)regsim_flash_mem - regsim_flash_mem_at)
#define CHIP_FLASH_BANK2 (CHIP_FLASH_BASE + 0x40000U)
/* chip_flash_read's loads: the test's flash, where a double word a power
 * cut interrupted has an ECC double error and its read raises the "NMI"
 * (FLASH_ECCR set, chip_nmi_flash_ecc() called, as the core would) */
uint8_t regsim_flash_load8(uint32_t addr);
#define CHIP_FLASH_LOAD8(addr) regsim_flash_load8(addr)

#endif /* REGSIM_G4_CHIP_H */
