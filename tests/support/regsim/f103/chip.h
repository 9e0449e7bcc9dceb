/* SPDX-License-Identifier: MIT */
/*
 * The real STM32F103 chip header with its peripherals moved into plain
 * arrays (tests/hal/stm32f103/test_chip_f1.c): chip_f1.c and iwdg.c on the host.
 */
#ifndef REGSIM_F103_CHIP_H
#define REGSIM_F103_CHIP_H

#include "../../../../hal/stm32f103/stm32f103xb/chip.h"

#include <stdint.h>

extern uint32_t regsim_rcc[64], regsim_afio[8], regsim_gpiob[8], regsim_flash[8], regsim_iwdg[4],
	regsim_dbgmcu[4];
#undef RCC_BASE
#undef AFIO_BASE
#undef GPIOB_BASE
#undef FLASH_R_BASE
#undef IWDG_BASE
#undef CHIP_DBGMCU_IWDG_REG
#define RCC_BASE ((uintptr_t)regsim_rcc)
#define AFIO_BASE ((uintptr_t)regsim_afio)
#define GPIOB_BASE ((uintptr_t)regsim_gpiob)
#define FLASH_R_BASE ((uintptr_t)regsim_flash)
#define IWDG_BASE ((uintptr_t)regsim_iwdg)
#define CHIP_DBGMCU_IWDG_REG REG32((uintptr_t)&regsim_dbgmcu[1]) /* 0xE0042004 */

#endif /* REGSIM_F103_CHIP_H */
