/* SPDX-License-Identifier: MIT */
#include "input_conv.h"

#include <stddef.h>

#include "fixmath.h"
#include "hal.h"
#include "sq_status.h"

/* Set-up arithmetic: unsigned integers of BIG_LIMBS 32-bit words. The
 * largest operand is an offset term: 17 digits x 10^60 (two decimals'
 * exponents apart) or mant x 10^30 x the unit's numerator (< 2^112, with
 * the share) x a 62-bit denominator: below 2^340, within 384 bits. */
#define BIG_LIMBS 12U
#define BIG_BITS (32U * BIG_LIMBS)
#define BITS_62 62U
#define ADD_BITS 96U                 /* |add| clamped to 2^96 (see make)     */
#define FAST_MUL_LIMIT ((int64_t)1 << 30)
#define RAW_LIMIT ((int64_t)1 << 40) /* raw bounds clamp: beyond 32-bit raws */
#define SCALE_MAX_BITS 31            /* one raw step must be < 2^31 outputs  */
#define PPM 1000000U

typedef struct {
	uint32_t w[BIG_LIMBS]; /* least significant word first */
} big_t;

/* a sign and a magnitude */
typedef struct {
	big_t m;
	bool neg;
} sbig_t;

static void big_set(big_t *a, uint64_t v)
{
	uint32_t i;

	for (i = 0U; i < BIG_LIMBS; i++) {
		a->w[i] = 0U;
	}
	a->w[0] = (uint32_t)v;
	a->w[1] = (uint32_t)(v >> 32);
}

static bool big_is_zero(const big_t *a)
{
	uint32_t i;
	uint32_t any = 0U;

	for (i = 0U; i < BIG_LIMBS; i++) {
		any |= a->w[i];
	}
	return any == 0U;
}

static uint32_t big_bitlen(const big_t *a)
{
	uint32_t i;
	uint32_t n = 0U;

	for (i = BIG_LIMBS; (i > 0U) && (n == 0U); i--) {
		uint32_t v = a->w[i - 1U];
		uint32_t b = 0U;

		while ((v != 0U) && (b < 32U)) {
			v >>= 1;
			b++;
		}
		if (b != 0U) {
			n = (32U * (i - 1U)) + b;
		}
	}
	return n;
}

static uint64_t big_low64(const big_t *a)
{
	return ((uint64_t)a->w[1] << 32) | a->w[0];
}

static int big_cmp(const big_t *a, const big_t *b)
{
	uint32_t i;

	for (i = BIG_LIMBS; i > 0U; i--) {
		if (a->w[i - 1U] != b->w[i - 1U]) {
			return (a->w[i - 1U] > b->w[i - 1U]) ? 1 : -1;
		}
	}
	return 0;
}

/* a = a m + b (b NULL: 0), one pass for a product and a sum; the operands
 * stay within the budget above (a carry out of the top word would be a
 * sizing mistake: programming error). Each step's t <= (2^32 - 1)^2 +
 * 2 (2^32 - 1) < 2^64. */
static void big_mul_add(big_t *a, uint32_t m, const big_t *b)
{
	uint64_t carry = 0U;
	uint32_t i;

	for (i = 0U; i < BIG_LIMBS; i++) {
		const uint64_t t = ((uint64_t)a->w[i] * m) + ((b != NULL) ? b->w[i] : 0U) + carry;

		a->w[i] = (uint32_t)t;
		carry = t >> 32;
	}
	HAL_REQUIRE(carry == 0U);
}

/* a *= m */
static void big_mul_u32(big_t *a, uint32_t m)
{
	big_mul_add(a, m, NULL);
}

static void big_add(big_t *a, const big_t *b)
{
	big_mul_add(a, 1U, b);
}

/* a -= b, a >= b */
static void big_sub(big_t *a, const big_t *b)
{
	uint32_t borrow = 0U;
	uint32_t i;

	for (i = 0U; i < BIG_LIMBS; i++) {
		const uint64_t t = (uint64_t)a->w[i] - b->w[i] - borrow;

		a->w[i] = (uint32_t)t;
		borrow = (uint32_t)((t >> 32) & 1U);
	}
}

