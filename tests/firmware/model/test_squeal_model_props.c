/* SPDX-License-Identifier: MIT */
/*
 * Properties of firmware/model that must hold for any input, checked on
 * many deterministic pseudo-random points, plus hand-derived values of the
 * default brake. Compiled for the float build (build/test/tests/firmware/model/test_squeal_model_props)
 * and the fixed build (build/test-fixed/tests/firmware/model/test_squeal_model_props).
 *
 * The few closed forms used here (v_H, N_H, the cubic border) are written
 * out by hand from docs/model.md sections 2 and 4, in double, on the inputs as
 * the build holds them.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "sq_num.h"
#include "squeal_model.h"

/* math.h defines NAN and INFINITY as float constants. */
#define D_NAN ((double)NAN)
#define D_INF ((double)INFINITY)

/* Distance in ln Q from a border below which the class may go either way
 * (the golden-vector test uses the same bound). */
#define BORDER_TOL 1e-3

#if defined(SQUEAL_NUMERIC_FIXED)
#define REL_TOL 1e-3
#else
#define REL_TOL 1e-5
#endif

/* ---- deterministic generator (xorshift64*) -------------------------------- */

static uint64_t rng_state = 0x9e3779b97f4a7c15ULL;

static uint64_t rng_u64(void)
{
	rng_state ^= rng_state >> 12;
	rng_state ^= rng_state << 25;
	rng_state ^= rng_state >> 27;
	return rng_state * 0x2545f4914f6cdd1dULL;
}

static uint32_t rng_u32(void)
{
	return (uint32_t)(rng_u64() >> 32);
}

/* Uniform in [0, 1). */
static double rng_unit(void)
{
	return (double)(rng_u64() >> 11) * 0x1p-53;
}

static double rng_range(double lo, double hi)
{
	return lo + (hi - lo) * rng_unit();
}

static double rng_log(double lo, double hi)
{
	return exp(rng_range(log(lo), log(hi)));
}

/* ---- inputs as the build holds them ---------------------------------------- */

typedef struct {
	double v0, force, slope, damping, omega0, mass, mu_inf, delta_mu;
} pt_t;

typedef struct {
	squeal_params_t p;
	squeal_point_t pt;
	pt_t held; /* the values the model sees, back in double */
} in_t;

static double hold(double v, int q)
{
	return sq_num_to_double(sq_num_from_double(v, q), q);
}

static void make_input(const pt_t *d, in_t *in)
{
	in->pt.v0_mps = sq_num_from_double(d->v0, SQUEAL_Q_V0);
	in->pt.force_n = sq_num_from_double(d->force, SQUEAL_Q_FORCE);
	in->p.slope_spm = sq_num_from_double(d->slope, SQUEAL_Q_SLOPE);
	in->p.damping = sq_num_from_double(d->damping, SQUEAL_Q_DAMPING);
	in->p.omega0_radps = sq_num_from_double(d->omega0, SQUEAL_Q_OMEGA0);
	in->p.mass_kg = sq_num_from_double(d->mass, SQUEAL_Q_MASS);
	in->p.mu_inf = sq_num_from_double(d->mu_inf, SQUEAL_Q_MU);
	in->p.delta_mu = sq_num_from_double(d->delta_mu, SQUEAL_Q_MU);
	in->held.v0 = hold(d->v0, SQUEAL_Q_V0);
	in->held.force = hold(d->force, SQUEAL_Q_FORCE);
	in->held.slope = hold(d->slope, SQUEAL_Q_SLOPE);
	in->held.damping = hold(d->damping, SQUEAL_Q_DAMPING);
	in->held.omega0 = hold(d->omega0, SQUEAL_Q_OMEGA0);
	in->held.mass = hold(d->mass, SQUEAL_Q_MASS);
	in->held.mu_inf = hold(d->mu_inf, SQUEAL_Q_MU);
	in->held.delta_mu = hold(d->delta_mu, SQUEAL_Q_MU);
}

