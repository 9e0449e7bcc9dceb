/* SPDX-License-Identifier: MIT */
/*
 * The input map on the fixture vehicle layouts in tests/firmware/monitor/fixtures/ (.cal)
 * (written for these tests, no vehicle's file), both numeric builds:
 *
 *   A moto15_p02       Motorola 15-bit wheel speeds, 0.01 km/h, offset
 *                      -67.67 km/h, a fault bit each; master-cylinder
 *                      pressure 0.1 bar with E2E P02; four corners
 *   B intel14_counter  Intel 14-bit at 1/32 km/h with a 4-bit alive counter
 *                      (and unused checksum bits) between; per-wheel kPa
 *   D mux_psi          one multiplexed frame: two speeds (1/64 m/s) and a
 *                      pressure in psi on three pages
 *   E ext29_kn         29-bit identifiers; signed Motorola clamp force (kN)
 *                      with E2E P01; vehicle speed 1/256 km/h
 *   F torque_rpm       wheel rpm and brake torque (Nm), 2-bit counters
 *
 * Frames are written byte by byte from the DBC conventions
 * (bit numbering in firmware/protocol/can_signal.h) and the expected raw values and conversions are
 * derived by hand in the comments. Also: bad calibrations are refused whole
 * with FILE:LINE; a short frame is a bad DLC; "not available" and a fault
 * bit raise the input fault. Contracts: NULL pointers and
 * a descriptor the calibration's validation refuses go to hal_contract_failed
 * (expect_assert_failure, tests/support/test_contract.c); frames never do.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "calib_map.h"
#include "calib_text.h"
#include "map_fixture.h"
#include "e2e_p01.h"
#include "input_rx.h"
#include "monitor.h"
#include "sq_status.h"

#ifndef FIXTURE_DIR
#define FIXTURE_DIR "tests/firmware/monitor/fixtures"
#endif

static calib_t cal;
static calib_names_t names;

static void load(const char *file)
{
	map_fixture_load(FIXTURE_DIR, file, &cal, &names);
}

static uint32_t input_named(const char *name)
{
	return map_fixture_input(&cal, &names, name);
}

/* input `name` prepared with the geometry of corner k */
static input_rx_cfg_t prepared(const char *name, uint32_t k)
{
	const calib_corner_t *c = &cal.corners[k];
	const input_geom_t g = { c->pad_radius_um, c->wheel_radius_um, c->piston_area_cmm2,
				 c->efficiency_ppm, c->axle_factor_ppm };
	input_rx_cfg_t cfg;

	assert_int_equal(input_rx_setup(&cal.inputs[input_named(name)], &g, &cfg), SQ_OK);
	return cfg;
}

static hal_can_frame_t frame(uint32_t id, bool ext, uint8_t dlc, const uint8_t *data)
{
	hal_can_frame_t f;

	memset(&f, 0, sizeof(f));
	f.id = id;
	f.flags = ext ? HAL_CAN_FLAG_EXT : 0U;
	f.dlc = dlc;
	memcpy(f.data, data, dlc);
	return f;
}

/* check one input on one frame: reason, raw (sign-extended), converted */
static void expect(const char *name, uint32_t corner, const hal_can_frame_t *f,
		   input_rx_reason_t reason, int64_t value, int32_t converted)
{
	input_rx_cfg_t cfg = prepared(name, corner);
	input_rx_state_t rx;
	bool id_only = false;
	input_rx_result_t r;

	input_rx_state_init(&rx);
	assert_true(input_rx_matches(&cfg, f, &id_only));
	r = input_rx_judge(&cfg, &rx, f);
	assert_int_equal(r.reason, reason);
	if (reason != INPUT_RX_DLC) {
		assert_true(r.value == value);
	}
	if ((reason == INPUT_RX_OK) || (reason == INPUT_RX_RANGE)) {
		/* the conversion of a value the range refuses, too */
		assert_int_equal(input_conv_apply(&cfg.conv, r.value), converted);
	}
}

/* ---- layouts ---------------------------------------------------------------------- */

static void test_a_motorola15_offset_fault_bits(void **state)
{
	/* WS_FL 7|15@0+: byte 0 = raw >> 7, byte 1 bits 7..1 = raw & 0x7F;
	 * raw 16767 = 0x417F: 82 FE. 16767 x 0.01 - 67.67 = 100 km/h;
	 * v0 = 100/3.6 x 0.12/0.3 = 11.111111 m/s. Fault bit 8 = byte 1 bit 0. */
	const uint8_t ok[8] = { 0x82, 0xFE, 0x00, 0x00 };
	const uint8_t fault[8] = { 0x82, 0xFF };
	const uint8_t na[8] = { 0xFF, 0xFE };          /* 0x7FFF: not available */
	/* WS_FR 23|15@0+ in bytes 2-3: raw 6767 = 0x1A6F -> 34 DE = 0 km/h */
	const uint8_t fr[8] = { 0, 0, 0x34, 0xDE };
	/* raw 0: -67.67 km/h, within min -1? no: implausible (range) */
	hal_can_frame_t f;

	(void)state;
	load("moto15_p02.cal");
	assert_int_equal(cal.n_corners, 4);
	f = frame(0x1A0, false, 8, ok);
	expect("WS_FL", 0, &f, INPUT_RX_OK, 16767, 11111111);
	f = frame(0x1A0, false, 8, fault);
	expect("WS_FL", 0, &f, INPUT_RX_QUALIFIER, 16767, 0);
	f = frame(0x1A0, false, 8, na);
	expect("WS_FL", 0, &f, INPUT_RX_NA, 0x7FFF, 0);
	f = frame(0x1A0, false, 8, fr);
	expect("WS_FR", 1, &f, INPUT_RX_OK, 6767, 0);
	/* a frame of one byte cannot hold WS_FL (bytes 0-1): bad DLC */
	f = frame(0x1A0, false, 1, ok);
	expect("WS_FL", 0, &f, INPUT_RX_DLC, 0, 0);
}

