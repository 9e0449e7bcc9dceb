/* SPDX-License-Identifier: MIT */
/*
 * Calibration storage: two slots in flash that the image never uses
 * (linker: __calib_start, two slots of __calib_slot_size bytes). A write
 * goes to the slot NOT holding the newest valid block: erase, program the
 * payload and the header, the header's magic word last. A reset at any
 * moment leaves the previous block intact in the other slot; a half-written
 * slot fails its magic or its CRC and is ignored. hal_calib_read() returns
 * the valid block with the highest sequence number.
 *
 * Slot layout: magic, seq, len, crc32(seq, len, payload), payload.
 *
 * Every read of a slot goes through chip_flash_read(): on a chip with
 * flash ECC (the G4: 64-bit double words) a power cut in the middle of a
 * double word can leave an ECC double error there; its read raises the NMI,
 * which the chip part clears and counts instead of resetting (no NMI reset
 * loop), and the read reports SQ_EIO. That slot is corrupt, like a
 * half-written one: ignored (stm32_calib_ecc_rejects() counts it), the
 * other slot is used, and the next write erases it.
 *
 * Erasing stalls the CPU (single flash bank; code runs from it) for up to
 * ~0.5 s on the F4, and the IWDG keeps counting: write calibration before
 * starting the watchdog or with a watchdog timeout above 1 s; a watchdog
 * reset in the middle is harmless (old block stays).
 */
#include <stddef.h>

#include "chip.h"
#include "hal.h"
#include "sq_status.h"
#include "stm32_calib.h"
#include "stm32_iwdg.h"
#include "stm32_platform_faults.h"

#define CALIB_MAGIC 0x4C435153UL /* "SQCL" */
#define CALIB_HDR_LEN 16U
#define READ_CHUNK 32U /* bytes read from flash at a time */

extern const uint8_t __calib_start[];
extern const uint8_t __calib_slot_size[];
extern const uint8_t __calib_slot_count[];

typedef struct {
	uint32_t magic;
	uint32_t seq;
	uint32_t len;
	uint32_t crc;
} calib_hdr_t;

_Static_assert(sizeof(calib_hdr_t) == CALIB_HDR_LEN, "header layout");

/* The header bytes programmed last, together with the magic word: the
 * flash's program unit, at least the magic itself. */
#define CALIB_MAGIC_UNIT (CHIP_FLASH_PROGRAM_BYTES > 4U ? CHIP_FLASH_PROGRAM_BYTES : 4U)
_Static_assert(CALIB_MAGIC_UNIT < CALIB_HDR_LEN && CALIB_HDR_LEN % CALIB_MAGIC_UNIT == 0U,
	       "the header splits into program units");

static uint32_t slot_size(void)
{
	return (uint32_t)(uintptr_t)__calib_slot_size;
}

static uint32_t slot_addr(uint32_t slot)
{
	return (uint32_t)(uintptr_t)__calib_start + slot * slot_size();
}

/* Slot reads that met an ECC double error (a corrupt slot), since start */
static uint32_t ecc_rejects;

uint32_t stm32_calib_ecc_rejects(void)
{
	return ecc_rejects;
}

/* n bytes at off in slot; false (counted) on an ECC double error */
static bool slot_read(uint32_t slot, uint32_t off, uint8_t *dst, uint32_t n)
{
	if (chip_flash_read(slot_addr(slot) + off, dst, n) != SQ_OK) {
		ecc_rejects++;
		return false;
	}
	return true;
}

static uint32_t crc32_update(uint32_t crc, const uint8_t *p, uint32_t n)
{
	uint32_t i;
	uint32_t k;

	for (i = 0; i < n; i++) {
		crc ^= p[i];
		for (k = 0; k < 8U; k++) {
			crc = (crc >> 1) ^ (0xEDB88320UL & (0U - (crc & 1U)));
		}
	}
	return crc;
}

/* The CRC's running value over seq and len (little-endian), before the
 * payload. */
static uint32_t crc_of_meta(uint32_t seq, uint32_t len)
{
	uint8_t meta[8];
	uint32_t i;

	for (i = 0; i < 4U; i++) {
		meta[i] = (uint8_t)((seq >> (8U * i)) & 0xFFU);
		meta[4U + i] = (uint8_t)((len >> (8U * i)) & 0xFFU);
	}
	return crc32_update(0xFFFFFFFFUL, meta, sizeof(meta));
}

static uint32_t le32(const uint8_t *b)
{
	return (uint32_t)b[0] | ((uint32_t)b[1] << 8) | ((uint32_t)b[2] << 16) | ((uint32_t)b[3] << 24);
}

static bool read_hdr(uint32_t slot, calib_hdr_t *h)
{
	uint8_t b[CALIB_HDR_LEN];

	if (!slot_read(slot, 0U, b, CALIB_HDR_LEN)) {
		return false;
	}
	h->magic = le32(&b[0]);
	h->seq = le32(&b[4]);
	h->len = le32(&b[8]);
	h->crc = le32(&b[12]);
	return true;
}

