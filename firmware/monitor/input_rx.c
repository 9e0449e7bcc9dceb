/* SPDX-License-Identifier: MIT */
#include "input_rx.h"

#include <stddef.h>

#include "calib_map.h"
#include "e2e_p02.h"
#include "e2e_p05.h"
#include "hal.h"
#include "sq_status.h"

static const char *const reason_names[INPUT_RX_REASON_COUNT] = {
	"ok", "dlc", "crc", "counter", "repeated", "na", "qualifier", "range", "step"
};

const char *input_rx_reason_name(input_rx_reason_t r)
{
	return ((uint32_t)r < (uint32_t)INPUT_RX_REASON_COUNT) ? reason_names[r] : "?";
}

int input_rx_setup(const calib_input_t *desc, const input_geom_t *geom,
		   input_rx_cfg_t *cfg)
{
	const char *why = NULL;
	input_raw_bounds_t b;

	/* descriptors come from a validated calibration */
	HAL_REQUIRE((desc != NULL) && (geom != NULL) && (cfg != NULL));
	HAL_REQUIRE(calib_input_check(desc, &why) == SQ_OK);
	cfg->desc = *desc;
	/* the one preparation calib_validate() also runs for every corner */
	if (calib_input_prepare(desc, geom, &cfg->conv, &b, &why) != SQ_OK) {
		return SQ_EINVAL;
	}
	cfg->raw_min = b.raw_min;
	cfg->raw_max = b.raw_max;
	cfg->raw_step = b.raw_step;
	return SQ_OK;
}

/* One selector condition: the raw selector within lo .. hi, or a frame too
 * short to hold it (it matches, then fails the DLC check; so does a
 * length beyond the frame's buffer, which is never read). */
static bool selector_holds(const can_signal_t *sel, uint32_t lo, uint32_t hi,
			   const hal_can_frame_t *f)
{
	uint32_t v;

	if ((f->dlc < can_signal_min_dlc(sel)) || (f->dlc > HAL_CAN_MAX_DLEN)) {
		return true;
	}
	v = can_signal_get(sel, f->data);
	return (v >= lo) && (v <= hi);
}

bool input_rx_matches(const input_rx_cfg_t *cfg, const hal_can_frame_t *f, bool *id_only)
{
	const calib_input_t *in;
	bool ext;
	bool want_ext;

	HAL_REQUIRE((cfg != NULL) && (f != NULL) && (id_only != NULL));
	in = &cfg->desc;
	ext = (f->flags & HAL_CAN_FLAG_EXT) != 0U;
	want_ext = (in->flags & CALIB_IN_EXTENDED) != 0U;
	*id_only = false;
	if (f->id != in->id) {
		return false;
	}
	if ((ext != want_ext) || ((f->flags & HAL_CAN_FLAG_RTR) != 0U)) {
		*id_only = true;
		return false;
	}
	/* every condition given must hold */
	if (((in->flags & CALIB_IN_MUX) != 0U) &&
	    !selector_holds(&in->mux, in->mux_value, in->mux_value_max, f)) {
		return false;
	}
	return ((in->flags & CALIB_IN_MUX2) == 0U) ||
	       selector_holds(&in->mux2, in->mux2_value, in->mux2_value_max, f);
}

/* The protection's verdict; *st the E2E status. */
static input_rx_reason_t protection(const input_rx_cfg_t *cfg, e2e_p01_rx_t *e2e,
				    const hal_can_frame_t *f, bool dlc_ok,
				    e2e_p01_status_t *st)
{
	const calib_input_t *in = &cfg->desc;
	/* with a bad DLC (or format) the check still runs once with the
	 * configured length and a frame of length 0, which fails: one receive
	 * cycle of the E2E state machine, as always, and no byte read */
	const uint8_t len = dlc_ok ? f->dlc : in->min_dlc;
	const uint8_t flen = dlc_ok ? f->dlc : 0U;

	switch (in->protection) {
	case CALIB_PROT_P01: {
		const e2e_p01_config_t c = { in->data_id, len, in->max_delta_counter };

		*st = e2e_p01_check(&c, e2e, f->data, flen);
		break;
	}
	case CALIB_PROT_P02: {
		e2e_p02_config_t c;
		uint32_t i;

		for (i = 0U; i < CALIB_DATA_ID_LIST_LEN; i++) {
			c.data_id_list[i] = in->data_id_list[i];
		}
		c.data_len = len;
		c.max_delta_counter = in->max_delta_counter;
		*st = e2e_p02_check(&c, e2e, f->data, flen);
		break;
	}
	case CALIB_PROT_P05: {
		const e2e_p05_config_t c = { in->data_id, len, in->e2e_offset_byte,
					     in->max_delta_counter };

		*st = e2e_p05_check(&c, e2e, f->data, flen);
		break;
	}
	case CALIB_PROT_COUNTER:
		e2e_rx_cycle(e2e, in->counter_modulus);
		if (!dlc_ok) {
			*st = e2e_rx_record(e2e, E2E_P01_STATUS_NONEWDATA);
		} else {
			const uint32_t c = can_signal_get(&in->counter, f->data);

			*st = (c >= in->counter_modulus) ? E2E_P01_STATUS_WRONGSEQUENCE :
				e2e_rx_sequence(e2e, (uint8_t)c, in->counter_modulus,
						in->max_delta_counter);
			(void)e2e_rx_record(e2e, *st);
		}
		break;
	default:
		*st = E2E_P01_STATUS_NONEWDATA;
		return INPUT_RX_OK;
	}
	switch (*st) {
	case E2E_P01_STATUS_OK:
	case E2E_P01_STATUS_INITIAL:
	case E2E_P01_STATUS_OKSOMELOST:
		return INPUT_RX_OK;
	case E2E_P01_STATUS_REPEATED:
		return INPUT_RX_REPEATED;
	case E2E_P01_STATUS_WRONGSEQUENCE:
		return INPUT_RX_COUNTER;
	default:
		return INPUT_RX_CRC;
	}
}

