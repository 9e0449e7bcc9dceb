/* SPDX-License-Identifier: MIT */
/*
 * The two-slot calibration storage (hal/stm32f4/calib_flash.c) on the host,
 * over a simulated NOR flash: erase sets a slot to 0xFF, programming can
 * only clear bits, and a "power cut" stops any erase or program after a
 * chosen number of bytes. The claim of hal.h is checked exhaustively: a
 * write interrupted at ANY byte leaves the old block or the new one
 * readable, never a mix, never nothing (once a block was stored).
 * The slot geometry comes from the link (--defsym), as on the target.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "chip.h"
#include "regsim/calib_pattern.h"
#include "stm32_board.h"

#define SLOT 2048U /* the F103's two-page slot (linker/stm32f103xb.ld) */
uint8_t calib_flash_sim[2U * SLOT] __attribute__((aligned(4)));

static long budget = -1; /* bytes the "power" still allows; -1: unlimited */
static uint32_t faults;

static bool spend(void)
{
	if (budget == 0) {
		return false;
	}
	if (budget > 0) {
		budget--;
	}
	return true;
}

int chip_flash_erase_slot(uint32_t slot)
{
	uint32_t i;

	if (slot > 1U) {
		return SQ_EINVAL;
	}
	for (i = 0; i < SLOT; i++) {
		if (!spend()) {
			return SQ_EIO; /* power gone half-way through the erase */
		}
		calib_flash_sim[slot * SLOT + i] = 0xFFU;
	}
	return SQ_OK;
}

/* Worn cells: bits set here stay 1 (erased) whatever is programmed, and
 * the program still reports success (a driver that does not read back). */
static uint8_t stuck[2U * SLOT];

int chip_flash_program(uint32_t addr, const uint8_t *data, uint32_t len)
{
	uint8_t *p = (uint8_t *)(uintptr_t)addr;
	const size_t at = (size_t)(p - calib_flash_sim);
	uint32_t i;

	for (i = 0; i < len; i++) {
		if (!spend()) {
			return SQ_EIO;
		}
		p[i] &= (uint8_t)(data[i] | stuck[at + i]); /* NOR: bits only go from 1 to 0 */
	}
	return SQ_OK;
}

/* NOR without ECC (the F4 and F103): a read is a copy */
int chip_flash_read(uint32_t addr, uint8_t *dst, uint32_t n)
{
	memcpy(dst, (const uint8_t *)(uintptr_t)addr, n);
	return SQ_OK;
}

void hal_watchdog_kick(void)
{
}

static bool watchdog_running;

bool stm32_watchdog_running(void)
{
	return watchdog_running;
}

void stm32_fault_raise(uint32_t hal_fault_bits)
{
	faults |= hal_fault_bits;
}

static int setup(void **state)
{
	(void)state;
	memset(calib_flash_sim, 0x00, sizeof(calib_flash_sim)); /* garbage, not erased */
	memset(stuck, 0x00, sizeof(stuck));
	budget = -1;
	faults = 0U;
	watchdog_running = false;
	return 0;
}

static void test_empty_reads_enoent(void **state)
{
	uint8_t buf[64];

	(void)state;
	assert_int_equal(hal_calib_read(buf, sizeof(buf)), SQ_ENOENT);
	memset(calib_flash_sim, 0xFF, sizeof(calib_flash_sim));
	assert_int_equal(hal_calib_read(buf, sizeof(buf)), SQ_ENOENT);
}

static void test_write_then_read_round_trip(void **state)
{
	uint8_t a[HAL_CALIB_MAX_LEN];
	uint8_t out[HAL_CALIB_MAX_LEN];

	(void)state;
	calib_pattern_fill(a, sizeof(a), 1U);
	assert_int_equal(hal_calib_write(a, sizeof(a)), SQ_OK);
	assert_int_equal(hal_calib_read(out, sizeof(out)), SQ_OK);
	assert_memory_equal(a, out, sizeof(a));
	assert_int_equal(faults, 0U);
}

