/* SPDX-License-Identifier: MIT */
#include "monitor.h"

#include <stddef.h>

#include "hal.h"
#include "sq_status.h"

#define US_PER_MS 1000U
#define PPM_ONE 1000000
#define NO_BORDER_MARGIN_RAW MSG_HOPF_MARGIN_MPS_MAX

static const e2e_p01_config_t *speed_cfg(const monitor_t *me, e2e_p01_config_t *cfg)
{
	cfg->data_id = MSG_DISC_SPEED_DATA_ID;
	cfg->data_len = MSG_DISC_SPEED_DLC;
	cfg->max_delta_counter = me->cal.e2e_max_delta_counter;
	return cfg;
}

static const e2e_p01_config_t *force_cfg(const monitor_t *me, e2e_p01_config_t *cfg)
{
	cfg->data_id = MSG_PAD_FORCE_DATA_ID;
	cfg->data_len = MSG_PAD_FORCE_DLC;
	cfg->max_delta_counter = me->cal.e2e_max_delta_counter;
	return cfg;
}

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
	e2e_p01_rx_init(&in->e2e);
	in->faults = INPUT_FAULT_NEVER_SEEN;
	in->has_prev_raw = false;
	in->prev_raw = 0U;
	in->value = 0;
	in->filtered_q8 = 0;
	in->last_used_us = now_us;
	in->last_seen_us = now_us;
	in->fresh = false;
	in->count = (input_counters_t){ 0 };
}

