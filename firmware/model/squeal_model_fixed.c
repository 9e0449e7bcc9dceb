/* SPDX-License-Identifier: MIT */
/*
 * Fixed-point build of the squeal model: the same algorithm as
 * squeal_model_float.c (read its header comment first), in integers only.
 *
 * Internal formats: every logarithm and every log-domain quantity (c2, s,
 * lq2, the cycle x) is an int64 Q32 (range +-2^31, resolution 2.3e-10);
 * G/H near zero come from the Q28 table in bessel_table.c with cubic Hermite
 * interpolation, above s = 32 from the asymptotic expansion. Results are
 * rounded into the header's per-field Q-formats, saturating with a SAT flag.
 * Error budget (dominant terms): ln to ~1e-9, table interpolation ~4e-8 in H,
 * exp to ~1e-8 relative; the outputs' own resolution (2^-Q) dominates.
 */
#if defined(SQUEAL_NUMERIC_FIXED)

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "bessel_table.h"
#include "fixmath.h"
#include "squeal_model.h"
#include "squeal_model_internal.h"

#include "sq_contract.h"

#define Q32_ONE FX_ONE_Q32
#define LN8_Q32 ((int64_t)8931133415)        /* ln 8 * 2^32 */
#define LN_1E6_Q32 ((int64_t)59337166024)    /* ln 1e6 * 2^32 */
#define HALF_LN_2_OVER_PI_Q32 ((int64_t)-969766475) /* 0.5 ln(2/pi) * 2^32 */
#define TABLE_S_MAX_Q32 ((int64_t)SQ_BESSEL_S_MAX << 32)
#define CELL_SHIFT (32 - SQ_BESSEL_STEP_LOG2)   /* Q32 -> table index */
#define Q28_ONE ((int64_t)1 << 28)
#define SOLVE_MAX_ITER 64

/* ln of a positive Q-format field, Q32 */
static int64_t ln_field(int32_t raw, int32_t q)
{
	return fx_ln_u64((uint64_t)(uint32_t)raw, q);
}

/* (a * b) >> 28 for Q28 operands (|products| < 2^62 by the callers' ranges);
 * the division rounds toward zero, so no right shift of a negative value. */
static int64_t mul_q28(int64_t a, int64_t b)
{
	return (a * b) / Q28_ONE;
}

/*
 * H(s) = G(s) - s and H'(s), both Q32, for s >= 0 in Q32.
 * Table part: cubic Hermite between nodes k/16 with t the position in the
 * cell. Asymptotic part (s > 32): H = 0.5 ln(2/pi) - 1.5 ln s + ln P(s) with
 * P as in the float build, ln P = -(y + y^2/2 + y^3/3 + y^4/4), y = 1 - P
 * <= 0.012 (omitted term < 5e-11); H' ~ -1.5/s + 3/(8 s^2) is only used to
 * steer Newton's method, so its truncation costs nothing in accuracy.
 */
