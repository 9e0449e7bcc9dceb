/* SPDX-License-Identifier: MIT */
/*
 * Float build of squeal_sigma.h: the first-order sigmas of the two border
 * functions (derivatives in the header comment), from the model's own
 * log-domain terms and its G(s) = ln(2 I1(s)/s) with G'(s).
 */
#if !defined(SQUEAL_NUMERIC_FIXED)

#include "sq_mathf.h"
#include "squeal_model_internal.h"
#include "squeal_sigma.h"
#include "squeal_sigma_internal.h"

/* sqrt(base + e^2 - 2 rho e r_dmu); >= 0 mathematically for |rho| <= 1,
 * clamped against rounding */
static float combine_f(float base, float e, float rho, float r_dmu)
{
	const float var = base + e * e - 2.0f * rho * e * r_dmu;

	return (var > 0.0f) ? sq_sqrtf(var) : 0.0f;
}

void squeal_sigma_borders(const squeal_params_t *p, const squeal_param_sd_t *sd,
			  const squeal_log_terms_t *t, squeal_sigma_result_t *out)
{
	const float r_m = sd->mass_kg_sd / p->mass_kg;
	const float r_w0 = sd->omega0_radps_sd / p->omega0_radps;
	const float r_d = sd->damping_sd / p->damping;
	const float r_dmu = sd->delta_mu_sd / p->delta_mu;
	const float r_a = sd->slope_spm_sd / p->slope_spm;
	const float rho = sd->slope_delta_mu_corr;
	float base;

	out->g_hopf = t->c2 + t->s;
	out->g_stable = t->stable_lhs - t->stable_rhs;
	base = r_m * r_m + r_w0 * r_w0 + r_d * r_d + r_dmu * r_dmu;
	/* a dg_H/da = s - 1;  a dg_S/da = -s H'(s) - 1 (H of the criterion) */
	out->sigma_hopf = combine_f(base, r_a * (t->s - 1.0f), rho, r_dmu);
	out->sigma_stable = combine_f(base, r_a * (-t->s * t->stable_dh - 1.0f), rho, r_dmu);
	out->flags = SQUEAL_SIGMA_HAS_BORDERS;
}

squeal_num_t squeal_sigma_distance(squeal_num_t g, squeal_num_t sigma)
{
	const float mag = (g < 0.0f) ? -g : g;

	if (!(sigma > 0.0f) || (mag >= SQUEAL_SIGMA_MARGIN_MAX * sigma)) {
		return SQUEAL_SIGMA_MARGIN_MAX;
	}
	return mag / sigma;
}

#endif /* !SQUEAL_NUMERIC_FIXED */