static void big_mul_u64(big_t *a, uint64_t v)
{
	big_t hi;
	uint32_t i;

	hi = *a;
	big_mul_u32(a, (uint32_t)v);
	big_mul_u32(&hi, (uint32_t)(v >> 32));
	HAL_REQUIRE(hi.w[BIG_LIMBS - 1U] == 0U);
	for (i = BIG_LIMBS - 1U; i > 0U; i--) {
		hi.w[i] = hi.w[i - 1U];
	}
	hi.w[0] = 0U;
	big_add(a, &hi);
}

/* a *= b (b's value below 2^64 x 2^64 is enough: product of two bigs is
 * only taken with a 62-bit factor) */
static void big_mul_big64(big_t *a, const big_t *b)
{
	HAL_REQUIRE(big_bitlen(b) <= 64U);
	big_mul_u64(a, big_low64(b));
}

static void big_mul_pow10(big_t *a, uint32_t n)
{
	/* in steps of at most 10^9, the largest power of ten below 2^32 */
	static const uint32_t pow10[10] = { 1U, 10U, 100U, 1000U, 10000U, 100000U, 1000000U,
					    10000000U, 100000000U, 1000000000U };
	uint32_t left = n;
	uint32_t guard;

	for (guard = 0U; (left > 0U) && (guard < 64U); guard++) {
		const uint32_t step = (left > 9U) ? 9U : left;

		big_mul_u32(a, pow10[step]);
		left -= step;
	}
}

static void big_shl1(big_t *a, uint32_t in_bit)
{
	uint32_t i;
	uint32_t carry = in_bit;

	for (i = 0U; i < BIG_LIMBS; i++) {
		const uint32_t out = a->w[i] >> 31;

		a->w[i] = (a->w[i] << 1) | carry;
		carry = out;
	}
	HAL_REQUIRE(carry == 0U);
}

static void big_shr1(big_t *a)
{
	uint32_t i;

	for (i = 0U; i < BIG_LIMBS; i++) {
		const uint32_t next = (i + 1U < BIG_LIMBS) ? a->w[i + 1U] : 0U;

		a->w[i] = (a->w[i] >> 1) | (next << 31);
	}
}

static void big_shl(big_t *a, uint32_t n)
{
	const uint32_t words = n / 32U;
	const uint32_t bits = n % 32U;
	uint32_t i;

	HAL_REQUIRE(words < BIG_LIMBS);
	for (i = BIG_LIMBS; i > words; i--) {
		a->w[i - 1U] = a->w[i - 1U - words];
	}
	for (i = 0U; i < words; i++) {
		a->w[i] = 0U;
	}
	for (i = 0U; i < bits; i++) {
		big_shl1(a, 0U);
	}
}

static uint32_t big_bit(const big_t *a, uint32_t i)
{
	return (a->w[i / 32U] >> (i % 32U)) & 1U;
}

/* q = n / d, r = n % d (d != 0); bit by bit, set-up only */
static void big_divmod(const big_t *n, const big_t *d, big_t *q, big_t *r)
{
	uint32_t i;

	HAL_REQUIRE(!big_is_zero(d));
	if ((big_bitlen(n) <= 64U) && (big_bitlen(d) <= 64U)) {
		/* the common case, in one native division */
		const uint64_t a = big_low64(n);
		const uint64_t b = big_low64(d);

		big_set(q, a / b);
		big_set(r, a % b);
		return;
	}
	big_set(q, 0U);
	big_set(r, 0U);
	if (big_cmp(n, d) < 0) {
		*r = *n;
		return;
	}
	for (i = big_bitlen(n); i > 0U; i--) {
		big_shl1(r, big_bit(n, i - 1U));
		if (big_cmp(r, d) >= 0) {
			big_sub(r, d);
			q->w[(i - 1U) / 32U] |= (uint32_t)1U << ((i - 1U) % 32U);
		}
	}
}

