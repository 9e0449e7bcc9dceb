/* SPDX-License-Identifier: MIT */
/*
 * Calibration write protection (docs/reliability.md): there is no
 * calibration write path over CAN. This test runs the whole firmware
 * (squeal_app: scheduler + monitor) on the test HAL with a stored,
 * non-default calibration, floods it with random and spoofed frames, and
 * asserts after every batch that
 *   - the bytes in calibration storage are unchanged,
 *   - hal_calib_write() was never called (the link wraps it and counts),
 *   - the monitor's calibration and model parameters are unchanged,
 *   - a restart (squeal_app_init) loads the same calibration again.
 * Frames tried:
 *   - every standard identifier 0..0x7FF with every DLC 0..8, as data and
 *     as remote frames, and extended frames whose low 11 bits are each
 *     identifier, random payloads;
 *   - our own input identifiers and our four output identifiers with a
 *     VALID E2E protection (every data ID of the DBC, every DLC 2..8, all
 *     counters): a spoofing node that knows the protocol;
 *   - diagnostic-style requests (UDS session control, security access with
 *     random keys, WriteDataByIdentifier, RequestDownload/TransferData,
 *     WriteMemoryByAddress, ECU reset) on 0x7DF and 0x7E0..0x7E7, single
 *     and ISO-TP multi-frame, carrying a complete valid calibration block
 *     with other values;
 *   - that same block as raw 8-byte chunks on every identifier.
 * The filter of the test HAL is off: the firmware itself sees every frame.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "calib.h"
#include "e2e_p01.h"
#include "hal.h"
#include "squeal_app.h"
#include "squeal_msgs.h"
#include "test_hal.h"

/* ---- count every hal_calib_write (linked with --wrap=hal_calib_write) ---- */
int __real_hal_calib_write(const uint8_t *buf, uint32_t len);
int __wrap_hal_calib_write(const uint8_t *buf, uint32_t len);
static uint32_t calib_write_calls;

int __wrap_hal_calib_write(const uint8_t *buf, uint32_t len)
{
	calib_write_calls++;
	return __real_hal_calib_write(buf, len);
}

/* ---- fixture -------------------------------------------------------------- */
static calib_t cal_stored;
static uint8_t block_stored[CALIB_BLOCK_LEN];
static uint64_t frames_sent;
static uint64_t rng_state = 0x9E3779B97F4A7C15ULL;

static uint32_t rnd(void)
{
	/* xorshift64*: reproducible, the seed is fixed */
	rng_state ^= rng_state >> 12;
	rng_state ^= rng_state << 25;
	rng_state ^= rng_state >> 27;
	return (uint32_t)((rng_state * 0x2545F4914F6CDD1DULL) >> 32);
}

/* A valid calibration that differs from the defaults in many fields. */
static void make_calibration(calib_t *cal)
{
	calib_default(cal);
	cal->criterion = (uint8_t)SQUEAL_CRITERION_CUBIC;
	cal->damping_q30 = 32212255;   /* 0.03 */
	cal->e2e_max_delta_counter = 3U;
	cal->stale_cycles = 5U;
	cal->debounce_count = 4U;
	cal->lowpass_alpha_q15 = 16384U;
	cal->rho_warn_ppm = 400000U;
	cal->hyst_lnq_micro = 30000U;
	cal->watchdog_ms = 200U;
}

static int setup(void **state)
{
	(void)state;
	test_hal_reset();
	make_calibration(&cal_stored);
	assert_int_equal(calib_encode(&cal_stored, block_stored, sizeof(block_stored)), SQ_OK);
	test_hal_calib_store(block_stored, sizeof(block_stored));
	test_hal_set_time_us(1000000U);
	calib_write_calls = 0U;
	assert_int_equal(squeal_app_init(), SQ_OK);
	return 0;
}