static int classify(const in_t *in, squeal_criterion_t c, squeal_result_t *r)
{
	memset(r, 0xa5, sizeof(*r));
	return squeal_model_classify(&in->p, &in->pt, c, r);
}

static double num(squeal_num_t n, int q)
{
	return sq_num_to_double(n, q);
}

/* ln Q = ln(D w0 m / (a N dmu)) + a v0, docs/model.md section 2. */
static double ln_q(const pt_t *h)
{
	return log(h->damping) + log(h->omega0) + log(h->mass) - log(h->slope) -
	       log(h->force) - log(h->delta_mu) + h->slope * h->v0;
}

/* A random calibration around the paper's brake (docs/model.md sections 6, 8). */
static void random_brake(pt_t *d)
{
	d->slope = rng_range(0.05, 10.0);
	d->damping = rng_log(0.005, 0.3);
	d->omega0 = rng_log(500.0, 50000.0);
	d->mass = rng_log(0.2, 5.0);
	d->mu_inf = rng_range(0.1, 0.5);
	d->delta_mu = rng_range(0.01, 0.4);
	d->v0 = rng_range(0.01, 40.0);
	d->force = rng_range(1.0, 30000.0);
}

/* ---- properties ------------------------------------------------------------ */

/*
 * At fixed N, steady sliding is unstable exactly below v_H (docs/model.md section 2):
 * sweeping v0 upwards, the class is UNSTABLE until v_H and never again
 * after it. And at fixed v0, unstable exactly above N_H.
 */
static void test_class_monotone_in_v0_across_hopf_border(void **state)
{
	unsigned checked = 0U;
	unsigned sets = 0U;
	int k;

	(void)state;
	for (k = 0; k < 400; k++) {
		pt_t d;
		in_t in;
		double ln_r;
		double v_h;
		int i;

		random_brake(&d);
		make_input(&d, &in);
		/* ln(a N dmu / (2 D w0 m)) */
		ln_r = log(in.held.slope) + log(in.held.force) + log(in.held.delta_mu) -
		       log(2.0) - log(in.held.damping) - log(in.held.omega0) -
		       log(in.held.mass);
		if (ln_r <= 0.0) {
			continue;
		}
		v_h = ln_r / in.held.slope;
		if (v_h > 90.0) {
			continue;
		}
		sets++;
		for (i = 1; i <= 60; i++) {
			squeal_result_t r;
			squeal_criterion_t c = (i & 1) ? SQUEAL_CRITERION_CUBIC :
							 SQUEAL_CRITERION_EXACT;
			double dist;

			d.v0 = v_h * 2.0 * i / 60.0;
			if (d.v0 > 100.0) {
				break;
			}
			make_input(&d, &in);
			/* distance from the Hopf border in ln Q */
			dist = in.held.slope * (in.held.v0 - v_h);
			assert_int_equal(classify(&in, c, &r), SQ_OK);
			if (dist < -BORDER_TOL && r.state != SQUEAL_STATE_UNSTABLE) {
				print_error("v0=%.9g below v_H=%.9g (a=%g N=%g) but %s\n", in.held.v0,
					    v_h, in.held.slope, in.held.force,
					    squeal_model_state_name(r.state));
				fail();
			}
			if (dist > BORDER_TOL && r.state == SQUEAL_STATE_UNSTABLE) {
				print_error("v0=%.9g above v_H=%.9g (a=%g N=%g) but unstable\n",
					    in.held.v0, v_h, in.held.slope, in.held.force);
				fail();
			}
			if (fabs(dist) > BORDER_TOL) {
				/* margin has the sign of the side */
				assert_true((r.flags & SQUEAL_HAS_HOPF_V0) != 0U);
				assert_true((num(r.hopf_margin_mps, SQUEAL_Q_V0) < 0.0) ==
					    (dist < 0.0));
				checked++;
			}
		}
	}
	print_message("monotone in v0: %u points on %u calibrations\n", checked, sets);
	assert_true(sets > 100U && checked > 5000U);
}

