/* SPDX-License-Identifier: MIT */
/*
 * The real STM32F405 chip header with every peripheral this test touches
 * moved into plain arrays, so the chip files (clock.c, iwdg.c ...) run on the
 * host against memory their tests (tests/hal/stm32f4/test_*.c) inspect and
 * drive. The arrays are regsim_f4.c's; regsim_f4_reset() clears them all.
 */
#ifndef REGSIM_F4_CHIP_H
#define REGSIM_F4_CHIP_H

#include "../../../../hal/stm32f4/stm32f405/chip.h"

#include <stdint.h>

extern uint32_t regsim_rcc[64], regsim_pwr[4], regsim_flash[8], regsim_tim11[32], regsim_iwdg[4],
	regsim_dbgmcu[4], regsim_gpiob[16];
void regsim_f4_reset(void);
int regsim_f4_setup(void **state);
#undef RCC_BASE
#undef PWR_BASE
#undef FLASH_R_BASE
#undef TIM11_BASE
#undef IWDG_BASE
#undef GPIOB_BASE
#undef CHIP_DBGMCU_IWDG_REG
#define RCC_BASE ((uintptr_t)regsim_rcc)
#define PWR_BASE ((uintptr_t)regsim_pwr)
#define FLASH_R_BASE ((uintptr_t)regsim_flash)
#define TIM11_BASE ((uintptr_t)regsim_tim11)
#define IWDG_BASE ((uintptr_t)regsim_iwdg)
#define GPIOB_BASE ((uintptr_t)regsim_gpiob)
#define CHIP_DBGMCU_IWDG_REG REG32((uintptr_t)&regsim_dbgmcu[2]) /* 0xE0042008 */

/* The core's SysTick, SCB and DWT registers (cortex_m.h): plain words,
 * except the two counters, which the test of systick.c drives through a
 * function it defines (each access may see the counter moved on). */
extern uint32_t regsim_syst[3], regsim_scb_icsr, regsim_scb_shpr3, regsim_demcr, regsim_dwt[3];
volatile uint32_t *regsim_syst_cvr(void);
volatile uint32_t *regsim_dwt_cyccnt(void);
#undef SYST_CSR
#undef SYST_RVR
#undef SYST_CVR
#undef SCB_ICSR
#undef SCB_SHPR3
#undef DEMCR
#undef DWT_CTRL
#undef DWT_CYCCNT
#undef DWT_LAR
#define SYST_CSR REG32((uintptr_t)&regsim_syst[0])
#define SYST_RVR REG32((uintptr_t)&regsim_syst[1])
#define SYST_CVR (*regsim_syst_cvr())
#define SCB_ICSR REG32((uintptr_t)&regsim_scb_icsr)
#define SCB_SHPR3 REG32((uintptr_t)&regsim_scb_shpr3)
#define DEMCR REG32((uintptr_t)&regsim_demcr)
#define DWT_CTRL REG32((uintptr_t)&regsim_dwt[0])
#define DWT_CYCCNT (*regsim_dwt_cyccnt())
#define DWT_LAR REG32((uintptr_t)&regsim_dwt[2])

/* REGSIM_F4_FLASH_HOOK (the test of flash.c): every access to FLASH_ACR,
 * FLASH_KEYR, FLASH_SR and FLASH_CR goes through a function the test
 * defines, which first plays the flash interface's answer to the stores
 * since the last access (the key sequence, write-1-to-clear, LOCK). */
#ifdef REGSIM_F4_FLASH_HOOK
volatile uint32_t *regsim_flash_reg(uint32_t offset);
#undef FLASH_ACR
#undef FLASH_KEYR
#undef FLASH_SR
#undef FLASH_CR
#define FLASH_ACR  (*regsim_flash_reg(0x00U))
#define FLASH_KEYR (*regsim_flash_reg(0x04U))
#define FLASH_SR   (*regsim_flash_reg(0x0CU))
#define FLASH_CR   (*regsim_flash_reg(0x10U))
#endif

#endif /* REGSIM_F4_CHIP_H */
