/* SPDX-License-Identifier: MIT */
#include "sim_num.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

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

/*
 * A model number as the decimal it was written as: the firmware stores its
 * decimal parameters as float (24-bit significand) or in a Q-format of at
 * least 2^-24 resolution, both within a part in 10^7 of the decimal, so
 * the FLT_DIG (6) significant digits read back are that decimal, and
 * strtod gives the double nearest to it (0.023, not 0.0230000004).
 */
static double sim_num_decimal(squeal_num_t value, int q)
{
	char text[32];
	const int n = snprintf(text, sizeof(text), "%.*e", FLT_DIG - 1, sim_num_to_double(value, q));

	return ((n > 0) && ((size_t)n < sizeof(text))) ? strtod(text, NULL) : sim_num_to_double(value, q);
}

void sim_params_default(sim_params_d_t *p)
{
	squeal_params_t fw;

	squeal_model_default_params(&fw); /* the one definition of the brake */
	p->mass_kg = sim_num_decimal(fw.mass_kg, SQUEAL_Q_MASS);
	p->omega0_radps = sim_num_decimal(fw.omega0_radps, SQUEAL_Q_OMEGA0);
	p->damping = sim_num_decimal(fw.damping, SQUEAL_Q_DAMPING);
	p->mu_inf = sim_num_decimal(fw.mu_inf, SQUEAL_Q_MU);
	p->delta_mu = sim_num_decimal(fw.delta_mu, SQUEAL_Q_MU);
	p->slope_spm = sim_num_decimal(fw.slope_spm, SQUEAL_Q_SLOPE);
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
