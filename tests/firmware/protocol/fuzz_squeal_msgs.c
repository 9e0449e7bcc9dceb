/* SPDX-License-Identifier: MIT */
/*
 * fuzz_msgs: every CAN message decoder, the E2E P01 check and the input
 * receive functions, with arbitrary bytes and DLCs.
 *
 * Input: byte 0 = MaxDeltaCounterInit for the E2E configs (any value: an
 * invalid one must be refused without touching the receiver), then records
 * of 10 bytes: [mode, dlc, 8 data bytes]. mode bits 0..2 pick the message
 * (mod 6), bit 3 "no frame this cycle" (data == NULL), bit 4 "fix the CRC"
 * (so the fuzzer gets past the CRC into the sequence logic), bit 5 "use the
 * message's own DLC". Each frame is handed over in a heap buffer of exactly
 * min(dlc, 8) bytes, so ASan catches any read beyond what was received.
 *
 * Properties:
 *   - unpack: SQ_OK iff dlc is the message's DLC, the counter is not 15 and
 *     (SquealDiag) the page is known; otherwise SQ_EBADMSG, output untouched;
 *   - round trip: where unpack succeeded, pack() succeeds iff every signal's
 *     raw value is inside its range or NA (checked through the descriptor
 *     table), and then every signal of pack(unpack(x)) equals x's, and
 *     pack(unpack(y)) == y byte for byte;
 *   - e2e_p01_check equals an independent model of the documented receiver
 *     (e2e_p01.h) on every call, with an independent bitwise CRC;
 *   - msg_*_receive: SQ_OK only for usable statuses (message written),
 *     otherwise the message is untouched;
 *   - e2e_p01_protect gives a frame whose CRC matches the reference.
 */
#include "fuzz_common.h"

#include <stdbool.h>

#include "any_msg.h"
#include "e2e_p01.h"
#include "sq_status.h"
#include "squeal_msgs.h"

/* ---- independent model of the P01 receiver (from e2e_p01.h's text) ------ */
typedef struct {
	bool wait_first;
	bool resync;
	uint8_t last;
	uint8_t tolerated;
} ref_rx_t;

static void ref_init(ref_rx_t *r)
{
	r->wait_first = true;
	r->resync = false;
	r->last = 0U;
	r->tolerated = 0U;
}

static bool cfg_valid(const e2e_p01_config_t *cfg)
{
	return (cfg->data_len >= 2U) && (cfg->data_len <= 8U) &&
	       (cfg->max_delta_counter >= 1U) && (cfg->max_delta_counter <= 14U);
}

static e2e_p01_status_t ref_check(const e2e_p01_config_t *cfg, ref_rx_t *r,
				  const uint8_t *data, uint8_t len)
{
	uint8_t c;
	uint8_t delta;

	if (r->tolerated < 14U) {
		r->tolerated++;
	}
	if (data == NULL) {
		return E2E_P01_STATUS_NONEWDATA;
	}
	if ((len != cfg->data_len) || (data[0] != fuzz_ref_e2e_crc(cfg->data_id, data, len))) {
		return E2E_P01_STATUS_WRONGCRC;
	}
	c = data[1] & 0x0FU;
	if (c == 15U) {
		return E2E_P01_STATUS_WRONGSEQUENCE;
	}
	if (r->wait_first) {
		r->wait_first = false;
		r->resync = false;
		r->last = c;
		r->tolerated = cfg->max_delta_counter;
		return E2E_P01_STATUS_INITIAL;
	}
	delta = (uint8_t)((c + 15U - r->last) % 15U);
	if (delta == 0U) {
		return E2E_P01_STATUS_REPEATED;
	}
	if (delta > r->tolerated) {
		/* adopt the new sequence; its next frame is INITIAL */
		r->resync = true;
		r->last = c;
		r->tolerated = cfg->max_delta_counter;
		return E2E_P01_STATUS_WRONGSEQUENCE;
	}
	r->last = c;
	r->tolerated = cfg->max_delta_counter;
	if (r->resync) {
		r->resync = false;
		return E2E_P01_STATUS_INITIAL;
	}
	return (delta == 1U) ? E2E_P01_STATUS_OK : E2E_P01_STATUS_OKSOMELOST;
}

