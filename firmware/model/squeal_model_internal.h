/* SPDX-License-Identifier: MIT */
/* Pieces shared by the float and fixed implementations of squeal_model.h. */
#ifndef SQUEAL_MODEL_INTERNAL_H
#define SQUEAL_MODEL_INTERNAL_H

#include "squeal_model.h"

/* A result with this state, no flags and every value 0. */
void squeal_model_result_clear(squeal_result_t *out, squeal_state_t state);

/* Per numeric build (squeal_model_float.c / squeal_model_fixed.c): */

/* The operating point against the documented domain: SQ_OK or SQ_EINVAL. */
int squeal_model_point_check(const squeal_point_t *point);

/*
 * The sliding case: valid calibration and point, v0 > 0, N > 0, slope > 0,
 * delta_mu > 0, out already cleared to STABLE. Fills in every result.
 */
void squeal_model_classify_sliding(const squeal_params_t *p,
				   const squeal_point_t *point,
				   squeal_criterion_t criterion,
				   squeal_result_t *out);

#endif /* SQUEAL_MODEL_INTERNAL_H */