static void test_class_monotone_in_force_across_hopf_border(void **state)
{
	unsigned checked = 0U;
	int k;

	(void)state;
	for (k = 0; k < 300; k++) {
		pt_t d;
		in_t in;
		double n_h;
		int i;

		random_brake(&d);
		d.v0 = rng_range(0.05, 5.0);
		make_input(&d, &in);
		/* N_H = 2 D w0 m e^(a v0) / (a dmu), docs/model.md section 2 */
		n_h = 2.0 * in.held.damping * in.held.omega0 * in.held.mass *
		      exp(in.held.slope * in.held.v0) / (in.held.slope * in.held.delta_mu);
		if (n_h > 200000.0 || n_h < 10.0) {
			continue;
		}
		for (i = 1; i <= 40; i++) {
			squeal_result_t r;
			double dist;

			d.force = n_h * 2.0 * i / 40.0;
			make_input(&d, &in);
			dist = log(n_h / in.held.force); /* ln Q - ln 1/2 */
			assert_int_equal(classify(&in, SQUEAL_CRITERION_EXACT, &r), SQ_OK);
			if (dist < -BORDER_TOL) {
				assert_int_equal(r.state, SQUEAL_STATE_UNSTABLE);
			}
			if (dist > BORDER_TOL) {
				assert_int_not_equal(r.state, SQUEAL_STATE_UNSTABLE);
			}
			checked++;
		}
	}
	print_message("monotone in N: %u points\n", checked);
	assert_true(checked > 2000U);
}

/*
 * I1(s)/s >= 1/2 + s^2/16 (the cubic is the series truncated), so exact
 * "stable" implies cubic "stable": the cubic form never warns more.
 * Both share the Hopf border, so "unstable" agrees.
 */
static void test_cubic_stable_set_contains_exact_stable_set(void **state)
{
	unsigned n_exact_stable = 0U;
	unsigned n_underwarn = 0U;
	int k;

	(void)state;
	for (k = 0; k < 20000; k++) {
		pt_t d;
		in_t in;
		squeal_result_t re;
		squeal_result_t rc;
		double lq;
		double s;
		double cubic_border;

		random_brake(&d);
		d.v0 = rng_range(0.01, 6.0);
		make_input(&d, &in);
		assert_int_equal(classify(&in, SQUEAL_CRITERION_EXACT, &re), SQ_OK);
		assert_int_equal(classify(&in, SQUEAL_CRITERION_CUBIC, &rc), SQ_OK);
		lq = ln_q(&in.held);
		s = in.held.slope * in.held.v0;
		cubic_border = log(0.5 + s * s / 16.0);
		if (fabs(lq - log(0.5)) > BORDER_TOL) {
			assert_int_equal(re.state == SQUEAL_STATE_UNSTABLE,
					 rc.state == SQUEAL_STATE_UNSTABLE);
		}
		if (re.state == SQUEAL_STATE_STABLE) {
			n_exact_stable++;
			if (fabs(lq - cubic_border) > BORDER_TOL &&
			    rc.state != SQUEAL_STATE_STABLE) {
				print_error("exact stable, cubic %s: v0=%g N=%g a=%g\n",
					    squeal_model_state_name(rc.state), in.held.v0,
					    in.held.force, in.held.slope);
				fail();
			}
		}
		if (re.state == SQUEAL_STATE_BISTABLE && rc.state == SQUEAL_STATE_STABLE) {
			n_underwarn++;
		}
	}
	print_message("exact stable %u, cubic under-warns (exact bistable, cubic stable) %u\n",
		      n_exact_stable, n_underwarn);
	assert_true(n_exact_stable > 1000U && n_underwarn > 100U);
}