static void test_writes_alternate_slots_and_keep_the_old(void **state)
{
	uint8_t a[100], b[100], c[100], out[100];

	(void)state;
	calib_pattern_fill(a, sizeof(a), 1U);
	calib_pattern_fill(b, sizeof(b), 2U);
	calib_pattern_fill(c, sizeof(c), 3U);
	assert_int_equal(hal_calib_write(a, sizeof(a)), SQ_OK);
	assert_int_equal(hal_calib_write(b, sizeof(b)), SQ_OK);
	/* a is still in the other slot, untouched */
	assert_memory_equal(&calib_flash_sim[16], a, sizeof(a));
	assert_memory_equal(&calib_flash_sim[SLOT + 16U], b, sizeof(b));
	assert_int_equal(hal_calib_write(c, sizeof(c)), SQ_OK);
	assert_memory_equal(&calib_flash_sim[16], c, sizeof(c));
	assert_int_equal(hal_calib_read(out, sizeof(out)), SQ_OK);
	assert_memory_equal(out, c, sizeof(c));
}

/* The heart of it: cut the power after every possible number of bytes. */
static void interrupted_write(size_t len)
{
	static uint8_t a[HAL_CALIB_MAX_LEN], b[HAL_CALIB_MAX_LEN], out[HAL_CALIB_MAX_LEN];
	long cut;
	long total = -1;
	uint32_t saw_old = 0U, saw_new = 0U;

	calib_pattern_fill(a, (uint32_t)len, 10U);
	calib_pattern_fill(b, (uint32_t)len, 20U);
	for (cut = 0;; cut++) {
		int rc;

		setup(NULL);
		assert_int_equal(hal_calib_write(a, (uint32_t)len), SQ_OK);
		budget = cut;
		rc = hal_calib_write(b, (uint32_t)len);
		budget = -1;
		assert_int_equal(hal_calib_read(out, (uint32_t)len), SQ_OK);
		if (memcmp(out, a, len) == 0) {
			saw_old++;
			assert_int_not_equal(rc, SQ_OK);
		} else {
			assert_memory_equal(out, b, len); /* never a mix */
			saw_new++;
		}
		if (rc == SQ_OK) {
			total = cut;
			break;
		}
		assert_int_equal(rc, SQ_EIO);
	}
	/* erase (SLOT) + payload + 12 header bytes + 4 magic bytes */
	assert_int_equal(total, (long)(SLOT + len + 16U));
	assert_int_equal(saw_new, 1U); /* only the complete write counts */
	assert_true(saw_old > SLOT);
}

static void test_interrupted_write_leaves_old_or_new(void **state)
{
	(void)state;
	interrupted_write(200U);
}

/* The calibration block v3 (1440 bytes, CALIB_BLOCK_LEN) spans both 1 KiB
 * pages of the F103's slot: cut anywhere, still old or new. */
static void test_interrupted_two_page_write_leaves_old_or_new(void **state)
{
	(void)state;
	interrupted_write(1440U);
}

static void test_corrupt_newest_falls_back_to_older(void **state)
{
	uint8_t a[64], b[64], out[64];

	(void)state;
	calib_pattern_fill(a, sizeof(a), 4U);
	calib_pattern_fill(b, sizeof(b), 5U);
	assert_int_equal(hal_calib_write(a, sizeof(a)), SQ_OK);
	assert_int_equal(hal_calib_write(b, sizeof(b)), SQ_OK);
	calib_flash_sim[SLOT + 16U + 10U] ^= 0x01U; /* one bit of b */
	assert_int_equal(hal_calib_read(out, sizeof(out)), SQ_OK);
	assert_memory_equal(out, a, sizeof(a));
	calib_flash_sim[16U + 63U] ^= 0x80U; /* and one of a */
	assert_int_equal(hal_calib_read(out, sizeof(out)), SQ_ENOENT);
}

static void put32(uint8_t *p, uint32_t v)
{
	p[0] = (uint8_t)v;
	p[1] = (uint8_t)(v >> 8);
	p[2] = (uint8_t)(v >> 16);
	p[3] = (uint8_t)(v >> 24);
}

/* Standard CRC-32 (IEEE 802.3, reflected), written here independently. */
static uint32_t crc32_ref(const uint8_t *p, uint32_t n, uint32_t crc)
{
	uint32_t i, k;

	for (i = 0; i < n; i++) {
		crc ^= p[i];
		for (k = 0; k < 8U; k++) {
			crc = (crc & 1U) ? (crc >> 1) ^ 0xEDB88320U : crc >> 1;
		}
	}
	return crc;
}

