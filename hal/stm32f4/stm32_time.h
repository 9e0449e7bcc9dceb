/* SPDX-License-Identifier: MIT */
/*
 * The board's time interface (systick.c): bounded waits in real time for the
 * drivers, the 1 kHz time base for board.c. Drivers depend on this header
 * and on stm32_board.h, never on each other.
 */
#ifndef STM32_TIME_H
#define STM32_TIME_H

#include <stdbool.h>
#include <stdint.h>

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

void SysTick_Handler(void);

#endif /* STM32_TIME_H */