static void test_a_master_cylinder_p02_axle(void **state)
{
	/* MC_PRESS 16|12@1+ 0.1 bar: raw 400 = 0x190 -> byte 2 0x90, byte 3 0x01;
	 * counter 5 in byte 1; CRC-8H2F over 05 90 01 00 00 00 00 and
	 * DataIDList[5] = 0x66 is 0x31 (bitwise reference in Python).
	 * FL: 40 bar x 2290 mm^2 = 9160 N; RL: 40e5 x 1257e-6 x 0.6 = 3016.8 N */
	const uint8_t d[8] = { 0x31, 0x05, 0x90, 0x01 };
	uint8_t bad[8];
	hal_can_frame_t f;

	(void)state;
	load("moto15_p02.cal");
	f = frame(0x1B0, false, 8, d);
	expect("MC_PRESS", 0, &f, INPUT_RX_OK, 400, 9160000);
	expect("MC_PRESS", 2, &f, INPUT_RX_OK, 400, 3016800);
	memcpy(bad, d, 8);
	bad[0] = 0x30;
	f = frame(0x1B0, false, 8, bad);
	expect("MC_PRESS", 0, &f, INPUT_RX_CRC, 400, 0);
}

static void test_b_intel14_with_counter_between(void **state)
{
	/* WS_FL 0|14@1+: raw 3200 = 0x0C80 -> byte 0 0x80, byte 1 low 6 bits 0x0C;
	 * WS_FR 14|14@1+: raw 1600: byte 1 bits 6-7 = 1600 & 3 = 0, byte 2 =
	 * (1600 >> 2) & 0xFF = 0x90, byte 3 low nibble = 1600 >> 10 = 1;
	 * counter 28|4@1+ = byte 3 high nibble = 3 -> byte 3 0x31.
	 * 3200/32 = 100 km/h -> 11111111 um/s; 50 km/h -> 5555555.6 -> 5555556 */
	const uint8_t s[8] = { 0x80, 0x0C, 0x90, 0x31, 0, 0, 0, 0 };
	/* P_FL 0|16@1+ kPa: 4000 kPa = 40 bar, eta 0.95: 9160 x 0.95 = 8702 N */
	const uint8_t p[8] = { 0xA0, 0x0F, 0xA0, 0x0F };
	hal_can_frame_t f;

	(void)state;
	load("intel14_counter.cal");
	f = frame(0x0B4, false, 8, s);
	expect("WS_FL", 0, &f, INPUT_RX_OK, 3200, 11111111);
	expect("WS_FR", 1, &f, INPUT_RX_OK, 1600, 5555556);
	f = frame(0x0B8, false, 8, p);
	expect("P_FL", 0, &f, INPUT_RX_OK, 4000, 8702000);
	expect("P_FR", 1, &f, INPUT_RX_OK, 4000, 8702000);
}

static void test_b_counter_repeats_and_jumps(void **state)
{
	input_rx_cfg_t cfg;
	input_rx_state_t rx;
	uint8_t s[8] = { 0x80, 0x0C, 0x90, 0x01 };
	hal_can_frame_t f;
	static const uint8_t counters[] = { 3, 4, 4, 9, 10, 11 };
	static const input_rx_reason_t want[] = { INPUT_RX_OK, INPUT_RX_OK, INPUT_RX_REPEATED,
		INPUT_RX_COUNTER, INPUT_RX_OK, INPUT_RX_OK };

	(void)state;
	load("intel14_counter.cal");
	cfg = prepared("WS_FL", 0);
	input_rx_state_init(&rx);
	for (size_t i = 0; i < sizeof(counters); i++) {
		s[3] = (uint8_t)((counters[i] << 4) | 0x01U);
		f = frame(0x0B4, false, 8, s);
		assert_int_equal(input_rx_judge(&cfg, &rx, &f).reason, want[i]);
	}
}

static void test_d_multiplexed(void **state)
{
	/* selector 0|2: page 0 V_FL, 1 V_FR, 2 MC_PSI; value 8|16@1+.
	 * V_FL raw 640 x 1/64 = 10 m/s -> v0 = 4 m/s; MC_PSI raw 1000 = 100 psi
	 * = 689475.7 Pa x 2290e-6 m^2 = 1578.899 N */
	const uint8_t p0[8] = { 0x00, 0x80, 0x02 };
	const uint8_t p2[8] = { 0x02, 0xE8, 0x03 };
	input_rx_cfg_t fl;
	bool id_only = false;
	hal_can_frame_t f;

	(void)state;
	load("mux_psi.cal");
	f = frame(0x3C0, false, 8, p0);
	expect("V_FL", 0, &f, INPUT_RX_OK, 640, 4000000);
	fl = prepared("V_FR", 1);
	assert_false(input_rx_matches(&fl, &f, &id_only)); /* page 0 is not V_FR's */
	f = frame(0x3C0, false, 8, p2);
	expect("MC_PSI", 0, &f, INPUT_RX_OK, 1000, 1578899);
	fl = prepared("V_FL", 0);
	assert_false(input_rx_matches(&fl, &f, &id_only));
}

static void test_e_29_bit_signed_motorola_p01(void **state)
{
	/* VSPEED 8|16@1+ 1/256 km/h: raw 25600 = 0x6400 -> bytes 1-2 00 64:
	 * 100 km/h -> 11111111 um/s. CLAMP 23|16@0- in bytes 2 (MSB), 3:
	 * 0x23C8 = 9160 x 0.001 kN = 9.16 kN; 0xFFFF = -1 -> -0.001 kN = -1 N */
	const uint8_t v[8] = { 0x00, 0x00, 0x64, 0x00 };
	uint8_t c[8] = { 0, 0, 0x23, 0xC8, 0, 0, 0, 0 };
	const e2e_p01_config_t p01 = { 0x0B0A, 8, 2 };
	e2e_p01_tx_t tx = { 0U };
	hal_can_frame_t f;
	input_rx_cfg_t cfg;
	bool id_only = false;

	(void)state;
	load("ext29_kn.cal");
	f = frame(0x18FEF100U, true, 8, v);
	expect("VSPEED", 0, &f, INPUT_RX_OK, 25600, 11111111);
	/* the same identifier as an 11-bit frame is not the input */
	f = frame(0x100U, false, 8, v);
	cfg = prepared("VSPEED", 0);
	assert_false(input_rx_matches(&cfg, &f, &id_only));
	assert_int_equal(e2e_p01_protect(&p01, &tx, c, 8), SQ_OK);
	f = frame(0x0CF00A0BU, true, 8, c);
	expect("CLAMP", 0, &f, INPUT_RX_OK, 9160, 9160000);
	c[2] = 0xFF;
	c[3] = 0xFF;
	assert_int_equal(e2e_p01_protect(&p01, &tx, c, 8), SQ_OK);
	f = frame(0x0CF00A0BU, true, 8, c);
	expect("CLAMP", 0, &f, INPUT_RX_OK, -1, -1000);
}

