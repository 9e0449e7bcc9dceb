/* SPDX-License-Identifier: MIT */
#include "monitor.h"

#include <stddef.h>

#include "hal.h"
#include "calib_map.h"
#include "sq_status.h"

#define US_PER_MS 1000U
#define PPM_ONE 1000000
#define NO_BORDER_MARGIN_RAW MSG_HOPF_MARGIN_MPS_MAX

static void sat_inc(uint32_t *c)
{
	if (*c < UINT32_MAX) {
		(*c)++;
	}
}

static void sat_add(uint32_t *c, uint32_t n)
{
	*c = (*c > UINT32_MAX - n) ? UINT32_MAX : (*c + n);
}

static uint16_t sat_u16(uint32_t v)
{
	return (v > 0xFFFFU) ? 0xFFFFU : (uint16_t)v;
}

static void input_init(input_t *in, uint64_t now_us)
{
	input_rx_state_init(&in->rx);
	in->faults = INPUT_FAULT_NEVER_SEEN;
	in->value = 0;
	in->filtered_q8 = 0;
	in->last_used_us = now_us;
	in->last_seen_us = now_us;
	in->fresh = false;
	in->count = (input_counters_t){ 0 };
}

static input_geom_t corner_geom(const calib_corner_t *c)
{
	return (input_geom_t){ c->pad_radius_um, c->wheel_radius_um, c->piston_area_cmm2,
			       c->efficiency_ppm, c->axle_factor_ppm };
}

/* This corner's brake and inputs; SQ_EINVAL if the calibration has none. */
static int corner_setup(monitor_t *me, uint32_t k)
{
	calib_input_t speed;
	calib_input_t force;
	input_geom_t g;

	if ((calib_validate(me->cal) != SQ_OK) ||
	    (calib_corner_view(me->cal, k, &me->corner, &speed, &force) != SQ_OK)) {
		return SQ_EINVAL;
	}
	g = corner_geom(&me->corner);
	if ((input_rx_setup(&speed, &g, &me->speed_rx) != SQ_OK) ||
	    (input_rx_setup(&force, &g, &me->force_rx) != SQ_OK)) {
		return SQ_EINVAL;
	}
	me->corner_index = (uint8_t)k;
	return SQ_OK;
}

/* Any deviation calibrated? All 0: no propagation at all (today's crisp
 * classes, and no cost). */
static bool sd_nonzero(const calib_sd_t *sd)
{
	return (sd->mass_sd_q16 != 0) || (sd->omega0_sd_q12 != 0) || (sd->damping_sd_q30 != 0) ||
	       (sd->mu_inf_sd_q30 != 0) || (sd->delta_mu_sd_q30 != 0) || (sd->slope_sd_q24 != 0);
}

int monitor_init_corner(monitor_t *me, const calib_t *cal, uint32_t k,
			bool calib_invalid, uint32_t platform_faults, uint64_t now_us)
{
	int rc = SQ_OK;

	HAL_REQUIRE(me != NULL);
	*me = (monitor_t){ 0 };
	me->cal = cal;
	me->calib_invalid = calib_invalid;
	if ((cal == NULL) || (corner_setup(me, k) != SQ_OK)) {
		me->cal = calib_factory();
		(void)corner_setup(me, 0U); /* the defaults always set up */
		me->calib_invalid = true;
		rc = SQ_EINVAL;
	}
	calib_corner_params(&me->corner, &me->params);
	calib_corner_sd(&me->corner, &me->sd);
	me->sigma_on = sd_nonzero(&me->corner.sd);
	me->margin_q16 = MODEL_MARGIN_NONE;
	me->platform_faults = platform_faults;
	input_init(&me->speed, now_us);
	input_init(&me->force, now_us);
	me->state = MONITOR_STATE_FAULT; /* until the first classification */
	me->candidate = MONITOR_STATE_FAULT;
	e2e_p01_tx_init(&me->tx_status);
	e2e_p01_tx_init(&me->tx_detail);
	e2e_p01_tx_init(&me->tx_detail2);
	e2e_p01_tx_init(&me->tx_diag);
	me->start_us = now_us;
	me->now_us = now_us;
	/* corner k sends its periodic messages k ms after corner 0: the
	 * corners' transmissions (and their E2E work) fall into different
	 * 1 ms steps */
	me->next_status_us = now_us + ((uint64_t)me->corner_index * US_PER_MS);
	me->next_detail_us = me->next_status_us;
	me->next_diag_us = me->next_status_us;
	me->selftest = (monitor_selftest_t){ (uint8_t)MSG_HSE_FREQ_NA, (uint8_t)MSG_RESET_CAUSE_MAX,
					     (uint8_t)MSG_BOR_LEVEL_NA, { 2U, 2U },
					     (uint16_t)MSG_STACK_HWM_UNKNOWN, false };
	me->started = true;
	return rc;
}

