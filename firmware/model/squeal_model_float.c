/* SPDX-License-Identifier: MIT */
/*
 * Float build of the squeal model (docs/model.md sections 2-4, 7).
 *
 * Everything is expressed through lq2 = ln(2Q) = c2 + s, with
 *   c2 = ln(2 D w0 m / (a N dmu))   (bounded: a sum of logs of bounded inputs)
 *   s  = a v0                        (the stick line in the dimensionless form)
 * so that e^(a v0) is never formed. With G(x) = ln(2 I1(x) / x) (G(0) = 0):
 *   unstable        lq2 <= 0                     (Q <= 1/2)
 *   stable (exact)  lq2 >= G(s)  <=>  c2 >= G(s) - s = H(s)
 *   stable (cubic)  lq2 >= ln(1 + s^2 / 8)       (Q >= 1/2 + s^2/16)
 *   exact cycle     G(x) = lq2                   (I1(x)/x = Q)
 *   cubic cycle     x3 = sqrt(8 (e^lq2 - 1))     (4 sqrt(Q - 1/2))
 *   v_H = -c2 / a, exists when c2 < 0;   N_H = 2 Q N = N e^lq2
 */
#if !defined(SQUEAL_NUMERIC_FIXED)

#include <float.h>
#include <stdbool.h>
#include <stddef.h>

#include "sq_mathf.h"
#include "squeal_model.h"
#include "squeal_model_internal.h"

#include "sq_contract.h"

/* 0.5 ln(2 / pi): the constant of H(s) = G(s) - s for large s */
#define HALF_LN_2_OVER_PI (-0.225791352644727f)
/* Below this s, G is summed from its power series; above, the asymptotic
 * expansion with 5 terms is used (first omitted term 0.68 / s^6 < 4e-8). */
#define SERIES_MAX_S 16.0f
#define SERIES_MAX_TERMS 64
#define SOLVE_MAX_ITER 60
#define UM_PER_M 1.0e6f

/* 1 / ((k+1)(k+2)) and 1 / ((k+1)(k+3)), k = 0..63: the ratios of
 * consecutive terms of the series of S(t) and S'(t), so that summing them
 * multiplies instead of dividing (a float division costs 14 cycles on the
 * Cortex-M4F, a multiplication 1). Constant expressions: the compiler's
 * one correctly rounded float division of two exact integers each. */
#define RATIO_S(k)  (1.0f / (float)(((k) + 1) * ((k) + 2)))
#define RATIO_DS(k) (1.0f / (float)(((k) + 1) * ((k) + 3)))
#define RATIOS_1(k)  { RATIO_S(k), RATIO_DS(k) }
#define RATIOS_4(k)  RATIOS_1(k), RATIOS_1((k) + 1), RATIOS_1((k) + 2), RATIOS_1((k) + 3)
#define RATIOS_16(k) RATIOS_4(k), RATIOS_4((k) + 4), RATIOS_4((k) + 8), RATIOS_4((k) + 12)
_Static_assert(SERIES_MAX_TERMS == 64, "four RATIOS_16 fill the series table");
typedef struct {
	float s;  /* 1 / ((k+1)(k+2)) */
	float ds; /* 1 / ((k+1)(k+3)) */
} series_ratio_t;
static const series_ratio_t series_ratio[SERIES_MAX_TERMS] = {
	RATIOS_16(0), RATIOS_16(16), RATIOS_16(32), RATIOS_16(48)
};

/*
 * G(x) = ln(2 I1(x)/x) and its derivative.
 * Series: 2 I1(x)/x = S(t) = sum_k t^k / (k! (k+1)!), t = x^2/4, so
 *   G = ln S = log1p(S - 1)   (no cancellation near x = 0)
 *   G' = (x/2) S'(t) / S.
 * Asymptotic: G = x + 0.5 ln(2/pi) - 1.5 ln x + ln P(x),
 *   P = 1 - 3/(8x) - 15/(128x^2) - 315/(3072x^3) - 14175/(98304x^4)
 *         - 1091475/(3932160x^5).
 * h_out receives H = G - x computed without cancellation (may be NULL).
 */
