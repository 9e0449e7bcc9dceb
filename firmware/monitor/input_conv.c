/* SPDX-License-Identifier: MIT */
#include "input_conv.h"

#include <stddef.h>

#include "fixmath.h"
#include "hal.h"
#include "sq_status.h"

#define LIMIT ((int64_t)1 << 30)     /* numerators and denominators stay below */
#define ADD_LIMIT ((int64_t)1 << 61)

/* A fraction n / d, d > 0, both kept below LIMIT in magnitude. */
typedef struct {
	int64_t n;
	int64_t d;
} frac_t;

static int64_t abs64(int64_t v)
{
	return (v < 0) ? -v : v;
}

static int64_t gcd64(int64_t a, int64_t b)
{
	uint32_t guard;

	a = abs64(a);
	b = abs64(b);
	/* Euclid on values below 2^62 needs fewer than 90 steps */
	for (guard = 0U; (b != 0) && (guard < 128U); guard++) {
		const int64_t t = a % b;

		a = b;
		b = t;
	}
	return (a == 0) ? 1 : a;
}

/* Reduce, then halve both until they fit (only for values no DBC uses). */
static frac_t frac_norm(int64_t n, int64_t d)
{
	const int64_t g = gcd64(n, d);
	uint32_t guard;

	n /= g;
	d /= g;
	for (guard = 0U; ((abs64(n) >= LIMIT) || (d >= LIMIT)) && (guard < 64U); guard++) {
		n = (n >= 0) ? ((n + 1) / 2) : ((n - 1) / 2);
		d = (d + 1) / 2;
	}
	return (frac_t){ n, d };
}

static frac_t frac_mul(frac_t a, frac_t b)
{
	/* cross-reduce first so that exact products stay exact */
	const int64_t g1 = gcd64(a.n, b.d);
	const int64_t g2 = gcd64(b.n, a.d);

	return frac_norm((a.n / g1) * (b.n / g2), (a.d / g2) * (b.d / g1));
}

static frac_t frac_pow10(int8_t e)
{
	int64_t p = 1;
	int32_t i;
	const int32_t m = (e < 0) ? -(int32_t)e : (int32_t)e;

	for (i = 0; i < m; i++) {
		p *= 10;
	}
	return (e < 0) ? (frac_t){ 1, p } : (frac_t){ p, 1 };
}

static frac_t frac_of(int64_t n, int64_t d)
{
	return frac_norm(n, d);
}

/* ---- units ---------------------------------------------------------------- */

static const char *const unit_names[INPUT_UNIT_COUNT] = {
	"km/h", "m/s", "mph", "rad/s", "rpm", "N", "kN", "bar", "kPa", "MPa", "psi", "Nm"
};

/* ASCII lower case as a byte value (unit strings are ASCII) */
static uint8_t lower(char c)
{
	const uint8_t u = (uint8_t)c;

	return ((u >= 0x41U) && (u <= 0x5AU)) ? (uint8_t)(u + 0x20U) : u;
}

/* a equals the short literal b, ignoring case; the loop runs along b */
static bool same_nocase(const char *a, const char *b)
{
	uint32_t i;

	for (i = 0U; b[i] != '\0'; i++) {
		if (lower(a[i]) != lower(b[i])) {
			return false;
		}
	}
	return a[i] == '\0';
}

int input_unit_parse(const char *s, input_unit_t *unit)
{
	uint32_t i;

	HAL_REQUIRE((s != NULL) && (unit != NULL));
	if (same_nocase(s, "kph")) {
		*unit = INPUT_UNIT_KMH;
		return SQ_OK;
	}
	if (same_nocase(s, "1/min")) {
		*unit = INPUT_UNIT_RPM;
		return SQ_OK;
	}
	for (i = 0U; i < (uint32_t)INPUT_UNIT_COUNT; i++) {
		if (same_nocase(s, unit_names[i])) {
			*unit = (input_unit_t)i;
			return SQ_OK;
		}
	}
	return SQ_ENOENT;
}

