/* SPDX-License-Identifier: MIT */
/*
 * Pack/unpack of the messages in squeal.dbc. One descriptor table drives
 * the bit layout of every signal (start bit, length, sign, range) and the
 * struct field that holds its raw value, so a layout lives in exactly one
 * place in C and a test compares that place with the DBC. Every message
 * goes through the same pack_msg()/unpack_msg(); a message's own functions
 * add only its value rules beyond the signals' ranges.
 */
#include "squeal_msgs.h"

#include "squeal_model.h"

#include "sq_contract.h"

#include <limits.h>
#include <stddef.h>

#include "sq_status.h"

/* Indices into msg_sig_table, in DBC order, grouped by message. */
enum {
	/* DiscSpeed */
	SIG_DS_CRC, SIG_DS_COUNTER, SIG_DS_RADPS,
	/* PadForce */
	SIG_PF_CRC, SIG_PF_COUNTER, SIG_PF_N,
	/* SquealStatus */
	SIG_ST_CRC, SIG_ST_COUNTER, SIG_ST_STATE, SIG_ST_WARNING,
	SIG_ST_BASIN, SIG_ST_MARGIN, SIG_ST_BORDER_SIGMA,
	/* SquealDetail */
	SIG_DT_CRC, SIG_DT_COUNTER, SIG_DT_V0, SIG_DT_HOPF_SPEED,
	SIG_DT_TRIGGER, SIG_DT_VSB,
	/* SquealDiag */
	SIG_DG_CRC, SIG_DG_COUNTER, SIG_DG_PAGE,
	SIG_DG_FAULT0, /* 12 fault bits follow in MSG_FAULT_* order */
	SIG_DG_UPTIME = SIG_DG_FAULT0 + 12, SIG_DG_BUS_OFF,
	SIG_DG_TASK_TIME, SIG_DG_RX_OVERRUN,
	SIG_DG_E2E_SPEED, SIG_DG_E2E_FORCE,
	SIG_DG_TX_OVERFLOW, SIG_DG_RX_BAD_FRAME,
	SIG_DG_HSE, SIG_DG_RESET, SIG_DG_BOR, SIG_DG_LB1, SIG_DG_LB2, SIG_DG_STACK,
	/* SquealDetail2 */
	SIG_D2_CRC, SIG_D2_COUNTER, SIG_D2_FORCE, SIG_D2_HOPF_FORCE,
	SIG_D2_LC_AMPLITUDE,
	SIG_END
};

_Static_assert(SIG_END == MSG_SIG_COUNT, "MSG_SIG_COUNT out of date");

#define N_DS (SIG_PF_CRC - SIG_DS_CRC)
#define N_PF (SIG_ST_CRC - SIG_PF_CRC)
#define N_ST (SIG_DT_CRC - SIG_ST_CRC)
#define N_DT (SIG_DG_CRC - SIG_DT_CRC)
#define N_DG (SIG_D2_CRC - SIG_DG_CRC)
#define N_D2 (SIG_END - SIG_D2_CRC)

_Static_assert(MSG_FAULT_ALL == (1U << (SIG_DG_UPTIME - SIG_DG_FAULT0)) - 1U,
	       "one fault signal per MSG_FAULT_* bit");

/* Where a signal's raw value lives: field of the message's struct type
 * (every struct is far smaller than 256 bytes: the offset fits). */
#define FLD(type, field, kind) { (uint8_t)offsetof(type, field), (uint8_t)(kind), 0U }
_Static_assert(sizeof(msg_squeal_diag_t) < 256U, "field offsets fit a uint8_t");

