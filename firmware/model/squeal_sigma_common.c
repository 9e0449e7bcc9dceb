/* SPDX-License-Identifier: MIT */
/* Parts of squeal_sigma.h that are the same in both numeric builds: domain
 * rules, the cases without a border, and which border a class is next to. */
#include <stdbool.h>
#include <stddef.h>

#include "squeal_model.h"
#include "squeal_model_internal.h"
#include "squeal_sigma.h"
#include "sq_contract.h"
#include "squeal_sigma_internal.h"

#define NUM_ZERO ((squeal_num_t)0)

/* 0 <= sd <= |value| (false for NaN in the float build) */
static bool sd_within(squeal_num_t sd, squeal_num_t value)
{
	const squeal_num_t mag = (value < NUM_ZERO) ? -value : value;

	return (sd >= NUM_ZERO) && (sd <= mag);
}

void squeal_sigma_sd_zero(squeal_param_sd_t *sd)
{
	HAL_REQUIRE(sd != NULL);
	*sd = (squeal_param_sd_t){ 0 };
}

int squeal_sigma_sd_check(const squeal_params_t *params,
			  const squeal_param_sd_t *sd)
{
	HAL_REQUIRE((params != NULL) && (sd != NULL));
	if (!sd_within(sd->mass_kg_sd, params->mass_kg) ||
	    !sd_within(sd->omega0_radps_sd, params->omega0_radps) ||
	    !sd_within(sd->damping_sd, params->damping) ||
	    !sd_within(sd->mu_inf_sd, SQUEAL_MU_MAX) ||
	    !sd_within(sd->delta_mu_sd, params->delta_mu) ||
	    !sd_within(sd->slope_spm_sd, params->slope_spm) ||
	    !(sd->slope_delta_mu_corr >= -SQUEAL_SIGMA_CORR_ONE) ||
	    !(sd->slope_delta_mu_corr <= SQUEAL_SIGMA_CORR_ONE)) {
		return SQ_EINVAL;
	}
	return SQ_OK;
}

static void result_clear(squeal_sigma_result_t *out, squeal_state_t state)
{
	/* no flags, no borders; the margin of no border, none for INVALID */
	*out = (squeal_sigma_result_t){
		.state = state,
		.margin_sigma = (state == SQUEAL_STATE_INVALID) ? 0 : SQUEAL_SIGMA_MARGIN_MAX,
	};
}

int squeal_sigma_margin(const squeal_sigma_result_t *r, squeal_state_t state,
			squeal_num_t *margin)
{
	squeal_num_t to_hopf;
	squeal_num_t to_stable;

	HAL_REQUIRE((r != NULL) && (margin != NULL));
	if ((r->flags & SQUEAL_SIGMA_HAS_BORDERS) == 0U) {
		*margin = SQUEAL_SIGMA_MARGIN_MAX;
		return SQ_OK;
	}
	to_hopf = squeal_sigma_distance(r->g_hopf, r->sigma_hopf);
	to_stable = squeal_sigma_distance(r->g_stable, r->sigma_stable);
	switch (state) {
	case SQUEAL_STATE_UNSTABLE:
		*margin = to_hopf;
		break;
	case SQUEAL_STATE_STABLE:
		*margin = to_stable;
		break;
	case SQUEAL_STATE_BISTABLE:
		*margin = (to_hopf < to_stable) ? to_hopf : to_stable;
		break;
	default:
		*margin = SQUEAL_SIGMA_MARGIN_MAX;
		break;
	}
	return SQ_OK;
}

int squeal_sigma_classify(const squeal_params_t *params,
			  const squeal_param_sd_t *sd,
			  const squeal_point_t *point,
			  squeal_criterion_t criterion,
			  squeal_result_t *out,
			  squeal_sigma_result_t *sig)
{
	squeal_log_terms_t t;
	squeal_case_t c;

	HAL_REQUIRE((params != NULL) && (point != NULL) && (out != NULL));
	HAL_REQUIRE((sd == NULL) == (sig == NULL));
	c = squeal_model_classify_case(params, point, criterion, out, &t);
	if (sd != NULL) {
		if ((c == SQUEAL_CASE_INVALID) || (squeal_sigma_sd_check(params, sd) != SQ_OK)) {
			result_clear(sig, SQUEAL_STATE_INVALID);
		} else {
			/* the class is the classification's; NOT_SLIDING and
			 * NO_BORDER have no border to be near */
			result_clear(sig, out->state);
			if (c == SQUEAL_CASE_SLIDING) {
				/* an unstable point's classification stopped
				 * before the stable border: computed here, once */
				squeal_model_stable_border(&t, criterion);
				squeal_sigma_borders(params, sd, &t, sig);
				(void)squeal_sigma_margin(sig, sig->state, &sig->margin_sigma);
			}
		}
	}
	return (c == SQUEAL_CASE_INVALID) ? SQ_EINVAL : SQ_OK;
}

int squeal_sigma_eval(const squeal_params_t *params,
		      const squeal_param_sd_t *sd,
		      const squeal_point_t *point,
		      squeal_sigma_result_t *out)
{
	squeal_result_t model;

	HAL_REQUIRE((params != NULL) && (sd != NULL) && (point != NULL) && (out != NULL));
	(void)squeal_sigma_classify(params, sd, point, SQUEAL_CRITERION_EXACT, &model, out);
	return (out->state == SQUEAL_STATE_INVALID) ? SQ_EINVAL : SQ_OK;
}
