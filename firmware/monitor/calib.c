/* SPDX-License-Identifier: MIT */
#include "calib.h"

#include <stddef.h>

#include "hal.h"
#include "calib_map.h"
#include "e2e_p05.h"
#include "sq_status.h"
#include "squeal_msgs.h"

#define HEADER_LEN 8U
#define CRC_LEN 4U

/* One row per stored field: where it lives in calib_t, its size in the
 * block, signedness and valid range. Encode, decode and validate all walk
 * this one table, so the layout and the ranges cannot drift apart. */
typedef struct {
	uint16_t offset;
	uint8_t size;      /* 1, 2, 4 or 8 bytes */
	uint8_t is_signed;
	int64_t min;
	int64_t max;
	uint8_t count;     /* array rows: this many elements ...            */
	uint16_t stride;   /* ... this far apart (inputs[], corners[])      */
} calib_field_t;

#define F_U8(f, lo, hi)  { (uint16_t)offsetof(calib_t, f), 1U, 0U, (lo), (hi), 1U, 0U }
#define F_U16(f, lo, hi) { (uint16_t)offsetof(calib_t, f), 2U, 0U, (lo), (hi), 1U, 0U }
#define F_U32(f, lo, hi) { (uint16_t)offsetof(calib_t, f), 4U, 0U, (lo), (hi), 1U, 0U }
#define F_I32(f, lo, hi) { (uint16_t)offsetof(calib_t, f), 4U, 1U, (lo), (hi), 1U, 0U }
/* One row per field of every input / corner slot (count and stride: the
 * array; off: the field in element 0). Storage ranges admit the zeros of an
 * unused slot; calib_map.c checks what a used one means. */
#define FI(off, size, sgn, lo, hi) \
	{ (uint16_t)(off), (size), (sgn), (lo), (hi), (uint8_t)CALIB_MAX_INPUTS, \
	  (uint16_t)sizeof(calib_input_t) }
#define FC(off, size, sgn, lo, hi) \
	{ (uint16_t)(off), (size), (sgn), (lo), (hi), (uint8_t)CALIB_MAX_CORNERS, \
	  (uint16_t)sizeof(calib_corner_t) }

/* Model fields get their ranges from squeal_model_params_check() too; the
 * rows repeat the documented domain so a block is range-checked in one pass. */
