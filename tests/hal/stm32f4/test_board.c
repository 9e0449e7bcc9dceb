/* SPDX-License-Identifier: MIT */
/*
 * The ECU's bring-up and idle (hal/stm32f4/board.c) on the host, every
 * driver it calls replaced by a recorder: the order board.c's header
 * promises (reset reason before the clocks change anything, the clocks,
 * the 1 kHz time base on the resulting core clock, interrupts on, the
 * self-test with the stack reserve, then every CAN controller at 500
 * kbit/s), a clock fallback raised as HAL_FAULT_CLOCK_FALLBACK, a CAN
 * controller that does not start not stopping the bring-up, and idle's
 * single WFI with interrupts masked, skipped when a frame waits or the
 * deadline has passed. board.c's main() is built as board_main()
 * (-Dmain=board_main): it hands over to squeal_main().
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "can_ctrl.h"
#include "chip.h"
#include "hal.h"
#include "sq_status.h"
#include "stm32_board.h"
#include "stm32_fault.h"
#include "stm32_iwdg.h"
#include "stm32_platform_faults.h"
#include "stm32_selftest.h"
#include "stm32_time.h"

int board_main(void);
int squeal_main(volatile const bool *stop);

/* ---- the recorders ----------------------------------------------------------- */

static char calls[512];
static int clock_rc;
static uint32_t raised;
static uint32_t time_start_hz;
static uint32_t selftest_reserve;
static uint32_t can_bitrate[HAL_CAN_BUSES];
static int can_rc;
static bool rx_pending;
static uint64_t now_us;
static uint32_t primask;
static uint32_t wfi_primask;
static const stm32_selftest_t selftest_result;

static void note(const char *what)
{
	(void)strncat(calls, what, sizeof(calls) - strlen(calls) - 1U);
	(void)strncat(calls, " ", sizeof(calls) - strlen(calls) - 1U);
}

void stm32_reset_reason_capture(void) { note("reset_reason"); }
int chip_clock_init(void) { note("clock"); return clock_rc; }
uint32_t chip_core_hz(void) { return (clock_rc == SQ_OK) ? 168000000U : 16000000U; }
void stm32_fault_raise(uint32_t bits) { note("fault"); raised |= bits; }
void stm32_time_start(uint32_t core_hz) { note("time"); time_start_hz = core_hz; }
void cm_irq_enable(void) { note("irq_on"); primask = 0U; }
uint32_t stm32_stack_reserve_bytes(void) { return 6144U; }
uint64_t hal_time_us(void) { return now_us; }
bool can_ctrl_rx_pending(void) { return rx_pending; }
void cm_dsb(void) { }
void cm_wfi(void) { note("wfi"); wfi_primask = primask; }

const stm32_selftest_t *stm32_selftest_run(uint32_t stack_reserve_bytes)
{
	note("selftest");
	selftest_reserve = stack_reserve_bytes;
	return &selftest_result;
}

int can_ctrl_start(uint8_t bus, uint32_t bitrate_bps)
{
	note(bus == 0U ? "can0" : "can1");
	can_bitrate[bus] = bitrate_bps;
	return can_rc;
}

uint32_t cm_irq_save(void)
{
	const uint32_t was = primask;

	primask = 1U;
	return was;
}

void cm_irq_restore(uint32_t was)
{
	primask = was;
}

int squeal_main(volatile const bool *stop)
{
	note("squeal_main");
	assert_non_null(stop);
	assert_false(*stop); /* never set on the ECU */
	return 7;
}

static int setup(void **state)
{
	(void)state;
	calls[0] = '\0';
	clock_rc = SQ_OK;
	raised = 0U;
	can_rc = SQ_OK;
	rx_pending = false;
	now_us = 0U;
	primask = 1U; /* out of reset the board runs masked until irq_on */
	return 0;
}

static void test_bring_up_order_then_the_firmware(void **state)
{
	(void)state;
	assert_int_equal(board_main(), 7);
	assert_string_equal(calls, "reset_reason clock time irq_on selftest can0 can1 squeal_main ");
	assert_int_equal(time_start_hz, 168000000U);
	assert_int_equal(selftest_reserve, 6144U);
	assert_int_equal(can_bitrate[0], 500000U);
	assert_int_equal(can_bitrate[1], 500000U);
	assert_int_equal(raised, 0U);
}

static void test_clock_fallback_is_raised_and_time_runs_on_hsi(void **state)
{
	(void)state;
	clock_rc = SQ_EAGAIN;
	can_rc = SQ_EIO; /* a controller that does not start: bring-up goes on */
	stm32_board_init();
	assert_string_equal(calls, "reset_reason clock fault time irq_on selftest can0 can1 ");
	assert_int_equal(raised, HAL_FAULT_CLOCK_FALLBACK);
	assert_int_equal(time_start_hz, 16000000U);
}

static void test_idle_waits_once_masked_unless_a_frame_waits(void **state)
{
	(void)state;
	primask = 0U;
	now_us = 1000U;
	hal_idle_until(2000U);
	assert_string_equal(calls, "wfi ");
	assert_int_equal(wfi_primask, 1U); /* WFI with interrupts masked */
	assert_int_equal(primask, 0U);     /* and unmasked again after */
	calls[0] = '\0';
	rx_pending = true;
	hal_idle_until(2000U);
	assert_string_equal(calls, "");
	rx_pending = false;
	now_us = 2000U; /* the deadline reached */
	hal_idle_until(2000U);
	assert_string_equal(calls, "");
	assert_int_equal(primask, 0U);
}

SQ_CMOCKA_MAIN(
	cmocka_unit_test_setup(test_bring_up_order_then_the_firmware, setup),
	cmocka_unit_test_setup(test_clock_fallback_is_raised_and_time_runs_on_hsi, setup),
	cmocka_unit_test_setup(test_idle_waits_once_masked_unless_a_frame_waits, setup))
