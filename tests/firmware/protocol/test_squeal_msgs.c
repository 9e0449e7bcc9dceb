/* SPDX-License-Identifier: MIT */
/*
 * Unit tests of firmware/protocol/squeal_msgs.c: pack/unpack of every
 * message in squeal.dbc, and receive (E2E P01 check, then unpack). The CRC
 * and E2E P01 themselves: test_crc8_p01.c, test_e2e_p01.c.
 *
 * Expected bytes are literals derived outside the code under test: the CRCs
 * were computed by an independent bitwise CRC in Python (poly 0x1D, start 0,
 * no final XOR, over data ID low, data ID high, bytes 1..n-1), the layouts
 * by packing the raw values into a little-endian integer in Python. The
 * DBC <-> C agreement itself is proven by check_squeal_msgs_dbc.py.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "any_msg.h"
#include "e2e_p01.h"
#include "p01_frames.h"
#include "sq_status.h"
#include "squeal_msgs.h"

/* ---- receive ------------------------------------------------------------- */

static void test_receive_writes_msg_only_for_usable_frames(void **state)
{
	e2e_p01_rx_t rx;
	msg_disc_speed_t m = { 0xEE, 0xEE, 0xEEEE };
	uint8_t f[4];

	(void)state;
	e2e_p01_rx_init(&rx);
	ds_frame(0, f);
	f[2] ^= 1U;
	assert_int_equal(msg_disc_speed_receive(&cfg_ds, &rx, f, 4, &m), SQ_EBADMSG);
	assert_int_equal(rx.status, E2E_P01_STATUS_WRONGCRC);
	assert_int_equal(m.disc_speed_radps, 0xEEEE);
	assert_int_equal(msg_disc_speed_receive(&cfg_ds, &rx, NULL, 0, &m), SQ_EAGAIN);
	assert_int_equal(m.disc_speed_radps, 0xEEEE);
	ds_frame(0, f);
	assert_int_equal(msg_disc_speed_receive(&cfg_ds, &rx, f, 4, &m), SQ_OK);
	assert_int_equal(m.disc_speed_radps, 12345);
	assert_int_equal(m.counter, 0);
	m.disc_speed_radps = 0xEEEE;
	assert_int_equal(msg_disc_speed_receive(&cfg_ds, &rx, f, 4, &m), SQ_EBADMSG);
	assert_int_equal(rx.status, E2E_P01_STATUS_REPEATED);
	assert_int_equal(m.disc_speed_radps, 0xEEEE);
	expect_assert_failure(msg_disc_speed_receive(&cfg_ds, &rx, f, 4, NULL));

	/* PadForce: the hand-derived frame from above */
	{
		static const uint8_t pf[4] = { 0x37, 0x0E, 0x50, 0x46 };
		msg_pad_force_t p = { 0, 0, 0 };

		e2e_p01_rx_init(&rx);
		assert_int_equal(msg_pad_force_receive(&cfg_pf, &rx, pf, 4, &p), SQ_OK);
		assert_int_equal(p.pad_force_n, 18000);
		assert_int_equal(p.counter, 14);
		assert_int_equal(msg_pad_force_receive(&cfg_pf, &rx, pf, 3, &p), SQ_EBADMSG);
	}
}

/* ---- layout: hand-derived frames ----------------------------------------- */

static void test_layout_squeal_detail(void **state)
{
	/* 12.34 m/s, 1.23 m/s, 0.50 m/s, 11.1 km/h, counter 3, crc field 0xAB */
	static const uint8_t expect[8] = { 0xAB, 0x23, 0x4D, 0xEC, 0x01, 0x32, 0xF0, 0x06 };
	msg_squeal_detail_t m = { 0xAB, 3, 1234, 123, 50, 111 };
	msg_squeal_detail_t u;
	uint8_t d[8];
	uint8_t dlc = 0;

	(void)state;
	assert_int_equal(msg_squeal_detail_pack(&m, d, &dlc), SQ_OK);
	assert_int_equal(dlc, 8);
	assert_memory_equal(d, expect, 8);
	assert_int_equal(msg_squeal_detail_unpack(expect, 8, &u), SQ_OK);
	assert_int_equal(u.crc, 0xAB);
	assert_int_equal(u.counter, 3);
	assert_int_equal(u.v0_mps, 1234);
	assert_int_equal(u.hopf_speed_mps, 123);
	assert_int_equal(u.trigger_velocity_mps, 50);
	assert_int_equal(u.vehicle_speed_border_kph, 111);
}

