/* SPDX-License-Identifier: MIT */
/*
 * The watchdog and reset-cause driver's interface to the other drivers and
 * the board (iwdg.c); the firmware uses hal.h's hal_watchdog_* and
 * hal_reset_reason().
 */
#ifndef STM32_IWDG_H
#define STM32_IWDG_H

#include <stdbool.h>

/* The IWDG was started (iwdg.c): long flash operations must not run now. */
bool stm32_watchdog_running(void);
/* Read RCC_CSR and the fault record once at boot (iwdg.c). */
void stm32_reset_reason_capture(void);

#endif /* STM32_IWDG_H */
