/* SPDX-License-Identifier: MIT */
/* Pieces shared by the float and fixed implementations of squeal_model.h. */
#ifndef SQUEAL_MODEL_INTERNAL_H
#define SQUEAL_MODEL_INTERNAL_H

#include <stdbool.h>
#include <stdint.h>

#include "squeal_model.h"

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

/* Per numeric build (squeal_model_float.c / squeal_model_fixed.c): */

/* The operating point against the documented domain: SQ_OK or SQ_EINVAL. */
int squeal_model_point_check(const squeal_point_t *point);

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
 */
#if defined(SQUEAL_NUMERIC_FIXED)
typedef struct {
	int64_t c2;         /* Q32 */
	int64_t s;          /* Q32 */
	int64_t ln_a;       /* Q32 */
	int64_t ln_w0;      /* Q32 */
	int64_t ln_force;   /* Q32 */
	int64_t stable_lhs; /* Q32 */
	int64_t stable_rhs; /* Q32 */
	int64_t stable_dh;  /* Q32, within [-1, 0] */
	bool has_border;
} squeal_log_terms_t;

/* H(s) = ln(2 I1(s)/s) - s and H'(s), Q32, for s >= 0 in Q32. */
void squeal_model_bessel_h(int64_t s_q32, int64_t *h_q32, int64_t *dh_q32);
#else
typedef struct {
	float c2;
	float s;
	float stable_lhs;
	float stable_rhs;
	float stable_dh;
	bool has_border;
} squeal_log_terms_t;

/* G(x) = ln(2 I1(x)/x), G'(x) and (h_out may be NULL) H = G - x, x >= 0. */
void squeal_model_bessel_g(float x, float *g_out, float *dg_out, float *h_out);
#endif

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
