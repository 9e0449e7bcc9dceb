/* SPDX-License-Identifier: MIT */
/*
 * fuzz_monitor: the monitor application (firmware/monitor/monitor.c) fed a
 * stream of arbitrary frames, well-formed protected inputs, time steps
 * (including backward clock jumps), CAN status reports and TX completions.
 *
 * Input: byte 0 picks one of four calibrations (defaults, E2E off, cubic
 * criterion with filtering and no debounce, moved identifiers), with bit 2
 * a vehicle input map, bit 3 standard deviations (moderate, or with bit 4
 * each as large as its parameter, correlation -1), then
 * operations [op, arguments...] until the input ends (at most 512).
 *
 * Properties after every operation:
 *   - nothing crashes, no sanitizer report, bounded time per operation;
 *   - the calibration in the monitor (me->cal, me->params, calib_invalid)
 *     is bit-for-bit what monitor_init() got: NO frame, whatever its
 *     identifier, flags, DLC, payload or E2E, changes it (the calibration
 *     write-protection property, see docs/reliability.md);
 *   - the state is one of 0..3 or 15 and the warning level matches it
 *     (or the uncertain rule's raised level: stable -> advisory, bistable
 *     -> critical, only with deviations; then BorderMargin_sigma is there
 *     exactly for a class, and the rule raises only within k sigma);
 *     after a step, a faulted input forces FAULT;
 *   - the TX queue indices stay in range; every queued frame is one of our
 *     four output identifiers, DLC 8, standard data frame, with a correct
 *     E2E CRC (independent reference) and a counter 0..14, and unpacks;
 *   - fault bits are inside MSG_FAULT_ALL; event counters never decrease.
 */
#include "fuzz_common.h"

#include <stdbool.h>

#include "calib.h"
#include "calib_map.h"
#include "input_conv.h"
#include "e2e_p01.h"
#include "monitor.h"
#include "sq_status.h"
#include "squeal_msgs.h"

#define MAX_OPS 512U

typedef struct {
	monitor_t me;
	calib_t cal0;
	squeal_params_t params0;
	bool calib_invalid0;
	uint64_t now_us;
	uint8_t counter[2]; /* our well-behaved sender's E2E counters */
} ctx_t;

static ctx_t ctx;

/* A vehicle layout on the legacy identifiers (so that pick_id() finds them):
 * a Motorola 15-bit km/h speed with a fault bit and a 4-bit counter, and a
 * multiplexed 12-bit bar pressure with E2E P02. */
static void vehicle_map(calib_t *cal)
{
	calib_input_t *sp = &cal->inputs[0];
	calib_input_t *pr = &cal->inputs[1];
	uint8_t i;

	cal->n_inputs = 2U;
	cal->n_corners = 1U;
	sp->id = cal->disc_speed_id;
	sp->min_dlc = 8U;
	sp->flags = (uint8_t)(CALIB_IN_NA | CALIB_IN_QUALIFIER);
	sp->sig = (can_signal_t){ 23U, 15U, (uint8_t)CAN_SIGNAL_MOTOROLA, 0U };
	sp->factor = (calib_dec_t){ 1, -2 };
	sp->offset = (calib_dec_t){ -6767, -2 };
	sp->unit = (uint8_t)INPUT_UNIT_KMH;
	sp->na_raw = 0x7FFFU;
	sp->qualifier_bit = 24U;
	sp->qualifier_invalid = 1U;
	sp->protection = (uint8_t)CALIB_PROT_COUNTER;
	sp->counter = (can_signal_t){ 60U, 4U, (uint8_t)CAN_SIGNAL_INTEL, 0U };
	sp->counter_modulus = 15U;
	sp->max_delta_counter = 2U;
	sp->period_ms = 10U;
	sp->stale_cycles = 3U;
	sp->max = (calib_dec_t){ 300, 0 };
	sp->min = (calib_dec_t){ -1, 0 };
	sp->step_max = (calib_dec_t){ 20, 0 };
	pr->id = cal->pad_force_id;
	pr->min_dlc = 8U;
	pr->flags = (uint8_t)(CALIB_IN_NA | CALIB_IN_MUX);
	pr->sig = (can_signal_t){ 16U, 12U, (uint8_t)CAN_SIGNAL_INTEL, 0U };
	pr->factor = (calib_dec_t){ 1, -1 };
	pr->unit = (uint8_t)INPUT_UNIT_BAR;
	pr->mux = (can_signal_t){ 12U, 2U, (uint8_t)CAN_SIGNAL_INTEL, 0U };
	pr->mux_value = 1U;
	pr->mux_value_max = 1U; /* the selector range is the one page */
	pr->na_raw = 0xFFFU;
	pr->protection = (uint8_t)CALIB_PROT_P02;
	for (i = 0U; i < CALIB_DATA_ID_LIST_LEN; i++) {
		pr->data_id_list[i] = (uint8_t)(0x11U * i + 1U);
	}
	pr->max_delta_counter = 2U;
	pr->period_ms = 20U;
	pr->stale_cycles = 3U;
	pr->max = (calib_dec_t){ 250, 0 };
	pr->step_max = (calib_dec_t){ 100, 0 };
	calib_corner_defaults(cal, 0U, &cal->corners[0]);
	cal->corners[0].speed_input = 0U;
	cal->corners[0].force_input = 1U;
	cal->corners[0].piston_area_cmm2 = 229000U;
}