/* rho = x / s lies in (0, 1) exactly for bistable points (docs/model.md section 4). */
static void test_basin_ratio_below_one_exactly_for_bistable(void **state)
{
	unsigned n_bistable = 0U;
	unsigned n_stable = 0U;
	int k;

	(void)state;
	for (k = 0; k < 20000; k++) {
		pt_t d;
		in_t in;
		squeal_result_t r;
		squeal_criterion_t c = (k & 1) ? SQUEAL_CRITERION_CUBIC : SQUEAL_CRITERION_EXACT;
		double rho;

		random_brake(&d);
		d.v0 = rng_range(0.01, 8.0);
		make_input(&d, &in);
		assert_int_equal(classify(&in, c, &r), SQ_OK);
		if (r.state == SQUEAL_STATE_UNSTABLE) {
			assert_true((r.flags & (SQUEAL_HAS_BASIN | SQUEAL_HAS_CYCLE)) == 0U);
			continue;
		}
		assert_true((r.flags & SQUEAL_HAS_BASIN) != 0U);
		assert_true((r.flags & SQUEAL_HAS_CYCLE) != 0U);
		rho = num(r.basin_ratio, SQUEAL_Q_RATIO);
		if (r.state == SQUEAL_STATE_BISTABLE) {
			n_bistable++;
			assert_true(rho > 0.0);
			/* class and ratio come from one x; allow rounding at 1 */
			assert_true(rho < 1.0 + BORDER_TOL);
		} else {
			n_stable++;
			assert_true(rho > 1.0 - BORDER_TOL ||
				    (r.flags & SQUEAL_SAT_BASIN) != 0U);
		}
	}
	print_message("bistable %u, stable %u\n", n_bistable, n_stable);
	assert_true(n_bistable > 1000U && n_stable > 1000U);
}

/* ---- robustness -------------------------------------------------------------- */

/* squeal_model.h's domain, on the values as held. */
static bool in_domain(const pt_t *h)
{
	return h->mass > 0.0 && h->mass <= 10000.0 &&
	       h->omega0 > 0.0 && h->omega0 <= 500000.0 &&
	       h->damping > 0.0 && h->damping <= 1.0 &&
	       h->slope >= 0.0 && h->slope <= 20.0 &&
	       h->mu_inf >= 0.0 && h->mu_inf <= 1.5 &&
	       h->delta_mu >= -1.5 && h->delta_mu <= 1.5 &&
	       h->mu_inf + h->delta_mu >= 0.0 &&
	       h->v0 >= 0.0 && h->v0 <= 100.0 &&
	       h->force >= 0.0 && h->force <= 500000.0;
}