int monitor_init(monitor_t *me, const calib_t *cal, bool calib_invalid,
		 uint32_t platform_faults, uint64_t now_us)
{
	return monitor_init_corner(me, cal, 0U, calib_invalid, platform_faults, now_us);
}

int monitor_set_selftest(monitor_t *me, const monitor_selftest_t *st)
{
	HAL_REQUIRE(me != NULL);
	HAL_REQUIRE(st != NULL);
	if ((st->reset_cause > MSG_RESET_CAUSE_MAX) ||
	    ((st->bor_level > 3U) && (st->bor_level != MSG_BOR_LEVEL_NA)) ||
	    (st->loopback[0] > MSG_LOOPBACK_MAX) || (st->loopback[1] > MSG_LOOPBACK_MAX) ||
	    (st->stack_high_water_b > MSG_STACK_HWM_UNKNOWN)) {
		return SQ_ERANGE;
	}
	me->selftest = *st;
	return SQ_OK;
}

/* ---- inputs -------------------------------------------------------------- */

/* Filter one used value and mark it fresh. */
static void input_accept(monitor_t *me, input_t *in, int32_t value,
			 uint64_t t_us)
{
	const int64_t x_q8 = (int64_t)value * 256;

	if ((in->faults & INPUT_FAULT_NEVER_SEEN) != 0U) {
		in->filtered_q8 = x_q8; /* start the filter at the value */
	} else {
		/* first-order low pass, alpha in Q15 (32768 = no filtering) */
		in->filtered_q8 += (((x_q8 - in->filtered_q8) *
				    (int64_t)me->cal->lowpass_alpha_q15) / 32768);
	}
	in->value = (int32_t)(in->filtered_q8 / 256);
	in->faults &= ~(INPUT_FAULT_IMPLAUSIBLE | INPUT_FAULT_STALE |
			INPUT_FAULT_NEVER_SEEN | INPUT_FAULT_E2E);
	in->last_used_us = t_us;
	in->fresh = true;
}

static uint64_t frame_time(const monitor_t *me, const hal_can_frame_t *f)
{
	/* HAL timestamps share hal_time_us()'s clock; a frame stamped in
	 * the future (clock glitch) is taken as received now */
	return ((f->timestamp_us != 0U) && (f->timestamp_us <= me->now_us)) ?
		f->timestamp_us : me->now_us;
}

/* A used raw value in the monitor's units: v0 [um/s] or N [mN]. */
static int32_t input_value(const monitor_t *me, const input_rx_cfg_t *cfg, int64_t raw)
{
	int32_t value = input_conv_apply(&cfg->conv, raw);

	if (cfg->conv.qty == (uint8_t)INPUT_QTY_TORQUE) {
		/* N = T / (n_f mu(v0) r_p) at the corner's current v0 */
		value = input_conv_torque_to_force(value, me->speed.value,
						   me->corner.friction_faces,
						   me->corner.pad_radius_um,
						   me->corner.mu_inf_q30,
						   me->corner.delta_mu_q30,
						   me->corner.slope_q24);
	}
	return value;
}

/* What one verdict of the input stage does to its input. */
typedef struct {
	uint8_t fault;   /* INPUT_FAULT_* it raises (0: none)              */
	uint8_t counter; /* offset of the uint32_t it counts in, in input_counters_t */
} verdict_rule_t;

/* The uint32_t counter at this offset (offsetof) of c. */
static uint32_t *counter_at(input_counters_t *c, uint8_t offset)
{
	return (uint32_t *)(void *)&((uint8_t *)c)[offset];
}

/*
 * One frame of one input: the input stage's verdict, recorded. Nothing
 * here checks the frame again: the verdict's counter and fault, the last
 * time a frame with a good protection was seen (staleness tells a silent
 * sender from a frozen one), and a used value converted and filtered.
 */
