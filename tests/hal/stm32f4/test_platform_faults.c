/* SPDX-License-Identifier: MIT */
/*
 * The platform fault registry (hal/stm32f4/platform_faults.c) on the host:
 * nothing raised at start, raised HAL_FAULT_* bits accumulate (never
 * cleared, a bit raised twice stays one bit), each raise with interrupts
 * masked (the test's cm_irq_save/cm_irq_restore record it).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "chip.h"
#include "hal.h"
#include "stm32_platform_faults.h"

static uint32_t primask;   /* 1: interrupts masked */
static uint32_t saves;
static uint32_t restores;

uint32_t cm_irq_save(void)
{
	uint32_t was = primask;

	primask = 1U;
	saves++;
	return was;
}

void cm_irq_restore(uint32_t was)
{
	assert_int_equal(primask, 1U); /* restored only what was saved */
	primask = was;
	restores++;
}

static void test_bits_accumulate_with_interrupts_masked(void **state)
{
	(void)state;
	assert_int_equal(hal_platform_faults(), 0U);
	stm32_fault_raise(HAL_FAULT_CAN_INIT);
	assert_int_equal(hal_platform_faults(), 0x2U);
	stm32_fault_raise(HAL_FAULT_CLOCK_FALLBACK | HAL_FAULT_SELFTEST);
	assert_int_equal(hal_platform_faults(), 0xBU);
	stm32_fault_raise(HAL_FAULT_CAN_INIT);
	stm32_fault_raise(0U);
	assert_int_equal(hal_platform_faults(), 0xBU);
	assert_int_equal(saves, 4U);
	assert_int_equal(restores, 4U);
	assert_int_equal(primask, 0U); /* interrupts back on after each */
}

static void test_a_raise_inside_a_masked_section_keeps_it_masked(void **state)
{
	uint32_t outer;

	(void)state;
	outer = cm_irq_save();
	stm32_fault_raise(HAL_FAULT_CALIB_STORAGE);
	assert_int_equal(primask, 1U);
	cm_irq_restore(outer);
	assert_int_equal(hal_platform_faults(), 0xFU);
}

SQ_CMOCKA_MAIN(
	cmocka_unit_test(test_bits_accumulate_with_interrupts_masked),
	cmocka_unit_test(test_a_raise_inside_a_masked_section_keeps_it_masked))