static void check_any(const in_t *in, squeal_criterion_t c, unsigned *n_valid)
{
	static const squeal_state_t states[] = {
		SQUEAL_STATE_STABLE, SQUEAL_STATE_BISTABLE, SQUEAL_STATE_UNSTABLE,
		SQUEAL_STATE_NOT_SLIDING, SQUEAL_STATE_INVALID,
	};
	const uint32_t known = 0x1fU | (0x3fU << 8);
	squeal_result_t r;
	bool valid_c = (c == SQUEAL_CRITERION_EXACT || c == SQUEAL_CRITERION_CUBIC);
	bool want_ok = valid_c && in_domain(&in->held);
	bool ok_state = false;
	size_t i;
	int ret;

	ret = classify(in, c, &r);
	for (i = 0; i < sizeof(states) / sizeof(states[0]); i++) {
		if (r.state == states[i]) {
			ok_state = true;
		}
	}
	if (!ok_state || (ret == SQ_OK) != (r.state != SQUEAL_STATE_INVALID) ||
	    (ret != SQ_OK && ret != SQ_EINVAL) || (ret == SQ_OK) != want_ok ||
	    (r.flags & ~known) != 0U) {
		print_error("ret %d state %d flags 0x%x, want %s; in: v0=%.9g N=%.9g a=%.9g "
			    "D=%.9g w0=%.9g m=%.9g mu=%.9g dmu=%.9g crit=%d\n",
			    ret, (int)r.state, (unsigned)r.flags, want_ok ? "ok" : "invalid",
			    in->held.v0, in->held.force, in->held.slope, in->held.damping,
			    in->held.omega0, in->held.mass, in->held.mu_inf, in->held.delta_mu,
			    (int)c);
		fail();
	}
	if (ret == SQ_OK) {
		(*n_valid)++;
#if !defined(SQUEAL_NUMERIC_FIXED)
		/* Every value is a finite number (saturated ones are FLT_MAX). */
		if (!(isfinite(r.ln_q) && isfinite(r.hopf_v0_mps) &&
		      isfinite(r.hopf_margin_mps) && isfinite(r.hopf_force_n) &&
		      isfinite(r.cycle_x) && isfinite(r.lc_amplitude_um) &&
		      isfinite(r.trigger_velocity_mps) && isfinite(r.basin_ratio))) {
			print_error("non-finite output, flags 0x%x; in: v0=%.9g N=%.9g a=%.9g "
				    "D=%.9g w0=%.9g m=%.9g mu=%.9g dmu=%.9g\n", (unsigned)r.flags,
				    in->held.v0, in->held.force, in->held.slope, in->held.damping,
				    in->held.omega0, in->held.mass, in->held.mu_inf,
				    in->held.delta_mu);
			fail();
		}
#endif
	} else {
		assert_int_equal(r.flags, 0);
	}
}

static squeal_num_t bits_to_num(uint32_t b)
{
	squeal_num_t n;

	_Static_assert(sizeof(n) == sizeof(b), "squeal_num_t is 32 bits");
	memcpy(&n, &b, sizeof(n));
	return n;
}

static void test_every_bit_pattern_is_handled(void **state)
{
	unsigned n_valid = 0U;
	int k;

	(void)state;
	for (k = 0; k < 200000; k++) {
		in_t in;
		squeal_criterion_t c;
		uint32_t cb = rng_u32();

		in.pt.v0_mps = bits_to_num(rng_u32());
		in.pt.force_n = bits_to_num(rng_u32());
		in.p.slope_spm = bits_to_num(rng_u32());
		in.p.damping = bits_to_num(rng_u32());
		in.p.omega0_radps = bits_to_num(rng_u32());
		in.p.mass_kg = bits_to_num(rng_u32());
		in.p.mu_inf = bits_to_num(rng_u32());
		in.p.delta_mu = bits_to_num(rng_u32());
		in.held.v0 = num(in.pt.v0_mps, SQUEAL_Q_V0);
		in.held.force = num(in.pt.force_n, SQUEAL_Q_FORCE);
		in.held.slope = num(in.p.slope_spm, SQUEAL_Q_SLOPE);
		in.held.damping = num(in.p.damping, SQUEAL_Q_DAMPING);
		in.held.omega0 = num(in.p.omega0_radps, SQUEAL_Q_OMEGA0);
		in.held.mass = num(in.p.mass_kg, SQUEAL_Q_MASS);
		in.held.mu_inf = num(in.p.mu_inf, SQUEAL_Q_MU);
		in.held.delta_mu = num(in.p.delta_mu, SQUEAL_Q_MU);
		/* mostly the two real criteria, sometimes garbage */
		cb = ((cb & 0xffU) < 0xf0U) ? (cb & 1U) : cb;
		memcpy(&c, &cb, sizeof(c));
		check_any(&in, c, &n_valid);
	}
	print_message("random bit patterns: %u of 200000 inside the domain\n", n_valid);

	/* One field random bits, the others a plausible brake: reaches the
	 * computation with every kind of odd value (denormals, huge, tiny). */
	n_valid = 0U;
	for (k = 0; k < 200000; k++) {
		pt_t d;
		in_t in;
		squeal_num_t *field[8];
		int q[8] = { SQUEAL_Q_V0, SQUEAL_Q_FORCE, SQUEAL_Q_SLOPE, SQUEAL_Q_DAMPING,
			     SQUEAL_Q_OMEGA0, SQUEAL_Q_MASS, SQUEAL_Q_MU, SQUEAL_Q_MU };
		double *held[8];
		unsigned which = rng_u32() % 8U;

		random_brake(&d);
		make_input(&d, &in);
		field[0] = &in.pt.v0_mps;
		field[1] = &in.pt.force_n;
		field[2] = &in.p.slope_spm;
		field[3] = &in.p.damping;
		field[4] = &in.p.omega0_radps;
		field[5] = &in.p.mass_kg;
		field[6] = &in.p.mu_inf;
		field[7] = &in.p.delta_mu;
		held[0] = &in.held.v0;
		held[1] = &in.held.force;
		held[2] = &in.held.slope;
		held[3] = &in.held.damping;
		held[4] = &in.held.omega0;
		held[5] = &in.held.mass;
		held[6] = &in.held.mu_inf;
		held[7] = &in.held.delta_mu;
		*field[which] = bits_to_num(rng_u32());
		*held[which] = num(*field[which], q[which]);
		check_any(&in, (k & 1) ? SQUEAL_CRITERION_CUBIC : SQUEAL_CRITERION_EXACT,
			  &n_valid);
	}
	print_message("one field random bits: %u of 200000 inside the domain\n", n_valid);
	assert_true(n_valid > 10000U);
}

