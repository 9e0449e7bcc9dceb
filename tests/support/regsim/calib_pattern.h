/* SPDX-License-Identifier: MIT */
/*
 * The calibration storage tests' blocks (tests/hal/stm32f4/test_calib_flash.c
 * on the F4/F103's byte-wise flash, tests/hal/stm32g4/test_chip_g4.c on the
 * G4's double words): a seed and a step of 7, so that two blocks of
 * different seeds differ in every byte and a mix of them is seen.
 */
#ifndef REGSIM_CALIB_PATTERN_H
#define REGSIM_CALIB_PATTERN_H

#include <stdint.h>

static inline void calib_pattern_fill(uint8_t *b, uint32_t len, uint8_t seed)
{
	uint32_t i;

	for (i = 0; i < len; i++) {
		b[i] = (uint8_t)(seed + 7U * i);
	}
}

#endif /* REGSIM_CALIB_PATTERN_H */
