/* SPDX-License-Identifier: MIT */
/*
 * squeal_model: the friction-oscillator ("mass on a belt") stability model of
 * a disc brake, as derived in docs/model.md.
 *
 * One API, two numeric builds chosen at compile time:
 *   - float (default): squeal_num_t is float, every field in SI units;
 *   - fixed (-DSQUEAL_NUMERIC_FIXED): squeal_num_t is int32_t and each field
 *     carries its own Q-format, given by the SQUEAL_Q_* macro named in its
 *     comment (value = raw / 2^Q). The fixed build contains no floating-point
 *     type at all.
 *
 * All arithmetic is done in the log domain (ln Q = C + s with
 * C = ln(D w0 m / (a N dmu)) and s = a v0), so no input inside the documented
 * limits can overflow, and every input outside them is reported, never
 * computed with.
 *
 * Input domain (both builds; anything else gives SQUEAL_STATE_INVALID and
 * SQ_EINVAL). Limits are physical plausibility bounds chosen so that every
 * intermediate fits the fixed build's formats:
 *   mass_kg        (0, 10000]        omega0_radps  (0, 500000]
 *   damping        (0, 1]            slope_spm     [0, 20]
 *   mu_inf         [0, 1.5]          delta_mu      [-1.5, 1.5], mu_inf+delta_mu >= 0
 *   v0_mps         [0, 100]          force_n       [0, 500000]
 * NaN and infinities are outside every range.
 *
 * Defined answers at the edges of the domain:
 *   v0 == 0 or force == 0       -> SQUEAL_STATE_NOT_SLIDING (no relative
 *                                  sliding or no contact: nothing to classify)
 *   slope == 0 or delta_mu <= 0 -> SQUEAL_STATE_STABLE with no Hopf border and
 *                                  no limit cycle (friction does not fall with
 *                                  speed, so the effective damping is >= D w0)
 */
#ifndef SQUEAL_MODEL_H
#define SQUEAL_MODEL_H

#include <stdint.h>

#include "sq_status.h"
#include "squeal_state.h" /* squeal_state_t: the values of the CAN signal SquealState */

#if defined(SQUEAL_NUMERIC_FIXED)
typedef int32_t squeal_num_t;
#define SQUEAL_NUMERIC_NAME "fixed"
#else
typedef float squeal_num_t;
#define SQUEAL_NUMERIC_NAME "float"
#endif

/*
 * Q-formats of the fixed build (number of fraction bits of each field).
 * The float build ignores them. Resolution = 2^-Q, range = +-2^(31-Q).
 */
#define SQUEAL_Q_MASS      16 /* kg,    range 32768,   res 1.5e-5 kg      */
#define SQUEAL_Q_OMEGA0    12 /* rad/s, range 524288,  res 2.4e-4 rad/s   */
#define SQUEAL_Q_DAMPING   30 /* -,     range 2,       res 9.3e-10        */
#define SQUEAL_Q_MU        30 /* -,     range 2,       res 9.3e-10        */
#define SQUEAL_Q_SLOPE     24 /* s/m,   range 128,     res 6.0e-8 s/m     */
#define SQUEAL_Q_V0        20 /* m/s,   range 2048,    res 9.5e-7 m/s     */
#define SQUEAL_Q_FORCE     12 /* N,     range 524288,  res 2.4e-4 N       */
#define SQUEAL_Q_LNQ       16 /* -,     range 32768,   res 1.5e-5         */
#define SQUEAL_Q_CYCLE_X   20 /* -,     range 2048                        */
#define SQUEAL_Q_AMPL_UM   12 /* um,    range 524288,  res 2.4e-4 um      */
#define SQUEAL_Q_RATIO     24 /* -,     range 128,     res 6.0e-8         */


typedef enum {
	SQUEAL_CRITERION_EXACT = 0, /* I1(s)/s, first-order averaging, default   */
	SQUEAL_CRITERION_CUBIC = 1  /* the paper's 1/2 + s^2/16 (under-warns)     */
} squeal_criterion_t;

/* Brake calibration: the oscillator's constants. */
typedef struct {
	squeal_num_t mass_kg;      /* m,      SQUEAL_Q_MASS    */
	squeal_num_t omega0_radps; /* w0,     SQUEAL_Q_OMEGA0  */
	squeal_num_t damping;      /* D,      SQUEAL_Q_DAMPING */
	squeal_num_t mu_inf;       /* mu_inf, SQUEAL_Q_MU      */
	squeal_num_t delta_mu;     /* mu_0 - mu_inf, SQUEAL_Q_MU */
	squeal_num_t slope_spm;    /* a,      SQUEAL_Q_SLOPE   */
} squeal_params_t;