/* n / d rounded to nearest, halves up */
static void big_div_round(const big_t *n, const big_t *d, big_t *q)
{
	big_t r;
	big_t twice;

	big_divmod(n, d, q, &r);
	twice = r;
	big_shl1(&twice, 0U);
	if (big_cmp(&twice, d) >= 0) {
		big_t one;

		big_set(&one, 1U);
		big_add(q, &one);
	}
}

/* binary gcd of two non-zero values (each step drops a bit of one) */
static void big_gcd(const big_t *x, const big_t *y, big_t *g)
{
	big_t a;
	big_t b;
	uint32_t k = 0U;
	uint32_t guard;

	a = *x;
	b = *y;
	HAL_REQUIRE(!big_is_zero(&a) && !big_is_zero(&b));
	if ((big_bitlen(&a) <= 64U) && (big_bitlen(&b) <= 64U)) {
		/* Euclid in 64 bits: fewer than 93 steps below 2^64 */
		uint64_t x64 = big_low64(&a);
		uint64_t y64 = big_low64(&b);

		for (guard = 0U; (y64 != 0U) && (guard < 128U); guard++) {
			const uint64_t t = x64 % y64;

			x64 = y64;
			y64 = t;
		}
		big_set(g, x64);
		return;
	}
	while ((((a.w[0] | b.w[0]) & 1U) == 0U) && (k < BIG_BITS)) {
		big_shr1(&a);
		big_shr1(&b);
		k++;
	}
	for (guard = 0U; ((a.w[0] & 1U) == 0U) && (guard < BIG_BITS); guard++) {
		big_shr1(&a);
	}
	for (guard = 0U; !big_is_zero(&b) && (guard < (4U * BIG_BITS)); guard++) {
		if ((b.w[0] & 1U) == 0U) {
			big_shr1(&b);
		} else {
			if (big_cmp(&a, &b) > 0) {
				const big_t t = a;

				a = b;
				b = t;
			}
			big_sub(&b, &a);
		}
	}
	big_shl(&a, k);
	*g = a;
}

/* n / d reduced (both non-zero) */
static void big_reduce(big_t *n, big_t *d)
{
	big_t g;
	big_t q;
	big_t r;

	big_gcd(n, d, &g);
	big_divmod(n, &g, &q, &r);
	*n = q;
	big_divmod(d, &g, &q, &r);
	*d = q;
}

static uint64_t mag64(int64_t v)
{
	return (v < 0) ? ((uint64_t)(-(v + 1)) + 1U) : (uint64_t)v;
}

/* ---- decimals ------------------------------------------------------------- */

bool input_dec_valid(input_dec_t d)
{
	return (d.mant >= -INPUT_DEC_MANT_MAX) && (d.mant <= INPUT_DEC_MANT_MAX) &&
	       (d.exp >= INPUT_DEC_EXP_MIN) && (d.exp <= INPUT_DEC_EXP_MAX);
}

/* d x 10^-e0 as an integer (d.exp >= e0) */
static sbig_t dec_scaled(input_dec_t d, int32_t e0)
{
	const int32_t de = (int32_t)d.exp - e0;
	sbig_t s;

	big_set(&s.m, mag64(d.mant));
	big_mul_pow10(&s.m, (uint32_t)de);
	s.neg = (d.mant < 0);
	return s;
}

static int sbig_cmp(const sbig_t *a, const sbig_t *b)
{
	const bool az = big_is_zero(&a->m);
	const bool bz = big_is_zero(&b->m);
	const bool an = a->neg && !az;
	const bool bn = b->neg && !bz;
	int c;

	if (an != bn) {
		return an ? -1 : 1;
	}
	c = big_cmp(&a->m, &b->m);
	return an ? -c : c;
}

