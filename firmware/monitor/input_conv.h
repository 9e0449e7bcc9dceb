/* SPDX-License-Identifier: MIT */
/*
 * input_conv: an input's raw value to the monitor's integer quantities,
 * converted once, identically in both numeric builds (integers only):
 *
 *   speed  -> v0 [um/s] at the pad radius:
 *             linear  km/h kph m/s mph:  v0 = v_w r_p / r_w
 *             angular rad/s rpm 1/min:   v0 = w r_p (disc turns with wheel)
 *   force  -> N [mN]: N, kN
 *   pressure -> N [mN] = p A eta k: bar, kPa, MPa, psi
 *   torque -> T [mNm] (Nm); the clamp force needs mu(v0), so the corner
 *             converts it per classification: input_conv_torque_to_force().
 *
 * physical = raw x factor + offset with factor = f_mant 10^f_exp and offset
 * = o_mant 10^o_exp (exact decimals as DBC files write them: up to 17
 * significant digits, exponent -30..30). The whole chain is one affine map
 * out = (value P + A) / Q, rounded to nearest (halves away from zero) and
 * saturated to int32, built once from exact fractions (multi-word integers
 * at set-up, no floating point):
 *   - P and Q are the reduced fraction when both fit 62 bits, with A the
 *     exact offset over the common denominator when that fits too: then
 *     every output is the correctly rounded exact value;
 *   - otherwise Q = 2^k and P = round(scale 2^k) with P >= 2^60 or
 *     k = 62, and A rounded: the output is off the exact value by at most
 *     2^-29 of one output step (before rounding).
 * Per frame: one multiply and one divide in 64 bits when |P| < 2^30 and
 * |A| <= 2^61 (every common DBC scaling), otherwise a 64x64->128 multiply
 * and one 128/64 divide by 32-bit digits (portable C, no __int128).
 */
#ifndef INPUT_CONV_H
#define INPUT_CONV_H

#include <stdbool.h>
#include <stdint.h>

/* A decimal mant x 10^exp (calib_dec_t is this type). */
typedef struct {
	int64_t mant;
	int8_t exp;
} input_dec_t;

#define INPUT_DEC_MANT_MAX 99999999999999999LL /* 17 significant digits */
#define INPUT_DEC_EXP_MIN (-30)
#define INPUT_DEC_EXP_MAX 30

typedef enum {
	INPUT_UNIT_KMH = 0,   /* "km/h", "kph"    */
	INPUT_UNIT_MPS,       /* "m/s"            */
	INPUT_UNIT_MPH,       /* "mph"            */
	INPUT_UNIT_RADPS,     /* "rad/s"          */
	INPUT_UNIT_RPM,       /* "rpm", "1/min"   */
	INPUT_UNIT_N,         /* "N"              */
	INPUT_UNIT_KN,        /* "kN"             */
	INPUT_UNIT_BAR,       /* "bar"            */
	INPUT_UNIT_KPA,       /* "kPa"            */
	INPUT_UNIT_MPA,       /* "MPa"            */
	INPUT_UNIT_PSI,       /* "psi"            */
	INPUT_UNIT_NM,        /* "Nm"             */
	INPUT_UNIT_COUNT
} input_unit_t;

typedef enum {
	INPUT_QTY_SPEED = 0,  /* v0 [um/s]  */
	INPUT_QTY_FORCE,      /* N [mN] (force and pressure) */
	INPUT_QTY_TORQUE      /* T [mNm]    */
} input_qty_t;

/* What the conversion needs of the corner. */
typedef struct {
	uint32_t pad_radius_um;    /* r_p                                     */
	uint32_t wheel_radius_um;  /* r_w                                     */
	uint32_t piston_area_cmm2; /* A, 0.01 mm^2 (pressure only)            */
	uint32_t efficiency_ppm;   /* eta, 1e-6                               */
	uint32_t axle_factor_ppm;  /* k, 1e-6                                 */
} input_geom_t;

/* out = (value * mul + add) / div, rounded to nearest, saturated;
 * add = add_hi 2^64 + add_lo (|add| <= 2^96). */
