/* SPDX-License-Identifier: MIT */
#include "fixmath.h"

/* Integer only, so both numeric builds link it: the fixed model uses all of
 * it, and the input conditioning (firmware/monitor/input_conv.c) takes mu(v0)
 * from fx_exp in either build so that both convert torque identically. */

#define SQRT2_Q30 ((int64_t)1518500250)  /* sqrt(2) * 2^30 */
#define ONE_Q30 ((int64_t)1 << 30)
#define ONE_Q31 ((int64_t)1 << 31)

/* index of the highest set bit, x != 0 (a bounded loop: 6 halvings) */
static int32_t msb_u64(uint64_t x)
{
	int32_t n = 0;
	int32_t shift;

	for (shift = 32; shift > 0; shift >>= 1) {
		if ((x >> (uint32_t)shift) != 0U) {
			x >>= (uint32_t)shift;
			n += shift;
		}
	}
	return n;
}

int64_t fx_ln_u64(uint64_t x, int32_t frac_bits)
{
	int32_t n;
	int64_t m_q31;
	int64_t r_q31;
	int64_t r2;
	int64_t acc;
	int64_t m_q30;

	if (x == 0U) {
		return INT64_MIN / 2;
	}
	n = msb_u64(x); /* x = 2^n * m, m in [1, 2) */
	if (n >= 30) {
		m_q30 = (int64_t)(x >> (uint32_t)(n - 30));
	} else {
		m_q30 = (int64_t)(x << (uint32_t)(30 - n));
	}
	/* move m into [1/sqrt2, sqrt2) so that |r| <= 0.172 below */
	if (m_q30 > SQRT2_Q30) {
		m_q31 = m_q30;      /* m/2 in Q31 */
		n += 1;
	} else {
		m_q31 = m_q30 * 2;  /* m in Q31 */
	}
	/* ln m = 2 atanh(r), r = (m - 1)/(m + 1); series to r^11 (next term
	 * 2 r^13 / 13 < 1.3e-11) */
	r_q31 = ((m_q31 - ONE_Q31) * ONE_Q31) / (m_q31 + ONE_Q31);
	r2 = (r_q31 * r_q31) >> 31;
	acc = ONE_Q31 / 11;
	acc = ONE_Q31 / 9 + ((r2 * acc) >> 31);
	acc = ONE_Q31 / 7 + ((r2 * acc) >> 31);
	acc = ONE_Q31 / 5 + ((r2 * acc) >> 31);
	acc = ONE_Q31 / 3 + ((r2 * acc) >> 31);
	acc = ONE_Q31 + ((r2 * acc) >> 31);
	/* (r * acc) is Q62; 2 r acc in Q32 is that >> 29 */
	return (int64_t)(n - frac_bits) * FX_LN2_Q32 + ((r_q31 * acc) >> 29);
}

/* e^r for 0 <= r < ln 2 (Q32 in, Q30 out in [2^30, 2^31)): Taylor series
 * to r^13/13! (omitted term < 2e-12). */
static int64_t exp_reduced_q30(int64_t r_q32)
{
	const int64_t r = r_q32 >> 2; /* Q30 */
	int64_t acc = ONE_Q30;
	int32_t k;

	for (k = 13; k >= 1; k--) {
		acc = ONE_Q30 + ((r * acc) >> 30) / k;
	}
	return acc;
}

/* Split y = k ln2 + r, 0 <= r < ln 2 (floor division for negative y). */
static int64_t exp_split(int64_t y_q32, int64_t *r_q32)
{
	int64_t k = y_q32 / FX_LN2_Q32;
	int64_t r = y_q32 - k * FX_LN2_Q32;

	if (r < 0) {
		r += FX_LN2_Q32;
		k -= 1;
	}
	*r_q32 = r;
	return k;
}

int64_t fx_exp_q32_to_i64(int64_t y_q32, int32_t q_out, bool *sat)
{
	int64_t r;
	int64_t k;
	int64_t m;
	int64_t shift;

	*sat = false;
	k = exp_split(y_q32, &r);
	m = exp_reduced_q30(r);      /* in [2^30, 2^31) */
	shift = k + q_out - 30;      /* value = m * 2^shift */
	if (shift >= 32) {
		*sat = true;
		return INT64_MAX;
	}
	if (shift >= 0) {
		return m << (uint32_t)shift; /* < 2^63 */
	}
	if (shift <= -40) {
		return 0;
	}
	return (m + ((int64_t)1 << (uint32_t)(-shift - 1))) >> (uint32_t)(-shift);
}

int32_t fx_exp_q32_to_i32(int64_t y_q32, int32_t q_out, bool *sat)
{
	const int64_t v = fx_exp_q32_to_i64(y_q32, q_out, sat);

	if (*sat || (v > INT32_MAX)) {
		*sat = true;
		return INT32_MAX;
	}
	return (int32_t)v;
}

uint32_t fx_expm1_small_q30(int64_t y_q32)
{
	const int64_t y = y_q32 >> 2; /* Q30, in [0, 2^30) */
	int64_t acc = ONE_Q30;
	int32_t k;

	/* e^y - 1 = y (1 + y/2 (1 + y/3 (1 + ...))), to y^16/16! */
	for (k = 16; k >= 2; k--) {
		acc = ONE_Q30 + ((y * acc) >> 30) / k;
	}
	return (uint32_t)((y * acc) >> 30);
}

uint64_t fx_isqrt_u64(uint64_t x)
{
	uint64_t res = 0U;
	uint64_t bit = (uint64_t)1 << 62;
	int32_t i;

	for (i = 0; (i < 32) && (bit > x); i++) {
		bit >>= 2;
	}
	for (i = 0; (i < 32) && (bit != 0U); i++) {
		if (x >= res + bit) {
			x -= res + bit;
			res = (res >> 1) + bit;
		} else {
			res >>= 1;
		}
		bit >>= 2;
	}
	return res;
}

int32_t fx_q32_to_i32(int64_t v_q32, int32_t q_out, bool *sat)
{
	uint32_t sh;
	int64_t v;

	*sat = false;
	if ((q_out < 0) || (q_out > 31) || (v_q32 < -(INT64_MAX / 2))) {
		*sat = true;
		return -INT32_MAX;
	}
	sh = (uint32_t)(32 - q_out);
	/* round half away from zero, symmetric for negative values */
	if (v_q32 >= 0) {
		v = (v_q32 + ((int64_t)1 << (sh - 1U))) >> sh;
	} else {
		v = -((-v_q32 + ((int64_t)1 << (sh - 1U))) >> sh);
	}
	if (v > INT32_MAX) {
		*sat = true;
		return INT32_MAX;
	}
	if (v < -INT32_MAX) {
		*sat = true;
		return -INT32_MAX;
	}
	return (int32_t)v;
}