static void test_layout_squeal_detail2(void **state)
{
	static const uint8_t expect[8] = { 0x5A, 0x05, 0x50, 0x46, 0xE0, 0x2E, 0xD2, 0x04 };
	msg_squeal_detail2_t m = { 0x5A, 5, 18000, 12000, 1234 };
	msg_squeal_detail2_t u;
	uint8_t d[8];
	uint8_t dlc = 0;

	(void)state;
	assert_int_equal(msg_squeal_detail2_pack(&m, d, &dlc), SQ_OK);
	assert_memory_equal(d, expect, 8);
	assert_int_equal(msg_squeal_detail2_unpack(expect, 8, &u), SQ_OK);
	assert_int_equal(u.force_n, 18000);
	assert_int_equal(u.hopf_force_n, 12000);
	assert_int_equal(u.lc_amplitude_um, 1234);
}

static void test_layout_squeal_status_extremes(void **state)
{
	/* fault, warning none, basin 1.0, margin +327.67, counter 1 */
	static const uint8_t expect[8] = { 0x00, 0xF1, 0x00, 0x10, 0x27, 0xFF, 0x7F, 0x00 };
	msg_squeal_status_t m = { 0, 1, MSG_SQUEAL_STATE_FAULT, 0, 10000, 32767, 0 };
	uint8_t d[8];
	uint8_t dlc = 0;

	(void)state;
	assert_int_equal(msg_squeal_status_pack(&m, d, &dlc), SQ_OK);
	assert_memory_equal(d, expect, 8);
}

/* BorderMargin_sigma: bits 56..63, Intel = byte 7 whole; raw
 * 21 = 2.0 sigma (x 0.1 - 0.1) */
static void test_layout_squeal_status_border_margin(void **state)
{
	/* counter 1 | stable 0 << 4 = 0x01; basin NA FF FF; margin NA 00 80 */
	static const uint8_t expect[8] = { 0x00, 0x01, 0x00, 0xFF, 0xFF, 0x00, 0x80, 0x15 };
	msg_squeal_status_t m = { 0, 1, MSG_SQUEAL_STATE_STABLE, 0, 0xFFFFU, -32768, 21 };
	msg_squeal_status_t u;
	uint8_t d[8];
	uint8_t dlc = 0;

	(void)state;
	assert_int_equal(msg_squeal_status_pack(&m, d, &dlc), SQ_OK);
	assert_memory_equal(d, expect, 8);
	assert_int_equal(msg_squeal_status_unpack(expect, 8, &u), SQ_OK);
	assert_int_equal(u.border_margin_sigma, 21);
}

