/* SPDX-License-Identifier: MIT */
/*
 * AUTOSAR E2E Profile 5 (AUTOSAR PRS E2E protocol, "Specification of E2E
 * Profile 5"), for long classic and CAN FD frames:
 *   bytes off, off+1  CRC-16/CCITT-FALSE (crc16_ccitt.h), little-endian
 *   byte off+2        counter 0..255, +1 (mod 256) per sent frame
 *   CRC over the frame's bytes 0 .. off-1 and off+2 .. len-1 (every byte
 *   but the two CRC bytes, the counter included), then the 16-bit Data ID,
 *   low byte first (the Data ID is never sent). off is e2e_offset_byte
 *   (AUTOSAR's Offset / 8), 0 by default.
 * Published example (AUTOSAR E2E Profile 5): 8 zero bytes, Data ID 0x1234
 * -> CRC bytes 1c ca; counter 1 -> cf 8d (tests/firmware/protocol).
 * The receiver's sequence machine is P01's (e2e_rx_sequence, e2e_p01.h)
 * with modulus 256; the statuses are e2e_p01_status_t.
 */
#ifndef E2E_P05_H
#define E2E_P05_H

#include <stdint.h>

#include "e2e_p01.h"

#define E2E_P05_MODULUS 256U
#define E2E_P05_HEADER_LEN 3U   /* CRC 2 bytes + counter                */
#define E2E_P05_MAX_LEN 64U     /* CAN FD                               */

typedef struct {
	uint16_t data_id;           /* both bytes in the CRC                  */
	uint8_t data_len;           /* 3..64: the frame's length in bytes     */
	uint8_t offset_byte;        /* CRC at offset_byte, offset_byte + 3 <= data_len */
	uint8_t max_delta_counter;  /* 1..255                                */
} e2e_p05_config_t;

/* SQ_OK, or SQ_EINVAL for data_len outside 3..64, a header beyond
 * data_len or max_delta_counter 0. Contracts (hal.h): NULL pointers, and a
 * configuration this rejects, given to crc/protect/check are programming
 * errors, and so is protecting a buffer of another length; a received
 * frame of the wrong length is bad data (WRONGCRC). */
int e2e_p05_config_check(const e2e_p05_config_t *cfg);

/* The CRC of a frame whose bytes other than the CRC (counter included)
 * are final; len must be cfg->data_len. */
uint16_t e2e_p05_crc(const e2e_p05_config_t *cfg, const uint8_t *data, uint8_t len);

/* Write the counter (byte offset + 2) and the CRC, advance the counter
 * (255 -> 0). SQ_OK. */
int e2e_p05_protect(const e2e_p05_config_t *cfg, e2e_p01_tx_t *tx,
		    uint8_t *data, uint8_t len);

/* One received frame (data NULL: none this cycle). Same statuses and
 * receiver state as P01; every counter 0..255 is valid. */
e2e_p01_status_t e2e_p05_check(const e2e_p05_config_t *cfg, e2e_p01_rx_t *rx,
			       const uint8_t *data, uint8_t len);

#endif /* E2E_P05_H */
