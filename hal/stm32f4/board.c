/* SPDX-License-Identifier: MIT */
/*
 * Board bring-up and main() of the ECU image: reset reason, clocks (HSI
 * fallback reported), 1 kHz time base, the bring-up self-test (selftest.c),
 * every CAN controller at the default bit rate, then the firmware's
 * squeal_main(), which never returns on the ECU. The one file that knows
 * every driver: the drivers know only stm32_board.h and stm32_time.h.
 *
 * Test builds (-DSQ_TARGET_TEST, run under qemu-system-arm) also print the
 * boot, fault and watchdog events through semihosting and end the run after
 * SQ_TARGET_TEST_RUN_MS milliseconds of main loop with a summary line.
 */
#include <stddef.h>

#include "bxcan.h"
#include "chip.h"
#include "squeal_app.h"
#include "sq_status.h"
#include "stm32_board.h"
#include "stm32_fault.h"
#include "stm32_selftest.h"
#include "stm32_time.h"

static volatile uint32_t platform_faults;
static volatile bool stop_requested; /* never set on the ECU */

int main(void);

void stm32_fault_raise(uint32_t hal_fault_bits)
{
	uint32_t primask = cm_irq_save();

	platform_faults |= hal_fault_bits;
	cm_irq_restore(primask);
	STM32_TEST_EVENT("fault", hal_fault_bits);
}

uint32_t hal_platform_faults(void)
{
	return platform_faults;
}

void stm32_board_init(void)
{
	uint8_t bus;

	stm32_reset_reason_capture();
	if (chip_clock_init() != SQ_OK) {
		stm32_fault_raise(HAL_FAULT_CLOCK_FALLBACK);
	}
	stm32_time_start(chip_core_hz());
	cm_irq_enable();
	STM32_TEST_EVENT("boot", chip_core_hz());
#if defined(SQ_TARGET_TEST)
	{
		const stm32_fault_record_t *f = stm32_last_fault();

		semihost_print_u32("EVT reset_reason value=", (uint32_t)hal_reset_reason(), NULL);
		if (f != NULL) {
			semihost_print_u32(" fault_vector=", f->vector, NULL);
			semihost_print_hex(" fault_pc=0x", f->pc, NULL);
			semihost_print_hex(" fault_cfsr=0x", f->cfsr, NULL);
			semihost_print_u32(" fault_count=", f->count, NULL);
			semihost_print_hex(" fault_msp=0x", f->msp, NULL);
			if (f->vector == STM32_FAULT_VECTOR_CONTRACT) {
				semihost_print_u32(" contract_line=", f->line, NULL);
			}
		}
		semihost_write0("\n");
	}
#endif
	(void)stm32_selftest_run(stm32_stack_reserve_bytes());
	/* Failure is recorded as HAL_FAULT_CAN_INIT; the firmware runs on
	 * and reports it (SquealDiag cannot go out then, but the ECU still
	 * kicks its watchdog and keeps its state). */
	for (bus = 0; bus < HAL_CAN_BUSES; bus++) {
		(void)bxcan_start(bus, BXCAN_DEFAULT_BITRATE);
	}
}

/*
 * WFI with interrupts masked: an interrupt that becomes pending after the
 * checks still ends the WFI, so no wake-up is lost. One WFI per call (the
 * next SysTick at the latest): the caller loops, hal.h allows early returns.
 */
void hal_idle_until(uint64_t deadline_us)
{
	uint32_t primask = cm_irq_save();

	/* A frame already waiting needs the caller now, not after a tick. */
	if (!bxcan_rx_pending() && hal_time_us() < deadline_us) {
		cm_dsb();
		cm_wfi();
	}
	cm_irq_restore(primask);
#if defined(SQ_TARGET_TEST)
	stm32_test_event("idle", 0U);
#endif
}

int main(void)
{
	stm32_board_init();
	return squeal_main(&stop_requested);
}

#if defined(SQ_TARGET_TEST)

#ifndef SQ_TARGET_TEST_RUN_MS
#define SQ_TARGET_TEST_RUN_MS 2000U
#endif

