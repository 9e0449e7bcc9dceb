/* SPDX-License-Identifier: MIT */
/* Parts of the model API that are the same in both numeric builds. */
#include "squeal_model.h"
#include "squeal_model_internal.h"

#include "sq_contract.h"

#include <stdbool.h>
#include <stddef.h>

/* Domain limits (see squeal_model.h), in the build's format. */
#define MASS_MAX      SQUEAL_NUM_LIMIT(10000, SQUEAL_Q_MASS)
#define OMEGA0_MAX    SQUEAL_NUM_LIMIT(500000, SQUEAL_Q_OMEGA0)
#define DAMPING_MAX   SQUEAL_NUM_LIMIT(1, SQUEAL_Q_DAMPING)
#define SLOPE_MAX     SQUEAL_NUM_LIMIT(20, SQUEAL_Q_SLOPE)
#define V0_MAX        SQUEAL_NUM_LIMIT(100, SQUEAL_Q_V0)
#define FORCE_MAX     SQUEAL_NUM_LIMIT(500000, SQUEAL_Q_FORCE)

/*
 * The paper's disc brake (docs/model.md section 8). Fixed-build values are the
 * nearest raw integers: D = 0.023 * 2^30 = 24696061.95, dmu = 0.15 * 2^30 =
 * 161061273.6 (errors < 1e-9, far below the tests' tolerances).
 */
static const squeal_params_t default_params = {
#if defined(SQUEAL_NUMERIC_FIXED)
	.mass_kg = 1 << SQUEAL_Q_MASS,
	.omega0_radps = 5000 << SQUEAL_Q_OMEGA0,
	.damping = 24696062,
	.mu_inf = 1 << (SQUEAL_Q_MU - 2),
	.delta_mu = 161061274,
	.slope_spm = 2 << SQUEAL_Q_SLOPE,
#else
	.mass_kg = 1.0f,
	.omega0_radps = 5000.0f,
	.damping = 0.023f,
	.mu_inf = 0.25f,
	.delta_mu = 0.15f,
	.slope_spm = 2.0f,
#endif
};

void squeal_model_default_params(squeal_params_t *params)
{
	HAL_REQUIRE(params != NULL);
	*params = default_params;
}

/* lo <= x <= hi: false for NaN and the infinities (float build) as the
 * limits are finite */
static bool in_range(squeal_num_t x, squeal_num_t lo, squeal_num_t hi)
{
	return (x >= lo) && (x <= hi);
}

int squeal_model_params_check(const squeal_params_t *params)
{
	HAL_REQUIRE(params != NULL);
	if (!in_range(params->mass_kg, SQUEAL_NUM_TINY, MASS_MAX) ||
	    !in_range(params->omega0_radps, SQUEAL_NUM_TINY, OMEGA0_MAX) ||
	    !in_range(params->damping, SQUEAL_NUM_TINY, DAMPING_MAX) ||
	    !in_range(params->mu_inf, 0, SQUEAL_MU_MAX) ||
	    !in_range(params->delta_mu, -SQUEAL_MU_MAX, SQUEAL_MU_MAX) ||
	    !in_range(params->slope_spm, 0, SLOPE_MAX) ||
	    !((squeal_wide_t)params->mu_inf + params->delta_mu >= 0)) {
		return SQ_EINVAL;
	}
	return SQ_OK;
}

/* The operating point against the documented domain: SQ_OK or SQ_EINVAL. */
static int point_check(const squeal_point_t *point)
{
	if (!in_range(point->v0_mps, 0, V0_MAX) || !in_range(point->force_n, 0, FORCE_MAX)) {
		return SQ_EINVAL;
	}
	return SQ_OK;
}

const char *squeal_model_state_name(squeal_state_t state)
{
	/* the classes 0 .. SQUEAL_STATE_NAMED - 1, in their values' order:
	 * the one spelling of these names (the bus's are the same) */
	static const char *const class_names[SQUEAL_STATE_NAMED] = {
		"stable", "bistable", "unstable", "not_sliding"
	};

	if ((unsigned int)state < SQUEAL_STATE_NAMED) {
		return class_names[state];
	}
	return (state == SQUEAL_STATE_INVALID) ? "invalid" : "?";
}

void squeal_model_result_clear(squeal_result_t *out, squeal_state_t state)
{
	*out = (squeal_result_t){ .state = state }; /* no flags, every value 0 */
}

/* Which domain rule the calibration and point fall under. */
static squeal_case_t model_case(const squeal_params_t *params, const squeal_point_t *point)
{
	if ((squeal_model_params_check(params) != SQ_OK) ||
	    (point_check(point) != SQ_OK)) {
		return SQUEAL_CASE_INVALID;
	}
	/* both are >= 0 here: "not > 0" is "== 0" without an exact float
	 * comparison */
	if (!(point->v0_mps > 0) || !(point->force_n > 0)) {
		return SQUEAL_CASE_NOT_SLIDING;
	}
	if (!(params->slope_spm > 0) || !(params->delta_mu > 0)) {
		/* friction does not fall with speed: no border, no cycle */
		return SQUEAL_CASE_NO_BORDER;
	}
	return SQUEAL_CASE_SLIDING;
}

/*
 * The domain rules of squeal_model.h (model_case); the sliding case
 * itself is each build's squeal_model_classify_sliding(). One source for
 * both entry points below, inlined into each (the 1 ms step calls
 * squeal_model_classify: no extra call layer).
 */
static inline squeal_case_t classify_case(const squeal_params_t *params,
					  const squeal_point_t *point,
					  squeal_criterion_t criterion,
					  squeal_result_t *out, squeal_log_terms_t *t)
{
	squeal_case_t c = model_case(params, point);

	if ((c == SQUEAL_CASE_INVALID) ||
	    ((criterion != SQUEAL_CRITERION_EXACT) &&
	     (criterion != SQUEAL_CRITERION_CUBIC))) {
		squeal_model_result_clear(out, SQUEAL_STATE_INVALID);
		c = SQUEAL_CASE_INVALID;
	} else if (c == SQUEAL_CASE_NOT_SLIDING) {
		squeal_model_result_clear(out, SQUEAL_STATE_NOT_SLIDING);
	} else {
		squeal_model_result_clear(out, SQUEAL_STATE_STABLE);
		if (c == SQUEAL_CASE_SLIDING) {
			squeal_model_classify_sliding(params, point, criterion, out, t);
		}
	}
	return c;
}

squeal_case_t squeal_model_classify_case(const squeal_params_t *params,
					 const squeal_point_t *point,
					 squeal_criterion_t criterion,
					 squeal_result_t *out, squeal_log_terms_t *t)
{
	return classify_case(params, point, criterion, out, t);
}

int squeal_model_classify(const squeal_params_t *params,
			  const squeal_point_t *point,
			  squeal_criterion_t criterion,
			  squeal_result_t *out)
{
	squeal_log_terms_t t;

	HAL_REQUIRE((params != NULL) && (point != NULL) && (out != NULL));
	return (classify_case(params, point, criterion, out, &t) == SQUEAL_CASE_INVALID) ?
		SQ_EINVAL : SQ_OK;
}