static void pick_calibration(uint8_t which, calib_t *cal)
{
	calib_default(cal);
	switch (which & 3U) {
	case 1U:
		cal->e2e_check_inputs = 0U;
		break;
	case 2U:
		cal->criterion = (uint8_t)SQUEAL_CRITERION_CUBIC;
		cal->lowpass_alpha_q15 = 8192U;
		cal->debounce_count = 1U;
		cal->e2e_max_delta_counter = 14U;
		cal->hyst_lnq_micro = 0U;
		cal->hyst_rho_ppm = 0U;
		break;
	case 3U:
		cal->disc_speed_id = 0x7FFU;
		cal->pad_force_id = 0x000U;
		cal->status_id = 0x110U;
		cal->detail_id = 0x111U;
		cal->diag_id = 0x555U;
		cal->detail2_id = 0x2AAU;
		cal->stale_cycles = 1U;
		cal->speed_step_max_raw = 65535U;
		cal->force_step_max_raw = 65535U;
		break;
	default:
		break;
	}
	if ((which & 8U) != 0U) {
		if ((which & 16U) != 0U) {
			/* as large as allowed: sd = |param|, corr -1 */
			cal->sd.mass_sd_q16 = cal->mass_q16;
			cal->sd.omega0_sd_q12 = cal->omega0_q12;
			cal->sd.damping_sd_q30 = cal->damping_q30;
			cal->sd.mu_inf_sd_q30 = cal->mu_inf_q30;
			cal->sd.delta_mu_sd_q30 = cal->delta_mu_q30;
			cal->sd.slope_sd_q24 = cal->slope_q24;
			cal->sd.slope_delta_mu_corr_q30 = -(1 << 30);
		} else {
			cal->sd.mass_sd_q16 = 1311;        /* 2 %  */
			cal->sd.damping_sd_q30 = 2469606;  /* 10 % */
			cal->sd.delta_mu_sd_q30 = 6442451; /* 4 %  */
			cal->sd.slope_sd_q24 = 1677722;    /* 5 %  */
			cal->sd.slope_delta_mu_corr_q30 = 912680550;
		}
	}
	/* after the flat keys: the map takes their identifiers */
	if ((which & 4U) != 0U) {
		vehicle_map(cal);
	}
}

static uint16_t data_id_of(const calib_t *cal, uint32_t id)
{
	if (id == cal->status_id) {
		return MSG_SQUEAL_STATUS_DATA_ID;
	}
	if (id == cal->detail_id) {
		return MSG_SQUEAL_DETAIL_DATA_ID;
	}
	if (id == cal->detail2_id) {
		return MSG_SQUEAL_DETAIL2_DATA_ID;
	}
	if (id == cal->diag_id) {
		return MSG_SQUEAL_DIAG_DATA_ID;
	}
	return 0U;
}