static void test_f_torque_and_rpm(void **state)
{
	/* W_RPM 7|16@0+ 0.25 rpm: 0x0EEC = 3820 -> 955 rpm -> x 2 pi/60 x 0.12 m
	 * = 12.000884 m/s; counter 63|2@0+: byte 7 bits 7-6, counter 2 -> 0x80.
	 * T_BRAKE 7|16@0-: 0x03E8 = 1000 Nm -> 1000000 mNm; at v0 = 0 with the
	 * default friction law mu = 0.4: N = 1000/(2 x 0.4 x 0.12) = 10416.667 N */
	const uint8_t w[8] = { 0x0E, 0xEC, 0, 0, 0, 0, 0, 0x80 };
	const uint8_t t[8] = { 0x03, 0xE8, 0, 0, 0, 0, 0, 0x80 };
	const uint8_t neg[8] = { 0xFF, 0x38, 0, 0, 0, 0, 0, 0x80 }; /* -200 Nm */
	const calib_corner_t *c;
	hal_can_frame_t f;

	(void)state;
	load("torque_rpm.cal");
	c = &cal.corners[0];
	f = frame(0x240, false, 8, w);
	expect("W_RPM", 0, &f, INPUT_RX_OK, 3820, 12000884);
	f = frame(0x241, false, 8, t);
	expect("T_BRAKE", 0, &f, INPUT_RX_OK, 1000, 1000000);
	assert_in_range(input_conv_torque_to_force(1000000, 0, c->friction_faces, c->pad_radius_um,
						   c->mu_inf_q30, c->delta_mu_q30, c->slope_q24),
			10416667 - 2, 10416667 + 2);
	/* -200 Nm is below min -100: refused by the range check (and
	 * still converted exactly) */
	f = frame(0x241, false, 8, neg);
	expect("T_BRAKE", 0, &f, INPUT_RX_RANGE, -200, -200000);
}

/* ---- the monitor: bad DLC, not available, fault bit ----------------------------- */

static void test_monitor_faults_on_layout_a(void **state)
{
	static monitor_t m;
	const uint8_t ok[8] = { 0x82, 0xFE };
	const uint8_t fault[8] = { 0x82, 0xFF };
	const uint8_t na[8] = { 0xFF, 0xFE };
	hal_can_frame_t f;

	(void)state;
	load("moto15_p02.cal");
	assert_int_equal(monitor_init_corner(&m, &cal, 0U, false, 0U, 1000U), SQ_OK);
	assert_false(m.calib_invalid);
	m.now_us = 2000U;
	f = frame(0x1A0, false, 8, ok);
	monitor_on_frame(&m, &f);
	assert_int_equal(m.speed.count.used, 1);
	assert_int_equal(m.speed.value, 11111111);
	assert_int_equal(m.speed.faults, 0);
	f = frame(0x1A0, false, 1, ok);
	monitor_on_frame(&m, &f);
	assert_int_equal(m.speed.count.bad_dlc, 1);
	assert_true((monitor_fault_bits(&m) & MSG_FAULT_E2E_SPEED) != 0U);
	f = frame(0x1A0, false, 8, ok);
	monitor_on_frame(&m, &f);
	assert_int_equal(m.speed.faults, 0);
	f = frame(0x1A0, false, 8, na);
	monitor_on_frame(&m, &f);
	assert_int_equal(m.speed.count.implausible, 1);
	assert_true((monitor_fault_bits(&m) & MSG_FAULT_SPEED_IMPLAUSIBLE) != 0U);
	f = frame(0x1A0, false, 8, ok);
	monitor_on_frame(&m, &f);
	assert_int_equal(m.speed.faults, 0);
	f = frame(0x1A0, false, 8, fault);
	monitor_on_frame(&m, &f);
	assert_int_equal(m.speed.count.implausible, 2);
	assert_true((monitor_fault_bits(&m) & MSG_FAULT_SPEED_IMPLAUSIBLE) != 0U);
	/* the corner's outputs: FL keeps 0x300.. */
	assert_int_equal(m.corner.status_id, 0x300);
	assert_int_equal(monitor_init_corner(&m, &cal, 3U, false, 0U, 1000U), SQ_OK);
	assert_int_equal(m.corner.status_id, 0x330);
	assert_int_equal(m.corner.diag_id, 0x332);
}

/* ---- bad calibrations: refused whole, FILE:LINE ---------------------------------- */

static const char good_input[] =
	"[input S]\n"              /* 1 */
	"id = 0x100\n"             /* 2 */
	"start_bit = 8\n"          /* 3 */
	"length = 16\n"            /* 4 */
	"byte_order = intel\n"     /* 5 */
	"factor = 0.01\n"          /* 6 */
	"unit = rad/s\n"           /* 7 */
	"period_ms = 10\n"         /* 8 */
	"max = 400\n"              /* 9 */
	"step_max = 10\n"          /* 10 */
	"[input F]\n"              /* 11 */
	"id = 0x101\n"             /* 12 */
	"start_bit = 16\n"         /* 13 */
	"length = 16\n"            /* 14 */
	"byte_order = intel\n"     /* 15 */
	"factor = 0.5\n"           /* 16 */
	"unit = N\n"               /* 17 */
	"period_ms = 10\n"         /* 18 */
	"max = 30000\n"            /* 19 */
	"step_max = 10000\n";      /* 20 */

static void refused(const char *text, const char *want)
{
	FILE *f = fmemopen((void *)(uintptr_t)text, strlen(text), "r");
	char err[300] = "";
	calib_t out;
	calib_t before;
	int rc;

	assert_non_null(f);
	memset(&out, 0x5A, sizeof(out));
	before = out;
	rc = calib_text_parse_map(f, "car.cal", &out, NULL, err, sizeof(err));
	fclose(f);
	if ((rc != SQ_EBADMSG) || (strncmp(err, want, strlen(want)) != 0)) {
		fail_msg("want '%s...', got rc %d '%s'", want, rc, err);
	}
	assert_memory_equal(&out, &before, sizeof(out)); /* refused whole */
}

