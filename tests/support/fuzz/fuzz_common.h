/* SPDX-License-Identifier: MIT */
/*
 * Shared bits of the libFuzzer targets in tests/support/fuzz/.
 *
 * Every target checks properties, not just "does not crash": FUZZ_REQUIRE
 * prints the failed property and aborts, which libFuzzer reports as a crash
 * and saves the input under build/fuzz-artifacts/ (see run-fuzz.sh).
 */
#ifndef FUZZ_COMMON_H
#define FUZZ_COMMON_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define FUZZ_REQUIRE(cond)                                                     \
	do {                                                                   \
		if (!(cond)) {                                                 \
			(void)fprintf(stderr, "%s:%d: property failed: %s\n",  \
				      __FILE__, __LINE__, #cond);              \
			abort();                                               \
		}                                                              \
	} while (0)

/* A reader over the fuzzer's bytes: past the end it returns zeros, so a
 * short input is still a complete (if boring) test case. */
typedef struct {
	const uint8_t *p;
	size_t left;
} fuzz_in_t;

static inline uint8_t fuzz_u8(fuzz_in_t *in)
{
	uint8_t v = 0U;

	if (in->left > 0U) {
		v = *in->p;
		in->p++;
		in->left--;
	}
	return v;
}

static inline uint16_t fuzz_u16(fuzz_in_t *in)
{
	const uint16_t lo = fuzz_u8(in);

	return (uint16_t)(lo | ((uint16_t)fuzz_u8(in) << 8));
}

static inline uint32_t fuzz_u32(fuzz_in_t *in)
{
	const uint32_t lo = fuzz_u16(in);

	return lo | ((uint32_t)fuzz_u16(in) << 16);
}

static inline void fuzz_bytes(fuzz_in_t *in, uint8_t *out, size_t n)
{
	size_t i;

	for (i = 0U; i < n; i++) {
		out[i] = fuzz_u8(in);
	}
}

/*
 * CRC-8 poly 0x1D, start 0, no final XOR, bit by bit: an independent
 * reference for the E2E P01 CRC (the firmware uses its own code).
 * Covers data ID low, data ID high, then bytes 1..len-1 of the frame.
 */
static inline uint8_t fuzz_ref_e2e_crc(uint16_t data_id, const uint8_t *frame,
				       size_t len)
{
	uint8_t buf[2 + 8];
	uint8_t crc = 0U;
	size_t n = 0U;
	size_t i;
	int b;

	buf[n++] = (uint8_t)(data_id & 0xFFU);
	buf[n++] = (uint8_t)(data_id >> 8);
	for (i = 1U; (i < len) && (i < 8U); i++) {
		buf[n++] = frame[i];
	}
	for (i = 0U; i < n; i++) {
		crc ^= buf[i];
		for (b = 0; b < 8; b++) {
			const uint32_t shifted = ((uint32_t)crc << 1) & 0xFFU;

			crc = (uint8_t)(((crc & 0x80U) != 0U) ? (shifted ^ 0x1DU) : shifted);
		}
	}
	return crc;
}

#endif /* FUZZ_COMMON_H */
