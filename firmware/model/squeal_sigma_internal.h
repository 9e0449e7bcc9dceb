/* SPDX-License-Identifier: MIT */
/* Per numeric build parts of squeal_sigma.h (squeal_sigma_{float,fixed}.c). */
#ifndef SQUEAL_SIGMA_INTERNAL_H
#define SQUEAL_SIGMA_INTERNAL_H

#include <stdbool.h>

#include "squeal_model_internal.h"
#include "squeal_sigma.h"

/* correlation 1 in the build's format */
#if defined(SQUEAL_NUMERIC_FIXED)
#define SQUEAL_SIGMA_CORR_ONE ((int32_t)1 << SQUEAL_Q_CORR)
#else
#define SQUEAL_SIGMA_CORR_ONE 1.0f
#endif

/*
 * The sliding case with falling friction (v0, N, a, dmu > 0; every input
 * checked): fills g_*, sigma_*, flags from the classification's own terms
 * (t, its stable border set: has_border). State and margin are left to
 * the caller.
 */
void squeal_sigma_borders(const squeal_params_t *p, const squeal_param_sd_t *sd,
			  const squeal_log_terms_t *t, squeal_sigma_result_t *out);

/* |g| / sigma in SQUEAL_Q_MARGIN, capped at SQUEAL_SIGMA_MARGIN_MAX; the
 * cap when sigma is 0. */
squeal_num_t squeal_sigma_distance(squeal_num_t g, squeal_num_t sigma);

#endif /* SQUEAL_SIGMA_INTERNAL_H */
