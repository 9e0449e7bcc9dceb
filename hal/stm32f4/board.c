/* SPDX-License-Identifier: MIT */
/*
 * Board bring-up and main() of the ECU image: reset reason, clocks (HSI
 * fallback reported), 1 kHz time base, the bring-up self-test (selftest.c),
 * every CAN controller at the default bit rate, then the firmware's
 * squeal_main(), which never returns on the ECU. The one file that knows
 * every driver; no driver knows the board (they report faults to the
 * registry, platform_faults.c, and, in test images, events to
 * test_events.c).
 *
 * Test images (-DSQ_TARGET_TEST, run under qemu-system-arm) also hand the
 * boot and every main-loop idle to the test run (test_run.c), which prints
 * the events and ends the run after SQ_TARGET_TEST_RUN_MS milliseconds of
 * main loop with a summary line.
 */
#include <stddef.h>

#include "stm32_board.h"

#include "can_ctrl.h"
#include "chip.h"
#include "squeal_app.h"
#include "sq_status.h"
#include "stm32_fault.h"
#include "stm32_iwdg.h"
#include "stm32_platform_faults.h"
#include "stm32_selftest.h"
#include "stm32_test.h"
#include "stm32_time.h"

static volatile bool stop_requested; /* never set on the ECU */

int main(void);

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
	stm32_test_boot_report();
#endif
	(void)stm32_selftest_run(stm32_stack_reserve_bytes());
	/* Failure is recorded as HAL_FAULT_CAN_INIT; the firmware runs on
	 * and reports it (SquealDiag cannot go out then, but the ECU still
	 * kicks its watchdog and keeps its state). */
	for (bus = 0; bus < HAL_CAN_BUSES; bus++) {
		(void)can_ctrl_start(bus, CAN_CTRL_DEFAULT_BITRATE);
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
	if (!can_ctrl_rx_pending() && hal_time_us() < deadline_us) {
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
