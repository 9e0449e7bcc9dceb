/* SPDX-License-Identifier: MIT */
/*
 * model_adapter: the only place where the monitor touches squeal_num_t.
 * The monitor conditions its inputs in integers (identical behaviour in both
 * numeric builds); this converts an operating point into the model's numbers,
 * runs the classification and converts the result back into integer units.
 */
#ifndef MODEL_ADAPTER_H
#define MODEL_ADAPTER_H

#include <stdint.h>

#include "squeal_model.h"
#include "squeal_sigma.h"

/* Result of one classification in integer engineering units. A field whose
 * MODEL_EVAL_HAS_* bit is clear does not exist (or did not fit) and is 0. */
#define MODEL_EVAL_HAS_HOPF_V0    (1U << 0)
#define MODEL_EVAL_HAS_HOPF_FORCE (1U << 1)
#define MODEL_EVAL_HAS_CYCLE      (1U << 2) /* amplitude and trigger  */
#define MODEL_EVAL_HAS_BASIN      (1U << 3)
#define MODEL_EVAL_HAS_LNQ        (1U << 4)

typedef struct {
	squeal_state_t state;
	uint32_t has;                 /* MODEL_EVAL_HAS_*                     */
	int32_t ln_2q_micro;          /* ln(2Q) x 1e6: 0 on the Hopf border   */
	int32_t hopf_v0_umps;         /* v_H [um/s]                           */
	int32_t hopf_margin_umps;     /* v0 - v_H [um/s]                      */
	int32_t hopf_force_mn;        /* N_H [mN], clamped to INT32_MAX       */
	int32_t lc_amplitude_nm;      /* A_LC [nm]                            */
	int32_t trigger_velocity_umps;/* A_LC w0 [um/s]                       */
	int32_t basin_ratio_ppm;      /* rho [1e-6]                           */
} model_eval_t;

/*
 * Classify the operating point (v0 [um/s], N [mN]) with the calibration's
 * model parameters. Returns the model's code (SQ_OK or SQ_EINVAL, then
 * out->state is SQUEAL_STATE_INVALID).
 */
int model_adapter_eval(const squeal_params_t *params,
		       squeal_criterion_t criterion,
		       int32_t v0_umps, int32_t force_mn, model_eval_t *out);

/*
 * The same classification with its uncertainty in one pass
 * (squeal_sigma_classify: the model's case and terms computed once, the
 * borders of `criterion` propagated): sig as squeal_sigma_classify fills
 * it. sd and sig both NULL: model_adapter_eval.
 */
int model_adapter_eval_sd(const squeal_params_t *params, const squeal_param_sd_t *sd,
			  squeal_criterion_t criterion, int32_t v0_umps, int32_t force_mn,
			  model_eval_t *out, squeal_sigma_result_t *sig);

/*
 * The calibration's standard deviations propagated to the exact
 * criterion's borders at the operating point (squeal_sigma_eval; same point
 * conversion as above).
 * Returns squeal_sigma_eval's code.
 */
int model_adapter_sigma(const squeal_params_t *params, const squeal_param_sd_t *sd,
			int32_t v0_umps, int32_t force_mn, squeal_sigma_result_t *out);

/* Margin of `state` (squeal_sigma_margin) in sigmas x 2^16, rounded;
 * MODEL_MARGIN_NONE (SQUEAL_SIGMA_MARGIN_MAX: no uncertainty, no border,
 * no adjacent border). */
#define MODEL_MARGIN_NONE ((int32_t)1000 << 16)
int32_t model_adapter_margin_q16(const squeal_sigma_result_t *r, squeal_state_t state);

#endif /* MODEL_ADAPTER_H */