const char *input_unit_name(input_unit_t unit)
{
	return ((uint32_t)unit < (uint32_t)INPUT_UNIT_COUNT) ? unit_names[unit] : "?";
}

input_qty_t input_unit_qty(input_unit_t unit)
{
	if (unit <= INPUT_UNIT_RPM) {
		return INPUT_QTY_SPEED;
	}
	return (unit == INPUT_UNIT_NM) ? INPUT_QTY_TORQUE : INPUT_QTY_FORCE;
}

bool input_unit_is_pressure(input_unit_t unit)
{
	return (unit >= INPUT_UNIT_BAR) && (unit <= INPUT_UNIT_PSI);
}

/* physical unit -> output unit (um/s, mN, mNm) */
static int unit_scale(input_unit_t unit, const input_geom_t *g, frac_t *k)
{
	const frac_t pad_over_wheel = frac_of(g->pad_radius_um, g->wheel_radius_um);
	/* pi ~ 103993 / 33102 (error 2e-10): rpm -> rad/s = pi / 30 */
	const frac_t rpm_to_radps = frac_of(103993, 33102LL * 30);
	/* Pa -> mN per 0.01 mm^2 x 1e-6 eta x 1e-6 k:
	 * N = p[Pa] A[mm^2] 1e-6 eta k; mN = 1e3 N */
	frac_t press = frac_of(g->piston_area_cmm2, 100LL * 1000);

	press = frac_mul(press, frac_of(g->efficiency_ppm, 1000000));
	press = frac_mul(press, frac_of(g->axle_factor_ppm, 1000000));
	switch (unit) {
	case INPUT_UNIT_KMH:
		*k = frac_mul(frac_of(10000000, 36), pad_over_wheel);
		break;
	case INPUT_UNIT_MPS:
		*k = frac_mul(frac_of(1000000, 1), pad_over_wheel);
		break;
	case INPUT_UNIT_MPH:
		*k = frac_mul(frac_of(447040, 1), pad_over_wheel);
		break;
	case INPUT_UNIT_RADPS:
		*k = frac_of(g->pad_radius_um, 1);
		break;
	case INPUT_UNIT_RPM:
		*k = frac_mul(rpm_to_radps, frac_of(g->pad_radius_um, 1));
		break;
	case INPUT_UNIT_N:
	case INPUT_UNIT_NM:
		*k = frac_of(1000, 1);
		break;
	case INPUT_UNIT_KN:
		*k = frac_of(1000000, 1);
		break;
	case INPUT_UNIT_BAR:
		*k = frac_mul(frac_of(100000, 1), press);
		break;
	case INPUT_UNIT_KPA:
		*k = frac_mul(frac_of(1000, 1), press);
		break;
	case INPUT_UNIT_MPA:
		*k = frac_mul(frac_of(1000000, 1), press);
		break;
	case INPUT_UNIT_PSI:
		*k = frac_mul(frac_of(6894757, 1000), press);
		break;
	default:
		return SQ_EINVAL;
	}
	return SQ_OK;
}