static void test_layout_squeal_diag_every_page(void **state)
{
	/* page 4 by hand: counter 13 | page 4 << 4 = 0x4D; Fault_SelfTest =
	 * bit 27 = byte 3 bit 3; HseFreq 80 (8.0 MHz) = byte 4; ResetCause 4 |
	 * BorLevel 3 << 3 | LoopbackCan1 0 << 6 = 0x1C; LoopbackCan2 2 |
	 * (StackHighWater 480 & 0x3F) << 2 = 0x82, 480 >> 6 = 0x07 */
	static const uint8_t expect[5][8] = {
		{ 0x11, 0x09, 0x21, 0x04, 0x56, 0x34, 0x12, 0x07 },
		{ 0x22, 0x1A, 0xFF, 0x0F, 0x45, 0x03, 0xEF, 0xBE },
		{ 0x33, 0x2B, 0x02, 0x00, 0x01, 0x00, 0xFF, 0xFF },
		{ 0x44, 0x3C, 0x00, 0x04, 0x2C, 0x01, 0x02, 0x00 },
		{ 0x55, 0x4D, 0x00, 0x08, 0x50, 0x1C, 0x82, 0x07 },
	};
	msg_squeal_diag_t m[5];
	uint8_t d[8];
	uint8_t dlc = 0;

	(void)state;
	memset(m, 0, sizeof(m));
	/* every counter filled on every page: pack must send only the page's */
	for (int p = 0; p < 5; p++) {
		m[p].hse_freq_100khz = 80;
		m[p].reset_cause = 4;
		m[p].bor_level = 3;
		m[p].loopback_can1 = 0;
		m[p].loopback_can2 = 2;
		m[p].stack_high_water_b = 480;
		m[p].uptime_s = 0x123456;
		m[p].bus_off_count = 7;
		m[p].worst_task_time_us = 0x0345;
		m[p].rx_overrun_count = 0xBEEF;
		m[p].e2e_error_count_speed = 1;
		m[p].e2e_error_count_force = 65535;
		m[p].tx_overflow_count = 300;
		m[p].rx_bad_frame_count = 2;
		m[p].page = (uint8_t)p;
	}
	m[0].crc = 0x11; m[0].counter = 9;  m[0].fault_bits = 0x421;
	m[1].crc = 0x22; m[1].counter = 10; m[1].fault_bits = MSG_FAULT_ALL;
	m[2].crc = 0x33; m[2].counter = 11; m[2].fault_bits = MSG_FAULT_FORCE_STALE;
	m[3].crc = 0x44; m[3].counter = 12; m[3].fault_bits = MSG_FAULT_TX_OVERFLOW;
	m[4].crc = 0x55; m[4].counter = 13; m[4].fault_bits = MSG_FAULT_SELF_TEST;
	for (int p = 0; p < 5; p++) {
		msg_squeal_diag_t u;

		assert_int_equal(msg_squeal_diag_pack(&m[p], d, &dlc), SQ_OK);
		assert_int_equal(dlc, 8);
		assert_memory_equal(d, expect[p], 8);
		memset(&u, 0xA5, sizeof(u));
		assert_int_equal(msg_squeal_diag_unpack(expect[p], 8, &u), SQ_OK);
		assert_int_equal(u.page, p);
		assert_int_equal(u.fault_bits, m[p].fault_bits);
		assert_int_equal(u.crc, m[p].crc);
		assert_int_equal(u.counter, m[p].counter);
		/* fields of the page decoded, all others 0 */
		assert_int_equal(u.uptime_s, p == 0 ? 0x123456U : 0U);
		assert_int_equal(u.bus_off_count, p == 0 ? 7 : 0);
		assert_int_equal(u.worst_task_time_us, p == 1 ? 0x0345 : 0);
		assert_int_equal(u.rx_overrun_count, p == 1 ? 0xBEEF : 0);
		assert_int_equal(u.e2e_error_count_speed, p == 2 ? 1 : 0);
		assert_int_equal(u.e2e_error_count_force, p == 2 ? 65535 : 0);
		assert_int_equal(u.tx_overflow_count, p == 3 ? 300 : 0);
		assert_int_equal(u.rx_bad_frame_count, p == 3 ? 2 : 0);
		assert_int_equal(u.hse_freq_100khz, p == 4 ? 80 : 0);
		assert_int_equal(u.reset_cause, p == 4 ? 4 : 0);
		assert_int_equal(u.bor_level, p == 4 ? 3 : 0);
		assert_int_equal(u.loopback_can2, p == 4 ? 2 : 0);
		assert_int_equal(u.stack_high_water_b, p == 4 ? 480 : 0);
	}
}

/* ---- round trips at the limits ------------------------------------------- */