static void check_tx_frame(const ctx_t *c, const hal_can_frame_t *f)
{
	const uint16_t data_id = data_id_of(&c->cal0, f->id);
	msg_squeal_status_t st;
	msg_squeal_detail_t dt;
	msg_squeal_detail2_t d2;
	msg_squeal_diag_t dg;
	int rc;

	FUZZ_REQUIRE(data_id != 0U);
	FUZZ_REQUIRE(f->dlc == 8U);
	FUZZ_REQUIRE(f->flags == 0U);
	FUZZ_REQUIRE(f->data[0] == fuzz_ref_e2e_crc(data_id, f->data, f->dlc));
	FUZZ_REQUIRE((f->data[1] & 0x0FU) <= E2E_P01_COUNTER_MAX);
	switch (data_id) {
	case MSG_SQUEAL_STATUS_DATA_ID:
		rc = msg_squeal_status_unpack(f->data, f->dlc, &st);
		FUZZ_REQUIRE((rc != SQ_OK) || (st.warning_level <= 3U));
		break;
	case MSG_SQUEAL_DETAIL_DATA_ID:
		rc = msg_squeal_detail_unpack(f->data, f->dlc, &dt);
		break;
	case MSG_SQUEAL_DETAIL2_DATA_ID:
		rc = msg_squeal_detail2_unpack(f->data, f->dlc, &d2);
		break;
	default:
		rc = msg_squeal_diag_unpack(f->data, f->dlc, &dg);
		FUZZ_REQUIRE((rc != SQ_OK) || ((dg.fault_bits & ~MSG_FAULT_ALL) == 0U));
		break;
	}
	FUZZ_REQUIRE(rc == SQ_OK);
}

static void check_counts_monotone(const input_counters_t *a, const input_counters_t *b)
{
	FUZZ_REQUIRE(b->frames >= a->frames);
	FUZZ_REQUIRE(b->used >= a->used);
	FUZZ_REQUIRE(b->bad_dlc >= a->bad_dlc);
	FUZZ_REQUIRE(b->e2e_wrong_crc >= a->e2e_wrong_crc);
	FUZZ_REQUIRE(b->e2e_wrong_sequence >= a->e2e_wrong_sequence);
	FUZZ_REQUIRE(b->e2e_repeated >= a->e2e_repeated);
	FUZZ_REQUIRE(b->e2e_lost >= a->e2e_lost);
	FUZZ_REQUIRE(b->implausible >= a->implausible);
	FUZZ_REQUIRE(b->stale_events >= a->stale_events);
}

static void check_monitor(const ctx_t *c, const monitor_t *before, bool stepped)
{
	const monitor_t *me = &c->me;
	hal_can_frame_t f;
	uint32_t i;

	/* write protection: the calibration never changes after init */
	FUZZ_REQUIRE(memcmp(me->cal, &c->cal0, sizeof(*me->cal)) == 0);
	FUZZ_REQUIRE(memcmp(&me->params, &c->params0, sizeof(me->params)) == 0);
	FUZZ_REQUIRE(me->calib_invalid == c->calib_invalid0);

	FUZZ_REQUIRE((me->state <= 3U) || (me->state == MONITOR_STATE_FAULT));
	switch (me->state) {
	case SQUEAL_STATE_UNSTABLE:
		FUZZ_REQUIRE(me->warning == MSG_WARNING_LEVEL_CRITICAL);
		break;
	case SQUEAL_STATE_BISTABLE:
		FUZZ_REQUIRE((me->warning == MSG_WARNING_LEVEL_ADVISORY) ||
			     (me->warning == MSG_WARNING_LEVEL_WARNING) ||
			     (me->uncertain && (me->warning == MSG_WARNING_LEVEL_CRITICAL)));
		break;
	case SQUEAL_STATE_STABLE:
		FUZZ_REQUIRE((me->warning == MSG_WARNING_LEVEL_NONE) ||
			     (me->uncertain && (me->warning == MSG_WARNING_LEVEL_ADVISORY)));
		break;
	default:
		FUZZ_REQUIRE(me->warning == MSG_WARNING_LEVEL_NONE);
		break;
	}
	/* the uncertainty: only with deviations, only for a class, the rule
	 * only within k sigma of the class's own margin (stable) */
	FUZZ_REQUIRE(me->sigma_on || (!me->uncertain && (me->margin_q16 == MODEL_MARGIN_NONE)));
	FUZZ_REQUIRE((me->state <= (uint8_t)SQUEAL_STATE_UNSTABLE) ||
		     (!me->uncertain && (me->margin_q16 == MODEL_MARGIN_NONE)));
	FUZZ_REQUIRE((me->margin_q16 >= 0) && (me->margin_q16 <= MODEL_MARGIN_NONE));
	FUZZ_REQUIRE((me->state != (uint8_t)SQUEAL_STATE_STABLE) || !me->uncertain ||
		     (me->margin_q16 < me->cal->uncertain_k_q16));
	if (stepped && ((me->speed.faults != 0U) || (me->force.faults != 0U))) {
		FUZZ_REQUIRE(me->state == MONITOR_STATE_FAULT);
	}
	FUZZ_REQUIRE(me->txq_count <= MONITOR_TX_QUEUE_LEN);
	FUZZ_REQUIRE(me->txq_head < MONITOR_TX_QUEUE_LEN);
	for (i = 0U; i < me->txq_count; i++) {
		check_tx_frame(c, &me->txq[(me->txq_head + i) % MONITOR_TX_QUEUE_LEN]);
	}
	if (monitor_peek_tx(me, &f) == SQ_OK) {
		FUZZ_REQUIRE(me->txq_count > 0U);
		check_tx_frame(c, &f);
	} else {
		FUZZ_REQUIRE(me->txq_count == 0U);
	}
	FUZZ_REQUIRE((monitor_fault_bits(me) & ~MSG_FAULT_ALL) == 0U);
	check_counts_monotone(&before->speed.count, &me->speed.count);
	check_counts_monotone(&before->force.count, &me->force.count);
	FUZZ_REQUIRE(me->count.unknown_id >= before->count.unknown_id);
	FUZZ_REQUIRE(me->count.error_frames >= before->count.error_frames);
	FUZZ_REQUIRE(me->count.rtr_or_ext >= before->count.rtr_or_ext);
	FUZZ_REQUIRE(me->count.classifications >= before->count.classifications);
	FUZZ_REQUIRE(me->count.tx_frames >= before->count.tx_frames);
	FUZZ_REQUIRE(me->count.tx_overflow >= before->count.tx_overflow);
	FUZZ_REQUIRE(me->count.tx_errors >= before->count.tx_errors);
	FUZZ_REQUIRE(me->now_us >= before->now_us);
	FUZZ_REQUIRE(me->worst_task_us >= before->worst_task_us);
}

