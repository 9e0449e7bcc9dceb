/* SPDX-License-Identifier: MIT */
/*
 * The crystal measured against the HSI before anything depends on it, the
 * same way on every STM32 here: the HSE, divided by the chip (F4: RTCPRE
 * 31 into TIM11; G4: HSE/32 into TIM17), drives channel 1 of a timer
 * clocked by the 16 MHz HSI; every 8th edge captured, 16 captures summed.
 * The chip enables the timer's clock and routes the input before, undoes
 * both after; this runs the timer (register addresses from its base: the
 * general-purpose timer layout, RM0090 / RM0440 TIMx registers).
 */
#ifndef STM32_HSE_METER_H
#define STM32_HSE_METER_H

#include <stdbool.h>
#include <stdint.h>

/* The HSE in Hz from timer tim_base whose channel 1 sees HSE / hse_div,
 * the timer counting the HSI (hsi_hz); 0 if an edge does not come within
 * its bound (no crystal). The timer is stopped afterwards. */
uint32_t stm32_hse_meter_run(uintptr_t tim_base, uint32_t hse_div, uint32_t hsi_hz);

/* hz within +-10 % of nominal_hz (the HSI's own error over temperature
 * included); 0 never is. */
bool stm32_hse_in_tolerance(uint32_t hz, uint32_t nominal_hz);

#endif /* STM32_HSE_METER_H */