static void test_bad_calibrations(void **state)
{
	char buf[2048];

	(void)state;
	/* the good one parses */
	snprintf(buf, sizeof(buf), "%s[corner FL]\nspeed = S\nforce = F\n", good_input);
	{
		FILE *f = fmemopen(buf, strlen(buf), "r");
		char err[300] = "";

		assert_int_equal(calib_text_parse_map(f, "car.cal", &cal, &names, err, sizeof(err)),
				 SQ_OK);
		fclose(f);
	}
	/* a signal beyond the DLC: bytes 1-2 need DLC 3 */
	snprintf(buf, sizeof(buf), "%smin_dlc = 2\n[corner FL]\nspeed = S\nforce = F\n", good_input);
	refused(buf, "car.cal:21: [input F]");
	/* beyond the 64 bits of a frame (Intel 60|8) */
	snprintf(buf, sizeof(buf), "[input S]\nid = 1\nstart_bit = 60\nlength = 8\n"
		 "byte_order = intel\nfactor = 1\nunit = N\nperiod_ms = 10\nmax = 1\nstep_max = 1\n");
	refused(buf, "car.cal:3: [input S]");
	/* zero length */
	snprintf(buf, sizeof(buf), "[input S]\nid = 1\nstart_bit = 8\nlength = 0\n");
	refused(buf, "car.cal:4: [input S] length = 0: zero length");
	/* factor 0 */
	snprintf(buf, sizeof(buf), "[input S]\nid = 1\nstart_bit = 8\nlength = 8\n"
		 "byte_order = intel\nfactor = 0.000\nunit = N\n");
	refused(buf, "car.cal:6: [input S] factor 0");
	/* an overlapping mux selector */
	snprintf(buf, sizeof(buf), "%smux_start_bit = 20\nmux_length = 4\nmux_byte_order = intel\n"
		 "mux_value = 1\n[corner FL]\nspeed = S\nforce = F\n", good_input);
	refused(buf, "car.cal:21: [input F] the mux selector overlaps");
	/* a duplicate corner */
	snprintf(buf, sizeof(buf), "%s[corner FL]\nspeed = S\nforce = F\n[corner fl]\n", good_input);
	refused(buf, "car.cal:24: duplicate corner 'fl'");
	/* unknown unit; a pressure without piston area */
	snprintf(buf, sizeof(buf), "[input S]\nid = 1\nstart_bit = 8\nlength = 8\n"
		 "byte_order = intel\nfactor = 1\nunit = furlong/fortnight\n");
	refused(buf, "car.cal:7: [input S] unknown unit");
	snprintf(buf, sizeof(buf), "%s[input P]\nid = 0x102\nstart_bit = 0\nlength = 12\n"
		 "byte_order = intel\nfactor = 0.1\nunit = bar\nperiod_ms = 10\nmax = 250\n"
		 "step_max = 50\n[corner FL]\nspeed = S\nforce = P\n", good_input);
	refused(buf, "car.cal:31: [corner FL] pressure without piston_area_mm2");
	/* a corner naming an unknown input, or a speed as its force */
	snprintf(buf, sizeof(buf), "%s[corner FL]\nspeed = S\nforce = G\n", good_input);
	refused(buf, "car.cal:23: [corner FL] force names an unknown input 'G'");
	snprintf(buf, sizeof(buf), "%s[corner FL]\nspeed = S\nforce = S\n", good_input);
	refused(buf, "car.cal:23: [corner FL] force input is not a force");
	/* a legacy input key in a file with corners */
	snprintf(buf, sizeof(buf), "disc_speed_id = 0x120\n%s[corner FL]\nspeed = S\nforce = F\n",
		 good_input);
	refused(buf, "car.cal:1: legacy input key 'disc_speed_id'");
	/* a 29-bit identifier without extended = yes; a key twice */
	snprintf(buf, sizeof(buf), "[input S]\nid = 0x18FEF100\nstart_bit = 8\nlength = 8\n"
		 "byte_order = intel\nfactor = 1\nunit = N\nperiod_ms = 10\nmax = 1\nstep_max = 1\n");
	refused(buf, "car.cal:2: [input S] id 0x18FEF100 is above 0x7FF");
	snprintf(buf, sizeof(buf), "[input S]\nid = 1\nid = 2\n");
	refused(buf, "car.cal:3: duplicate key 'id'");
	/* inputs without a corner; an unknown section */
	refused(good_input, "car.cal:1: [input] sections but no [corner]");
	refused("[brake FL]\n", "car.cal:1: unknown section 'brake'");
}

static const char good_input_with_corner[] =
	"[input S]\nid = 0x100\nstart_bit = 8\nlength = 16\nbyte_order = intel\n"
	"factor = 0.01\nunit = rad/s\nperiod_ms = 10\nmax = 400\nstep_max = 10\n"
	"[input F]\nid = 0x101\nstart_bit = 16\nlength = 16\nbyte_order = intel\n"
	"factor = 0.5\nunit = N\nperiod_ms = 10\nmax = 30000\nstep_max = 10000\n"
	"[corner FL]\nspeed = S\nforce = F\n";

/* ---- calibrations that set up exactly as written ---------------------------------- */

static void parse_text(const char *text)
{
	FILE *f = fmemopen((void *)(uintptr_t)text, strlen(text), "r");
	char err[300] = "";

	assert_non_null(f);
	if (calib_text_parse_map(f, "car.cal", &cal, &names, err, sizeof(err)) != SQ_OK) {
		fclose(f);
		fail_msg("%s", err);
	}
	fclose(f);
}

/* corner k's speed (0) or force (1) input, set up as the monitor does it:
 * calib_corner_view() (which carries the torque share) and its geometry */
static input_rx_cfg_t corner_input(uint32_t k, int which)
{
	calib_corner_t c;
	calib_input_t sp;
	calib_input_t fo;
	input_geom_t g;
	input_rx_cfg_t cfg;

	assert_int_equal(calib_validate(&cal), SQ_OK);
	assert_int_equal(calib_corner_view(&cal, k, &c, &sp, &fo), SQ_OK);
	g = calib_corner_geom(&c);
	assert_int_equal(input_rx_setup((which == 0) ? &sp : &fo, &g, &cfg), SQ_OK);
	return cfg;
}

/* One input N (newtons, so that the conversion is x 1000 to mN) with the
 * given factor/offset/range lines on a 32-bit raw (bytes 0..3, Intel), and
 * a plain speed; corner FL. */
static void force_input(const char *lines)
{
	char buf[1024];

	snprintf(buf, sizeof(buf),
		 "[input S]\nid = 0x100\nstart_bit = 0\nlength = 16\nbyte_order = intel\n"
		 "factor = 0.01\nunit = rad/s\nperiod_ms = 10\nmax = 400\nstep_max = 10\n"
		 "[input F]\nid = 0x101\nperiod_ms = 10\nbyte_order = intel\n%s"
		 "[corner FL]\nspeed = S\nforce = F\n", lines);
	parse_text(buf);
}

