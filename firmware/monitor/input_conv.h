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
 * = o_mant 10^o_exp (exact decimals, as DBC files write them). The whole
 * chain is one affine map out = (value P + A) / Q, rounded to nearest,
 * computed once from reduced fractions (numerators and denominators kept
 * below 2^30, so common DBC scalings convert exactly and any other within
 * 1e-9 relative) and saturated to int32.
 */
#ifndef INPUT_CONV_H
#define INPUT_CONV_H

#include <stdbool.h>
#include <stdint.h>

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

/* out = (value * mul + add) / div, rounded to nearest, saturated. */
typedef struct {
	int64_t mul;
	int64_t add;
	int64_t div;   /* > 0 */
	uint8_t qty;   /* input_qty_t */
} input_conv_t;

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

/*
 * Build the conversion. SQ_OK, or SQ_EINVAL: factor 0, unknown unit,
 * exponent outside -12..12, a zero radius, or a pressure without area.
 */
int input_conv_make(int32_t f_mant, int8_t f_exp, int32_t o_mant, int8_t o_exp,
		    input_unit_t unit, const input_geom_t *geom, input_conv_t *conv);

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