/* ---- one table over the six messages ------------------------------------ */

/* The descriptor table's opinion of a frame of the right DLC. */
static bool frame_decodable(const msg_desc_t *desc, const uint8_t *d)
{
	uint32_t i;

	for (i = 0U; i < desc->sig_count; i++) {
		const msg_sig_desc_t *s = &msg_sig_table[desc->sig_first + i];
		int32_t raw = 0;

		FUZZ_REQUIRE(msg_sig_get_raw(s, d, desc->dlc, &raw) == SQ_OK ||
			     (s->flags & MSG_SIG_MUXED) != 0U);
		if (((s->flags & MSG_SIG_E2E) != 0U) && (s->start_bit == 8U) &&
		    (raw > (int32_t)E2E_P01_COUNTER_MAX)) {
			return false; /* counter 15 */
		}
		if (((s->flags & MSG_SIG_MUXOR) != 0U) && (raw > s->raw_max)) {
			return false; /* unknown page */
		}
	}
	return true;
}

static bool frame_in_range(const msg_desc_t *desc, const uint8_t *d)
{
	uint32_t i;

	for (i = 0U; i < desc->sig_count; i++) {
		const msg_sig_desc_t *s = &msg_sig_table[desc->sig_first + i];
		int32_t raw = 0;
		const int rc = msg_sig_get_raw(s, d, desc->dlc, &raw);

		if (rc == SQ_ENOENT) {
			continue; /* other page */
		}
		FUZZ_REQUIRE(rc == SQ_OK);
		/* SquealState: only the VAL table's 0..3 and 15 are sent,
		 * although the 4-bit signal's range is 0..15 */
		if ((s->msg_id == MSG_SQUEAL_STATUS_ID) && (i == 2U) &&
		    (raw > (int32_t)MSG_SQUEAL_STATE_NOT_SLIDING) &&
		    (raw != (int32_t)MSG_SQUEAL_STATE_FAULT)) {
			return false;
		}
		if (((raw < s->raw_min) || (raw > s->raw_max)) &&
		    !(((s->flags & MSG_SIG_HAS_NA) != 0U) && (raw == s->na_raw))) {
			return false;
		}
	}
	return true;
}

static void same_signals(const msg_desc_t *desc, const uint8_t *a, const uint8_t *b)
{
	uint32_t i;

	for (i = 0U; i < desc->sig_count; i++) {
		const msg_sig_desc_t *s = &msg_sig_table[desc->sig_first + i];
		int32_t ra = 0;
		int32_t rb = 0;
		const int rca = msg_sig_get_raw(s, a, desc->dlc, &ra);
		const int rcb = msg_sig_get_raw(s, b, desc->dlc, &rb);

		FUZZ_REQUIRE(rca == rcb);
		FUZZ_REQUIRE(ra == rb);
	}
}

static void check_unpack_roundtrip(const msg_desc_t *desc, const uint8_t *d,
				   uint8_t dlc, const uint8_t *full)
{
	any_msg_t m;
	any_msg_t m2;
	any_msg_t sentinel;
	uint8_t y[8];
	uint8_t z[8];
	uint8_t ydlc = 0U;
	uint8_t zdlc = 0U;
	int rc;
	int prc;

	memset(&sentinel, 0x6B, sizeof(sentinel));
	m = sentinel;
	rc = any_msg_unpack(desc->id, d, dlc, &m);
	FUZZ_REQUIRE((rc == SQ_OK) || (rc == SQ_EBADMSG));
	if (dlc != desc->dlc) {
		FUZZ_REQUIRE(rc == SQ_EBADMSG);
	} else {
		FUZZ_REQUIRE((rc == SQ_OK) == frame_decodable(desc, full));
	}
	if (rc != SQ_OK) {
		FUZZ_REQUIRE(memcmp(&m, &sentinel, sizeof(m)) == 0);
		return;
	}
	prc = any_msg_pack(desc->id, &m, y, &ydlc);
	FUZZ_REQUIRE((prc == SQ_OK) || (prc == SQ_ERANGE));
	FUZZ_REQUIRE((prc == SQ_OK) == frame_in_range(desc, full));
	if (prc != SQ_OK) {
		return;
	}
	FUZZ_REQUIRE(ydlc == desc->dlc);
	same_signals(desc, full, y);
	memset(&m2, 0, sizeof(m2));
	FUZZ_REQUIRE(any_msg_unpack(desc->id, y, ydlc, &m2) == SQ_OK);
	FUZZ_REQUIRE(any_msg_pack(desc->id, &m2, z, &zdlc) == SQ_OK);
	FUZZ_REQUIRE((zdlc == ydlc) && (memcmp(y, z, sizeof(y)) == 0));
}

