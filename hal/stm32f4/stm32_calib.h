/* SPDX-License-Identifier: MIT */
/*
 * The calibration storage's count beyond hal.h (calib_flash.c): slot reads
 * that met a flash ECC double error (a slot a power cut left in the middle
 * of a double word, on the G4), each time a slot was found corrupt that
 * way since start. Chips without flash ECC: always 0.
 */
#ifndef STM32_CALIB_H
#define STM32_CALIB_H

#include <stdint.h>

uint32_t stm32_calib_ecc_rejects(void);

#endif /* STM32_CALIB_H */
