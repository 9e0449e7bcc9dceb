/* SPDX-License-Identifier: MIT */
/*
 * Board bring-up and main() of the ECU image: reset reason, clocks (HSI
 * fallback reported), 1 kHz time base, CAN1 at the default bit rate, then
 * the firmware's squeal_main(), which never returns on the ECU.
 *
 * Test builds (-DSQ_TARGET_TEST, run under qemu-system-arm) also print the
 * boot, fault and watchdog events through semihosting and end the run after
 * SQ_TARGET_TEST_RUN_MS milliseconds of main loop with a summary line.
 */
#include "chip.h"
#include "hal_stm32.h"
#include "squeal_app.h"

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
		}
		semihost_write0("\n");
	}
#endif
	/* Failure is recorded as HAL_FAULT_CAN_INIT; the firmware runs on
	 * and reports it (SquealDiag cannot go out then, but the ECU still
	 * kicks its watchdog and keeps its state). */
	(void)bxcan_start(BXCAN_DEFAULT_BITRATE);
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
				uint32_t q;

				/* in assembly: in C the compiler may assume it away */
				__asm__ volatile("udiv %0, %1, %2" : "=r"(q) : "r"(1U), "r"(0U));
				(void)q;
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
