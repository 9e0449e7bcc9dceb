/* SPDX-License-Identifier: MIT */
/*
 * Fixed-point build of squeal_sigma.h: the float build's algorithm
 * (squeal_sigma_float.c) in integers. Relative deviations and derivative
 * factors are Q32 int64; the sum of squares is taken after shifting every
 * term by one common amount so that the largest is below 2^29 (squares and
 * their sum then fit in 63 bits), and the square root is shifted back.
 */
#if defined(SQUEAL_NUMERIC_FIXED)

#include <stdbool.h>
#include <stdint.h>

#include "fixmath.h"
#include "squeal_model_internal.h"
#include "squeal_sigma.h"
#include "squeal_sigma_internal.h"

#define Q32_ONE FX_ONE_Q32
#define NORM_LIMIT ((uint64_t)1 << 29)
#define MAX_SHIFT 40

/* sd / value in Q32 for 0 <= sd <= value, value > 0: at most 2^32 */
static int64_t rel_q32(int32_t sd, int32_t value)
{
	return (int64_t)(((uint64_t)(uint32_t)sd << 32) / (uint64_t)(uint32_t)value);
}

/* a * b / 2^32 for |a| < 2^62 and |b| <= 2^32, truncated toward zero
 * (split so that no product leaves 64 bits) */
static int64_t mul_q32(int64_t a, int64_t b)
{
	const bool neg = (a < 0) != (b < 0);
	const uint64_t ua = (a < 0) ? (uint64_t)(-a) : (uint64_t)a;
	const uint64_t ub = (b < 0) ? (uint64_t)(-b) : (uint64_t)b;
	const uint64_t r = (ua >> 32) * ub + (((ua & 0xFFFFFFFFU) * ub) >> 32);

	return neg ? -(int64_t)r : (int64_t)r;
}

static uint64_t mag(int64_t x)
{
	return (x < 0) ? (uint64_t)(-x) : (uint64_t)x;
}

/* magnitude shifted right, sign kept (no right shift of a negative value) */
static int64_t shift_down(int64_t x, int32_t sh)
{
	const int64_t m = (int64_t)(mag(x) >> sh);

	return (x < 0) ? -m : m;
}

/*
 * sqrt(sum r_i^2 + e^2 - 2 rho e r_dmu) in Q32, terms Q32 (|r_i| <= 2^32,
 * |e| < 2^44), rho Q30. Returns the sigma, sets *sat when it exceeds
 * SQUEAL_Q_SIGMA's range.
 */
static int32_t combine_q32(const int64_t r[4], int64_t e, int32_t rho, int64_t r_dmu,
		       bool *sat)
{
	uint64_t biggest = mag(e);
	int64_t u[4];
	int64_t ue;
	int64_t ud;
	int64_t var;
	int64_t cross;
	uint64_t sigma_q32;
	int32_t sh = 0;
	int32_t i;

	for (i = 0; i < 4; i++) {
		if (mag(r[i]) > biggest) {
			biggest = mag(r[i]);
		}
	}
	while (((biggest >> sh) >= NORM_LIMIT) && (sh < MAX_SHIFT)) {
		sh++;
	}
	var = 0;
	for (i = 0; i < 4; i++) {
		u[i] = shift_down(r[i], sh);
		var += u[i] * u[i];
	}
	ue = shift_down(e, sh);
	ud = shift_down(r_dmu, sh);
	var += ue * ue;
	/* 2 rho ue ud: |ue ud| < 2^58, rho Q30 -> Q32 (<= 2^32) */
	cross = mul_q32(ue * ud, (int64_t)rho * 4);
	var -= 2 * cross;
	if (var < 0) {
		var = 0;
	}
	sigma_q32 = fx_isqrt_u64((uint64_t)var) << sh;
	/* Q32 -> SQUEAL_Q_SIGMA */
	sigma_q32 >>= (32 - SQUEAL_Q_SIGMA);
	if (sigma_q32 > (uint64_t)INT32_MAX) {
		*sat = true;
		return INT32_MAX;
	}
	return (int32_t)sigma_q32;
}

void squeal_sigma_borders(const squeal_params_t *p, const squeal_param_sd_t *sd,
			  const squeal_log_terms_t *t, squeal_sigma_result_t *out)
{
	int64_t r[4];
	int64_t r_a;
	bool sat = false;
	bool sat_g;

	r[0] = rel_q32(sd->mass_kg_sd, p->mass_kg);
	r[1] = rel_q32(sd->omega0_radps_sd, p->omega0_radps);
	r[2] = rel_q32(sd->damping_sd, p->damping);
	r[3] = rel_q32(sd->delta_mu_sd, p->delta_mu);
	r_a = rel_q32(sd->slope_spm_sd, p->slope_spm);
	/* a dg_H/da = s - 1;  a dg_S/da = -s H'(s) - 1 (H of the criterion) */
	out->sigma_hopf = combine_q32(r, mul_q32(t->s - Q32_ONE, r_a),
				  sd->slope_delta_mu_corr, r[3], &sat);
	out->sigma_stable = combine_q32(r, mul_q32(-mul_q32(t->s, t->stable_dh) - Q32_ONE, r_a),
				    sd->slope_delta_mu_corr, r[3], &sat);
	out->g_hopf = fx_q32_to_i32(t->c2 + t->s, SQUEAL_Q_LNQ, &sat_g);
	out->g_stable = fx_q32_to_i32(t->stable_lhs - t->stable_rhs, SQUEAL_Q_LNQ, &sat_g);
	out->flags = SQUEAL_SIGMA_HAS_BORDERS;
	if (sat) {
		out->flags |= SQUEAL_SIGMA_SAT;
	}
}

squeal_num_t squeal_sigma_distance(squeal_num_t g, squeal_num_t sigma)
{
	/* |g| Q16 << 24 / sigma Q24 = Q16; |g| < 2^31 so the shift fits */
	const uint64_t num = mag(g) << SQUEAL_Q_SIGMA;
	uint64_t d;

	if (sigma <= 0) {
		return SQUEAL_SIGMA_MARGIN_MAX;
	}
	d = num / (uint64_t)(uint32_t)sigma;
	if (d >= (uint64_t)SQUEAL_SIGMA_MARGIN_MAX) {
		return SQUEAL_SIGMA_MARGIN_MAX;
	}
	return (int32_t)d;
}

#endif /* SQUEAL_NUMERIC_FIXED */