static void assert_calibration_unchanged(void)
{
	uint8_t now[HAL_CALIB_MAX_LEN];
	const monitor_t *me = squeal_app_monitor();
	uint8_t enc[CALIB_BLOCK_LEN];
	squeal_params_t p;

	assert_int_equal(test_hal_calib_stored(now, sizeof(now)), CALIB_BLOCK_LEN);
	assert_memory_equal(now, block_stored, CALIB_BLOCK_LEN);
	assert_int_equal(calib_write_calls, 0U);
	/* field by field through the encoder (calib_t has padding bytes,
	 * which a struct copy need not preserve) */
	assert_int_equal(calib_encode(me->cal, enc, sizeof(enc)), SQ_OK);
	assert_memory_equal(enc, block_stored, CALIB_BLOCK_LEN);
	calib_model_params(&cal_stored, &p);
	assert_memory_equal(&me->params, &p, sizeof(p));
	assert_false(me->calib_invalid);
}

/* Run the firmware until every queued frame was delivered. */
static void drain(void)
{
	uint32_t guard;

	for (guard = 0U; (test_hal_rx_pending() > 0U) && (guard < 1000000U); guard++) {
		hal_idle_until(squeal_app_poll());
	}
	assert_int_equal(test_hal_rx_pending(), 0U);
	test_hal_tx_clear();
}

static void send(const hal_can_frame_t *f_in)
{
	hal_can_frame_t f = *f_in;

	/* 20 us apart: a busy 500 kbit/s bus */
	f.timestamp_us = hal_time_us() + 20U * (test_hal_rx_pending() + 1U);
	if (test_hal_rx_pending() >= TEST_HAL_RX_CAP - 1U) {
		drain();
		assert_calibration_unchanged();
		f.timestamp_us = hal_time_us() + 20U;
	}
	assert_int_equal(test_hal_rx_push(&f), SQ_OK);
	frames_sent++;
}

static void random_payload(hal_can_frame_t *f)
{
	uint32_t i;

	for (i = 0U; i < 8U; i++) {
		f->data[i] = (uint8_t)rnd();
	}
}

/* ---- tests ---------------------------------------------------------------- */

static void test_every_identifier_dlc_and_kind(void **state)
{
	const monitor_t *me;
	uint64_t before;
	uint32_t id;
	uint8_t dlc;
	uint32_t kind;

	(void)state;
	before = frames_sent;
	for (id = 0U; id <= 0x7FFU; id++) {
		for (dlc = 0U; dlc <= 8U; dlc++) {
			for (kind = 0U; kind < 3U; kind++) {
				hal_can_frame_t f;

				memset(&f, 0, sizeof(f));
				f.dlc = dlc;
				random_payload(&f);
				if (kind == 0U) {
					f.id = id;                 /* data frame */
				} else if (kind == 1U) {
					f.id = id;                 /* remote frame */
					f.flags = HAL_CAN_FLAG_RTR;
				} else {
					/* extended frame whose low bits are id */
					f.id = ((rnd() & 0x3FFFFU) << 11) | id;
					f.flags = HAL_CAN_FLAG_EXT;
				}
				send(&f);
			}
		}
	}
	drain();
	assert_calibration_unchanged();
	/* every frame reached the monitor and was accounted for */
	me = squeal_app_monitor();
	assert_int_equal((uint64_t)me->count.unknown_id + me->count.rtr_or_ext +
			 me->speed.count.frames + me->force.count.frames,
			 frames_sent - before);
	assert_int_equal(me->count.rtr_or_ext, 2U * 9U); /* RTR on our 2 IDs */
	assert_int_equal(me->speed.count.frames, 9U);    /* data frames, DLC 0..8 */
}

/* A frame with a valid E2E P01 protection for data_id, length dlc. */
static void send_protected(uint32_t id, uint16_t data_id, uint8_t dlc, uint8_t counter)
{
	hal_can_frame_t f;
	const e2e_p01_config_t cfg = { data_id, dlc, 1U };
	e2e_p01_tx_t tx = { counter };

	memset(&f, 0, sizeof(f));
	f.id = id;
	f.dlc = dlc;
	random_payload(&f);
	assert_int_equal(e2e_p01_protect(&cfg, &tx, f.data, dlc), SQ_OK);
	send(&f);
}

