/* SPDX-License-Identifier: MIT */
/* replay_summary: episodes, time per state and occupancy per corner from the
 * ECU's frames; see replay_summary.h. */
#include "replay_summary.h"

#include <stddef.h>
#include <string.h>

#include "squeal_msgs.h"
#include "sq_status.h"

const char *rs_state_name(unsigned i)
{
	const char *n = msg_squeal_state_name(
		(uint8_t)((i < MSG_SQUEAL_STATE_SLOT_FAULT) ? i : MSG_SQUEAL_STATE_FAULT));

	return (n != NULL) ? n : "?";
}
const char *const rs_corner_names[RS_CORNERS_MAX] = { "FL", "FR", "RL", "RR" };

/* The signals read, looked up once by their DBC names. */
typedef struct {
	const msg_sig_desc_t *state;
	const msg_sig_desc_t *warning;
	const msg_sig_desc_t *margin;
	const msg_sig_desc_t *v0;
	const msg_sig_desc_t *force;
} rs_sigs_t;

static rs_sigs_t sigs;

static const msg_sig_desc_t *sig_find(uint16_t msg_id, const char *name)
{
	unsigned i;

	for (i = 0U; i < MSG_SIG_COUNT; i++) {
		if ((msg_sig_table[i].msg_id == msg_id) && (strcmp(msg_sig_table[i].name, name) == 0)) {
			return &msg_sig_table[i];
		}
	}
	return NULL;
}

/* Raw value of sig in f; false when the frame does not carry it, or it is
 * the signal's "not available" value. */
static bool raw_of(const msg_sig_desc_t *sig, const hal_can_frame_t *f, int32_t *raw)
{
	if ((sig == NULL) || (msg_sig_get_raw(sig, f->data, f->dlc, raw) != SQ_OK)) {
		return false;
	}
	return ((sig->flags & MSG_SIG_HAS_NA) == 0U) || (*raw != sig->na_raw);
}

/* physical = (raw * num + off) / den, as an exact decimal when den divides
 * a power of ten up to 10^6 (every factor in the DBC does). */
static void write_phys(json_writer_t *w, const msg_sig_desc_t *sig, bool have, int32_t raw)
{
	const int64_t num = (int64_t)raw * sig->factor_num + sig->offset_num;
	int64_t scale = 1;
	unsigned dec = 0U;

	if (!have) {
		json_null(w);
		return;
	}
	while ((dec < 6U) && ((scale % sig->factor_den) != 0)) {
		scale *= 10;
		dec++;
	}
	if ((scale % sig->factor_den) == 0) {
		json_fixed(w, num * (scale / sig->factor_den), dec);
	} else {
		json_double(w, (double)num / (double)sig->factor_den);
	}
}

void replay_summary_set_corner(replay_summary_t *rs, unsigned k, const rs_corner_ids_t *ids)
{
	if (k < RS_CORNERS_MAX) {
		rs->corner[k].ids = *ids;
	}
}

void replay_summary_set_ids(replay_summary_t *rs, const rs_corner_ids_t *base)
{
	unsigned k;

	for (k = 0U; k < RS_CORNERS_MAX; k++) {
		rs_corner_ids_t ids = *base;

		ids.status_id = (uint16_t)(ids.status_id + k * RS_CORNER_ID_STEP);
		ids.detail_id = (uint16_t)(ids.detail_id + k * RS_CORNER_ID_STEP);
		ids.detail2_id = (uint16_t)(ids.detail2_id + k * RS_CORNER_ID_STEP);
		rs->corner[k].ids = ids;
	}
}

_Static_assert(offsetof(rs_corner_t, cell_us) + sizeof(((rs_corner_t *)NULL)->cell_us) ==
	       sizeof(rs_corner_t), "the cells are a corner's last member (replay_summary_init)");

void replay_summary_init(replay_summary_t *rs, json_writer_t *w)
{
	static const rs_corner_ids_t dbc = {
		MSG_SQUEAL_STATUS_ID, MSG_SQUEAL_DETAIL_ID, MSG_SQUEAL_DETAIL2_ID
	};

	unsigned k;

	for (k = 0U; k < RS_CORNERS_MAX; k++) {
		rs_corner_t *c = &rs->corner[k];

		if (c->cells_used) {
			memset(c->cell_us, 0, sizeof(c->cell_us));
		}
		memset(c, 0, offsetof(rs_corner_t, cell_us));
	}
	rs->finished = false;
	rs->w = w;
	sigs.state = sig_find(MSG_SQUEAL_STATUS_ID, "SquealState");
	sigs.warning = sig_find(MSG_SQUEAL_STATUS_ID, "WarningLevel");
	sigs.margin = sig_find(MSG_SQUEAL_STATUS_ID, "HopfMargin_mps");
	sigs.v0 = sig_find(MSG_SQUEAL_DETAIL_ID, "V0_mps");
	sigs.force = sig_find(MSG_SQUEAL_DETAIL2_ID, "Force_N");
	if ((sigs.state == NULL) || (sigs.warning == NULL) || (sigs.margin == NULL) ||
	    (sigs.v0 == NULL) || (sigs.force == NULL)) {
		w->error = true; /* the descriptor table lost a signal: a build error */
	}
	replay_summary_set_ids(rs, &dbc);
	json_key(w, "episodes");
	json_begin_array(w);
}

