/* SPDX-License-Identifier: MIT */
/*
 * What a calibration's input map and corners mean
 * (firmware/monitor/calib_map.c), both numeric builds: the legacy form's
 * one corner on DiscSpeed/PadForce (squeal.dbc: BO_ 272 / 273, 16|16@1+,
 * factors 0.01 and 0.5, data IDs 0x2C51 / 0x2C52), a corner's defaults
 * (the flat keys, output identifiers 0x300.. + 0x10 per position), the
 * smallest DLC that holds every bit an input uses (worked by hand from the
 * DBC bit numbering), and calib_map_check() naming the input or corner of
 * each broken rule of calib_map.h / docs/calib-input-map.md.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "calib.h"
#include "calib_map.h"
#include "sq_status.h"

/* A speed input 0x200 (16|16@1+, 0.01 rad/s) and a force input 0x201
 * (0|16@1+, 0.5 N), one corner FL on them. */
static void two_input_map(calib_t *cal)
{
	calib_input_t *sp = &cal->inputs[0];
	calib_input_t *fo = &cal->inputs[1];

	calib_default(cal);
	cal->n_inputs = 2U;
	cal->n_corners = 1U;
	memset(sp, 0, sizeof(*sp));
	sp->id = 0x200U;
	sp->sig = (can_signal_t){ 16U, 16U, CAN_SIGNAL_INTEL, 0U };
	sp->factor = (calib_dec_t){ 1, -2 };
	sp->unit = (uint8_t)INPUT_UNIT_RADPS;
	sp->max = (calib_dec_t){ 600, 0 };
	sp->step_max = (calib_dec_t){ 10, 0 };
	sp->min_dlc = 4U;
	sp->period_ms = 10U;
	sp->stale_cycles = 3U;
	*fo = *sp;
	fo->id = 0x201U;
	fo->sig = (can_signal_t){ 0U, 16U, CAN_SIGNAL_INTEL, 0U };
	fo->factor = (calib_dec_t){ 5, -1 };
	fo->unit = (uint8_t)INPUT_UNIT_N;
	fo->max = (calib_dec_t){ 30000, 0 };
	fo->step_max = (calib_dec_t){ 10000, 0 };
	fo->min_dlc = 2U;
	calib_corner_defaults(cal, 0U, &cal->corners[0]);
	cal->corners[0].speed_input = 0U;
	cal->corners[0].force_input = 1U;
}

static void test_legacy_form_is_one_corner_on_disc_speed_and_pad_force(void **state)
{
	calib_t cal;
	calib_corner_t c;
	calib_input_t sp;
	calib_input_t fo;

	(void)state;
	calib_default(&cal);
	assert_int_equal(calib_corner_count(&cal), 1U);
	assert_int_equal(calib_map_validate(&cal), SQ_OK);
	assert_int_equal(calib_corner_view(&cal, 0U, &c, &sp, &fo), SQ_OK);
	assert_int_equal(c.pos, 0U);
	assert_int_equal(c.status_id, 0x300U);
	assert_int_equal(c.detail_id, 0x301U);
	assert_int_equal(c.diag_id, 0x302U);
	assert_int_equal(c.detail2_id, 0x303U);
	assert_int_equal(sp.id, 272U);
	assert_int_equal(fo.id, 273U);
	assert_int_equal(sp.sig.start_bit, 16U);
	assert_int_equal(sp.sig.length, 16U);
	assert_int_equal(fo.sig.start_bit, 16U);
	assert_true(sp.factor.mant == 1 && sp.factor.exp == -2);
	assert_true(fo.factor.mant == 5 && fo.factor.exp == -1);
	assert_int_equal(sp.unit, INPUT_UNIT_RADPS);
	assert_int_equal(fo.unit, INPUT_UNIT_N);
	assert_int_equal(sp.protection, CALIB_PROT_P01); /* e2e_check_inputs = 1 */
	assert_int_equal(sp.data_id, 0x2C51U);
	assert_int_equal(fo.data_id, 0x2C52U);
	assert_int_equal(sp.min_dlc, 4U);
	assert_int_equal(calib_input_needed_dlc(&sp), 4U);
	assert_int_equal(calib_corner_view(&cal, 1U, &c, &sp, &fo), SQ_EINVAL);
	/* the legacy form without E2E: no protection */
	cal.e2e_check_inputs = 0U;
	assert_int_equal(calib_corner_view(&cal, 0U, &c, &sp, &fo), SQ_OK);
	assert_int_equal(sp.protection, CALIB_PROT_NONE);
}

