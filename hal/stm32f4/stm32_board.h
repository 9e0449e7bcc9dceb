/* SPDX-License-Identifier: MIT */
/*
 * The board (board.c): bring-up and main() of the ECU image. The board
 * knows every driver; no driver includes this header (each includes the
 * interfaces it uses: stm32_platform_faults.h, stm32_iwdg.h, stm32_time.h,
 * stm32_test.h, chip.h). The board's own users (tests of the board's
 * parts) get those interfaces through it.
 */
#ifndef STM32_BOARD_H
#define STM32_BOARD_H

#include <stdbool.h>
#include <stdint.h>

#include "hal.h"
#include "stm32_iwdg.h"
#include "stm32_platform_faults.h"
#include "stm32_test.h"

/* Board bring-up: clocks, time, reset reason, self-test, CAN; interrupts on. */
void stm32_board_init(void);

#endif /* STM32_BOARD_H */