void squeal_model_bessel_h(int64_t s_q32, int64_t *h_q32, int64_t *dh_q32)
{
	if (s_q32 < TABLE_S_MAX_Q32) {
		const int64_t k = s_q32 >> CELL_SHIFT;
		const int64_t t = (s_q32 - (k << CELL_SHIFT)) >> (CELL_SHIFT - 28);
		const int64_t t2 = mul_q28(t, t);
		const int64_t t3 = mul_q28(t2, t);
		const int64_t h0 = sq_bessel_h_q28[k];
		const int64_t h1 = sq_bessel_h_q28[k + 1];
		/* node derivatives times the cell width 1/16 */
		const int64_t d0 = sq_bessel_dh_q28[k] / 16;
		const int64_t d1 = sq_bessel_dh_q28[k + 1] / 16;
		const int64_t b00 = 2 * t3 - 3 * t2 + Q28_ONE;
		const int64_t b10 = t3 - 2 * t2 + t;
		const int64_t b01 = 3 * t2 - 2 * t3;
		const int64_t b11 = t3 - t2;
		/* derivatives of the basis (per unit t) */
		const int64_t e01 = 6 * t - 6 * t2; /* = -(d/dt) b00 */
		const int64_t e10 = 3 * t2 - 4 * t + Q28_ONE;
		const int64_t e11 = 3 * t2 - 2 * t;
		int64_t h;
		int64_t dh_dt;

		h = mul_q28(b00, h0) + mul_q28(b10, d0) + mul_q28(b01, h1) +
		    mul_q28(b11, d1);
		dh_dt = mul_q28(e01, h1 - h0) + mul_q28(e10, d0) + mul_q28(e11, d1);
		*h_q32 = h * 16;        /* Q28 -> Q32 */
		*dh_q32 = dh_dt * 256;  /* per unit s = 16 per unit t; Q28 -> Q32 */
	} else {
		/* r = 1/s in Q32; s >= 32 so r <= 2^27 */
		const int64_t r = (int64_t)(((uint64_t)1 << 63) / ((uint64_t)s_q32 >> 1));
		int64_t y;
		int64_t y2;
		int64_t lnp;

		y = (int64_t)1192181760 * r >> 32;                     /* 1091475/3932160 */
		y = (((int64_t)619315200 + y) * r) >> 32;           /* 14175/98304 */
		y = (((int64_t)440401920 + y) * r) >> 32;           /* 315/3072 */
		y = (((int64_t)503316480 + y) * r) >> 32;           /* 15/128 */
		y = (((int64_t)1610612736 + y) * r) >> 32;          /* 3/8 */
		y2 = (y * y) >> 32;
		lnp = -(y + y2 / 2 + ((y2 * y) >> 32) / 3 + ((y2 * y2) >> 32) / 4);
		*h_q32 = HALF_LN_2_OVER_PI_Q32 -
			 3 * (fx_ln_u64((uint64_t)s_q32, 32) / 2) + lnp;
		*dh_q32 = -3 * (r / 2) + ((3 * ((r * r) >> 32)) / 8);
	}
}

/*
 * Solve G(x) = H(x) + x = lq2 for x (Q32), lq2 > 0: Newton inside a bracket
 * [lo, hi] that always holds the root, bisecting when a step would leave it
 * or when the quotient would not fit. At most SOLVE_MAX_ITER steps.
 */
static int64_t solve_exact_cycle(int64_t lq2)
{
	int64_t lo = 0;
	int64_t hi = 2 * lq2 + 16 * Q32_ONE;
	int64_t x;
	int32_t i;

	if (lq2 < 2 * Q32_ONE) {
		/* G ~ x^2 / 8: x0 = sqrt(8 lq2) */
		x = (int64_t)(fx_isqrt_u64((uint64_t)(8 * lq2)) << 16);
	} else {
		x = lq2 + 3 * (fx_ln_u64((uint64_t)lq2, 32) / 2) + Q32_ONE / 4;
	}
	if ((x <= lo) || (x >= hi)) {
		x = lo + (hi - lo) / 2;
	}
	for (i = 0; i < SOLVE_MAX_ITER; i++) {
		int64_t h;
		int64_t dh;
		int64_t f;
		int64_t dg;
		int64_t next;

		squeal_model_bessel_h(x, &h, &dh);
		f = h + x - lq2;
		dg = dh + Q32_ONE;
		if (f == 0) {
			break;
		}
		if (f < 0) {
			lo = x;
		} else {
			hi = x;
		}
		if ((f > -(Q32_ONE / 4)) && (f < Q32_ONE / 4) && (dg > ((int64_t)1 << 16))) {
			next = x - (f * Q32_ONE) / dg;
		} else {
			next = lo;
		}
		if ((next <= lo) || (next >= hi)) {
			next = lo + (hi - lo) / 2;
		}
		if (((next - x) <= 4) && ((x - next) <= 4)) {
			x = next;
			break;
		}
		if (hi - lo <= 4) {
			break;
		}
		x = next;
	}
	return x;
}

