/* SPDX-License-Identifier: MIT */
#include "decode_inputs.h"

#include <inttypes.h>
#include <string.h>

#include "calib_map.h"
#include "candump_hal.h"
#include "calib_text.h"
#include "sq_status.h"

static const char *const pos_names[CALIB_MAX_CORNERS] = { "FL", "FR", "RL", "RR" };

static input_geom_t geom_of(const calib_corner_t *c)
{
	return (input_geom_t){ c->pad_radius_um, c->wheel_radius_um,
			       (c->piston_area_cmm2 != 0U) ? c->piston_area_cmm2 : 100U,
			       c->efficiency_ppm, c->axle_factor_ppm };
}

int decode_inputs_load(decode_inputs_t *d, const char *path)
{
	char err[300];
	uint32_t i;
	uint32_t k;

	memset(d, 0, sizeof(*d));
	if (calib_text_load_map(path, &d->cal, &d->names, err, sizeof(err)) != SQ_OK) {
		fprintf(stderr, "squeal-sim decode: %s\n", err);
		return -1;
	}
	d->n_corners = calib_corner_count(&d->cal);
	for (k = 0U; k < d->n_corners; k++) {
		calib_input_t sp;
		calib_input_t fo;
		input_geom_t g;

		(void)calib_corner_view(&d->cal, k, &d->corner[k], &sp, &fo);
		g = geom_of(&d->corner[k]);
		if ((input_rx_setup(&sp, &g, &d->corner_rx[k][0]) != SQ_OK) ||
		    (input_rx_setup(&fo, &g, &d->corner_rx[k][1]) != SQ_OK)) {
			fprintf(stderr, "squeal-sim decode: %s: corner %u cannot be set up\n", path, k);
			return -1;
		}
	}
	if (d->cal.n_corners == 0U) {
		/* the legacy form: DiscSpeed and PadForce */
		d->n_inputs = 2U;
		d->rx[0] = d->corner_rx[0][0];
		d->rx[1] = d->corner_rx[0][1];
		snprintf(d->names.input[0], sizeof(d->names.input[0]), "DiscSpeed");
		snprintf(d->names.input[1], sizeof(d->names.input[1]), "PadForce");
	} else {
		d->n_inputs = d->cal.n_inputs;
		for (i = 0U; i < d->n_inputs; i++) {
			/* the geometry of the first corner that uses it (the raw and
			 * physical columns do not depend on it) */
			calib_corner_t c = d->corner[0];

			for (k = d->n_corners; k > 0U; k--) {
				if ((d->cal.corners[k - 1U].speed_input == i) ||
				    (d->cal.corners[k - 1U].force_input == i)) {
					c = d->cal.corners[k - 1U];
				}
			}
			const input_geom_t g = geom_of(&c);

			if (input_rx_setup(&d->cal.inputs[i], &g, &d->rx[i]) != SQ_OK) {
				fprintf(stderr, "squeal-sim decode: %s: input %s cannot be set up\n", path,
					d->names.input[i]);
				return -1;
			}
		}
	}
	for (i = 0U; i < d->n_inputs; i++) {
		input_rx_state_init(&d->st[i]);
	}
	return 0;
}

void decode_inputs_csv_header(FILE *out)
{
	fprintf(out, "t_s,iface,id,input,raw,physical,unit,valid,reason\n");
}

static double physical(const calib_input_t *in, int64_t value)
{
	return (double)value * calib_dec_value(in->factor) + calib_dec_value(in->offset);
}

/* The corners that use input i, as the monitor converts it. */
static void corner_views(decode_inputs_t *d, uint32_t i, int64_t value, FILE *out)
{
	uint32_t k;

	for (k = 0U; k < d->n_corners; k++) {
		const bool legacy = d->cal.n_corners == 0U;
		const bool sp = legacy ? (i == 0U) : (d->corner[k].speed_input == i);
		const bool fo = legacy ? (i == 1U) : (d->corner[k].force_input == i);

		if (sp) {
			const int32_t v0 = input_conv_apply(&d->corner_rx[k][0].conv, value);

			d->corner_v0_umps[k] = v0;
			fprintf(out, " %s:v0_mps=%.6f", pos_names[d->corner[k].pos], (double)v0 / 1e6);
		}
		if (fo) {
			int32_t n = input_conv_apply(&d->corner_rx[k][1].conv, value);

			if (d->corner_rx[k][1].conv.qty == (uint8_t)INPUT_QTY_TORQUE) {
				n = input_conv_torque_to_force(n, d->corner_v0_umps[k],
							       d->corner[k].friction_faces,
							       d->corner[k].pad_radius_um,
							       d->corner[k].mu_inf_q30,
							       d->corner[k].delta_mu_q30,
							       d->corner[k].slope_q24);
			}
			fprintf(out, " %s:force_N=%.3f", pos_names[d->corner[k].pos], (double)n / 1e3);
		}
	}
}

void decode_inputs_frame(decode_inputs_t *d, const candump_frame_t *f, bool csv, FILE *out)
{
	hal_can_frame_t h;
	uint32_t i;

	if (candump_to_hal(f, &h) != SQ_OK) {
		/* the firmware would not see it either: counted, said at the end */
		if (f->kind == CANDUMP_KIND_XL) {
			d->skipped_xl++;
		} else {
			d->skipped_fd++;
		}
		return;
	}
	for (i = 0U; i < d->n_inputs; i++) {
		const input_rx_cfg_t *cfg = &d->rx[i];
		bool id_only = false;
		input_rx_result_t r;
		input_rx_reason_t why;

		if (!input_rx_matches(cfg, &h, &id_only)) {
			continue;
		}
		r = input_rx_judge(cfg, &d->st[i], &h);
		why = (input_rx_reason_t)r.reason;
		if (csv) {
			fprintf(out, "%" PRIu64 ".%06" PRIu64 ",%s,", f->t_ns / 1000000000U,
				(f->t_ns % 1000000000U) / 1000U, f->iface);
			fprintf(out, f->ext ? "%08" PRIX32 : "%03" PRIX32, f->id);
			fprintf(out, ",%s,", d->names.input[i]);
			if (why == INPUT_RX_DLC) {
				fprintf(out, ",");
			} else {
				fprintf(out, "%" PRId64 ",%.9g", r.value, physical(&cfg->desc, r.value));
			}
			fprintf(out, ",%s,%d,%s\n", input_unit_name((input_unit_t)cfg->desc.unit),
				why == INPUT_RX_OK ? 1 : 0, input_rx_reason_name(why));
			continue;
		}
		fprintf(out, "  %s", d->names.input[i]);
		if (why != INPUT_RX_DLC) {
			fprintf(out, " raw=%" PRId64 " phys=%.9g %s", r.value,
				physical(&cfg->desc, r.value),
				input_unit_name((input_unit_t)cfg->desc.unit));
		}
		fprintf(out, " valid=%d reason=%s", why == INPUT_RX_OK ? 1 : 0,
			input_rx_reason_name(why));
		if (why == INPUT_RX_OK) {
			corner_views(d, i, r.value, out);
		}
		fprintf(out, "\n");
	}
}

void decode_inputs_summary(const decode_inputs_t *d, FILE *out)
{
	if ((d->skipped_xl + d->skipped_fd) == 0U) {
		return;
	}
	fprintf(out, "squeal-sim decode: %" PRIu64 " frames not decoded as inputs (CAN XL %" PRIu64
		", CAN FD longer than this build's %u-byte frames %" PRIu64 ")\n",
		d->skipped_xl + d->skipped_fd, d->skipped_xl, (unsigned)HAL_CAN_MAX_DLEN,
		d->skipped_fd);
}