int monitor_init(monitor_t *me, const calib_t *cal, bool calib_invalid,
		 uint32_t platform_faults, uint64_t now_us)
{
	int rc = SQ_OK;

	HAL_REQUIRE(me != NULL);
	*me = (monitor_t){ 0 };
	if ((cal != NULL) && (calib_validate(cal) == SQ_OK)) {
		me->cal = *cal;
		me->calib_invalid = calib_invalid;
	} else {
		calib_default(&me->cal);
		me->calib_invalid = true;
		rc = SQ_EINVAL;
	}
	calib_model_params(&me->cal, &me->params);
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
	me->next_status_us = now_us;
	me->next_detail_us = now_us;
	me->next_diag_us = now_us;
	me->selftest = (monitor_selftest_t){ (uint8_t)MSG_HSE_FREQ_NA, (uint8_t)MSG_RESET_CAUSE_MAX,
					     (uint8_t)MSG_BOR_LEVEL_NA, { 2U, 2U },
					     (uint16_t)MSG_STACK_HWM_UNKNOWN, false };
	me->started = true;
	return rc;
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

/* ---- inputs --------------------------------------------------------------- */

/* Accept one plausible raw value: convert, filter, mark fresh. */
static void input_accept(monitor_t *me, input_t *in, int32_t value,
			 uint64_t t_us)
{
	const int64_t x_q8 = (int64_t)value * 256;

	if ((in->faults & INPUT_FAULT_NEVER_SEEN) != 0U) {
		in->filtered_q8 = x_q8; /* start the filter at the value */
	} else {
		/* first-order low pass, alpha in Q15 (32768 = no filtering) */
		in->filtered_q8 += (((x_q8 - in->filtered_q8) *
				    (int64_t)me->cal.lowpass_alpha_q15) / 32768);
	}
	in->value = (int32_t)(in->filtered_q8 / 256);
	in->faults &= ~(INPUT_FAULT_IMPLAUSIBLE | INPUT_FAULT_STALE |
			INPUT_FAULT_NEVER_SEEN | INPUT_FAULT_E2E);
	in->last_used_us = t_us;
	in->fresh = true;
	sat_inc(&in->count.used);
}

/*
 * Plausibility of one E2E-good raw value: "not available", beyond the
 * calibrated maximum, or a jump from the previous value larger than the
 * calibrated step (rate limit) makes the input implausible until a
 * plausible value arrives. The rate check compares with the previous
 * received value, so a real step costs one frame and a spike two.
 */
static bool input_plausible(input_t *in, uint16_t raw, uint16_t na_raw,
			    uint16_t max_raw, uint16_t step_max_raw)
{
	bool ok = (raw != na_raw) && (raw <= max_raw);

	if (ok && in->has_prev_raw) {
		const uint16_t d = (raw > in->prev_raw) ? (uint16_t)(raw - in->prev_raw) :
			(uint16_t)(in->prev_raw - raw);

		ok = d <= step_max_raw;
	}
	if (raw != na_raw) {
		in->prev_raw = raw;
		in->has_prev_raw = true;
	}
	if (!ok) {
		in->faults |= INPUT_FAULT_IMPLAUSIBLE;
		sat_inc(&in->count.implausible);
	}
	return ok;
}

static uint64_t frame_time(const monitor_t *me, const hal_can_frame_t *f)
{
	/* HAL timestamps share hal_time_us()'s clock; a frame stamped in
	 * the future (clock glitch) is taken as received now */
	return ((f->timestamp_us != 0U) && (f->timestamp_us <= me->now_us)) ?
		f->timestamp_us : me->now_us;
}

/*
 * The E2E part shared by both inputs. Returns true when the frame may be
 * used; a frame that failed marks the input (fault) and is counted.
 * With E2E checking switched off by calibration only the length is checked.
 */
static bool input_e2e(monitor_t *me, input_t *in, const e2e_p01_config_t *cfg,
		      const hal_can_frame_t *f)
{
	e2e_p01_status_t st;

	if (f->dlc != cfg->data_len) {
		sat_inc(&in->count.bad_dlc);
		in->faults |= INPUT_FAULT_E2E;
		if (me->cal.e2e_check_inputs != 0U) {
			/* still one receive cycle for the E2E state machine */
			(void)e2e_p01_check(cfg, &in->e2e, f->data, f->dlc);
		}
		return false;
	}
	if (me->cal.e2e_check_inputs == 0U) {
		return true;
	}
	st = e2e_p01_check(cfg, &in->e2e, f->data, f->dlc);
	switch (st) {
	case E2E_P01_STATUS_OK:
	case E2E_P01_STATUS_INITIAL:
		in->last_seen_us = frame_time(me, f);
		return true;
	case E2E_P01_STATUS_OKSOMELOST:
		sat_add(&in->count.e2e_lost, in->e2e.lost_data);
		in->last_seen_us = frame_time(me, f);
		return true;
	case E2E_P01_STATUS_REPEATED:
		/* no new data, not an error: a frozen sender goes stale */
		sat_inc(&in->count.e2e_repeated);
		in->last_seen_us = frame_time(me, f);
		return false;
	case E2E_P01_STATUS_WRONGSEQUENCE:
		sat_inc(&in->count.e2e_wrong_sequence);
		in->faults |= INPUT_FAULT_E2E;
		return false;
	default: /* WRONGCRC */
		sat_inc(&in->count.e2e_wrong_crc);
		in->faults |= INPUT_FAULT_E2E;
		return false;
	}
}

/* A copy of the payload with the E2E counter nibble cleared, for unpacking
 * plain frames when E2E checking is off (their byte 1 may hold anything). */
static void plain_copy(const hal_can_frame_t *f, uint8_t data[8])
{
	uint32_t i;

	for (i = 0U; i < 8U; i++) {
		data[i] = f->data[i];
	}
	data[1] &= 0xF0U;
}


static void speed_frame(monitor_t *me, const hal_can_frame_t *f)
{
	input_t *in = &me->speed;
	e2e_p01_config_t cfg;
	msg_disc_speed_t m;
	uint8_t data[8];

	sat_inc(&in->count.frames);
	if (!input_e2e(me, in, speed_cfg(me, &cfg), f)) {
		return;
	}
	plain_copy(f, data);
	if (msg_disc_speed_unpack(data, f->dlc, &m) != SQ_OK) {
		sat_inc(&in->count.bad_dlc);
		in->faults |= INPUT_FAULT_E2E;
		return;
	}
	if (input_plausible(in, m.disc_speed_radps, MSG_DISC_SPEED_RADPS_NA,
			    me->cal.speed_max_raw, me->cal.speed_step_max_raw)) {
		/* v0 = Omega r_p: 0.01 rad/s x um -> um/s (< 6.6e8, fits) */
		const uint64_t v0 = ((uint64_t)m.disc_speed_radps *
				     me->cal.pad_radius_um + 50U) / 100U;

		input_accept(me, in, (int32_t)v0, frame_time(me, f));
	}
}

static void force_frame(monitor_t *me, const hal_can_frame_t *f)
{
	input_t *in = &me->force;
	e2e_p01_config_t cfg;
	msg_pad_force_t m;
	uint8_t data[8];

	sat_inc(&in->count.frames);
	if (!input_e2e(me, in, force_cfg(me, &cfg), f)) {
		return;
	}
	plain_copy(f, data);
	if (msg_pad_force_unpack(data, f->dlc, &m) != SQ_OK) {
		sat_inc(&in->count.bad_dlc);
		in->faults |= INPUT_FAULT_E2E;
		return;
	}
	if (input_plausible(in, m.pad_force_n, MSG_PAD_FORCE_N_NA,
			    me->cal.force_max_raw, me->cal.force_step_max_raw)) {
		/* 0.5 N per bit -> mN */
		input_accept(me, in, (int32_t)m.pad_force_n * 500, frame_time(me, f));
	}
}

void monitor_on_frame(monitor_t *me, const hal_can_frame_t *frame)
{
	HAL_REQUIRE((me != NULL) && (frame != NULL));
	if (!me->started) {
		return;
	}
	if ((frame->flags & HAL_CAN_FLAG_ERR) != 0U) {
		sat_inc(&me->count.error_frames);
		return;
	}
	if ((frame->id == me->cal.disc_speed_id) || (frame->id == me->cal.pad_force_id)) {
		if ((frame->flags & (HAL_CAN_FLAG_RTR | HAL_CAN_FLAG_EXT)) != 0U) {
			sat_inc(&me->count.rtr_or_ext);
			return;
		}
		if (frame->id == me->cal.disc_speed_id) {
			speed_frame(me, frame);
		} else {
			force_frame(me, frame);
		}
		return;
	}
	sat_inc(&me->count.unknown_id);
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
static void input_tick(monitor_t *me, input_t *in)
{
	const uint64_t period_us = (uint64_t)me->cal.input_period_ms * US_PER_MS;
	const uint64_t timeout_us = period_us * me->cal.stale_cycles;
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
			e2e_p01_rx_reset(&in->e2e);
		}
		in->has_prev_raw = false;
		in->fresh = false;
	}
}