static void test_exact_dbc_factors(void **state)
{
	input_rx_cfg_t cfg;

	(void)state;
	/* 2^-10 N (a Toyota-style factor) on 16 bits, max 63.99 N: refused at
	 * set-up before (10 digits beyond the old exponent span). mN =
	 * raw x 1000 / 1024 = raw x 125 / 128: 1000 -> 976.5625 -> 977, 64 ->
	 * 62.5 -> 63 (halves away from zero); plausible raws: 0 .. floor(63.99
	 * x 1024) = floor(65525.76) = 65525 */
	force_input("start_bit = 0\nlength = 16\nfactor = 0.0009765625\nunit = N\n"
		    "max = 63.99\nstep_max = 63.99\n");
	assert_int_equal(cal.inputs[1].factor.mant, 9765625);
	assert_int_equal(cal.inputs[1].factor.exp, -10);
	cfg = corner_input(0U, 1);
	assert_int_equal(input_conv_apply(&cfg.conv, 1000), 977);
	assert_int_equal(input_conv_apply(&cfg.conv, 64), 63);
	assert_true(cfg.raw_min == 0);
	assert_true(cfg.raw_max == 65525);
	/* 1e-07 kN on a 32-bit unsigned raw: 4294967295 x 1e-7 kN =
	 * 429.4967295 kN = 429496729.5 mN -> 429496730 (a tie, away from 0) */
	force_input("start_bit = 0\nlength = 32\nfactor = 1e-07\nunit = kN\n"
		    "max = 2147483647\nstep_max = 1e3\n");
	assert_int_equal(cal.inputs[1].factor.mant, 1);
	assert_int_equal(cal.inputs[1].factor.exp, -7);
	assert_int_equal(cal.inputs[1].max.mant, 2147483647);
	cfg = corner_input(0U, 1);
	assert_int_equal(input_conv_apply(&cfg.conv, 4294967295LL), 429496730);
	assert_true(cfg.raw_max >= 4294967295LL); /* every raw is plausible */
	/* 17 significant digits, as repr() writes 1/3: 0.33333333333333331 N
	 * = 33333333333333331 / 10^17 N; mN = raw x 33333333333333331 / 10^14:
	 * 3 -> 999.99999999999993 -> 1000; 1234567 -> 411522333.33.. ->
	 * 411522333; 3000000 -> 999999999.99999993 -> 1000000000 */
	force_input("start_bit = 0\nlength = 32\nfactor = 0.33333333333333331\nunit = N\n"
		    "max = 2e9\nstep_max = 2e9\n");
	assert_true(cal.inputs[1].factor.mant == 33333333333333331LL);
	assert_int_equal(cal.inputs[1].factor.exp, -17);
	cfg = corner_input(0U, 1);
	assert_int_equal(input_conv_apply(&cfg.conv, 3), 1000);
	assert_int_equal(input_conv_apply(&cfg.conv, 1234567), 411522333);
	assert_int_equal(input_conv_apply(&cfg.conv, 3000000), 1000000000);
	/* the same in kN on a signed 16-bit raw: raw x mul passes 2^63 (the
	 * 128-bit path): 6000 -> 1999999999.9999998 -> 2000000000, -6000 ->
	 * -2000000000, 5999 -> 1999666666.67 -> 1999666667; 7000 saturates */
	force_input("start_bit = 0\nlength = 16\nsigned = yes\nfactor = 0.33333333333333331\n"
		    "unit = kN\nmin = -1e4\nmax = 1e4\nstep_max = 1e4\n");
	cfg = corner_input(0U, 1);
	assert_int_equal(cfg.conv.wide, 1);
	assert_int_equal(input_conv_apply(&cfg.conv, 6000), 2000000000);
	assert_int_equal(input_conv_apply(&cfg.conv, -6000), -2000000000);
	assert_int_equal(input_conv_apply(&cfg.conv, 5999), 1999666667);
	assert_int_equal(input_conv_apply(&cfg.conv, 7000), INT32_MAX);
	assert_int_equal(input_conv_apply(&cfg.conv, -7000), INT32_MIN);
	/* negative offsets in exponent notation: 0.5 N, offset -4.5e1 N:
	 * raw 100 -> 50 - 45 = 5 N = 5000 mN, raw 0 -> -45000 mN; and 2^-10 N
	 * with -1.25e-1 N: raw 1000 -> 0.9765625 - 0.125 = 0.8515625 N ->
	 * 851.5625 -> 852 mN (offset and scale over one denominator) */
	force_input("start_bit = 0\nlength = 16\nfactor = 0.5\noffset = -4.5e1\nunit = N\n"
		    "min = -45\nmax = 1e4\nstep_max = 1e4\n");
	assert_int_equal(cal.inputs[1].offset.mant, -45);
	assert_int_equal(cal.inputs[1].offset.exp, 0);
	cfg = corner_input(0U, 1);
	assert_int_equal(input_conv_apply(&cfg.conv, 100), 5000);
	assert_int_equal(input_conv_apply(&cfg.conv, 0), -45000);
	force_input("start_bit = 0\nlength = 16\nfactor = 0.0009765625\noffset = -1.25e-1\n"
		    "unit = N\nmin = -1\nmax = 64\nstep_max = 64\n");
	cfg = corner_input(0U, 1);
	assert_int_equal(input_conv_apply(&cfg.conv, 1000), 852);
	/* min -1 N: raw >= ceil((-1 + 0.125) x 1024) = ceil(-896) = -896,
	 * raw <= floor(64.125 x 1024) = 65664 */
	assert_true(cfg.raw_min == -896);
	assert_true(cfg.raw_max == 65664);
}

