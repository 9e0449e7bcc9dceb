/* SPDX-License-Identifier: MIT */
#include "calib_map.h"

#include <stddef.h>

#include "e2e_p05.h"
#include "hal.h"
#include "input_conv.h"
#include "sq_status.h"
#include "squeal_msgs.h"

/* calib_input_prepare() with the share given apart from the descriptor
 * (the validation checks the stored inputs in place, without the copies
 * calib_corner_view() makes: the ECU's start-up stack). */
static int prepare_share(const calib_input_t *in, uint32_t share_ppm, const input_geom_t *geom,
			 input_conv_t *conv, input_raw_bounds_t *bounds, const char **why);

#define STD_ID_MAX 0x7FFU
#define CORNER_ID_STEP 0x10U

static bool bit_in(const can_signal_t *s, uint16_t bit)
{
	const can_signal_t b = { bit, 1U, (uint8_t)CAN_SIGNAL_INTEL, 0U };

	return can_signal_overlap(s, &b);
}

uint8_t calib_input_needed_dlc(const calib_input_t *in)
{
	uint8_t need;
	uint8_t d;

	if (in == NULL) {
		return 0U;
	}
	need = can_signal_min_dlc(&in->sig);
	if (need == 0U) {
		return 0U;
	}
	if ((in->flags & CALIB_IN_MUX) != 0U) {
		d = can_signal_min_dlc(&in->mux);
		need = (d > need) ? d : need;
	}
	if ((in->flags & CALIB_IN_MUX2) != 0U) {
		d = can_signal_min_dlc(&in->mux2);
		need = (d > need) ? d : need;
	}
	if ((in->flags & CALIB_IN_QUALIFIER) != 0U) {
		d = (uint8_t)((in->qualifier_bit / 8U) + 1U);
		need = (d > need) ? d : need;
	}
	if ((in->protection == (uint8_t)CALIB_PROT_P01) ||
	    (in->protection == (uint8_t)CALIB_PROT_P02)) {
		need = (need < 2U) ? 2U : need;
	}
	if (in->protection == (uint8_t)CALIB_PROT_P05) {
		d = (uint8_t)(in->e2e_offset_byte + E2E_P05_HEADER_LEN);
		need = (d > need) ? d : need;
	}
	if (in->protection == (uint8_t)CALIB_PROT_COUNTER) {
		d = can_signal_min_dlc(&in->counter);
		need = (d > need) ? d : need;
	}
	return need;
}

uint8_t calib_input_frame_len(const calib_input_t *in)
{
	const uint8_t need = calib_input_needed_dlc(in);
	uint8_t code;

	if ((need == 0U) || (in->fd == 0U) || (need <= HAL_CAN_CLASSIC_MAX_DLEN)) {
		return need;
	}
	for (code = 9U; code < 16U; code++) {
		if (hal_can_dlc_to_len(code) >= need) {
			return hal_can_dlc_to_len(code);
		}
	}
	return 0U; /* unreachable: a valid signal ends within 64 bytes */
}

static int fail(const char **why, const char *msg)
{
	*why = msg;
	return SQ_EINVAL;
}

/* The P05 header: CRC (2 bytes) and counter at e2e_offset_byte. */
static can_signal_t p05_header(const calib_input_t *in)
{
	return (can_signal_t){ (uint16_t)(8U * in->e2e_offset_byte), 8U * E2E_P05_HEADER_LEN,
			       (uint8_t)CAN_SIGNAL_INTEL, 0U };
}

/* raw values that fit the signal */
static bool fits(const can_signal_t *s, uint32_t v)
{
	return (s->length >= 32U) || (v < (1UL << s->length));
}