static void test_roundtrip_disc_speed_and_pad_force_limits(void **state)
{
	static const uint16_t vals[] = { 0, 1, MSG_DISC_SPEED_RADPS_MAX, MSG_DISC_SPEED_RADPS_NA };
	uint8_t d[8];
	uint8_t dlc;

	(void)state;
	for (size_t i = 0; i < sizeof(vals) / sizeof(vals[0]); i++) {
		for (uint8_t c = 0; c <= 14U; c = (uint8_t)(c + 14U)) {
			msg_disc_speed_t m = { (uint8_t)(0xFFU - c), c, vals[i] };
			msg_disc_speed_t u;
			msg_pad_force_t p = { c, c, vals[i] };
			msg_pad_force_t pu;

			assert_int_equal(msg_disc_speed_pack(&m, d, &dlc), SQ_OK);
			assert_int_equal(dlc, MSG_DISC_SPEED_DLC);
			for (size_t k = dlc; k < 8U; k++) {
				assert_int_equal(d[k], 0); /* beyond the DLC */
			}
			assert_int_equal(msg_disc_speed_unpack(d, dlc, &u), SQ_OK);
			assert_int_equal(u.crc, m.crc);
			assert_int_equal(u.counter, m.counter);
			assert_int_equal(u.disc_speed_radps, m.disc_speed_radps);
			assert_int_equal(msg_pad_force_pack(&p, d, &dlc), SQ_OK);
			assert_int_equal(dlc, MSG_PAD_FORCE_DLC);
			assert_int_equal(msg_pad_force_unpack(d, dlc, &pu), SQ_OK);
			assert_int_equal(pu.crc, p.crc);
			assert_int_equal(pu.counter, p.counter);
			assert_int_equal(pu.pad_force_n, p.pad_force_n);
		}
	}
	assert_int_equal(MSG_PAD_FORCE_N_MAX, 65534);
	assert_int_equal(MSG_PAD_FORCE_N_NA, 0xFFFF);
}

static void test_roundtrip_squeal_status_limits(void **state)
{
	static const uint8_t states[] = { 0, 1, 2, 3, 15 };
	static const uint16_t basins[] = { 0, MSG_BASIN_RATIO_MAX, MSG_BASIN_RATIO_NA };
	static const int16_t margins[] = { MSG_HOPF_MARGIN_MPS_MIN, -1, 0, 1,
					   MSG_HOPF_MARGIN_MPS_MAX, MSG_HOPF_MARGIN_MPS_NA };
	uint8_t d[8];
	uint8_t dlc;

	(void)state;
	for (size_t s = 0; s < sizeof(states); s++) {
		for (uint8_t w = 0; w <= 3U; w++) {
			for (size_t b = 0; b < 3U; b++) {
				for (size_t g = 0; g < sizeof(margins) / sizeof(margins[0]); g++) {
					msg_squeal_status_t m = { (uint8_t)(s * 50U), (uint8_t)(w + s),
								  states[s], w, basins[b], margins[g],
								  (uint8_t)(g * 85U) };
					msg_squeal_status_t u;

					assert_int_equal(msg_squeal_status_pack(&m, d, &dlc), SQ_OK);
					assert_int_equal(msg_squeal_status_unpack(d, dlc, &u), SQ_OK);
					assert_int_equal(u.crc, m.crc);
					assert_int_equal(u.counter, m.counter);
					assert_int_equal(u.squeal_state, m.squeal_state);
					assert_int_equal(u.warning_level, m.warning_level);
					assert_int_equal(u.basin_ratio, m.basin_ratio);
					assert_int_equal(u.hopf_margin_mps, m.hopf_margin_mps);
					assert_int_equal(u.border_margin_sigma, m.border_margin_sigma);
				}
			}
		}
	}
}

