/* SPDX-License-Identifier: MIT */
#include "model_adapter.h"

#include <stdbool.h>
#include <stddef.h>

#include "hal.h"

#if defined(SQUEAL_NUMERIC_FIXED)

_Static_assert(SQUEAL_Q_MARGIN == 16, "the margin is Q16: model_adapter_margin_q16 copies it");

/* round(v * mul / 2^q) for v >= 0 or < 0, clamped to int32 */
static int32_t q_to_int(int32_t v, int64_t mul, uint32_t q)
{
	int64_t x = (int64_t)v * mul;
	const int64_t half = (int64_t)1 << (q - 1U);

	x = (x >= 0) ? ((x + half) / ((int64_t)1 << q)) : -((-x + half) / ((int64_t)1 << q));
	if (x > INT32_MAX) {
		return INT32_MAX;
	}
	if (x < -INT32_MAX) {
		return -INT32_MAX;
	}
	return (int32_t)x;
}

static void point_from_int(int32_t v0_umps, int32_t force_mn, squeal_point_t *pt)
{
	/* um/s -> Q20 m/s and mN -> Q12 N, rounded; inputs are >= 0 */
	pt->v0_mps = (int32_t)((((int64_t)v0_umps * ((int64_t)1 << SQUEAL_Q_V0)) + 500000) /
			       1000000);
	pt->force_n = (int32_t)((((int64_t)force_mn * ((int64_t)1 << SQUEAL_Q_FORCE)) + 500) /
				1000);
}

#define TO_INT(val, mul, q) q_to_int((val), (mul), (q))

#else

static int32_t f_to_int(float v, float mul)
{
	const float x = v * mul;

	if (!(x < 2147483520.0f)) { /* also NaN: never produced by the model */
		return INT32_MAX;
	}
	if (x < -2147483520.0f) {
		return -INT32_MAX;
	}
	return (int32_t)((x >= 0.0f) ? (x + 0.5f) : (x - 0.5f));
}

static void point_from_int(int32_t v0_umps, int32_t force_mn, squeal_point_t *pt)
{
	pt->v0_mps = (float)v0_umps * 1.0e-6f;
	pt->force_n = (float)force_mn * 1.0e-3f;
}

#define TO_INT(val, mul, q) f_to_int((val), (float)(mul))

#endif

static uint32_t has_if(const squeal_result_t *r, uint32_t has, uint32_t sat,
		       uint32_t bit)
{
	return (((r->flags & has) != 0U) && ((r->flags & sat) == 0U)) ? bit : 0U;
}

int model_adapter_eval(const squeal_params_t *params,
		       squeal_criterion_t criterion,
		       int32_t v0_umps, int32_t force_mn, model_eval_t *out)
{
	return model_adapter_eval_sd(params, NULL, criterion, v0_umps, force_mn, out, NULL);
}