/* E2E header of message id (struct type): CRC byte 0, counter byte 1 bits 0..3. */
#define E2E_SIGS(id, name, type)                                                   \
	{ (id), name "_CRC", "", 0U, 8U, MSG_SIG_E2E, 0U, 1, 1, 0, 0, 255, 0,           \
	  FLD(type, crc, MSG_FIELD_U8) },                                               \
	{ (id), name "_Counter", "", 8U, 4U, MSG_SIG_E2E, 0U, 1, 1, 0, 0,              \
	  (int32_t)E2E_P01_COUNTER_MAX, 0, FLD(type, counter, MSG_FIELD_U8) }

/* plain unsigned value */
#define UNS(id, name, unit, start, len, num, den, max, fld)                        \
	{ (id), name, unit, (start), (len), 0U, 0U, (num), (den), 0, 0, (max), 0, fld }
/* unsigned value with "not available" = all ones, range 0..max */
#define UNS_NA(id, name, unit, start, len, num, den, max, fld)                     \
	{ (id), name, unit, (start), (len), MSG_SIG_HAS_NA, 0U, (num), (den), 0,        \
	  0, (max), (int32_t)((1UL << (len)) - 1UL), fld }
/* multiplexed unsigned counter of SquealDiag, range 0..all ones */
#define MUXED(name, unit, start, len, page, kind, field)                           \
	{ MSG_SQUEAL_DIAG_ID, name, unit, (start), (len), MSG_SIG_MUXED, (page), 1, 1, 0, 0, \
	  (int32_t)((1UL << (len)) - 1UL), 0, FLD(msg_squeal_diag_t, field, kind) }
/* multiplexed unsigned value with a scale and a range below all ones (the
 * values above it are "not available"/"unknown", documented in the DBC) */
#define MUXED_R(name, unit, start, len, page, num, den, max, field)                \
	{ MSG_SQUEAL_DIAG_ID, name, unit, (start), (len), MSG_SIG_MUXED, (page), (num), (den), \
	  0, 0, (max), 0, FLD(msg_squeal_diag_t, field, MSG_FIELD_U8) }
/* the same with a "not available" raw value above the range */
#define MUXED_NA(name, unit, start, len, page, num, den, max, na, kind, field)      \
	{ MSG_SQUEAL_DIAG_ID, name, unit, (start), (len), MSG_SIG_MUXED | MSG_SIG_HAS_NA, \
	  (page), (num), (den), 0, 0, (max), (na), FLD(msg_squeal_diag_t, field, kind) }
/* fault bit `bit` of SquealDiag's fault_bits */
#define FAULT(name, bit)                                                           \
	{ MSG_SQUEAL_DIAG_ID, name, "", 16U + (bit), 1U, 0U, 0U, 1, 1, 0, 0, 1, 0,      \
	  { (uint8_t)offsetof(msg_squeal_diag_t, fault_bits), (uint8_t)MSG_FIELD_BIT, (bit) } }