static void test_spoofed_frames_with_valid_e2e(void **state)
{
	const uint32_t ids[6] = { MSG_DISC_SPEED_ID, MSG_PAD_FORCE_ID, MSG_SQUEAL_STATUS_ID,
				  MSG_SQUEAL_DETAIL_ID, MSG_SQUEAL_DIAG_ID, MSG_SQUEAL_DETAIL2_ID };
	uint32_t i;
	uint32_t j;
	uint8_t dlc;
	uint8_t counter;
	uint32_t rep;

	(void)state;
	/* every identifier x every data ID x every DLC x every counter */
	for (i = 0U; i < 6U; i++) {
		for (j = 0U; j < MSG_COUNT; j++) {
			for (dlc = 2U; dlc <= 8U; dlc++) {
				for (counter = 0U; counter <= E2E_P01_COUNTER_MAX; counter++) {
					send_protected(ids[i], msg_table[j].data_id, dlc, counter);
				}
			}
		}
	}
	/* a long valid sequence on the inputs with random values (the input
	 * path accepts these: they reach conditioning and classification) */
	for (rep = 0U; rep < 20000U; rep++) {
		const uint32_t k = rep & 1U;

		send_protected(ids[k], msg_table[k].data_id, 4U,
			       (uint8_t)((rep / 2U) % (E2E_P01_COUNTER_MAX + 1U)));
	}
	drain();
	assert_calibration_unchanged();
}

/* One ISO-TP transfer of payload (single frame or first + consecutive). */
static void send_isotp(uint32_t id, const uint8_t *payload, uint32_t len)
{
	hal_can_frame_t f;
	uint32_t pos;
	uint8_t sn = 1U;

	memset(&f, 0, sizeof(f));
	f.id = id;
	f.dlc = 8U;
	if (len <= 7U) {
		f.data[0] = (uint8_t)len;
		memcpy(&f.data[1], payload, len);
		send(&f);
		return;
	}
	f.data[0] = (uint8_t)(0x10U | ((len >> 8) & 0x0FU));
	f.data[1] = (uint8_t)len;
	memcpy(&f.data[2], payload, 6U);
	send(&f);
	for (pos = 6U; pos < len; pos += 7U) {
		const uint32_t n = (len - pos < 7U) ? (len - pos) : 7U;

		memset(f.data, 0, sizeof(f.data));
		f.data[0] = (uint8_t)(0x20U | (sn & 0x0FU));
		memcpy(&f.data[1], &payload[pos], n);
		send(&f);
		sn++;
	}
}

