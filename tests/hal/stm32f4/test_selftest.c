/* SPDX-License-Identifier: MIT */
/*
 * The bring-up self-test (hal/stm32f4/selftest.c) on the host, every input
 * it reads given by this test: the measured crystal, reset reason, BOR
 * level, previous stack high-water mark, platform faults and each bus's
 * loopback answer. Expected verdicts by hand from stm32_selftest.h and
 * hal.h: a clock fallback fails CRYSTAL; a BOR level below 3 fails BOR (a
 * chip without BOR does not); more than 7/8 of the stack reserve fails
 * STACK; loopback SQ_OK -> PASS 0, SQ_EAGAIN -> UNAVAILABLE 2, SQ_ENODEV ->
 * NO_BUS 3, anything else -> FAIL 1 and LOOPBACK; a loopback failure raises
 * HAL_FAULT_CAN_INIT, BOR or STACK raise HAL_FAULT_SELFTEST.
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
#include "stm32_fault.h"
#include "stm32_platform_faults.h"
#include "stm32_selftest.h"

/* ---- the board as this test makes it ---------------------------------------- */

static uint32_t hse_hz, bor_level, stack_prev, faults_before, raised;
static int loopback_rc[HAL_CAN_BUSES];

uint32_t chip_hse_measured_hz(void) { return hse_hz; }
uint32_t chip_bor_level(void) { return bor_level; }
uint32_t stm32_stack_hwm_prev(void) { return stack_prev; }
hal_reset_reason_t hal_reset_reason(void) { return HAL_RESET_WATCHDOG; }
uint32_t hal_platform_faults(void) { return faults_before | raised; }
void stm32_fault_raise(uint32_t bits) { raised |= bits; }

int can_ctrl_selftest_loopback(uint8_t bus)
{
	assert_true(bus < HAL_CAN_BUSES);
	return loopback_rc[bus];
}

static int setup(void **state)
{
	(void)state;
	hse_hz = 8000000U;
	bor_level = 3U;
	stack_prev = 1000U;
	faults_before = 0U;
	raised = 0U;
	loopback_rc[0] = SQ_OK;
	loopback_rc[1] = SQ_OK;
	return 0;
}

#define RESERVE_B 4096U /* 7/8: 3584 bytes */

static void test_healthy_board_passes_and_is_reported(void **state)
{
	const stm32_selftest_t *r;
	hal_selftest_t h;

	(void)state;
	r = stm32_selftest_run(RESERVE_B);
	assert_ptr_equal(r, stm32_selftest());
	assert_int_equal(r->hse_hz, 8000000U);
	assert_int_equal(r->reset_reason, (uint32_t)HAL_RESET_WATCHDOG);
	assert_int_equal(r->bor_level, 3U);
	assert_int_equal(r->stack_hwm_prev, 1000U);
	assert_int_equal(r->loopback[0], 0U);
	assert_int_equal(r->loopback[1], 0U);
	assert_int_equal(r->faults, 0U);
	assert_int_equal(raised, 0U);
	assert_int_equal(hal_selftest(&h), SQ_OK);
	assert_int_equal(h.hse_hz, 8000000U);
	assert_int_equal(h.stack_high_water_prev_b, 1000U);
	assert_int_equal(h.bor_level, 3U);
	assert_false(h.failed);
	expect_assert_failure(hal_selftest(NULL));
}

static void test_each_check_at_its_bound(void **state)
{
	static const struct {
		uint32_t bor, stack, faults_before;
		int lb0, lb1;
		uint32_t want_faults, want_raised, want_lb0, want_lb1;
	} cases[] = {
		/* stack exactly 7/8 passes, one byte more fails */
		{ 3U, 3584U, 0U, SQ_OK, SQ_OK, 0x0U, 0x0U, 0U, 0U },
		{ 3U, 3585U, 0U, SQ_OK, SQ_OK, 0x8U, HAL_FAULT_SELFTEST, 0U, 0U },
		{ 3U, 0xFFFFFFFFU, 0U, SQ_OK, SQ_OK, 0x0U, 0x0U, 0U, 0U }, /* unknown */
		{ 2U, 0U, 0U, SQ_OK, SQ_OK, 0x2U, HAL_FAULT_SELFTEST, 0U, 0U },
		{ 0U, 0U, 0U, SQ_OK, SQ_OK, 0x2U, HAL_FAULT_SELFTEST, 0U, 0U }, /* BOR off */
		{ 0xFFU, 0U, 0U, SQ_OK, SQ_OK, 0x0U, 0x0U, 0U, 0U },            /* no BOR */
		{ 3U, 0U, HAL_FAULT_CLOCK_FALLBACK, SQ_OK, SQ_OK, 0x1U, 0x0U, 0U, 0U },
		{ 3U, 0U, 0U, SQ_EAGAIN, SQ_ENODEV, 0x0U, 0x0U, 2U, 3U },
		{ 3U, 0U, 0U, SQ_OK, SQ_EIO, 0x4U, HAL_FAULT_CAN_INIT, 0U, 1U },
		{ 1U, 4000U, 0U, SQ_EIO, SQ_OK, 0xEU, HAL_FAULT_CAN_INIT | HAL_FAULT_SELFTEST, 1U, 0U },
	};
	size_t i;

	(void)state;
	for (i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
		const stm32_selftest_t *r;

		setup(NULL);
		bor_level = cases[i].bor;
		stack_prev = cases[i].stack;
		faults_before = cases[i].faults_before;
		loopback_rc[0] = cases[i].lb0;
		loopback_rc[1] = cases[i].lb1;
		r = stm32_selftest_run(RESERVE_B);
		assert_int_equal(r->faults, cases[i].want_faults);
		assert_int_equal(raised, cases[i].want_raised);
		assert_int_equal(r->loopback[0], cases[i].want_lb0);
		assert_int_equal(r->loopback[1], cases[i].want_lb1);
	}
}

static void test_hal_view_of_unmeasured_values(void **state)
{
	hal_selftest_t h;

	(void)state;
	bor_level = 0xFFU;          /* CHIP_BOR_NONE: an F103 */
	stack_prev = 0xFFFFFFFFU;   /* power-on: nothing painted before */
	hse_hz = 0U;
	loopback_rc[1] = SQ_ENODEV;
	faults_before = HAL_FAULT_CLOCK_FALLBACK;
	(void)stm32_selftest_run(RESERVE_B);
	assert_int_equal(hal_selftest(&h), SQ_OK);
	assert_int_equal(h.bor_level, 0xFFU);                     /* HAL_SELFTEST_NO_BOR */
	assert_int_equal(h.stack_high_water_prev_b, 0xFFFFFFFFU); /* NOT_MEASURED */
	assert_int_equal(h.hse_hz, 0U);
	assert_int_equal(h.loopback[0], 0U);
	assert_int_equal(h.loopback[1], 3U);
	assert_true(h.failed); /* the crystal */
}

SQ_CMOCKA_MAIN(
	cmocka_unit_test_setup(test_healthy_board_passes_and_is_reported, setup),
	cmocka_unit_test_setup(test_each_check_at_its_bound, setup),
	cmocka_unit_test_setup(test_hal_view_of_unmeasured_values, setup))
