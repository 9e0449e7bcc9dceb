/* SPDX-License-Identifier: MIT */
/*
 * sq_num: test-side conversion between double and squeal_num_t.
 *
 * Float build: squeal_num_t is float; a double is rounded to nearest (IEEE),
 * overflowing to +-inf exactly as a float conversion would, NaN stays NaN.
 * Fixed build: squeal_num_t holds raw = round(v 2^q) for the field's
 * SQUEAL_Q_* format; the conversion rounds half up (floor(v 2^q + 0.5)),
 * saturates to INT32_MIN/INT32_MAX outside the format's range and maps NaN
 * to INT32_MIN. Every saturated value lies outside the model's input domain,
 * so squeal_model.h says it must be classified INVALID.
 * tests/support/reference/squeal_reference.py (to_float32, to_fixed_raw) mirrors
 * these rules; keep them identical.
 *
 * Test code only: uses double and libm.
 */
#ifndef SQ_NUM_H
#define SQ_NUM_H

#include <stdbool.h>

#include "squeal_model.h"

/* Field formats, one per kind of value (the q of the fixed build). */
squeal_num_t sq_num_from_double(double v, int q);
double sq_num_to_double(squeal_num_t n, int q);
/* Largest magnitude a field can hold: FLT_MAX, or (2^31 - 1) / 2^q. */
double sq_num_field_max(int q);
/* One least significant bit of a field: 0 for float, 2^-q for fixed. */
double sq_num_lsb(int q);
/* True when v converts without rounding or saturation. */
bool sq_num_exact(double v, int q);
/* "float" or "fixed". */
const char *sq_num_build_name(void);
bool sq_num_is_fixed(void);

#endif /* SQ_NUM_H */