/* ln x of the selected criterion's cycle (Q32) and x itself (Q32, clamped). */
static int64_t cycle_ln_x(int64_t lq2, squeal_criterion_t criterion,
			  int64_t *x_q32)
{
	bool sat;

	if (criterion != SQUEAL_CRITERION_CUBIC) {
		*x_q32 = solve_exact_cycle(lq2);
		return fx_ln_u64((uint64_t)*x_q32, 32);
	}
	if (lq2 < Q32_ONE) {
		/* x3 = sqrt(8 (e^lq2 - 1)), with e^lq2 - 1 in Q30 (no
		 * cancellation near the Hopf border) */
		const uint64_t em1 = fx_expm1_small_q30(lq2);
		const uint64_t x_q30 = fx_isqrt_u64((8U * em1) << 30);

		*x_q32 = (int64_t)(x_q30 << 2);
		return fx_ln_u64(x_q30, 30);
	} else {
		/* ln x3 = (ln 8 + lq2 + ln(1 - e^-lq2)) / 2 */
		const int32_t em = fx_exp_q32_to_i32(-lq2, 30, &sat);
		const int64_t ln_1m = fx_ln_u64((uint64_t)((1U << 30) - (uint32_t)em), 30);
		const int64_t ln_x = (LN8_Q32 + lq2 + ln_1m) / 2;

		*x_q32 = fx_exp_q32_to_i64(ln_x, 32, &sat);
		return ln_x;
	}
}

/* c2, s and the logarithms kept; has_border false (the stable_* fields
 * are set only with it). */
static void log_terms_fixed(const squeal_params_t *p, const squeal_point_t *point,
			    squeal_log_terms_t *t)
{
	t->ln_a = ln_field(p->slope_spm, SQUEAL_Q_SLOPE);
	t->ln_w0 = ln_field(p->omega0_radps, SQUEAL_Q_OMEGA0);
	t->ln_force = ln_field(point->force_n, SQUEAL_Q_FORCE);
	t->c2 = FX_LN2_Q32 + ln_field(p->damping, SQUEAL_Q_DAMPING) + t->ln_w0 +
		ln_field(p->mass_kg, SQUEAL_Q_MASS) - t->ln_a - t->ln_force -
		ln_field(p->delta_mu, SQUEAL_Q_MU);
	/* s = a v0: Q24 * Q20 = Q44 -> Q32; < 2000 * 2^32 by the domain */
	t->s = ((int64_t)p->slope_spm * point->v0_mps) >> 12;
	t->has_border = false; /* the stable border: squeal_model_stable_border */
}

/* The stable border of the criterion into t (one source for the
 * classification, which inlines it, and squeal_model_stable_border). */
static inline void stable_border_fixed(squeal_log_terms_t *t, squeal_criterion_t criterion)
{
	int64_t rhs;
	int64_t dh;

	if (criterion == SQUEAL_CRITERION_CUBIC) {
		/* ln 2Q >= ln(1 + s^2/8); s in Q16 keeps s^2 in 64 bits */
		const uint64_t s16 = (uint64_t)t->s >> 16;
		const uint64_t u = ((s16 * s16) >> 3) + ((uint64_t)1 << 32);
		/* (s/4) / (1 + s^2/8) in Q32: s/4 < 2^41 shifted up by 21, the
		 * Q32 divisor (>= 2^32) down by 11 */
		const uint64_t q = (((uint64_t)t->s >> 2) << 21) / (u >> 11);
		const uint64_t one_minus_q = ((uint64_t)1 << 32) - q; /* q < 2^32 */

		rhs = fx_ln_u64(u, 32);
		dh = -(int64_t)one_minus_q;
	} else {
		/* c2 >= H(s) */
		squeal_model_bessel_h(t->s, &rhs, &dh);
		/* H' lies in [-1, 0]; keep the interpolated value there */
		if (dh < -Q32_ONE) {
			dh = -Q32_ONE;
		} else if (dh > 0) {
			dh = 0;
		} else {
			/* in range */
		}
	}
	squeal_model_border_set(t, criterion, rhs, dh);
}