const msg_sig_desc_t msg_sig_table[MSG_SIG_COUNT] = {
	E2E_SIGS(MSG_DISC_SPEED_ID, "DiscSpeed", msg_disc_speed_t),
	UNS_NA(MSG_DISC_SPEED_ID, "DiscSpeed_radps", "rad/s", 16U, 16U, 1, 100,
	       (int32_t)MSG_DISC_SPEED_RADPS_MAX,
	       FLD(msg_disc_speed_t, disc_speed_radps, MSG_FIELD_U16)),

	E2E_SIGS(MSG_PAD_FORCE_ID, "PadForce", msg_pad_force_t),
	UNS_NA(MSG_PAD_FORCE_ID, "PadForce_N", "N", 16U, 16U, 1, 2,
	       (int32_t)MSG_PAD_FORCE_N_MAX, FLD(msg_pad_force_t, pad_force_n, MSG_FIELD_U16)),

	E2E_SIGS(MSG_SQUEAL_STATUS_ID, "SquealStatus", msg_squeal_status_t),
	/* the highest state is FAULT (what the value table allows: pack) */
	UNS(MSG_SQUEAL_STATUS_ID, "SquealState", "", 12U, 4U, 1, 1,
	    (int32_t)MSG_SQUEAL_STATE_FAULT, FLD(msg_squeal_status_t, squeal_state, MSG_FIELD_U8)),
	UNS(MSG_SQUEAL_STATUS_ID, "WarningLevel", "", 16U, 4U, 1, 1, 3,
	    FLD(msg_squeal_status_t, warning_level, MSG_FIELD_U8)),
	UNS_NA(MSG_SQUEAL_STATUS_ID, "BasinRatio", "", 24U, 16U, 1, 10000,
	       (int32_t)MSG_BASIN_RATIO_MAX, FLD(msg_squeal_status_t, basin_ratio, MSG_FIELD_U16)),
	{ MSG_SQUEAL_STATUS_ID, "HopfMargin_mps", "m/s", 40U, 16U,
	  MSG_SIG_SIGNED | MSG_SIG_HAS_NA, 0U, 1, 100, 0,
	  MSG_HOPF_MARGIN_MPS_MIN, MSG_HOPF_MARGIN_MPS_MAX,
	  MSG_HOPF_MARGIN_MPS_NA, FLD(msg_squeal_status_t, hopf_margin_mps, MSG_FIELD_S16) },
	/* raw 0 = not available (what a monitor without deviations sends) */
	{ MSG_SQUEAL_STATUS_ID, "BorderMargin_sigma", "sigma", 56U, 8U, MSG_SIG_HAS_NA, 0U,
	  1, 10, -1, 1, (int32_t)MSG_BORDER_MARGIN_SIGMA_SAT,
	  (int32_t)MSG_BORDER_MARGIN_SIGMA_NA,
	  FLD(msg_squeal_status_t, border_margin_sigma, MSG_FIELD_U8) },

	E2E_SIGS(MSG_SQUEAL_DETAIL_ID, "SquealDetail", msg_squeal_detail_t),
	UNS_NA(MSG_SQUEAL_DETAIL_ID, "V0_mps", "m/s", 12U, 14U, 1, 100,
	       (int32_t)MSG_V0_MPS_MAX, FLD(msg_squeal_detail_t, v0_mps, MSG_FIELD_U16)),
	UNS_NA(MSG_SQUEAL_DETAIL_ID, "HopfSpeed_mps", "m/s", 26U, 14U, 1, 100,
	       (int32_t)MSG_HOPF_SPEED_MPS_MAX,
	       FLD(msg_squeal_detail_t, hopf_speed_mps, MSG_FIELD_U16)),
	UNS_NA(MSG_SQUEAL_DETAIL_ID, "TriggerVelocity_mps", "m/s", 40U, 12U, 1,
	       100, (int32_t)MSG_TRIGGER_VELOCITY_MPS_MAX,
	       FLD(msg_squeal_detail_t, trigger_velocity_mps, MSG_FIELD_U16)),
	UNS_NA(MSG_SQUEAL_DETAIL_ID, "VehicleSpeedBorder_kph", "km/h", 52U, 12U,
	       1, 10, (int32_t)MSG_VEHICLE_SPEED_BORDER_KPH_MAX,
	       FLD(msg_squeal_detail_t, vehicle_speed_border_kph, MSG_FIELD_U16)),

	E2E_SIGS(MSG_SQUEAL_DIAG_ID, "SquealDiag", msg_squeal_diag_t),
	{ MSG_SQUEAL_DIAG_ID, "SquealDiag_Page", "", 12U, 4U, MSG_SIG_MUXOR, 0U,
	  1, 1, 0, 0, (int32_t)MSG_DIAG_PAGE_COUNT - 1, 0,
	  FLD(msg_squeal_diag_t, page, MSG_FIELD_U8) },
	FAULT("Fault_SpeedStale", 0U),
	FAULT("Fault_ForceStale", 1U),
	FAULT("Fault_E2eSpeed", 2U),
	FAULT("Fault_E2eForce", 3U),
	FAULT("Fault_SpeedImplausible", 4U),
	FAULT("Fault_ForceImplausible", 5U),
	FAULT("Fault_CalibInvalid", 6U),
	FAULT("Fault_BusOffSeen", 7U),
	FAULT("Fault_ClockFallback", 8U),
	FAULT("Fault_CanInit", 9U),
	FAULT("Fault_TxOverflow", 10U),
	FAULT("Fault_SelfTest", 11U),
	MUXED("Uptime_s", "s", 32U, 24U, MSG_DIAG_PAGE_UPTIME, MSG_FIELD_U32, uptime_s),
	MUXED("BusOffCount", "", 56U, 8U, MSG_DIAG_PAGE_UPTIME, MSG_FIELD_U8, bus_off_count),
	MUXED("WorstTaskTime_us", "us", 32U, 16U, MSG_DIAG_PAGE_TASK, MSG_FIELD_U16,
	      worst_task_time_us),
	MUXED("RxOverrunCount", "", 48U, 16U, MSG_DIAG_PAGE_TASK, MSG_FIELD_U16,
	      rx_overrun_count),
	MUXED("E2eErrorCountSpeed", "", 32U, 16U, MSG_DIAG_PAGE_E2E, MSG_FIELD_U16,
	      e2e_error_count_speed),
	MUXED("E2eErrorCountForce", "", 48U, 16U, MSG_DIAG_PAGE_E2E, MSG_FIELD_U16,
	      e2e_error_count_force),
	MUXED("TxOverflowCount", "", 32U, 16U, MSG_DIAG_PAGE_FRAMES, MSG_FIELD_U16,
	      tx_overflow_count),
	MUXED("RxBadFrameCount", "", 48U, 16U, MSG_DIAG_PAGE_FRAMES, MSG_FIELD_U16,
	      rx_bad_frame_count),
	MUXED_NA("HseFreq_MHz", "MHz", 32U, 8U, MSG_DIAG_PAGE_SELFTEST, 1, 10,
		 (int32_t)MSG_HSE_FREQ_MAX, (int32_t)MSG_HSE_FREQ_NA, MSG_FIELD_U8, hse_freq_100khz),
	MUXED_R("ResetCause", "", 40U, 3U, MSG_DIAG_PAGE_SELFTEST, 1, 1,
		(int32_t)MSG_RESET_CAUSE_MAX, reset_cause),
	MUXED_NA("BorLevel", "", 43U, 3U, MSG_DIAG_PAGE_SELFTEST, 1, 1, 3,
		 (int32_t)MSG_BOR_LEVEL_NA, MSG_FIELD_U8, bor_level),
	MUXED_R("LoopbackCan1", "", 46U, 2U, MSG_DIAG_PAGE_SELFTEST, 1, 1,
		(int32_t)MSG_LOOPBACK_MAX, loopback_can1),
	MUXED_R("LoopbackCan2", "", 48U, 2U, MSG_DIAG_PAGE_SELFTEST, 1, 1,
		(int32_t)MSG_LOOPBACK_MAX, loopback_can2),
	MUXED_NA("StackHighWater_B", "B", 50U, 14U, MSG_DIAG_PAGE_SELFTEST, 1, 1,
		 (int32_t)MSG_STACK_HWM_UNKNOWN - 1, (int32_t)MSG_STACK_HWM_UNKNOWN, MSG_FIELD_U16,
		 stack_high_water_b),

	E2E_SIGS(MSG_SQUEAL_DETAIL2_ID, "SquealDetail2", msg_squeal_detail2_t),
	UNS_NA(MSG_SQUEAL_DETAIL2_ID, "Force_N", "N", 16U, 16U, 1, 2,
	       (int32_t)MSG_FORCE_N_MAX, FLD(msg_squeal_detail2_t, force_n, MSG_FIELD_U16)),
	UNS_NA(MSG_SQUEAL_DETAIL2_ID, "HopfForce_N", "N", 32U, 16U, 1, 1,
	       (int32_t)MSG_HOPF_FORCE_N_MAX, FLD(msg_squeal_detail2_t, hopf_force_n, MSG_FIELD_U16)),
	UNS_NA(MSG_SQUEAL_DETAIL2_ID, "LcAmplitude_um", "um", 48U, 16U, 1, 10,
	       (int32_t)MSG_LC_AMPLITUDE_UM_MAX,
	       FLD(msg_squeal_detail2_t, lc_amplitude_um, MSG_FIELD_U16)),
};