/* A measured operating point. */
typedef struct {
	squeal_num_t v0_mps;  /* disc surface speed at r_p, SQUEAL_Q_V0 */
	squeal_num_t force_n; /* pad normal force N,       SQUEAL_Q_FORCE */
} squeal_point_t;

/* Which result fields hold a value (others are 0 and must not be used). */
#define SQUEAL_HAS_LNQ        (1U << 0) /* ln_q                               */
#define SQUEAL_HAS_HOPF_V0    (1U << 1) /* hopf_v0_mps, hopf_margin_mps       */
#define SQUEAL_HAS_HOPF_FORCE (1U << 2) /* hopf_force_n                       */
#define SQUEAL_HAS_CYCLE      (1U << 3) /* cycle_x, lc_amplitude_um, trigger  */
#define SQUEAL_HAS_BASIN      (1U << 4) /* basin_ratio                        */
/* A value that exists but does not fit its field is clamped to the field's
 * maximum and marked here (the fixed build's ranges are narrower). */
#define SQUEAL_SAT_HOPF_V0    (1U << 8) /* hopf_v0_mps and hopf_margin_mps    */
#define SQUEAL_SAT_HOPF_FORCE (1U << 9)
#define SQUEAL_SAT_CYCLE_X    (1U << 10)
#define SQUEAL_SAT_AMPLITUDE  (1U << 11)
#define SQUEAL_SAT_TRIGGER    (1U << 12)
#define SQUEAL_SAT_BASIN      (1U << 13)

/*
 * Result of one classification.
 *   ln_q           ln Q, Q = D w0 m e^(a v0) / (a N dmu)          SQUEAL_Q_LNQ
 *   hopf_v0_mps    v_H: steady sliding unstable for v0 < v_H      SQUEAL_Q_V0
 *                  (exists only when a N dmu > 2 D w0 m)
 *   hopf_margin_mps v0 - v_H (negative = unstable side)           SQUEAL_Q_V0
 *   hopf_force_n   N_H: unstable for N > N_H                      SQUEAL_Q_FORCE
 *   cycle_x        x = a w0 A_LC of the unstable cycle of the selected
 *                  criterion (exists when Q > 1/2)                SQUEAL_Q_CYCLE_X
 *   lc_amplitude_um  A_LC in micrometres                          SQUEAL_Q_AMPL_UM
 *   trigger_velocity_mps  A_LC w0 = x / a                         SQUEAL_Q_V0
 *   basin_ratio    rho = x / s: < 1 exactly when bistable         SQUEAL_Q_RATIO
 */
typedef struct {
	squeal_state_t state;
	uint32_t flags; /* SQUEAL_HAS_* | SQUEAL_SAT_* */
	squeal_num_t ln_q;
	squeal_num_t hopf_v0_mps;
	squeal_num_t hopf_margin_mps;
	squeal_num_t hopf_force_n;
	squeal_num_t cycle_x;
	squeal_num_t lc_amplitude_um;
	squeal_num_t trigger_velocity_mps;
	squeal_num_t basin_ratio;
} squeal_result_t;

/*
 * Check a calibration against the documented domain.
 * Returns SQ_OK, or SQ_EINVAL if any field is outside it (params NULL is a
 * programming error: hal_contract_failed, hal.h).
 */
int squeal_model_params_check(const squeal_params_t *params);

/*
 * Classify one operating point.
 * Returns SQ_OK with out->state one of STABLE, BISTABLE, UNSTABLE or
 * NOT_SLIDING; SQ_EINVAL with out->state = INVALID (all values 0, no flags)
 * when params or point is outside the domain or criterion is unknown. A
 * NULL pointer is a programming error (hal_contract_failed, hal.h).
 * Pure function: no state, no side effects, bounded time.
 */
int squeal_model_classify(const squeal_params_t *params,
			  const squeal_point_t *point,
			  squeal_criterion_t criterion,
			  squeal_result_t *out);

/* The paper's default disc brake (docs/model.md section 8). */
void squeal_model_default_params(squeal_params_t *params);

/* "stable", "bistable", "unstable", "not_sliding", "invalid" ("?" otherwise). */
const char *squeal_model_state_name(squeal_state_t state);

#endif /* SQUEAL_MODEL_H */
