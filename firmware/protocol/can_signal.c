/* SPDX-License-Identifier: MIT */
#include "can_signal.h"

#include <stddef.h>

#include "sq_contract.h"

#define BITS_PER_FRAME 64U

/*
 * Position of the signal's bits, LSB first. Intel counts up from the start
 * bit; Motorola's start bit is the MSB, so its LSB is found by walking the
 * sawtooth length - 1 steps, and from the LSB the walk goes back up
 * (bit 7 of a byte continues at bit 0 of the byte before). One walk per bit
 * keeps both orders in one loop of at most 32 steps.
 */
static uint8_t moto_next_down(uint8_t pos)
{
	/* MSB -> LSB direction: 8i+j -> 8i+j-1, bit 0 of byte i -> bit 7 of i+1 */
	return ((pos % 8U) == 0U) ? (uint8_t)(pos + 15U) : (uint8_t)(pos - 1U);
}

static uint8_t moto_next_up(uint8_t pos)
{
	/* LSB -> MSB: the inverse of moto_next_down */
	return ((pos % 8U) == 7U) ? (uint8_t)(pos - 15U) : (uint8_t)(pos + 1U);
}

/* The LSB's number, or 0xFF when a bit falls outside the frame. */
static uint8_t lsb_position(const can_signal_t *sig)
{
	uint32_t pos = sig->start_bit;
	uint32_t i;

	if (sig->byte_order == (uint8_t)CAN_SIGNAL_INTEL) {
		pos += (uint32_t)sig->length - 1U;
		return (pos < BITS_PER_FRAME) ? (uint8_t)sig->start_bit : 0xFFU;
	}
	for (i = 1U; i < sig->length; i++) {
		pos = moto_next_down((uint8_t)pos);
		if (pos >= BITS_PER_FRAME) {
			return 0xFFU;
		}
	}
	return (uint8_t)pos;
}

uint8_t can_signal_min_dlc(const can_signal_t *sig)
{
	uint8_t lsb;
	uint32_t hi_byte;

	HAL_REQUIRE(sig != NULL);
	if ((sig->length == 0U) || (sig->length > CAN_SIGNAL_MAX_LEN) ||
	    (sig->start_bit >= BITS_PER_FRAME) || (sig->byte_order > 1U) ||
	    (sig->is_signed > 1U)) {
		return 0U;
	}
	lsb = lsb_position(sig);
	if (lsb == 0xFFU) {
		return 0U;
	}
	if (sig->byte_order == (uint8_t)CAN_SIGNAL_INTEL) {
		hi_byte = ((uint32_t)sig->start_bit + sig->length - 1U) / 8U;
	} else {
		hi_byte = (uint32_t)lsb / 8U; /* Motorola: the LSB is in the last byte */
	}
	return (uint8_t)(hi_byte + 1U);
}

bool can_signal_valid(const can_signal_t *sig)
{
	return can_signal_min_dlc(sig) != 0U;
}

static uint8_t step_up(const can_signal_t *sig, uint8_t pos)
{
	return (sig->byte_order == (uint8_t)CAN_SIGNAL_INTEL) ? (uint8_t)(pos + 1U) :
		moto_next_up(pos);
}

/* The signal's bits as a 64-bit mask over the frame (bit n = DBC bit n). */
static uint64_t bit_mask(const can_signal_t *sig)
{
	uint64_t m = 0U;
	uint8_t pos = lsb_position(sig);
	uint32_t i;

	for (i = 0U; i < sig->length; i++) {
		m |= (uint64_t)1U << pos;
		pos = step_up(sig, pos);
	}
	return m;
}

bool can_signal_overlap(const can_signal_t *a, const can_signal_t *b)
{
	HAL_REQUIRE((a != NULL) && (b != NULL));
	if (!can_signal_valid(a) || !can_signal_valid(b)) {
		return true; /* a bad descriptor clashes with everything (validation) */
	}
	return (bit_mask(a) & bit_mask(b)) != 0U;
}

uint32_t can_signal_get(const can_signal_t *sig, const uint8_t data[8])
{
	uint32_t raw = 0U;
	uint8_t pos;
	uint32_t i;

	/* descriptors are validated with the calibration, before use */
	HAL_REQUIRE(can_signal_valid(sig) && (data != NULL));
	pos = lsb_position(sig);
	for (i = 0U; i < sig->length; i++) {
		raw |= (((uint32_t)data[pos / 8U] >> (pos % 8U)) & 1U) << i;
		pos = step_up(sig, pos);
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

void can_signal_put(const can_signal_t *sig, uint8_t data[8], uint32_t raw)
{
	uint8_t pos;
	uint32_t i;

	HAL_REQUIRE(can_signal_valid(sig) && (data != NULL));
	pos = lsb_position(sig);
	for (i = 0U; i < sig->length; i++) {
		const uint8_t bit = (uint8_t)(1U << (pos % 8U));

		if (((raw >> i) & 1U) != 0U) {
			data[pos / 8U] |= bit;
		} else {
			data[pos / 8U] &= (uint8_t)~bit;
		}
		pos = step_up(sig, pos);
	}
}