/* ---- classification, debounce, warnings ---------------------------------- */

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
		       (abs32(me->eval.ln_2q_micro) > me->cal.hyst_lnq_micro);
	}
	/* stable <-> bistable: rho crosses 1 */
	return ((me->eval.has & MODEL_EVAL_HAS_BASIN) == 0U) ||
	       (abs32(me->eval.basin_ratio_ppm - PPM_ONE) > me->cal.hyst_rho_ppm);
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
	if (me->candidate_count >= me->cal.debounce_count) {
		set_state(me, cls);
	}
}

static uint8_t classify_pair(monitor_t *me)
{
	const int32_t v0 = me->speed.value;
	const int32_t force = me->force.value;

	sat_inc(&me->count.classifications);
	if (((uint32_t)v0 < me->cal.v0_min_umps) || ((uint32_t)force < me->cal.force_min_mn)) {
		me->eval = (model_eval_t){ .state = SQUEAL_STATE_NOT_SLIDING };
		me->have_eval = true;
		return SQUEAL_STATE_NOT_SLIDING;
	}
	if (model_adapter_eval(&me->params, (squeal_criterion_t)me->cal.criterion,
			       v0, force, &me->eval) != SQ_OK) {
		sat_inc(&me->count.model_invalid);
		me->have_eval = false;
		return MONITOR_STATE_FAULT;
	}
	me->have_eval = true;
	return (uint8_t)me->eval.state;
}