static const calib_field_t fields[] = {
	F_I32(mass_q16, 1, 10000LL << 16),
	F_I32(omega0_q12, 1, 500000LL << 12),
	F_I32(damping_q30, 1, 1LL << 30),
	F_I32(mu_inf_q30, 0, 3LL << 29),
	F_I32(delta_mu_q30, -(3LL << 29), 3LL << 29),
	F_I32(slope_q24, 0, 20LL << 24),
	F_U8(criterion, 0, 1),
	F_U32(pad_radius_um, 10000, 1000000),     /* 1 cm .. 1 m */
	F_U32(wheel_radius_um, 10000, 2000000),   /* 1 cm .. 2 m */
	F_U16(bitrate_kbps, 10, 1000),
	F_U16(disc_speed_id, 0, 0x7FF),
	F_U16(pad_force_id, 0, 0x7FF),
	F_U16(status_id, 0, 0x7FF),
	F_U16(detail_id, 0, 0x7FF),
	F_U16(diag_id, 0, 0x7FF),
	F_U16(detail2_id, 0, 0x7FF),
	F_U8(e2e_check_inputs, 0, 1),
	F_U8(e2e_max_delta_counter, 1, 14),
	F_U16(input_period_ms, 1, 1000),
	F_U16(status_period_ms, 1, 1000),
	F_U16(detail_period_ms, 1, 10000),
	F_U16(diag_period_ms, 100, 10000),
	F_U8(stale_cycles, 1, 100),
	F_U16(speed_max_raw, 1, 65534),
	F_U16(speed_step_max_raw, 1, 65535),
	F_U16(force_max_raw, 1, 65534),
	F_U16(force_step_max_raw, 1, 65535),
	F_U16(lowpass_alpha_q15, 1, 32768),
	F_U32(v0_min_umps, 0, 10000000),
	F_U32(force_min_mn, 0, 100000000),
	F_U8(debounce_count, 1, 50),
	F_U32(hyst_lnq_micro, 0, 5000000),
	F_U32(hyst_rho_ppm, 0, 1000000),
	F_U32(rho_warn_ppm, 0, 1000000),
	F_U16(watchdog_ms, 10, 10000),
	F_U8(input_bus, 0, 1),
	F_U8(output_bus, 0, 1),
	F_U8(input_listen_only, 0, 1),
	F_U8(n_inputs, 0, (int64_t)CALIB_MAX_INPUTS),
	F_U8(n_corners, 0, (int64_t)CALIB_MAX_CORNERS),
	/* standard deviations: the parameters' stored ranges; sd <= |param|
	 * and |corr| <= 1 are squeal_sigma_sd_check()'s (sd_check below) */
	F_I32(sd.mass_sd_q16, 0, 10000LL << 16),
	F_I32(sd.omega0_sd_q12, 0, 500000LL << 12),
	F_I32(sd.damping_sd_q30, 0, 1LL << 30),
	F_I32(sd.mu_inf_sd_q30, 0, 3LL << 29),
	F_I32(sd.delta_mu_sd_q30, 0, 3LL << 29),
	F_I32(sd.slope_sd_q24, 0, 20LL << 24),
	F_I32(sd.slope_delta_mu_corr_q30, -(1LL << 30), 1LL << 30),
	F_I32(uncertain_k_q16, 0, 100LL << 16),  /* 0: rule off */
	FI(offsetof(calib_t, inputs[0].id), 4U, 0U, 0, 0x1FFFFFFF),
	FI(offsetof(calib_t, inputs[0].flags), 1U, 0U, 0, (int64_t)CALIB_IN_FLAGS_ALL),
	FI(offsetof(calib_t, inputs[0].min_dlc), 1U, 0U, 0, (int64_t)CAN_SIGNAL_MAX_BYTES),
	FI(offsetof(calib_t, inputs[0].fd), 1U, 0U, 0, 1),
	FI(offsetof(calib_t, inputs[0].sig.start_bit), 2U, 0U, 0, (int64_t)CAN_SIGNAL_MAX_BITS - 1),
	FI(offsetof(calib_t, inputs[0].sig.length), 1U, 0U, 0, 32),
	FI(offsetof(calib_t, inputs[0].sig.byte_order), 1U, 0U, 0, 1),
	FI(offsetof(calib_t, inputs[0].sig.is_signed), 1U, 0U, 0, 1),
	FI(offsetof(calib_t, inputs[0].factor.mant), 8U, 1U, -INPUT_DEC_MANT_MAX, INPUT_DEC_MANT_MAX),
	FI(offsetof(calib_t, inputs[0].factor.exp), 1U, 1U, INPUT_DEC_EXP_MIN, INPUT_DEC_EXP_MAX),
	FI(offsetof(calib_t, inputs[0].offset.mant), 8U, 1U, -INPUT_DEC_MANT_MAX, INPUT_DEC_MANT_MAX),
	FI(offsetof(calib_t, inputs[0].offset.exp), 1U, 1U, INPUT_DEC_EXP_MIN, INPUT_DEC_EXP_MAX),
	FI(offsetof(calib_t, inputs[0].unit), 1U, 0U, 0, 255),
	FI(offsetof(calib_t, inputs[0].mux.start_bit), 2U, 0U, 0, (int64_t)CAN_SIGNAL_MAX_BITS - 1),
	FI(offsetof(calib_t, inputs[0].mux.length), 1U, 0U, 0, 32),
	FI(offsetof(calib_t, inputs[0].mux.byte_order), 1U, 0U, 0, 1),
	FI(offsetof(calib_t, inputs[0].mux.is_signed), 1U, 0U, 0, 1),
	FI(offsetof(calib_t, inputs[0].mux_value), 4U, 0U, 0, (int64_t)UINT32_MAX),
	FI(offsetof(calib_t, inputs[0].mux_value_max), 4U, 0U, 0, (int64_t)UINT32_MAX),
	FI(offsetof(calib_t, inputs[0].mux2.start_bit), 2U, 0U, 0, (int64_t)CAN_SIGNAL_MAX_BITS - 1),
	FI(offsetof(calib_t, inputs[0].mux2.length), 1U, 0U, 0, 32),
	FI(offsetof(calib_t, inputs[0].mux2.byte_order), 1U, 0U, 0, 1),
	FI(offsetof(calib_t, inputs[0].mux2.is_signed), 1U, 0U, 0, 1),
	FI(offsetof(calib_t, inputs[0].mux2_value), 4U, 0U, 0, (int64_t)UINT32_MAX),
	FI(offsetof(calib_t, inputs[0].mux2_value_max), 4U, 0U, 0, (int64_t)UINT32_MAX),
	FI(offsetof(calib_t, inputs[0].na_raw), 4U, 0U, 0, (int64_t)UINT32_MAX),
	FI(offsetof(calib_t, inputs[0].na_raw2), 4U, 0U, 0, (int64_t)UINT32_MAX),
	FI(offsetof(calib_t, inputs[0].qualifier_bit), 2U, 0U, 0, (int64_t)CAN_SIGNAL_MAX_BITS - 1),
	FI(offsetof(calib_t, inputs[0].qualifier_invalid), 1U, 0U, 0, 1),
	FI(offsetof(calib_t, inputs[0].protection), 1U, 0U, 0, (int64_t)CALIB_PROT_COUNT - 1),
	FI(offsetof(calib_t, inputs[0].data_id), 2U, 0U, 0, 0xFFFF),
	FI(offsetof(calib_t, inputs[0].data_id_list[0]), 1U, 0U, 0, 255),
	FI(offsetof(calib_t, inputs[0].data_id_list[1]), 1U, 0U, 0, 255),
	FI(offsetof(calib_t, inputs[0].data_id_list[2]), 1U, 0U, 0, 255),
	FI(offsetof(calib_t, inputs[0].data_id_list[3]), 1U, 0U, 0, 255),
	FI(offsetof(calib_t, inputs[0].data_id_list[4]), 1U, 0U, 0, 255),
	FI(offsetof(calib_t, inputs[0].data_id_list[5]), 1U, 0U, 0, 255),
	FI(offsetof(calib_t, inputs[0].data_id_list[6]), 1U, 0U, 0, 255),
	FI(offsetof(calib_t, inputs[0].data_id_list[7]), 1U, 0U, 0, 255),
	FI(offsetof(calib_t, inputs[0].data_id_list[8]), 1U, 0U, 0, 255),
	FI(offsetof(calib_t, inputs[0].data_id_list[9]), 1U, 0U, 0, 255),
	FI(offsetof(calib_t, inputs[0].data_id_list[10]), 1U, 0U, 0, 255),
	FI(offsetof(calib_t, inputs[0].data_id_list[11]), 1U, 0U, 0, 255),
	FI(offsetof(calib_t, inputs[0].data_id_list[12]), 1U, 0U, 0, 255),
	FI(offsetof(calib_t, inputs[0].data_id_list[13]), 1U, 0U, 0, 255),
	FI(offsetof(calib_t, inputs[0].data_id_list[14]), 1U, 0U, 0, 255),
	FI(offsetof(calib_t, inputs[0].data_id_list[15]), 1U, 0U, 0, 255),
	FI(offsetof(calib_t, inputs[0].counter.start_bit), 2U, 0U, 0, (int64_t)CAN_SIGNAL_MAX_BITS - 1),
	FI(offsetof(calib_t, inputs[0].counter.length), 1U, 0U, 0, 32),
	FI(offsetof(calib_t, inputs[0].counter.byte_order), 1U, 0U, 0, 1),
	FI(offsetof(calib_t, inputs[0].counter.is_signed), 1U, 0U, 0, 1),
	FI(offsetof(calib_t, inputs[0].counter_modulus), 1U, 0U, 0, 16),
	FI(offsetof(calib_t, inputs[0].max_delta_counter), 1U, 0U, 0, 255),
	FI(offsetof(calib_t, inputs[0].e2e_offset_byte), 1U, 0U, 0,
	   (int64_t)CAN_SIGNAL_MAX_BYTES - (int64_t)E2E_P05_HEADER_LEN),
	FI(offsetof(calib_t, inputs[0].period_ms), 2U, 0U, 0, 1000),
	FI(offsetof(calib_t, inputs[0].stale_cycles), 1U, 0U, 0, 100),
	FI(offsetof(calib_t, inputs[0].max.mant), 8U, 1U, -INPUT_DEC_MANT_MAX, INPUT_DEC_MANT_MAX),
	FI(offsetof(calib_t, inputs[0].max.exp), 1U, 1U, INPUT_DEC_EXP_MIN, INPUT_DEC_EXP_MAX),
	FI(offsetof(calib_t, inputs[0].min.mant), 8U, 1U, -INPUT_DEC_MANT_MAX, INPUT_DEC_MANT_MAX),
	FI(offsetof(calib_t, inputs[0].min.exp), 1U, 1U, INPUT_DEC_EXP_MIN, INPUT_DEC_EXP_MAX),
	FI(offsetof(calib_t, inputs[0].step_max.mant), 8U, 1U, -INPUT_DEC_MANT_MAX, INPUT_DEC_MANT_MAX),
	FI(offsetof(calib_t, inputs[0].step_max.exp), 1U, 1U, INPUT_DEC_EXP_MIN, INPUT_DEC_EXP_MAX),
	FC(offsetof(calib_t, corners[0].pos), 1U, 0U, 0, 3),
	FC(offsetof(calib_t, corners[0].speed_input), 1U, 0U, 0, (int64_t)CALIB_MAX_INPUTS - 1),
	FC(offsetof(calib_t, corners[0].force_input), 1U, 0U, 0, (int64_t)CALIB_MAX_INPUTS - 1),
	FC(offsetof(calib_t, corners[0].friction_faces), 1U, 0U, 0, 4),
	FC(offsetof(calib_t, corners[0].piston_area_cmm2), 4U, 0U, 0, 100000000),   /* up to 1 m^2 */
	FC(offsetof(calib_t, corners[0].efficiency_ppm), 4U, 0U, 0, 1000000),
	FC(offsetof(calib_t, corners[0].axle_factor_ppm), 4U, 0U, 0, 4000000),
	FC(offsetof(calib_t, corners[0].torque_share_ppm), 4U, 0U, 0, 1000000),
	FC(offsetof(calib_t, corners[0].mass_q16), 4U, 1U, 0, 10000LL << 16),
	FC(offsetof(calib_t, corners[0].omega0_q12), 4U, 1U, 0, 500000LL << 12),
	FC(offsetof(calib_t, corners[0].damping_q30), 4U, 1U, 0, 1LL << 30),
	FC(offsetof(calib_t, corners[0].mu_inf_q30), 4U, 1U, 0, 3LL << 29),
	FC(offsetof(calib_t, corners[0].delta_mu_q30), 4U, 1U, -(3LL << 29), 3LL << 29),
	FC(offsetof(calib_t, corners[0].slope_q24), 4U, 1U, 0, 20LL << 24),
	FC(offsetof(calib_t, corners[0].criterion), 1U, 0U, 0, 1),
	FC(offsetof(calib_t, corners[0].pad_radius_um), 4U, 0U, 0, 1000000),
	FC(offsetof(calib_t, corners[0].wheel_radius_um), 4U, 0U, 0, 2000000),
	FC(offsetof(calib_t, corners[0].status_id), 2U, 0U, 0, 0x7FF),
	FC(offsetof(calib_t, corners[0].detail_id), 2U, 0U, 0, 0x7FF),
	FC(offsetof(calib_t, corners[0].detail2_id), 2U, 0U, 0, 0x7FF),
	FC(offsetof(calib_t, corners[0].diag_id), 2U, 0U, 0, 0x7FF),
	FC(offsetof(calib_t, corners[0].sd.mass_sd_q16), 4U, 1U, 0, 10000LL << 16),
	FC(offsetof(calib_t, corners[0].sd.omega0_sd_q12), 4U, 1U, 0, 500000LL << 12),
	FC(offsetof(calib_t, corners[0].sd.damping_sd_q30), 4U, 1U, 0, 1LL << 30),
	FC(offsetof(calib_t, corners[0].sd.mu_inf_sd_q30), 4U, 1U, 0, 3LL << 29),
	FC(offsetof(calib_t, corners[0].sd.delta_mu_sd_q30), 4U, 1U, 0, 3LL << 29),
	FC(offsetof(calib_t, corners[0].sd.slope_sd_q24), 4U, 1U, 0, 20LL << 24),
	FC(offsetof(calib_t, corners[0].sd.slope_delta_mu_corr_q30), 4U, 1U,
	   -(1LL << 30), 1LL << 30),
};