static int check_protection(const calib_input_t *in, const char **why)
{
	const can_signal_t header = { 0U, 12U, (uint8_t)CAN_SIGNAL_INTEL, 0U }; /* CRC + counter nibble */

	switch (in->protection) {
	case CALIB_PROT_NONE:
		return SQ_OK;
	case CALIB_PROT_P01:
	case CALIB_PROT_P02:
		if (in->fd != 0U) {
			/* their CRCs cover a classic frame (2..8 bytes); an FD
			 * frame of the id would be a contract failure there */
			return fail(why, "protection p01 and p02 protect classic frames: fd = yes needs p05, counter or none");
		}
		if (can_signal_overlap(&in->sig, &header)) {
			return fail(why, "signal overlaps the E2E CRC byte or counter nibble");
		}
		if ((in->max_delta_counter < 1U) ||
		    (in->max_delta_counter > ((in->protection == (uint8_t)CALIB_PROT_P01) ? 14U : 15U))) {
			return fail(why, "max_delta_counter out of range (p01 1..14, p02 1..15)");
		}
		return SQ_OK;
	case CALIB_PROT_P05: {
		const can_signal_t h = p05_header(in);

		if (((uint32_t)in->e2e_offset_byte + E2E_P05_HEADER_LEN) > in->min_dlc) {
			return fail(why, "e2e_offset_byte: the P05 CRC and counter (3 bytes from it) run beyond min_dlc");
		}
		if (can_signal_overlap(&in->sig, &h)) {
			return fail(why, "signal overlaps the P05 CRC or counter (e2e_offset_byte .. +2)");
		}
		if (in->max_delta_counter < 1U) {
			return fail(why, "max_delta_counter out of range (p05 1..255)");
		}
		return SQ_OK;
	}
	case CALIB_PROT_COUNTER:
		if (!can_signal_valid(&in->counter) || (in->counter.length > 4U)) {
			return fail(why, "counter signal: length 1..4 within the frame");
		}
		if (can_signal_overlap(&in->counter, &in->sig)) {
			return fail(why, "counter overlaps the value signal");
		}
		if ((in->counter_modulus < 2U) || (in->counter_modulus > (1U << in->counter.length))) {
			return fail(why, "counter_modulus out of range (2 .. 2^counter_length)");
		}
		if ((in->max_delta_counter < 1U) || (in->max_delta_counter >= in->counter_modulus)) {
			return fail(why, "max_delta_counter out of range (1 .. counter_modulus - 1)");
		}
		return SQ_OK;
	default:
		return fail(why, "unknown protection");
	}
}

/* The E2E header or counter a selector must keep out of, if any. */
static bool in_header(const calib_input_t *in, const can_signal_t *sel)
{
	const can_signal_t header = { 0U, 12U, (uint8_t)CAN_SIGNAL_INTEL, 0U };

	if ((in->protection == (uint8_t)CALIB_PROT_P01) ||
	    (in->protection == (uint8_t)CALIB_PROT_P02)) {
		return can_signal_overlap(sel, &header);
	}
	if (in->protection == (uint8_t)CALIB_PROT_P05) {
		const can_signal_t h = p05_header(in);

		return can_signal_overlap(sel, &h);
	}
	if (in->protection == (uint8_t)CALIB_PROT_COUNTER) {
		return can_signal_overlap(sel, &in->counter);
	}
	return false;
}

/* One selector condition: a valid signal clear of the value, the
 * qualifier bit and the E2E header, and a range value .. value_max that
 * fits it. The messages start with the key they are about. */
static int check_selector(const calib_input_t *in, const can_signal_t *sel, uint32_t lo,
			  uint32_t hi, bool second, const char **why)
{
	if (!can_signal_valid(sel)) {
		return fail(why, second ? "mux2_length: the selector runs beyond the frame or has a bad length" :
			    "mux_length: the selector runs beyond the frame or has a bad length");
	}
	if (can_signal_overlap(sel, &in->sig)) {
		return fail(why, second ? "mux2_start_bit: the selector overlaps the value signal" :
			    "mux_start_bit: the selector overlaps the value signal");
	}
	if (((in->flags & CALIB_IN_QUALIFIER) != 0U) && bit_in(sel, in->qualifier_bit)) {
		return fail(why, second ? "mux2_start_bit: the selector holds the qualifier bit" :
			    "mux_start_bit: the selector holds the qualifier bit");
	}
	if (in_header(in, sel)) {
		return fail(why, second ? "mux2_start_bit: the selector overlaps the E2E CRC, counter or counter signal" :
			    "mux_start_bit: the selector overlaps the E2E CRC, counter or counter signal");
	}
	if (!fits(sel, lo)) {
		return fail(why, second ? "mux2_value does not fit the selector" :
			    "mux_value does not fit the selector");
	}
	if ((hi < lo) || !fits(sel, hi)) {
		return fail(why, second ? "mux2_value_max below mux2_value or beyond the selector" :
			    "mux_value_max below mux_value or beyond the selector");
	}
	return SQ_OK;
}