static void input_frame(monitor_t *me, input_t *in, const input_rx_cfg_t *cfg,
			const hal_can_frame_t *f)
{
	/*
	 * The fault each verdict raises and the counter it counts in. A frame
	 * that fails its length or its protection is an E2E fault; one that
	 * passed the protection but carries no usable value ("not available",
	 * qualifier, range, step) makes the input implausible until a usable
	 * value arrives; a repeated counter is no new data, not an error: a
	 * frozen sender goes stale.
	 */
#define VERDICT(fault, counter) { (uint8_t)(fault), (uint8_t)offsetof(input_counters_t, counter) }
	static const verdict_rule_t verdict[INPUT_RX_REASON_COUNT] = {
		VERDICT(0U, used),                                   /* ok        */
		VERDICT(INPUT_FAULT_E2E, bad_dlc),                   /* dlc       */
		VERDICT(INPUT_FAULT_E2E, e2e_wrong_crc),             /* crc       */
		VERDICT(INPUT_FAULT_E2E, e2e_wrong_sequence),        /* counter   */
		VERDICT(0U, e2e_repeated),                           /* repeated  */
		VERDICT(INPUT_FAULT_IMPLAUSIBLE, implausible),       /* na        */
		VERDICT(INPUT_FAULT_IMPLAUSIBLE, implausible),       /* qualifier */
		VERDICT(INPUT_FAULT_IMPLAUSIBLE, implausible),       /* range     */
		VERDICT(INPUT_FAULT_IMPLAUSIBLE, implausible),       /* step      */
	};
	/* the reason is an input_rx_reason_t below INPUT_RX_REASON_COUNT */
	const input_rx_result_t r = input_rx_judge(cfg, &in->rx, f);
	const input_rx_reason_t why = (input_rx_reason_t)r.reason;
	const uint32_t fault = verdict[r.reason].fault;
	const uint64_t t_us = frame_time(me, f);

	sat_inc(&in->count.frames);
	sat_inc(counter_at(&in->count, verdict[r.reason].counter));
	sat_inc(&in->count.verdict[r.reason]);
	in->faults |= fault;
	if ((fault != INPUT_FAULT_E2E) && (r.e2e_status != (uint8_t)E2E_P01_STATUS_NONEWDATA)) {
		sat_add(&in->count.e2e_lost, r.lost);
		in->last_seen_us = t_us;
	}
	if (why == INPUT_RX_OK) {
		input_accept(me, in, input_value(me, cfg, r.value), t_us);
	}
}

void monitor_on_frame(monitor_t *me, const hal_can_frame_t *frame)
{
	bool speed_fmt = false;
	bool force_fmt = false;
	bool used = false;

	HAL_REQUIRE((me != NULL) && (frame != NULL));
	if (!me->started) {
		return;
	}
	if ((frame->flags & HAL_CAN_FLAG_ERR) != 0U) {
		sat_inc(&me->count.error_frames);
		return;
	}
	/* one frame may carry both inputs (a vehicle's ESC frame) */
	if (input_rx_matches(&me->speed_rx, frame, &speed_fmt)) {
		input_frame(me, &me->speed, &me->speed_rx, frame);
		used = true;
	}
	if (input_rx_matches(&me->force_rx, frame, &force_fmt)) {
		input_frame(me, &me->force, &me->force_rx, frame);
		used = true;
	}
	if (!used) {
		if (speed_fmt || force_fmt) {
			sat_inc(&me->count.rtr_or_ext);
		} else {
			sat_inc(&me->count.unknown_id);
		}
	}
}

void monitor_on_can_status(monitor_t *me, const hal_can_status_t *status)
{
	HAL_REQUIRE((me != NULL) && (status != NULL));
	if ((status->state == HAL_CAN_STATE_BUS_OFF) || (status->bus_off_count != 0U)) {
		me->bus_off_seen = true;
	}
	me->count.bus_off_events = status->bus_off_count;
	me->count.rx_overruns = status->rx_overruns;
}

void monitor_report_task_time(monitor_t *me, uint32_t task_us)
{
	HAL_REQUIRE(me != NULL);
	if (task_us > me->worst_task_us) {
		me->worst_task_us = task_us;
	}
}

/* Staleness and the E2E "no new data" cycle of one input. */
static void input_tick(monitor_t *me, input_t *in, const input_rx_cfg_t *cfg)
{
	const uint64_t period_us = (uint64_t)cfg->desc.period_ms * US_PER_MS;
	const uint64_t timeout_us = period_us * cfg->desc.stale_cycles;
	const uint64_t age = (me->now_us > in->last_used_us) ?
		(me->now_us - in->last_used_us) : 0U;

	if ((age > timeout_us) && ((in->faults & INPUT_FAULT_STALE) == 0U)) {
		const uint64_t silent = (me->now_us > in->last_seen_us) ?
			(me->now_us - in->last_seen_us) : 0U;

		in->faults |= INPUT_FAULT_STALE;
		sat_inc(&in->count.stale_events);
		/* after a real outage the E2E receiver starts over (P01: the
		 * next good frame is INITIAL, whatever its counter); but a
		 * sender that kept sending its last frame is frozen: keep the
		 * reference so its repeats stay REPEATED and the input FAULT */
		if (silent > timeout_us) {
			e2e_p01_rx_reset(&in->rx.e2e);
		}
		in->rx.has_prev = false;
		in->fresh = false;
	}
}

/* ---- classify ------------------------------------------------------------ */