/* Per-field values that sit at, just inside and just outside the limits,
 * tiny, denormal, zero, NaN and infinite, mixed at random. */
static double edge_value(double lo, double hi)
{
	switch (rng_u32() % 16U) {
	case 0:
		return 0.0;
	case 1:
		return lo;
	case 2:
		return hi;
	case 3:
		return nextafter(hi, D_INF) * (1.0 + 1e-6);
	case 4:
		return -1e-6;
	case 5:
		return D_NAN;
	case 6:
		return D_INF;
	case 7:
		return 1e-40;
	case 8:
		return 1e-9;
	default:
		return (hi > 0.0) ? rng_log(1e-7, hi) : rng_range(lo, hi);
	}
}

static void test_edge_values_are_handled(void **state)
{
	unsigned n_valid = 0U;
	int k;

	(void)state;
	for (k = 0; k < 100000; k++) {
		pt_t d;
		in_t in;

		d.v0 = edge_value(0.0, 100.0);
		d.force = edge_value(0.0, 500000.0);
		d.slope = edge_value(0.0, 20.0);
		d.damping = edge_value(0.0, 1.0);
		d.omega0 = edge_value(0.0, 500000.0);
		d.mass = edge_value(0.0, 10000.0);
		d.mu_inf = edge_value(0.0, 1.5);
		d.delta_mu = (rng_u32() & 1U) ? -edge_value(0.0, 1.5) : edge_value(0.0, 1.5);
		make_input(&d, &in);
		check_any(&in, (k & 1) ? SQUEAL_CRITERION_CUBIC : SQUEAL_CRITERION_EXACT,
			  &n_valid);
	}
	print_message("edge values: %u of 100000 inside the domain\n", n_valid);
	assert_true(n_valid > 1000U);
}

/* ---- hand-derived values ---------------------------------------------------- */

static void default_brake(pt_t *d, double v0, double force)
{
	d->mass = 1.0;
	d->omega0 = 5000.0;
	d->damping = 0.023;
	d->mu_inf = 0.25;
	d->delta_mu = 0.15;
	d->slope = 2.0;
	d->v0 = v0;
	d->force = force;
}

static void assert_close(double got, double want, double tol, const char *what)
{
	if (!(fabs(got - want) <= tol)) {
		print_error("%s = %.9g, want %.9g +- %.3g\n", what, got, want, tol);
		fail();
	}
}