/* ---- receivers ---------------------------------------------------------- */
typedef struct {
	e2e_p01_rx_t rx[MSG_COUNT];
	ref_rx_t ref[MSG_COUNT];
	e2e_p01_rx_t in_rx[2]; /* msg_disc_speed_receive / msg_pad_force_receive */
	e2e_p01_tx_t tx[MSG_COUNT];
} state_t;

static void check_rx_fields(const e2e_p01_rx_t *rx)
{
	FUZZ_REQUIRE(rx->last_valid_counter <= E2E_P01_COUNTER_MAX);
	FUZZ_REQUIRE(rx->max_delta_counter <= E2E_P01_COUNTER_MAX);
	FUZZ_REQUIRE(rx->lost_data < E2E_P01_COUNTER_MAX);
	FUZZ_REQUIRE((uint32_t)rx->status < (uint32_t)E2E_P01_STATUS_COUNT);
}

static void check_e2e(state_t *s, uint32_t k, const e2e_p01_config_t *cfg,
		      const uint8_t *d, uint8_t dlc)
{
	e2e_p01_rx_t before = s->rx[k];
	const e2e_p01_status_t st = e2e_p01_check(cfg, &s->rx[k], d, dlc);

	FUZZ_REQUIRE((uint32_t)st < (uint32_t)E2E_P01_STATUS_COUNT);
	FUZZ_REQUIRE(cfg_valid(cfg));
	FUZZ_REQUIRE(st == ref_check(cfg, &s->ref[k], d, dlc));
	FUZZ_REQUIRE(s->rx[k].status == st);
	FUZZ_REQUIRE(s->rx[k].status_count[st] >= before.status_count[st]);
	if (e2e_p01_status_usable(st)) {
		FUZZ_REQUIRE(d != NULL);
		FUZZ_REQUIRE(d[0] == fuzz_ref_e2e_crc(cfg->data_id, d, dlc));
		FUZZ_REQUIRE(s->rx[k].last_valid_counter == (d[1] & 0x0FU));
	}
	if (st == E2E_P01_STATUS_OKSOMELOST) {
		FUZZ_REQUIRE(s->rx[k].lost_data >= 1U);
	}
	check_rx_fields(&s->rx[k]);
}

static void check_receive(state_t *s, const msg_desc_t *desc,
			  const e2e_p01_config_t *cfg, const uint8_t *d, uint8_t dlc)
{
	any_msg_t m;
	any_msg_t sentinel;
	int rc;
	e2e_p01_rx_t *rx;

	memset(&sentinel, 0x29, sizeof(sentinel));
	m = sentinel;
	if (desc->id == MSG_DISC_SPEED_ID) {
		rx = &s->in_rx[0];
		rc = msg_disc_speed_receive(cfg, rx, d, dlc, &m.ds);
	} else if (desc->id == MSG_PAD_FORCE_ID) {
		rx = &s->in_rx[1];
		rc = msg_pad_force_receive(cfg, rx, d, dlc, &m.pf);
	} else {
		return;
	}
	FUZZ_REQUIRE((rc == SQ_OK) || (rc == SQ_EAGAIN) || (rc == SQ_EBADMSG));
	if (rc == SQ_OK) {
		FUZZ_REQUIRE(e2e_p01_status_usable(rx->status));
		FUZZ_REQUIRE(memcmp(&m, &sentinel, sizeof(m)) != 0);
	} else {
		FUZZ_REQUIRE(memcmp(&m, &sentinel, sizeof(m)) == 0);
		FUZZ_REQUIRE(!e2e_p01_status_usable(rx->status) || (rc == SQ_EBADMSG));
	}
	if (rc == SQ_EAGAIN) {
		FUZZ_REQUIRE(d == NULL);
	}
	check_rx_fields(rx);
}