static void test_refused_at_its_line(void **state)
{
	char buf[2048];

	(void)state;
	/* max below min: the text parser took it and the corner never set
	 * up; now refused at the max line (line 9 here: input S's max) */
	snprintf(buf, sizeof(buf), "[input S]\nid = 0x100\nstart_bit = 8\nlength = 16\n"
		 "byte_order = intel\nfactor = 0.01\nunit = rad/s\nperiod_ms = 10\nmax = 10\n"
		 "min = 20\nstep_max = 10\n%s[corner FL]\nspeed = S\nforce = F\n",
		 good_input + strlen("[input S]\nid = 0x100\nstart_bit = 8\nlength = 16\n"
				     "byte_order = intel\nfactor = 0.01\nunit = rad/s\n"
				     "period_ms = 10\nmax = 400\nstep_max = 10\n"));
	refused(buf, "car.cal:9: [input S] max is below min");
	/* a range between two raw steps holds no raw value: 0.1 .. 0.3 N in
	 * raw steps of 0.5 N */
	snprintf(buf, sizeof(buf), "%.*smax = 0.3\nmin = 0.1\nstep_max = 10000\n"
		 "[corner FL]\nspeed = S\nforce = F\n",
		 (int)(strstr(good_input, "max = 30000") - good_input), good_input);
	refused(buf, "car.cal:19: [input F] max: no raw value");
	/* one raw step of 2^31 mN or more cannot convert: at the factor */
	snprintf(buf, sizeof(buf), "%s[input T]\nid = 0x102\nstart_bit = 0\nlength = 8\n"
		 "byte_order = intel\nfactor = 3e6\nunit = N\nperiod_ms = 10\nmax = 1e9\n"
		 "step_max = 1e9\n[corner FL]\nspeed = S\nforce = T\n", good_input);
	refused(buf, "car.cal:26: [input T] factor: one raw step");
	/* more than 17 significant digits, exponent beyond 30 */
	snprintf(buf, sizeof(buf), "[input S]\nid = 1\nstart_bit = 8\nlength = 8\n"
		 "byte_order = intel\nfactor = 0.123456789012345678\n");
	refused(buf, "car.cal:6: [input S] factor needs a decimal number");
	snprintf(buf, sizeof(buf), "[input S]\nid = 1\nstart_bit = 8\nlength = 8\n"
		 "byte_order = intel\nfactor = 1e-31\n");
	refused(buf, "car.cal:6: [input S] factor needs a decimal number");
	/* torque_share outside (0, 1], or on an input that is no torque */
	snprintf(buf, sizeof(buf), "%s[corner FL]\nspeed = S\nforce = F\ntorque_share = 0.5\n",
		 good_input);
	refused(buf, "car.cal:24: [corner FL] torque_share for a force input that is not a torque");
	snprintf(buf, sizeof(buf), "%s[corner FL]\nspeed = S\nforce = F\ntorque_share = 1.5\n",
		 good_input);
	refused(buf, "car.cal:24: [corner FL] torque_share = 1.5 must be in (0, 1]");
	/* input_iface: 1..15 of A-Z a-z 0-9 _ . - */
	refused("input_iface = can0/x\n", "car.cal:1: input_iface = 'can0/x'");
	refused("input_iface = can0\ninput_iface = can1\n", "car.cal:2: duplicate key 'input_iface'");
	/* signal: printable, no blanks, 1..63 */
	snprintf(buf, sizeof(buf), "%ssignal = %s\n", good_input,
		 "M.SSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSSS");
	refused(buf, "car.cal:21: [input F] signal: the DBC name");
}

/* A qualifier bit beyond min_dlc: the monitor would read a byte the frame
 * need not have. Refused by the input map (calib_input_needed_dlc counts
 * the bit), for the block as for the text. */
static void test_qualifier_beyond_min_dlc(void **state)
{
	calib_input_t in;
	const char *why = NULL;

	(void)state;
	parse_text(good_input_with_corner);
	in = cal.inputs[1];                 /* F: bytes 2..3, min_dlc 4 */
	assert_int_equal(in.min_dlc, 4);
	in.flags |= CALIB_IN_QUALIFIER;
	in.qualifier_bit = 7;               /* byte 0: within min_dlc 4 */
	assert_int_equal(calib_input_check(&in, &why), SQ_OK);
	in.qualifier_bit = 40;              /* byte 5: beyond it */
	assert_int_equal(calib_input_check(&in, &why), SQ_EINVAL);
	assert_string_equal(why, "a signal beyond min_dlc");
	cal.inputs[1] = in;
	assert_int_equal(calib_validate(&cal), SQ_EINVAL);
	in.min_dlc = 6;
	assert_int_equal(calib_input_check(&in, &why), SQ_OK);
}

