/* SPDX-License-Identifier: MIT */
#include "sim_num.h"

#include <math.h>
#include <stdint.h>

int sim_num_from_double(double value, int q, squeal_num_t *out)
{
#if defined(SQUEAL_NUMERIC_FIXED)
	double scaled;

	if (isnan(value)) {
		*out = INT32_MIN;
		return -1;
	}
	scaled = nearbyint(ldexp(value, q));
	if (scaled > (double)INT32_MAX) {
		*out = INT32_MAX;
		return -1;
	}
	if (scaled < (double)INT32_MIN) {
		*out = INT32_MIN;
		return -1;
	}
	*out = (int32_t)scaled;
	return 0;
#else
	(void)q;
	*out = (float)value;
	return (isfinite(value) && !isfinite(*out)) ? -1 : 0;
#endif
}

double sim_num_to_double(squeal_num_t value, int q)
{
#if defined(SQUEAL_NUMERIC_FIXED)
	return ldexp((double)value, -q);
#else
	(void)q;
	return (double)value;
#endif
}

void sim_params_default(sim_params_d_t *p)
{
	p->mass_kg = 1.0;
	p->omega0_radps = 5000.0;
	p->damping = 0.023;
	p->mu_inf = 0.25;
	p->delta_mu = 0.15;
	p->slope_spm = 2.0;
}

int sim_params_to_model(const sim_params_d_t *in, squeal_params_t *out)
{
	int rc = 0;

	rc |= sim_num_from_double(in->mass_kg, SQUEAL_Q_MASS, &out->mass_kg);
	rc |= sim_num_from_double(in->omega0_radps, SQUEAL_Q_OMEGA0, &out->omega0_radps);
	rc |= sim_num_from_double(in->damping, SQUEAL_Q_DAMPING, &out->damping);
	rc |= sim_num_from_double(in->mu_inf, SQUEAL_Q_MU, &out->mu_inf);
	rc |= sim_num_from_double(in->delta_mu, SQUEAL_Q_MU, &out->delta_mu);
	rc |= sim_num_from_double(in->slope_spm, SQUEAL_Q_SLOPE, &out->slope_spm);
	return rc;
}

int sim_point_to_model(double v0_mps, double force_n, squeal_point_t *out)
{
	int rc = 0;

	rc |= sim_num_from_double(v0_mps, SQUEAL_Q_V0, &out->v0_mps);
	rc |= sim_num_from_double(force_n, SQUEAL_Q_FORCE, &out->force_n);
	return rc;
}