/*
 * One classification of the fresh input pair, with its uncertainty in the
 * same pass when deviations are calibrated (model_adapter_eval_sd: the
 * model's case and terms once, the corner's own criterion's borders).
 * sig->state is a class (STABLE, BISTABLE, UNSTABLE) when sig holds this
 * classification's borders, INVALID when nothing was propagated.
 */
static uint8_t classify_pair(monitor_t *me, squeal_sigma_result_t *sig)
{
	const int32_t v0 = me->speed.value;
	const int32_t force = me->force.value;
	uint8_t cls;
	int rc = SQ_OK;

	sat_inc(&me->count.classifications);
	me->speed.fresh = false;
	me->force.fresh = false;
	sig->state = SQUEAL_STATE_INVALID;
	if (((uint32_t)v0 < me->cal->v0_min_umps) || ((uint32_t)force < me->cal->force_min_mn)) {
		/* below the thresholds: not sliding, without the model */
		me->eval = (model_eval_t){ .state = SQUEAL_STATE_NOT_SLIDING };
	} else if (me->sigma_on) {
		rc = model_adapter_eval_sd(&me->params, &me->sd, (squeal_criterion_t)me->corner.criterion,
					   v0, force, &me->eval, sig);
	} else {
		rc = model_adapter_eval(&me->params, (squeal_criterion_t)me->corner.criterion,
					v0, force, &me->eval);
	}
	if (rc != SQ_OK) {
		/* the model refused the point: no class */
		sat_inc(&me->count.model_invalid);
		me->have_eval = false;
		cls = MONITOR_STATE_FAULT;
	} else {
		me->have_eval = true;
		cls = (uint8_t)me->eval.state;
	}
	return cls;
}

/* ---- debounce ------------------------------------------------------------ */

static uint32_t abs32(int32_t v)
{
	return (v < 0) ? (uint32_t)(-(int64_t)v) : (uint32_t)v;
}

/* Is the new classification far enough beyond the border it crossed? */
static bool beyond_band(const monitor_t *me, uint8_t from, uint8_t to)
{
	const bool hopf = (from == (uint8_t)SQUEAL_STATE_UNSTABLE) ||
			  (to == (uint8_t)SQUEAL_STATE_UNSTABLE);

	if (hopf) {
		return ((me->eval.has & MODEL_EVAL_HAS_LNQ) != 0U) &&
		       (abs32(me->eval.ln_2q_micro) > me->cal->hyst_lnq_micro);
	}
	/* stable <-> bistable: rho crosses 1 */
	return ((me->eval.has & MODEL_EVAL_HAS_BASIN) == 0U) ||
	       (abs32(me->eval.basin_ratio_ppm - PPM_ONE) > me->cal->hyst_rho_ppm);
}

static void set_state(monitor_t *me, uint8_t state)
{
	if (state != me->state) {
		me->state = state;
		sat_inc(&me->count.state_changes);
		me->status_now = true;
	}
	me->candidate = state;
	me->candidate_count = 0U;
}

static void debounce(monitor_t *me, uint8_t cls)
{
	if (cls == me->state) {
		me->candidate = cls;
		me->candidate_count = 0U;
		return;
	}
	/* immediate: out of FAULT, into "not sliding" (v0 or N fell below
	 * its threshold: certain), or a point clearly beyond the border */
	if ((me->state == MONITOR_STATE_FAULT) || (cls == (uint8_t)SQUEAL_STATE_NOT_SLIDING) ||
	    ((me->state != (uint8_t)SQUEAL_STATE_NOT_SLIDING) &&
	     beyond_band(me, me->state, cls))) {
		set_state(me, cls);
		return;
	}
	if (cls == me->candidate) {
		if (me->candidate_count < UINT8_MAX) {
			me->candidate_count++;
		}
	} else {
		me->candidate = cls;
		me->candidate_count = 1U;
	}
	if (me->candidate_count >= me->cal->debounce_count) {
		set_state(me, cls);
	}
}

/* ---- uncertainty and warning level of the debounced class ---------------- */

/*
 * The uncertainty of the debounced class (docs/uncertainty.md):
 * BorderMargin of `state` and whether the point is within k sigma of the
 * border to the MORE severe neighbouring class (stable: the stable border,
 * next to bistable; bistable: the Hopf border, next to unstable; unstable
 * has no more severe neighbour). Only with deviations calibrated; the
 * result of the latest classification (sig, valid) or none.
 */
static void update_uncertainty(monitor_t *me, const squeal_sigma_result_t *sig, bool valid)
{
	int32_t toward = MODEL_MARGIN_NONE;

	me->uncertain = false;
	me->margin_q16 = MODEL_MARGIN_NONE;
	if (valid && (me->state <= (uint8_t)SQUEAL_STATE_UNSTABLE)) {
		/* STABLE 0, BISTABLE 1, UNSTABLE 2: a class with a border */
		me->margin_q16 = model_adapter_margin_q16(sig, (squeal_state_t)me->state);
		if (me->state == (uint8_t)SQUEAL_STATE_STABLE) {
			toward = me->margin_q16;
		} else if (me->state == (uint8_t)SQUEAL_STATE_BISTABLE) {
			toward = model_adapter_margin_q16(sig, SQUEAL_STATE_UNSTABLE); /* g_H */
		} else {
			/* unstable: already the most severe */
		}
		me->uncertain = toward < me->cal->uncertain_k_q16;
	}
}

