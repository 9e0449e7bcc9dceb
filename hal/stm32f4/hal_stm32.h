/* SPDX-License-Identifier: MIT */
/*
 * Internals shared by the bare-metal HAL's files (STM32F4 and the F103
 * port). Not part of the hardware boundary: firmware/ includes only hal.h.
 */
#ifndef HAL_STM32_H
#define HAL_STM32_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "hal.h"

/* ---- time (systick.c) ---------------------------------------------------- */

/* SysTick free-running (no interrupt) at the reset clock, for the bounded
 * waits of clock start-up. */
void stm32_time_early_init(uint32_t core_hz);
/* SysTick at 1 kHz with interrupt; the time base of hal_time_us(). */
void stm32_time_start(uint32_t core_hz);
/* Milliseconds since stm32_time_start() (wraps after 49 days: use deltas). */
uint32_t stm32_uptime_ms(void);

/*
 * A bounded wait in real time: counts SysTick ticks (processor clock) between
 * polls, so it needs neither interrupts nor a calibrated loop. The poll
 * count is a second bound, in case SysTick itself is not running: every poll
 * takes at least one clock cycle, so it never ends before the real timeout.
 */
typedef struct {
	uint32_t last_val;
	uint32_t elapsed_ticks;
	uint32_t limit_ticks;
	uint32_t polls;
} stm32_timeout_t;

void stm32_timeout_start(stm32_timeout_t *t, uint32_t timeout_us);
bool stm32_timeout_expired(stm32_timeout_t *t);

/* Wait until (reg & mask) == value or timeout_us passes: SQ_OK or SQ_EAGAIN. */
int stm32_wait_reg(volatile const uint32_t *reg, uint32_t mask, uint32_t value,
		   uint32_t timeout_us);

/* ---- CAN (bxcan.c) --------------------------------------------------------- */

/* Bit timing for the bxCAN on an APB clock: SQ_OK with *btr, or SQ_EINVAL
 * if the bit rate cannot be made exactly (see bxcan.c). */
int bxcan_bit_timing(uint32_t apb_hz, uint32_t bitrate_bps, uint32_t *btr);
/* Start CAN1 at bitrate_bps, accepting every standard and extended frame
 * until hal_can_set_rx_filter(). SQ_OK, SQ_EINVAL, SQ_EAGAIN (controller did
 * not acknowledge: HAL_FAULT_CAN_INIT raised, interface stays stopped). */
int bxcan_start(uint32_t bitrate_bps);
#define BXCAN_DEFAULT_BITRATE 500000UL
/* A received frame waits in the ring (hal_idle_until does not sleep then). */
bool stm32_can_rx_pending(void);

void CAN1_TX_IRQHandler(void);
void CAN1_RX0_IRQHandler(void);
void CAN1_SCE_IRQHandler(void);
void SysTick_Handler(void);

/* ---- faults, reset (board.c, startup.c, iwdg.c) ------------------------- */

void stm32_fault_raise(uint32_t hal_fault_bits);
void stm32_reset_reason_capture(void);

/* What a fault handler left in no-init RAM before it reset the core. */
typedef struct {
	uint32_t magic;     /* STM32_FAULT_MAGIC when valid                    */
	uint32_t vector;    /* exception number (3 HardFault, 4 MemManage ...) */
	uint32_t pc;        /* stacked PC of the faulting code                 */
	uint32_t lr;        /* stacked LR                                      */
	uint32_t cfsr;      /* SCB CFSR                                        */
	uint32_t hfsr;      /* SCB HFSR                                        */
	uint32_t fault_addr; /* MMFAR or BFAR when valid, else 0               */
	uint32_t count;     /* faults since power-on                           */
} stm32_fault_record_t;
#define STM32_FAULT_MAGIC 0xFA017EC0UL

/* The record of the fault that caused this reset (NULL if none). */
const stm32_fault_record_t *stm32_last_fault(void);
bool stm32_fault_record_take(stm32_fault_record_t *out);

/* Board bring-up: clocks, time, reset reason, CAN; then interrupts on. */
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

#endif /* HAL_STM32_H */
