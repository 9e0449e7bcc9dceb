/* SPDX-License-Identifier: MIT */
/* Pieces shared by the float and fixed implementations of squeal_model.h. */
#ifndef SQUEAL_MODEL_INTERNAL_H
#define SQUEAL_MODEL_INTERNAL_H

#include <stdbool.h>
#include <stdint.h>

#include "squeal_model.h"

/*
 * The build's number types and constants where the two builds differ only
 * in type: squeal_wide_t holds log-domain terms (fixed: int64 Q32) and sums
 * of two fields without overflow; the domain limits of squeal_model.h and
 * the basin ratio's 1 in the fields' formats (fixed: raw, SQUEAL_Q_*).
 */
#if defined(SQUEAL_NUMERIC_FIXED)
typedef int64_t squeal_wide_t;
#define SQUEAL_NUM_LIMIT(v, q)  ((int32_t)(v) << (q)) /* integer v in Q q */
#define SQUEAL_NUM_TINY         1                     /* smallest > 0     */
#define SQUEAL_MU_MAX           ((int32_t)3 << (SQUEAL_Q_MU - 1)) /* 1.5 */
#define SQUEAL_RATIO_ONE        ((int32_t)1 << SQUEAL_Q_RATIO)
#define SQUEAL_RATIO_BELOW_ONE  (SQUEAL_RATIO_ONE - 1)
#else
#include <float.h>

typedef float squeal_wide_t;
#define SQUEAL_NUM_LIMIT(v, q)  ((float)(v))
#define SQUEAL_NUM_TINY         FLT_TRUE_MIN
#define SQUEAL_MU_MAX           1.5f
#define SQUEAL_RATIO_ONE        1.0f
#define SQUEAL_RATIO_BELOW_ONE  (1.0f - FLT_EPSILON / 2.0f)
#endif

/* Which of the domain rules of squeal_model.h a calibration and an
 * operating point fall under (both non-NULL). */
typedef enum {
	SQUEAL_CASE_INVALID,     /* outside the documented domain          */
	SQUEAL_CASE_NOT_SLIDING, /* v0 == 0 or N == 0                      */
	SQUEAL_CASE_NO_BORDER,   /* a == 0 or dmu <= 0: stable, no border   */
	SQUEAL_CASE_SLIDING      /* v0, N, a, dmu > 0: the borders exist    */
} squeal_case_t;

/* A result with this state, no flags and every value 0. */
void squeal_model_result_clear(squeal_result_t *out, squeal_state_t state);

/*
 * The log-domain terms every border test is built from (valid calibration
 * and point with v0, N, a, delta_mu > 0): c2 = ln(2 D w0 m / (a N dmu)) and
 * s = a v0, so ln 2Q = c2 + s. The fixed build also keeps the logarithms it
 * needs again afterwards. Then, once squeal_model_stable_border() has run
 * (has_border), the stable border of the criterion in use:
 *   the point is stable iff stable_lhs >= stable_rhs (the model's own
 *   comparison), g_S = stable_lhs - stable_rhs, and stable_dh = H'(s) for
 *   g_S = c2 - H(s):
 *     exact  lhs c2,       rhs H(s) = ln(2 I1(s)/s) - s,  H' = G' - 1
 *     cubic  lhs ln 2Q,    rhs ln(1 + s^2/8),  H(s) = rhs - s,
 *            H' = (s/4) / (1 + s^2/8) - 1
 * One classification fills these once; the uncertainty propagation
 * (squeal_sigma.h) reads the same numbers instead of computing them again.
 * Fixed build: every term Q32, stable_dh within [-1, 0].
 */
typedef struct {
	squeal_wide_t c2;
	squeal_wide_t s;
#if defined(SQUEAL_NUMERIC_FIXED)
	squeal_wide_t ln_a;
	squeal_wide_t ln_w0;
	squeal_wide_t ln_force;
#endif
	squeal_wide_t stable_lhs;
	squeal_wide_t stable_rhs;
	squeal_wide_t stable_dh;
	bool has_border;
} squeal_log_terms_t;

/* Per numeric build (squeal_model_float.c / squeal_model_fixed.c): */
#if defined(SQUEAL_NUMERIC_FIXED)
/* H(s) = ln(2 I1(s)/s) - s and H'(s), Q32, for s >= 0 in Q32. */
void squeal_model_bessel_h(int64_t s_q32, int64_t *h_q32, int64_t *dh_q32);
#else
/* G(x) = ln(2 I1(x)/x), G'(x) and (h_out may be NULL) H = G - x, x >= 0. */
void squeal_model_bessel_g(float x, float *g_out, float *dg_out, float *h_out);
#endif

/* The stable border found (rhs and H' of the criterion, from the build's
 * G or H): its left-hand side, exact c2 or cubic ln 2Q = c2 + s, and
 * has_border. Both builds' stable border ends here. */
static inline void squeal_model_border_set(squeal_log_terms_t *t, squeal_criterion_t criterion,
					   squeal_wide_t rhs, squeal_wide_t dh)
{
	t->stable_lhs = (criterion == SQUEAL_CRITERION_CUBIC) ? (t->c2 + t->s) : t->c2;
	t->stable_rhs = rhs;
	t->stable_dh = dh;
	t->has_border = true;
}

/* The class is decided by the border comparison; the basin ratio comes
 * from the solved cycle. Within the solver's last bit they could disagree:
 * keep rho < 1 exactly for bistable, >= 1 for stable (out has a cycle). */
static inline void squeal_model_basin_side(squeal_result_t *out, bool stable)
{
	if (!stable && !(out->basin_ratio < SQUEAL_RATIO_ONE)) {
		out->basin_ratio = SQUEAL_RATIO_BELOW_ONE;
	} else if (!stable && !(out->basin_ratio > 0)) {
		out->basin_ratio = SQUEAL_NUM_TINY;
	} else if (stable && (out->basin_ratio < SQUEAL_RATIO_ONE)) {
		out->basin_ratio = SQUEAL_RATIO_ONE;
	} else {
		/* rho already on the side of its class */
	}
}

/* The stable border of `criterion` (exact or cubic) at t's point, once:
 * nothing when t->has_border is already set. */
void squeal_model_stable_border(squeal_log_terms_t *t, squeal_criterion_t criterion);

/*
 * The sliding case: valid calibration and point, v0 > 0, N > 0, slope > 0,
 * delta_mu > 0, out already cleared to STABLE. Fills in every result, and t
 * with the terms it used (the stable border unless the point is unstable).
 */
void squeal_model_classify_sliding(const squeal_params_t *p,
				   const squeal_point_t *point,
				   squeal_criterion_t criterion,
				   squeal_result_t *out, squeal_log_terms_t *t);

/*
 * squeal_model_classify (known criterion, non-NULL pointers), also giving
 * the domain case the point fell under; in the sliding case t holds the
 * terms of the classification (otherwise t is not touched).
 */
squeal_case_t squeal_model_classify_case(const squeal_params_t *params,
					 const squeal_point_t *point,
					 squeal_criterion_t criterion,
					 squeal_result_t *out, squeal_log_terms_t *t);

#endif /* SQUEAL_MODEL_INTERNAL_H */
