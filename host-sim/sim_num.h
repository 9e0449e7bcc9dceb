/* SPDX-License-Identifier: MIT */
/*
 * Host-side conversion between double (what a user types, what we print)
 * and the model's squeal_num_t (float, or int32 with a field's Q-format).
 */
#ifndef SIM_NUM_H
#define SIM_NUM_H

#include "squeal_model.h"

/* Convert; the fixed build rounds to nearest and saturates (NaN -> INT32_MIN,
 * so the model rejects it). Returns 0, or -1 when the value was not
 * representable exactly enough (saturated or NaN). */
int sim_num_from_double(double value, int q, squeal_num_t *out);
double sim_num_to_double(squeal_num_t value, int q);

/* A calibration/point from doubles (SI units). Returns 0 or -1 as above. */
typedef struct {
	double mass_kg;
	double omega0_radps;
	double damping;
	double mu_inf;
	double delta_mu;
	double slope_spm;
} sim_params_d_t;

/* The firmware's default brake (squeal_model_default_params, the one
 * definition), each parameter as the decimal it was written as. */
void sim_params_default(sim_params_d_t *p);
int sim_params_to_model(const sim_params_d_t *in, squeal_params_t *out);
int sim_point_to_model(double v0_mps, double force_n, squeal_point_t *out);

#endif /* SIM_NUM_H */
