/* SPDX-License-Identifier: MIT */
/*
 * E2E Profile 1 fixtures shared by the CRC, E2E P01 and message tests of
 * firmware/protocol: the CRC's bitwise definition as the reference, the
 * configurations of DiscSpeed and PadForce, and DiscSpeed frames whose CRCs
 * were computed outside the code under test (Python, bitwise).
 */
#ifndef P01_FRAMES_H
#define P01_FRAMES_H

#include <stddef.h>
#include <stdint.h>

#include "e2e_p01.h"

/* Reference: CRC-8 poly 0x1D, one bit at a time, from init, xorout at the end. */
uint8_t ref_crc8(const uint8_t *d, size_t n, uint8_t init, uint8_t xorout);

extern const e2e_p01_config_t cfg_ds; /* DiscSpeed, max delta 1 */
extern const e2e_p01_config_t cfg_pf; /* PadForce, max delta 1 */

/* DiscSpeed_radps = 123.45 rad/s (raw 12345) with counter c (mod 15):
 * CRC, c, 0x39, 0x30. */
void ds_frame(uint8_t counter, uint8_t f[4]);

#endif /* P01_FRAMES_H */