static void test_diagnostic_requests_and_raw_blocks(void **state)
{
	calib_t other;
	uint8_t blk[CALIB_BLOCK_LEN];
	uint8_t req[4U + CALIB_BLOCK_LEN];
	uint32_t id;
	uint32_t k;
	uint32_t pos;

	(void)state;
	calib_default(&other);
	other.disc_speed_id = 0x120U;  /* what an attacker would want */
	other.e2e_check_inputs = 0U;
	other.speed_max_raw = 65534U;
	assert_int_equal(calib_encode(&other, blk, sizeof(blk)), SQ_OK);

	for (id = 0x7DFU; id <= 0x7E7U; id++) {
		static const uint8_t session[][2] = { { 0x10, 0x01 }, { 0x10, 0x02 },
						      { 0x10, 0x03 }, { 0x10, 0x60 } };
		static const uint8_t reset[2] = { 0x11, 0x01 };
		static const uint8_t dids[][2] = { { 0xF1, 0x90 }, { 0xF1, 0x8C },
						   { 0x01, 0x00 }, { 0xCA, 0x1B } };

		for (k = 0U; k < 4U; k++) {
			send_isotp(id, session[k], 2U);
		}
		/* security access: request seed, then 64 random keys */
		for (k = 0U; k < 64U; k++) {
			uint8_t sa[6] = { 0x27, 0x01, 0, 0, 0, 0 };

			send_isotp(id, sa, 2U);
			sa[1] = 0x02U;
			sa[2] = (uint8_t)rnd();
			sa[3] = (uint8_t)rnd();
			sa[4] = (uint8_t)rnd();
			sa[5] = (uint8_t)rnd();
			send_isotp(id, sa, 6U);
		}
		/* WriteDataByIdentifier with the whole block */
		for (k = 0U; k < 4U; k++) {
			req[0] = 0x2EU;
			req[1] = dids[k][0];
			req[2] = dids[k][1];
			memcpy(&req[3], blk, sizeof(blk));
			send_isotp(id, req, 3U + sizeof(blk));
		}
		/* WriteMemoryByAddress at the calibration sector */
		req[0] = 0x3DU;
		req[1] = 0x44U;
		req[2] = 0x08U;
		req[3] = 0x00U;
		memcpy(&req[4], blk, sizeof(blk) - 4U);
		send_isotp(id, req, sizeof(req) - 4U);
		/* RequestDownload + TransferData + RequestTransferExit */
		{
			const uint8_t dl[] = { 0x34, 0x00, 0x44, 0x08, 0x00, 0x40, 0x00,
					       0x00, 0x00, 0x00, 0x67 };

			send_isotp(id, dl, sizeof(dl));
		}
		req[0] = 0x36U;
		req[1] = 0x01U;
		memcpy(&req[2], blk, sizeof(blk));
		send_isotp(id, req, 2U + sizeof(blk));
		req[0] = 0x37U;
		send_isotp(id, req, 1U);
		send_isotp(id, reset, 2U);
	}
	/* the block as raw chunks on every identifier */
	for (id = 0U; id <= 0x7FFU; id++) {
		for (pos = 0U; pos < sizeof(blk); pos += 8U) {
			hal_can_frame_t f;
			const uint32_t n = (sizeof(blk) - pos < 8U) ? (uint32_t)(sizeof(blk) - pos) : 8U;

			memset(&f, 0, sizeof(f));
			f.id = id;
			f.dlc = (uint8_t)n;
			memcpy(f.data, &blk[pos], n);
			send(&f);
		}
	}
	drain();
	assert_calibration_unchanged();
}

static void test_restart_loads_the_same_calibration(void **state)
{
	uint32_t id;

	(void)state;
	/* some traffic, then a "reset": init again from storage */
	for (id = 0U; id < 0x800U; id += 7U) {
		hal_can_frame_t f;

		memset(&f, 0, sizeof(f));
		f.id = id;
		f.dlc = 8U;
		random_payload(&f);
		send(&f);
	}
	drain();
	assert_int_equal(squeal_app_init(), SQ_OK);
	assert_calibration_unchanged();
	(void)printf("frames sent in all tests: %llu, hal_calib_write calls: %u\n",
		     (unsigned long long)frames_sent, calib_write_calls);
}

/* Test the test: a write through the HAL does change storage and is seen. */
static void test_the_check_sees_a_write(void **state)
{
	uint8_t blk[CALIB_BLOCK_LEN];
	uint8_t now[HAL_CALIB_MAX_LEN];

	(void)state;
	memcpy(blk, block_stored, sizeof(blk));
	blk[20] ^= 1U;
	assert_int_equal(hal_calib_write(blk, sizeof(blk)), SQ_OK);
	assert_int_equal(calib_write_calls, 1U);
	assert_int_equal(test_hal_calib_stored(now, sizeof(now)), CALIB_BLOCK_LEN);
	assert_memory_not_equal(now, block_stored, CALIB_BLOCK_LEN);
}

SQ_CMOCKA_MAIN(
	cmocka_unit_test_setup(test_every_identifier_dlc_and_kind, setup),
	cmocka_unit_test_setup(test_spoofed_frames_with_valid_e2e, setup),
	cmocka_unit_test_setup(test_diagnostic_requests_and_raw_blocks, setup),
	cmocka_unit_test_setup(test_restart_loads_the_same_calibration, setup),
	cmocka_unit_test_setup(test_the_check_sees_a_write, setup))