static void write_episode(replay_summary_t *rs, unsigned k, uint64_t end_us)
{
	json_writer_t *w = rs->w;
	const rs_episode_t *e = &rs->corner[k].ep;

	json_begin_object(w);
	json_kv_string(w, "corner", rs_corner_names[k]);
	json_kv_string(w, "state", rs_state_name(e->state));
	json_kv_seconds(w, "start_s", e->start_us);
	json_kv_seconds(w, "end_s", end_us);
	json_kv_u64(w, "warning_level", e->warning_max);
	json_key(w, "v0_min_mps");
	write_phys(w, sigs.v0, e->have_v0, e->v0_min);
	json_key(w, "v0_max_mps");
	write_phys(w, sigs.v0, e->have_v0, e->v0_max);
	json_key(w, "force_min_n");
	write_phys(w, sigs.force, e->have_force, e->force_min);
	json_key(w, "force_max_n");
	write_phys(w, sigs.force, e->have_force, e->force_max);
	json_key(w, "min_hopf_margin_mps");
	write_phys(w, sigs.margin, e->have_margin, e->margin_min);
	json_end_object(w);
	rs->corner[k].episodes++;
}

static unsigned bin_of(int32_t raw, int32_t per_bin, unsigned bins)
{
	const int32_t b = (raw < 0) ? 0 : raw / per_bin;

	return ((unsigned)b >= bins) ? bins - 1U : (unsigned)b;
}

/* The time since the corner's last frame counts for what held before. */
static void account(rs_corner_t *c, uint64_t t_us)
{
	uint64_t dt;

	if (!c->seen || (t_us <= c->last_us)) {
		return;
	}
	dt = t_us - c->last_us;
	c->state_us[c->state] += dt;
	if (c->have_v0 && c->have_force) {
		/* raw V0_mps is 0.01 m/s, raw Force_N 0.5 N */
		c->cell_us[c->state][bin_of(c->v0_raw, (int32_t)RS_V0_BIN_CMPS, RS_V0_BINS)]
			  [bin_of(c->force_raw, (int32_t)(2U * RS_FORCE_BIN_N), RS_FORCE_BINS)] += dt;
		c->cells_used = true;
	}
	c->last_us = t_us;
}

static void on_status(replay_summary_t *rs, unsigned k, const hal_can_frame_t *f)
{
	rs_corner_t *c = &rs->corner[k];
	rs_episode_t *e = &c->ep;
	int32_t st;
	int32_t lvl;
	int32_t margin;
	bool have_margin;
	unsigned s;

	if (!raw_of(sigs.state, f, &st) || !raw_of(sigs.warning, f, &lvl)) {
		return; /* wrong DLC: not a status frame of ours */
	}
	have_margin = raw_of(sigs.margin, f, &margin);
	s = msg_squeal_state_slot((uint32_t)st);
	if (!c->seen) {
		c->seen = true;
		c->first_us = f->timestamp_us;
		c->last_us = f->timestamp_us;
	}
	c->state = (uint8_t)s;
	if (e->open && (e->state != s)) {
		write_episode(rs, k, f->timestamp_us);
		e->open = false;
	}
	if (!e->open) {
		memset(e, 0, sizeof(*e));
		e->open = true;
		e->state = (uint8_t)s;
		e->start_us = f->timestamp_us;
	}
	if ((uint32_t)lvl > e->warning_max) {
		e->warning_max = (uint8_t)lvl;
	}
	if (have_margin && (!e->have_margin || (margin < e->margin_min))) {
		e->have_margin = true;
		e->margin_min = margin;
	}
}

static void range(bool *have, int32_t *lo, int32_t *hi, int32_t v)
{
	if (!*have || (v < *lo)) {
		*lo = v;
	}
	if (!*have || (v > *hi)) {
		*hi = v;
	}
	*have = true;
}

/* A detail frame's value (have: it carries one) and, in an open episode,
 * the episode's range of it. */