/* A slot as the format says: magic "SQCL", seq, len, crc32(seq, len,
 * payload), payload; all little endian. */
static void forge_slot(uint32_t slot, uint32_t seq, const uint8_t *payload, uint32_t len)
{
	uint8_t *p = &calib_flash_sim[slot * SLOT];
	uint8_t meta[8];
	uint32_t crc;

	memset(p, 0xFF, SLOT);
	put32(&meta[0], seq);
	put32(&meta[4], len);
	crc = ~crc32_ref(payload, len, crc32_ref(meta, 8U, 0xFFFFFFFFU));
	put32(&p[0], 0x4C435153U);
	put32(&p[4], seq);
	put32(&p[8], len);
	put32(&p[12], crc);
	memcpy(&p[16], payload, len);
}

static void test_crc_reference_check_value(void **state)
{
	(void)state;
	assert_int_equal(~crc32_ref((const uint8_t *)"123456789", 9U, 0xFFFFFFFFU), 0xCBF43926U);
}

/* Sequence numbers compare modulo 2^32: after 0xFFFFFFFF comes 0. */
static void test_sequence_wraps(void **state)
{
	uint8_t a[32], b[32], c[32], out[32];

	(void)state;
	calib_pattern_fill(a, sizeof(a), 6U);
	calib_pattern_fill(b, sizeof(b), 7U);
	calib_pattern_fill(c, sizeof(c), 8U);
	forge_slot(0U, 0xFFFFFFFFU, a, sizeof(a));
	forge_slot(1U, 0U, b, sizeof(b));
	assert_int_equal(hal_calib_read(out, sizeof(out)), SQ_OK);
	assert_memory_equal(out, b, sizeof(b));
	/* the next write replaces the older slot 0 and gets seq 1 */
	assert_int_equal(hal_calib_write(c, sizeof(c)), SQ_OK);
	assert_memory_equal(&calib_flash_sim[SLOT + 16U], b, sizeof(b));
	assert_int_equal(calib_flash_sim[4], 1U);
	assert_int_equal(hal_calib_read(out, sizeof(out)), SQ_OK);
	assert_memory_equal(out, c, sizeof(c));
	/* a forged slot with the wrong CRC is ignored */
	put32(&calib_flash_sim[4], 0x7FFFFFFFU);
	assert_int_equal(hal_calib_read(out, sizeof(out)), SQ_OK);
	assert_memory_equal(out, b, sizeof(b));
}

static void test_short_block_pads_and_bad_args(void **state)
{
	uint8_t a[8] = { 1, 2, 3, 4, 5, 6, 7, 8 };
	uint8_t out[12];
	static const uint8_t want[12] = { 1, 2, 3, 4, 5, 6, 7, 8, 0xFF, 0xFF, 0xFF, 0xFF };
	uint8_t big[HAL_CALIB_MAX_LEN + 1U];

	(void)state;
	assert_int_equal(hal_calib_write(a, sizeof(a)), SQ_OK);
	assert_int_equal(hal_calib_read(out, sizeof(out)), SQ_OK);
	assert_memory_equal(out, want, sizeof(want));
	memset(big, 0, sizeof(big));
	assert_int_equal(hal_calib_write(big, sizeof(big)), SQ_EINVAL);
	assert_int_equal(hal_calib_write(NULL, 4U), SQ_EINVAL);
	assert_int_equal(hal_calib_read(NULL, 4U), SQ_EINVAL);
	assert_int_equal(hal_calib_read(big, sizeof(big)), SQ_EINVAL);
}

/* A slot that reads back as a valid block, but not the one written, is a
 * failed write. The first write to empty slots is seq 1; with the 8-byte
 * payload below its CRC-32 over (seq, len, payload) is 0x384E0880, and with
 * seq 3 it is 0xBFEE2DE3 = 0x384E0880 | 0x87A02563 (zlib.crc32, and
 * crc32_ref here). Worn cells that stay 1 at bit 1 of the seq's first byte
 * and at the bits 0x87A02563 of the CRC therefore turn the written block
 * into a valid block with seq 3: its magic, length and CRC check, only its
 * sequence number says it is not what was written. hal_calib_write must
 * report SQ_EIO with the storage fault (the slot cannot be trusted to
 * order the next write), not success. */
