/* SPDX-License-Identifier: MIT */
/*
 * fuzz_calib_block: calib_decode() on arbitrary bytes (the stored block is
 * read from flash or a file: it may hold anything).
 *
 * Each input is decoded twice: as it is, and with its header and CRC
 * repaired (magic, version, length and CRC-32 made right), so the fuzzer
 * reaches the field and range checks behind the CRC instead of stopping at
 * the 1-in-2^32 CRC gate.
 *
 * Properties:
 *   - the return code is SQ_OK or SQ_EBADMSG with a reason that is not
 *     CALIB_OK; on SQ_EBADMSG the output is untouched;
 *   - accepted => calib_validate() passes, the block is at least
 *     CALIB_BLOCK_LEN long with the right header and CRC (checked here with
 *     an independent bitwise CRC-32), and encode(decode(x)) equals the
 *     first CALIB_BLOCK_LEN bytes of x exactly (no field is normalised or
 *     dropped silently);
 *   - the model parameters of an accepted block pass squeal_model_params_check
 *     (so a calibration that loads can always be classified with).
 */
#include "fuzz_common.h"

#include "calib.h"

static uint32_t ref_crc32(const uint8_t *p, size_t n)
{
	uint32_t crc = 0xFFFFFFFFU;
	size_t i;
	int b;

	for (i = 0U; i < n; i++) {
		crc ^= p[i];
		for (b = 0; b < 8; b++) {
			crc = ((crc & 1U) != 0U) ? ((crc >> 1) ^ 0xEDB88320U) : (crc >> 1);
		}
	}
	return ~crc;
}

static uint32_t le(const uint8_t *p, size_t n)
{
	uint32_t v = 0U;
	size_t i;

	for (i = 0U; i < n; i++) {
		v |= (uint32_t)p[i] << (8U * i);
	}
	return v;
}

static void put_le(uint8_t *p, uint32_t v, size_t n)
{
	size_t i;

	for (i = 0U; i < n; i++) {
		p[i] = (uint8_t)(v >> (8U * i));
	}
}

static void check_decode(const uint8_t *buf, size_t size)
{
	calib_t cal;
	calib_t sentinel;
	calib_error_t why = CALIB_OK;
	uint8_t enc[CALIB_BLOCK_LEN];
	squeal_params_t params;
	int rc;

	memset(&sentinel, 0xC3, sizeof(sentinel));
	cal = sentinel;
	rc = calib_decode(buf, (uint32_t)size, &cal, &why);
	FUZZ_REQUIRE((rc == SQ_OK) || (rc == SQ_EBADMSG));
	if (rc != SQ_OK) {
		FUZZ_REQUIRE(why != CALIB_OK);
		FUZZ_REQUIRE(memcmp(&cal, &sentinel, sizeof(cal)) == 0);
		return;
	}
	FUZZ_REQUIRE(why == CALIB_OK);
	FUZZ_REQUIRE(size >= CALIB_BLOCK_LEN);
	FUZZ_REQUIRE(le(buf, 4U) == 0x42435153U);
	FUZZ_REQUIRE(le(buf + 4, 2U) == CALIB_VERSION);
	FUZZ_REQUIRE(le(buf + 6, 2U) == CALIB_BLOCK_LEN);
	FUZZ_REQUIRE(le(buf + CALIB_BLOCK_LEN - 4U, 4U) ==
		     ref_crc32(buf, CALIB_BLOCK_LEN - 4U));
	FUZZ_REQUIRE(calib_validate(&cal) == SQ_OK);
	FUZZ_REQUIRE(calib_encode(&cal, enc, sizeof(enc)) == SQ_OK);
	FUZZ_REQUIRE(memcmp(enc, buf, CALIB_BLOCK_LEN) == 0);
	calib_model_params(&cal, &params);
	FUZZ_REQUIRE(squeal_model_params_check(&params) == SQ_OK);
	/* a short buffer is refused whatever it holds */
	FUZZ_REQUIRE(calib_decode(buf, CALIB_BLOCK_LEN - 1U, &cal, &why) == SQ_EBADMSG);
	FUZZ_REQUIRE(why == CALIB_ERR_LENGTH);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	uint8_t *fixed;

	check_decode(data, size);
	if (size < CALIB_BLOCK_LEN) {
		return 0;
	}
	fixed = malloc(size);
	if (fixed == NULL) {
		return 0;
	}
	memcpy(fixed, data, size);
	put_le(fixed, 0x42435153U, 4U);
	put_le(fixed + 4, CALIB_VERSION, 2U);
	put_le(fixed + 6, CALIB_BLOCK_LEN, 2U);
	put_le(fixed + CALIB_BLOCK_LEN - 4U, ref_crc32(fixed, CALIB_BLOCK_LEN - 4U), 4U);
	check_decode(fixed, size);
	free(fixed);
	return 0;
}