static void test_corner_defaults_follow_the_flat_keys_and_position(void **state)
{
	calib_t cal;
	calib_corner_t c;

	(void)state;
	calib_default(&cal);
	calib_corner_defaults(&cal, 3U, &c);
	assert_int_equal(c.pos, 3U);
	assert_int_equal(c.status_id, 0x330U);
	assert_int_equal(c.detail_id, 0x331U);
	assert_int_equal(c.diag_id, 0x332U);
	assert_int_equal(c.detail2_id, 0x333U);
	assert_int_equal(c.friction_faces, 2U);
	assert_int_equal(c.efficiency_ppm, 1000000U);
	assert_int_equal(c.axle_factor_ppm, 1000000U);
	assert_int_equal(c.torque_share_ppm, 1000000U);
	assert_int_equal(c.mass_q16, cal.mass_q16);
	assert_int_equal(c.pad_radius_um, 120000U);
	assert_int_equal(c.wheel_radius_um, 300000U);
	/* corner <-> flat keys */
	c.mass_q16 = 3 * 65536;
	c.status_id = 0x400U;
	calib_flat_from_corner(&c, &cal);
	assert_int_equal(cal.mass_q16, 3 * 65536);
	assert_int_equal(cal.status_id, 0x400U);
	memset(&c, 0, sizeof(c));
	calib_corner_from_flat(&cal, &c);
	assert_int_equal(c.mass_q16, 3 * 65536);
	assert_int_equal(c.status_id, 0x400U);
	/* the corner's geometry for the conversion */
	c.piston_area_cmm2 = 123456U;
	c.efficiency_ppm = 950000U;
	c.axle_factor_ppm = 500000U;
	{
		const input_geom_t g = calib_corner_geom(&c);

		assert_int_equal(g.pad_radius_um, 120000U);
		assert_int_equal(g.wheel_radius_um, 300000U);
		assert_int_equal(g.piston_area_cmm2, 123456U);
		assert_int_equal(g.efficiency_ppm, 950000U);
		assert_int_equal(g.axle_factor_ppm, 500000U);
	}
}

static void test_needed_dlc_holds_every_bit_used(void **state)
{
	calib_input_t in;

	(void)state;
	memset(&in, 0, sizeof(in));
	in.sig = (can_signal_t){ 24U, 8U, CAN_SIGNAL_INTEL, 0U }; /* byte 3 */
	assert_int_equal(calib_input_needed_dlc(&in), 4U);
	in.sig = (can_signal_t){ 0U, 8U, CAN_SIGNAL_INTEL, 0U };  /* byte 0 */
	assert_int_equal(calib_input_needed_dlc(&in), 1U);
	in.protection = CALIB_PROT_P01; /* CRC byte 0, counter byte 1 */
	assert_int_equal(calib_input_needed_dlc(&in), 2U);
	in.protection = CALIB_PROT_COUNTER;
	in.counter = (can_signal_t){ 44U, 4U, CAN_SIGNAL_INTEL, 0U }; /* byte 5 */
	assert_int_equal(calib_input_needed_dlc(&in), 6U);
	in.protection = CALIB_PROT_NONE;
	in.flags = CALIB_IN_QUALIFIER;
	in.qualifier_bit = 63U; /* byte 7 */
	assert_int_equal(calib_input_needed_dlc(&in), 8U);
	in.flags = CALIB_IN_MUX;
	in.mux = (can_signal_t){ 47U, 8U, CAN_SIGNAL_MOTOROLA, 0U }; /* 47..40: byte 5 */
	assert_int_equal(calib_input_needed_dlc(&in), 6U);
	in.sig.length = 0U; /* a bad signal */
	assert_int_equal(calib_input_needed_dlc(&in), 0U);
	assert_int_equal(calib_input_needed_dlc(NULL), 0U);
}