const msg_desc_t msg_table[MSG_COUNT] = {
	{ MSG_DISC_SPEED_ID, "DiscSpeed", MSG_DISC_SPEED_DLC,
	  MSG_DISC_SPEED_PERIOD_MS, MSG_DISC_SPEED_DATA_ID, SIG_DS_CRC, N_DS },
	{ MSG_PAD_FORCE_ID, "PadForce", MSG_PAD_FORCE_DLC,
	  MSG_PAD_FORCE_PERIOD_MS, MSG_PAD_FORCE_DATA_ID, SIG_PF_CRC, N_PF },
	{ MSG_SQUEAL_STATUS_ID, "SquealStatus", MSG_SQUEAL_STATUS_DLC,
	  MSG_SQUEAL_STATUS_PERIOD_MS, MSG_SQUEAL_STATUS_DATA_ID, SIG_ST_CRC,
	  N_ST },
	{ MSG_SQUEAL_DETAIL_ID, "SquealDetail", MSG_SQUEAL_DETAIL_DLC,
	  MSG_SQUEAL_DETAIL_PERIOD_MS, MSG_SQUEAL_DETAIL_DATA_ID, SIG_DT_CRC,
	  N_DT },
	{ MSG_SQUEAL_DIAG_ID, "SquealDiag", MSG_SQUEAL_DIAG_DLC,
	  MSG_SQUEAL_DIAG_PERIOD_MS, MSG_SQUEAL_DIAG_DATA_ID, SIG_DG_CRC, N_DG },
	{ MSG_SQUEAL_DETAIL2_ID, "SquealDetail2", MSG_SQUEAL_DETAIL2_DLC,
	  MSG_SQUEAL_DETAIL2_PERIOD_MS, MSG_SQUEAL_DETAIL2_DATA_ID, SIG_D2_CRC,
	  N_D2 },
};