#define FIELD_COUNT (sizeof(fields) / sizeof(fields[0]))

/* The factory defaults (docs/model.md section 8, the DBC's IDs and periods); no
 * input map (n_corners 0: the legacy DiscSpeed/PadForce corner). A const
 * object, so that a monitor running on defaults needs no copy of its own. */
static const calib_t factory = {
	.mass_q16 = 1 << 16,
	.omega0_q12 = 5000 << 12,
	.damping_q30 = 24696062,   /* 0.023 * 2^30 */
	.mu_inf_q30 = 1 << 28,     /* 0.25 */
	.delta_mu_q30 = 161061274, /* 0.15 * 2^30 */
	.slope_q24 = 2 << 24,
	.criterion = (uint8_t)SQUEAL_CRITERION_EXACT,
	.pad_radius_um = 120000U,
	.wheel_radius_um = 300000U,
	.bitrate_kbps = 500U,
	/* the identifiers of squeal.dbc (squeal_msgs.h, checked against the
	 * DBC by tests/firmware/protocol): written once, there */
	.disc_speed_id = (uint16_t)MSG_DISC_SPEED_ID,
	.pad_force_id = (uint16_t)MSG_PAD_FORCE_ID,
	.status_id = (uint16_t)MSG_SQUEAL_STATUS_ID,
	.detail_id = (uint16_t)MSG_SQUEAL_DETAIL_ID,
	.diag_id = (uint16_t)MSG_SQUEAL_DIAG_ID,
	.detail2_id = (uint16_t)MSG_SQUEAL_DETAIL2_ID,
	.e2e_check_inputs = 1U,
	.e2e_max_delta_counter = 2U,
	.input_period_ms = 10U,
	.status_period_ms = 10U,
	.detail_period_ms = 100U,
	.diag_period_ms = 1000U,
	.stale_cycles = 3U,
	.speed_max_raw = 40000U,       /* 400 rad/s: 432 km/h at r_w 0.3 m */
	.speed_step_max_raw = 1000U,   /* 10 rad/s in one 10 ms period    */
	.force_max_raw = 60000U,       /* 30 kN                           */
	.force_step_max_raw = 20000U,  /* 10 kN in one period             */
	.lowpass_alpha_q15 = 32768U,   /* filter off                      */
	.v0_min_umps = 10000U,         /* 0.01 m/s                        */
	.force_min_mn = 100000U,       /* 100 N                           */
	.debounce_count = 3U,
	.hyst_lnq_micro = 20000U,      /* 0.02 in ln Q                    */
	.hyst_rho_ppm = 20000U,        /* 0.02 in rho                     */
	.rho_warn_ppm = 500000U,       /* 0.5                             */
	.watchdog_ms = 100U,
	.input_bus = 0U,               /* one bus, in normal mode: as before */
	.output_bus = 0U,
	.input_listen_only = 0U,
	.n_inputs = 0U,
	.n_corners = 0U,
	.sd = { 0 },                   /* no uncertainty: crisp classes   */
	.uncertain_k_q16 = 2 << 16,    /* k = 2 sigma                     */
};