void squeal_model_classify_sliding(const squeal_params_t *p,
				   const squeal_point_t *point,
				   squeal_criterion_t criterion,
				   squeal_result_t *out, squeal_log_terms_t *t)
{
	int64_t x = 0; /* the cycle x, Q32 (cycle_ln_x) */
	int64_t ln_x;
	int64_t ln_a;
	int64_t ln_w0;
	int64_t ln_force;
	int64_t c2;
	int64_t lq2;
	bool stable;
	bool sat;

	log_terms_fixed(p, point, t);
	ln_a = t->ln_a;
	ln_w0 = t->ln_w0;
	ln_force = t->ln_force;
	c2 = t->c2;
	lq2 = c2 + t->s;
	out->ln_q = fx_q32_to_i32(lq2 - FX_LN2_Q32, SQUEAL_Q_LNQ, &sat);
	out->flags |= SQUEAL_HAS_LNQ;

	if (c2 < 0) {
		/* v_H = -c2 / a: Q32 / Q24 -> Q20 needs << 12; -c2 < 2^39 */
		const int64_t vh = ((-c2) * 4096) / p->slope_spm;

		out->flags |= SQUEAL_HAS_HOPF_V0;
		if (vh > INT32_MAX) {
			out->hopf_v0_mps = INT32_MAX;
			out->hopf_margin_mps = -INT32_MAX;
			out->flags |= SQUEAL_SAT_HOPF_V0;
		} else {
			out->hopf_v0_mps = (int32_t)vh;
			out->hopf_margin_mps = point->v0_mps - (int32_t)vh;
		}
	}
	out->hopf_force_n = fx_exp_q32_to_i32(ln_force + lq2, SQUEAL_Q_FORCE, &sat);
	out->flags |= SQUEAL_HAS_HOPF_FORCE | (sat ? SQUEAL_SAT_HOPF_FORCE : 0U);

	if (lq2 <= 0) {
		out->state = SQUEAL_STATE_UNSTABLE;
		return;
	}
	stable_border_fixed(t, criterion);
	stable = t->stable_lhs >= t->stable_rhs;
	out->state = stable ? SQUEAL_STATE_STABLE : SQUEAL_STATE_BISTABLE;

	ln_x = cycle_ln_x(lq2, criterion, &x);
	out->flags |= SQUEAL_HAS_CYCLE | SQUEAL_HAS_BASIN;
	if (x > ((int64_t)INT32_MAX << (32 - SQUEAL_Q_CYCLE_X))) {
		out->cycle_x = INT32_MAX;
		out->flags |= SQUEAL_SAT_CYCLE_X;
	} else {
		out->cycle_x = (int32_t)(x >> (32 - SQUEAL_Q_CYCLE_X));
	}
	out->trigger_velocity_mps = fx_exp_q32_to_i32(ln_x - ln_a, SQUEAL_Q_V0, &sat);
	out->flags |= sat ? SQUEAL_SAT_TRIGGER : 0U;
	out->lc_amplitude_um = fx_exp_q32_to_i32(ln_x + LN_1E6_Q32 - ln_a - ln_w0,
						 SQUEAL_Q_AMPL_UM, &sat);
	out->flags |= sat ? SQUEAL_SAT_AMPLITUDE : 0U;
	out->basin_ratio = fx_exp_q32_to_i32(
		ln_x - ln_a - ln_field(point->v0_mps, SQUEAL_Q_V0),
		SQUEAL_Q_RATIO, &sat);
	out->flags |= sat ? SQUEAL_SAT_BASIN : 0U;

	squeal_model_basin_side(out, stable);
}

/* The border an unstable point's classification stopped before, for the
 * uncertainty propagation (squeal_model_internal.h). */
void squeal_model_stable_border(squeal_log_terms_t *t, squeal_criterion_t criterion)
{
	if (!t->has_border) {
		stable_border_fixed(t, criterion);
	}
}

#endif /* SQUEAL_NUMERIC_FIXED */