/* ---- pack/unpack's access to the struct fields -------------------------- */

/* Indices into msg_table, in its order. */
#define IX_DISC_SPEED     0U
#define IX_PAD_FORCE      1U
#define IX_SQUEAL_STATUS  2U
#define IX_SQUEAL_DETAIL  3U
#define IX_SQUEAL_DIAG    4U
#define IX_SQUEAL_DETAIL2 5U

/* the most signals of one message (SquealDiag's), for a frame's raw values */
#define SIGS_PER_MSG_MAX N_DG
_Static_assert((N_DS <= N_DG) && (N_PF <= N_DG) && (N_ST <= N_DG) && (N_DT <= N_DG) &&
	       (N_D2 <= N_DG), "SquealDiag has the most signals");

/* A field's raw signal value, from the bytes of its message's struct (the
 * field is of f's kind and alignment: the table says so). */
static int32_t sig_field_get(const uint8_t *msg, const msg_sig_field_t *f)
{
	const uint8_t *at = &msg[f->offset];
	int32_t raw;

	switch (f->kind) {
	case MSG_FIELD_U8:
		raw = (int32_t)*at;
		break;
	case MSG_FIELD_U16:
	case MSG_FIELD_S16:
	case MSG_FIELD_BIT: {
		const uint16_t v = *(const uint16_t *)(const void *)at;

		if (f->kind == MSG_FIELD_S16) {
			raw = (int32_t)(int16_t)v; /* two's complement: well defined */
		} else if (f->kind == MSG_FIELD_BIT) {
			raw = (int32_t)(((uint32_t)v >> f->bit) & 1U);
		} else {
			raw = (int32_t)v;
		}
		break;
	}
	default: {
		const uint32_t v = *(const uint32_t *)(const void *)at;

		raw = (v > (uint32_t)INT32_MAX) ? -1 : (int32_t)v;
		break;
	}
	}
	return raw;
}

