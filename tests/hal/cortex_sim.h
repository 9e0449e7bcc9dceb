/* SPDX-License-Identifier: MIT */
/*
 * The Cortex-M core and board time under a host CAN peripheral simulation
 * (stm32f4/bxcan_sim.c, stm32g4/fdcan_sim.c): PRIMASK, the NVIC enables, the
 * microsecond clock, the platform faults raised, and the driver's timeouts,
 * where every poll is one microsecond of simulated time.
 *
 * It implements cortex_m.h's host functions, hal_time_us(),
 * stm32_fault_raise(), stm32_timeout_*() and the simulations' common
 * sim_advance_us(), sim_now_us() and sim_fault_bits().
 */
#ifndef CORTEX_SIM_H
#define CORTEX_SIM_H

#include <stdbool.h>
#include <stdint.h>

/* Power-on: clock at 1000 us, interrupts unmasked, every NVIC line off. */
void cortex_sim_reset(void);

bool cortex_sim_irq_enabled(uint32_t irq);

/* Provided by the peripheral simulation: move the wire on one step; run
 * once the handler of every enabled interrupt that is pending, true when
 * any ran. */
void cortex_sim_step(void);
bool cortex_sim_irq_round(void);

/* Interrupt dispatch unless PRIMASK is set or a handler is running: rounds
 * of handlers, each followed by a step, until a round runs none (at most
 * CORTEX_SIM_IRQ_ROUNDS). cortex_sim_run: a step, then the dispatch. */
#define CORTEX_SIM_IRQ_ROUNDS 32U
void cortex_sim_irqs(void);
void cortex_sim_run(void);

void sim_advance_us(uint32_t us);
uint64_t sim_now_us(void);
uint32_t sim_fault_bits(void);

#endif