/* "Not available", then the qualifier bit: OK when the value is usable. */
static input_rx_reason_t availability(const calib_input_t *in, const hal_can_frame_t *f,
				      uint32_t raw)
{
	input_rx_reason_t why = INPUT_RX_OK;

	if ((((in->flags & CALIB_IN_NA) != 0U) && (raw == in->na_raw)) ||
	    (((in->flags & CALIB_IN_NA2) != 0U) && (raw == in->na_raw2))) {
		why = INPUT_RX_NA;
	} else if (((in->flags & CALIB_IN_QUALIFIER) != 0U) &&
		   ((uint32_t)((f->data[in->qualifier_bit / 8U] >> (in->qualifier_bit % 8U)) & 1U) ==
		    in->qualifier_invalid)) {
		why = INPUT_RX_QUALIFIER;
	} else {
		/* available */
	}
	return why;
}

/* Range, then step against the previous value; the value becomes the
 * previous one either way (as the monitor always did: a real step costs one
 * frame, a spike two). */
static input_rx_reason_t plausibility(const input_rx_cfg_t *cfg, input_rx_state_t *st,
				      int64_t value)
{
	input_rx_reason_t why = INPUT_RX_RANGE;
	bool ok;

	ok = (value >= cfg->raw_min) && (value <= cfg->raw_max);
	if (ok) {
		why = INPUT_RX_OK;
		if (st->has_prev) {
			const int64_t d = (value > st->prev) ? (value - st->prev) : (st->prev - value);

			ok = d <= cfg->raw_step;
			why = ok ? INPUT_RX_OK : INPUT_RX_STEP;
		}
	}
	st->prev = value;
	st->has_prev = true;
	return why;
}

/* The frame's format is the message's (FD or classic) and its length one
 * that format has and this build's frame buffer holds. */
static bool format_ok(const calib_input_t *in, const hal_can_frame_t *f)
{
	const bool fd = (f->flags & HAL_CAN_FLAG_FDF) != 0U;
	const bool want_fd = in->fd != 0U;

	if (fd != want_fd) {
		return false;
	}
	if (f->dlc > HAL_CAN_MAX_DLEN) {
		return false;
	}
	return fd ? (hal_can_len_to_dlc(f->dlc) != 0xFFU) : (f->dlc <= HAL_CAN_CLASSIC_MAX_DLEN);
}

void input_rx_state_init(input_rx_state_t *st)
{
	HAL_REQUIRE(st != NULL);
	e2e_p01_rx_init(&st->e2e);
	st->has_prev = false;
	st->prev = 0;
}

input_rx_result_t input_rx_judge(const input_rx_cfg_t *cfg, input_rx_state_t *st,
				 const hal_can_frame_t *f)
{
	const calib_input_t *in;
	input_rx_result_t r = { (uint8_t)INPUT_RX_OK, (uint8_t)E2E_P01_STATUS_NONEWDATA, 0U, 0U, 0 };
	bool dlc_ok;
	e2e_p01_status_t st_e2e = E2E_P01_STATUS_NONEWDATA;
	input_rx_reason_t why;

	HAL_REQUIRE((cfg != NULL) && (st != NULL) && (f != NULL));
	in = &cfg->desc;
	if (!format_ok(in, f)) {
		dlc_ok = false;
	} else if ((in->flags & CALIB_IN_DLC_EXACT) != 0U) {
		dlc_ok = f->dlc == in->min_dlc;
	} else {
		dlc_ok = f->dlc >= in->min_dlc;
	}
	why = protection(cfg, &st->e2e, f, dlc_ok, &st_e2e);
	r.e2e_status = (uint8_t)st_e2e;
	r.lost = (st_e2e == E2E_P01_STATUS_OKSOMELOST) ? st->e2e.lost_data : 0U;
	if (!dlc_ok) {
		why = INPUT_RX_DLC;
	} else {
		r.raw = can_signal_get(&in->sig, f->data);
		r.value = can_signal_value(&in->sig, r.raw);
		if (why == INPUT_RX_OK) {
			why = availability(in, f, r.raw);
		}
		if (why == INPUT_RX_OK) {
			why = plausibility(cfg, st, r.value);
		}
	}
	r.reason = (uint8_t)why;
	return r;
}
