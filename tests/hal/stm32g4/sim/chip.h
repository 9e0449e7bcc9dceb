/* SPDX-License-Identifier: MIT */
/*
 * The chip header for host builds of the FDCAN driver (FDCAN_SIM): what
 * hal/stm32g4/fdcan.c needs of a G4 chip.h (chip_api.h's calls, the
 * FDCAN interrupt numbers of RM0440 table 97), with the FDCAN instances and
 * the message RAM moved onto the simulation (tests/hal/stm32g4/fdcan_sim.c):
 * these addresses are handles for fd_rd()/fd_wr(), never dereferenced.
 */
#ifndef FDCAN_SIM_CHIP_H
#define FDCAN_SIM_CHIP_H

#include "cortex_m.h"
#include "chip_api.h"
/* the FDCAN kernel clock (the real chip.h declares it too): fdcan_sim.c */
uint32_t chip_fdcan_kernel_hz(void);

#define CHIP_NAME "STM32G474 (simulated FDCAN)"
#define CHIP_IRQ_FDCAN1_IT0 21U
#define CHIP_IRQ_FDCAN2_IT0 86U
#define FDCAN1_BASE 0x1000UL
#define FDCAN2_BASE 0x2000UL
#define SRAMCAN_BASE 0x10000UL

#endif /* FDCAN_SIM_CHIP_H */