static int check_selectors(const calib_input_t *in, const char **why)
{
	const bool mux = (in->flags & CALIB_IN_MUX) != 0U;
	const bool mux2 = (in->flags & CALIB_IN_MUX2) != 0U;

	if (mux2 && !mux) {
		return fail(why, "mux2_start_bit: a second selector needs the first (mux_*)");
	}
	if (mux && (check_selector(in, &in->mux, in->mux_value, in->mux_value_max, false, why) != SQ_OK)) {
		return SQ_EINVAL;
	}
	if (mux2) {
		if (check_selector(in, &in->mux2, in->mux2_value, in->mux2_value_max, true, why) != SQ_OK) {
			return SQ_EINVAL;
		}
		if (can_signal_overlap(&in->mux, &in->mux2)) {
			return fail(why, "mux2_start_bit: the two selectors overlap");
		}
	}
	return SQ_OK;
}

/* The decimals in range, max >= min, and a raw value between them. */
static int check_range(const calib_input_t *in, const char **why)
{
	input_raw_bounds_t b;

	if (!input_dec_valid(in->factor)) {
		return fail(why, "factor beyond 17 significant digits or exponent -30..30");
	}
	if (!input_dec_valid(in->offset)) {
		return fail(why, "offset beyond 17 significant digits or exponent -30..30");
	}
	if (!input_dec_valid(in->max) || !input_dec_valid(in->min) || !input_dec_valid(in->step_max)) {
		return fail(why, "max, min and step_max: at most 17 significant digits, exponent -30..30");
	}
	if (in->step_max.mant <= 0) {
		return fail(why, "step_max must be > 0");
	}
	if (input_dec_cmp(in->max, in->min) < 0) {
		return fail(why, "max is below min");
	}
	if (input_conv_raw_bounds(in->factor, in->offset, in->min, in->max, in->step_max, &b) != SQ_OK) {
		return fail(why, "max: no raw value of the signal lies within min .. max (a factor's step apart)");
	}
	return SQ_OK;
}

/* The frame format: classic up to 8 bytes, FD with its lengths. */
static int check_format(const calib_input_t *in, const char **why)
{
	if (in->fd > 1U) {
		return fail(why, "fd must be yes or no");
	}
	if ((in->fd == 0U) && (can_signal_min_dlc(&in->sig) > HAL_CAN_CLASSIC_MAX_DLEN)) {
		return fail(why, "start_bit: the value runs beyond the 8 bytes of a classic frame (an FD message needs fd = yes)");
	}
	if ((in->fd == 0U) && (calib_input_needed_dlc(in) > HAL_CAN_CLASSIC_MAX_DLEN)) {
		return fail(why, "a selector, qualifier bit or E2E header beyond the 8 bytes of a classic frame (an FD message needs fd = yes)");
	}
	if ((in->fd == 0U) && (in->min_dlc > HAL_CAN_CLASSIC_MAX_DLEN)) {
		return fail(why, "min_dlc above 8 needs fd = yes (a classic frame has at most 8 bytes)");
	}
	if ((in->min_dlc > HAL_CAN_CLASSIC_MAX_DLEN) && (hal_can_len_to_dlc(in->min_dlc) == 0xFFU)) {
		return fail(why, "min_dlc: above 8 an FD frame has 12, 16, 20, 24, 32, 48 or 64 bytes");
	}
	return SQ_OK;
}