static uint8_t warning_level(const monitor_t *me)
{
	switch (me->state) {
	case SQUEAL_STATE_UNSTABLE:
		return MSG_WARNING_LEVEL_CRITICAL;
	case SQUEAL_STATE_BISTABLE:
		if (me->uncertain) {
			return MSG_WARNING_LEVEL_CRITICAL; /* within k sigma of Hopf */
		}
		/* small basin (rho below the threshold): a small disturbance
		 * starts stick-slip */
		if (((me->eval.has & MODEL_EVAL_HAS_BASIN) == 0U) ||
		    ((uint32_t)me->eval.basin_ratio_ppm < me->cal->rho_warn_ppm)) {
			return MSG_WARNING_LEVEL_WARNING;
		}
		return MSG_WARNING_LEVEL_ADVISORY;
	case SQUEAL_STATE_STABLE:
		/* within k sigma of the stable border: the level of the
		 * bistable side of it, where rho -> 1 */
		if (me->uncertain) {
			return ((uint32_t)PPM_ONE < me->cal->rho_warn_ppm) ?
				MSG_WARNING_LEVEL_WARNING : MSG_WARNING_LEVEL_ADVISORY;
		}
		return MSG_WARNING_LEVEL_NONE;
	default:
		return MSG_WARNING_LEVEL_NONE;
	}
}

/* Warning level of the debounced state; a change is sent at once. */
static void update_warning(monitor_t *me)
{
	const uint8_t warning = warning_level(me);

	if (warning != me->warning) {
		me->warning = warning;
		me->status_now = true;
	}
}

/* ---- encode: transmit ---------------------------------------------------- */

static void tx_push(monitor_t *me, uint16_t id, const uint8_t *data, uint8_t dlc)
{
	hal_can_frame_t *f;
	uint32_t i;

	if (me->txq_count >= MONITOR_TX_QUEUE_LEN) {
		sat_inc(&me->count.tx_overflow);
		return;
	}
	f = &me->txq[(me->txq_head + me->txq_count) % MONITOR_TX_QUEUE_LEN];
	*f = (hal_can_frame_t){ 0 };
	f->id = id;
	f->dlc = dlc;
	for (i = 0U; i < dlc; i++) {
		f->data[i] = data[i];
	}
	f->timestamp_us = me->now_us;
	me->txq_count++;
}

/* protect with E2E P01 and queue; a pack error is a firmware bug: count it
 * as a TX error rather than send a wrong frame */
static void tx_protected(monitor_t *me, uint16_t id, uint16_t data_id,
			 e2e_p01_tx_t *tx, uint8_t *data, uint8_t dlc, int pack_rc)
{
	const e2e_p01_config_t cfg = { data_id, dlc, 1U };

	if ((pack_rc != SQ_OK) || (e2e_p01_protect(&cfg, tx, data, dlc) != SQ_OK)) {
		sat_inc(&me->count.tx_errors);
		return;
	}
	tx_push(me, id, data, dlc);
}

static bool classified(const monitor_t *me)
{
	return me->have_eval && (me->state != MONITOR_STATE_FAULT) &&
	       (me->state != (uint8_t)SQUEAL_STATE_NOT_SLIDING);
}

/* um/s -> 0.01 m/s, rounded, clamped to [0, max] */
static uint16_t umps_to_cmps(int32_t umps, uint16_t max)
{
	int64_t v = ((int64_t)umps + 5000) / 10000;

	if (v < 0) {
		v = 0;
	}
	return (v > (int64_t)max) ? max : (uint16_t)v;
}