void calib_default(calib_t *cal)
{
	HAL_REQUIRE(cal != NULL);
	*cal = factory;
}

const calib_t *calib_factory(void)
{
	return &factory;
}

static int64_t field_get(const calib_t *cal, const calib_field_t *f, uint32_t k)
{
	const uint8_t *base = (const uint8_t *)cal + f->offset + (k * f->stride);

	switch (f->size) {
	case 1U:
		if (f->is_signed != 0U) {
			return *(const int8_t *)(const void *)base;
		}
		return *(const uint8_t *)base;
	case 2U:
		return *(const uint16_t *)(const void *)base;
	case 8U:
		return *(const int64_t *)(const void *)base;
	default:
		if (f->is_signed != 0U) {
			return *(const int32_t *)(const void *)base;
		}
		return *(const uint32_t *)(const void *)base;
	}
}

static void field_set(calib_t *cal, const calib_field_t *f, uint32_t k, uint64_t raw64)
{
	const uint32_t raw = (uint32_t)raw64;
	uint8_t *base = (uint8_t *)cal + f->offset + (k * f->stride);

	switch (f->size) {
	case 1U:
		if (f->is_signed != 0U) {
			*(int8_t *)(void *)base = (raw <= 0x7FU) ? (int8_t)raw :
				(int8_t)(-(int32_t)((~raw) & 0xFFU) - 1);
		} else {
			*base = (uint8_t)raw;
		}
		break;
	case 2U:
		*(uint16_t *)(void *)base = (uint16_t)raw;
		break;
	case 8U:
		/* two's complement bits -> int64 without implementation-
		 * defined conversion */
		{
			const uint64_t inv = ~raw64;

			*(int64_t *)(void *)base = (raw64 <= (uint64_t)INT64_MAX) ?
				(int64_t)raw64 : (-(int64_t)inv - 1);
		}
		break;
	default:
		if (f->is_signed != 0U) {
			/* two's complement bits -> int32 without implementation-
			 * defined conversion */
			*(int32_t *)(void *)base = (raw <= 0x7FFFFFFFUL) ?
				(int32_t)raw : -(int32_t)(~raw) - 1;
		} else {
			*(uint32_t *)(void *)base = raw;
		}
		break;
	}
}

