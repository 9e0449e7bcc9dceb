/* SPDX-License-Identifier: MIT */
/*
 * host-sim/plant_vehicle.c on the fixture layout tests/host-sim/two_corners.cal
 * (run from the top of the checkout, as make test does): the frames of the
 * map, each input's physical value at an operating point, and the bytes
 * packed, all worked out by hand from the fixture's comments:
 *   r_p 0.15 m, r_w 0.3 m: disc surface v0 = vehicle * 0.5, wheel
 *   omega = vehicle / 0.3; FL pressure p = N / (2000 mm^2 * 0.8);
 *   FR torque total T = N * 2 faces * mu(v0) * r_p / 0.5 share with
 *   mu(v0) = 0.3 + 0.2 exp(-v0).
 * A value beyond the signal is clamped to its top raw value, one below it
 * when that is the input's "not available" code (a decoder must never read
 * a real, if saturated, speed as "not available"); an alive counter
 * (protection = counter) counts 0 .. counter_modulus - 1 and wraps there.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "calib_text.h"
#include "plant_vehicle.h"
#include "sq_cmocka.h"

#define FIXTURE "tests/host-sim/two_corners.cal"

static calib_t cal;

static void load(void)
{
	calib_names_t names;
	char err[300] = "";
	int rc = calib_text_load_map(FIXTURE, &cal, &names, err, sizeof(err));

	if (rc != 0) {
		fail_msg("%s", err);
	}
}

static void test_frames_of_the_map(void **state)
{
	plant_vframe_t fr[CALIB_MAX_INPUTS];

	(void)state;
	load();
	assert_int_equal(plant_vehicle_frames(&cal, fr), 3);
	/* 0x120 carries both speeds: the shorter period, 8 bytes, no E2E */
	assert_int_equal(fr[0].id, 0x120);
	assert_false(fr[0].ext);
	assert_false(fr[0].fd);
	assert_int_equal(fr[0].n, 2);
	assert_int_equal(fr[0].in[0], 0);
	assert_int_equal(fr[0].in[1], 1);
	assert_int_equal(fr[0].period_ms, 10);
	assert_int_equal(fr[0].dlc, 8);
	assert_int_equal(fr[0].prot, 0xFF);
	assert_int_equal(fr[1].id, 0x130);
	assert_int_equal(fr[1].n, 1);
	assert_int_equal(fr[1].in[0], 2);
	assert_int_equal(fr[2].id, 0x140);
	assert_true(fr[2].ext);
	assert_int_equal(fr[2].in[0], 3);

	/* the legacy form (no [corner]) has none */
	cal.n_corners = 0U;
	assert_int_equal(plant_vehicle_frames(&cal, fr), 0);
}

static void test_physical_in_each_unit(void **state)
{
	const double mu_at_5 = 0.3 + 0.2 * exp(-5.0);

	(void)state;
	load();
	/* 10 m/s: 36 km/h; 10 / 0.3 rad/s = 318.3099 rpm */
	assert_true(fabs(plant_vehicle_physical(&cal, 0, 10.0, 14400.0) - 36.0) <= 1e-12);
	assert_true(fabs(plant_vehicle_physical(&cal, 1, 10.0, 14400.0) - (10.0 / 0.3 * 60.0 / (2.0 * M_PI))) <= 1e-9);
	/* 14400 N on 2000 mm^2 at eta 0.8: 9 MPa = 90 bar */
	assert_true(fabs(plant_vehicle_physical(&cal, 2, 10.0, 14400.0) - 90.0) <= 1e-9);
	/* 1000 N at v0 = 5 m/s: 1000 * 2 * mu * 0.15 / 0.5 = 600 mu Nm (mu in
	 * Q30, so within 1e-9 of the decimal) */
	assert_true(fabs(plant_vehicle_physical(&cal, 3, 10.0, 1000.0) - 600.0 * mu_at_5) <= 1e-6);
}

/* The same inputs read in the other units (definitions: 1 mph = 0.44704
 * m/s exactly, 1 psi = 6894.757293 Pa, NIST SP 811): 10 m/s = 22.369363
 * mph; 9 MPa = 1305.3404 psi = 9000 kPa = 9 MPa; 14400 N = 14.4 kN. */
static void test_physical_in_the_other_units(void **state)
{
	(void)state;
	load();
	cal.inputs[0].unit = (uint8_t)INPUT_UNIT_MPH;
	assert_true(fabs(plant_vehicle_physical(&cal, 0, 10.0, 14400.0) - 10.0 / 0.44704) <= 1e-9);
	cal.inputs[0].unit = (uint8_t)INPUT_UNIT_MPS;
	assert_true(fabs(plant_vehicle_physical(&cal, 0, 10.0, 14400.0) - 10.0) <= 1e-12);
	cal.inputs[2].unit = (uint8_t)INPUT_UNIT_PSI;
	assert_true(fabs(plant_vehicle_physical(&cal, 2, 10.0, 14400.0) - 9e6 / 6894.757293) <= 1e-7 * 1305.34);
	cal.inputs[2].unit = (uint8_t)INPUT_UNIT_KPA;
	assert_true(fabs(plant_vehicle_physical(&cal, 2, 10.0, 14400.0) - 9000.0) <= 1e-9);
	cal.inputs[2].unit = (uint8_t)INPUT_UNIT_MPA;
	assert_true(fabs(plant_vehicle_physical(&cal, 2, 10.0, 14400.0) - 9.0) <= 1e-12);
}

