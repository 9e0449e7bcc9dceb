/* SPDX-License-Identifier: MIT */
/*
 * The input stage's one verdict per frame (input_rx_judge), both numeric
 * builds, on fixture layout A (tests/firmware/monitor/fixtures/moto15_p02.cal, written for
 * the tests): WS_FL is Motorola 7|15 at 0.01 km/h, offset -67.67 km/h,
 * na_raw 0x7FFF, qualifier bit 8 (1 = invalid), min -1, max 300 km/h,
 * step_max 20 km/h; MC_PRESS is Intel 16|12 at 0.1 bar with E2E P02.
 *
 * Raw bounds by hand: min -1 km/h -> raw >= (-1 + 67.67) / 0.01 = 6667,
 * max 300 -> raw <= 36767, step 20 km/h -> 2000 raw.
 * A WS_FL frame for raw R: byte 0 = R >> 7, byte 1 = (R & 0x7F) << 1 | qual.
 *
 * Checked: the order of the checks (protection before "not available",
 * "not available" before the qualifier, the qualifier before the range,
 * the range before the step), each reason's name, the step against the
 * previous value (a refused value still becomes the previous one), and
 * that a second "not available" value (na_raw2) is refused as `na` and
 * never used, by the input stage and by the monitor recording it; the
 * range's upper end is plausible (max set to 200 km/h: raw 26767 taken,
 * 26768 = 200.01 km/h refused; the fixture's 300 km/h is raw 36767, beyond
 * the 15-bit signal); an input with exact_dlc (the legacy DiscSpeed,
 * squeal.dbc: 4 bytes) takes only frames of exactly min_dlc bytes, a
 * longer one is `dlc` like a shorter one.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "calib_map.h"
#include "calib_text.h"
#include "map_fixture.h"
#include "input_rx.h"
#include "monitor.h"
#include "sq_status.h"

#ifndef FIXTURE_DIR
#define FIXTURE_DIR "tests/firmware/monitor/fixtures"
#endif

#define WS_FL_ID 0x1A0U
#define RAW_100_KPH 16767U  /* 100 km/h */
#define RAW_1_KPH 6867U     /* 1 km/h: inside the range */
#define RAW_MIN 6667U       /* -1 km/h */
#define RAW_MAX_200 26767U  /* 200 km/h: (200 + 67.67) / 0.01 */
#define RAW_STEP 2000U      /* 20 km/h */

static calib_t cal;
static calib_names_t names;

static void load(void)
{
	map_fixture_load(FIXTURE_DIR, "moto15_p02.cal", &cal, &names);
}

static uint32_t input_named(const char *name)
{
	return map_fixture_input(&cal, &names, name);
}

static input_rx_cfg_t prepared(const calib_input_t *in)
{
	const calib_corner_t *c = &cal.corners[0];
	const input_geom_t g = { c->pad_radius_um, c->wheel_radius_um, c->piston_area_cmm2,
				 c->efficiency_ppm, c->axle_factor_ppm };
	input_rx_cfg_t cfg;

	assert_int_equal(input_rx_setup(in, &g, &cfg), SQ_OK);
	return cfg;
}

/* a WS_FL frame carrying raw (15 bit) and the qualifier bit */
static hal_can_frame_t ws_fl(uint32_t raw, unsigned qual)
{
	hal_can_frame_t f;

	memset(&f, 0, sizeof(f));
	f.id = WS_FL_ID;
	f.dlc = 8U;
	f.data[0] = (uint8_t)(raw >> 7);
	f.data[1] = (uint8_t)(((raw & 0x7FU) << 1) | (qual & 1U));
	return f;
}

static input_rx_reason_t judge(const input_rx_cfg_t *cfg, input_rx_state_t *st,
			       const hal_can_frame_t *f)
{
	bool id_only = false;

	assert_true(input_rx_matches(cfg, f, &id_only));
	return (input_rx_reason_t)input_rx_judge(cfg, st, f).reason;
}

static void test_reason_names(void **state)
{
	static const char *const want[] = { "ok", "dlc", "crc", "counter", "repeated",
					    "na", "qualifier", "range", "step" };

	(void)state;
	assert_int_equal(sizeof(want) / sizeof(want[0]), INPUT_RX_REASON_COUNT);
	for (uint32_t i = 0U; i < (uint32_t)INPUT_RX_REASON_COUNT; i++) {
		assert_string_equal(input_rx_reason_name((input_rx_reason_t)i), want[i]);
	}
	assert_string_equal(input_rx_reason_name(INPUT_RX_REASON_COUNT), "?");
}