static uint32_t pick_id(const ctx_t *c, fuzz_in_t *in, uint8_t *flags)
{
	const uint8_t sel = fuzz_u8(in);
	const uint32_t ids[8] = { c->cal0.disc_speed_id, c->cal0.pad_force_id,
				  c->cal0.status_id, c->cal0.detail_id,
				  c->cal0.diag_id, c->cal0.detail2_id, 0x000U, 0x7FFU };

	*flags = fuzz_u8(in) & 0x07U;
	if (sel < 0x80U) {
		return ids[sel & 7U];
	}
	if ((*flags & HAL_CAN_FLAG_EXT) != 0U) {
		return fuzz_u32(in) & 0x1FFFFFFFU;
	}
	return fuzz_u16(in) & 0x7FFU;
}

static uint64_t pick_stamp(const ctx_t *c, fuzz_in_t *in)
{
	const uint8_t how = fuzz_u8(in);
	const uint64_t d = fuzz_u16(in);

	switch (how & 3U) {
	case 0U:
		return 0U;                 /* no timestamp */
	case 1U:
		return c->now_us;
	case 2U:
		return (c->now_us > d) ? (c->now_us - d) : 0U;
	default:
		return c->now_us + d;      /* from the future: clock glitch */
	}
}

/* One DiscSpeed (which == 0) or PadForce frame from a correct sender. */
static void good_frame(ctx_t *c, uint32_t which, uint16_t raw, uint8_t skip)
{
	hal_can_frame_t f = { 0 };
	e2e_p01_config_t cfg;
	e2e_p01_tx_t tx;
	int rc;

	cfg.max_delta_counter = 1U;
	if (which == 0U) {
		const msg_disc_speed_t m = { 0U, 0U, raw };

		rc = msg_disc_speed_pack(&m, f.data, &f.dlc);
		cfg.data_id = MSG_DISC_SPEED_DATA_ID;
		f.id = c->cal0.disc_speed_id;
	} else {
		const msg_pad_force_t m = { 0U, 0U, raw };

		rc = msg_pad_force_pack(&m, f.data, &f.dlc);
		cfg.data_id = MSG_PAD_FORCE_DATA_ID;
		f.id = c->cal0.pad_force_id;
	}
	FUZZ_REQUIRE(rc == SQ_OK);
	cfg.data_len = f.dlc;
	/* skip > 0: frames lost or a sender restart (counter jump) */
	c->counter[which] = (uint8_t)((c->counter[which] + (skip % 15U)) % 15U);
	tx.counter = c->counter[which];
	FUZZ_REQUIRE(e2e_p01_protect(&cfg, &tx, f.data, f.dlc) == SQ_OK);
	c->counter[which] = tx.counter;
	f.timestamp_us = c->now_us;
	monitor_on_frame(&c->me, &f);
}