int input_conv_make(int32_t f_mant, int8_t f_exp, int32_t o_mant, int8_t o_exp,
		    input_unit_t unit, const input_geom_t *geom, input_conv_t *conv)
{
	frac_t k;
	frac_t scale;
	frac_t offs;

	HAL_REQUIRE((geom != NULL) && (conv != NULL));
	/* the values are calibration data: calib_map checks them with this */
	if ((f_mant == 0) ||
	    (f_exp < -12) || (f_exp > 12) || (o_exp < -12) || (o_exp > 12) ||
	    (geom->pad_radius_um == 0U) || (geom->wheel_radius_um == 0U) ||
	    ((uint32_t)unit >= (uint32_t)INPUT_UNIT_COUNT)) {
		return SQ_EINVAL;
	}
	if (input_unit_is_pressure(unit) &&
	    ((geom->piston_area_cmm2 == 0U) || (geom->efficiency_ppm == 0U) ||
	     (geom->axle_factor_ppm == 0U))) {
		return SQ_EINVAL;
	}
	if (unit_scale(unit, geom, &k) != SQ_OK) {
		return SQ_EINVAL;
	}
	scale = frac_mul(frac_mul(frac_of(f_mant, 1), frac_pow10(f_exp)), k);
	offs = frac_mul(frac_mul(frac_of(o_mant, 1), frac_pow10(o_exp)), k);
	conv->mul = scale.n;
	conv->div = scale.d;
	/* add = offset x div, rounded: offs.n x scale.d / offs.d */
	{
		const int64_t g = gcd64(offs.d, scale.d);
		const int64_t num = offs.n * (scale.d / g); /* < 2^60 */
		const int64_t den = offs.d / g;
		int64_t add = (num >= 0) ? ((num + den / 2) / den) : -((-num + den / 2) / den);

		if (add > ADD_LIMIT) {
			add = ADD_LIMIT;
		}
		if (add < -ADD_LIMIT) {
			add = -ADD_LIMIT;
		}
		conv->add = add;
	}
	{
		const input_qty_t qty = input_unit_qty(unit);

		conv->qty = (uint8_t)qty;
	}
	return SQ_OK;
}

static int32_t sat32(int64_t v)
{
	if (v > INT32_MAX) {
		return INT32_MAX;
	}
	return (v < INT32_MIN) ? INT32_MIN : (int32_t)v;
}

int32_t input_conv_apply(const input_conv_t *conv, int64_t value)
{
	int64_t x;

	/* only a conversion input_conv_make() built */
	HAL_REQUIRE((conv != NULL) && (conv->div > 0));
	/* |value| < 2^32, |mul| < 2^30, |add| <= 2^61: no overflow */
	if (value > (int64_t)UINT32_MAX) {
		value = (int64_t)UINT32_MAX;
	}
	if (value < -(int64_t)UINT32_MAX) {
		value = -(int64_t)UINT32_MAX;
	}
	x = value * conv->mul + conv->add;
	x = (x >= 0) ? ((x + conv->div / 2) / conv->div) :
		-((-x + conv->div / 2) / conv->div);
	return sat32(x);
}

int32_t input_conv_torque_to_force(int32_t torque_mnm, int32_t v0_umps,
				   uint8_t friction_faces, uint32_t pad_radius_um,
				   int32_t mu_inf_q30, int32_t delta_mu_q30,
				   int32_t slope_q24)
{
	/* -a v0 in Q32: slope_q24 v0[um/s] / 1e6 << 8 (both < 2^31: fits) */
	const int64_t av = ((int64_t)slope_q24 * (v0_umps > 0 ? v0_umps : 0)) / 1000000;
	bool sat = false;
	const int64_t e_q30 = fx_exp_q32_to_i32(-(av * 256), 30, &sat);
	const int64_t mu_q30 = (int64_t)mu_inf_q30 + (((int64_t)delta_mu_q30 * e_q30) / (1LL << 30));
	int64_t x;
	int64_t den;
	int64_t q;

	if (torque_mnm <= 0) {
		return 0;
	}
	/* the corner's geometry is validated with the calibration */
	HAL_REQUIRE((friction_faces != 0U) && (pad_radius_um != 0U));
	if (mu_q30 <= 0) {
		return INT32_MAX; /* friction gone at this speed: no force bounds it */
	}
	/* N[mN] = T[mNm] 1e6 / (n_f mu r_p[um]) = x 2^30 / den */
	x = ((int64_t)torque_mnm * 1000000) / (int64_t)pad_radius_um;  /* < 2^41 */
	den = (int64_t)friction_faces * mu_q30;                          /* < 2^35 */
	q = x / den;
	if (q >= 2) {
		return INT32_MAX;
	}
	/* x 2^30 / den in two 2^15 steps: remainders stay below 2^50 */
	{
		const int64_t r1 = (x % den) * (1LL << 15);
		const int64_t q1 = r1 / den;
		const int64_t r2 = (r1 % den) * (1LL << 15);

		return sat32(q * (1LL << 30) + q1 * (1LL << 15) + (r2 + den / 2) / den);
	}
}