static void test_checks_in_order(void **state)
{
	input_rx_cfg_t cfg;
	input_rx_state_t st;
	hal_can_frame_t f;

	(void)state;
	load();
	cfg = prepared(&cal.inputs[input_named("WS_FL")]);
	assert_true(cfg.raw_min == RAW_MIN);
	assert_true(cfg.raw_step == RAW_STEP);
	input_rx_state_init(&st);
	/* "not available" wins over an invalid qualifier */
	f = ws_fl(0x7FFFU, 1U);
	assert_int_equal(judge(&cfg, &st, &f), INPUT_RX_NA);
	/* the qualifier wins over the range (raw 0 = -67.67 km/h) */
	f = ws_fl(0U, 1U);
	assert_int_equal(judge(&cfg, &st, &f), INPUT_RX_QUALIFIER);
	/* neither the NA nor the qualifier refusal became the previous value:
	 * no step check against them */
	f = ws_fl(RAW_100_KPH, 0U);
	assert_int_equal(judge(&cfg, &st, &f), INPUT_RX_OK);
	f = ws_fl(0U, 0U);
	assert_int_equal(judge(&cfg, &st, &f), INPUT_RX_RANGE);
	f = ws_fl(RAW_MIN - 1U, 0U);
	assert_int_equal(judge(&cfg, &st, &f), INPUT_RX_RANGE);
	/* the range refusal became the previous value: RAW_MIN is a step of 1
	 * from it */
	f = ws_fl(RAW_MIN, 0U);
	assert_int_equal(judge(&cfg, &st, &f), INPUT_RX_OK);
	/* the step: exactly step_max passes, one more is refused once, and
	 * the refused value is the reference of the next frame */
	f = ws_fl(RAW_MIN + RAW_STEP, 0U);
	assert_int_equal(judge(&cfg, &st, &f), INPUT_RX_OK);
	f = ws_fl(RAW_MIN + 2U * RAW_STEP + 1U, 0U);
	assert_int_equal(judge(&cfg, &st, &f), INPUT_RX_STEP);
	assert_int_equal(judge(&cfg, &st, &f), INPUT_RX_OK);
	/* a short frame is DLC before anything else */
	f.dlc = 1U;
	assert_int_equal(judge(&cfg, &st, &f), INPUT_RX_DLC);
}

static void test_protection_before_availability(void **state)
{
	/* MC_PRESS: raw 0xFFF ("not available") in bytes 2-3, counter 5 in
	 * byte 1, byte 0 not its CRC: the protection's verdict comes first */
	input_rx_cfg_t cfg;
	input_rx_state_t st;
	hal_can_frame_t f;
	bool id_only = false;

	(void)state;
	load();
	cfg = prepared(&cal.inputs[input_named("MC_PRESS")]);
	input_rx_state_init(&st);
	memset(&f, 0, sizeof(f));
	f.id = 0x1B0U;
	f.dlc = 8U;
	f.data[1] = 0x05U;
	f.data[2] = 0xFFU;
	f.data[3] = 0x0FU;
	assert_true(input_rx_matches(&cfg, &f, &id_only));
	assert_int_equal(input_rx_judge(&cfg, &st, &f).reason, INPUT_RX_CRC);
}

/* na_raw2: the second "not available" value of an input that also has
 * na_raw; RAW_1_KPH would otherwise be a usable value (inside the range,
 * no previous value) */
static void test_na_raw2_is_refused(void **state)
{
	static monitor_t m;
	calib_input_t *in;
	input_rx_cfg_t cfg;
	input_rx_state_t st;
	hal_can_frame_t f;
	input_rx_result_t r;

	(void)state;
	load();
	in = &cal.inputs[input_named("WS_FL")];
	assert_true((in->flags & CALIB_IN_NA) != 0U);
	/* without na_raw2 the value is used */
	cfg = prepared(in);
	input_rx_state_init(&st);
	f = ws_fl(RAW_1_KPH, 0U);
	assert_int_equal(judge(&cfg, &st, &f), INPUT_RX_OK);
	/* with it, refused as "not available", value still extracted */
	in->flags |= CALIB_IN_NA2;
	in->na_raw2 = RAW_1_KPH;
	assert_int_equal(calib_validate(&cal), SQ_OK);
	cfg = prepared(in);
	input_rx_state_init(&st);
	r = input_rx_judge(&cfg, &st, &f);
	assert_int_equal(r.reason, INPUT_RX_NA);
	assert_true(r.value == (int64_t)RAW_1_KPH);
	/* na_raw is still refused too, and another value used */
	f = ws_fl(0x7FFFU, 0U);
	assert_int_equal(judge(&cfg, &st, &f), INPUT_RX_NA);
	f = ws_fl(RAW_100_KPH, 0U);
	assert_int_equal(judge(&cfg, &st, &f), INPUT_RX_OK);

	/* the monitor records the verdict: not used, implausible, fault */
	assert_int_equal(monitor_init_corner(&m, &cal, 0U, false, 0U, 1000U), SQ_OK);
	m.now_us = 2000U;
	f = ws_fl(RAW_100_KPH, 0U);
	monitor_on_frame(&m, &f);
	assert_int_equal(m.speed.count.used, 1);
	assert_int_equal(m.speed.value, 11111111);
	f = ws_fl(RAW_1_KPH, 0U);
	monitor_on_frame(&m, &f);
	assert_int_equal(m.speed.count.frames, 2);
	assert_int_equal(m.speed.count.used, 1);
	assert_int_equal(m.speed.count.implausible, 1);
	assert_int_equal(m.speed.value, 11111111); /* the value before it */
	assert_true((monitor_fault_bits(&m) & MSG_FAULT_SPEED_IMPLAUSIBLE) != 0U);
}

