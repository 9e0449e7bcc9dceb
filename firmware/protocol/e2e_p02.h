/* SPDX-License-Identifier: MIT */
/*
 * AUTOSAR E2E Profile 2 on a classic CAN frame (AUTOSAR PRS E2E protocol,
 * section "Specification of E2E Profile 2"):
 *   byte 0           CRC-8H2F (poly 0x2F, start 0xFF, final XOR 0xFF; check
 *                    value 0xDF over "123456789")
 *   byte 1 bits 0..3 counter 0..15, +1 (mod 16) per sent frame
 *   CRC over bytes 1 .. len-1, then one Data ID byte: DataIDList[counter].
 * The spec's example (DataIDList 0x01..0x10, bytes 1..7 = 01 00 .. 00)
 * protects to CRC 0x1B; tests/firmware/monitor/test_input_conv.c checks it.
 * The receiver's sequence machine is P01's (e2e_rx_sequence) with modulus
 * 16; the statuses are e2e_p01_status_t.
 */
#ifndef E2E_P02_H
#define E2E_P02_H

#include <stddef.h>
#include <stdint.h>

#include "e2e_p01.h"

#define E2E_P02_DATA_ID_COUNT 16U
#define E2E_P02_MODULUS 16U
#define CRC8_H2F_CHECK 0xDFU

typedef struct {
	uint8_t data_id_list[E2E_P02_DATA_ID_COUNT];
	uint8_t data_len;           /* 2..8                                  */
	uint8_t max_delta_counter;  /* 1..15                                 */
} e2e_p02_config_t;

/* CRC-8H2F continuing from crc (the register, no final XOR applied). */
uint8_t crc8_h2f_update(uint8_t crc, const uint8_t *data, size_t len);
/* Whole CRC-8H2F: start 0xFF, final XOR 0xFF. */
uint8_t crc8_h2f(const uint8_t *data, size_t len);

/* SQ_OK, or SQ_EINVAL for data_len outside 2..8 or max_delta_counter
 * outside 1..15. Contracts (hal.h): NULL pointers, and a configuration this
 * rejects, given to crc/protect/check are programming errors, and so is
 * protecting a buffer of another length; a received frame of the wrong
 * length is bad data (WRONGCRC). */
int e2e_p02_config_check(const e2e_p02_config_t *cfg);

/* The CRC of a frame whose bytes 1..len-1 (counter included) are final. */
uint8_t e2e_p02_crc(const e2e_p02_config_t *cfg, const uint8_t *data, uint8_t len);

/* Write counter (low nibble of byte 1) and CRC, advance the counter
 * (15 -> 0). SQ_OK (len must be cfg->data_len, the counter 0..15). */
int e2e_p02_protect(const e2e_p02_config_t *cfg, e2e_p01_tx_t *tx,
		    uint8_t *data, uint8_t len);

/* One received frame (data NULL: none this cycle). Same statuses and
 * receiver state as P01; counter 15 is valid. */
e2e_p01_status_t e2e_p02_check(const e2e_p02_config_t *cfg, e2e_p01_rx_t *rx,
			       const uint8_t *data, uint8_t len);

#endif /* E2E_P02_H */
