/* SPDX-License-Identifier: MIT */
#include "calib.h"

#include <stddef.h>

#include "hal.h"
#include "sq_status.h"

#define HEADER_LEN 8U
#define CRC_LEN 4U

/* One row per stored field: where it lives in calib_t, its size in the
 * block, signedness and valid range. Encode, decode and validate all walk
 * this one table, so the layout and the ranges cannot drift apart. */
typedef struct {
	uint16_t offset;
	uint8_t size;      /* 1, 2 or 4 bytes */
	uint8_t is_signed;
	int64_t min;
	int64_t max;
} calib_field_t;

#define F_U8(f, lo, hi)  { (uint16_t)offsetof(calib_t, f), 1U, 0U, (lo), (hi) }
#define F_U16(f, lo, hi) { (uint16_t)offsetof(calib_t, f), 2U, 0U, (lo), (hi) }
#define F_U32(f, lo, hi) { (uint16_t)offsetof(calib_t, f), 4U, 0U, (lo), (hi) }
#define F_I32(f, lo, hi) { (uint16_t)offsetof(calib_t, f), 4U, 1U, (lo), (hi) }

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
};

#define FIELD_COUNT (sizeof(fields) / sizeof(fields[0]))

void calib_default(calib_t *cal)
{
	HAL_REQUIRE(cal != NULL);
	/* the model's defaults in fixed-build units, whatever this build is */
	cal->mass_q16 = 1 << 16;
	cal->omega0_q12 = 5000 << 12;
	cal->damping_q30 = 24696062;   /* 0.023 * 2^30 */
	cal->mu_inf_q30 = 1 << 28;     /* 0.25 */
	cal->delta_mu_q30 = 161061274; /* 0.15 * 2^30 */
	cal->slope_q24 = 2 << 24;
	cal->criterion = (uint8_t)SQUEAL_CRITERION_EXACT;
	cal->pad_radius_um = 120000U;
	cal->wheel_radius_um = 300000U;
	cal->bitrate_kbps = 500U;
	cal->disc_speed_id = 0x110U;
	cal->pad_force_id = 0x111U;
	cal->status_id = 0x300U;
	cal->detail_id = 0x301U;
	cal->diag_id = 0x302U;
	cal->detail2_id = 0x303U;
	cal->e2e_check_inputs = 1U;
	cal->e2e_max_delta_counter = 2U;
	cal->input_period_ms = 10U;
	cal->status_period_ms = 10U;
	cal->detail_period_ms = 100U;
	cal->diag_period_ms = 1000U;
	cal->stale_cycles = 3U;
	cal->speed_max_raw = 40000U;       /* 400 rad/s: 432 km/h at r_w 0.3 m */
	cal->speed_step_max_raw = 1000U;   /* 10 rad/s in one 10 ms period    */
	cal->force_max_raw = 60000U;       /* 30 kN                           */
	cal->force_step_max_raw = 20000U;  /* 10 kN in one period             */
	cal->lowpass_alpha_q15 = 32768U;   /* filter off                      */
	cal->v0_min_umps = 10000U;         /* 0.01 m/s                        */
	cal->force_min_mn = 100000U;       /* 100 N                           */
	cal->debounce_count = 3U;
	cal->hyst_lnq_micro = 20000U;      /* 0.02 in ln Q                    */
	cal->hyst_rho_ppm = 20000U;        /* 0.02 in rho                     */
	cal->rho_warn_ppm = 500000U;       /* 0.5                             */
	cal->watchdog_ms = 100U;
	cal->input_bus = 0U;          /* one bus, in normal mode: as before */
	cal->output_bus = 0U;
	cal->input_listen_only = 0U;
}

static int64_t field_get(const calib_t *cal, const calib_field_t *f)
{
	const uint8_t *base = (const uint8_t *)cal + f->offset;

	switch (f->size) {
	case 1U:
		return *(const uint8_t *)base;
	case 2U:
		return *(const uint16_t *)(const void *)base;
	default:
		if (f->is_signed != 0U) {
			return *(const int32_t *)(const void *)base;
		}
		return *(const uint32_t *)(const void *)base;
	}
}

static void field_set(calib_t *cal, const calib_field_t *f, uint32_t raw)
{
	uint8_t *base = (uint8_t *)cal + f->offset;

	switch (f->size) {
	case 1U:
		*base = (uint8_t)raw;
		break;
	case 2U:
		*(uint16_t *)(void *)base = (uint16_t)raw;
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

static calib_error_t validate_why(const calib_t *cal)
{
	uint32_t i;

	HAL_REQUIRE(cal != NULL);
	for (i = 0U; i < FIELD_COUNT; i++) {
		const int64_t v = field_get(cal, &fields[i]);

		if ((v < fields[i].min) || (v > fields[i].max)) {
			return CALIB_ERR_RANGE;
		}
	}
	if (((int64_t)cal->mu_inf_q30 + cal->delta_mu_q30 < 0) || !ids_distinct(cal)) {
		return CALIB_ERR_RANGE;
	}
	if (!bitrate_exact(cal->bitrate_kbps)) {
		return CALIB_ERR_BITRATE;
	}
	return CALIB_OK;
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

static void put_le(uint8_t *p, uint32_t v, uint32_t size)
{
	uint32_t i;

	for (i = 0U; i < size; i++) {
		p[i] = (uint8_t)(v >> (8U * i));
	}
}

static uint32_t get_le(const uint8_t *p, uint32_t size)
{
	uint32_t v = 0U;
	uint32_t i;

	for (i = 0U; i < size; i++) {
		v |= (uint32_t)p[i] << (8U * i);
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
		const int64_t v = field_get(cal, &fields[i]);

		put_le(&buf[pos], (uint32_t)(v & 0xFFFFFFFFLL), fields[i].size);
		pos += fields[i].size;
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
			field_set(&tmp, &fields[i], get_le(&buf[pos], fields[i].size));
			pos += fields[i].size;
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

void calib_model_params(const calib_t *cal, squeal_params_t *params)
{
#if defined(SQUEAL_NUMERIC_FIXED)
	params->mass_kg = cal->mass_q16;
	params->omega0_radps = cal->omega0_q12;
	params->damping = cal->damping_q30;
	params->mu_inf = cal->mu_inf_q30;
	params->delta_mu = cal->delta_mu_q30;
	params->slope_spm = cal->slope_q24;
#else
	/* exact: every Q value is an integer times a power of two */
	params->mass_kg = (float)cal->mass_q16 * (1.0f / 65536.0f);
	params->omega0_radps = (float)cal->omega0_q12 * (1.0f / 4096.0f);
	params->damping = (float)cal->damping_q30 * (1.0f / 1073741824.0f);
	params->mu_inf = (float)cal->mu_inf_q30 * (1.0f / 1073741824.0f);
	params->delta_mu = (float)cal->delta_mu_q30 * (1.0f / 1073741824.0f);
	params->slope_spm = (float)cal->slope_q24 * (1.0f / 16777216.0f);
#endif
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