static bool ids_distinct(const calib_t *cal)
{
	const uint16_t ids[6] = { cal->disc_speed_id, cal->pad_force_id,
				  cal->status_id, cal->detail_id,
				  cal->diag_id, cal->detail2_id };
	uint32_t i;
	uint32_t j;

	for (i = 0U; i < 6U; i++) {
		for (j = i + 1U; j < 6U; j++) {
			if (ids[i] == ids[j]) {
				return false;
			}
		}
	}
	return true;
}

/* The CiA 301 bit rates, which the bxCAN times exactly on every clock the
 * ECU runs (APB1 42 MHz F4, 36 MHz F103, HSI fallback 16 / 8 MHz); others
 * in range (800 kbit/s: 52.5 clocks per bit at 42 MHz) would be refused by
 * hal_can_set_bitrate() at run time, so they are refused here first. */
static bool bitrate_exact(uint16_t kbps)
{
	static const uint16_t exact[] = { 10U, 20U, 50U, 100U, 125U, 250U, 500U, 1000U };
	uint32_t i;

	for (i = 0U; i < (sizeof(exact) / sizeof(exact[0])); i++) {
		if (exact[i] == kbps) {
			return true;
		}
	}
	return false;
}

/* Each brake's deviations in squeal_sigma's domain for its parameters
 * (0 <= sd <= |param|, mu_inf's sd <= 1.5, |corr| <= 1): the flat keys and
 * every corner slot (unused slots are zeros, which pass). */