/* The range's upper end is plausible: with max = 200 km/h a car at
 * exactly 200 km/h is used, one raw step more (200.01 km/h) is refused as
 * `range`. */
static void test_range_max_is_taken(void **state)
{
	calib_input_t *in;
	input_rx_cfg_t cfg;
	input_rx_state_t st;
	hal_can_frame_t f;
	input_rx_result_t r;

	(void)state;
	load();
	in = &cal.inputs[input_named("WS_FL")];
	in->max = (calib_dec_t){ 200, 0 };
	assert_int_equal(calib_validate(&cal), SQ_OK);
	cfg = prepared(in);
	assert_true(cfg.raw_max == RAW_MAX_200);
	input_rx_state_init(&st);
	f = ws_fl(RAW_MAX_200, 0U);
	r = input_rx_judge(&cfg, &st, &f);
	assert_int_equal(r.reason, INPUT_RX_OK);
	assert_true(r.value == (int64_t)RAW_MAX_200);
	/* a step of 1 from the previous value: only the range refuses it */
	f = ws_fl(RAW_MAX_200 + 1U, 0U);
	assert_int_equal(judge(&cfg, &st, &f), INPUT_RX_RANGE);
	/* the lower end likewise, from a fresh state (no step check) */
	input_rx_state_init(&st);
	f = ws_fl(RAW_MIN, 0U);
	assert_int_equal(judge(&cfg, &st, &f), INPUT_RX_OK);
}

/* exact_dlc: the legacy speed input (DiscSpeed, id 272, 16|16@1+ in a
 * 4-byte frame, docs/calib-input-map.md: "the DLC must equal min_dlc")
 * takes a 4-byte frame only; 3 or 5..8 bytes are `dlc`, the value never
 * used. Without E2E, so that only the length decides. */
static void test_exact_dlc_refuses_longer_frames(void **state)
{
	calib_t leg;
	calib_corner_t c;
	calib_input_t sp;
	calib_input_t fo;
	input_geom_t g;
	input_rx_cfg_t cfg;
	input_rx_state_t st;
	hal_can_frame_t f;
	input_rx_result_t r;
	uint8_t dlc;

	(void)state;
	calib_default(&leg);
	leg.e2e_check_inputs = 0U;
	assert_int_equal(calib_corner_view(&leg, 0U, &c, &sp, &fo), SQ_OK);
	assert_true((sp.flags & CALIB_IN_DLC_EXACT) != 0U);
	assert_int_equal(sp.min_dlc, 4U);
	g = calib_corner_geom(&c);
	assert_int_equal(input_rx_setup(&sp, &g, &cfg), SQ_OK);
	input_rx_state_init(&st);
	memset(&f, 0, sizeof(f));
	f.id = 272U;
	f.data[2] = 0xE8U; /* raw 1000 = 10 rad/s */
	f.data[3] = 0x03U;
	f.dlc = 4U;
	r = input_rx_judge(&cfg, &st, &f);
	assert_int_equal(r.reason, INPUT_RX_OK);
	assert_true(r.value == 1000);
	for (dlc = 5U; dlc <= 8U; dlc++) {
		f.dlc = dlc;
		assert_int_equal(judge(&cfg, &st, &f), INPUT_RX_DLC);
	}
	f.dlc = 3U;
	assert_int_equal(judge(&cfg, &st, &f), INPUT_RX_DLC);

	/* a map input with exact_dlc: WS_FL needs bytes 0..1 (Motorola 7|15,
	 * qualifier bit 8), so min_dlc 2: 2 bytes taken, 3 and 8 refused */
	load();
	cal.inputs[input_named("WS_FL")].flags |= CALIB_IN_DLC_EXACT;
	cal.inputs[input_named("WS_FL")].min_dlc = 2U;
	assert_int_equal(calib_validate(&cal), SQ_OK);
	cfg = prepared(&cal.inputs[input_named("WS_FL")]);
	input_rx_state_init(&st);
	f = ws_fl(RAW_100_KPH, 0U);
	f.dlc = 2U;
	assert_int_equal(judge(&cfg, &st, &f), INPUT_RX_OK);
	f.dlc = 3U;
	assert_int_equal(judge(&cfg, &st, &f), INPUT_RX_DLC);
	f.dlc = 8U;
	assert_int_equal(judge(&cfg, &st, &f), INPUT_RX_DLC);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_reason_names),
		cmocka_unit_test(test_checks_in_order),
		cmocka_unit_test(test_protection_before_availability),
		cmocka_unit_test(test_na_raw2_is_refused),
		cmocka_unit_test(test_range_max_is_taken),
		cmocka_unit_test(test_exact_dlc_refuses_longer_frames),
	};

#if defined(SQUEAL_NUMERIC_FIXED)
	return cmocka_run_group_tests_name("input verdict (fixed)", tests, NULL, NULL);
#else
	return cmocka_run_group_tests_name("input verdict (float)", tests, NULL, NULL);
#endif
}
