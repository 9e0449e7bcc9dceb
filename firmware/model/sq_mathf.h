/* SPDX-License-Identifier: MIT */
/*
 * Single-precision elementary functions for the float build of the model.
 * firmware/ is freestanding (no libm), and the Cortex-M4F FPU is single
 * precision only, so these work in float throughout. Accuracy: a few ulp over
 * the documented argument ranges (proved against numpy in tests/firmware/model).
 */
#ifndef SQ_MATHF_H
#define SQ_MATHF_H

#include <stdbool.h>
#include <stdint.h>

#define SQ_LN2F 0.693147180559945309f

/* true when x is neither NaN nor infinite */
bool sq_isfinitef(float x);
/* natural log, x > 0 finite (subnormals handled); returns -FLT_MAX otherwise */
float sq_lnf(float x);
/* ln(1 + y), y > -1; accurate for small |y| */
float sq_log1pf(float y);
/* e^x for x in [-87, 88]; clamps outside */
float sq_expf(float x);
/* e^x - 1, accurate for small |x|; x <= 88 */
float sq_expm1f(float x);
/* square root, x >= 0 finite; 0 otherwise */
float sq_sqrtf(float x);

/*
 * Extended-range non-negative numbers m * 2^e (m in [1, 2), or m = 0) for
 * the quotients and products of the model's outputs, whose intermediates may
 * leave float's range although the result fits (or must be reported as not
 * fitting). Each operation rounds like one float operation.
 */
typedef struct {
	float m;
	int32_t e;
} sq_xf_t;

sq_xf_t sq_xf_from(float x);          /* x >= 0 finite (subnormals too) */
sq_xf_t sq_xf_exp(float y);           /* e^y for |y| < 2^20            */
sq_xf_t sq_xf_mul(sq_xf_t a, sq_xf_t b);
sq_xf_t sq_xf_div(sq_xf_t a, sq_xf_t b); /* b != 0                      */
/* as a float: FLT_MAX and *sat = true beyond its range; gradual underflow */
float sq_xf_to_float(sq_xf_t a, bool *sat);

#endif /* SQ_MATHF_H */
