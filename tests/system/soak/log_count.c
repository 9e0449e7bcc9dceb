/* SPDX-License-Identifier: MIT */
/*
 * log_count: the soak's independent reference. Reads a candump -L log of
 * DiscSpeed/PadForce (stdin) as the plant wrote it and says what the
 * monitor must report for it, without any firmware code:
 *   - frames per input identifier;
 *   - wrong-CRC frames: CRC-8 written here from its definition (AUTOSAR E2E
 *     Profile 1, variant 1A: polynomial 0x1D, start 0x00, no final XOR,
 *     over the data ID's low and high byte, then the frame's bytes 1..n-1;
 *     check value of "123456789" 0x37, verified at start); the data IDs are
 *     the DBC's E2E_DataID attributes (build/monitor/monitor_expect.h);
 *   - for the good frames, the documented receiver rules (README "Fault
 *     handling", monitor.h, e2e_p01.h): more than stale_cycles x period
 *     (30 ms) since the last used frame -> one stale event and the receiver
 *     starts over (the frame is used, nothing counted lost); otherwise the
 *     counter delta d: 0 repeated, 1..3 used with d - 1 lost (delta 3 is
 *     within the tolerance because P01 raises the tolerated jump by one on
 *     every check), 4..14 wrong sequence (not used);
 *   - one stale event per input at the end (replay runs on 100 ms after
 *     the last frame).
 * Output: "key value" lines (speed_*, force_*, lines, other).
 * Usage: log_count [--selftest] < LOG
 */
#include <inttypes.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "monitor_expect.h"

#define STALE_US 30000ULL

typedef struct {
	uint32_t id;
	uint16_t data_id;
	const char *name;
	uint64_t frames;
	uint64_t crc_bad;
	uint64_t bad_dlc;
	uint64_t used;
	uint64_t lost;
	uint64_t repeated;
	uint64_t wrong_sequence;
	uint64_t stale;
	bool have_ref;
	unsigned last_counter;
	uint64_t last_used_us;
} input_ref_t;

static uint8_t crc8_1d(uint8_t crc, const uint8_t *p, size_t n)
{
	for (size_t i = 0; i < n; i++) {
		crc ^= p[i];
		for (unsigned b = 0; b < 8U; b++) {
			crc = (uint8_t)(((crc & 0x80U) != 0U) ? (((unsigned)crc << 1) ^ 0x1DU) :
				       ((unsigned)crc << 1));
		}
	}
	return crc;
}

static int hexval(int c)
{
	if ((c >= '0') && (c <= '9')) {
		return c - '0';
	}
	if ((c >= 'A') && (c <= 'F')) {
		return c - 'A' + 10;
	}
	if ((c >= 'a') && (c <= 'f')) {
		return c - 'a' + 10;
	}
	return -1;
}

static void frame(input_ref_t *in, uint64_t t_us, const uint8_t *d, size_t n)
{
	uint8_t hdr[2];
	uint8_t crc;
	unsigned ctr;

	in->frames++;
	if (n != 4U) {
		in->bad_dlc++;
		return;
	}
	hdr[0] = (uint8_t)(in->data_id & 0xFFU);
	hdr[1] = (uint8_t)(in->data_id >> 8);
	crc = crc8_1d(0U, hdr, 2U);
	crc = crc8_1d(crc, &d[1], n - 1U);
	if (crc != d[0]) {
		in->crc_bad++;
		return;
	}
	ctr = d[1] & 0x0FU;
	if (in->have_ref && (t_us - in->last_used_us > STALE_US)) {
		in->stale++;
		in->have_ref = false;
	}
	if (in->have_ref) {
		const unsigned delta = (ctr + 15U - in->last_counter) % 15U;

		if (delta == 0U) {
			in->repeated++;
			return;
		}
		if (delta > 3U) {
			in->wrong_sequence++;
			return;
		}
		in->lost += delta - 1U;
	}
	in->have_ref = true;
	in->last_counter = ctr;
	in->last_used_us = t_us;
	in->used++;
}

static void print(const input_ref_t *in)
{
	printf("%s_frames %" PRIu64 "\n", in->name, in->frames);
	printf("%s_crc_bad %" PRIu64 "\n", in->name, in->crc_bad);
	printf("%s_bad_dlc %" PRIu64 "\n", in->name, in->bad_dlc);
	printf("%s_used %" PRIu64 "\n", in->name, in->used);
	printf("%s_lost %" PRIu64 "\n", in->name, in->lost);
	printf("%s_repeated %" PRIu64 "\n", in->name, in->repeated);
	printf("%s_wrong_sequence %" PRIu64 "\n", in->name, in->wrong_sequence);
	printf("%s_stale %" PRIu64 "\n", in->name, in->stale + (in->have_ref ? 1U : 0U));
}

int main(int argc, char **argv)
{
	static const uint8_t check[9] = { '1', '2', '3', '4', '5', '6', '7', '8', '9' };
	input_ref_t in[2] = {
		{ .id = EXP_DBC_DISCSPEED_ID, .data_id = EXP_DBC_DISCSPEED_DATA_ID, .name = "speed" },
		{ .id = EXP_DBC_PADFORCE_ID, .data_id = EXP_DBC_PADFORCE_DATA_ID, .name = "force" },
	};
	char line[512];
	uint64_t lines = 0U;
	uint64_t other = 0U;
	uint64_t malformed = 0U;

	if (crc8_1d(0U, check, sizeof(check)) != 0x37U) {
		fprintf(stderr, "log_count: CRC-8 check value wrong\n");
		return 1;
	}
	if ((argc > 1) && (strcmp(argv[1], "--selftest") == 0)) {
		printf("crc8 check 0x37 ok\n");
		return 0;
	}
	while (fgets(line, sizeof(line), stdin) != NULL) {
		unsigned long long sec = 0U;
		unsigned long long usec = 0U;
		char iface[64];
		char body[256];
		char *hash;
		uint8_t d[8];
		size_t n = 0U;
		uint32_t id;
		bool ok = true;

		lines++;
		if (sscanf(line, " (%llu.%llu) %63s %255s", &sec, &usec, iface, body) != 4) {
			malformed++;
			continue;
		}
		hash = strchr(body, '#');
		if (hash == NULL) {
			malformed++;
			continue;
		}
		*hash = '\0';
		id = (uint32_t)strtoul(body, NULL, 16);
		for (const char *p = hash + 1; (*p != '\0') && ok; p += 2) {
			const int hi = hexval((unsigned char)p[0]);
			const int lo = (hi >= 0) ? hexval((unsigned char)p[1]) : -1;

			if ((lo < 0) || (n >= 8U)) {
				ok = false;
			} else {
				d[n++] = (uint8_t)((hi << 4) | lo);
			}
		}
		if (!ok) {
			malformed++;
			continue;
		}
		if (id == in[0].id) {
			frame(&in[0], sec * 1000000ULL + usec, d, n);
		} else if (id == in[1].id) {
			frame(&in[1], sec * 1000000ULL + usec, d, n);
		} else {
			other++;
		}
	}
	printf("lines %" PRIu64 "\n", lines);
	printf("malformed %" PRIu64 "\n", malformed);
	printf("other %" PRIu64 "\n", other);
	print(&in[0]);
	print(&in[1]);
	return 0;
}
