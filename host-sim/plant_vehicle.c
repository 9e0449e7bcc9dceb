/* SPDX-License-Identifier: MIT */
#include "plant_vehicle.h"

#include <math.h>
#include <string.h>

#include "calib_map.h"
#include "calib_sections.h"
#include "e2e_p02.h"
#include "e2e_p05.h"
#include "input_conv.h"

#define NO_PROT 0xFFU

uint32_t plant_vehicle_frames(const calib_t *cal, plant_vframe_t frames[CALIB_MAX_INPUTS])
{
	uint32_t n = 0U;
	uint32_t i;

	if (cal->n_corners == 0U) {
		return 0U;
	}
	for (i = 0U; i < cal->n_inputs; i++) {
		const calib_input_t *in = &cal->inputs[i];
		const bool ext = (in->flags & CALIB_IN_EXTENDED) != 0U;
		const bool mux = (in->flags & CALIB_IN_MUX) != 0U;
		const bool mux2 = (in->flags & CALIB_IN_MUX2) != 0U;
		uint32_t k;

		/* one frame per identifier and selector page: every selector is
		 * written with the low end of its range */
		for (k = 0U; k < n; k++) {
			if ((frames[k].id == in->id) && (frames[k].ext == ext) &&
			    (frames[k].has_mux == mux) && (!mux || (frames[k].mux_value == in->mux_value)) &&
			    (frames[k].has_mux2 == mux2) &&
			    (!mux2 || (frames[k].mux2_value == in->mux2_value))) {
				break;
			}
		}
		if (k == n) {
			memset(&frames[n], 0, sizeof(frames[n]));
			frames[n].id = in->id;
			frames[n].ext = ext;
			frames[n].has_mux = mux;
			frames[n].mux_value = in->mux_value;
			frames[n].has_mux2 = mux2;
			frames[n].mux2_value = in->mux2_value;
			frames[n].prot = NO_PROT;
			frames[n].period_ms = in->period_ms;
			frames[n].fd = in->fd != 0U;
			frames[n].dlc = frames[n].fd ? in->min_dlc : 8U;
			n++;
		}
		if (frames[k].fd && (in->min_dlc > frames[k].dlc)) {
			frames[k].dlc = in->min_dlc;
		}
		frames[k].in[frames[k].n] = (uint8_t)i;
		frames[k].n++;
		if (in->period_ms < frames[k].period_ms) {
			frames[k].period_ms = in->period_ms;
		}
		if ((in->flags & CALIB_IN_DLC_EXACT) != 0U) {
			frames[k].dlc = in->min_dlc;
		}
		if ((frames[k].prot == NO_PROT) && (in->protection != (uint8_t)CALIB_PROT_NONE)) {
			frames[k].prot = (uint8_t)i;
		}
	}
	return n;
}

/* The first corner that uses input i. */
static const calib_corner_t *corner_of(const calib_t *cal, uint32_t i, bool *is_speed)
{
	uint32_t k;

	for (k = 0U; k < cal->n_corners; k++) {
		if ((cal->corners[k].speed_input == i) || (cal->corners[k].force_input == i)) {
			*is_speed = cal->corners[k].speed_input == i;
			return &cal->corners[k];
		}
	}
	return NULL;
}

static double q(int32_t v, double one)
{
	return (double)v / one;
}

double plant_vehicle_physical(const calib_t *cal, uint32_t i, double vehicle_mps,
			      double force_n)
{
	bool is_speed = false;
	const calib_corner_t *c = corner_of(cal, i, &is_speed);
	const input_unit_t u = (input_unit_t)cal->inputs[i].unit;
	double r_w;
	double r_p;
	double pa;

	if (c == NULL) {
		return 0.0;
	}
	r_w = (double)c->wheel_radius_um * 1e-6;
	r_p = (double)c->pad_radius_um * 1e-6;
	switch (u) {
	case INPUT_UNIT_KMH:
		return vehicle_mps * 3.6;
	case INPUT_UNIT_MPS:
		return vehicle_mps;
	case INPUT_UNIT_MPH:
		return vehicle_mps / 0.44704;
	case INPUT_UNIT_RADPS:
		return vehicle_mps / r_w;
	case INPUT_UNIT_RPM:
		return vehicle_mps / r_w * 60.0 / (2.0 * M_PI);
	case INPUT_UNIT_N:
		return force_n;
	case INPUT_UNIT_KN:
		return force_n / 1000.0;
	case INPUT_UNIT_NM: {
		const double v0 = vehicle_mps * r_p / r_w;
		const double mu = q(c->mu_inf_q30, 1073741824.0) +
			q(c->delta_mu_q30, 1073741824.0) * exp(-q(c->slope_q24, 16777216.0) * v0);

		/* the input is the total the corner has torque_share of */
		return force_n * (double)c->friction_faces * mu * r_p /
		       ((double)c->torque_share_ppm * 1e-6);
	}
	default:
		break;
	}
	/* pressure: p = N / (A eta k) */
	pa = force_n / ((double)c->piston_area_cmm2 * 1e-8 * (double)c->efficiency_ppm * 1e-6 *
			(double)c->axle_factor_ppm * 1e-6);
	switch (u) {
	case INPUT_UNIT_BAR:
		return pa / 1e5;
	case INPUT_UNIT_KPA:
		return pa / 1e3;
	case INPUT_UNIT_MPA:
		return pa / 1e6;
	default:
		return pa / 6894.757;
	}
}