static void test_roundtrip_squeal_detail_limits(void **state)
{
	static const uint16_t v14[] = { 0, 1, MSG_V0_MPS_MAX, MSG_V0_MPS_NA };
	static const uint16_t v12[] = { 0, 1, MSG_TRIGGER_VELOCITY_MPS_MAX, MSG_TRIGGER_VELOCITY_MPS_NA };
	uint8_t d[8];
	uint8_t dlc;

	(void)state;
	for (size_t a = 0; a < 4U; a++) {
		for (size_t b = 0; b < 4U; b++) {
			/* neighbours get opposite extremes, so a bit leaking across a
			 * field border would show */
			msg_squeal_detail_t m = { 0xFF, 14, v14[a], v14[3U - a], v12[b], v12[3U - b] };
			msg_squeal_detail_t u;

			assert_int_equal(msg_squeal_detail_pack(&m, d, &dlc), SQ_OK);
			assert_int_equal(msg_squeal_detail_unpack(d, dlc, &u), SQ_OK);
			assert_int_equal(u.crc, m.crc);
			assert_int_equal(u.counter, m.counter);
			assert_int_equal(u.v0_mps, m.v0_mps);
			assert_int_equal(u.hopf_speed_mps, m.hopf_speed_mps);
			assert_int_equal(u.trigger_velocity_mps, m.trigger_velocity_mps);
			assert_int_equal(u.vehicle_speed_border_kph, m.vehicle_speed_border_kph);
		}
	}
	assert_int_equal(MSG_HOPF_SPEED_MPS_NA, MSG_V0_MPS_NA);
	assert_int_equal(MSG_VEHICLE_SPEED_BORDER_KPH_NA, 0xFFF);
}

static void test_roundtrip_squeal_detail2_limits(void **state)
{
	static const uint16_t v[] = { 0, 1, 65534, 0xFFFF };
	uint8_t d[8];
	uint8_t dlc;

	(void)state;
	for (size_t a = 0; a < 4U; a++) {
		for (size_t b = 0; b < 4U; b++) {
			msg_squeal_detail2_t m = { (uint8_t)a, (uint8_t)b, v[a], v[b], v[3U - a] };
			msg_squeal_detail2_t u;

			assert_int_equal(msg_squeal_detail2_pack(&m, d, &dlc), SQ_OK);
			assert_int_equal(msg_squeal_detail2_unpack(d, dlc, &u), SQ_OK);
			assert_int_equal(u.crc, m.crc);
			assert_int_equal(u.counter, m.counter);
			assert_int_equal(u.force_n, m.force_n);
			assert_int_equal(u.hopf_force_n, m.hopf_force_n);
			assert_int_equal(u.lc_amplitude_um, m.lc_amplitude_um);
		}
	}
}

static void test_roundtrip_squeal_diag_limits(void **state)
{
	uint8_t d[8];
	uint8_t dlc;

	(void)state;
	for (int ext = 0; ext < 2; ext++) {
		for (uint8_t p = 0; p < MSG_DIAG_PAGE_COUNT; p++) {
			msg_squeal_diag_t m;
			msg_squeal_diag_t u;
			uint16_t v16 = ext != 0 ? 0xFFFFU : 0U;

			memset(&m, 0, sizeof(m));
			m.page = p;
			m.counter = ext != 0 ? 14 : 0;
			m.crc = ext != 0 ? 0xFF : 0;
			m.fault_bits = ext != 0 ? MSG_FAULT_ALL : 0;
			m.uptime_s = ext != 0 ? MSG_UPTIME_S_MAX : 0;
			m.bus_off_count = ext != 0 ? 0xFF : 0;
			m.worst_task_time_us = v16;
			m.rx_overrun_count = v16;
			m.e2e_error_count_speed = v16;
			m.e2e_error_count_force = v16;
			m.tx_overflow_count = v16;
			m.rx_bad_frame_count = v16;
			assert_int_equal(msg_squeal_diag_pack(&m, d, &dlc), SQ_OK);
			assert_int_equal(msg_squeal_diag_unpack(d, dlc, &u), SQ_OK);
			assert_int_equal(u.page, p);
			assert_int_equal(u.crc, m.crc);
			assert_int_equal(u.counter, m.counter);
			assert_int_equal(u.fault_bits, m.fault_bits);
			assert_int_equal(u.uptime_s, p == 0 ? m.uptime_s : 0U);
			assert_int_equal(u.bus_off_count, p == 0 ? m.bus_off_count : 0);
			assert_int_equal(u.worst_task_time_us, p == 1 ? v16 : 0);
			assert_int_equal(u.rx_overrun_count, p == 1 ? v16 : 0);
			assert_int_equal(u.e2e_error_count_speed, p == 2 ? v16 : 0);
			assert_int_equal(u.e2e_error_count_force, p == 2 ? v16 : 0);
			assert_int_equal(u.tx_overflow_count, p == 3 ? v16 : 0);
			assert_int_equal(u.rx_bad_frame_count, p == 3 ? v16 : 0);
		}
	}
	/* each fault bit alone lands on its own signal */
	for (unsigned int i = 0; i < 11U; i++) {
		msg_squeal_diag_t m;
		msg_squeal_diag_t u;

		memset(&m, 0, sizeof(m));
		m.fault_bits = (uint16_t)(1U << i);
		assert_int_equal(msg_squeal_diag_pack(&m, d, &dlc), SQ_OK);
		assert_int_equal(d[(16U + i) / 8U], (uint8_t)(1U << ((16U + i) % 8U)));
		assert_int_equal(msg_squeal_diag_unpack(d, dlc, &u), SQ_OK);
		assert_int_equal(u.fault_bits, m.fault_bits);
	}
}