/*
 * Default brake (docs/model.md section 8): m = 1 kg, w0 = 5000 rad/s, D = 0.023,
 * dmu = 0.15, a = 2 s/m, N = 9000 N.
 *   a N dmu = 2 * 9000 * 0.15 = 2700;  2 D w0 m = 2 * 0.023 * 5000 = 230
 *   v_H = ln(2700 / 230) / 2 = ln(11.7391304) / 2 = 2.4629277 / 2
 *       = 1.2314639 m/s                      (docs/model.md: 1.2315 m/s)
 * At v0 = 1 m/s:
 *   N_H = 2 D w0 m e^(a v0) / (a dmu) = 230 e^2 / 0.3
 *       = 766.66667 * 7.3890561 = 5664.9430 N
 *   ln Q = ln(115 / 2700) + 2 = -3.1560749 + 2 = -1.1560749 < ln 1/2
 *       -> unstable; margin = 1 - 1.2314639 = -0.2314639 m/s.
 * At v0 = 2 m/s: ln Q = -3.1560749 + 4 = 0.8439251, Q = 2.3254; s = 4:
 *   exact: I1(4)/4 = 9.7594652 / 4 = 2.4398663 > Q        -> bistable
 *   cubic: 1/2 + 16/16 = 1.5 < Q                          -> stable
 *   (the cubic form under-warns, docs/model.md section 6).
 */
static void test_default_brake_hand_values(void **state)
{
	double tol_rel = REL_TOL;
	pt_t d;
	in_t in;
	squeal_result_t r;

	(void)state;
	default_brake(&d, 1.0, 9000.0);
	make_input(&d, &in);
	assert_int_equal(classify(&in, SQUEAL_CRITERION_EXACT, &r), SQ_OK);
	assert_int_equal(r.state, SQUEAL_STATE_UNSTABLE);
	assert_true((r.flags & SQUEAL_HAS_HOPF_V0) && (r.flags & SQUEAL_HAS_HOPF_FORCE) &&
		    (r.flags & SQUEAL_HAS_LNQ));
	assert_true((r.flags & (SQUEAL_HAS_CYCLE | SQUEAL_HAS_BASIN)) == 0U);
	assert_close(num(r.hopf_v0_mps, SQUEAL_Q_V0), 1.2314639, 1.2315 * tol_rel + 1e-7,
		     "v_H");
	assert_close(num(r.hopf_margin_mps, SQUEAL_Q_V0), -0.2314639, 1.2315 * tol_rel + 1e-7,
		     "margin");
	assert_close(num(r.hopf_force_n, SQUEAL_Q_FORCE), 5664.9430, 5664.943 * tol_rel + 1e-3,
		     "N_H");
	assert_close(num(r.ln_q, SQUEAL_Q_LNQ), -1.1560749, 1e-4, "ln Q");

	default_brake(&d, 2.0, 9000.0);
	make_input(&d, &in);
	assert_int_equal(classify(&in, SQUEAL_CRITERION_EXACT, &r), SQ_OK);
	assert_int_equal(r.state, SQUEAL_STATE_BISTABLE);
	assert_int_equal(classify(&in, SQUEAL_CRITERION_CUBIC, &r), SQ_OK);
	assert_int_equal(r.state, SQUEAL_STATE_STABLE);

	/* Not sliding: no speed, or no force. */
	default_brake(&d, 0.0, 9000.0);
	make_input(&d, &in);
	assert_int_equal(classify(&in, SQUEAL_CRITERION_EXACT, &r), SQ_OK);
	assert_int_equal(r.state, SQUEAL_STATE_NOT_SLIDING);
	default_brake(&d, 1.0, 0.0);
	make_input(&d, &in);
	assert_int_equal(classify(&in, SQUEAL_CRITERION_EXACT, &r), SQ_OK);
	assert_int_equal(r.state, SQUEAL_STATE_NOT_SLIDING);
	/* Friction not falling with speed: stable, nothing else. */
	default_brake(&d, 1.0, 9000.0);
	d.slope = 0.0;
	make_input(&d, &in);
	assert_int_equal(classify(&in, SQUEAL_CRITERION_EXACT, &r), SQ_OK);
	assert_int_equal(r.state, SQUEAL_STATE_STABLE);
	assert_int_equal(r.flags, 0);
	default_brake(&d, 1.0, 9000.0);
	d.delta_mu = -0.1;
	make_input(&d, &in);
	assert_int_equal(classify(&in, SQUEAL_CRITERION_CUBIC, &r), SQ_OK);
	assert_int_equal(r.state, SQUEAL_STATE_STABLE);
	assert_int_equal(r.flags, 0);
}