static void send_status(monitor_t *me)
{
	msg_squeal_status_t m = { 0 };
	uint8_t data[8];
	uint8_t dlc = 0U;
	int rc;

	m.squeal_state = me->state;
	m.warning_level = me->warning;
	m.basin_ratio = MSG_BASIN_RATIO_NA;
	m.hopf_margin_mps = MSG_HOPF_MARGIN_MPS_NA;
	if (classified(me)) {
		if ((me->eval.has & MODEL_EVAL_HAS_BASIN) != 0U) {
			/* 64 bit: the ratio saturates at INT32_MAX ppm and
			 * + 50 must not overflow */
			const int64_t r = ((int64_t)me->eval.basin_ratio_ppm + 50) / 100;

			m.basin_ratio = (r > (int64_t)MSG_BASIN_RATIO_MAX) ?
				(uint16_t)MSG_BASIN_RATIO_MAX : (uint16_t)r;
		}
		if ((me->eval.has & MODEL_EVAL_HAS_HOPF_V0) != 0U) {
			int64_t cm = (int64_t)me->eval.hopf_margin_umps;

			cm = (cm >= 0) ? ((cm + 5000) / 10000) : -((-cm + 5000) / 10000);
			if (cm > MSG_HOPF_MARGIN_MPS_MAX) {
				cm = MSG_HOPF_MARGIN_MPS_MAX;
			}
			if (cm < MSG_HOPF_MARGIN_MPS_MIN) {
				cm = MSG_HOPF_MARGIN_MPS_MIN;
			}
			m.hopf_margin_mps = (int16_t)cm;
		} else if ((me->eval.has & MODEL_EVAL_HAS_LNQ) != 0U) {
			/* no Hopf border: stable at every speed */
			m.hopf_margin_mps = NO_BORDER_MARGIN_RAW;
		} else {
			/* friction not falling with speed: no border at all */
			m.hopf_margin_mps = NO_BORDER_MARGIN_RAW;
		}
	}
	m.border_margin_sigma = MSG_BORDER_MARGIN_SIGMA_NA;
	if (classified(me) && (me->margin_q16 < MODEL_MARGIN_NONE)) {
		/* tenths of a sigma, rounded; raw = tenths + 1 (0: n/a) */
		const int64_t tenths = (((int64_t)me->margin_q16 * 10) + 32768) >> 16;

		m.border_margin_sigma = (tenths >= (int64_t)MSG_BORDER_MARGIN_SIGMA_SAT - 1) ?
			(uint8_t)MSG_BORDER_MARGIN_SIGMA_SAT : (uint8_t)(tenths + 1);
	}
	rc = msg_squeal_status_pack(&m, data, &dlc);
	tx_protected(me, me->corner.status_id, MSG_SQUEAL_STATUS_DATA_ID,
		     &me->tx_status, data, dlc, rc);
}

static void send_detail(monitor_t *me)
{
	msg_squeal_detail_t d = { 0 };
	msg_squeal_detail2_t d2 = { 0 };
	uint8_t data[8];
	uint8_t dlc = 0U;
	int rc;
	const bool speed_ok = (me->speed.faults == 0U);
	const bool force_ok = (me->force.faults == 0U);
	const bool cls = classified(me);

	d.v0_mps = speed_ok ? umps_to_cmps(me->speed.value, MSG_V0_MPS_MAX) : MSG_V0_MPS_NA;
	d.hopf_speed_mps = MSG_HOPF_SPEED_MPS_NA;
	d.trigger_velocity_mps = MSG_TRIGGER_VELOCITY_MPS_NA;
	d.vehicle_speed_border_kph = MSG_VEHICLE_SPEED_BORDER_KPH_NA;
	if (cls && ((me->eval.has & MODEL_EVAL_HAS_HOPF_V0) != 0U)) {
		/* v_car = v0 r_w / r_p; 0.1 km/h = v[um/s] * 36 / 1e6 */
		const uint64_t kph10 = ((uint64_t)(uint32_t)me->eval.hopf_v0_umps *
					me->corner.wheel_radius_um * 36U /
					me->corner.pad_radius_um + 500000U) / 1000000U;

		d.hopf_speed_mps = umps_to_cmps(me->eval.hopf_v0_umps, MSG_HOPF_SPEED_MPS_MAX);
		d.vehicle_speed_border_kph = (kph10 > MSG_VEHICLE_SPEED_BORDER_KPH_MAX) ?
			(uint16_t)MSG_VEHICLE_SPEED_BORDER_KPH_MAX : (uint16_t)kph10;
	}
	if (cls && ((me->eval.has & MODEL_EVAL_HAS_CYCLE) != 0U)) {
		d.trigger_velocity_mps = umps_to_cmps(me->eval.trigger_velocity_umps,
						      MSG_TRIGGER_VELOCITY_MPS_MAX);
	}
	rc = msg_squeal_detail_pack(&d, data, &dlc);
	tx_protected(me, me->corner.detail_id, MSG_SQUEAL_DETAIL_DATA_ID,
		     &me->tx_detail, data, dlc, rc);

	d2.force_n = MSG_FORCE_N_NA;
	if (force_ok) {
		const uint32_t n = ((uint32_t)me->force.value + 250U) / 500U;

		d2.force_n = (n > MSG_FORCE_N_MAX) ? (uint16_t)MSG_FORCE_N_MAX : (uint16_t)n;
	}
	d2.hopf_force_n = MSG_HOPF_FORCE_N_NA;
	d2.lc_amplitude_um = MSG_LC_AMPLITUDE_UM_NA;
	if (cls && ((me->eval.has & MODEL_EVAL_HAS_HOPF_FORCE) != 0U)) {
		const uint32_t n = ((uint32_t)me->eval.hopf_force_mn + 500U) / 1000U;

		d2.hopf_force_n = (n > MSG_HOPF_FORCE_N_MAX) ? (uint16_t)MSG_HOPF_FORCE_N_MAX :
			(uint16_t)n;
	}
	if (cls && ((me->eval.has & MODEL_EVAL_HAS_CYCLE) != 0U)) {
		const uint32_t a = ((uint32_t)me->eval.lc_amplitude_nm + 50U) / 100U;

		d2.lc_amplitude_um = (a > MSG_LC_AMPLITUDE_UM_MAX) ?
			(uint16_t)MSG_LC_AMPLITUDE_UM_MAX : (uint16_t)a;
	}
	rc = msg_squeal_detail2_pack(&d2, data, &dlc);
	tx_protected(me, me->corner.detail2_id, MSG_SQUEAL_DETAIL2_DATA_ID,
		     &me->tx_detail2, data, dlc, rc);
}

