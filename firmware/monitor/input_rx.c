/* SPDX-License-Identifier: MIT */
#include "input_rx.h"

#include <stddef.h>

#include "calib_map.h"
#include "e2e_p02.h"
#include "hal.h"
#include "sq_status.h"

static const char *const reason_names[INPUT_RX_REASON_COUNT] = {
	"ok", "dlc", "na", "qualifier", "crc", "counter", "repeated", "implausible"
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
 * short to hold it (it matches, then fails the DLC check). */
static bool selector_holds(const can_signal_t *sel, uint32_t lo, uint32_t hi,
			   const hal_can_frame_t *f)
{
	uint32_t v;

	if (f->dlc < can_signal_min_dlc(sel)) {
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
	/* with a bad DLC the check still runs once with the configured length
	 * (it fails): one receive cycle of the E2E state machine, as always */
	const uint8_t len = dlc_ok ? f->dlc : in->min_dlc;

	switch (in->protection) {
	case CALIB_PROT_P01: {
		const e2e_p01_config_t c = { in->data_id, len, in->max_delta_counter };

		*st = e2e_p01_check(&c, e2e, f->data, f->dlc);
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
		*st = e2e_p02_check(&c, e2e, f->data, f->dlc);
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

input_rx_result_t input_rx_frame(const input_rx_cfg_t *cfg, e2e_p01_rx_t *e2e,
				 const hal_can_frame_t *f)
{
	const calib_input_t *in;
	input_rx_result_t r = { (uint8_t)INPUT_RX_OK, (uint8_t)E2E_P01_STATUS_NONEWDATA, 0U, 0U, 0 };
	bool dlc_ok;
	e2e_p01_status_t st = E2E_P01_STATUS_NONEWDATA;
	input_rx_reason_t why;

	HAL_REQUIRE((cfg != NULL) && (e2e != NULL) && (f != NULL));
	in = &cfg->desc;
	if ((in->flags & CALIB_IN_DLC_EXACT) != 0U) {
		dlc_ok = f->dlc == in->min_dlc;
	} else {
		dlc_ok = (f->dlc >= in->min_dlc) && (f->dlc <= CAN_SIGNAL_FRAME_BYTES);
	}
	why = protection(cfg, e2e, f, dlc_ok, &st);

	r.e2e_status = (uint8_t)st;
	r.lost = (st == E2E_P01_STATUS_OKSOMELOST) ? e2e->lost_data : 0U;
	if (!dlc_ok) {
		r.reason = (uint8_t)INPUT_RX_DLC;
		return r;
	}
	r.raw = can_signal_get(&in->sig, f->data);
	r.value = can_signal_value(&in->sig, r.raw);
	if (why == INPUT_RX_OK) {
		if ((((in->flags & CALIB_IN_NA) != 0U) && (r.raw == in->na_raw)) ||
		    (((in->flags & CALIB_IN_NA2) != 0U) && (r.raw == in->na_raw2))) {
			why = INPUT_RX_NA;
		} else if (((in->flags & CALIB_IN_QUALIFIER) != 0U) &&
			   ((uint32_t)((f->data[in->qualifier_bit / 8U] >> (in->qualifier_bit % 8U)) & 1U) ==
			    in->qualifier_invalid)) {
			why = INPUT_RX_QUALIFIER;
		} else {
			/* usable so far */
		}
	}
	r.reason = (uint8_t)why;
	return r;
}

bool input_rx_plausible(const input_rx_cfg_t *cfg, bool *has_prev, int64_t *prev,
			int64_t value)
{
	bool ok;

	HAL_REQUIRE((cfg != NULL) && (has_prev != NULL) && (prev != NULL));
	ok = (value >= cfg->raw_min) && (value <= cfg->raw_max);
	if (ok && *has_prev) {
		const int64_t d = (value > *prev) ? (value - *prev) : (*prev - value);

		ok = d <= cfg->raw_step;
	}
	*prev = value;
	*has_prev = true;
	return ok;
}
