/* SPDX-License-Identifier: MIT */
/*
 * Pack/unpack of the messages in squeal.dbc. One descriptor table drives
 * the bit layout of every signal (start bit, length, sign, range), so a
 * layout lives in exactly one place in C and a test compares that place
 * with the DBC. The per-message functions only map struct fields to and
 * from the table's raw values.
 */
#include "squeal_msgs.h"

#include "squeal_model.h"

#include "sq_contract.h"

#include <limits.h>

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

/* E2E header of message id: CRC byte 0, counter byte 1 bits 0..3. */
#define E2E_SIGS(id, name)                                                 \
	{ (id), name "_CRC", "", 0U, 8U, MSG_SIG_E2E, 0U, 1, 1, 0, 0, 255, 0 }, \
	{ (id), name "_Counter", "", 8U, 4U, MSG_SIG_E2E, 0U, 1, 1, 0, 0,      \
	  (int32_t)E2E_P01_COUNTER_MAX, 0 }

/* plain unsigned value */
#define UNS(id, name, unit, start, len, num, den, max)                     \
	{ (id), name, unit, (start), (len), 0U, 0U, (num), (den), 0, 0, (max), 0 }
/* unsigned value with "not available" = all ones, range 0..max */
#define UNS_NA(id, name, unit, start, len, num, den, max)                  \
	{ (id), name, unit, (start), (len), MSG_SIG_HAS_NA, 0U, (num), (den), 0, \
	  0, (max), (int32_t)((1UL << (len)) - 1UL) }
/* multiplexed unsigned counter, range 0..all ones */
#define MUXED(id, name, unit, start, len, page)                            \
	{ (id), name, unit, (start), (len), MSG_SIG_MUXED, (page), 1, 1, 0, 0, \
	  (int32_t)((1UL << (len)) - 1UL), 0 }
/* multiplexed unsigned value with a scale and a range below all ones (the
 * values above it are "not available"/"unknown", documented in the DBC) */
#define MUXED_R(id, name, unit, start, len, page, num, den, max)               \
	{ (id), name, unit, (start), (len), MSG_SIG_MUXED, (page), (num), (den), 0, 0, \
	  (max), 0 }
/* the same with a "not available" raw value above the range */
#define MUXED_NA(id, name, unit, start, len, page, num, den, max, na)           \
	{ (id), name, unit, (start), (len), MSG_SIG_MUXED | MSG_SIG_HAS_NA, (page), (num), \
	  (den), 0, 0, (max), (na) }
#define FAULT(name, bit) UNS(MSG_SQUEAL_DIAG_ID, name, "", 16U + (bit), 1U, 1, 1, 1)