uint16_t monitor_fault_bits(const monitor_t *me)
{
	uint32_t b = 0U;

	HAL_REQUIRE(me != NULL);
	if ((me->speed.faults & (INPUT_FAULT_STALE | INPUT_FAULT_NEVER_SEEN)) != 0U) {
		b |= MSG_FAULT_SPEED_STALE;
	}
	if ((me->force.faults & (INPUT_FAULT_STALE | INPUT_FAULT_NEVER_SEEN)) != 0U) {
		b |= MSG_FAULT_FORCE_STALE;
	}
	if ((me->speed.faults & INPUT_FAULT_E2E) != 0U) {
		b |= MSG_FAULT_E2E_SPEED;
	}
	if ((me->force.faults & INPUT_FAULT_E2E) != 0U) {
		b |= MSG_FAULT_E2E_FORCE;
	}
	if ((me->speed.faults & INPUT_FAULT_IMPLAUSIBLE) != 0U) {
		b |= MSG_FAULT_SPEED_IMPLAUSIBLE;
	}
	if ((me->force.faults & INPUT_FAULT_IMPLAUSIBLE) != 0U) {
		b |= MSG_FAULT_FORCE_IMPLAUSIBLE;
	}
	if (me->calib_invalid) {
		b |= MSG_FAULT_CALIB_INVALID;
	}
	if (me->bus_off_seen) {
		b |= MSG_FAULT_BUS_OFF_SEEN;
	}
	if ((me->platform_faults & HAL_FAULT_CLOCK_FALLBACK) != 0U) {
		b |= MSG_FAULT_CLOCK_FALLBACK;
	}
	if ((me->platform_faults & HAL_FAULT_CAN_INIT) != 0U) {
		b |= MSG_FAULT_CAN_INIT;
	}
	if (me->count.tx_overflow != 0U) {
		b |= MSG_FAULT_TX_OVERFLOW;
	}
	if (me->selftest.failed) {
		b |= MSG_FAULT_SELF_TEST;
	}
	return (uint16_t)b;
}

static uint16_t e2e_errors(const input_t *in)
{
	uint32_t n = in->count.e2e_wrong_crc;

	n = (n > UINT32_MAX - in->count.e2e_wrong_sequence) ? UINT32_MAX :
		n + in->count.e2e_wrong_sequence;
	return sat_u16(n);
}

static void send_diag(monitor_t *me)
{
	msg_squeal_diag_t m = { 0 };
	uint8_t data[8];
	uint8_t dlc = 0U;
	const uint64_t up_s = (me->now_us - me->start_us) / 1000000U;
	int rc;

	m.page = me->diag_page;
	m.fault_bits = monitor_fault_bits(me);
	switch (me->diag_page) {
	case MSG_DIAG_PAGE_UPTIME:
		m.uptime_s = (up_s > MSG_UPTIME_S_MAX) ? MSG_UPTIME_S_MAX : (uint32_t)up_s;
		m.bus_off_count = (me->count.bus_off_events > MSG_BUS_OFF_COUNT_MAX) ?
			(uint8_t)MSG_BUS_OFF_COUNT_MAX : (uint8_t)me->count.bus_off_events;
		break;
	case MSG_DIAG_PAGE_TASK:
		m.worst_task_time_us = sat_u16(me->worst_task_us);
		m.rx_overrun_count = sat_u16(me->count.rx_overruns);
		break;
	case MSG_DIAG_PAGE_E2E:
		m.e2e_error_count_speed = e2e_errors(&me->speed);
		m.e2e_error_count_force = e2e_errors(&me->force);
		break;
	case MSG_DIAG_PAGE_FRAMES:
		m.tx_overflow_count = sat_u16(me->count.tx_overflow);
		m.rx_bad_frame_count = sat_u16(me->speed.count.bad_dlc +
					       me->force.count.bad_dlc +
					       me->count.rtr_or_ext);
		break;
	default:
		m.hse_freq_100khz = me->selftest.hse_freq_100khz;
		m.reset_cause = me->selftest.reset_cause;
		m.bor_level = me->selftest.bor_level;
		m.loopback_can1 = me->selftest.loopback[0];
		m.loopback_can2 = me->selftest.loopback[1];
		m.stack_high_water_b = me->selftest.stack_high_water_b;
		break;
	}
	me->diag_page = (uint8_t)((me->diag_page + 1U) % MSG_DIAG_PAGE_COUNT);
	rc = msg_squeal_diag_pack(&m, data, &dlc);
	tx_protected(me, me->corner.diag_id, MSG_SQUEAL_DIAG_DATA_ID,
		     &me->tx_diag, data, dlc, rc);
}

