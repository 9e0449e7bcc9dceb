/* SPDX-License-Identifier: MIT */
/* Parts of the model API that are the same in both numeric builds. */
#include "squeal_model.h"
#include "squeal_model_internal.h"

#include "sq_contract.h"

#include <stddef.h>

/*
 * The paper's disc brake (model.md section 8). Fixed-build values are the
 * nearest raw integers: D = 0.023 * 2^30 = 24696061.95, dmu = 0.15 * 2^30 =
 * 161061273.6 (errors < 1e-9, far below the tests' tolerances).
 */
void squeal_model_default_params(squeal_params_t *params)
{
	HAL_REQUIRE(params != NULL);
#if defined(SQUEAL_NUMERIC_FIXED)
	params->mass_kg = 1 << SQUEAL_Q_MASS;
	params->omega0_radps = 5000 << SQUEAL_Q_OMEGA0;
	params->damping = 24696062;
	params->mu_inf = 1 << (SQUEAL_Q_MU - 2);
	params->delta_mu = 161061274;
	params->slope_spm = 2 << SQUEAL_Q_SLOPE;
#else
	params->mass_kg = 1.0f;
	params->omega0_radps = 5000.0f;
	params->damping = 0.023f;
	params->mu_inf = 0.25f;
	params->delta_mu = 0.15f;
	params->slope_spm = 2.0f;
#endif
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
	out->state = state;
	out->flags = 0U;
	out->ln_q = 0;
	out->hopf_v0_mps = 0;
	out->hopf_margin_mps = 0;
	out->hopf_force_n = 0;
	out->cycle_x = 0;
	out->lc_amplitude_um = 0;
	out->trigger_velocity_mps = 0;
	out->basin_ratio = 0;
}

/* Which domain rule the calibration and point fall under. */
static squeal_case_t model_case(const squeal_params_t *params, const squeal_point_t *point)
{
	if ((squeal_model_params_check(params) != SQ_OK) ||
	    (squeal_model_point_check(point) != SQ_OK)) {
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