static bool sds_valid(const calib_t *cal);

static bool sd_valid(const calib_corner_t *c)
{
	squeal_params_t p;
	squeal_param_sd_t sd;

	calib_corner_params(c, &p);
	calib_corner_sd(c, &sd);
	return squeal_sigma_sd_check(&p, &sd) == SQ_OK;
}

int calib_sd_validate(const calib_t *cal)
{
	HAL_REQUIRE(cal != NULL);
	return sds_valid(cal) ? SQ_OK : SQ_EINVAL;
}

static bool sds_valid(const calib_t *cal)
{
	calib_corner_t flat;
	bool ok;
	uint32_t k;

	flat = (calib_corner_t){ 0 };
	calib_corner_from_flat(cal, &flat);
	ok = sd_valid(&flat);
	for (k = 0U; ok && (k < CALIB_MAX_CORNERS); k++) {
		ok = sd_valid(&cal->corners[k]);
	}
	return ok;
}

static calib_error_t validate_why(const calib_t *cal)
{
	uint32_t i;

	HAL_REQUIRE(cal != NULL);
	for (i = 0U; i < FIELD_COUNT; i++) {
		uint32_t k;

		for (k = 0U; k < fields[i].count; k++) {
			const int64_t v = field_get(cal, &fields[i], k);

			if ((v < fields[i].min) || (v > fields[i].max)) {
				return CALIB_ERR_RANGE;
			}
		}
	}
	if (((int64_t)cal->mu_inf_q30 + cal->delta_mu_q30 < 0) || !ids_distinct(cal) ||
	    !sds_valid(cal)) {
		return CALIB_ERR_RANGE;
	}
	if (!bitrate_exact(cal->bitrate_kbps)) {
		return CALIB_ERR_BITRATE;
	}
	if (calib_map_validate(cal) != SQ_OK) {
		return CALIB_ERR_RANGE;
	}
	return CALIB_OK;
}

calib_error_t calib_check(const calib_t *cal)
{
	HAL_REQUIRE(cal != NULL);
	return validate_why(cal);
}