static void drain(ctx_t *c, uint8_t n, uint8_t rc_sel)
{
	static const int rcs[8] = { SQ_OK, SQ_OK, SQ_OK, SQ_ENETUNREACH,
				    SQ_ENETDOWN, SQ_EINVAL, SQ_EIO, SQ_OK };
	hal_can_frame_t f;
	uint32_t i;

	for (i = 0U; i < n; i++) {
		if (monitor_peek_tx(&c->me, &f) != SQ_OK) {
			break;
		}
		check_tx_frame(c, &f);
		monitor_tx_done(&c->me, rcs[(rc_sel + i) & 7U]);
	}
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	fuzz_in_t in = { data, size };
	ctx_t *c = &ctx;
	calib_t cal;
	uint32_t op_count;
	static monitor_t before;

	memset(c, 0, sizeof(*c));
	pick_calibration(fuzz_u8(&in), &cal);
	c->now_us = 1000000U;
	FUZZ_REQUIRE(monitor_init(&c->me, &cal, false, 0U, c->now_us) == SQ_OK);
	/* byte copies (a struct assignment need not copy padding) */
	memcpy(&c->cal0, c->me.cal, sizeof(c->cal0));
	memcpy(&c->params0, &c->me.params, sizeof(c->params0));
	c->calib_invalid0 = c->me.calib_invalid;
	{
		uint8_t a[CALIB_BLOCK_LEN];
		uint8_t b[CALIB_BLOCK_LEN];

		/* field by field: the monitor took exactly this calibration */
		FUZZ_REQUIRE(calib_encode(&c->cal0, a, sizeof(a)) == SQ_OK);
		FUZZ_REQUIRE(calib_encode(&cal, b, sizeof(b)) == SQ_OK);
		FUZZ_REQUIRE(memcmp(a, b, sizeof(a)) == 0);
	}

	for (op_count = 0U; (op_count < MAX_OPS) && (in.left > 0U); op_count++) {
		const uint8_t op = fuzz_u8(&in);
		bool stepped = false;

		before = c->me;
		switch (op & 7U) {
		case 0U:
		case 1U: {
			hal_can_frame_t f = { 0 };

			f.id = pick_id(c, &in, &f.flags);
			f.dlc = fuzz_u8(&in) & 0x0FU; /* 9..15: beyond classic CAN */
			fuzz_bytes(&in, f.data, sizeof(f.data));
			f.timestamp_us = pick_stamp(c, &in);
			monitor_on_frame(&c->me, &f);
			break;
		}
		case 2U:
			good_frame(c, (op >> 3) & 1U, fuzz_u16(&in), (uint8_t)(op >> 4));
			break;
		case 3U: {
			const uint64_t dt = (uint64_t)fuzz_u16(&in) * (((op & 0x08U) != 0U) ? 1000U : 1U);

			if ((op & 0x10U) != 0U) {
				/* the caller's clock jumps back: time must not */
				monitor_step(&c->me, (c->now_us > dt) ? (c->now_us - dt) : 0U);
			} else {
				c->now_us += dt;
				monitor_step(&c->me, c->now_us);
			}
			stepped = true;
			break;
		}
		case 4U:
			drain(c, (uint8_t)(op >> 3), fuzz_u8(&in));
			break;
		case 5U: {
			hal_can_status_t st;

			st.state = (hal_can_state_t)(fuzz_u8(&in) % 5U);
			st.tx_error_count = fuzz_u8(&in);
			st.rx_error_count = fuzz_u8(&in);
			st.bus_off_count = fuzz_u32(&in);
			st.rx_overruns = fuzz_u32(&in);
			st.tx_dropped = fuzz_u32(&in);
			st.error_frames = fuzz_u32(&in);
			monitor_on_can_status(&c->me, &st);
			break;
		}
		case 6U:
			monitor_report_task_time(&c->me, fuzz_u32(&in));
			break;
		default: {
			/* a plausible 10 ms input cycle, then the 1 ms tasks */
			const uint16_t v = fuzz_u16(&in);
			const uint16_t n = fuzz_u16(&in);
			uint32_t t;

			c->now_us += 10000U;
			good_frame(c, 0U, v, 0U);
			good_frame(c, 1U, n, 0U);
			for (t = 0U; t < 10U; t++) {
				monitor_step(&c->me, c->now_us - 9000U + 1000U * t);
			}
			stepped = true;
			break;
		}
		}
		check_monitor(c, &before, stepped);
	}
	return 0;
}