int calib_input_check(const calib_input_t *in, const char **why)
{
	input_unit_t unit;
	uint8_t need;

	if ((in == NULL) || (why == NULL)) {
		return SQ_EINVAL;
	}
	if (((in->flags & CALIB_IN_EXTENDED) == 0U) && (in->id > STD_ID_MAX)) {
		return fail(why, "id above 0x7FF needs extended = yes");
	}
	if ((in->sig.length == 0U) || (in->sig.length > CAN_SIGNAL_MAX_LEN)) {
		return fail(why, "length must be 1..32");
	}
	if (!can_signal_valid(&in->sig)) {
		return fail(why, "signal beyond the 512 bits of an FD frame");
	}
	if (in->factor.mant == 0) {
		return fail(why, "factor 0");
	}
	unit = (input_unit_t)in->unit;
	if ((uint32_t)unit >= (uint32_t)INPUT_UNIT_COUNT) {
		return fail(why, "unknown unit");
	}
	if (((in->flags & CALIB_IN_QUALIFIER) != 0U) && bit_in(&in->sig, in->qualifier_bit)) {
		return fail(why, "qualifier bit inside the value signal");
	}
	if (check_selectors(in, why) != SQ_OK) {
		return SQ_EINVAL;
	}
	if ((((in->flags & CALIB_IN_NA) != 0U) && !fits(&in->sig, in->na_raw)) ||
	    (((in->flags & CALIB_IN_NA2) != 0U) && !fits(&in->sig, in->na_raw2))) {
		return fail(why, "na_raw does not fit the signal");
	}
	if (check_protection(in, why) != SQ_OK) {
		return SQ_EINVAL;
	}
	if (check_format(in, why) != SQ_OK) {
		return SQ_EINVAL;
	}
	need = calib_input_needed_dlc(in);
	if (in->min_dlc < need) {
		return fail(why, "a signal beyond min_dlc");
	}
	if ((in->period_ms < 1U) || (in->period_ms > 1000U) || (in->stale_cycles < 1U)) {
		return fail(why, "period_ms 1..1000 and stale_cycles 1..100");
	}
	if (in->conv_share_ppm > 1000000U) {
		return fail(why, "torque_share above 1");
	}
	return check_range(in, why);
}

input_geom_t calib_corner_geom(const calib_corner_t *c)
{
	return (input_geom_t){ c->pad_radius_um, c->wheel_radius_um, c->piston_area_cmm2,
			       c->efficiency_ppm, c->axle_factor_ppm };
}

int calib_input_prepare(const calib_input_t *in, const input_geom_t *geom,
			input_conv_t *conv, input_raw_bounds_t *bounds, const char **why)
{
	return prepare_share(in, in->conv_share_ppm, geom, conv, bounds, why);
}

static int prepare_share(const calib_input_t *in, uint32_t share_ppm, const input_geom_t *geom,
			 input_conv_t *conv, input_raw_bounds_t *bounds, const char **why)
{
	const uint32_t share = (share_ppm == 0U) ? 1000000U : share_ppm;

	if (calib_input_check(in, why) != SQ_OK) {
		return SQ_EINVAL;
	}
	if (input_conv_make_share(in->factor.mant, in->factor.exp, in->offset.mant, in->offset.exp,
				  (input_unit_t)in->unit, geom, share, conv) != SQ_OK) {
		return fail(why, "factor: one raw step is 2^31 output units or more, or the corner's geometry cannot convert it");
	}
	if (input_conv_raw_bounds(in->factor, in->offset, in->min, in->max, in->step_max,
				  bounds) != SQ_OK) {
		return fail(why, "max: no raw value of the signal lies within min .. max");
	}
	return SQ_OK;
}

static int corner_check(const calib_t *cal, const calib_corner_t *c, const char **why)
{
	const calib_input_t *sp;
	const calib_input_t *fo;
	input_unit_t fu;

	if ((c->speed_input >= cal->n_inputs) || (c->force_input >= cal->n_inputs)) {
		return fail(why, "names an unknown input");
	}
	sp = &cal->inputs[c->speed_input];
	fo = &cal->inputs[c->force_input];
	if (input_unit_qty((input_unit_t)sp->unit) != INPUT_QTY_SPEED) {
		return fail(why, "speed input is not a speed");
	}
	fu = (input_unit_t)fo->unit;
	if (input_unit_qty(fu) == INPUT_QTY_SPEED) {
		return fail(why, "force input is not a force, pressure or torque");
	}
	if (input_unit_is_pressure(fu) && (c->piston_area_cmm2 == 0U)) {
		return fail(why, "pressure without piston_area_mm2");
	}
	if ((c->efficiency_ppm == 0U) || (c->axle_factor_ppm == 0U) ||
	    (c->friction_faces < 1U)) {
		return fail(why, "efficiency, axle_factor must be > 0 and friction_faces 1..4");
	}
	if ((c->torque_share_ppm < 1U) || (c->torque_share_ppm > 1000000U)) {
		return fail(why, "torque_share must be in (0, 1]");
	}
	if ((c->torque_share_ppm != 1000000U) && (input_unit_qty(fu) != INPUT_QTY_TORQUE)) {
		return fail(why, "torque_share for a force input that is not a torque (Nm)");
	}
	if ((c->mass_q16 < 1) || (c->omega0_q12 < 1) || (c->damping_q30 < 1) ||
	    ((int64_t)c->mu_inf_q30 + c->delta_mu_q30 < 0) ||
	    (c->pad_radius_um < 10000U) || (c->wheel_radius_um < 10000U)) {
		return fail(why, "brake parameters out of range");
	}
	return SQ_OK;
}