static bool slot_valid(uint32_t slot, calib_hdr_t *h)
{
	uint8_t chunk[READ_CHUNK];
	uint32_t crc;
	uint32_t off;

	if (!read_hdr(slot, h) || h->magic != CALIB_MAGIC || h->len > HAL_CALIB_MAX_LEN ||
	    h->len > slot_size() - CALIB_HDR_LEN) {
		return false;
	}
	crc = crc_of_meta(h->seq, h->len);
	for (off = 0U; off < h->len; off += READ_CHUNK) {
		const uint32_t n = (h->len - off < READ_CHUNK) ? h->len - off : READ_CHUNK;

		if (!slot_read(slot, CALIB_HDR_LEN + off, chunk, n)) {
			return false;
		}
		crc = crc32_update(crc, chunk, n);
	}
	return ~crc == h->crc;
}

/* The newest valid slot, or -1. Sequence numbers compare modulo 2^32. */
static int newest_slot(calib_hdr_t *out)
{
	calib_hdr_t h[2];
	bool ok0 = slot_valid(0U, &h[0]);
	bool ok1 = slot_valid(1U, &h[1]);
	int best;

	if (ok0 && ok1) {
		best = (int32_t)(h[1].seq - h[0].seq) > 0 ? 1 : 0;
	} else if (ok0) {
		best = 0;
	} else if (ok1) {
		best = 1;
	} else {
		return -1;
	}
	*out = h[best];
	return best;
}

int hal_calib_read(uint8_t *buf, uint32_t len)
{
	calib_hdr_t h;
	int slot;
	uint32_t stored;
	uint32_t i;

	if (buf == NULL || len > HAL_CALIB_MAX_LEN) {
		return SQ_EINVAL;
	}
	slot = newest_slot(&h);
	if (slot < 0) {
		return SQ_ENOENT;
	}
	stored = (h.len < len) ? h.len : len;
	if (!slot_read((uint32_t)slot, CALIB_HDR_LEN, buf, stored)) {
		return SQ_EIO; /* it read whole a moment ago */
	}
	/* Shorter stored block: the rest reads as erased flash (0xFF); the
	 * block's own CRC (firmware/monitor) decides whether it is usable. */
	for (i = stored; i < len; i++) {
		buf[i] = 0xFFU;
	}
	return SQ_OK;
}

int hal_calib_write(const uint8_t *buf, uint32_t len)
{
	calib_hdr_t cur;
	calib_hdr_t hdr;
	calib_hdr_t check;
	int newest;
	uint32_t target;
	uint32_t addr;
	uint8_t chunk[READ_CHUNK];
	uint32_t off;
	uint32_t i;

	if (buf == NULL || len > HAL_CALIB_MAX_LEN || (uint32_t)(uintptr_t)__calib_slot_count != 2U ||
	    len > slot_size() - CALIB_HDR_LEN) {
		return SQ_EINVAL;
	}
	/* An erase stalls the CPU (F4: up to 0.5 s per 16 KiB sector, code
	 * runs from the same flash bank) while the IWDG keeps counting: the
	 * watchdog would reset mid-write and the time base would lose those
	 * ticks. Writes are therefore refused once the watchdog runs:
	 * calibration is written before hal_watchdog_start(). */
	if (stm32_watchdog_running()) {
		return SQ_EAGAIN;
	}
	newest = newest_slot(&cur);
	target = newest == 0 ? 1U : 0U;
	hdr.magic = CALIB_MAGIC;
	hdr.seq = newest < 0 ? 1U : cur.seq + 1U;
	hdr.len = len;
	hdr.crc = ~crc32_update(crc_of_meta(hdr.seq, len), buf, len);
	addr = slot_addr(target);

	hal_watchdog_kick();
	if (chip_flash_erase_slot(target) != SQ_OK) {
		stm32_fault_raise(HAL_FAULT_CALIB_STORAGE);
		return SQ_EIO;
	}
	hal_watchdog_kick();
	/* Blank check of what we are about to program. */
	for (off = 0U; off < CALIB_HDR_LEN + len; off += READ_CHUNK) {
		const uint32_t n = (CALIB_HDR_LEN + len - off < READ_CHUNK) ? CALIB_HDR_LEN + len - off :
										READ_CHUNK;
		bool blank = slot_read(target, off, chunk, n);

		for (i = 0U; blank && (i < n); i++) {
			blank = chunk[i] == 0xFFU;
		}
		if (!blank) {
			stm32_fault_raise(HAL_FAULT_CALIB_STORAGE);
			return SQ_EIO;
		}
	}
	/* Payload, then the header after the magic's program unit, then that
	 * unit with the magic that makes it count: seq/len/crc, then magic
	 * (units of 4 or fewer bytes); len/crc, then magic + seq (the G4's
	 * 8-byte double words, each programmed once). */
	if (chip_flash_program(addr + CALIB_HDR_LEN, buf, len) != SQ_OK ||
	    chip_flash_program(addr + CALIB_MAGIC_UNIT, (const uint8_t *)&hdr + CALIB_MAGIC_UNIT,
			       CALIB_HDR_LEN - CALIB_MAGIC_UNIT) != SQ_OK ||
	    chip_flash_program(addr, (const uint8_t *)&hdr, CALIB_MAGIC_UNIT) != SQ_OK) {
		stm32_fault_raise(HAL_FAULT_CALIB_STORAGE);
		return SQ_EIO;
	}
	if (!slot_valid(target, &check) || check.seq != hdr.seq) {
		stm32_fault_raise(HAL_FAULT_CALIB_STORAGE);
		return SQ_EIO;
	}
	return SQ_OK;
}