/* Periodic deadline: keep the phase, but never try to catch up a backlog. */
static bool due(uint64_t *next_us, uint64_t now_us, uint16_t period_ms)
{
	const uint64_t period_us = (uint64_t)period_ms * US_PER_MS;

	if (now_us < *next_us) {
		return false;
	}
	*next_us += period_us;
	if (*next_us <= now_us) {
		*next_us = now_us + period_us;
	}
	return true;
}

/* The periodic messages due now (and SquealStatus at once on a change). */
static void encode(monitor_t *me)
{
	if (due(&me->next_status_us, me->now_us, me->cal->status_period_ms) || me->status_now) {
		me->status_now = false;
		send_status(me);
	}
	if (due(&me->next_detail_us, me->now_us, me->cal->detail_period_ms)) {
		send_detail(me);
	}
	if (due(&me->next_diag_us, me->now_us, me->cal->diag_period_ms)) {
		send_diag(me);
	}
}

/* ---- the step ------------------------------------------------------------ */

bool monitor_wants_classify(const monitor_t *me)
{
	return (me != NULL) && me->speed.fresh && me->force.fresh &&
	       (me->speed.faults == 0U) && (me->force.faults == 0U);
}

/*
 * condition -> classify -> debounce -> encode, each stage once, in order:
 * the inputs' staleness; a faulty input is FAULT at once, a new pair is
 * classified (when this corner has the step's slot) with its uncertainty;
 * the class debounced and its warning level; the messages due.
 */
void monitor_step_slot(monitor_t *me, uint64_t now_us, bool may_classify)
{
	HAL_REQUIRE(me != NULL);
	if (!me->started) {
		return;
	}
	if (now_us > me->now_us) {
		me->now_us = now_us; /* monotonic even if the caller's clock is not */
	}
	input_tick(me, &me->speed, &me->speed_rx);
	input_tick(me, &me->force, &me->force_rx);

	if ((me->speed.faults != 0U) || (me->force.faults != 0U)) {
		/* no class (classify), FAULT at once (debounce), so no margin */
		me->have_eval = false;
		set_state(me, MONITOR_STATE_FAULT);
		update_uncertainty(me, NULL, false);
	} else if (may_classify && me->speed.fresh && me->force.fresh) {
		squeal_sigma_result_t sig;
		const uint8_t cls = classify_pair(me, &sig);

		debounce(me, cls);
		if (me->sigma_on) {
			/* without deviations nothing is uncertain and there is
			 * no margin (as set at start, and on every fault); sig
			 * holds borders when it is a class's (sliding, valid) */
			update_uncertainty(me, &sig, sig.state <= SQUEAL_STATE_UNSTABLE);
		}
	} else {
		/* no fault and no new input pair: nothing to classify */
	}
	update_warning(me);
	encode(me);
}

void monitor_step(monitor_t *me, uint64_t now_us)
{
	monitor_step_slot(me, now_us, true);
}

int monitor_peek_tx(const monitor_t *me, hal_can_frame_t *frame)
{
	HAL_REQUIRE((me != NULL) && (frame != NULL));
	if (me->txq_count == 0U) {
		return SQ_EAGAIN;
	}
	*frame = me->txq[me->txq_head];
	return SQ_OK;
}

void monitor_tx_done(monitor_t *me, int hal_rc)
{
	HAL_REQUIRE(me != NULL);
	if (me->txq_count == 0U) {
		return;
	}
	if (hal_rc == SQ_OK) {
		sat_inc(&me->count.tx_frames);
	} else {
		sat_inc(&me->count.tx_errors);
	}
	me->txq_head = (uint8_t)((me->txq_head + 1U) % MONITOR_TX_QUEUE_LEN);
	me->txq_count--;
}