/* Store a received raw value (of the signal's range) into its field. */
static void sig_field_put(uint8_t *msg, const msg_sig_field_t *f, int32_t raw)
{
	uint8_t *at = &msg[f->offset];

	if (f->kind == MSG_FIELD_U8) {
		*at = (uint8_t)raw;
	} else if (f->kind == MSG_FIELD_U32) {
		*(uint32_t *)(void *)at = (uint32_t)raw;
	} else {
		uint16_t *v = (uint16_t *)(void *)at;

		if (f->kind != MSG_FIELD_BIT) {
			*v = (uint16_t)raw; /* MSG_FIELD_S16: two's complement */
		} else {
			/* bit 0's signal comes first: it starts the word afresh */
			const uint32_t others = (f->bit == 0U) ? 0U : ((uint32_t)*v & ~(1U << f->bit));

			*v = (uint16_t)(others | ((raw != 0) ? (1U << f->bit) : 0U));
		}
	}
}

/* ---- bit access ---------------------------------------------------------- */

/*
 * Intel (little-endian) signal access, whole bytes at a time: a signal of
 * len <= 31 bits starting at bit `start` touches at most 5 bytes, which are
 * gathered into one 64-bit word. put_bits ORs into a zeroed frame: the
 * signals of a message do not overlap.
 */
static void put_bits(uint8_t data[MSG_MAX_DLC], uint8_t start, uint8_t len,
		     uint32_t value)
{
	const unsigned int first = (unsigned int)start / 8U;
	const unsigned int last = ((unsigned int)start + len - 1U) / 8U;
	uint64_t w = ((uint64_t)value & (((uint64_t)1U << len) - 1U)) << ((unsigned int)start % 8U);
	unsigned int b;

	for (b = first; b <= last; b++) {
		data[b] = (uint8_t)(data[b] | (w & 0xFFU));
		w >>= 8;
	}
}

static uint32_t get_bits(const uint8_t *data, uint8_t start, uint8_t len)
{
	const unsigned int first = (unsigned int)start / 8U;
	const unsigned int last = ((unsigned int)start + len - 1U) / 8U;
	uint64_t w = 0U;
	unsigned int b;

	for (b = last + 1U; b > first; b--) {
		w = (w << 8) | data[b - 1U];
	}
	return (uint32_t)((w >> ((unsigned int)start % 8U)) &
			  (((uint64_t)1U << len) - 1U));
}

static int32_t sig_read(const msg_sig_desc_t *s, const uint8_t *data)
{
	uint32_t v = get_bits(data, s->start_bit, s->length);

	if ((s->flags & MSG_SIG_SIGNED) != 0U &&
	    ((v >> (s->length - 1U)) & 1U) != 0U) {
		return (int32_t)((int64_t)v - ((int64_t)1 << s->length));
	}
	return (int32_t)v;
}

static bool sig_in_range(const msg_sig_desc_t *s, int32_t raw)
{
	if (raw >= s->raw_min && raw <= s->raw_max) {
		return true;
	}
	return (s->flags & MSG_SIG_HAS_NA) != 0U && raw == s->na_raw;
}

/* A signal of this frame: not multiplexed, or on the multiplexor's page
 * (every multiplexor comes before the signals it selects). */
static bool sig_on_page(const msg_sig_desc_t *s, int32_t page)
{
	return (s->flags & MSG_SIG_MUXED) == 0U || (int32_t)s->mux_value == page;
}

/* ---- pack/unpack: one path for every message ----------------------------- */