static void legacy_speed(const calib_t *cal, calib_input_t *in);
static void legacy_force(const calib_t *cal, calib_input_t *in);

/* The share calib_corner_view() gives a corner's force input: the corner's
 * torque_share for a torque, none (0) otherwise. */
static uint32_t force_share(const calib_corner_t *c, const calib_input_t *fo)
{
	return (input_unit_qty((input_unit_t)fo->unit) == INPUT_QTY_TORQUE) ? c->torque_share_ppm : 0U;
}


/* Corner k sets up exactly as input_rx_setup() will do it: both inputs
 * prepared with the corner's geometry and the share calib_corner_view()
 * gives its torque input. */
static int corner_setup_check(const calib_t *cal, uint32_t k, int8_t *input, const char **why)
{
	input_conv_t conv;
	input_raw_bounds_t b;
	int rc = SQ_OK;

	if (cal->n_corners == 0U) {
		/* the legacy corner: DiscSpeed and PadForce on the flat keys'
		 * geometry (calib_corner_defaults()) */
		const input_geom_t g = { cal->pad_radius_um, cal->wheel_radius_um, 0U, 1000000U,
					 1000000U };
		calib_input_t in;

		legacy_speed(cal, &in);
		rc = prepare_share(&in, 0U, &g, &conv, &b, why);
		if (rc == SQ_OK) {
			legacy_force(cal, &in);
			rc = prepare_share(&in, 0U, &g, &conv, &b, why);
		}
	} else {
		const calib_corner_t *c = &cal->corners[k];
		const input_geom_t g = calib_corner_geom(c);
		const calib_input_t *fo = &cal->inputs[c->force_input];

		rc = prepare_share(&cal->inputs[c->speed_input], 0U, &g, &conv, &b, why);
		if (rc != SQ_OK) {
			*input = (int8_t)c->speed_input;
		} else {
			rc = prepare_share(fo, force_share(c, fo), &g, &conv, &b, why);
			if (rc != SQ_OK) {
				*input = (int8_t)c->force_input;
			}
		}
	}
	return rc;
}

/* Output identifiers of all corners and input identifiers differ. */
static bool ids_clash(const calib_t *cal, uint32_t k, uint32_t j, uint32_t m)
{
	const calib_corner_t *c = &cal->corners[k];
	const uint16_t ids[4] = { c->status_id, c->detail_id, c->detail2_id, c->diag_id };
	uint32_t i;

	for (i = 0U; i < 4U; i++) {
		if ((j != i) && (ids[i] == ids[j]) && (m == k)) {
			return true;
		}
	}
	return false;
}

static int check_ids(const calib_t *cal, calib_map_error_t *e)
{
	uint32_t k;
	uint32_t j;
	uint32_t m;
	uint32_t i;

	for (k = 0U; k < cal->n_corners; k++) {
		const calib_corner_t *c = &cal->corners[k];
		const uint16_t ids[4] = { c->status_id, c->detail_id, c->detail2_id, c->diag_id };

		for (j = 0U; j < 4U; j++) {
			if (ids_clash(cal, k, j, k)) {
				e->corner = (int8_t)k;
				e->why = "two outputs of the corner share an identifier";
				return SQ_EINVAL;
			}
			for (m = k + 1U; m < cal->n_corners; m++) {
				const calib_corner_t *o = &cal->corners[m];

				if ((ids[j] == o->status_id) || (ids[j] == o->detail_id) ||
				    (ids[j] == o->detail2_id) || (ids[j] == o->diag_id)) {
					e->corner = (int8_t)m;
					e->why = "output identifier used by another corner";
					return SQ_EINVAL;
				}
			}
			for (i = 0U; i < cal->n_inputs; i++) {
				if (((cal->inputs[i].flags & CALIB_IN_EXTENDED) == 0U) &&
				    (cal->inputs[i].id == ids[j])) {
					e->corner = (int8_t)k;
					e->why = "output identifier equals an input's identifier";
					return SQ_EINVAL;
				}
			}
		}
	}
	return SQ_OK;
}

