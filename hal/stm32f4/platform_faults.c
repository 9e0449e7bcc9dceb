/* SPDX-License-Identifier: MIT */
/*
 * The platform fault registry: the HAL_FAULT_* bits the drivers found at
 * start-up or since (cumulative), for hal_platform_faults().
 */
#include "stm32_platform_faults.h"

#include "chip.h"
#include "hal.h"
#include "stm32_test.h"

static volatile uint32_t platform_faults;

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
