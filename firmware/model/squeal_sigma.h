/* SPDX-License-Identifier: MIT */
/*
 * squeal_sigma: how sure is a classification? First-order propagation of the
 * calibration's standard deviations to the two border functions of the
 * classification's criterion (docs/model.md sections 2-4; docs/uncertainty.md):
 *
 *   g_H = ln 2Q = ln(2 D w0 m / (a N dmu)) + a v0        Hopf border: g_H = 0
 *   g_S = ln 2Q - G(s),  s = a v0                         stable border: g_S = 0
 *     exact criterion  G(s) = ln(2 I1(s)/s)
 *     cubic criterion  G(s) = ln(1 + s^2/8)   (Q = 1/2 + s^2/16)
 *
 *   unstable  g_H <= 0;   bistable  g_H > 0 and g_S < 0;   stable  g_S >= 0
 *
 * Closed-form derivatives, written with relative deviations r_x = sd_x / x
 * (N and v0 are measured at run time and taken as exact):
 *
 *   dg/dm m = 1,  dg/dw0 w0 = 1,  dg/dD D = 1,  dg/ddmu dmu = -1  (both g)
 *   dg_H/da a = a v0 - 1 = s - 1
 *   dg_S/da a = s - 1 - s G'(s)          (s depends on a: ds/da = v0)
 *     exact: G'(s) = I1'(s)/I1(s) - 1/s = I0(s)/I1(s) - 2/s
 *            (I1'/I1 = I0/I1 - 1/s)
 *     cubic: G'(s) = (s/4) / (1 + s^2/8), so s G'(s) = 2 s^2 / (8 + s^2)
 *     and with H(s) = G(s) - s:  dg_S/da a = -s H'(s) - 1
 *
 *   sigma_g^2 = r_m^2 + r_w0^2 + r_D^2 + r_dmu^2 + e_a^2 - 2 rho e_a r_dmu
 *   e_a = r_a (dg/da a),  rho = corr(a, dmu)  (mu_inf enters no border)
 *
 * The margin of a class is the distance, in standard deviations, to the
 * border adjacent to it: unstable -> |g_H| / sigma_H; stable -> g_S /
 * sigma_S; bistable -> the smaller of g_H / sigma_H and -g_S / sigma_S.
 * Where a border has sigma 0 (all standard deviations 0) its distance is
 * SQUEAL_SIGMA_MARGIN_MAX: no uncertainty, so the class is exactly the
 * model's. Not sliding, and a brake without falling friction (a = 0 or
 * dmu <= 0: no border at all), also give SQUEAL_SIGMA_MARGIN_MAX.
 *
 * Both numeric builds, one API (squeal_num_t as in squeal_model.h; the
 * fixed build's formats are the SQUEAL_Q_* named per field). Pure functions,
 * no heap, no libm, bounded time. squeal_sigma_classify() classifies and
 * propagates in one pass for the criterion given (the monitor's step);
 * squeal_sigma_eval() is the same for the exact criterion.
 */
#ifndef SQUEAL_SIGMA_H
#define SQUEAL_SIGMA_H

#include <stdint.h>

#include "squeal_model.h"

#define SQUEAL_Q_CORR   30 /* correlation in [-1, 1]                      */
#define SQUEAL_Q_SIGMA  24 /* sigma of a border function, range 128       */
#define SQUEAL_Q_MARGIN 16 /* margin in standard deviations               */

/* Largest margin reported (sigmas): "no uncertainty" or "no border". */
#if defined(SQUEAL_NUMERIC_FIXED)
#define SQUEAL_SIGMA_MARGIN_MAX ((int32_t)1000 << SQUEAL_Q_MARGIN)
#else
#define SQUEAL_SIGMA_MARGIN_MAX 1000.0f
#endif

/*
 * Standard deviations of the calibration, in the formats of the matching
 * squeal_params_t fields. Domain: each in [0, its parameter's value] (a
 * relative deviation above 1 is outside any first-order propagation), mu_inf
 * in [0, 1.5], slope_delta_mu_corr in [-1, 1].
 */
