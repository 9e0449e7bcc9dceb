/* SPDX-License-Identifier: MIT */
/*
 * The STM32F405 chip header for host builds of the bxCAN driver: the real
 * hal/stm32f4/stm32f405/chip.h (bit names, interrupt numbers, offsets), with
 * the peripheral bases moved onto the simulation (tests/hal/stm32f4/bxcan_sim.c).
 * CAN registers go through can_rd()/can_wr() (BXCAN_SIM) to the simulated
 * controller; RCC and GPIO are plain memory the simulation reads.
 */
#ifndef BXCAN_SIM_CHIP_H
#define BXCAN_SIM_CHIP_H

#include "../../../../hal/stm32f4/stm32f405/chip.h"

#include <stdint.h>

extern uint32_t bxcan_sim_rcc[64];
extern uint32_t bxcan_sim_gpiob[16];

#undef CAN1_BASE
#undef CAN2_BASE
#undef RCC_BASE
#undef GPIOB_BASE
#define CAN1_BASE 0x1000UL /* handles for can_rd()/can_wr(), never dereferenced */
#define CAN2_BASE 0x2000UL
#define RCC_BASE ((uintptr_t)bxcan_sim_rcc)
#define GPIOB_BASE ((uintptr_t)bxcan_sim_gpiob)

#endif /* BXCAN_SIM_CHIP_H */