int calib_validate(const calib_t *cal)
{
	HAL_REQUIRE(cal != NULL);
	return (validate_why(cal) == CALIB_OK) ? SQ_OK : SQ_EINVAL;
}

int calib_field_range(uint32_t offset, int64_t *min, int64_t *max)
{
	uint32_t i;

	HAL_REQUIRE((min != NULL) && (max != NULL));
	for (i = 0U; i < FIELD_COUNT; i++) {
		if (fields[i].offset == offset) {
			*min = fields[i].min;
			*max = fields[i].max;
			return SQ_OK;
		}
	}
	return SQ_ENOENT;
}

static void put_le(uint8_t *p, uint64_t v, uint32_t size)
{
	uint32_t i;

	for (i = 0U; i < size; i++) {
		const uint32_t sh = 8U * i;

		p[i] = (uint8_t)(v >> sh);
	}
}

static uint64_t get_le(const uint8_t *p, uint32_t size)
{
	uint64_t v = 0U;
	uint32_t i;

	for (i = 0U; i < size; i++) {
		const uint32_t sh = 8U * i;

		v |= (uint64_t)p[i] << sh;
	}
	return v;
}

int calib_encode(const calib_t *cal, uint8_t *buf, uint32_t buf_len)
{
	uint32_t pos = HEADER_LEN;
	uint32_t i;

	HAL_REQUIRE((cal != NULL) && (buf != NULL) && (buf_len >= CALIB_BLOCK_LEN));
	if (calib_validate(cal) != SQ_OK) {
		return SQ_EINVAL; /* out-of-range values: the data's fault */
	}
	put_le(&buf[0], (uint32_t)CALIB_MAGIC, 4U);
	put_le(&buf[4], CALIB_VERSION, 2U);
	put_le(&buf[6], CALIB_BLOCK_LEN, 2U);
	for (i = 0U; i < FIELD_COUNT; i++) {
		uint32_t k;

		for (k = 0U; k < fields[i].count; k++) {
			const int64_t v = field_get(cal, &fields[i], k);

			/* the low `size` bytes of the two's complement value */
			put_le(&buf[pos], (uint64_t)v, fields[i].size);
			pos += fields[i].size;
		}
	}
	if (pos != CALIB_BLOCK_LEN - CRC_LEN) {
		return SQ_EINVAL; /* layout and CALIB_BLOCK_LEN disagree */
	}
	put_le(&buf[pos], calib_crc32(0U, buf, pos), 4U);
	return SQ_OK;
}

int calib_decode(const uint8_t *buf, uint32_t len, calib_t *cal,
		 calib_error_t *reason)
{
	calib_error_t err = CALIB_OK;
	calib_t tmp;
	uint32_t pos = HEADER_LEN;
	uint32_t i;

	HAL_REQUIRE((buf != NULL) && (cal != NULL));
	calib_default(&tmp); /* every byte of tmp defined before use */
	if (len < CALIB_BLOCK_LEN) {
		err = CALIB_ERR_LENGTH;
	} else if (get_le(&buf[0], 4U) != (uint32_t)CALIB_MAGIC) {
		err = CALIB_ERR_MAGIC;
	} else if (get_le(&buf[4], 2U) != CALIB_VERSION) {
		err = CALIB_ERR_VERSION;
	} else if (get_le(&buf[6], 2U) != CALIB_BLOCK_LEN) {
		err = CALIB_ERR_LENGTH;
	} else if (get_le(&buf[CALIB_BLOCK_LEN - CRC_LEN], 4U) !=
		   calib_crc32(0U, buf, CALIB_BLOCK_LEN - CRC_LEN)) {
		err = CALIB_ERR_CRC;
	} else {
		for (i = 0U; i < FIELD_COUNT; i++) {
			uint32_t k;

			for (k = 0U; k < fields[i].count; k++) {
				field_set(&tmp, &fields[i], k, get_le(&buf[pos], fields[i].size));
				pos += fields[i].size;
			}
		}
		err = validate_why(&tmp);
	}
	if (reason != NULL) {
		*reason = err;
	}
	if (err != CALIB_OK) {
		return SQ_EBADMSG;
	}
	*cal = tmp;
	return SQ_OK;
}