int calib_map_check(const calib_t *cal, calib_map_error_t *err)
{
	calib_map_error_t e = { -1, -1, NULL };
	uint32_t i;
	uint32_t k;
	int rc = SQ_OK;

	if (cal == NULL) {
		return SQ_EINVAL;
	}
	if (cal->n_corners == 0U) {
		if (cal->n_inputs != 0U) {
			e.why = "inputs without corners";
			rc = SQ_EINVAL;
		} else if (corner_setup_check(cal, 0U, &e.input, &e.why) != SQ_OK) {
			e.corner = 0;  /* the legacy corner (flat keys) */
			e.input = -1;
			rc = SQ_EINVAL;
		} else {
			/* the legacy corner sets up */
		}
	} else if (cal->n_inputs == 0U) {
		e.why = "corners without inputs";
		rc = SQ_EINVAL;
	} else {
		for (i = 0U; (i < cal->n_inputs) && (rc == SQ_OK); i++) {
			if (calib_input_check(&cal->inputs[i], &e.why) != SQ_OK) {
				e.input = (int8_t)i;
				rc = SQ_EINVAL;
			}
		}
		for (k = 0U; (k < cal->n_corners) && (rc == SQ_OK); k++) {
			for (i = 0U; i < k; i++) {
				if (cal->corners[i].pos == cal->corners[k].pos) {
					e.why = "two corners with one position";
					rc = SQ_EINVAL;
				}
			}
			if ((rc == SQ_OK) && (corner_check(cal, &cal->corners[k], &e.why) != SQ_OK)) {
				rc = SQ_EINVAL;
			}
			if ((rc == SQ_OK) && (corner_setup_check(cal, k, &e.input, &e.why) != SQ_OK)) {
				rc = SQ_EINVAL;
			}
			if (rc != SQ_OK) {
				e.corner = (int8_t)k;
			}
		}
		if (rc == SQ_OK) {
			rc = check_ids(cal, &e);
		}
	}
	if ((err != NULL) && (rc != SQ_OK)) {
		*err = e;
	}
	return rc;
}

int calib_map_validate(const calib_t *cal)
{
	return calib_map_check(cal, NULL);
}

uint32_t calib_corner_count(const calib_t *cal)
{
	return ((cal == NULL) || (cal->n_corners == 0U)) ? 1U : cal->n_corners;
}

void calib_corner_from_flat(const calib_t *cal, calib_corner_t *c)
{
	c->mass_q16 = cal->mass_q16;
	c->omega0_q12 = cal->omega0_q12;
	c->damping_q30 = cal->damping_q30;
	c->mu_inf_q30 = cal->mu_inf_q30;
	c->delta_mu_q30 = cal->delta_mu_q30;
	c->slope_q24 = cal->slope_q24;
	c->criterion = cal->criterion;
	c->pad_radius_um = cal->pad_radius_um;
	c->wheel_radius_um = cal->wheel_radius_um;
	c->status_id = cal->status_id;
	c->detail_id = cal->detail_id;
	c->detail2_id = cal->detail2_id;
	c->diag_id = cal->diag_id;
	c->sd = cal->sd;
}

void calib_flat_from_corner(const calib_corner_t *c, calib_t *cal)
{
	cal->mass_q16 = c->mass_q16;
	cal->omega0_q12 = c->omega0_q12;
	cal->damping_q30 = c->damping_q30;
	cal->mu_inf_q30 = c->mu_inf_q30;
	cal->delta_mu_q30 = c->delta_mu_q30;
	cal->slope_q24 = c->slope_q24;
	cal->criterion = c->criterion;
	cal->pad_radius_um = c->pad_radius_um;
	cal->wheel_radius_um = c->wheel_radius_um;
	cal->status_id = c->status_id;
	cal->detail_id = c->detail_id;
	cal->detail2_id = c->detail2_id;
	cal->diag_id = c->diag_id;
	cal->sd = c->sd;
}

