/* SPDX-License-Identifier: MIT */
/*
 * Integer-only elementary functions for the fixed-point build of the model.
 * Logarithms are returned in Q32 (int64_t): ln of any positive 64-bit Q-format
 * value fits with ~1e-9 absolute error. Exponentials take a Q32 argument and
 * return a value in a requested Q-format, saturating (and saying so) instead
 * of overflowing. Bounded loops only; 64-bit integer multiply/divide (libgcc's
 * __aeabi_lmul/__aeabi_ldivmod on Cortex-M) and no floating point at all.
 */
#ifndef FIXMATH_H
#define FIXMATH_H

#include <stdbool.h>
#include <stdint.h>

#define FX_ONE_Q32 ((int64_t)1 << 32)
#define FX_LN2_Q32 ((int64_t)2977044472)   /* ln 2 * 2^32 */

/* ln(x / 2^frac_bits) in Q32, for x > 0; INT64_MIN / 2 for x == 0. */
int64_t fx_ln_u64(uint64_t x, int32_t frac_bits);

/* e^(y / 2^32) as a Q(q_out) int32. Clamps to INT32_MAX and sets *sat when
 * it does not fit; underflows to 0 (without *sat). q_out in [0, 62]. */
int32_t fx_exp_q32_to_i32(int64_t y_q32, int32_t q_out, bool *sat);

/* e^(y / 2^32) as a Q(q_out) int64 (same rules, clamp INT64_MAX). */
int64_t fx_exp_q32_to_i64(int64_t y_q32, int32_t q_out, bool *sat);

/* e^y - 1 for 0 <= y < 1 (y in Q32), result Q30. */
uint32_t fx_expm1_small_q30(int64_t y_q32);

/* floor(sqrt(x)) */
uint64_t fx_isqrt_u64(uint64_t x);

/* Round a Q32 value to Q(q_out) int32, saturating; *sat set if clamped. */
int32_t fx_q32_to_i32(int64_t v_q32, int32_t q_out, bool *sat);

#endif /* FIXMATH_H */