typedef struct {
	squeal_num_t mass_kg_sd;          /* SQUEAL_Q_MASS    */
	squeal_num_t omega0_radps_sd;     /* SQUEAL_Q_OMEGA0  */
	squeal_num_t damping_sd;          /* SQUEAL_Q_DAMPING */
	squeal_num_t mu_inf_sd;           /* SQUEAL_Q_MU (enters no border) */
	squeal_num_t delta_mu_sd;         /* SQUEAL_Q_MU      */
	squeal_num_t slope_spm_sd;        /* SQUEAL_Q_SLOPE   */
	squeal_num_t slope_delta_mu_corr; /* SQUEAL_Q_CORR    */
} squeal_param_sd_t;

/* Which values of squeal_sigma_result_t hold a value. */
#define SQUEAL_SIGMA_HAS_BORDERS (1U << 0) /* g_*, sigma_* (sliding, falling friction) */
#define SQUEAL_SIGMA_SAT         (1U << 1) /* a sigma clamped to its field's maximum  */

/*
 *   state         class of the point (squeal_model_classify's, same criterion)
 *   g_hopf        g_H = ln 2Q                           SQUEAL_Q_LNQ
 *   g_stable      g_S = ln 2Q - ln(2 I1(s)/s)           SQUEAL_Q_LNQ
 *   sigma_hopf    first-order sigma of g_H              SQUEAL_Q_SIGMA
 *   sigma_stable  first-order sigma of g_S              SQUEAL_Q_SIGMA
 *   margin_sigma  margin of `state` (see above), >= 0   SQUEAL_Q_MARGIN
 */
typedef struct {
	squeal_state_t state;
	uint32_t flags;
	squeal_num_t g_hopf;
	squeal_num_t g_stable;
	squeal_num_t sigma_hopf;
	squeal_num_t sigma_stable;
	squeal_num_t margin_sigma;
} squeal_sigma_result_t;

/* All standard deviations 0 (today's behaviour: crisp classes). */
void squeal_sigma_sd_zero(squeal_param_sd_t *sd);

/* SQ_OK, or SQ_EINVAL when sd is NULL or outside its domain for params
 * (params itself must pass squeal_model_params_check). */
int squeal_sigma_sd_check(const squeal_params_t *params,
			  const squeal_param_sd_t *sd);

/*
 * One classification and its uncertainty, from one evaluation of the
 * domain rules and of the log-domain terms: squeal_model_classify(params,
 * point, criterion, out), and with sd the deviations propagated to the
 * borders of the same criterion into sig (sig->state is out->state):
 * SQUEAL_SIGMA_HAS_BORDERS with g_*, sigma_* and the margin of the class
 * when sliding with falling friction; no flags and margin
 * SQUEAL_SIGMA_MARGIN_MAX when not sliding or without a border; state
 * INVALID and every value 0 when the classification is invalid or sd is
 * outside its domain (the classification itself does not depend on sd).
 * sd and sig both NULL: the classification alone. Returns
 * squeal_model_classify's code. NULL params, point or out, or only one of
 * sd and sig, is a programming error.
 */
int squeal_sigma_classify(const squeal_params_t *params,
			  const squeal_param_sd_t *sd,
			  const squeal_point_t *point,
			  squeal_criterion_t criterion,
			  squeal_result_t *out,
			  squeal_sigma_result_t *sig);

/*
 * The same for the exact criterion, uncertainty only: SQ_OK with out
 * filled, SQ_EINVAL with out->state INVALID and every value 0 when params,
 * sd or point is outside its domain. A NULL pointer is a programming error
 * (nothing touched).
 */
int squeal_sigma_eval(const squeal_params_t *params,
		      const squeal_param_sd_t *sd,
		      const squeal_point_t *point,
		      squeal_sigma_result_t *out);

/*
 * The margin of another class (e.g. the monitor's debounced state) from an
 * evaluated result: SQ_OK and *margin; SQUEAL_SIGMA_MARGIN_MAX where r has
 * no borders or state has no adjacent border (not sliding, invalid).
 * SQ_EINVAL when a pointer is NULL.
 */
int squeal_sigma_margin(const squeal_sigma_result_t *r, squeal_state_t state,
			squeal_num_t *margin);

#endif /* SQUEAL_SIGMA_H */