const msg_sig_desc_t msg_sig_table[MSG_SIG_COUNT] = {
	E2E_SIGS(MSG_DISC_SPEED_ID, "DiscSpeed"),
	UNS_NA(MSG_DISC_SPEED_ID, "DiscSpeed_radps", "rad/s", 16U, 16U, 1, 100,
	       (int32_t)MSG_DISC_SPEED_RADPS_MAX),

	E2E_SIGS(MSG_PAD_FORCE_ID, "PadForce"),
	UNS_NA(MSG_PAD_FORCE_ID, "PadForce_N", "N", 16U, 16U, 1, 2,
	       (int32_t)MSG_PAD_FORCE_N_MAX),

	E2E_SIGS(MSG_SQUEAL_STATUS_ID, "SquealStatus"),
	/* the highest state is FAULT (what the value table allows: pack) */
	UNS(MSG_SQUEAL_STATUS_ID, "SquealState", "", 12U, 4U, 1, 1,
	    (int32_t)MSG_SQUEAL_STATE_FAULT),
	UNS(MSG_SQUEAL_STATUS_ID, "WarningLevel", "", 16U, 4U, 1, 1, 3),
	UNS_NA(MSG_SQUEAL_STATUS_ID, "BasinRatio", "", 24U, 16U, 1, 10000,
	       (int32_t)MSG_BASIN_RATIO_MAX),
	{ MSG_SQUEAL_STATUS_ID, "HopfMargin_mps", "m/s", 40U, 16U,
	  MSG_SIG_SIGNED | MSG_SIG_HAS_NA, 0U, 1, 100, 0,
	  MSG_HOPF_MARGIN_MPS_MIN, MSG_HOPF_MARGIN_MPS_MAX,
	  MSG_HOPF_MARGIN_MPS_NA },
	/* raw 0 = not available (what a monitor without deviations sends) */
	{ MSG_SQUEAL_STATUS_ID, "BorderMargin_sigma", "sigma", 56U, 8U, MSG_SIG_HAS_NA, 0U,
	  1, 10, -1, 1, (int32_t)MSG_BORDER_MARGIN_SIGMA_SAT,
	  (int32_t)MSG_BORDER_MARGIN_SIGMA_NA },

	E2E_SIGS(MSG_SQUEAL_DETAIL_ID, "SquealDetail"),
	UNS_NA(MSG_SQUEAL_DETAIL_ID, "V0_mps", "m/s", 12U, 14U, 1, 100,
	       (int32_t)MSG_V0_MPS_MAX),
	UNS_NA(MSG_SQUEAL_DETAIL_ID, "HopfSpeed_mps", "m/s", 26U, 14U, 1, 100,
	       (int32_t)MSG_HOPF_SPEED_MPS_MAX),
	UNS_NA(MSG_SQUEAL_DETAIL_ID, "TriggerVelocity_mps", "m/s", 40U, 12U, 1,
	       100, (int32_t)MSG_TRIGGER_VELOCITY_MPS_MAX),
	UNS_NA(MSG_SQUEAL_DETAIL_ID, "VehicleSpeedBorder_kph", "km/h", 52U, 12U,
	       1, 10, (int32_t)MSG_VEHICLE_SPEED_BORDER_KPH_MAX),

	E2E_SIGS(MSG_SQUEAL_DIAG_ID, "SquealDiag"),
	{ MSG_SQUEAL_DIAG_ID, "SquealDiag_Page", "", 12U, 4U, MSG_SIG_MUXOR, 0U,
	  1, 1, 0, 0, (int32_t)MSG_DIAG_PAGE_COUNT - 1, 0 },
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
	MUXED(MSG_SQUEAL_DIAG_ID, "Uptime_s", "s", 32U, 24U, MSG_DIAG_PAGE_UPTIME),
	MUXED(MSG_SQUEAL_DIAG_ID, "BusOffCount", "", 56U, 8U, MSG_DIAG_PAGE_UPTIME),
	MUXED(MSG_SQUEAL_DIAG_ID, "WorstTaskTime_us", "us", 32U, 16U,
	      MSG_DIAG_PAGE_TASK),
	MUXED(MSG_SQUEAL_DIAG_ID, "RxOverrunCount", "", 48U, 16U,
	      MSG_DIAG_PAGE_TASK),
	MUXED(MSG_SQUEAL_DIAG_ID, "E2eErrorCountSpeed", "", 32U, 16U,
	      MSG_DIAG_PAGE_E2E),
	MUXED(MSG_SQUEAL_DIAG_ID, "E2eErrorCountForce", "", 48U, 16U,
	      MSG_DIAG_PAGE_E2E),
	MUXED(MSG_SQUEAL_DIAG_ID, "TxOverflowCount", "", 32U, 16U,
	      MSG_DIAG_PAGE_FRAMES),
	MUXED(MSG_SQUEAL_DIAG_ID, "RxBadFrameCount", "", 48U, 16U,
	      MSG_DIAG_PAGE_FRAMES),
	MUXED_NA(MSG_SQUEAL_DIAG_ID, "HseFreq_MHz", "MHz", 32U, 8U, MSG_DIAG_PAGE_SELFTEST, 1, 10,
		 (int32_t)MSG_HSE_FREQ_MAX, (int32_t)MSG_HSE_FREQ_NA),
	MUXED_R(MSG_SQUEAL_DIAG_ID, "ResetCause", "", 40U, 3U, MSG_DIAG_PAGE_SELFTEST, 1, 1,
		(int32_t)MSG_RESET_CAUSE_MAX),
	MUXED_NA(MSG_SQUEAL_DIAG_ID, "BorLevel", "", 43U, 3U, MSG_DIAG_PAGE_SELFTEST, 1, 1, 3,
		 (int32_t)MSG_BOR_LEVEL_NA),
	MUXED_R(MSG_SQUEAL_DIAG_ID, "LoopbackCan1", "", 46U, 2U, MSG_DIAG_PAGE_SELFTEST, 1, 1,
		(int32_t)MSG_LOOPBACK_MAX),
	MUXED_R(MSG_SQUEAL_DIAG_ID, "LoopbackCan2", "", 48U, 2U, MSG_DIAG_PAGE_SELFTEST, 1, 1,
		(int32_t)MSG_LOOPBACK_MAX),
	MUXED_NA(MSG_SQUEAL_DIAG_ID, "StackHighWater_B", "B", 50U, 14U, MSG_DIAG_PAGE_SELFTEST, 1, 1,
		 (int32_t)MSG_STACK_HWM_UNKNOWN - 1, (int32_t)MSG_STACK_HWM_UNKNOWN),

	E2E_SIGS(MSG_SQUEAL_DETAIL2_ID, "SquealDetail2"),
	UNS_NA(MSG_SQUEAL_DETAIL2_ID, "Force_N", "N", 16U, 16U, 1, 2,
	       (int32_t)MSG_FORCE_N_MAX),
	UNS_NA(MSG_SQUEAL_DETAIL2_ID, "HopfForce_N", "N", 32U, 16U, 1, 1,
	       (int32_t)MSG_HOPF_FORCE_N_MAX),
	UNS_NA(MSG_SQUEAL_DETAIL2_ID, "LcAmplitude_um", "um", 48U, 16U, 1, 10,
	       (int32_t)MSG_LC_AMPLITUDE_UM_MAX),
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

/* ---- bit access ---------------------------------------------------------- */

/* Intel layout: bit k of the value goes to frame bit start+k, frame bit b
 * being bit (b % 8) of byte b / 8. Bitwise on purpose: obviously right,
 * and at most 64 steps per frame. */
/*
 * Intel (little-endian) signal access, whole bytes at a time: a signal of
 * len <= 31 bits starting at bit `start` touches at most 5 bytes, which are
 * gathered into one 64-bit word, masked and scattered back.
 */
static void put_bits(uint8_t data[MSG_MAX_DLC], uint8_t start, uint8_t len,
		     uint32_t value)
{
	const unsigned int first = (unsigned int)start / 8U;
	const unsigned int last = ((unsigned int)start + len - 1U) / 8U;
	const unsigned int sh = (unsigned int)start % 8U;
	const uint64_t mask = (((uint64_t)1U << len) - 1U) << sh;
	uint64_t w = 0U;
	unsigned int b;

	for (b = last + 1U; b > first; b--) {
		w = (w << 8) | data[b - 1U];
	}
	w = (w & ~mask) | (((uint64_t)value << sh) & mask);
	for (b = first; b <= last; b++) {
		data[b] = (uint8_t)(w & 0xFFU);
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

static bool sig_on_page(const msg_sig_desc_t *s, uint8_t page)
{
	return (s->flags & MSG_SIG_MUXED) == 0U || s->mux_value == page;
}

/*
 * Range-check raw[0..count-1] against the signals first..first+count-1,
 * then write a zeroed frame. Multiplexed signals not on page are skipped.
 */
static int pack_sigs(unsigned int first, unsigned int count,
		     const int32_t *raw, uint8_t page, uint8_t frame_dlc,
		     uint8_t data[MSG_MAX_DLC], uint8_t *dlc)
{
	unsigned int i;

	for (i = 0U; i < count; i++) {
		const msg_sig_desc_t *s = &msg_sig_table[first + i];

		if (sig_on_page(s, page) && !sig_in_range(s, raw[i])) {
			return SQ_ERANGE;
		}
	}
	for (i = 0U; i < MSG_MAX_DLC; i++) {
		data[i] = 0U;
	}
	for (i = 0U; i < count; i++) {
		const msg_sig_desc_t *s = &msg_sig_table[first + i];

		if (sig_on_page(s, page)) {
			/* two's complement of negative raw values: well defined */
			put_bits(data, s->start_bit, s->length, (uint32_t)raw[i]);
		}
	}
	*dlc = frame_dlc;
	return SQ_OK;
}

/* Read the signals of a frame; counter 15 is malformed. */
static int unpack_sigs(unsigned int first, unsigned int count,
		       const uint8_t *data, uint8_t dlc, uint8_t frame_dlc,
		       int32_t *raw)
{
	unsigned int i;

	if (data == NULL || dlc != frame_dlc) {
		return SQ_EBADMSG;
	}
	for (i = 0U; i < count; i++) {
		raw[i] = sig_read(&msg_sig_table[first + i], data);
	}
	/* signals first+1 is always the E2E counter */
	if (raw[1] > (int32_t)E2E_P01_COUNTER_MAX) {
		return SQ_EBADMSG;
	}
	return SQ_OK;
}

/* ---- per-message mapping ------------------------------------------------- */

int msg_disc_speed_pack(const msg_disc_speed_t *msg, uint8_t data[8], uint8_t *dlc)
{
	int32_t raw[N_DS];

	HAL_REQUIRE((msg != NULL) && (data != NULL) && (dlc != NULL));
	raw[0] = msg->crc;
	raw[1] = msg->counter;
	raw[2] = msg->disc_speed_radps;
	return pack_sigs(SIG_DS_CRC, N_DS, raw, 0U, MSG_DISC_SPEED_DLC, data, dlc);
}

int msg_disc_speed_unpack(const uint8_t *data, uint8_t dlc, msg_disc_speed_t *msg)
{
	int32_t raw[N_DS];
	int rc;

	HAL_REQUIRE(msg != NULL);
	rc = unpack_sigs(SIG_DS_CRC, N_DS, data, dlc, MSG_DISC_SPEED_DLC, raw);
	if (rc != SQ_OK) {
		return rc;
	}
	msg->crc = (uint8_t)raw[0];
	msg->counter = (uint8_t)raw[1];
	msg->disc_speed_radps = (uint16_t)raw[2];
	return SQ_OK;
}

int msg_pad_force_pack(const msg_pad_force_t *msg, uint8_t data[8], uint8_t *dlc)
{
	int32_t raw[N_PF];

	HAL_REQUIRE((msg != NULL) && (data != NULL) && (dlc != NULL));
	raw[0] = msg->crc;
	raw[1] = msg->counter;
	raw[2] = msg->pad_force_n;
	return pack_sigs(SIG_PF_CRC, N_PF, raw, 0U, MSG_PAD_FORCE_DLC, data, dlc);
}

int msg_pad_force_unpack(const uint8_t *data, uint8_t dlc, msg_pad_force_t *msg)
{
	int32_t raw[N_PF];
	int rc;

	HAL_REQUIRE(msg != NULL);
	rc = unpack_sigs(SIG_PF_CRC, N_PF, data, dlc, MSG_PAD_FORCE_DLC, raw);
	if (rc != SQ_OK) {
		return rc;
	}
	msg->crc = (uint8_t)raw[0];
	msg->counter = (uint8_t)raw[1];
	msg->pad_force_n = (uint16_t)raw[2];
	return SQ_OK;
}

/* SquealState has a value table: only its entries may be sent. */
static bool squeal_state_valid(uint8_t state)
{
	return (state < SQUEAL_STATE_NAMED) || (state == MSG_SQUEAL_STATE_FAULT);
}

int msg_squeal_status_pack(const msg_squeal_status_t *msg, uint8_t data[8],
			   uint8_t *dlc)
{
	int32_t raw[N_ST];

	HAL_REQUIRE((msg != NULL) && (data != NULL) && (dlc != NULL));
	if (!squeal_state_valid(msg->squeal_state)) {
		return SQ_ERANGE;
	}
	raw[0] = msg->crc;
	raw[1] = msg->counter;
	raw[2] = msg->squeal_state;
	raw[3] = msg->warning_level;
	raw[4] = msg->basin_ratio;
	raw[5] = msg->hopf_margin_mps;
	raw[6] = msg->border_margin_sigma;
	return pack_sigs(SIG_ST_CRC, N_ST, raw, 0U, MSG_SQUEAL_STATUS_DLC, data,
			 dlc);
}

int msg_squeal_status_unpack(const uint8_t *data, uint8_t dlc,
			     msg_squeal_status_t *msg)
{
	int32_t raw[N_ST];
	int rc;

	HAL_REQUIRE(msg != NULL);
	rc = unpack_sigs(SIG_ST_CRC, N_ST, data, dlc, MSG_SQUEAL_STATUS_DLC, raw);
	if (rc != SQ_OK) {
		return rc;
	}
	msg->crc = (uint8_t)raw[0];
	msg->counter = (uint8_t)raw[1];
	msg->squeal_state = (uint8_t)raw[2];
	msg->warning_level = (uint8_t)raw[3];
	msg->basin_ratio = (uint16_t)raw[4];
	msg->hopf_margin_mps = (int16_t)raw[5];
	msg->border_margin_sigma = (uint8_t)raw[6];
	return SQ_OK;
}

int msg_squeal_detail_pack(const msg_squeal_detail_t *msg, uint8_t data[8],
			   uint8_t *dlc)
{
	int32_t raw[N_DT];

	HAL_REQUIRE((msg != NULL) && (data != NULL) && (dlc != NULL));
	raw[0] = msg->crc;
	raw[1] = msg->counter;
	raw[2] = msg->v0_mps;
	raw[3] = msg->hopf_speed_mps;
	raw[4] = msg->trigger_velocity_mps;
	raw[5] = msg->vehicle_speed_border_kph;
	return pack_sigs(SIG_DT_CRC, N_DT, raw, 0U, MSG_SQUEAL_DETAIL_DLC, data,
			 dlc);
}

int msg_squeal_detail_unpack(const uint8_t *data, uint8_t dlc,
			     msg_squeal_detail_t *msg)
{
	int32_t raw[N_DT];
	int rc;

	HAL_REQUIRE(msg != NULL);
	rc = unpack_sigs(SIG_DT_CRC, N_DT, data, dlc, MSG_SQUEAL_DETAIL_DLC, raw);
	if (rc != SQ_OK) {
		return rc;
	}
	msg->crc = (uint8_t)raw[0];
	msg->counter = (uint8_t)raw[1];
	msg->v0_mps = (uint16_t)raw[2];
	msg->hopf_speed_mps = (uint16_t)raw[3];
	msg->trigger_velocity_mps = (uint16_t)raw[4];
	msg->vehicle_speed_border_kph = (uint16_t)raw[5];
	return SQ_OK;
}

int msg_squeal_detail2_pack(const msg_squeal_detail2_t *msg, uint8_t data[8],
			    uint8_t *dlc)
{
	int32_t raw[N_D2];

	HAL_REQUIRE((msg != NULL) && (data != NULL) && (dlc != NULL));
	raw[0] = msg->crc;
	raw[1] = msg->counter;
	raw[2] = msg->force_n;
	raw[3] = msg->hopf_force_n;
	raw[4] = msg->lc_amplitude_um;
	return pack_sigs(SIG_D2_CRC, N_D2, raw, 0U, MSG_SQUEAL_DETAIL2_DLC, data,
			 dlc);
}

int msg_squeal_detail2_unpack(const uint8_t *data, uint8_t dlc,
			      msg_squeal_detail2_t *msg)
{
	int32_t raw[N_D2];
	int rc;

	HAL_REQUIRE(msg != NULL);
	rc = unpack_sigs(SIG_D2_CRC, N_D2, data, dlc, MSG_SQUEAL_DETAIL2_DLC, raw);
	if (rc != SQ_OK) {
		return rc;
	}
	msg->crc = (uint8_t)raw[0];
	msg->counter = (uint8_t)raw[1];
	msg->force_n = (uint16_t)raw[2];
	msg->hopf_force_n = (uint16_t)raw[3];
	msg->lc_amplitude_um = (uint16_t)raw[4];
	return SQ_OK;
}

#define DG(sig) ((sig) - SIG_DG_CRC)

int msg_squeal_diag_pack(const msg_squeal_diag_t *msg, uint8_t data[8],
			 uint8_t *dlc)
{
	int32_t raw[N_DG];
	unsigned int i;

	HAL_REQUIRE((msg != NULL) && (data != NULL) && (dlc != NULL));
	if ((msg->fault_bits & ~MSG_FAULT_ALL) != 0U) {
		return SQ_ERANGE;
	}
	raw[DG(SIG_DG_CRC)] = msg->crc;
	raw[DG(SIG_DG_COUNTER)] = msg->counter;
	raw[DG(SIG_DG_PAGE)] = msg->page;
	for (i = 0U; i < (unsigned int)(SIG_DG_UPTIME - SIG_DG_FAULT0); i++) {
		raw[DG(SIG_DG_FAULT0) + i] = (int32_t)((msg->fault_bits >> i) & 1U);
	}
	/* 24-bit field: a larger value is out of range, not truncated */
	raw[DG(SIG_DG_UPTIME)] = msg->uptime_s > MSG_UPTIME_S_MAX ?
		-1 : (int32_t)msg->uptime_s;
	raw[DG(SIG_DG_BUS_OFF)] = msg->bus_off_count;
	raw[DG(SIG_DG_TASK_TIME)] = msg->worst_task_time_us;
	raw[DG(SIG_DG_RX_OVERRUN)] = msg->rx_overrun_count;
	raw[DG(SIG_DG_E2E_SPEED)] = msg->e2e_error_count_speed;
	raw[DG(SIG_DG_E2E_FORCE)] = msg->e2e_error_count_force;
	raw[DG(SIG_DG_TX_OVERFLOW)] = msg->tx_overflow_count;
	raw[DG(SIG_DG_RX_BAD_FRAME)] = msg->rx_bad_frame_count;
	raw[DG(SIG_DG_HSE)] = msg->hse_freq_100khz;
	raw[DG(SIG_DG_RESET)] = msg->reset_cause;
	raw[DG(SIG_DG_BOR)] = msg->bor_level;
	raw[DG(SIG_DG_LB1)] = msg->loopback_can1;
	raw[DG(SIG_DG_LB2)] = msg->loopback_can2;
	raw[DG(SIG_DG_STACK)] = msg->stack_high_water_b;
	return pack_sigs(SIG_DG_CRC, N_DG, raw, msg->page, MSG_SQUEAL_DIAG_DLC,
			 data, dlc);
}

int msg_squeal_diag_unpack(const uint8_t *data, uint8_t dlc,
			   msg_squeal_diag_t *msg)
{
	int32_t raw[N_DG];
	msg_squeal_diag_t out = { 0 };
	unsigned int i;
	int rc;

	HAL_REQUIRE(msg != NULL);
	rc = unpack_sigs(SIG_DG_CRC, N_DG, data, dlc, MSG_SQUEAL_DIAG_DLC, raw);
	if (rc != SQ_OK) {
		return rc;
	}
	if (raw[DG(SIG_DG_PAGE)] >= (int32_t)MSG_DIAG_PAGE_COUNT) {
		return SQ_EBADMSG;
	}
	out.crc = (uint8_t)raw[DG(SIG_DG_CRC)];
	out.counter = (uint8_t)raw[DG(SIG_DG_COUNTER)];
	out.page = (uint8_t)raw[DG(SIG_DG_PAGE)];
	for (i = 0U; i < (unsigned int)(SIG_DG_UPTIME - SIG_DG_FAULT0); i++) {
		if (raw[DG(SIG_DG_FAULT0) + i] != 0) {
			out.fault_bits = (uint16_t)(out.fault_bits | (1U << i));
		}
	}
	switch (out.page) {
	case MSG_DIAG_PAGE_UPTIME:
		out.uptime_s = (uint32_t)raw[DG(SIG_DG_UPTIME)];
		out.bus_off_count = (uint8_t)raw[DG(SIG_DG_BUS_OFF)];
		break;
	case MSG_DIAG_PAGE_TASK:
		out.worst_task_time_us = (uint16_t)raw[DG(SIG_DG_TASK_TIME)];
		out.rx_overrun_count = (uint16_t)raw[DG(SIG_DG_RX_OVERRUN)];
		break;
	case MSG_DIAG_PAGE_E2E:
		out.e2e_error_count_speed = (uint16_t)raw[DG(SIG_DG_E2E_SPEED)];
		out.e2e_error_count_force = (uint16_t)raw[DG(SIG_DG_E2E_FORCE)];
		break;
	case MSG_DIAG_PAGE_FRAMES:
		out.tx_overflow_count = (uint16_t)raw[DG(SIG_DG_TX_OVERFLOW)];
		out.rx_bad_frame_count = (uint16_t)raw[DG(SIG_DG_RX_BAD_FRAME)];
		break;
	default:
		out.hse_freq_100khz = (uint8_t)raw[DG(SIG_DG_HSE)];
		out.reset_cause = (uint8_t)raw[DG(SIG_DG_RESET)];
		out.bor_level = (uint8_t)raw[DG(SIG_DG_BOR)];
		out.loopback_can1 = (uint8_t)raw[DG(SIG_DG_LB1)];
		out.loopback_can2 = (uint8_t)raw[DG(SIG_DG_LB2)];
		out.stack_high_water_b = (uint16_t)raw[DG(SIG_DG_STACK)];
		break;
	}
	*msg = out;
	return SQ_OK;
}

/* ---- receive: E2E check, then unpack only a usable frame ------------------ */

static int receive_check(const e2e_p01_config_t *cfg, e2e_p01_rx_t *rx,
			 const uint8_t *data, uint8_t dlc)
{
	e2e_p01_status_t st = e2e_p01_check(cfg, rx, data, dlc);

	if (st == E2E_P01_STATUS_NONEWDATA) {
		return SQ_EAGAIN;
	}
	return e2e_p01_status_usable(st) ? SQ_OK : SQ_EBADMSG;
}

int msg_disc_speed_receive(const e2e_p01_config_t *cfg, e2e_p01_rx_t *rx,
			   const uint8_t *data, uint8_t dlc,
			   msg_disc_speed_t *msg)
{
	int rc;

	HAL_REQUIRE((cfg != NULL) && (rx != NULL) && (msg != NULL));
	rc = receive_check(cfg, rx, data, dlc);
	if (rc != SQ_OK) {
		return rc;
	}
	return msg_disc_speed_unpack(data, dlc, msg);
}

int msg_pad_force_receive(const e2e_p01_config_t *cfg, e2e_p01_rx_t *rx,
			  const uint8_t *data, uint8_t dlc,
			  msg_pad_force_t *msg)
{
	int rc;

	HAL_REQUIRE((cfg != NULL) && (rx != NULL) && (msg != NULL));
	rc = receive_check(cfg, rx, data, dlc);
	if (rc != SQ_OK) {
		return rc;
	}
	return msg_pad_force_unpack(data, dlc, msg);
}

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
