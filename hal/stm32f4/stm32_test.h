/* SPDX-License-Identifier: MIT */
/*
 * Test images only (-DSQ_TARGET_TEST, run under qemu-system-arm): the
 * semihosting output (semihost.c), the event sink the drivers report to
 * (test_events.c) and the main-loop hook of the test run (test_run.c).
 * None of these files is linked into the ECU image (mk/target.mk); in it
 * STM32_TEST_EVENT() is nothing.
 *
 * Layers, each knowing only the ones below it: board.c calls the test run
 * (test_run.c), which reads the drivers and the event sink; the drivers
 * (bxcan.c, iwdg.c, platform_faults.c) call only the event sink, which
 * knows no driver.
 */
#ifndef STM32_TEST_H
#define STM32_TEST_H

#include <stdint.h>

#if defined(SQ_TARGET_TEST)

/* ---- semihosting (semihost.c) ------------------------------------------- */
void semihost_write0(const char *s);
void semihost_exit(uint32_t code) __attribute__((noreturn));
/* "key=value" line helpers: no printf on the target. */
void semihost_print_u32(const char *prefix, uint32_t value, const char *suffix);
void semihost_print_hex(const char *prefix, uint32_t value, const char *suffix);

/* ---- the drivers' event sink (test_events.c) ----------------------------- */
/* One event (boot, fault, CAN timeouts, watchdog): printed as
 * "EVT what value=N"; watchdog kicks are counted instead ("wdg_kick",
 * value = kicks so far; the first one is printed). Thread mode only. */
void stm32_test_note(const char *what, uint32_t value);
/* Kicks seen so far and the uptime of the last one. */
uint32_t stm32_test_kicks(uint32_t *last_kick_ms);
#define STM32_TEST_EVENT(what, value) stm32_test_note((what), (value))

/* ---- the test run (test_run.c), called by board.c only ------------------- */
/* At boot, after the clocks: the reset reason and the fault record. */
void stm32_test_boot_report(void);
/* Every main-loop idle ("idle"): the first one announces the main loop
 * (and, in the fault images, provokes the fault), the run ends after
 * SQ_TARGET_TEST_RUN_MS with a summary line. */
void stm32_test_event(const char *what, uint32_t value);

#else
#define STM32_TEST_EVENT(what, value) ((void)0)
#endif

#endif /* STM32_TEST_H */