static bool main_loop_seen;
static uint32_t kicks_seen;
static uint32_t last_kick_ms;
static uint32_t idle_calls;
static uint64_t last_time_us;
static uint32_t time_back; /* hal_time_us() smaller than the call before */

#if defined(SQ_TARGET_TEST_STACK_OVERFLOW)
/* Stack-overflow test: push the MSP below the bottom of SRAM (the stack
 * reserve starts there), in assembly so that no compiler check or tail
 * call optimisation interferes. Each push of 64 bytes moves MSP down;
 * the first push below 0x20000000 faults (BusFault on the stacking or
 * on the store), with MSP pointing at no memory. */
static void stack_overflow(void)
{
	__asm__ volatile("1:\n\t"
			 "push {r0-r12, lr}\n\t"
			 "sub sp, sp, #8\n\t"
			 "b 1b\n\t" ::: "memory");
}
#endif

/* Events arrive from thread mode only (boot, init, main loop). */
void stm32_test_event(const char *what, uint32_t value)
{
	const char *w = what;

	if (w[0] == 'w' && w[1] == 'd' && w[2] == 'g' && w[3] == '_' && w[4] == 'k') {
		kicks_seen = value;
		last_kick_ms = stm32_uptime_ms();
		if (value == 1U) {
			semihost_write0("EVT wdg_kick first\n");
		}
		return;
	}
	if (w[0] == 'i' && w[1] == 'd' && w[2] == 'l' && w[3] == 'e') {
		uint32_t now = stm32_uptime_ms();
		hal_can_status_t st;

		uint64_t t_us = hal_time_us();

		idle_calls++;
		if (t_us < last_time_us) {
			time_back++;
		}
		last_time_us = t_us;
		if (!main_loop_seen) {
			main_loop_seen = true;
			semihost_print_u32("EVT main_loop uptime_ms=", now, "\n");
#if defined(SQ_TARGET_TEST_FAULT)
			/* Fault-path test: divide by zero (trapped: DIV_0_TRP) on
			 * the first boot; the handler records it and resets, and
			 * the second boot must report HAL_RESET_FAULT. */
			if (hal_reset_reason() != HAL_RESET_FAULT) {
#if defined(SQ_TARGET_TEST_STACK_OVERFLOW)
				stack_overflow();
#elif defined(SQ_TARGET_TEST_CONTRACT)
				/* a programming error: a bus index hal.h does not have */
				hal_can_frame_t f = { 0 };

				(void)hal_can_send((uint8_t)HAL_CAN_BUSES, &f);
#elif defined(SQ_TARGET_TEST_NMI)
				/* what the clock security system does when the
				 * crystal stops: the NMI (QEMU has no CSS) */
				SCB_ICSR = SCB_ICSR_NMIPENDSET;
				cm_dsb();
				cm_isb();
#else
				uint32_t q;

				/* in assembly: in C the compiler may assume it away */
				__asm__ volatile("udiv %0, %1, %2" : "=r"(q) : "r"(1U), "r"(0U));
				(void)q;
#endif
			}
#endif
		}
		if (now < SQ_TARGET_TEST_RUN_MS) {
			return;
		}
		if (hal_can_get_status(0U, &st) != SQ_OK) {
			st.state = HAL_CAN_STATE_STOPPED;
		}
		semihost_print_u32("EVT summary uptime_ms=", now, NULL);
		semihost_print_u32(" kicks=", kicks_seen, NULL);
		semihost_print_u32(" last_kick_ms=", last_kick_ms, NULL);
		semihost_print_u32(" idle_calls=", idle_calls, NULL);
		semihost_print_u32(" time_back=", time_back, NULL);
		semihost_print_u32(" time_ms=", (uint32_t)(t_us / 1000U), NULL);
		semihost_print_hex(" faults=0x", platform_faults, NULL);
		semihost_print_u32(" can_state=", (uint32_t)st.state, NULL);
		semihost_print_u32(" reset_reason=", (uint32_t)hal_reset_reason(), NULL);
		semihost_print_u32(" core_mhz=", hal_cycles_per_us(), "\n");
		semihost_exit(0U);
	}
	semihost_write0("EVT ");
	semihost_write0(w);
	semihost_print_u32(" value=", value, "\n");
}

#endif /* SQ_TARGET_TEST */
