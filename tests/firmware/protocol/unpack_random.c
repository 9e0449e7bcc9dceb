/* SPDX-License-Identifier: MIT */
/*
 * Test helper of tests/firmware/protocol/test_squeal_msgs_unpack.py: random frames
 * through the firmware's unpackers (the inputs, and the outputs that host
 * tools decode; SquealDiag's pages are covered by the fixed cases).
 *
 *   unpack_random N SEED   for every message in the table below, N
 *                          random frames (random bytes; one in eight with a
 *                          random DLC 0..8 instead of the message's), each
 *                          printed as
 *                            <DBC message> <dlc> <8 bytes hex> [Signal=raw ...] rc=<rc> [@Signal=raw ...]
 *                          with the raw value of every DBC signal the
 *                          unpacker returned (only when rc is SQ_OK; the
 *                          bytes beyond the DLC are random too and must be
 *                          ignored), then what the descriptor-driven
 *                          msg_sig_get_raw() reads (any frame of the DLC).
 * The Python side decodes the same bytes with canmatrix from the DBC and
 * compares. A new message is one adapter function and one table row.
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

/* The outputs' unpackers (host tools decode the monitor's frames with them) */
static int unpack_squeal_status(const uint8_t *data, uint8_t dlc)
{
	msg_squeal_status_t m;
	int rc = msg_squeal_status_unpack(data, dlc, &m);

	if (rc == SQ_OK) {
		printf(" SquealStatus_CRC=%u SquealStatus_Counter=%u SquealState=%u WarningLevel=%u"
		       " BasinRatio=%u HopfMargin_mps=%d BorderMargin_sigma=%u", (unsigned int)m.crc,
		       (unsigned int)m.counter, (unsigned int)m.squeal_state,
		       (unsigned int)m.warning_level, (unsigned int)m.basin_ratio,
		       (int)m.hopf_margin_mps, (unsigned int)m.border_margin_sigma);
	}
	return rc;
}

static int unpack_squeal_detail(const uint8_t *data, uint8_t dlc)
{
	msg_squeal_detail_t m;
	int rc = msg_squeal_detail_unpack(data, dlc, &m);

	if (rc == SQ_OK) {
		printf(" SquealDetail_CRC=%u SquealDetail_Counter=%u V0_mps=%u HopfSpeed_mps=%u"
		       " TriggerVelocity_mps=%u VehicleSpeedBorder_kph=%u", (unsigned int)m.crc,
		       (unsigned int)m.counter, (unsigned int)m.v0_mps, (unsigned int)m.hopf_speed_mps,
		       (unsigned int)m.trigger_velocity_mps, (unsigned int)m.vehicle_speed_border_kph);
	}
	return rc;
}

static int unpack_squeal_detail2(const uint8_t *data, uint8_t dlc)
{
	msg_squeal_detail2_t m;
	int rc = msg_squeal_detail2_unpack(data, dlc, &m);

	if (rc == SQ_OK) {
		printf(" SquealDetail2_CRC=%u SquealDetail2_Counter=%u Force_N=%u HopfForce_N=%u"
		       " LcAmplitude_um=%u", (unsigned int)m.crc, (unsigned int)m.counter,
		       (unsigned int)m.force_n, (unsigned int)m.hopf_force_n,
		       (unsigned int)m.lc_amplitude_um);
	}
	return rc;
}

struct input_msg {
	const char *dbc_name; /* the message's name in the DBC */
	uint16_t id;          /* its identifier (descriptor table) */
	uint8_t dlc;          /* its DLC */
	unpack_print_fn unpack;
};

/* One row per message with an unpacker: the inputs first. */
static const struct input_msg inputs[] = {
	{ "DiscSpeed", MSG_DISC_SPEED_ID, MSG_DISC_SPEED_DLC, unpack_disc_speed },
	{ "PadForce", MSG_PAD_FORCE_ID, MSG_PAD_FORCE_DLC, unpack_pad_force },
	{ "SquealStatus", MSG_SQUEAL_STATUS_ID, MSG_SQUEAL_STATUS_DLC, unpack_squeal_status },
	{ "SquealDetail", MSG_SQUEAL_DETAIL_ID, MSG_SQUEAL_DETAIL_DLC, unpack_squeal_detail },
	{ "SquealDetail2", MSG_SQUEAL_DETAIL2_ID, MSG_SQUEAL_DETAIL2_DLC, unpack_squeal_detail2 },
};

/* The descriptor-driven reader (host tools' decode): " @Signal=raw" for
 * every signal it reads from this frame. */
static void print_generic(uint16_t id, const uint8_t *data, uint8_t dlc)
{
	const msg_desc_t *m = msg_desc_find(id);

	for (unsigned int j = 0U; m != NULL && j < m->sig_count; j++) {
		const msg_sig_desc_t *sig = &msg_sig_table[m->sig_first + j];
		int32_t raw;

		if (msg_sig_get_raw(sig, data, dlc, &raw) == SQ_OK) {
			printf(" @%s=%" PRId32, sig->name, raw);
		}
	}
}

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
			printf(" rc=%d", rc);
			print_generic(inputs[k].id, d, dlc);
			printf("\n");
		}
	}
	return 0;
}
