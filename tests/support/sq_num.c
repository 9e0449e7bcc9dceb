/* SPDX-License-Identifier: MIT */
#include "sq_num.h"

#include <float.h>
#include <math.h>
#include <stdint.h>

#if defined(SQUEAL_NUMERIC_FIXED)

squeal_num_t sq_num_from_double(double v, int q)
{
	double scaled;

	if (isnan(v)) {
		return INT32_MIN;
	}
	if (!(fabs(v) < 0x1p40)) {
		return (v > 0.0) ? INT32_MAX : INT32_MIN;
	}
	scaled = ldexp(v, q);
	if (scaled >= 2147483647.0) {
		return INT32_MAX;
	}
	if (scaled <= -2147483648.0) {
		return INT32_MIN;
	}
	return (int32_t)floor(scaled + 0.5);
}

double sq_num_to_double(squeal_num_t n, int q)
{
	return ldexp((double)n, -q);
}

double sq_num_field_max(int q)
{
	return ldexp(2147483647.0, -q);
}

double sq_num_lsb(int q)
{
	return ldexp(1.0, -q);
}

const char *sq_num_build_name(void)
{
	return "fixed";
}

bool sq_num_is_fixed(void)
{
	return true;
}

#else /* float */

squeal_num_t sq_num_from_double(double v, int q)
{
	/* Half-way between FLT_MAX and 2^128: IEEE rounds this and above to
	 * infinity (FLT_MAX has an odd significand). Done explicitly, because
	 * converting an out-of-range double to float is undefined in C. */
	const double overflow = 0x1.ffffffp127;

	(void)q;
	if (isnan(v)) {
		return (float)v;
	}
	if (v >= overflow) {
		return INFINITY;
	}
	if (v <= -overflow) {
		return -INFINITY;
	}
	return (float)v;
}

double sq_num_to_double(squeal_num_t n, int q)
{
	(void)q;
	return (double)n;
}

double sq_num_field_max(int q)
{
	(void)q;
	return (double)FLT_MAX;
}

double sq_num_lsb(int q)
{
	(void)q;
	return 0.0;
}

const char *sq_num_build_name(void)
{
	return "float";
}

bool sq_num_is_fixed(void)
{
	return false;
}

#endif

bool sq_num_exact(double v, int q)
{
	double back = sq_num_to_double(sq_num_from_double(v, q), q);

	if (isnan(v)) {
		return false;
	}
	return back == v;
}
