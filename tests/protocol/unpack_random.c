/* SPDX-License-Identifier: MIT */
/*
 * Test helper of tests/protocol/test_unpack_crosscheck.py: random frames
 * through the firmware's input unpackers.
 *
 *   unpack_random N SEED   for every input message in the table below, N
 *                          random frames (random bytes; one in eight with a
 *                          random DLC 0..8 instead of the message's), each
 *                          printed as
 *                            <DBC message> <dlc> <8 bytes hex> [Signal=raw ...] rc=<rc>
 *                          with the raw value of every DBC signal the
 *                          unpacker returned (only when rc is SQ_OK; the
 *                          bytes beyond the DLC are random too and must be
 *                          ignored).
 * The Python side decodes the same bytes with canmatrix from the DBC and
 * compares. A new input message is one adapter function and one table row.
 */
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>

#include "sq_status.h"
#include "squeal_msgs.h"

/* An adapter unpacks one frame and prints " Signal=raw" for each field. */
typedef int (*unpack_print_fn)(const uint8_t *data, uint8_t dlc);

static int unpack_disc_speed(const uint8_t *data, uint8_t dlc)
{
	msg_disc_speed_t m;
	int rc = msg_disc_speed_unpack(data, dlc, &m);

	if (rc == SQ_OK) {
		printf(" DiscSpeed_CRC=%u DiscSpeed_Counter=%u DiscSpeed_radps=%u", (unsigned int)m.crc,
		       (unsigned int)m.counter, (unsigned int)m.disc_speed_radps);
	}
	return rc;
}

static int unpack_pad_force(const uint8_t *data, uint8_t dlc)
{
	msg_pad_force_t m;
	int rc = msg_pad_force_unpack(data, dlc, &m);

	if (rc == SQ_OK) {
		printf(" PadForce_CRC=%u PadForce_Counter=%u PadForce_N=%u", (unsigned int)m.crc,
		       (unsigned int)m.counter, (unsigned int)m.pad_force_n);
	}
	return rc;
}

struct input_msg {
	const char *dbc_name; /* the message's name in the DBC */
	uint8_t dlc;          /* its DLC */
	unpack_print_fn unpack;
};

/* One row per input message. */
static const struct input_msg inputs[] = {
	{ "DiscSpeed", MSG_DISC_SPEED_DLC, unpack_disc_speed },
	{ "PadForce", MSG_PAD_FORCE_DLC, unpack_pad_force },
};

static uint64_t rng_state;

static uint32_t rng(void) /* xorshift64*: reproducible from the seed */
{
	rng_state ^= rng_state >> 12;
	rng_state ^= rng_state << 25;
	rng_state ^= rng_state >> 27;
	return (uint32_t)((rng_state * 0x2545F4914F6CDD1DULL) >> 32);
}

int main(int argc, char **argv)
{
	unsigned long n;

	if (argc != 3) {
		fprintf(stderr, "usage: %s N SEED\n", argv[0]);
		return 2;
	}
	n = strtoul(argv[1], NULL, 10);
	rng_state = strtoull(argv[2], NULL, 10) | 1ULL;
	for (size_t k = 0; k < sizeof(inputs) / sizeof(inputs[0]); k++) {
		for (unsigned long i = 0; i < n; i++) {
			uint8_t d[MSG_MAX_DLC];
			uint8_t dlc = inputs[k].dlc;
			int rc;

			for (unsigned int b = 0; b < MSG_MAX_DLC; b++) {
				d[b] = (uint8_t)rng();
			}
			if ((rng() & 7U) == 0U) {
				dlc = (uint8_t)(rng() % 9U);
			}
			printf("%s %u ", inputs[k].dbc_name, (unsigned int)dlc);
			for (unsigned int b = 0; b < MSG_MAX_DLC; b++) {
				printf("%02X", (unsigned int)d[b]);
			}
			rc = inputs[k].unpack(d, dlc);
			printf(" rc=%d\n", rc);
		}
	}
	return 0;
}