/* ---- rejection ----------------------------------------------------------- */

static void test_pack_rejects_out_of_range_values(void **state)
{
	uint8_t d[8];
	uint8_t before[8];
	uint8_t dlc = 0x77;

	(void)state;
	memset(d, 0x5C, sizeof(d));
	memcpy(before, d, sizeof(d));
	{
		msg_disc_speed_t m = { 0, 15, 100 };
		assert_int_equal(msg_disc_speed_pack(&m, d, &dlc), SQ_ERANGE);
	}
	{
		msg_squeal_status_t m = { 0, 0, 4, 0, 0, 0, 0 };
		assert_int_equal(msg_squeal_status_pack(&m, d, &dlc), SQ_ERANGE);
		m.squeal_state = 14;
		assert_int_equal(msg_squeal_status_pack(&m, d, &dlc), SQ_ERANGE);
		m.squeal_state = 0;
		m.warning_level = 4;
		assert_int_equal(msg_squeal_status_pack(&m, d, &dlc), SQ_ERANGE);
		m.warning_level = 0;
		m.basin_ratio = MSG_BASIN_RATIO_MAX + 1U;
		assert_int_equal(msg_squeal_status_pack(&m, d, &dlc), SQ_ERANGE);
	}
	{
		msg_squeal_detail_t m = { 0, 0, MSG_V0_MPS_NA + 1U, 0, 0, 0 };
		assert_int_equal(msg_squeal_detail_pack(&m, d, &dlc), SQ_ERANGE);
		m.v0_mps = 0;
		m.vehicle_speed_border_kph = 0x1000;
		assert_int_equal(msg_squeal_detail_pack(&m, d, &dlc), SQ_ERANGE);
	}
	{
		msg_squeal_diag_t m;
		memset(&m, 0, sizeof(m));
		m.page = MSG_DIAG_PAGE_COUNT;
		assert_int_equal(msg_squeal_diag_pack(&m, d, &dlc), SQ_ERANGE);
		m.page = MSG_DIAG_PAGE_UPTIME;
		m.uptime_s = MSG_UPTIME_S_MAX + 1U;
		assert_int_equal(msg_squeal_diag_pack(&m, d, &dlc), SQ_ERANGE);
		m.page = MSG_DIAG_PAGE_TASK; /* uptime not on this page: ignored */
		assert_int_equal(msg_squeal_diag_pack(&m, d, &dlc), SQ_OK);
		memcpy(d, before, sizeof(d));
		dlc = 0x77;
		m.fault_bits = 1U << 12; /* one above Fault_SelfTest */
		assert_int_equal(msg_squeal_diag_pack(&m, d, &dlc), SQ_ERANGE);
		m.fault_bits = 0U;
		m.page = MSG_DIAG_PAGE_SELFTEST; /* page 4: each field in range */
		m.hse_freq_100khz = 255U; /* not available: allowed */
		m.bor_level = 7U;
		m.stack_high_water_b = 16383U;
		assert_int_equal(msg_squeal_diag_pack(&m, d, &dlc), SQ_OK);
		memcpy(d, before, sizeof(d));
		dlc = 0x77;
		m.reset_cause = 7U; /* 0..6 */
		assert_int_equal(msg_squeal_diag_pack(&m, d, &dlc), SQ_ERANGE);
		m.reset_cause = 0U;
		m.bor_level = 4U; /* 0..3 or 7 */
		assert_int_equal(msg_squeal_diag_pack(&m, d, &dlc), SQ_ERANGE);
		m.bor_level = 3U;
		m.stack_high_water_b = 16384U; /* 14 bits */
		assert_int_equal(msg_squeal_diag_pack(&m, d, &dlc), SQ_ERANGE);
	}
	assert_memory_equal(d, before, sizeof(d));
	assert_int_equal(dlc, 0x77);
	expect_assert_failure(msg_disc_speed_pack(NULL, d, &dlc));
	{
		msg_pad_force_t m = { 0, 0, 0 };
		expect_assert_failure(msg_pad_force_pack(&m, NULL, &dlc));
		expect_assert_failure(msg_pad_force_pack(&m, d, NULL));
	}
}