static void test_a_valid_map_and_its_views(void **state)
{
	calib_t cal;
	calib_corner_t c;
	calib_input_t sp;
	calib_input_t fo;

	(void)state;
	two_input_map(&cal);
	assert_int_equal(calib_map_validate(&cal), SQ_OK);
	assert_int_equal(calib_corner_count(&cal), 1U);
	assert_int_equal(calib_corner_view(&cal, 0U, &c, &sp, &fo), SQ_OK);
	assert_int_equal(sp.id, 0x200U);
	assert_int_equal(fo.id, 0x201U);
	assert_int_equal(fo.conv_share_ppm, 0U); /* a force: no share */
	/* a torque input carries the corner's share on its copy only */
	cal.inputs[1].unit = (uint8_t)INPUT_UNIT_NM;
	cal.corners[0].torque_share_ppm = 250000U;
	assert_int_equal(calib_corner_view(&cal, 0U, &c, &sp, &fo), SQ_OK);
	assert_int_equal(fo.conv_share_ppm, 250000U);
	assert_int_equal(sp.conv_share_ppm, 0U);
	assert_int_equal(cal.inputs[1].conv_share_ppm, 0U);
}

typedef enum {
	BREAK_STD_ID_ABOVE_7FF,
	BREAK_SIGNAL_LENGTH_0,
	BREAK_FORCE_UNDER_P01_HEADER,
	BREAK_MAX_BELOW_MIN,
	BREAK_MIN_DLC_TOO_SHORT,
	BREAK_UNKNOWN_UNIT,
	BREAK_MUX2_WITHOUT_MUX,
	BREAK_CORNER_UNKNOWN_INPUT,
	BREAK_CORNER_SPEED_AS_FORCE,
	BREAK_CORNER_FORCE_AS_SPEED,
	BREAK_OUTPUT_ID_IS_AN_INPUT,
	BREAK_TWO_CORNERS_ONE_POSITION,
	BREAK_CORNERS_WITHOUT_INPUTS,
	BREAK_INPUTS_WITHOUT_CORNERS,
} breakage_t;

static void apply(calib_t *cal, breakage_t b)
{
	switch (b) {
	case BREAK_STD_ID_ABOVE_7FF: cal->inputs[1].id = 0x800U; break;
	case BREAK_SIGNAL_LENGTH_0: cal->inputs[0].sig.length = 0U; break;
	case BREAK_FORCE_UNDER_P01_HEADER: /* 0|16 holds the CRC byte */
		cal->inputs[1].protection = CALIB_PROT_P01;
		cal->inputs[1].max_delta_counter = 1U;
		break;
	case BREAK_MAX_BELOW_MIN: cal->inputs[0].min = (calib_dec_t){ 700, 0 }; break;
	case BREAK_MIN_DLC_TOO_SHORT: cal->inputs[0].min_dlc = 3U; break; /* 16|16 ends in byte 3 */
	case BREAK_UNKNOWN_UNIT: cal->inputs[1].unit = (uint8_t)INPUT_UNIT_COUNT; break;
	case BREAK_MUX2_WITHOUT_MUX: cal->inputs[0].flags = CALIB_IN_MUX2; break;
	case BREAK_CORNER_UNKNOWN_INPUT: cal->corners[0].speed_input = 2U; break;
	case BREAK_CORNER_SPEED_AS_FORCE: cal->corners[0].force_input = 0U; break;
	case BREAK_CORNER_FORCE_AS_SPEED: cal->corners[0].speed_input = 1U; break;
	case BREAK_OUTPUT_ID_IS_AN_INPUT: cal->corners[0].diag_id = 0x201U; break;
	case BREAK_TWO_CORNERS_ONE_POSITION:
		cal->corners[1] = cal->corners[0];
		cal->n_corners = 2U;
		break;
	case BREAK_CORNERS_WITHOUT_INPUTS: cal->n_inputs = 0U; break;
	case BREAK_INPUTS_WITHOUT_CORNERS: cal->n_corners = 0U; break;
	default: fail(); break;
	}
}

