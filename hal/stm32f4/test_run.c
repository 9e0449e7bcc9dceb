/* SPDX-License-Identifier: MIT */
/*
 * Test images only (-DSQ_TARGET_TEST, under qemu-system-arm): the run
 * around the unchanged firmware. board.c calls it at boot (the reset reason
 * and the fault record) and at every main-loop idle; after
 * SQ_TARGET_TEST_RUN_MS milliseconds of main loop it prints one summary
 * line and ends QEMU. The fault images (-DSQ_TARGET_TEST_FAULT) provoke
 * their fault on the first idle of the first boot: a division by zero, a
 * stack overflow, a contract violation or the clock security system's NMI.
 * It sits above the drivers (it reads their status); no driver calls it.
 */
#include <stddef.h>

#include "chip.h"
#include "hal.h"
#include "stm32_fault.h"
#include "stm32_test.h"
#include "stm32_time.h"

/* Linked only into the test images (mk/target.mk); empty elsewhere. */
#if defined(SQ_TARGET_TEST)

#ifndef SQ_TARGET_TEST_RUN_MS
#define SQ_TARGET_TEST_RUN_MS 2000U
#endif

static bool main_loop_seen;
static uint32_t idle_calls;
static uint64_t last_time_us;
static uint32_t time_back; /* hal_time_us() smaller than the call before */

void stm32_test_boot_report(void)
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

#if defined(SQ_TARGET_TEST_STACK_OVERFLOW)
/* Stack-overflow test: push the MSP below the bottom of SRAM (the stack
 * reserve starts there), in assembly so that no compiler check or tail
 * call optimisation interferes. One word (0, never the paint) per push,
 * so every word of the reserve is written whatever the depth of the call
 * (the next boot's self-test must see the whole reserve used); the first
 * push below 0x20000000 faults (BusFault on the store, then on the
 * stacking), with MSP pointing at no memory. */
static void stack_overflow(void)
{
	__asm__ volatile("movs r0, #0\n\t"
			 "1:\n\t"
			 "push {r0}\n\t"
			 "b 1b\n\t" ::: "r0", "memory");
}
#endif

static void summary(uint32_t now_ms, uint64_t t_us)
{
	hal_can_status_t st;
	uint32_t last_kick_ms = 0U;
	const uint32_t kicks = stm32_test_kicks(&last_kick_ms);

	if (hal_can_get_status(0U, &st) != SQ_OK) {
		st.state = HAL_CAN_STATE_STOPPED;
	}
	semihost_print_u32("EVT summary uptime_ms=", now_ms, NULL);
	semihost_print_u32(" kicks=", kicks, NULL);
	semihost_print_u32(" last_kick_ms=", last_kick_ms, NULL);
	semihost_print_u32(" idle_calls=", idle_calls, NULL);
	semihost_print_u32(" time_back=", time_back, NULL);
	semihost_print_u32(" time_ms=", (uint32_t)(t_us / 1000U), NULL);
	semihost_print_hex(" faults=0x", hal_platform_faults(), NULL);
	semihost_print_u32(" can_state=", (uint32_t)st.state, NULL);
	semihost_print_u32(" reset_reason=", (uint32_t)hal_reset_reason(), NULL);
	semihost_print_u32(" core_mhz=", hal_cycles_per_us(), "\n");
	semihost_exit(0U);
}

/* The main loop's idle (board.c's hal_idle_until), thread mode only. The
 * fault images fault here, in this function: run-ecu-boot.sh checks that
 * the recorded PC names it. */
void stm32_test_event(const char *what, uint32_t value)
{
	const uint32_t now = stm32_uptime_ms();
	const uint64_t t_us = hal_time_us();

	(void)what;
	(void)value;
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
	if (now >= SQ_TARGET_TEST_RUN_MS) {
		summary(now, t_us);
	}
}

#endif /* SQ_TARGET_TEST */