static void test_unpack_rejects_wrong_dlc_for_every_message(void **state)
{
	static const uint8_t zeros[8] = { 0 };
	any_msg_t m;

	(void)state;
	for (uint8_t dlc = 0; dlc <= 8U; dlc++) {
		int want4 = dlc == 4U ? SQ_OK : SQ_EBADMSG;
		int want8 = dlc == 8U ? SQ_OK : SQ_EBADMSG;

		assert_int_equal(msg_disc_speed_unpack(zeros, dlc, &m.ds), want4);
		assert_int_equal(msg_pad_force_unpack(zeros, dlc, &m.pf), want4);
		assert_int_equal(msg_squeal_status_unpack(zeros, dlc, &m.st), want8);
		assert_int_equal(msg_squeal_detail_unpack(zeros, dlc, &m.dt), want8);
		assert_int_equal(msg_squeal_detail2_unpack(zeros, dlc, &m.d2), want8);
		assert_int_equal(msg_squeal_diag_unpack(zeros, dlc, &m.dg), want8);
	}
	assert_int_equal(msg_squeal_status_unpack(zeros, 15, &m.st), SQ_EBADMSG);
	assert_int_equal(msg_squeal_status_unpack(NULL, 8, &m.st), SQ_EBADMSG);
	expect_assert_failure(msg_squeal_status_unpack(zeros, 8, NULL));
	{
		/* diag page 5 does not exist */
		const uint8_t bad_page[8] = { 0, 0x50, 0, 0, 0, 0, 0, 0 };
		memset(&m.dg, 0x5A, sizeof(m.dg));
		assert_int_equal(msg_squeal_diag_unpack(bad_page, 8, &m.dg), SQ_EBADMSG);
		assert_int_equal(m.dg.page, 0x5A); /* untouched */
	}
}

/* ---- descriptor table ---------------------------------------------------- */

static void test_descriptor_table_is_self_consistent(void **state)
{
	(void)state;
	for (size_t i = 0; i < MSG_COUNT; i++) {
		const msg_desc_t *m = &msg_table[i];
		uint8_t used[16][64]; /* per mux page (0 for plain signals) */
		int crc_seen = 0, counter_seen = 0;

		memset(used, 0, sizeof(used));
		assert_ptr_equal(msg_desc_find(m->id), m);
		assert_true(m->id <= 0x7FFU);
		assert_true(m->dlc >= 2U && m->dlc <= 8U);
		for (size_t j = 0; j < m->sig_count; j++) {
			const msg_sig_desc_t *s = &msg_sig_table[m->sig_first + j];

			assert_int_equal(s->msg_id, m->id);
			assert_true(s->length >= 1U && s->length <= 31U);
			assert_true((unsigned int)s->start_bit + s->length <= 8U * m->dlc);
			assert_true(s->factor_den > 0);
			assert_true(s->raw_min <= s->raw_max);
			if ((s->flags & MSG_SIG_HAS_NA) != 0U) {
				assert_true(s->na_raw < s->raw_min || s->na_raw > s->raw_max);
			}
			if ((s->flags & MSG_SIG_E2E) != 0U) {
				if (s->start_bit == 0U) {
					crc_seen = s->length == 8U;
				} else {
					counter_seen = s->start_bit == 8U && s->length == 4U;
				}
			}
			/* no two signals share a bit (on the same page) */
			for (unsigned int b = s->start_bit; b < (unsigned int)s->start_bit + s->length; b++) {
				for (unsigned int p = 0; p < 16U; p++) {
					if ((s->flags & MSG_SIG_MUXED) != 0U && p != s->mux_value) {
						continue;
					}
					assert_int_equal(used[p][b], 0);
					used[p][b] = 1;
				}
			}
		}
		assert_true(crc_seen);
		assert_true(counter_seen);
	}
	assert_int_equal(msg_table[MSG_COUNT - 1U].sig_first + msg_table[MSG_COUNT - 1U].sig_count,
			 MSG_SIG_COUNT);
	assert_null(msg_desc_find(0x7FF));
}