/*
 * docs/model.md section 6, "exact averaged x" and "cubic x3" columns, at
 * D = 0.023: pick N so that Q is the table's value with the default brake
 * at v0 = 1 m/s:  Q = 115 e^2 / (0.3 N)  ->  N = 115 e^2 / (0.3 Q).
 * cubic x3 = 4 sqrt(Q - 1/2) by hand: Q = 0.6 -> 4 sqrt(0.1) = 1.2649;
 * 1 -> 2.8284; 2 -> 4.8990; 3 -> 6.3246. Table values have 4 decimals.
 */
static void test_cycle_x_matches_model_md_table(void **state)
{
	static const struct {
		double q, x_exact, x_cubic;
	} rows[] = {
		{ 0.6, 1.2259, 1.2649 }, { 1.0, 2.4868, 2.8284 },
		{ 2.0, 3.6924, 4.8990 }, { 3.0, 4.3089, 6.3246 },
	};
	size_t i;

	(void)state;
	for (i = 0; i < sizeof(rows) / sizeof(rows[0]); i++) {
		pt_t d;
		in_t in;
		squeal_result_t r;

		default_brake(&d, 1.0, 115.0 * exp(2.0) / (0.3 * rows[i].q));
		make_input(&d, &in);
		assert_int_equal(classify(&in, SQUEAL_CRITERION_EXACT, &r), SQ_OK);
		assert_true((r.flags & SQUEAL_HAS_CYCLE) != 0U);
		assert_close(num(r.cycle_x, SQUEAL_Q_CYCLE_X), rows[i].x_exact,
			     6e-5 + rows[i].x_exact * REL_TOL, "exact x");
		/* A = x / (a w0), in um; trigger = x / a */
		assert_close(num(r.lc_amplitude_um, SQUEAL_Q_AMPL_UM),
			     rows[i].x_exact / (2.0 * 5000.0) * 1e6,
			     (6e-5 + rows[i].x_exact * REL_TOL) * 100.0, "A_LC um");
		assert_close(num(r.trigger_velocity_mps, SQUEAL_Q_V0), rows[i].x_exact / 2.0,
			     3e-5 + rows[i].x_exact * REL_TOL, "trigger");
		assert_int_equal(classify(&in, SQUEAL_CRITERION_CUBIC, &r), SQ_OK);
		assert_close(num(r.cycle_x, SQUEAL_Q_CYCLE_X), rows[i].x_cubic,
			     6e-5 + rows[i].x_cubic * REL_TOL, "cubic x3");
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_class_monotone_in_v0_across_hopf_border),
		cmocka_unit_test(test_class_monotone_in_force_across_hopf_border),
		cmocka_unit_test(test_cubic_stable_set_contains_exact_stable_set),
		cmocka_unit_test(test_basin_ratio_below_one_exactly_for_bistable),
		cmocka_unit_test(test_every_bit_pattern_is_handled),
		cmocka_unit_test(test_edge_values_are_handled),
		cmocka_unit_test(test_default_brake_hand_values),
		cmocka_unit_test(test_cycle_x_matches_model_md_table),
	};

	return cmocka_run_group_tests_name(sq_num_is_fixed() ? "model props (fixed)" :
							       "model props (float)",
					   tests, NULL, NULL);
}
