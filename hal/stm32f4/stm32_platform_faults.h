/* SPDX-License-Identifier: MIT */
/*
 * The platform fault registry (platform_faults.c): the HAL_FAULT_* bits
 * hal_platform_faults() reports. Drivers raise bits here; the registry
 * knows no driver.
 */
#ifndef STM32_PLATFORM_FAULTS_H
#define STM32_PLATFORM_FAULTS_H

#include <stdint.h>

/* Raise HAL_FAULT_* bits (hal_platform_faults()); safe from interrupts. */
void stm32_fault_raise(uint32_t hal_fault_bits);

#endif /* STM32_PLATFORM_FAULTS_H */