void calib_corner_params(const calib_corner_t *c, squeal_params_t *params)
{
#if defined(SQUEAL_NUMERIC_FIXED)
	params->mass_kg = c->mass_q16;
	params->omega0_radps = c->omega0_q12;
	params->damping = c->damping_q30;
	params->mu_inf = c->mu_inf_q30;
	params->delta_mu = c->delta_mu_q30;
	params->slope_spm = c->slope_q24;
#else
	/* exact: every Q value is an integer times a power of two */
	params->mass_kg = (float)c->mass_q16 * (1.0f / 65536.0f);
	params->omega0_radps = (float)c->omega0_q12 * (1.0f / 4096.0f);
	params->damping = (float)c->damping_q30 * (1.0f / 1073741824.0f);
	params->mu_inf = (float)c->mu_inf_q30 * (1.0f / 1073741824.0f);
	params->delta_mu = (float)c->delta_mu_q30 * (1.0f / 1073741824.0f);
	params->slope_spm = (float)c->slope_q24 * (1.0f / 16777216.0f);
#endif
}

void calib_corner_sd(const calib_corner_t *c, squeal_param_sd_t *sd)
{
	HAL_REQUIRE((c != NULL) && (sd != NULL));
#if defined(SQUEAL_NUMERIC_FIXED)
	sd->mass_kg_sd = c->sd.mass_sd_q16;
	sd->omega0_radps_sd = c->sd.omega0_sd_q12;
	sd->damping_sd = c->sd.damping_sd_q30;
	sd->mu_inf_sd = c->sd.mu_inf_sd_q30;
	sd->delta_mu_sd = c->sd.delta_mu_sd_q30;
	sd->slope_spm_sd = c->sd.slope_sd_q24;
	sd->slope_delta_mu_corr = c->sd.slope_delta_mu_corr_q30; /* Q30 = SQUEAL_Q_CORR */
#else
	sd->mass_kg_sd = (float)c->sd.mass_sd_q16 * (1.0f / 65536.0f);
	sd->omega0_radps_sd = (float)c->sd.omega0_sd_q12 * (1.0f / 4096.0f);
	sd->damping_sd = (float)c->sd.damping_sd_q30 * (1.0f / 1073741824.0f);
	sd->mu_inf_sd = (float)c->sd.mu_inf_sd_q30 * (1.0f / 1073741824.0f);
	sd->delta_mu_sd = (float)c->sd.delta_mu_sd_q30 * (1.0f / 1073741824.0f);
	sd->slope_spm_sd = (float)c->sd.slope_sd_q24 * (1.0f / 16777216.0f);
	sd->slope_delta_mu_corr = (float)c->sd.slope_delta_mu_corr_q30 *
				  (1.0f / 1073741824.0f);
#endif
}

squeal_num_t calib_uncertain_k(const calib_t *cal)
{
	HAL_REQUIRE(cal != NULL);
#if defined(SQUEAL_NUMERIC_FIXED)
	return cal->uncertain_k_q16; /* Q16 = SQUEAL_Q_MARGIN */
#else
	return (float)cal->uncertain_k_q16 * (1.0f / 65536.0f);
#endif
}

void calib_model_params(const calib_t *cal, squeal_params_t *params)
{
	calib_corner_t c;

	calib_corner_defaults(cal, 0U, &c);
	calib_corner_params(&c, params);
}

uint32_t calib_crc32(uint32_t crc, const uint8_t *data, uint32_t len)
{
	uint32_t i;
	uint32_t b;

	crc = ~crc;
	for (i = 0U; i < len; i++) {
		crc ^= data[i];
		for (b = 0U; b < 8U; b++) {
			crc = (crc >> 1) ^ (0xEDB88320U & (0U - (crc & 1U)));
		}
	}
	return ~crc;
}

const char *calib_error_name(calib_error_t err)
{
	switch (err) {
	case CALIB_OK:
		return "ok";
	case CALIB_ERR_LENGTH:
		return "wrong length";
	case CALIB_ERR_MAGIC:
		return "bad magic";
	case CALIB_ERR_VERSION:
		return "unsupported version";
	case CALIB_ERR_CRC:
		return "CRC mismatch";
	case CALIB_ERR_RANGE:
		return "field out of range";
	case CALIB_ERR_BITRATE:
		return "bit rate not timed exactly by the CAN clock (10, 20, 50, 100, 125, 250, 500, 1000 kbit/s)";
	default:
		return "?";
	}
}