/*
 * Message m from its struct: every field of the frame's page range-checked
 * (fields_ok: the message's own value rules), then a zeroed frame with the
 * signals written; data untouched on an error.
 */
static int pack_msg(const msg_desc_t *m, const uint8_t *msg, bool fields_ok,
		    uint8_t data[MSG_MAX_DLC], uint8_t *dlc)
{
	uint8_t frame[MSG_MAX_DLC] = { 0 };
	int32_t page = 0;
	unsigned int i;

	HAL_REQUIRE((msg != NULL) && (data != NULL) && (dlc != NULL));
	if (!fields_ok) {
		return SQ_ERANGE;
	}
	for (i = m->sig_first; i < (unsigned int)m->sig_first + m->sig_count; i++) {
		const msg_sig_desc_t *s = &msg_sig_table[i];
		int32_t raw;

		if (!sig_on_page(s, page)) {
			continue;
		}
		raw = sig_field_get(msg, &s->field);
		if (!sig_in_range(s, raw)) {
			return SQ_ERANGE;
		}
		if ((s->flags & MSG_SIG_MUXOR) != 0U) {
			page = raw;
		}
		/* two's complement of negative raw values: well defined */
		put_bits(frame, s->start_bit, s->length, (uint32_t)raw);
	}
	for (i = 0U; i < MSG_MAX_DLC; i++) {
		data[i] = frame[i];
	}
	*dlc = m->dlc;
	return SQ_OK;
}

/*
 * A received frame of message m into (every field of) its struct, written
 * only when the frame is well formed: its DLC, a counter below 15, a
 * multiplexor in its range. The fields of another page are 0.
 */
static int unpack_msg(const msg_desc_t *m, const uint8_t *data, uint8_t dlc, uint8_t *msg)
{
	int32_t raw[SIGS_PER_MSG_MAX] = { 0 };
	int32_t page = 0;
	unsigned int i;

	HAL_REQUIRE(msg != NULL);
	if (data == NULL || dlc != m->dlc) {
		return SQ_EBADMSG;
	}
	for (i = 0U; i < m->sig_count; i++) {
		const msg_sig_desc_t *s = &msg_sig_table[m->sig_first + i];

		raw[i] = sig_read(s, data);
		if ((s->flags & MSG_SIG_MUXOR) != 0U) {
			if (raw[i] > s->raw_max) {
				return SQ_EBADMSG; /* a page the DBC does not have */
			}
			page = raw[i];
		}
	}
	/* signal sig_first + 1 is always the E2E counter */
	if (raw[1] > (int32_t)E2E_P01_COUNTER_MAX) {
		return SQ_EBADMSG;
	}
	for (i = 0U; i < m->sig_count; i++) {
		const msg_sig_desc_t *s = &msg_sig_table[m->sig_first + i];

		sig_field_put(msg, &s->field, sig_on_page(s, page) ? raw[i] : 0);
	}
	return SQ_OK;
}

/* SquealState has a value table: only its entries may be sent. */
static bool squeal_state_valid(uint8_t state)
{
	return (state < SQUEAL_STATE_NAMED) || (state == MSG_SQUEAL_STATE_FAULT);
}

/* A message's pack and unpack (squeal_msgs.h); fields_ok: its own value
 * rules beyond the signals' ranges, on a non-NULL msg. */
#define MSG_CODEC(name, ix, fields_ok)                                                  \
	int msg_##name##_pack(const msg_##name##_t *msg, uint8_t data[8], uint8_t *dlc)  \
	{                                                                               \
		return pack_msg(&msg_table[(ix)], (const uint8_t *)msg, (msg == NULL) || (fields_ok), \
				data, dlc);                                             \
	}                                                                               \
	int msg_##name##_unpack(const uint8_t *data, uint8_t dlc, msg_##name##_t *msg)   \
	{                                                                               \
		return unpack_msg(&msg_table[(ix)], data, dlc, (uint8_t *)msg);            \
	}

