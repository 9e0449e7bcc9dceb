/* SPDX-License-Identifier: MIT */
#include "crc16_ccitt.h"

#include "sq_contract.h"

/* Bitwise: 8 steps per byte over at most 64 bytes of an FD frame; a table
 * would cost 512 bytes of flash for a few microseconds per frame. */
uint16_t crc16_ccitt_update(uint16_t crc, const uint8_t *data, size_t len)
{
	uint32_t c = crc;
	size_t i;
	uint32_t k;

	HAL_REQUIRE((data != NULL) || (len == 0U));
	for (i = 0U; i < len; i++) {
		c ^= (uint32_t)data[i] << 8;
		for (k = 0U; k < 8U; k++) {
			c = ((c & 0x8000U) != 0U) ? (((c << 1) ^ CRC16_CCITT_POLY) & 0xFFFFU) :
				((c << 1) & 0xFFFFU);
		}
	}
	return (uint16_t)c;
}

uint16_t crc16_ccitt(const uint8_t *data, size_t len)
{
	return crc16_ccitt_update((uint16_t)CRC16_CCITT_INIT, data, len);
}