/* a - b */
static sbig_t sbig_sub(const sbig_t *a, const sbig_t *b)
{
	sbig_t r;

	if (a->neg != b->neg) {
		r.m = a->m;
		big_add(&r.m, &b->m);
		r.neg = a->neg;
	} else if (big_cmp(&a->m, &b->m) >= 0) {
		r.m = a->m;
		big_sub(&r.m, &b->m);
		r.neg = a->neg;
	} else {
		r.m = b->m;
		big_sub(&r.m, &a->m);
		r.neg = !a->neg;
	}
	return r;
}

/* floor(n / d) (ceil when up), clamped to +-RAW_LIMIT */
static int64_t sbig_div_clamped(const sbig_t *n, const sbig_t *d, bool up)
{
	big_t q;
	big_t r;
	bool neg;
	int64_t v;

	big_divmod(&n->m, &d->m, &q, &r);
	neg = (n->neg != d->neg) && !big_is_zero(&n->m);
	/* magnitude of the result: q, or q + 1 when the remainder rounds away */
	if (!big_is_zero(&r) && (neg != up)) {
		big_t one;

		big_set(&one, 1U);
		big_add(&q, &one);
	}
	v = (big_bitlen(&q) > 40U) ? RAW_LIMIT : (int64_t)big_low64(&q);
	v = (v > RAW_LIMIT) ? RAW_LIMIT : v;
	return neg ? -v : v;
}

static int32_t exp_min(int32_t a, int32_t b)
{
	return (a < b) ? a : b;
}

int input_dec_cmp(input_dec_t a, input_dec_t b)
{
	const int32_t e0 = exp_min(a.exp, b.exp);
	sbig_t x;
	sbig_t y;

	HAL_REQUIRE(input_dec_valid(a) && input_dec_valid(b));
	x = dec_scaled(a, e0);
	y = dec_scaled(b, e0);
	return sbig_cmp(&x, &y);
}

/* floor or ceil of (x - o) / f for the decimal x, clamped */
static int64_t bound_of(input_dec_t x, const sbig_t *o, const sbig_t *f, int32_t e0, bool up)
{
	sbig_t v;
	sbig_t n;

	v = dec_scaled(x, e0);
	n = sbig_sub(&v, o);
	return sbig_div_clamped(&n, f, up);
}