static void take_value(const msg_sig_desc_t *sig, const hal_can_frame_t *f, bool open, bool *have,
		       int32_t *raw, bool *ep_have, int32_t *lo, int32_t *hi)
{
	int32_t v = 0;

	*have = raw_of(sig, f, &v);
	*raw = v;
	if (*have && open) {
		range(ep_have, lo, hi, v);
	}
}

void replay_summary_on_frame(replay_summary_t *rs, const hal_can_frame_t *f)
{
	unsigned k;

	if ((f->flags & (HAL_CAN_FLAG_EXT | HAL_CAN_FLAG_RTR | HAL_CAN_FLAG_ERR)) != 0U) {
		return;
	}
	for (k = 0U; k < RS_CORNERS_MAX; k++) {
		rs_corner_t *c = &rs->corner[k];

		if (f->id == c->ids.status_id) {
			account(c, f->timestamp_us);
			on_status(rs, k, f);
		} else if (f->id == c->ids.detail_id) {
			account(c, f->timestamp_us);
			take_value(sigs.v0, f, c->ep.open, &c->have_v0, &c->v0_raw, &c->ep.have_v0,
				   &c->ep.v0_min, &c->ep.v0_max);
		} else if (f->id == c->ids.detail2_id) {
			account(c, f->timestamp_us);
			take_value(sigs.force, f, c->ep.open, &c->have_force, &c->force_raw,
				   &c->ep.have_force, &c->ep.force_min, &c->ep.force_max);
		} else {
			continue;
		}
		return;
	}
}

void rs_json_state_times(json_writer_t *w, const char *key, const uint64_t us[RS_N_STATES])
{
	unsigned s;

	json_key(w, key);
	json_begin_object(w);
	for (s = 0U; s < RS_N_STATES; s++) {
		json_kv_seconds(w, rs_state_name(s), us[s]);
	}
	json_end_object(w);
}

static void write_corner(const replay_summary_t *rs, unsigned k)
{
	json_writer_t *w = rs->w;
	const rs_corner_t *c = &rs->corner[k];
	unsigned s;
	unsigned i;
	unsigned j;

	json_begin_object(w);
	json_kv_string(w, "corner", rs_corner_names[k]);
	json_kv_u64(w, "status_id", c->ids.status_id);
	json_kv_u64(w, "detail_id", c->ids.detail_id);
	json_kv_u64(w, "detail2_id", c->ids.detail2_id);
	json_kv_seconds(w, "first_s", c->first_us);
	json_kv_seconds(w, "end_s", c->last_us);
	json_kv_u64(w, "episodes", c->episodes);
	rs_json_state_times(w, "state_time_s", c->state_us);
	/* occupancy: [v0 cell, force cell, state, seconds], non-zero cells only */
	json_key(w, "cells");
	json_begin_array(w);
	for (s = 0U; s < RS_N_STATES; s++) {
		for (i = 0U; i < RS_V0_BINS; i++) {
			for (j = 0U; j < RS_FORCE_BINS; j++) {
				if (c->cell_us[s][i][j] == 0U) {
					continue;
				}
				json_begin_array(w);
				json_u64(w, i);
				json_u64(w, j);
				json_string(w, rs_state_name(s));
				json_fixed(w, (int64_t)c->cell_us[s][i][j], 6U);
				json_end_array(w);
			}
		}
	}
	json_end_array(w);
	json_end_object(w);
}

void replay_summary_finish(replay_summary_t *rs, uint64_t end_us)
{
	json_writer_t *w = rs->w;
	unsigned k;

	if (rs->finished) {
		return;
	}
	rs->finished = true;
	for (k = 0U; k < RS_CORNERS_MAX; k++) {
		account(&rs->corner[k], end_us);
		if (rs->corner[k].ep.open) {
			write_episode(rs, k, end_us);
			rs->corner[k].ep.open = false;
		}
	}
	json_end_array(w);
	json_key(w, "cells_grid");
	json_begin_object(w);
	json_key(w, "v0_bin_mps");
	json_fixed(w, RS_V0_BIN_CMPS, 2U);
	json_kv_u64(w, "v0_bins", RS_V0_BINS);
	json_kv_u64(w, "force_bin_n", RS_FORCE_BIN_N);
	json_kv_u64(w, "force_bins", RS_FORCE_BINS);
	json_kv_string(w, "note", "cell i covers [i, i+1) bins from 0; values beyond the last cell count in it");
	json_end_object(w);
	json_key(w, "corners");
	json_begin_array(w);
	for (k = 0U; k < RS_CORNERS_MAX; k++) {
		if (rs->corner[k].seen) {
			write_corner(rs, k);
		}
	}
	json_end_array(w);
}
