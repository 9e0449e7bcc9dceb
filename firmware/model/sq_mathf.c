/* SPDX-License-Identifier: MIT */
#include "sq_mathf.h"

#include <float.h>
#include <stdint.h>

#if !defined(SQUEAL_NUMERIC_FIXED)

/* ln 2 split so that k * LN2_HI is exact for |k| < 2^11 */
#define LN2_HI 0.693145751953125f
#define LN2_LO 1.428606765330187e-06f
#define INV_LN2 1.442695040888963f
#define SQRT2 1.41421356237f

typedef union {
	float f;
	uint32_t u;
} f32_bits_t;

bool sq_isfinitef(float x)
{
	f32_bits_t v = { .f = x };

	return ((v.u >> 23) & 0xffU) != 0xffU;
}

/* 2 atanh(r) = ln((1 + r) / (1 - r)) for |r| <= 0.172 (m in [1/sqrt2, sqrt2]).
 * The series' first omitted term is 2 r^13 / 13 < 1.3e-11. */
static float atanh2_series(float r)
{
	const float r2 = r * r;
	const float p = 1.0f + r2 * (1.0f / 3.0f + r2 * (1.0f / 5.0f +
			r2 * (1.0f / 7.0f + r2 * (1.0f / 9.0f + r2 * (1.0f / 11.0f)))));

	return 2.0f * r * p;
}

float sq_lnf(float x)
{
	f32_bits_t v = { .f = x };
	int32_t e = 0;
	float m;
	float r;
	float kf;

	if (!(x > 0.0f) || !sq_isfinitef(x)) {
		return -FLT_MAX;
	}
	if (((v.u >> 23) & 0xffU) == 0U) {
		/* subnormal: scale into the normal range first */
		v.f = x * 8388608.0f; /* 2^23 */
		e = -23;
	}
	e += (int32_t)((v.u >> 23) & 0xffU) - 127;
	v.u = (v.u & 0x007fffffU) | 0x3f800000U; /* mantissa in [1, 2) */
	m = v.f;
	if (m > SQRT2) {
		m *= 0.5f;
		e += 1;
	}
	r = (m - 1.0f) / (m + 1.0f);
	kf = (float)e;
	return kf * LN2_HI + (kf * LN2_LO + atanh2_series(r));
}

float sq_log1pf(float y)
{
	if (!(y > -1.0f) || !sq_isfinitef(y)) {
		return -FLT_MAX;
	}
	if (y > -0.29f && y < 0.41f) {
		/* 1 + y = (1 + r) / (1 - r) with r = y / (2 + y): no cancellation */
		return atanh2_series(y / (2.0f + y));
	}
	return sq_lnf(1.0f + y);
}

/* e^r - 1 for |r| <= 0.35, Taylor to r^8/8! (omitted term < 2e-10) */
static float expm1_reduced(float r)
{
	return r * (1.0f + r * (1.0f / 2.0f + r * (1.0f / 6.0f + r * (1.0f / 24.0f +
		r * (1.0f / 120.0f + r * (1.0f / 720.0f + r * (1.0f / 5040.0f +
		r * (1.0f / 40320.0f))))))));
}

/* Split x = k ln2 + r with |r| <= ln2 / 2. */
static int32_t exp_reduce(float x, float *r)
{
	const float kf = x * INV_LN2;
	const int32_t k = (int32_t)(kf + ((kf >= 0.0f) ? 0.5f : -0.5f));
	const float kk = (float)k;

	*r = (x - kk * LN2_HI) - kk * LN2_LO;
	return k;
}

/* 2^k for k in [-126, 127] */
static float pow2i(int32_t k)
{
	f32_bits_t v;

	v.u = (uint32_t)(k + 127) << 23;
	return v.f;
}

float sq_expf(float x)
{
	float r;
	int32_t k;
	float p;

	if (!(x > -87.0f)) {
		return 0.0f; /* also NaN: callers never pass one */
	}
	if (x > 88.0f) {
		x = 88.0f;
	}
	k = exp_reduce(x, &r);
	p = 1.0f + expm1_reduced(r);
	/* k <= 127 here; for k = 127 scale in two steps to stay normal */
	if (k > 126) {
		return p * pow2i(k - 1) * 2.0f;
	}
	return p * pow2i(k);
}

float sq_expm1f(float x)
{
	if (x > -0.34f && x < 0.34f) {
		return expm1_reduced(x);
	}
	return sq_expf(x) - 1.0f;
}

/* sqrt of a normal, positive float */
static float sqrt_normal(float x)
{
	f32_bits_t v = { .f = x };
	float y;
	int32_t i;

	/* halve the exponent for a first guess within ~4 %, then Newton:
	 * each step doubles the correct bits, 4 steps reach full precision */
	v.u = (v.u >> 1) + 0x1fc00000U;
	y = v.f;
	for (i = 0; i < 4; i++) {
		y = 0.5f * (y + x / y);
	}
	return y;
}

float sq_sqrtf(float x)
{
	if (!(x > 0.0f) || !sq_isfinitef(x)) {
		return 0.0f;
	}
	if (x < FLT_MIN) {
		/* subnormal: sqrt(x) = sqrt(x * 2^24) / 2^12 */
		return sqrt_normal(x * 16777216.0f) * (1.0f / 4096.0f);
	}
	return sqrt_normal(x);
}

sq_xf_t sq_xf_from(float x)
{
	f32_bits_t v = { .f = x };
	sq_xf_t r = { 0.0f, 0 };

	if (!(x > 0.0f) || !sq_isfinitef(x)) {
		return r;
	}
	if (((v.u >> 23) & 0xffU) == 0U) {
		v.f = x * 8388608.0f; /* subnormal: 2^23 */
		r.e = -23;
	}
	r.e += (int32_t)((v.u >> 23) & 0xffU) - 127;
	v.u = (v.u & 0x007fffffU) | 0x3f800000U;
	r.m = v.f;
	return r;
}

static sq_xf_t xf_norm(float m, int32_t e)
{
	sq_xf_t r = { m, e };

	if (!(m > 0.0f)) {
		r.m = 0.0f;
		r.e = 0;
		return r;
	}
	if (r.m >= 2.0f) {
		r.m *= 0.5f;
		r.e += 1;
	} else if (r.m < 1.0f) {
		r.m *= 2.0f;
		r.e -= 1;
	} else {
		/* already in [1, 2) */
	}
	return r;
}

sq_xf_t sq_xf_exp(float y)
{
	float r;
	const int32_t k = exp_reduce(y, &r);

	return xf_norm(1.0f + expm1_reduced(r), k);
}

sq_xf_t sq_xf_mul(sq_xf_t a, sq_xf_t b)
{
	return xf_norm(a.m * b.m, a.e + b.e);
}

sq_xf_t sq_xf_div(sq_xf_t a, sq_xf_t b)
{
	if (!(b.m > 0.0f)) {
		sq_xf_t inf = { 1.0f, 1 << 20 };

		return inf;
	}
	return xf_norm(a.m / b.m, a.e - b.e);
}

float sq_xf_to_float(sq_xf_t a, bool *sat)
{
	*sat = false;
	if (!(a.m > 0.0f)) {
		return 0.0f;
	}
	if (a.e > 127) {
		*sat = true;
		return FLT_MAX;
	}
	if (a.e >= -126) {
		return a.m * pow2i(a.e);
	}
	if (a.e >= -190) {
		/* two steps: the second rounds once into the subnormal range */
		return (a.m * pow2i(a.e + 64)) * pow2i(-64);
	}
	return 0.0f;
}

#endif /* !SQUEAL_NUMERIC_FIXED */