void squeal_model_bessel_g(float x, float *g_out, float *dg_out, float *h_out)
{
	if (x <= SERIES_MAX_S) {
		const float t = 0.25f * x * x;
		float term = 1.0f;  /* t^k / (k! (k+1)!) */
		float dterm = 0.5f; /* k t^(k-1) / (k! (k+1)!) for k >= 1 */
		float sm1 = 0.0f;   /* S - 1 */
		float ds = 0.0f;    /* S' */
		int32_t k;

		for (k = 0; k < SERIES_MAX_TERMS; k++) {
			term *= t * series_ratio[k].s;
			sm1 += term;
			ds += dterm;
			dterm *= t * series_ratio[k].ds;
			if (term <= sm1 * 1.0e-9f) {
				break;
			}
		}
		*g_out = sq_log1pf(sm1);
		*dg_out = 0.5f * x * ds / (1.0f + sm1);
		if (h_out != NULL) {
			*h_out = *g_out - x;
		}
	} else {
		const float r = 1.0f / x;
		const float p = 1.0f - r * (3.0f / 8.0f + r * (15.0f / 128.0f +
				r * (315.0f / 3072.0f + r * (14175.0f / 98304.0f +
				r * (1091475.0f / 3932160.0f)))));
		const float dp = r * r * (3.0f / 8.0f + r * (30.0f / 128.0f +
				 r * (945.0f / 3072.0f + r * (56700.0f / 98304.0f +
				 r * (5457375.0f / 3932160.0f)))));
		const float h = HALF_LN_2_OVER_PI - 1.5f * sq_lnf(x) + sq_lnf(p);

		*g_out = x + h;
		*dg_out = 1.0f - 1.5f * r + dp / p;
		if (h_out != NULL) {
			*h_out = h;
		}
	}
}

/*
 * Solve G(x) = lq2 for x > 0 (lq2 > 0): Newton's method kept inside a
 * bracket [lo, hi] that always holds the root, bisecting whenever a Newton
 * step would leave it. G(0) = 0 < lq2 and G(2 lq2 + 16) > lq2 for all lq2 > 0.
 */
static float solve_exact_cycle(float lq2)
{
	float lo = 0.0f;
	float hi = 2.0f * lq2 + 16.0f;
	float x;
	int32_t i;

	/* G(x) ~ x^2/8 near 0 and ~ x - 1.5 ln x for large x */
	if (lq2 < 2.0f) {
		x = sq_sqrtf(8.0f * lq2);
	} else {
		x = lq2 + 1.5f * sq_lnf(lq2 + 1.5f * sq_lnf(lq2) + 1.0f) + 0.23f;
	}
	if (!(x > lo) || !(x < hi)) {
		x = 0.5f * (lo + hi);
	}
	for (i = 0; i < SOLVE_MAX_ITER; i++) {
		float g;
		float dg;
		float f;
		float next;

		squeal_model_bessel_g(x, &g, &dg, NULL);
		f = g - lq2;
		if (f == 0.0f) {
			break;
		}
		if (f < 0.0f) {
			lo = x;
		} else {
			hi = x;
		}
		next = (dg > 0.0f) ? (x - f / dg) : lo;
		if (!(next > lo) || !(next < hi)) {
			next = 0.5f * (lo + hi);
		}
		if ((next - x <= 2.0e-7f * x) && (x - next <= 2.0e-7f * x)) {
			x = next;
			break;
		}
		x = next;
	}
	return x;
}

/* Store an extended-range value into a field, flagging it when it does not
 * fit a float. */
static float put(sq_xf_t v, squeal_result_t *out, uint32_t sat_flag)
{
	bool sat;
	const float f = sq_xf_to_float(v, &sat);

	if (sat) {
		out->flags |= sat_flag;
	}
	return f;
}

/* Cycle amplitude and everything derived from it, for lq2 > 0. The cycle x
 * is kept in extended range so that x / a, x / (a w0) and x / (a v0) are
 * right (or flagged) even where x itself or an intermediate overflows. */