static void test_extended_multiplexing(void **state)
{
	static const char text[] =
		"[input S]\nid = 0x100\nstart_bit = 8\nlength = 16\nbyte_order = intel\n"
		"factor = 0.01\nunit = rad/s\nperiod_ms = 10\nmax = 400\nstep_max = 10\n"
		"[input F]\n"                       /* 11 */
		"id = 0x3C0\nstart_bit = 16\nlength = 16\nbyte_order = intel\n"
		"factor = 0.5\nunit = N\nperiod_ms = 10\nmax = 30000\nstep_max = 30000\n"
		"signal = BRAKE_PAGE.PadForce\n"
		/* outer selector bits 0..3: pages 2..3; inner bits 56..59: 5..7 */
		"mux_start_bit = 0\nmux_length = 4\nmux_byte_order = intel\nmux_value = 2\n"
		"mux_value_max = 3\n"
		"mux2_start_bit = 56\nmux2_length = 4\nmux2_byte_order = intel\nmux2_value = 5\n"
		"mux2_value_max = 7\n"
		"[corner FL]\nspeed = S\nforce = F\n";
	/* page pairs (outer, inner) and whether the frame carries F */
	static const struct {
		uint8_t outer;
		uint8_t inner;
		bool carries;
	} pages[] = {
		{ 2U, 5U, true }, { 3U, 7U, true }, { 2U, 6U, true },
		{ 1U, 5U, false }, { 4U, 6U, false }, { 15U, 7U, false },
		{ 2U, 4U, false }, { 3U, 8U, false }, { 0U, 0U, false },
	};
	input_rx_cfg_t cfg;
	bool id_only = false;
	uint32_t i;

	(void)state;
	parse_text(text);
	assert_string_equal(names.signal[1], "BRAKE_PAGE.PadForce");
	assert_string_equal(names.signal[0], "");
	assert_int_equal(cal.inputs[1].min_dlc, 8); /* the inner selector in byte 7 */
	cfg = corner_input(0U, 1);
	for (i = 0U; i < sizeof(pages) / sizeof(pages[0]); i++) {
		uint8_t d[8] = { 0 };
		hal_can_frame_t f;

		d[0] = pages[i].outer;
		d[7] = pages[i].inner;
		d[2] = 0x10;                        /* raw 0x0010 = 16 -> 8 N */
		f = frame(0x3C0, false, 8U, d);
		if (input_rx_matches(&cfg, &f, &id_only) != pages[i].carries) {
			fail_msg("page %u/%u: carries %d", pages[i].outer, pages[i].inner,
				 (int)pages[i].carries);
		}
		if (pages[i].carries) {
			input_rx_state_t rx;
			input_rx_result_t r;

			input_rx_state_init(&rx);
			r = input_rx_judge(&cfg, &rx, &f);
			assert_int_equal(r.reason, INPUT_RX_OK);
			assert_int_equal(input_conv_apply(&cfg.conv, r.value), 8000);
		}
	}
	/* too short for the inner selector: matches, then a bad DLC */
	{
		const uint8_t d[8] = { 2U, 0U, 0x10U, 0U, 0U, 0U, 0U, 0U };
		const hal_can_frame_t f = frame(0x3C0, false, 4U, d);
		input_rx_state_t rx;

		assert_true(input_rx_matches(&cfg, &f, &id_only));
		input_rx_state_init(&rx);
		assert_int_equal(input_rx_judge(&cfg, &rx, &f).reason, INPUT_RX_DLC);
	}
	/* written back and parsed again: the same block */
	{
		char *out = NULL;
		size_t len = 0;
		FILE *w = open_memstream(&out, &len);
		calib_t first = cal;
		uint8_t a[CALIB_BLOCK_LEN];
		uint8_t b[CALIB_BLOCK_LEN];

		assert_int_equal(calib_text_write_map(w, &cal, &names), SQ_OK);
		fclose(w);
		assert_non_null(strstr(out, "mux2_value_max = 7\n"));
		assert_non_null(strstr(out, "signal = BRAKE_PAGE.PadForce\n"));
		parse_text(out);
		free(out);
		assert_int_equal(calib_encode(&first, a, sizeof(a)), SQ_OK);
		assert_int_equal(calib_encode(&cal, b, sizeof(b)), SQ_OK);
		assert_memory_equal(a, b, sizeof(a));
	}
	/* selectors: not overlapping each other, the value or the E2E header;
	 * value_max not below value; a second selector needs the first */
	{
		char buf[2048];
		char *p;

		snprintf(buf, sizeof(buf), "%s", text);
		p = strstr(buf, "mux2_start_bit = 56");
		memcpy(p, "mux2_start_bit = 02", 19U);
		refused(buf, "car.cal:27: [input F] mux2_start_bit: the two selectors overlap");
		snprintf(buf, sizeof(buf), "%s", text);
		p = strstr(buf, "mux_value_max = 3");
		memcpy(p, "mux_value_max = 1", 17U);
		refused(buf, "car.cal:26: [input F] mux_value_max below mux_value");
		snprintf(buf, sizeof(buf), "%s", text);
		p = strstr(buf, "mux2_value_max = 7");
		memcpy(p, "mux2_value_max = 4", 18U);
		refused(buf, "car.cal:31: [input F] mux2_value_max below mux2_value or beyond");
		snprintf(buf, sizeof(buf), "%s", text);
		p = strstr(buf, "mux_start_bit = 0\nmux_length = 4\nmux_byte_order = intel\nmux_value = 2\nmux_value_max = 3\n");
		memset(p, ' ', strlen("mux_start_bit = 0\nmux_length = 4\nmux_byte_order = intel\nmux_value = 2\nmux_value_max = 3"));
		/* (the blanked selector lines are one line now: mux2 on line 23) */
		refused(buf, "car.cal:23: [input F] mux2_start_bit: a second selector needs the first");
	}
}

static void test_torque_share(void **state)
{
	static const char text[] =
		"[input W]\nid = 0x240\nstart_bit = 0\nlength = 16\nbyte_order = intel\n"
		"factor = 0.01\nunit = rad/s\nperiod_ms = 10\nmax = 400\nstep_max = 100\n"
		"[input T]\nid = 0x241\nstart_bit = 16\nlength = 16\nbyte_order = intel\n"
		"factor = 1\nunit = Nm\nperiod_ms = 10\nmax = 20000\nstep_max = 20000\n"
		"[corner FL]\nspeed = W\nforce = T\ntorque_share = 0.6\n"
		"[corner FR]\nspeed = W\nforce = T\ntorque_share = 0.4\n";
	input_rx_cfg_t fl;
	input_rx_cfg_t fr;

	(void)state;
	parse_text(text);
	assert_int_equal(cal.corners[0].torque_share_ppm, 600000);
	assert_int_equal(cal.corners[1].torque_share_ppm, 400000);
	/* the front axle's total torque 1000 Nm: FL 0.6 x 1000 Nm = 600000
	 * mNm, FR 400000 mNm; the input's plausibility is the total's */
	fl = corner_input(0U, 1);
	fr = corner_input(1U, 1);
	assert_int_equal(input_conv_apply(&fl.conv, 1000), 600000);
	assert_int_equal(input_conv_apply(&fr.conv, 1000), 400000);
	assert_int_equal(input_conv_apply(&fl.conv, 3), 1800);
	assert_true(fl.raw_max == 20000);
	/* the stored input itself (no corner) converts the whole value */
	{
		const input_geom_t g = calib_corner_geom(&cal.corners[0]);
		input_rx_cfg_t whole;

		assert_int_equal(input_rx_setup(&cal.inputs[1], &g, &whole), SQ_OK);
		assert_int_equal(input_conv_apply(&whole.conv, 1000), 1000000);
	}
	/* through the block and back */
	{
		uint8_t a[CALIB_BLOCK_LEN];
		calib_t back;

		assert_int_equal(calib_encode(&cal, a, sizeof(a)), SQ_OK);
		assert_int_equal(calib_decode(a, sizeof(a), &back, NULL), SQ_OK);
		assert_int_equal(back.corners[0].torque_share_ppm, 600000);
	}
}

static void test_written_map_parses_back(void **state)
{
	char *text = NULL;
	size_t len = 0;
	FILE *w;
	FILE *r;
	calib_t back;
	char err[300] = "";
	uint8_t a[CALIB_BLOCK_LEN];
	uint8_t b[CALIB_BLOCK_LEN];

	(void)state;
	load("moto15_p02.cal");
	w = open_memstream(&text, &len);
	assert_int_equal(calib_text_write(w, &cal), SQ_OK);
	fclose(w);
	r = fmemopen(text, len, "r");
	assert_int_equal(calib_text_parse_map(r, "written", &back, NULL, err, sizeof(err)), SQ_OK);
	fclose(r);
	free(text);
	/* the stored blocks are byte-identical */
	assert_int_equal(calib_encode(&cal, a, sizeof(a)), SQ_OK);
	assert_int_equal(calib_encode(&back, b, sizeof(b)), SQ_OK);
	assert_memory_equal(a, b, sizeof(a));
	/* and the block decodes to the same map */
	assert_int_equal(calib_decode(a, sizeof(a), &back, NULL), SQ_OK);
	assert_int_equal(back.n_corners, 4);
	assert_int_equal(back.inputs[0].offset.mant, -6767);
	assert_int_equal(back.inputs[0].offset.exp, -2);
}

