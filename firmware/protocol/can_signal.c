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
	uint32_t i;

	/* descriptors are validated with the calibration, before use */
	HAL_REQUIRE(can_signal_valid(sig) && (data != NULL));
	for (i = 0U; i < sig->length; i++) {
		const uint32_t pos = bit_pos(sig, i);

		raw |= (((uint32_t)data[pos / 8U] >> (pos % 8U)) & 1U) << i;
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
	uint32_t i;

	HAL_REQUIRE(can_signal_valid(sig) && (data != NULL));
	for (i = 0U; i < sig->length; i++) {
		const uint32_t pos = bit_pos(sig, i);
		const uint8_t bit = (uint8_t)(1U << (pos % 8U));

		if (((raw >> i) & 1U) != 0U) {
			data[pos / 8U] |= bit;
		} else {
			data[pos / 8U] &= (uint8_t)~bit;
		}
	}
}