static uint32_t raw_of(const calib_input_t *in, double phys, uint64_t *saturated)
{
	const double r = nearbyint((phys - calib_dec_value(in->offset)) / calib_dec_value(in->factor));
	const double top = ldexp(1.0, in->sig.length - (in->sig.is_signed != 0U ? 1 : 0));
	double lo = (in->sig.is_signed != 0U) ? -top : 0.0;
	double hi = top - 1.0;
	double v = r;

	/* stay clear of the "not available" codes */
	if (((in->flags & CALIB_IN_NA) != 0U) && ((double)in->na_raw == hi)) {
		hi -= 1.0;
	}
	if (!(v >= lo)) {
		v = lo;
		(*saturated)++;
	} else if (v > hi) {
		v = hi;
		(*saturated)++;
	} else {
		/* in range */
	}
	return can_signal_raw_of(&in->sig, (int64_t)v);
}

void plant_vehicle_pack(const calib_t *cal, const plant_vframe_t *fr, e2e_p01_tx_t *tx,
			double vehicle_mps, double force_n, hal_can_frame_t *f,
			uint64_t *saturated)
{
	uint32_t j;

	memset(f, 0, sizeof(*f));
	f->id = fr->id;
	f->flags = (uint8_t)((fr->ext ? HAL_CAN_FLAG_EXT : 0U) | (fr->fd ? HAL_CAN_FLAG_FDF : 0U));
	f->dlc = fr->dlc;
	for (j = 0U; j < fr->n; j++) {
		const calib_input_t *in = &cal->inputs[fr->in[j]];

		if ((in->flags & CALIB_IN_MUX) != 0U) {
			can_signal_put(&in->mux, f->data, in->mux_value);
		}
		if ((in->flags & CALIB_IN_MUX2) != 0U) {
			can_signal_put(&in->mux2, f->data, in->mux2_value);
		}
		if ((in->flags & CALIB_IN_QUALIFIER) != 0U) {
			const uint8_t bit = (uint8_t)(1U << (in->qualifier_bit % 8U));

			if (in->qualifier_invalid != 0U) {
				f->data[in->qualifier_bit / 8U] &= (uint8_t)~bit;
			} else {
				f->data[in->qualifier_bit / 8U] |= bit;
			}
		}
		can_signal_put(&in->sig, f->data,
			       raw_of(in, plant_vehicle_physical(cal, fr->in[j], vehicle_mps, force_n),
				      saturated));
	}
	if (fr->prot != NO_PROT) {
		const calib_input_t *in = &cal->inputs[fr->prot];

		switch (in->protection) {
		case CALIB_PROT_P01: {
			const e2e_p01_config_t c = { in->data_id, f->dlc, in->max_delta_counter };

			(void)e2e_p01_protect(&c, tx, f->data, f->dlc);
			break;
		}
		case CALIB_PROT_P02: {
			e2e_p02_config_t c;

			memcpy(c.data_id_list, in->data_id_list, sizeof(c.data_id_list));
			c.data_len = f->dlc;
			c.max_delta_counter = in->max_delta_counter;
			(void)e2e_p02_protect(&c, tx, f->data, f->dlc);
			break;
		}
		case CALIB_PROT_P05: {
			const e2e_p05_config_t c = { in->data_id, f->dlc, in->e2e_offset_byte,
						     in->max_delta_counter };

			(void)e2e_p05_protect(&c, tx, f->data, f->dlc);
			break;
		}
		default:
			can_signal_put(&in->counter, f->data, tx->counter % in->counter_modulus);
			tx->counter = (uint8_t)((tx->counter + 1U) % in->counter_modulus);
			break;
		}
	}
}
