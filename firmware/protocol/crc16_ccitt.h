/* SPDX-License-Identifier: MIT */
/*
 * CRC-16/CCITT-FALSE (also "CRC-16/IBM-3740"): polynomial 0x1021, MSB
 * first (no reflection), start 0xFFFF, no final XOR; check value 0x29B1
 * over ASCII "123456789". The CRC of AUTOSAR E2E Profile 5 (e2e_p05.h).
 */
#ifndef CRC16_CCITT_H
#define CRC16_CCITT_H

#include <stddef.h>
#include <stdint.h>

#define CRC16_CCITT_INIT  0xFFFFU
#define CRC16_CCITT_CHECK 0x29B1U /* crc16_ccitt("123456789", 9) */

/* Continue a CRC over len more bytes from the register value crc (a whole
 * CRC is its own register value: no final XOR). data may be NULL only when
 * len == 0. */
uint16_t crc16_ccitt_update(uint16_t crc, const uint8_t *data, size_t len);

/* The whole CRC from CRC16_CCITT_INIT. */
uint16_t crc16_ccitt(const uint8_t *data, size_t len);

#endif /* CRC16_CCITT_H */