int input_conv_raw_bounds(input_dec_t factor, input_dec_t offset, input_dec_t min,
			  input_dec_t max, input_dec_t step_max, input_raw_bounds_t *b)
{
	int32_t e0;
	sbig_t f;
	sbig_t o;

	HAL_REQUIRE(b != NULL);
	if (!input_dec_valid(factor) || !input_dec_valid(offset) || !input_dec_valid(min) ||
	    !input_dec_valid(max) || !input_dec_valid(step_max) || (factor.mant == 0) ||
	    (step_max.mant <= 0)) {
		return SQ_EINVAL;
	}
	e0 = exp_min(exp_min(exp_min(factor.exp, offset.exp), exp_min(min.exp, max.exp)),
		     step_max.exp);
	f = dec_scaled(factor, e0);
	o = dec_scaled(offset, e0);
	/* min <= raw f + o <= max: raw in [(min - o) / f, (max - o) / f],
	 * the ends swapped for a negative factor */
	b->raw_min = bound_of(f.neg ? max : min, &o, &f, e0, true);
	b->raw_max = bound_of(f.neg ? min : max, &o, &f, e0, false);
	/* |d raw| |f| <= step_max */
	f.neg = false;
	big_set(&o.m, 0U);
	o.neg = false;
	b->raw_step = bound_of(step_max, &o, &f, e0, false);
	return (b->raw_min <= b->raw_max) ? SQ_OK : SQ_EINVAL;
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

typedef struct {
	uint32_t num;
	uint32_t den;
} unit_factor_t;

/* physical unit -> output unit (um/s, mN, mNm) as an exact fraction,
 * the share included (below 2^112 / 2^67), multiplied into kn / kd */
static void unit_scale(input_unit_t unit, const input_geom_t *g, uint32_t share_ppm,
		       big_t *kn, big_t *kd)
{
	/* the unit -> um/s, mN (pressures: Pa), mNm factor num / den, in
	 * input_unit_t's order (unit is below INPUT_UNIT_COUNT: checked) */
	static const unit_factor_t factor[INPUT_UNIT_COUNT] = {
		{ 10000000U, 36U },         /* km/h -> um/s: 1e9 / 3600 */
		{ 1000000U, 1U },           /* m/s                      */
		{ 447040U, 1U },            /* mph: 0.44704 m/s exactly */
		{ 1U, 1U },                 /* rad/s: the pad radius below */
		/* pi ~ 103993 / 33102 (error 2e-10): rpm -> rad/s = pi / 30 */
		{ 103993U, 33102U * 30U },  /* rpm                      */
		{ 1000U, 1U },              /* N -> mN                  */
		{ 1000000U, 1U },           /* kN                       */
		{ 100000U, 1U },            /* bar -> Pa                */
		{ 1000U, 1U },              /* kPa                      */
		{ 1000000U, 1U },           /* MPa                      */
		{ 6894757U, 1000U },        /* psi                      */
		{ 1000U, 1U },              /* Nm -> mNm                */
	};
	_Static_assert((unsigned int)INPUT_UNIT_COUNT == 12U,
		       "one factor per input_unit_t, in its order");

	big_mul_u32(kn, factor[unit].num);
	big_mul_u32(kd, factor[unit].den);
	if (input_unit_qty(unit) == INPUT_QTY_SPEED) {
		/* linear speeds at the wheel's rim: x r_p / r_w; angular: x r_p */
		big_mul_u32(kn, g->pad_radius_um);
		if ((unit == INPUT_UNIT_KMH) || (unit == INPUT_UNIT_MPS) || (unit == INPUT_UNIT_MPH)) {
			big_mul_u32(kd, g->wheel_radius_um);
		}
	}
	if (input_unit_is_pressure(unit)) {
		/* Pa -> mN: N = p[Pa] A[mm^2] 1e-6 eta k, A in 0.01 mm^2, eta and k
		 * in 1e-6; mN = 1e3 N */
		big_mul_u32(kn, g->piston_area_cmm2);
		big_mul_u32(kn, g->efficiency_ppm);
		big_mul_u32(kn, g->axle_factor_ppm);
		big_mul_u32(kd, 100000U);
		big_mul_u32(kd, PPM);
		big_mul_u32(kd, PPM);
	}
	if (share_ppm != PPM) {
		big_mul_u32(kn, share_ppm);
		big_mul_u32(kd, PPM);
	}
}

/* The 128-bit two's complement of a signed big (|v| <= 2^96 after the
 * clamp), as high and low words. */
static void to_words(const big_t *mag, bool neg, int64_t *hi, uint64_t *lo)
{
	uint64_t h = (uint64_t)mag->w[2] | ((uint64_t)mag->w[3] << 32);
	uint64_t l = big_low64(mag);

	if (neg && ((h | l) != 0U)) {
		/* -x = ~x + 1: the high word takes the carry when l was 0 */
		uint64_t carry = 0U;

		if (l == 0U) {
			carry = 1U;
		}
		l = ~l + 1U;
		h = ~h + carry;
	}
	/* two's complement bits -> int64 without implementation-defined
	 * conversion */
	{
		const uint64_t nh = ~h;

		*hi = (h <= (uint64_t)INT64_MAX) ? (int64_t)h : (-(int64_t)nh - 1);
	}
	*lo = l;
}

/* |d| in output units per raw unit (or per physical unit for the offset):
 * |d| x the unit's fraction, reduced (n 0: den 1) */
static void dec_in_output(input_dec_t d, input_unit_t unit, const input_geom_t *geom,
			  uint32_t share_ppm, big_t *n, big_t *den)
{
	big_set(n, mag64(d.mant));
	big_set(den, 1U);
	if (big_is_zero(n)) {
		return;
	}
	big_mul_pow10((d.exp >= 0) ? n : den, (uint32_t)((d.exp >= 0) ? d.exp : -(int32_t)d.exp));
	unit_scale(unit, geom, share_ppm, n, den);
	big_reduce(n, den);
}

/* mul, div (both < 2^62 on return) and add of the map for scale sn / sd
 * and offset on / od (add's sign is the caller's); add may be on itself
 * (on is read before add is written). */
static void combine(const big_t *sn, const big_t *sd, const big_t *on, const big_t *od,
		    uint64_t *mul, uint64_t *div, big_t *add)
{
	big_t a;
	big_t b;
	big_t c;
	big_t l;

	if ((big_bitlen(sn) <= BITS_62) && (big_bitlen(sd) <= BITS_62)) {
		/* exact scale; the offset over a common denominator when that
		 * fits too (then every output is the exact value rounded) */
		*mul = big_low64(sn);
		*div = big_low64(sd);
		if (big_is_zero(on)) {
			big_set(add, 0U);
			return;
		}
		big_gcd(sd, od, &a);              /* a = g                    */
		big_divmod(od, &a, &b, &c);       /* b = m = od / g           */
		if (big_bitlen(&b) <= BITS_62) {
			big_divmod(sd, &a, &l, &c); /* l = sd / g (< 2^62)      */
			a = *sd;
			big_mul_big64(&a, &b);      /* a = sd m, the common den */
			c = *sn;
			big_mul_big64(&c, &b);      /* c = sn m                 */
			if ((big_bitlen(&a) <= BITS_62) && (big_bitlen(&c) <= BITS_62)) {
				*mul = big_low64(&c);
				*div = big_low64(&a);
				b = *on;
				big_mul_big64(&b, &l);  /* on x (sd / g)            */
				*add = b;
				return;
			}
		}
		/* add = round(on sd / od) */
		a = *on;
		big_mul_big64(&a, sd);
		big_div_round(&a, od, add);
		return;
	}
	/* approximation: div = 2^k, mul = round(scale 2^k) with
	 * k = min(60 - t, 62) for scale in [2^(t-1), 2^(t+1)): mul in
	 * [2^59, 2^61] (relative error <= 2^-60) or k = 62; t <= 31 by the
	 * caller's check, so k >= 29 */
	{
		const int32_t t = (int32_t)big_bitlen(sn) - (int32_t)big_bitlen(sd);
		const int32_t k0 = 60 - t;
		const uint32_t k = (uint32_t)((k0 > 62) ? 62 : k0);

		a = *sn;
		big_shl(&a, k);
		big_div_round(&a, sd, &b);
		*mul = big_low64(&b);
		*div = (uint64_t)1U << k;
		a = *on;
		big_shl(&a, k);
		big_div_round(&a, od, add);
	}
}

int input_conv_make(int64_t f_mant, int8_t f_exp, int64_t o_mant, int8_t o_exp,
		    input_unit_t unit, const input_geom_t *geom, input_conv_t *conv)
{
	return input_conv_make_share(f_mant, f_exp, o_mant, o_exp, unit, geom, PPM, conv);
}

int input_conv_make_share(int64_t f_mant, int8_t f_exp, int64_t o_mant, int8_t o_exp,
			  input_unit_t unit, const input_geom_t *geom, uint32_t share_ppm,
			  input_conv_t *conv)
{
	const input_dec_t f = { f_mant, f_exp };
	const input_dec_t o = { o_mant, o_exp };
	big_t sn;
	big_t sd;
	big_t on;
	big_t od;
	uint64_t mul = 0U;
	uint64_t div = 1U;

	HAL_REQUIRE((geom != NULL) && (conv != NULL));
	/* the values are calibration data: calib_map checks them with this */
	if ((f_mant == 0) || !input_dec_valid(f) || !input_dec_valid(o) ||
	    (geom->pad_radius_um == 0U) || (geom->wheel_radius_um == 0U) ||
	    ((uint32_t)unit >= (uint32_t)INPUT_UNIT_COUNT) || (share_ppm < 1U) ||
	    (share_ppm > PPM)) {
		return SQ_EINVAL;
	}
	if (input_unit_is_pressure(unit) &&
	    ((geom->piston_area_cmm2 == 0U) || (geom->efficiency_ppm == 0U) ||
	     (geom->axle_factor_ppm == 0U))) {
		return SQ_EINVAL;
	}
	dec_in_output(f, unit, geom, share_ppm, &sn, &sd);
	/* one raw step must stay below the int32 output range: beyond that
	 * every reading but one saturates, a calibration mistake */
	if (big_bitlen(&sn) > (big_bitlen(&sd) + (uint32_t)SCALE_MAX_BITS - 1U)) {
		big_set(&on, (uint64_t)1U << (uint32_t)SCALE_MAX_BITS);
		od = sd;
		big_mul_big64(&od, &on);         /* sd 2^31 */
		if (big_cmp(&sn, &od) >= 0) {
			return SQ_EINVAL;
		}
	}
	dec_in_output(o, unit, geom, share_ppm, &on, &od);
	combine(&sn, &sd, &on, &od, &mul, &div, &on);   /* on: the offset term now */
	if (big_bitlen(&on) > ADD_BITS) {
		/* |value mul| < 2^94: beyond 2^96 the output saturates either way */
		big_set(&on, 0U);
		on.w[ADD_BITS / 32U] = 1U;
	}
	conv->mul = (f_mant < 0) ? -(int64_t)mul : (int64_t)mul;
	conv->div = (int64_t)div;
	to_words(&on, o_mant < 0, &conv->add_hi, &conv->add_lo);
	conv->wide = (uint8_t)(((mul >= (uint64_t)FAST_MUL_LIMIT) || (big_bitlen(&on) > 61U)) ?
			       1U : 0U);
	conv->add = 0;
	if (conv->wide == 0U) {
		conv->add = (int64_t)big_low64(&on);
		conv->add = (o_mant < 0) ? -conv->add : conv->add;
	}
	{
		const input_qty_t qty = input_unit_qty(unit); /* no cast of a call's result */

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

/* ---- 128-bit helpers (per frame, wide conversions only) ---------------------- */

typedef struct {
	uint64_t hi;
	uint64_t lo;
} u128_t;

static u128_t mul64x64(uint64_t a, uint64_t b)
{
	const uint64_t a0 = a & 0xFFFFFFFFU;
	const uint64_t a1 = a >> 32;
	const uint64_t b0 = b & 0xFFFFFFFFU;
	const uint64_t b1 = b >> 32;
	const uint64_t p00 = a0 * b0;
	const uint64_t p01 = a0 * b1;
	const uint64_t p10 = a1 * b0;
	const uint64_t p11 = a1 * b1;
	const uint64_t mid = (p00 >> 32) + (p01 & 0xFFFFFFFFU) + (p10 & 0xFFFFFFFFU);
	u128_t r;

	r.lo = (mid << 32) | (p00 & 0xFFFFFFFFU);
	r.hi = p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
	return r;
}

static u128_t add128(u128_t a, u128_t b)
{
	u128_t r;

	r.lo = a.lo + b.lo;
	r.hi = a.hi + b.hi + ((r.lo < a.lo) ? 1U : 0U);
	return r;
}

static u128_t neg128(u128_t a)
{
	uint64_t carry = 0U;
	u128_t r;

	if (a.lo == 0U) {
		carry = 1U;
	}
	r.lo = ~a.lo + 1U;
	r.hi = ~a.hi + carry;
	return r;
}

static uint32_t nlz64(uint64_t v)
{
	uint32_t n = 0U;

	while ((n < 64U) && ((v & ((uint64_t)1U << 63)) == 0U)) {
		v <<= 1;
		n++;
	}
	return n;
}

/*
 * One 32-bit quotient digit of div128by64: un / vn1 estimated, then
 * corrected while it is too large against the next dividend digit un_next
 * (at most twice), for the normalised divisor vn1 2^32 + vn0.
 */
static uint64_t div_digit(uint64_t un, uint64_t un_next, uint64_t vn1, uint64_t vn0)
{
	const uint64_t b = (uint64_t)1U << 32;
	uint64_t q = un / vn1;
	uint64_t rhat = un - (q * vn1);
	uint32_t guard;

	for (guard = 0U; (guard < 2U) && ((q >= b) || ((q * vn0) > ((b * rhat) + un_next))); guard++) {
		q--;
		rhat += vn1;
		if (rhat >= b) {
			break;
		}
	}
	return q;
}

/*
 * (hi 2^64 + lo) / d for hi < d (the quotient fits 64 bits): Knuth's
 * algorithm D with 32-bit digits (Hacker's Delight, divlu), each digit
 * estimate corrected at most twice.
 */
static uint64_t div128by64(uint64_t hi, uint64_t lo, uint64_t d)
{
	const uint64_t b = (uint64_t)1U << 32;
	const uint32_t s = nlz64(d);
	uint64_t vn1;
	uint64_t vn0;
	uint64_t un32;
	uint64_t un10;
	uint64_t un1;
	uint64_t un0;
	uint64_t un21;
	uint64_t q1;
	uint64_t q0;

	HAL_REQUIRE((d != 0U) && (hi < d));
	d <<= s;
	vn1 = d >> 32;
	vn0 = d & 0xFFFFFFFFU;
	un32 = hi;
	if (s != 0U) {
		const uint32_t rs = 64U - s;

		un32 = (hi << s) | (lo >> rs);
	}
	un10 = lo << s;
	un1 = un10 >> 32;
	un0 = un10 & 0xFFFFFFFFU;
	q1 = div_digit(un32, un1, vn1, vn0);
	un21 = (un32 * b) + un1 - (q1 * d);
	q0 = div_digit(un21, un0, vn1, vn0);
	return (q1 * b) + q0;
}

static int32_t apply_wide(const input_conv_t *conv, int64_t value)
{
	const bool neg_p = (value < 0) != (conv->mul < 0);
	const u128_t add = { (uint64_t)conv->add_hi, conv->add_lo };
	const uint64_t div = (uint64_t)conv->div;
	u128_t x = mul64x64(mag64(value), mag64(conv->mul)); /* < 2^94 */
	bool neg;
	uint64_t q;

	if (neg_p) {
		x = neg128(x);
	}
	x = add128(x, add);                 /* |x| < 2^97 */
	neg = (x.hi >> 63) != 0U;
	if (neg) {
		x = neg128(x);
	}
	/* halves away from zero: floor((|x| + div / 2) / div) */
	x = add128(x, (u128_t){ 0U, div / 2U });
	if (x.hi >= div) {
		return neg ? INT32_MIN : INT32_MAX;  /* quotient >= 2^64 */
	}
	q = div128by64(x.hi, x.lo, div);
	if (q > (uint64_t)INT32_MAX) {
		return neg ? INT32_MIN : INT32_MAX;
	}
	return neg ? -(int32_t)q : (int32_t)q;
}

int32_t input_conv_apply(const input_conv_t *conv, int64_t value)
{
	int64_t x;

	/* only a conversion input_conv_make() built */
	HAL_REQUIRE((conv != NULL) && (conv->div > 0));
	if (value > (int64_t)UINT32_MAX) {
		value = (int64_t)UINT32_MAX;
	}
	if (value < -(int64_t)UINT32_MAX) {
		value = -(int64_t)UINT32_MAX;
	}
	if (conv->wide != 0U) {
		return apply_wide(conv, value);
	}
	/* |value| < 2^32, |mul| < 2^30, |add| <= 2^61: no overflow */
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