static void check_protect(state_t *s, uint32_t k, const e2e_p01_config_t *cfg,
			  const uint8_t *full)
{
	uint8_t f[8];
	const uint8_t counter = s->tx[k].counter;
	int rc;

	memcpy(f, full, sizeof(f));
	rc = e2e_p01_protect(cfg, &s->tx[k], f, cfg->data_len);
	FUZZ_REQUIRE(rc == SQ_OK);
	FUZZ_REQUIRE((f[1] & 0x0FU) == counter);
	FUZZ_REQUIRE((f[1] & 0xF0U) == (full[1] & 0xF0U));
	FUZZ_REQUIRE(f[0] == fuzz_ref_e2e_crc(cfg->data_id, f, cfg->data_len));
	FUZZ_REQUIRE(memcmp(&f[2], &full[2], 6U) == 0);
	FUZZ_REQUIRE(s->tx[k].counter == (uint8_t)((counter + 1U) % 15U));
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	fuzz_in_t in = { data, size };
	state_t s;
	uint8_t max_delta;
	uint32_t k;
	uint32_t rec;

	for (k = 0U; k < MSG_COUNT; k++) {
		e2e_p01_rx_init(&s.rx[k]);
		ref_init(&s.ref[k]);
		e2e_p01_tx_init(&s.tx[k]);
	}
	e2e_p01_rx_init(&s.in_rx[0]);
	e2e_p01_rx_init(&s.in_rx[1]);
	/* valid configurations only: an invalid one is a programming error
	 * (the contract handler; tests/firmware/protocol/test_squeal_msgs.c checks that) */
	max_delta = (uint8_t)(1U + (fuzz_u8(&in) % 14U));

	for (rec = 0U; (rec < 256U) && (in.left > 0U); rec++) {
		const uint8_t mode = fuzz_u8(&in);
		const msg_desc_t *desc;
		e2e_p01_config_t cfg;
		uint8_t full[8];
		uint8_t dlc;
		uint8_t *buf;
		size_t n;

		k = (uint32_t)(mode & 0x07U) % MSG_COUNT;
		desc = &msg_table[k];
		dlc = fuzz_u8(&in);
		fuzz_bytes(&in, full, sizeof(full));
		if ((mode & 0x20U) != 0U) {
			dlc = desc->dlc;
		}
		if (((mode & 0x10U) != 0U) && (dlc == desc->dlc)) {
			full[0] = fuzz_ref_e2e_crc(desc->data_id, full, dlc);
		}
		cfg.data_id = desc->data_id;
		cfg.data_len = desc->dlc;
		cfg.max_delta_counter = max_delta;

		/* exactly the bytes that arrived */
		n = (dlc < 8U) ? dlc : 8U;
		buf = malloc(n);
		if (buf == NULL) {
			return 0;
		}
		memcpy(buf, full, n);

		if ((mode & 0x08U) != 0U) {
			check_e2e(&s, k, &cfg, NULL, dlc);
			check_receive(&s, desc, &cfg, NULL, dlc);
		} else {
			uint32_t j;

			/* every decoder sees every frame (wrong DLCs too) */
			for (j = 0U; j < MSG_COUNT; j++) {
				check_unpack_roundtrip(&msg_table[j], buf, dlc, full);
			}
			check_e2e(&s, k, &cfg, buf, dlc);
			check_receive(&s, desc, &cfg, buf, dlc);
		}
		check_protect(&s, k, &cfg, full);
		free(buf);
	}
	return 0;
}
