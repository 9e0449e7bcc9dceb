/* SPDX-License-Identifier: MIT */
/*
 * Bring-up self-test, run by board.c at every start: measured crystal,
 * reset cause, brown-out level, a silent-loopback frame through each CAN
 * controller (nothing reaches the bus), and the previous run's stack
 * high-water mark. Test builds print it over semihosting as one line:
 *   EVT selftest hse_hz=... reset=... bor=... lb0=... lb1=... stack_prev=... faults=0x...
 */
#include <stddef.h>

#include "stm32_selftest.h"

#include "can_ctrl.h"
#include "chip.h"
#include "sq_status.h"
#include "stm32_fault.h"
#include "stm32_platform_faults.h"
#include "stm32_test.h"

static stm32_selftest_t result;

static uint32_t loopback(uint8_t bus)
{
	switch (can_ctrl_selftest_loopback(bus)) {
	case SQ_OK:
		return STM32_LOOPBACK_PASS;
	case SQ_EAGAIN:
		return STM32_LOOPBACK_UNAVAILABLE;
	case SQ_ENODEV:
		return STM32_LOOPBACK_NO_BUS;
	default:
		return STM32_LOOPBACK_FAIL;
	}
}

const stm32_selftest_t *stm32_selftest_run(uint32_t stack_reserve_bytes)
{
	uint32_t faults = 0U;
	uint32_t bus;

	result.hse_hz = chip_hse_measured_hz();
	result.reset_reason = (uint32_t)hal_reset_reason();
	result.bor_level = chip_bor_level();
	result.stack_hwm_prev = stm32_stack_hwm_prev();
	if ((hal_platform_faults() & HAL_FAULT_CLOCK_FALLBACK) != 0U) {
		faults |= STM32_SELFTEST_CRYSTAL;
	}
	if (result.bor_level != CHIP_BOR_NONE && result.bor_level < 3U) {
		faults |= STM32_SELFTEST_BOR;
	}
	if (result.stack_hwm_prev != STM32_STACK_HWM_UNKNOWN &&
	    result.stack_hwm_prev > stack_reserve_bytes / 8U * 7U) {
		faults |= STM32_SELFTEST_STACK;
	}
	for (bus = 0; bus < HAL_CAN_BUSES; bus++) {
		result.loopback[bus] = loopback((uint8_t)bus);
		/* "unavailable" is reported and raises CAN_INIT through the
		 * driver; only a controller that answered wrongly fails here */
		if (result.loopback[bus] == STM32_LOOPBACK_FAIL) {
			faults |= STM32_SELFTEST_LOOPBACK;
		}
	}
	result.faults = faults;
	if ((faults & STM32_SELFTEST_LOOPBACK) != 0U) {
		stm32_fault_raise(HAL_FAULT_CAN_INIT);
	}
	if ((faults & (STM32_SELFTEST_BOR | STM32_SELFTEST_STACK)) != 0U) {
		stm32_fault_raise(STM32_FAULT_SELFTEST);
	}
#if defined(SQ_TARGET_TEST)
	semihost_print_u32("EVT selftest hse_hz=", result.hse_hz, NULL);
	semihost_print_u32(" reset=", result.reset_reason, NULL);
	semihost_print_u32(" bor=", result.bor_level, NULL);
	semihost_print_u32(" lb0=", result.loopback[0], NULL);
	semihost_print_u32(" lb1=", result.loopback[1], NULL);
	semihost_print_u32(" stack_prev=", result.stack_hwm_prev, NULL);
	semihost_print_u32(" stack_reserve=", stack_reserve_bytes, NULL);
	semihost_print_hex(" faults=0x", result.faults, "\n");
#endif
	return &result;
}

const stm32_selftest_t *stm32_selftest(void)
{
	return &result;
}

/* hal.h's view of the same result, for the firmware (SquealDiag page 4). */
int hal_selftest(hal_selftest_t *out)
{
	uint32_t bus;

	HAL_REQUIRE(out != NULL);
	out->hse_hz = result.hse_hz;
	out->stack_high_water_prev_b = (result.stack_hwm_prev == STM32_STACK_HWM_UNKNOWN) ?
		HAL_SELFTEST_NOT_MEASURED : result.stack_hwm_prev;
	out->bor_level = (result.bor_level == CHIP_BOR_NONE) ? (uint8_t)HAL_SELFTEST_NO_BOR :
		(uint8_t)result.bor_level;
	for (bus = 0U; bus < HAL_CAN_BUSES; bus++) {
		out->loopback[bus] = (uint8_t)result.loopback[bus];
	}
	out->failed = result.faults != 0U;
	return SQ_OK;
}
