/* SPDX-License-Identifier: MIT */
/*
 * CRC-8 with polynomial 0x1D (x^8 + x^4 + x^3 + x^2 + 1), MSB first, not
 * reflected, as AUTOSAR E2E Profile 1 applies it.
 *
 * Profile 1 calls the SAE-J1850 routine (start 0xFF, final XOR 0xFF) in a
 * way whose net effect is start value 0x00 and no final XOR. That variant
 * ("CRC-8/SAE-J1850-ZERO") has the check value 0x37 over ASCII "123456789";
 * plain CRC-8/SAE-J1850 has 0x4B. Both are provided so a test can prove which
 * one the E2E code uses (crc8_p01()).
 */
#ifndef CRC8_P01_H
#define CRC8_P01_H

#include <stddef.h>
#include <stdint.h>

#define CRC8_P01_POLY        0x1DU
#define CRC8_P01_CHECK       0x37U /* crc8_p01("123456789", 9)       */
#define CRC8_SAE_J1850_CHECK 0x4BU /* crc8_sae_j1850("123456789", 9) */

/* Continue a CRC over len more bytes: crc is the register value so far
 * (no final XOR applied). data may be NULL only when len == 0. */
uint8_t crc8_p01_update(uint8_t crc, const uint8_t *data, size_t len);

/* Profile 1 CRC: start 0x00, no final XOR. */
uint8_t crc8_p01(const uint8_t *data, size_t len);

/* Plain CRC-8/SAE-J1850: start 0xFF, final XOR 0xFF (not used on the bus). */
uint8_t crc8_sae_j1850(const uint8_t *data, size_t len);

#endif /* CRC8_P01_H */
