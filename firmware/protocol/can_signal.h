/* SPDX-License-Identifier: MIT */
/*
 * can_signal: one signal of a CAN frame (classic, up to 8 bytes, or CAN FD,
 * up to 64), described the way a DBC file describes it, and the raw value it
 * carries. One code path for every message: the same descriptor type reads
 * DiscSpeed_radps, a vehicle's wheel speed or a brake pressure
 * (docs/calib-input-map.md).
 *
 * Bit numbering (DBC): bit j of byte i is number 8 i + j, j = 7 the MSB;
 * an FD frame of 64 bytes has the numbers 0..511.
 *   Intel    (@1): start_bit is the LSB; the signal takes the numbers
 *                  start .. start + length - 1.
 *   Motorola (@0): start_bit is the MSB; from there the signal runs down to
 *                  bit 0 of that byte and goes on at bit 7 of the next byte
 *                  (the "sawtooth"): 22|15@0 takes 22..16, then 31..24.
 * Raw values are 1..32 bits; signed raws are two's complement.
 */
#ifndef CAN_SIGNAL_H
#define CAN_SIGNAL_H

#include <stdbool.h>
#include <stdint.h>

#define CAN_SIGNAL_MAX_LEN 32U
#define CAN_SIGNAL_MAX_BYTES 64U  /* the longest frame: CAN FD          */
#define CAN_SIGNAL_MAX_BITS (8U * CAN_SIGNAL_MAX_BYTES)

/* can_signal_t.byte_order */
#define CAN_SIGNAL_INTEL    0U /* DBC @1 */
#define CAN_SIGNAL_MOTOROLA 1U /* DBC @0 */

typedef struct {
	uint16_t start_bit;  /* DBC start bit, 0..511                         */
	uint8_t length;      /* 1..32                                         */
	uint8_t byte_order;  /* CAN_SIGNAL_INTEL or CAN_SIGNAL_MOTOROLA        */
	uint8_t is_signed;   /* 1: two's complement                           */
} can_signal_t;

/*
 * Contracts (hal.h): a NULL pointer is a programming error everywhere; so
 * is a bad descriptor given to get/value/put/raw_of, which take only
 * descriptors the calibration's validation (min_dlc, valid, overlap) passed.
 *
 * The smallest data length in bytes that holds every bit of the signal
 * (1..64), or 0 when the descriptor is bad: length 0 or > 32, start bit
 * > 511, byte order unknown, or a bit beyond the 512 bits of an FD frame.
 * Whether that length exists (above 8 only 12, 16, 20, 24, 32, 48, 64) and
 * whether the message is an FD one is the calibration's business.
 */
uint8_t can_signal_min_dlc(const can_signal_t *sig);

/* True when sig is a usable descriptor (can_signal_min_dlc() != 0). */
bool can_signal_valid(const can_signal_t *sig);

/* True when the two signals share a bit, or when either is bad. */
bool can_signal_overlap(const can_signal_t *a, const can_signal_t *b);

/*
 * The raw bits of sig in data, the frame's bytes: at least
 * can_signal_min_dlc(sig) of them (check the frame's length against
 * min_dlc first). Unsigned: 0 .. 2^length - 1.
 */
uint32_t can_signal_get(const can_signal_t *sig, const uint8_t *data);

/* raw as a number: sign-extended when sig is signed. */
int64_t can_signal_value(const can_signal_t *sig, uint32_t raw);

/* The inverse: write the low `length` bits of raw into data (at least
 * can_signal_min_dlc(sig) bytes) at sig's position; every other bit is
 * kept. */
void can_signal_put(const can_signal_t *sig, uint8_t *data, uint32_t raw);

/* Every value of a signal, as raw bits: signed values are truncated to
 * two's complement in `length` bits. */
uint32_t can_signal_raw_of(const can_signal_t *sig, int64_t value);

#endif /* CAN_SIGNAL_H */