typedef struct {
	int64_t mul;     /* |mul| < 2^62 */
	int64_t add;     /* the offset term when wide == 0 (|add| <= 2^61)    */
	int64_t div;     /* 0 < div <= 2^62 */
	uint8_t qty;     /* input_qty_t */
	uint8_t wide;    /* 1: value mul + add may pass 2^63: 128-bit path    */
	int64_t add_hi;  /* the offset term in 128 bits: add_hi 2^64 + add_lo */
	uint64_t add_lo;
} input_conv_t;

/* The plausible raw values of an input: raw_min <= value <= raw_max, and
 * |change| <= raw_step (clamped to +-2^40, beyond any 32-bit raw). */
typedef struct {
	int64_t raw_min;
	int64_t raw_max;
	int64_t raw_step;
} input_raw_bounds_t;

/*
 * Contracts (hal.h): NULL pointers, a conversion input_conv_make() did not
 * build, and a zero friction_faces or pad radius (validated with the
 * calibration) are programming errors. Unit strings and calibration values
 * are data: they get an error code.
 *
 * The unit of a DBC unit string, case-insensitive ("km/h", "Km/h", "KPH",
 * "Bar", "rpm", "1/min", "Nm", ...). SQ_OK and *unit, or SQ_ENOENT.
 */
int input_unit_parse(const char *s, input_unit_t *unit);
const char *input_unit_name(input_unit_t unit);
input_qty_t input_unit_qty(input_unit_t unit);
bool input_unit_is_pressure(input_unit_t unit);

/* A decimal within the documented range (mantissa and exponent). */
bool input_dec_valid(input_dec_t d);

/* Exact comparison of two valid decimals: -1, 0 or 1. */
int input_dec_cmp(input_dec_t a, input_dec_t b);

/*
 * Build the conversion. SQ_OK, or SQ_EINVAL: factor 0, a decimal outside
 * its range, unknown unit, a zero radius, a pressure without area,
 * efficiency or axle factor, or one raw step of 2^31 output units or more
 * (every reading but one would saturate).
 */
int input_conv_make(int64_t f_mant, int8_t f_exp, int64_t o_mant, int8_t o_exp,
		    input_unit_t unit, const input_geom_t *geom, input_conv_t *conv);

/* The same for share_ppm (1..1000000, 1e-6) of the value: a corner's
 * torque_share of a total or per-axle torque. SQ_EINVAL also for a share
 * outside 1..1000000. */
int input_conv_make_share(int64_t f_mant, int8_t f_exp, int64_t o_mant, int8_t o_exp,
			  input_unit_t unit, const input_geom_t *geom, uint32_t share_ppm,
			  input_conv_t *conv);

/*
 * The raw values with min <= raw x factor + offset <= max and the largest
 * change |d raw| x |factor| <= step_max, exactly. SQ_OK, or SQ_EINVAL: a
 * decimal outside its range, factor 0, step_max <= 0, or no raw value
 * within min .. max (max below min, or both between two raw steps).
 */
int input_conv_raw_bounds(input_dec_t factor, input_dec_t offset, input_dec_t min,
			  input_dec_t max, input_dec_t step_max, input_raw_bounds_t *b);

/* The raw value (sign-extended) in the quantity's unit, saturated. */
int32_t input_conv_apply(const input_conv_t *conv, int64_t value);

/*
 * Clamp force [mN] from brake torque T [mNm] at v0 [um/s]:
 * N = T / (n_f mu(v0) r_p), mu(v0) = mu_inf + delta_mu e^(-a v0) with the
 * model's parameters in their stored Q-formats (calib.h). 0 for T <= 0,
 * INT32_MAX when mu(v0) <= 0 or the force does not fit.
 */
int32_t input_conv_torque_to_force(int32_t torque_mnm, int32_t v0_umps,
				   uint8_t friction_faces, uint32_t pad_radius_um,
				   int32_t mu_inf_q30, int32_t delta_mu_q30,
				   int32_t slope_q24);

#endif /* INPUT_CONV_H */