static void test_sig_get_raw_sign_extends_and_respects_mux(void **state)
{
	const msg_sig_desc_t *margin = NULL;
	const msg_sig_desc_t *uptime = NULL;
	const msg_desc_t *st = msg_desc_find(MSG_SQUEAL_STATUS_ID);
	const msg_desc_t *dg = msg_desc_find(MSG_SQUEAL_DIAG_ID);
	static const uint8_t f_st[8] = { 0xC5, 0x27, 0x03, 0xFF, 0xFF, 0x85, 0xFF, 0x00 };
	static const uint8_t f_dg0[8] = { 0x11, 0x09, 0x21, 0x04, 0x56, 0x34, 0x12, 0x07 };
	static const uint8_t f_dg1[8] = { 0x22, 0x1A, 0xFF, 0x07, 0x45, 0x03, 0xEF, 0xBE };
	int32_t raw = 0;

	(void)state;
	assert_non_null(st);
	assert_non_null(dg);
	for (size_t j = 0; j < st->sig_count; j++) {
		if (strcmp(msg_sig_table[st->sig_first + j].name, "HopfMargin_mps") == 0) {
			margin = &msg_sig_table[st->sig_first + j];
		}
	}
	for (size_t j = 0; j < dg->sig_count; j++) {
		if (strcmp(msg_sig_table[dg->sig_first + j].name, "Uptime_s") == 0) {
			uptime = &msg_sig_table[dg->sig_first + j];
		}
	}
	assert_non_null(margin);
	assert_non_null(uptime);
	assert_int_equal(msg_sig_get_raw(margin, f_st, 8, &raw), SQ_OK);
	assert_int_equal(raw, -123);
	assert_int_equal(msg_sig_get_raw(margin, f_st, 7, &raw), SQ_EBADMSG);
	assert_int_equal(msg_sig_get_raw(uptime, f_dg0, 8, &raw), SQ_OK);
	assert_int_equal(raw, 0x123456);
	assert_int_equal(msg_sig_get_raw(uptime, f_dg1, 8, &raw), SQ_ENOENT);
	expect_assert_failure(msg_sig_get_raw(NULL, f_dg1, 8, &raw));
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_receive_writes_msg_only_for_usable_frames),
		cmocka_unit_test(test_layout_squeal_detail),
		cmocka_unit_test(test_layout_squeal_detail2),
		cmocka_unit_test(test_layout_squeal_status_extremes),
		cmocka_unit_test(test_layout_squeal_status_border_margin),
		cmocka_unit_test(test_layout_squeal_diag_every_page),
		cmocka_unit_test(test_roundtrip_disc_speed_and_pad_force_limits),
		cmocka_unit_test(test_roundtrip_squeal_status_limits),
		cmocka_unit_test(test_roundtrip_squeal_detail_limits),
		cmocka_unit_test(test_roundtrip_squeal_detail2_limits),
		cmocka_unit_test(test_roundtrip_squeal_diag_limits),
		cmocka_unit_test(test_pack_rejects_out_of_range_values),
		cmocka_unit_test(test_unpack_rejects_wrong_dlc_for_every_message),
		cmocka_unit_test(test_descriptor_table_is_self_consistent),
		cmocka_unit_test(test_sig_get_raw_sign_extends_and_respects_mux),
	};

	return cmocka_run_group_tests_name("protocol", tests, NULL, NULL);
}
