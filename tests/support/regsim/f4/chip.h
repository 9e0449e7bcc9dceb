/* SPDX-License-Identifier: MIT */
/*
 * The real STM32F405 chip header with every peripheral this test touches
 * moved into plain arrays, so the chip files (clock.c, iwdg.c ...) run on the
 * host against memory their tests (tests/hal/stm32f4/test_*.c) inspect and
 * drive. A test defines the arrays its file uses.
 */
#ifndef REGSIM_F4_CHIP_H
#define REGSIM_F4_CHIP_H

#include "../../../../hal/stm32f4/stm32f405/chip.h"

#include <stdint.h>

extern uint32_t regsim_rcc[64], regsim_pwr[4], regsim_flash[8], regsim_tim11[32], regsim_iwdg[4],
	regsim_dbgmcu[4], regsim_gpiob[16];
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

#endif /* REGSIM_F4_CHIP_H */