static uint8_t warning_level(const monitor_t *me)
{
	switch (me->state) {
	case SQUEAL_STATE_UNSTABLE:
		return MSG_WARNING_LEVEL_CRITICAL;
	case SQUEAL_STATE_BISTABLE:
		/* small basin (rho below the threshold): a small disturbance
		 * starts stick-slip */
		if (((me->eval.has & MODEL_EVAL_HAS_BASIN) == 0U) ||
		    ((uint32_t)me->eval.basin_ratio_ppm < me->cal.rho_warn_ppm)) {
			return MSG_WARNING_LEVEL_WARNING;
		}
		return MSG_WARNING_LEVEL_ADVISORY;
	default:
		return MSG_WARNING_LEVEL_NONE;
	}
}

/* ---- transmit ------------------------------------------------------------- */

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
	rc = msg_squeal_status_pack(&m, data, &dlc);
	tx_protected(me, me->cal.status_id, MSG_SQUEAL_STATUS_DATA_ID,
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
					me->cal.wheel_radius_um * 36U /
					me->cal.pad_radius_um + 500000U) / 1000000U;

		d.hopf_speed_mps = umps_to_cmps(me->eval.hopf_v0_umps, MSG_HOPF_SPEED_MPS_MAX);
		d.vehicle_speed_border_kph = (kph10 > MSG_VEHICLE_SPEED_BORDER_KPH_MAX) ?
			(uint16_t)MSG_VEHICLE_SPEED_BORDER_KPH_MAX : (uint16_t)kph10;
	}
	if (cls && ((me->eval.has & MODEL_EVAL_HAS_CYCLE) != 0U)) {
		d.trigger_velocity_mps = umps_to_cmps(me->eval.trigger_velocity_umps,
						      MSG_TRIGGER_VELOCITY_MPS_MAX);
	}
	rc = msg_squeal_detail_pack(&d, data, &dlc);
	tx_protected(me, me->cal.detail_id, MSG_SQUEAL_DETAIL_DATA_ID,
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
	tx_protected(me, me->cal.detail2_id, MSG_SQUEAL_DETAIL2_DATA_ID,
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
	tx_protected(me, me->cal.diag_id, MSG_SQUEAL_DIAG_DATA_ID,
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

void monitor_step(monitor_t *me, uint64_t now_us)
{
	uint8_t warning;

	HAL_REQUIRE(me != NULL);
	if (!me->started) {
		return;
	}
	if (now_us > me->now_us) {
		me->now_us = now_us; /* monotonic even if the caller's clock is not */
	}
	input_tick(me, &me->speed);
	input_tick(me, &me->force);

	if ((me->speed.faults != 0U) || (me->force.faults != 0U)) {
		set_state(me, MONITOR_STATE_FAULT);
		me->have_eval = false;
	} else if (me->speed.fresh && me->force.fresh) {
		me->speed.fresh = false;
		me->force.fresh = false;
		debounce(me, classify_pair(me));
	} else {
		/* no fault and no new input pair: nothing to classify */
	}
	warning = warning_level(me);
	if (warning != me->warning) {
		me->warning = warning;
		me->status_now = true;
	}

	if (due(&me->next_status_us, me->now_us, me->cal.status_period_ms) || me->status_now) {
		me->status_now = false;
		send_status(me);
	}
	if (due(&me->next_detail_us, me->now_us, me->cal.detail_period_ms)) {
		send_detail(me);
	}
	if (due(&me->next_diag_us, me->now_us, me->cal.diag_period_ms)) {
		send_diag(me);
	}
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
