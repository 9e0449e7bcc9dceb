/* SPDX-License-Identifier: MIT */
/*
 * The board interface the drivers report to (board.c, semihost.c): platform
 * fault bits and, in test builds, semihosting events. Drivers include this,
 * stm32_time.h and chip.h; board.c is the one file that knows every driver.
 */
#ifndef STM32_BOARD_H
#define STM32_BOARD_H

#include <stdbool.h>
#include <stdint.h>

#include "hal.h"

/* Raise HAL_FAULT_* bits (hal_platform_faults()); safe from interrupts. */
void stm32_fault_raise(uint32_t hal_fault_bits);

/* The IWDG was started (iwdg.c): long flash operations must not run now. */
bool stm32_watchdog_running(void);
/* Read RCC_CSR and the fault record once at boot (iwdg.c). */
void stm32_reset_reason_capture(void);

/* Board bring-up: clocks, time, reset reason, self-test, CAN; interrupts on. */
void stm32_board_init(void);

/* ---- semihosting (semihost.c), test builds only ---------------------------- */

#if defined(SQ_TARGET_TEST)
void semihost_write0(const char *s);
void semihost_exit(uint32_t code) __attribute__((noreturn));
/* "key=value" line helpers: no printf on the target. */
void semihost_print_u32(const char *prefix, uint32_t value, const char *suffix);
void semihost_print_hex(const char *prefix, uint32_t value, const char *suffix);
/* Test event hook: the test build reports boot, faults, watchdog kicks. */
void stm32_test_event(const char *what, uint32_t value);
#define STM32_TEST_EVENT(what, value) stm32_test_event((what), (value))
#else
#define STM32_TEST_EVENT(what, value) ((void)0)
#endif

#endif /* STM32_BOARD_H */