int model_adapter_eval_sd(const squeal_params_t *params, const squeal_param_sd_t *sd,
			  squeal_criterion_t criterion, int32_t v0_umps, int32_t force_mn,
			  model_eval_t *out, squeal_sigma_result_t *sig)
{
	squeal_point_t pt;
	squeal_result_t r;
	int rc;

	HAL_REQUIRE((params != NULL) && (out != NULL));
	if ((v0_umps < 0) || (force_mn < 0)) {
		/* the model would say invalid too; keep integers out of UB */
		v0_umps = -1;
		force_mn = -1;
	}
	point_from_int(v0_umps, force_mn, &pt);
	/* without deviations the classification alone (the 1 ms step's
	 * common case: no propagation layer to pass through) */
	rc = (sd == NULL) ? squeal_model_classify(params, &pt, criterion, &r) :
		squeal_sigma_classify(params, sd, &pt, criterion, &r, sig);
	out->state = r.state;
	out->has = has_if(&r, SQUEAL_HAS_HOPF_V0, SQUEAL_SAT_HOPF_V0, MODEL_EVAL_HAS_HOPF_V0) |
		   has_if(&r, SQUEAL_HAS_HOPF_FORCE, 0U, MODEL_EVAL_HAS_HOPF_FORCE) |
		   has_if(&r, SQUEAL_HAS_CYCLE, SQUEAL_SAT_AMPLITUDE | SQUEAL_SAT_TRIGGER,
			  MODEL_EVAL_HAS_CYCLE) |
		   has_if(&r, SQUEAL_HAS_BASIN, SQUEAL_SAT_BASIN, MODEL_EVAL_HAS_BASIN) |
		   has_if(&r, SQUEAL_HAS_LNQ, 0U, MODEL_EVAL_HAS_LNQ);
	/* ln(2Q) = ln Q + ln 2 */
	out->ln_2q_micro = ((out->has & MODEL_EVAL_HAS_LNQ) != 0U) ?
		TO_INT(r.ln_q, 1000000, SQUEAL_Q_LNQ) + 693147 : 0;
	out->hopf_v0_umps = ((out->has & MODEL_EVAL_HAS_HOPF_V0) != 0U) ?
		TO_INT(r.hopf_v0_mps, 1000000, SQUEAL_Q_V0) : 0;
	out->hopf_margin_umps = ((out->has & MODEL_EVAL_HAS_HOPF_V0) != 0U) ?
		TO_INT(r.hopf_margin_mps, 1000000, SQUEAL_Q_V0) : 0;
	out->hopf_force_mn = ((out->has & MODEL_EVAL_HAS_HOPF_FORCE) != 0U) ?
		(((r.flags & SQUEAL_SAT_HOPF_FORCE) != 0U) ? INT32_MAX :
		 TO_INT(r.hopf_force_n, 1000, SQUEAL_Q_FORCE)) : 0;
	out->lc_amplitude_nm = ((out->has & MODEL_EVAL_HAS_CYCLE) != 0U) ?
		TO_INT(r.lc_amplitude_um, 1000, SQUEAL_Q_AMPL_UM) : 0;
	out->trigger_velocity_umps = ((out->has & MODEL_EVAL_HAS_CYCLE) != 0U) ?
		TO_INT(r.trigger_velocity_mps, 1000000, SQUEAL_Q_V0) : 0;
	out->basin_ratio_ppm = ((out->has & MODEL_EVAL_HAS_BASIN) != 0U) ?
		TO_INT(r.basin_ratio, 1000000, SQUEAL_Q_RATIO) : 0;
	/* rounding to ppm must not move rho across 1 (the class decides) */
	if ((r.state == SQUEAL_STATE_BISTABLE) && (out->basin_ratio_ppm >= 1000000)) {
		out->basin_ratio_ppm = 999999;
	}
	return rc;
}

int model_adapter_sigma(const squeal_params_t *params, const squeal_param_sd_t *sd,
			int32_t v0_umps, int32_t force_mn, squeal_sigma_result_t *out)
{
	squeal_point_t pt;
	/* as model_adapter_eval: negative inputs are invalid to the model */
	const bool neg = (v0_umps < 0) || (force_mn < 0);

	HAL_REQUIRE((params != NULL) && (sd != NULL) && (out != NULL));
	point_from_int(neg ? -1 : v0_umps, neg ? -1 : force_mn, &pt);
	return squeal_sigma_eval(params, sd, &pt, out);
}

int32_t model_adapter_margin_q16(const squeal_sigma_result_t *r, squeal_state_t state)
{
	squeal_num_t m = SQUEAL_SIGMA_MARGIN_MAX;
	int32_t q = MODEL_MARGIN_NONE;

	HAL_REQUIRE(r != NULL);
	if (squeal_sigma_margin(r, state, &m) == SQ_OK) {
#if defined(SQUEAL_NUMERIC_FIXED)
		q = m; /* SQUEAL_Q_MARGIN == 16, checked above */
#else
		q = f_to_int(m, 65536.0f);
#endif
	}
	return (q >= MODEL_MARGIN_NONE) ? MODEL_MARGIN_NONE : q;
}
