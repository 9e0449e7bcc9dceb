/* SPDX-License-Identifier: MIT */
#include "can_signal.h"

#include <stddef.h>

#include "sq_contract.h"

/*
 * Motorola's sawtooth is a straight run in "big-endian bit order": number
 * the bits of byte i from its MSB, m = 8 i + (7 - j). Then a Motorola
 * signal takes m(start) .. m(start) + length - 1, MSB first, and every
 * check is a range check; the mapping is its own inverse.
 */
static uint32_t moto_index(uint32_t pos)
{
	return (pos & ~7U) | (7U - (pos & 7U));
}

/* Where the signal's bits run in its order's linear numbering (Intel: the
 * DBC numbers, Motorola: moto_index): first .. first + length - 1. */
static uint32_t run_first(const can_signal_t *sig)
{
	return (sig->byte_order == (uint8_t)CAN_SIGNAL_INTEL) ? sig->start_bit :
		moto_index(sig->start_bit);
}

/* The DBC number of the signal's bit i, LSB first (i < length). */
static uint32_t bit_pos(const can_signal_t *sig, uint32_t i)
{
	if (sig->byte_order == (uint8_t)CAN_SIGNAL_INTEL) {
		return (uint32_t)sig->start_bit + i;
	}
	return moto_index(run_first(sig) + sig->length - 1U - i);
}

/*
 * get and put walk the signal a byte at a time, LSB first: its LSB's byte
 * from the LSB's bit, then each next byte from bit 0 (Intel: the byte
 * after, Motorola: the byte before), so a 32-bit signal is at most five
 * chunks instead of 32 single bits.
 */
#define CHUNKS_MAX 5U

typedef struct {
	uint32_t byte;  /* the byte the next chunk is in */
	uint32_t shift; /* its first bit in that byte */
	uint32_t done;  /* the signal's bits already walked */
} chunk_t;

static void chunk_start(const can_signal_t *sig, chunk_t *c)
{
	const uint32_t lsb = bit_pos(sig, 0U);

	c->byte = lsb / 8U;
	c->shift = lsb % 8U;
	c->done = 0U;
}

/* The bits of the chunk at c: to the top of its byte or the signal's end. */
static uint32_t chunk_bits(const can_signal_t *sig, const chunk_t *c)
{
	const uint32_t room = 8U - c->shift;
	const uint32_t left = sig->length - c->done;

	return (left < room) ? left : room;
}

static void chunk_next(const can_signal_t *sig, chunk_t *c, uint32_t n)
{
	c->done += n;
	c->shift = 0U;
	if (c->done < sig->length) {
		/* a valid signal's next byte is in the frame (can_signal_min_dlc) */
		c->byte = (sig->byte_order == (uint8_t)CAN_SIGNAL_INTEL) ? (c->byte + 1U) :
			(c->byte - 1U);
	}
}

uint8_t can_signal_min_dlc(const can_signal_t *sig)
{
	uint32_t last;

	HAL_REQUIRE(sig != NULL);
	if ((sig->length == 0U) || (sig->length > CAN_SIGNAL_MAX_LEN) ||
	    (sig->start_bit >= CAN_SIGNAL_MAX_BITS) || (sig->byte_order > 1U) ||
	    (sig->is_signed > 1U)) {
		return 0U;
	}
	/* the far end of the run: Intel's MSB, Motorola's LSB; both keep the
	 * byte number of the DBC bit they stand for */
	last = run_first(sig) + sig->length - 1U;
	if (last >= CAN_SIGNAL_MAX_BITS) {
		return 0U;
	}
	return (uint8_t)((last / 8U) + 1U);
}

bool can_signal_valid(const can_signal_t *sig)
{
	return can_signal_min_dlc(sig) != 0U;
}

/* Does the (valid) signal hold DBC bit pos? */
static bool holds(const can_signal_t *sig, uint32_t pos)
{
	const uint32_t first = run_first(sig);
	const uint32_t m = (sig->byte_order == (uint8_t)CAN_SIGNAL_INTEL) ? pos : moto_index(pos);

	return (m >= first) && (m < (first + sig->length));
}

bool can_signal_overlap(const can_signal_t *a, const can_signal_t *b)
{
	uint32_t i;

	HAL_REQUIRE((a != NULL) && (b != NULL));
	if (!can_signal_valid(a) || !can_signal_valid(b)) {
		return true; /* a bad descriptor clashes with everything (validation) */
	}
	for (i = 0U; i < a->length; i++) {
		if (holds(b, bit_pos(a, i))) {
			return true;
		}
	}
	return false;
}

uint32_t can_signal_get(const can_signal_t *sig, const uint8_t *data)
{
	uint32_t raw = 0U;
	chunk_t c;
	uint32_t i;

	/* descriptors are validated with the calibration, before use */
	HAL_REQUIRE(can_signal_valid(sig) && (data != NULL));
	chunk_start(sig, &c);
	for (i = 0U; (i < CHUNKS_MAX) && (c.done < sig->length); i++) {
		const uint32_t n = chunk_bits(sig, &c);
		const uint32_t mask = (1U << n) - 1U;

		raw |= (((uint32_t)data[c.byte] >> c.shift) & mask) << c.done;
		chunk_next(sig, &c, n);
	}
	return raw;
}

int64_t can_signal_value(const can_signal_t *sig, uint32_t raw)
{
	uint64_t top;
	uint64_t r;

	HAL_REQUIRE(can_signal_valid(sig));
	top = (uint64_t)1U << (sig->length - 1U);
	r = (uint64_t)raw & ((top << 1) - 1U);
	if ((sig->is_signed != 0U) && ((r & top) != 0U)) {
		return -(int64_t)((top << 1) - r);
	}
	return (int64_t)r;
}

uint32_t can_signal_raw_of(const can_signal_t *sig, int64_t value)
{
	HAL_REQUIRE(can_signal_valid(sig));
	return (uint32_t)((uint64_t)value & (((uint64_t)1U << sig->length) - 1U));
}

void can_signal_put(const can_signal_t *sig, uint8_t *data, uint32_t raw)
{
	chunk_t c;
	uint32_t i;

	HAL_REQUIRE(can_signal_valid(sig) && (data != NULL));
	chunk_start(sig, &c);
	for (i = 0U; (i < CHUNKS_MAX) && (c.done < sig->length); i++) {
		const uint32_t n = chunk_bits(sig, &c);
		const uint32_t mask = ((1U << n) - 1U) << c.shift;
		const uint32_t bits = ((raw >> c.done) << c.shift) & mask;

		data[c.byte] = (uint8_t)(((uint32_t)data[c.byte] & ~mask) | bits);
		chunk_next(sig, &c, n);
	}
}