void calib_corner_defaults(const calib_t *cal, uint8_t pos, calib_corner_t *c)
{
	const uint16_t step = (uint16_t)(CORNER_ID_STEP * pos);

	*c = (calib_corner_t){ 0 };
	c->pos = pos;
	c->friction_faces = 2U;
	c->efficiency_ppm = 1000000U;
	c->axle_factor_ppm = 1000000U;
	c->torque_share_ppm = 1000000U;
	calib_corner_from_flat(cal, c);
	c->status_id = (uint16_t)(c->status_id + step);
	c->detail_id = (uint16_t)(c->detail_id + step);
	c->detail2_id = (uint16_t)(c->detail2_id + step);
	c->diag_id = (uint16_t)(c->diag_id + step);
}

/* DiscSpeed_radps / PadForce_N (squeal.dbc: 16|16@1+ after CRC and counter)
 * with the legacy keys' protection, period and plausibility. */
static void legacy_input(const calib_t *cal, uint16_t id, uint16_t data_id,
			 calib_dec_t factor, input_unit_t unit, uint16_t max_raw,
			 uint16_t step_raw, calib_input_t *in)
{
	*in = (calib_input_t){ 0 };
	in->id = id;
	in->min_dlc = MSG_DISC_SPEED_DLC; /* == MSG_PAD_FORCE_DLC */
	in->flags = (uint8_t)(CALIB_IN_NA | CALIB_IN_DLC_EXACT);
	in->sig = (can_signal_t){ 16U, 16U, (uint8_t)CAN_SIGNAL_INTEL, 0U };
	in->factor = factor;
	in->offset = (calib_dec_t){ 0, 0 };
	in->unit = (uint8_t)unit;
	in->na_raw = MSG_DISC_SPEED_RADPS_NA; /* == MSG_PAD_FORCE_N_NA */
	in->protection = (uint8_t)((cal->e2e_check_inputs != 0U) ? CALIB_PROT_P01 :
				   CALIB_PROT_NONE);
	in->data_id = data_id;
	in->max_delta_counter = cal->e2e_max_delta_counter;
	in->period_ms = cal->input_period_ms;
	in->stale_cycles = cal->stale_cycles;
	/* raw bounds x factor: the same raw limits as before */
	in->max = (calib_dec_t){ (int64_t)max_raw * factor.mant, factor.exp };
	in->min = (calib_dec_t){ 0, 0 };
	in->step_max = (calib_dec_t){ (int64_t)step_raw * factor.mant, factor.exp };
}

static void legacy_speed(const calib_t *cal, calib_input_t *in)
{
	legacy_input(cal, cal->disc_speed_id, MSG_DISC_SPEED_DATA_ID, (calib_dec_t){ 1, -2 },
		     INPUT_UNIT_RADPS, cal->speed_max_raw, cal->speed_step_max_raw, in);
}

static void legacy_force(const calib_t *cal, calib_input_t *in)
{
	legacy_input(cal, cal->pad_force_id, MSG_PAD_FORCE_DATA_ID, (calib_dec_t){ 5, -1 },
		     INPUT_UNIT_N, cal->force_max_raw, cal->force_step_max_raw, in);
}

int calib_corner_view(const calib_t *cal, uint32_t k, calib_corner_t *corner,
		      calib_input_t *speed, calib_input_t *force)
{
	if ((cal == NULL) || (corner == NULL) || (speed == NULL) || (force == NULL) ||
	    (k >= calib_corner_count(cal))) {
		return SQ_EINVAL;
	}
	if (cal->n_corners == 0U) {
		calib_corner_defaults(cal, 0U, corner);
		legacy_speed(cal, speed);
		legacy_force(cal, force);
		return SQ_OK;
	}
	*corner = cal->corners[k];
	*speed = cal->inputs[corner->speed_input];
	*force = cal->inputs[corner->force_input];
	speed->conv_share_ppm = 0U;
	force->conv_share_ppm = force_share(corner, force);
	return SQ_OK;
}