static void test_pack(void **state)
{
	plant_vframe_t fr[CALIB_MAX_INPUTS];
	e2e_p01_tx_t tx = { 0 };
	hal_can_frame_t f;
	uint64_t sat = 0;
	/* 36 km/h at 0.01: 3600 = 0x0E10; 318.3099 rpm at 0.1: 3183 = 0x0C6F */
	static const uint8_t speeds[8] = { 0x10, 0x0E, 0x6F, 0x0C, 0, 0, 0, 0 };
	/* 90 bar = (raw * 0.1) - 10: raw 1000 = 0x03E8 */
	static const uint8_t pressure[8] = { 0xE8, 0x03, 0, 0, 0, 0, 0, 0 };

	(void)state;
	load();
	assert_int_equal(plant_vehicle_frames(&cal, fr), 3);
	plant_vehicle_pack(&cal, &fr[0], &tx, 10.0, 14400.0, &f, &sat);
	assert_int_equal(f.id, 0x120);
	assert_int_equal(f.flags, 0);
	assert_int_equal(f.dlc, 8);
	assert_memory_equal(f.data, speeds, sizeof(speeds));
	plant_vehicle_pack(&cal, &fr[1], &tx, 10.0, 14400.0, &f, &sat);
	assert_memory_equal(f.data, pressure, sizeof(pressure));
	/* 0 N: 0 bar is raw 100 (the offset) */
	plant_vehicle_pack(&cal, &fr[1], &tx, 10.0, 0.0, &f, &sat);
	assert_int_equal(f.data[0] | (f.data[1] << 8), 100);
	assert_int_equal(sat, 0);
	plant_vehicle_pack(&cal, &fr[2], &tx, 10.0, 1000.0, &f, &sat);
	assert_int_equal(f.flags, HAL_CAN_FLAG_EXT);
	/* 600 mu(5) = 180.81 Nm, 1 Nm per bit from bit 8 */
	assert_int_equal(f.data[1] | (f.data[2] << 8), 181);
	assert_int_equal(f.data[0], 0);

	/* 200 m/s is 720 km/h: beyond 16 bits at 0.01, clamped to 65535 and
	 * counted; 6366.2 rpm (raw 63662) still fits */
	plant_vehicle_pack(&cal, &fr[0], &tx, 200.0, 0.0, &f, &sat);
	assert_int_equal(f.data[0] | (f.data[1] << 8), 65535);
	assert_int_equal(f.data[2] | (f.data[3] << 8), 63662);
	assert_int_equal(sat, 1);
}

/* 200 m/s (720 km/h at 0.01: raw 72000) is beyond WS_FL's 16 bits: with
 * na_raw 0xFFFF the sender stops at 0xFFFE, so the frame never says "not
 * available"; a na_raw elsewhere (0x8000) leaves the top at 0xFFFF. */
static void test_clamp_stays_clear_of_not_available(void **state)
{
	plant_vframe_t fr[CALIB_MAX_INPUTS];
	e2e_p01_tx_t tx = { 0 };
	hal_can_frame_t f;
	uint64_t sat = 0;

	(void)state;
	load();
	cal.inputs[0].flags |= CALIB_IN_NA;
	cal.inputs[0].na_raw = 0xFFFFU;
	assert_int_equal(plant_vehicle_frames(&cal, fr), 3);
	plant_vehicle_pack(&cal, &fr[0], &tx, 200.0, 0.0, &f, &sat);
	assert_int_equal(f.data[0] | (f.data[1] << 8), 0xFFFE);
	assert_int_equal(sat, 1);
	/* 100 m/s = 36000 raw: in range, untouched */
	plant_vehicle_pack(&cal, &fr[0], &tx, 100.0, 0.0, &f, &sat);
	assert_int_equal(f.data[0] | (f.data[1] << 8), 36000);
	assert_int_equal(sat, 1);
	cal.inputs[0].na_raw = 0x8000U;
	plant_vehicle_pack(&cal, &fr[0], &tx, 200.0, 0.0, &f, &sat);
	assert_int_equal(f.data[0] | (f.data[1] << 8), 0xFFFF);
	assert_int_equal(sat, 2);
}

/* P_FL (0x130, alone in its frame) with an alive counter of 4 bits at bit
 * 16 that wraps at 10: frame k carries k mod 10, 0..9, 0..9, 0.. */
static void test_alive_counter_wraps_at_its_modulus(void **state)
{
	plant_vframe_t fr[CALIB_MAX_INPUTS];
	e2e_p01_tx_t tx = { 0 };
	hal_can_frame_t f;
	uint64_t sat = 0;
	calib_input_t *in;

	(void)state;
	load();
	in = &cal.inputs[2];
	in->protection = (uint8_t)CALIB_PROT_COUNTER;
	in->counter = (can_signal_t){ 16U, 4U, (uint8_t)CAN_SIGNAL_INTEL, 0U };
	in->counter_modulus = 10U;
	assert_int_equal(plant_vehicle_frames(&cal, fr), 3);
	assert_int_equal(fr[1].id, 0x130);
	assert_int_equal(fr[1].prot, 2);
	for (uint32_t k = 0U; k < 35U; k++) {
		plant_vehicle_pack(&cal, &fr[1], &tx, 10.0, 14400.0, &f, &sat);
		assert_int_equal(f.data[2] & 0x0FU, k % 10U);
		/* the value beside it as without a counter: 90 bar, raw 1000 */
		assert_int_equal(f.data[0] | (f.data[1] << 8), 1000);
	}
	assert_int_equal(sat, 0);
}

SQ_CMOCKA_MAIN(
	cmocka_unit_test(test_frames_of_the_map),
	cmocka_unit_test(test_physical_in_each_unit),
	cmocka_unit_test(test_physical_in_the_other_units),
	cmocka_unit_test(test_pack),
	cmocka_unit_test(test_clamp_stays_clear_of_not_available),
	cmocka_unit_test(test_alive_counter_wraps_at_its_modulus))
