/* SPDX-License-Identifier: MIT */
#include "cortex_sim.h"

#include <string.h>

#include "cortex_m.h"
#include "hal.h"
#include "stm32_platform_faults.h"
#include "stm32_time.h"

#define NVIC_LINES 128U

static uint64_t now_us;
static uint32_t primask;
static bool nvic_en[NVIC_LINES];
static bool in_isr;
static uint32_t faults;

void cortex_sim_reset(void)
{
	memset(nvic_en, 0, sizeof(nvic_en));
	now_us = 1000U;
	primask = 0U;
	in_isr = false;
	faults = 0U;
}

void cortex_sim_irqs(void)
{
	uint32_t round;

	if (primask != 0U || in_isr) {
		return;
	}
	in_isr = true;
	for (round = 0U; round < CORTEX_SIM_IRQ_ROUNDS; round++) {
		const bool any = cortex_sim_irq_round();

		cortex_sim_step();
		if (!any) {
			break;
		}
	}
	in_isr = false;
}

void cortex_sim_run(void)
{
	cortex_sim_step();
	cortex_sim_irqs();
}

bool cortex_sim_irq_enabled(uint32_t irq)
{
	return irq < NVIC_LINES && nvic_en[irq];
}

void sim_advance_us(uint32_t us)
{
	now_us += us;
	cortex_sim_run();
}

uint64_t sim_now_us(void) { return now_us; }
uint32_t sim_fault_bits(void) { return faults; }

/* ---- what the driver needs from the board and the core -------------------- */

uint64_t hal_time_us(void) { return now_us; }

void stm32_fault_raise(uint32_t hal_fault_bits)
{
	faults |= hal_fault_bits;
}

void stm32_timeout_start(stm32_timeout_t *t, uint32_t timeout_us)
{
	t->last_val = 0U;
	t->elapsed_ticks = 0U;
	t->limit_ticks = timeout_us;
	t->polls = 0U;
}

bool stm32_timeout_expired(stm32_timeout_t *t)
{
	sim_advance_us(1U);
	t->polls++;
	return t->polls >= t->limit_ticks;
}

void cm_dsb(void) {}
void cm_isb(void) {}
void cm_dmb(void) {}
void cm_wfi(void) {}

void cm_irq_disable(void)
{
	primask = 1U;
}

void cm_irq_enable(void)
{
	primask = 0U;
	cortex_sim_run();
}

uint32_t cm_irq_save(void)
{
	const uint32_t old = primask;

	cm_irq_disable();
	return old;
}

void cm_irq_restore(uint32_t pm)
{
	primask = pm;
	if (pm == 0U) {
		cortex_sim_run();
	}
}

void cm_nvic_enable(uint32_t irq, uint8_t prio)
{
	(void)prio;
	nvic_en[irq] = true;
}

void cm_nvic_disable(uint32_t irq)
{
	nvic_en[irq] = false;
}