static void test_input_rx_contracts(void **state)
{
	const calib_corner_t *c;
	input_geom_t g;
	input_rx_cfg_t cfg;
	calib_input_t bad;
	input_rx_state_t rx;
	hal_can_frame_t f;
	bool id_only = false;
	static const uint8_t zeros[8] = { 0 };

	(void)state;
	load("ext29_kn.cal");
	c = &cal.corners[0];
	g = (input_geom_t){ c->pad_radius_um, c->wheel_radius_um, c->piston_area_cmm2,
			    c->efficiency_ppm, c->axle_factor_ppm };
	cfg = prepared("CLAMP", 0U);
	input_rx_state_init(&rx);
	f = frame(0x0CF00A0BU, true, 8U, zeros);
	expect_assert_failure(input_rx_setup(NULL, &g, &cfg));
	expect_assert_failure(input_rx_setup(&cal.inputs[0], NULL, &cfg));
	expect_assert_failure(input_rx_setup(&cal.inputs[0], &g, NULL));
	/* a descriptor calib validation would refuse: a signal beyond bit 63 */
	bad = cal.inputs[input_named("CLAMP")];
	bad.sig.start_bit = 63U;
	bad.sig.byte_order = (uint8_t)CAN_SIGNAL_INTEL;
	expect_assert_failure(input_rx_setup(&bad, &g, &cfg));
	expect_assert_failure(input_rx_matches(NULL, &f, &id_only));
	expect_assert_failure(input_rx_matches(&cfg, NULL, &id_only));
	expect_assert_failure(input_rx_matches(&cfg, &f, NULL));
	expect_assert_failure(input_rx_state_init(NULL));
	expect_assert_failure(input_rx_judge(NULL, &rx, &f));
	expect_assert_failure(input_rx_judge(&cfg, NULL, &f));
	expect_assert_failure(input_rx_judge(&cfg, &rx, NULL));
	/* bad data keeps its counted reason: a short frame, a wrong CRC */
	f = frame(0x0CF00A0BU, true, 2U, zeros);
	assert_true(input_rx_matches(&cfg, &f, &id_only));
	assert_int_equal(input_rx_judge(&cfg, &rx, &f).reason, INPUT_RX_DLC);
	f = frame(0x0CF00A0BU, true, 8U, zeros);
	f.data[0] = 0x5AU; /* not the P01 CRC of these bytes */
	assert_int_equal(input_rx_judge(&cfg, &rx, &f).reason, INPUT_RX_CRC);
}

/* The deviations: flat keys are every corner's, a [corner] may set its own
 * (stored in the parameters' Q formats: 0.006 x 2^30 = 6442450.9); a
 * corner's deviation above its own parameter is refused; the writer writes
 * them back. */
static void test_corner_deviations(void **state)
{
	char buf[2048];
	char err[300] = "";
	FILE *f;
	calib_t c2;

	(void)state;
	snprintf(buf, sizeof(buf), "delta_mu_sd = 0.006\nslope_spm_sd = 0.1\n%s"
		 "[corner FL]\nspeed = S\nforce = F\n"
		 "[corner FR]\nspeed = S\nforce = F\nslope_spm = 3\nslope_spm_sd = 0.3\n"
		 "status_id = 0x320\ndetail_id = 0x321\ndiag_id = 0x322\ndetail2_id = 0x323\n",
		 good_input);
	f = fmemopen(buf, strlen(buf), "r");
	assert_non_null(f);
	assert_int_equal(calib_text_parse_map(f, "car.cal", &cal, &names, err, sizeof(err)), SQ_OK);
	fclose(f);
	assert_int_equal(cal.n_corners, 2);
	assert_int_equal(cal.corners[0].sd.delta_mu_sd_q30, 6442451);
	assert_int_equal(cal.corners[0].sd.slope_sd_q24, 1677722);   /* 0.1 x 2^24 */
	assert_int_equal(cal.corners[1].sd.delta_mu_sd_q30, 6442451); /* inherited */
	assert_int_equal(cal.corners[1].sd.slope_sd_q24, 5033165);   /* 0.3 x 2^24 */
	/* written and read back: the same block */
	{
		char *text = NULL;
		size_t len = 0;
		FILE *o = open_memstream(&text, &len);
		uint8_t a[CALIB_BLOCK_LEN];
		uint8_t b[CALIB_BLOCK_LEN];

		assert_non_null(o);
		assert_int_equal(calib_text_write(o, &cal), SQ_OK);
		fclose(o);
		f = fmemopen(text, len, "r");
		assert_non_null(f);
		assert_int_equal(calib_text_parse_map(f, "w.cal", &c2, NULL, err, sizeof(err)),
				 SQ_OK);
		fclose(f);
		free(text);
		assert_int_equal(calib_encode(&cal, a, sizeof(a)), SQ_OK);
		assert_int_equal(calib_encode(&c2, b, sizeof(b)), SQ_OK);
		assert_memory_equal(a, b, sizeof(a));
	}
	snprintf(buf, sizeof(buf), "%s[corner FL]\nspeed = S\nforce = F\nslope_spm = 1\n"
		 "slope_spm_sd = 1.5\n", good_input);
	refused(buf, "car.cal: a standard deviation");
}

SQ_CMOCKA_MAIN(
	cmocka_unit_test(test_a_motorola15_offset_fault_bits),
	cmocka_unit_test(test_a_master_cylinder_p02_axle),
	cmocka_unit_test(test_b_intel14_with_counter_between),
	cmocka_unit_test(test_b_counter_repeats_and_jumps),
	cmocka_unit_test(test_d_multiplexed),
	cmocka_unit_test(test_e_29_bit_signed_motorola_p01),
	cmocka_unit_test(test_f_torque_and_rpm),
	cmocka_unit_test(test_monitor_faults_on_layout_a),
	cmocka_unit_test(test_bad_calibrations),
	cmocka_unit_test(test_corner_deviations),
	cmocka_unit_test(test_written_map_parses_back),
	cmocka_unit_test(test_input_rx_contracts),
	cmocka_unit_test(test_exact_dbc_factors),
	cmocka_unit_test(test_refused_at_its_line),
	cmocka_unit_test(test_qualifier_beyond_min_dlc),
	cmocka_unit_test(test_extended_multiplexing),
	cmocka_unit_test(test_torque_share))