static void test_each_broken_rule_is_named_at_its_input_or_corner(void **state)
{
	static const struct {
		breakage_t b;
		int8_t input;
		int8_t corner;
	} cases[] = {
		{ BREAK_STD_ID_ABOVE_7FF, 1, -1 },
		{ BREAK_SIGNAL_LENGTH_0, 0, -1 },
		{ BREAK_FORCE_UNDER_P01_HEADER, 1, -1 },
		{ BREAK_MAX_BELOW_MIN, 0, -1 },
		{ BREAK_MIN_DLC_TOO_SHORT, 0, -1 },
		{ BREAK_UNKNOWN_UNIT, 1, -1 },
		{ BREAK_MUX2_WITHOUT_MUX, 0, -1 },
		{ BREAK_CORNER_UNKNOWN_INPUT, -1, 0 },
		{ BREAK_CORNER_SPEED_AS_FORCE, -1, 0 },
		{ BREAK_CORNER_FORCE_AS_SPEED, -1, 0 },
		{ BREAK_OUTPUT_ID_IS_AN_INPUT, -1, 0 },
		{ BREAK_TWO_CORNERS_ONE_POSITION, -1, 1 },
		{ BREAK_CORNERS_WITHOUT_INPUTS, -1, -1 },
		{ BREAK_INPUTS_WITHOUT_CORNERS, -1, -1 },
	};
	size_t i;

	(void)state;
	for (i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
		calib_t cal;
		calib_map_error_t err = { 99, 99, NULL };
		const char *why = NULL;

		two_input_map(&cal);
		apply(&cal, cases[i].b);
		assert_int_equal(calib_map_check(&cal, &err), SQ_EINVAL);
		assert_int_equal(calib_map_validate(&cal), SQ_EINVAL);
		assert_int_equal(err.input, cases[i].input);
		assert_int_equal(err.corner, cases[i].corner);
		assert_non_null(err.why);
		if (cases[i].input >= 0) {
			/* the input alone says the same */
			assert_int_equal(calib_input_check(&cal.inputs[cases[i].input], &why), SQ_EINVAL);
			assert_string_equal(why, err.why);
		}
	}
}

/* period 1..1000 ms at both ends; two corners never share a position */
static void test_period_bounds(void **state)
{
	calib_t cal;
	const char *why = NULL;

	(void)state;
	two_input_map(&cal);
	cal.inputs[0].period_ms = 1000U;
	assert_int_equal(calib_input_check(&cal.inputs[0], &why), SQ_OK);
	assert_int_equal(calib_map_validate(&cal), SQ_OK);
	cal.inputs[0].period_ms = 1001U;
	assert_int_equal(calib_input_check(&cal.inputs[0], &why), SQ_EINVAL);
	assert_string_equal(why, "period_ms 1..1000 and stale_cycles 1..100");
	assert_int_equal(calib_map_validate(&cal), SQ_EINVAL);
	cal.inputs[0].period_ms = 1U;
	assert_int_equal(calib_input_check(&cal.inputs[0], &why), SQ_OK);
	cal.inputs[0].period_ms = 0U;
	assert_int_equal(calib_input_check(&cal.inputs[0], &why), SQ_EINVAL);
}

static void test_two_corners_one_position_refused(void **state)
{
	calib_t cal;

	(void)state;
	two_input_map(&cal);
	cal.n_corners = 2U;
	calib_corner_defaults(&cal, 1U, &cal.corners[1]);
	cal.corners[1].speed_input = 0U;
	cal.corners[1].force_input = 1U;
	assert_int_equal(calib_map_validate(&cal), SQ_OK); /* FL and FR */
	cal.corners[1].pos = cal.corners[0].pos;
	assert_int_equal(calib_map_validate(&cal), SQ_EINVAL);
}

/* a rolling counter of 4 bits counting 0..11: a jump of 11 is the largest */
static void test_counter_delta_bounds(void **state)
{
	calib_t cal;
	calib_input_t *in = &cal.inputs[0];
	const char *why = NULL;

	(void)state;
	two_input_map(&cal);
	in->protection = (uint8_t)CALIB_PROT_COUNTER;
	in->counter = (can_signal_t){ 0U, 4U, CAN_SIGNAL_INTEL, 0U }; /* byte 0, clear of bits 16..31 */
	in->counter_modulus = 12U;
	in->max_delta_counter = 11U;
	assert_int_equal(calib_input_check(in, &why), SQ_OK);
	in->max_delta_counter = 12U;
	assert_int_equal(calib_input_check(in, &why), SQ_EINVAL);
	assert_string_equal(why, "max_delta_counter out of range (1 .. counter_modulus - 1)");
	in->max_delta_counter = 0U;
	assert_int_equal(calib_input_check(in, &why), SQ_EINVAL);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_legacy_form_is_one_corner_on_disc_speed_and_pad_force),
		cmocka_unit_test(test_corner_defaults_follow_the_flat_keys_and_position),
		cmocka_unit_test(test_needed_dlc_holds_every_bit_used),
		cmocka_unit_test(test_a_valid_map_and_its_views),
		cmocka_unit_test(test_period_bounds),
		cmocka_unit_test(test_two_corners_one_position_refused),
		cmocka_unit_test(test_counter_delta_bounds),
		cmocka_unit_test(test_each_broken_rule_is_named_at_its_input_or_corner),
	};

	return cmocka_run_group_tests_name("calib_map", tests, NULL, NULL);
}