static void fill_cycle(const squeal_params_t *p, const squeal_point_t *pt,
		       float lq2, squeal_criterion_t criterion,
		       squeal_result_t *out)
{
	const sq_xf_t a = sq_xf_from(p->slope_spm);
	sq_xf_t x;

	if (criterion == SQUEAL_CRITERION_CUBIC) {
		/* 4 sqrt(Q - 1/2) = sqrt(8 (e^lq2 - 1)); for large lq2 the -1
		 * is below float resolution and sqrt(8) e^(lq2/2) cannot
		 * overflow in extended range */
		if (lq2 < 20.0f) {
			x = sq_xf_from(sq_sqrtf(8.0f * sq_expm1f(lq2)));
		} else {
			x = sq_xf_mul(sq_xf_from(2.82842712475f), sq_xf_exp(0.5f * lq2));
		}
	} else {
		x = sq_xf_from(solve_exact_cycle(lq2));
	}
	out->flags |= SQUEAL_HAS_CYCLE | SQUEAL_HAS_BASIN;
	out->cycle_x = put(x, out, SQUEAL_SAT_CYCLE_X);
	out->trigger_velocity_mps = put(sq_xf_div(x, a), out, SQUEAL_SAT_TRIGGER);
	out->lc_amplitude_um = put(sq_xf_div(sq_xf_mul(x, sq_xf_from(UM_PER_M)),
					     sq_xf_mul(a, sq_xf_from(p->omega0_radps))),
				   out, SQUEAL_SAT_AMPLITUDE);
	out->basin_ratio = put(sq_xf_div(x, sq_xf_mul(a, sq_xf_from(pt->v0_mps))),
			       out, SQUEAL_SAT_BASIN);
}

/* c2, s; has_border false (the stable_* fields are set only with it). */
static void log_terms_float(const squeal_params_t *p, const squeal_point_t *point,
			    squeal_log_terms_t *t)
{
	t->s = p->slope_spm * point->v0_mps;
	t->c2 = SQ_LN2F + sq_lnf(p->damping) + sq_lnf(p->omega0_radps) +
		sq_lnf(p->mass_kg) - sq_lnf(p->slope_spm) -
		sq_lnf(point->force_n) - sq_lnf(p->delta_mu);
	t->has_border = false; /* the stable border: squeal_model_stable_border */
}

/* The stable border of the criterion into t (one source for the
 * classification, which inlines it, and squeal_model_stable_border). */
static inline void stable_border_float(squeal_log_terms_t *t, squeal_criterion_t criterion)
{
	const float s = t->s;
	float rhs;
	float dh;

	if (criterion == SQUEAL_CRITERION_CUBIC) {
		/* ln 2Q >= ln(1 + s^2/8) */
		rhs = sq_log1pf(0.125f * s * s);
		dh = 0.25f * s / (1.0f + 0.125f * s * s) - 1.0f;
	} else {
		float g;
		float dg;

		/* c2 >= H(s) */
		squeal_model_bessel_g(s, &g, &dg, &rhs);
		dh = dg - 1.0f;
	}
	squeal_model_border_set(t, criterion, rhs, dh);
}

void squeal_model_stable_border(squeal_log_terms_t *t, squeal_criterion_t criterion)
{
	if (!t->has_border) {
		stable_border_float(t, criterion);
	}
}

void squeal_model_classify_sliding(const squeal_params_t *p,
				   const squeal_point_t *point,
				   squeal_criterion_t criterion,
				   squeal_result_t *out, squeal_log_terms_t *t)
{
	float c2;
	float lq2;
	bool stable;

	log_terms_float(p, point, t);
	c2 = t->c2;
	lq2 = c2 + t->s;
	out->ln_q = lq2 - SQ_LN2F;
	out->flags |= SQUEAL_HAS_LNQ;

	/* Hopf border in speed: lq2 = 0 at v0 = -c2 / a */
	if (c2 < 0.0f) {
		out->flags |= SQUEAL_HAS_HOPF_V0;
		out->hopf_v0_mps = put(sq_xf_div(sq_xf_from(-c2), sq_xf_from(p->slope_spm)),
				       out, SQUEAL_SAT_HOPF_V0);
		out->hopf_margin_mps = ((out->flags & SQUEAL_SAT_HOPF_V0) != 0U) ?
			-FLT_MAX : point->v0_mps - out->hopf_v0_mps;
	}
	/* Hopf border in force: N_H = 2 Q N = N e^lq2 (extended range: N may
	 * be tiny and e^lq2 huge) */
	out->flags |= SQUEAL_HAS_HOPF_FORCE;
	out->hopf_force_n = put(sq_xf_mul(sq_xf_from(point->force_n), sq_xf_exp(lq2)),
				out, SQUEAL_SAT_HOPF_FORCE);

	if (!(lq2 > 0.0f)) {
		out->state = SQUEAL_STATE_UNSTABLE;
		return;
	}
	stable_border_float(t, criterion);
	stable = t->stable_lhs >= t->stable_rhs;
	out->state = stable ? SQUEAL_STATE_STABLE : SQUEAL_STATE_BISTABLE;
	fill_cycle(p, point, lq2, criterion, out);

	squeal_model_basin_side(out, stable);
}

#endif /* !SQUEAL_NUMERIC_FIXED */