static void test_valid_read_back_with_another_seq_is_eio(void **state)
{
	static const uint8_t payload[8] = { 0x73, 0x0E, 0x00, 0x00, 0x5A, 0x5A, 0x5A, 0x5A };
	uint8_t meta[8];
	uint32_t crc1;
	uint32_t crc3;

	(void)state;
	put32(&meta[0], 1U);
	put32(&meta[4], 8U);
	crc1 = ~crc32_ref(payload, 8U, crc32_ref(meta, 8U, 0xFFFFFFFFU));
	put32(&meta[0], 3U);
	crc3 = ~crc32_ref(payload, 8U, crc32_ref(meta, 8U, 0xFFFFFFFFU));
	assert_int_equal(crc1, 0x384E0880U);
	assert_int_equal(crc3, 0xBFEE2DE3U);
	stuck[4] = 0x02U;  /* seq 1 reads as 3 */
	put32(&stuck[12], 0x87A02563U); /* and the CRC as seq 3's */

	assert_int_equal(hal_calib_write(payload, sizeof(payload)), SQ_EIO);
	assert_int_equal(faults & HAL_FAULT_CALIB_STORAGE, HAL_FAULT_CALIB_STORAGE);
	/* what slot 0 holds: magic, seq 3, len 8, seq 3's CRC, the payload */
	assert_int_equal(calib_flash_sim[4], 3U);
	assert_int_equal(calib_flash_sim[12], 0xE3U);
	assert_int_equal(calib_flash_sim[15], 0xBFU);
	assert_memory_equal(&calib_flash_sim[16], payload, sizeof(payload));
}

/* an erase stalls the CPU longer than a watchdog period, so a
 * write is refused once the IWDG runs: SQ_EAGAIN, flash untouched (no
 * erase, no byte programmed), no storage fault; the stored block stays. */
static void test_write_refused_while_watchdog_runs(void **state)
{
	uint8_t a[64];
	uint8_t b[64];
	uint8_t out[64];
	uint8_t before[sizeof(calib_flash_sim)];

	(void)state;
	calib_pattern_fill(a, sizeof(a), 3U);
	calib_pattern_fill(b, sizeof(b), 9U);
	assert_int_equal(hal_calib_write(a, sizeof(a)), SQ_OK);
	memcpy(before, calib_flash_sim, sizeof(before));
	watchdog_running = true;
	assert_int_equal(hal_calib_write(b, sizeof(b)), SQ_EAGAIN);
	assert_memory_equal(before, calib_flash_sim, sizeof(before));
	assert_int_equal(faults, 0U);
	assert_int_equal(hal_calib_read(out, sizeof(out)), SQ_OK);
	assert_memory_equal(a, out, sizeof(a));
}

static void test_failed_erase_reports_storage_fault(void **state)
{
	uint8_t a[16];

	(void)state;
	calib_pattern_fill(a, sizeof(a), 8U);
	budget = 5;
	assert_int_equal(hal_calib_write(a, sizeof(a)), SQ_EIO);
	assert_int_equal(faults & HAL_FAULT_CALIB_STORAGE, HAL_FAULT_CALIB_STORAGE);
}

SQ_CMOCKA_MAIN(
	cmocka_unit_test_setup(test_empty_reads_enoent, setup),
	cmocka_unit_test_setup(test_write_then_read_round_trip, setup),
	cmocka_unit_test_setup(test_writes_alternate_slots_and_keep_the_old, setup),
	cmocka_unit_test_setup(test_interrupted_write_leaves_old_or_new, setup),
	cmocka_unit_test_setup(test_interrupted_two_page_write_leaves_old_or_new, setup),
	cmocka_unit_test_setup(test_corrupt_newest_falls_back_to_older, setup),
	cmocka_unit_test(test_crc_reference_check_value),
	cmocka_unit_test_setup(test_sequence_wraps, setup),
	cmocka_unit_test_setup(test_short_block_pads_and_bad_args, setup),
	cmocka_unit_test_setup(test_failed_erase_reports_storage_fault, setup),
	cmocka_unit_test_setup(test_valid_read_back_with_another_seq_is_eio, setup),
	cmocka_unit_test_setup(test_write_refused_while_watchdog_runs, setup))