MSG_CODEC(disc_speed, IX_DISC_SPEED, true)
MSG_CODEC(pad_force, IX_PAD_FORCE, true)
MSG_CODEC(squeal_status, IX_SQUEAL_STATUS, squeal_state_valid(msg->squeal_state))
MSG_CODEC(squeal_detail, IX_SQUEAL_DETAIL, true)
MSG_CODEC(squeal_detail2, IX_SQUEAL_DETAIL2, true)
MSG_CODEC(squeal_diag, IX_SQUEAL_DIAG, (msg->fault_bits & ~MSG_FAULT_ALL) == 0U)

/* ---- receive: E2E check, then unpack only a usable frame ------------------ */

static int receive_msg(const e2e_p01_config_t *cfg, e2e_p01_rx_t *rx, const uint8_t *data,
		       uint8_t dlc, const msg_desc_t *m, uint8_t *msg)
{
	e2e_p01_status_t st;

	HAL_REQUIRE((cfg != NULL) && (rx != NULL) && (msg != NULL));
	st = e2e_p01_check(cfg, rx, data, dlc);
	if (st == E2E_P01_STATUS_NONEWDATA) {
		return SQ_EAGAIN;
	}
	if (!e2e_p01_status_usable(st)) {
		return SQ_EBADMSG;
	}
	return unpack_msg(m, data, dlc, msg);
}

#define MSG_RECEIVE(name, ix)                                                          \
	int msg_##name##_receive(const e2e_p01_config_t *cfg, e2e_p01_rx_t *rx,         \
				 const uint8_t *data, uint8_t dlc, msg_##name##_t *msg) \
	{                                                                              \
		return receive_msg(cfg, rx, data, dlc, &msg_table[(ix)], (uint8_t *)msg); \
	}

MSG_RECEIVE(disc_speed, IX_DISC_SPEED)
MSG_RECEIVE(pad_force, IX_PAD_FORCE)

/* ---- descriptor access --------------------------------------------------- */

const char *msg_squeal_state_name(uint8_t state)
{
	const char *name;

	if (state < SQUEAL_STATE_NAMED) {
		/* the model's classes: their names are the model's */
		name = squeal_model_state_name((squeal_state_t)state);
	} else if (state == MSG_SQUEAL_STATE_FAULT) {
		name = "fault";
	} else {
		name = NULL; /* a value the DBC does not name */
	}
	return name;
}

uint32_t msg_squeal_state_slot(uint32_t state)
{
	return (state < SQUEAL_STATE_NAMED) ? state : MSG_SQUEAL_STATE_SLOT_FAULT;
}

const msg_desc_t *msg_desc_find(uint16_t id)
{
	size_t i;

	for (i = 0U; i < MSG_COUNT; i++) {
		if (msg_table[i].id == id) {
			return &msg_table[i];
		}
	}
	return NULL;
}

int msg_sig_get_raw(const msg_sig_desc_t *sig, const uint8_t *data,
		    uint8_t dlc, int32_t *raw)
{
	const msg_desc_t *m;

	HAL_REQUIRE((sig != NULL) && (data != NULL) && (raw != NULL));
	m = msg_desc_find(sig->msg_id);
	if (m == NULL) {
		return SQ_EINVAL;
	}
	if (dlc != m->dlc) {
		return SQ_EBADMSG;
	}
	if ((sig->flags & MSG_SIG_MUXED) != 0U) {
		unsigned int i;

		for (i = 0U; i < m->sig_count; i++) {
			const msg_sig_desc_t *mux = &msg_sig_table[m->sig_first + i];

			if ((mux->flags & MSG_SIG_MUXOR) != 0U &&
			    sig_read(mux, data) != (int32_t)sig->mux_value) {
				return SQ_ENOENT;
			}
		}
	}
	*raw = sig_read(sig, data);
	return SQ_OK;
}
