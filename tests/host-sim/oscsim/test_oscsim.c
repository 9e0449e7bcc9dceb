/* SPDX-License-Identifier: MIT */
/*
 * Unit tests of host-sim/oscsim against closed forms derived by hand:
 * the harmonic and the damped linear oscillator, constant-friction
 * stick-slip, the linearised return map at the Hopf point, and the table
 * of docs/model.md section 6 (computed there independently).
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "oscsim/oscsim.h"

#define PI 3.14159265358979323846
#define D_INF ((double)INFINITY)

/* cmocka's assert_float_equal works in float; these tolerances need double */
#define assert_near(a, b, tol)                                              \
	do {                                                                \
		double a_ = (a), b_ = (b), t_ = (tol);                      \
		if (!(fabs(a_ - b_) <= t_)) {                               \
			fail_msg("%s = %.17g, expected %.17g +- %.3g", #a,  \
				 a_, b_, t_);                               \
		}                                                           \
	} while (0)

/* ---- the integrator on y'' = -y ----------------------------------------- */

static void harmonic(double t, const double *y, double *dydt, void *ctx)
{
	(void)t;
	(void)ctx;
	dydt[0] = y[1];
	dydt[1] = -y[0];
}

static void init_harmonic(oscsim_dp5_t *dp, int dir, double rtol)
{
	const double y0[2] = { 1.0, 0.0 };
	const double atol[2] = { rtol * 1e-2, rtol * 1e-2 };

	assert_int_equal(oscsim_dp5_init(dp, 2, harmonic, NULL, 0.0, y0, dir, 0.0,
					 rtol, atol, 100000U),
			 SQ_OK);
}

static void test_dp5_harmonic_forward_and_backward(void **state)
{
	oscsim_dp5_t dp;

	(void)state;
	init_harmonic(&dp, 1, 1e-10);
	assert_int_equal(oscsim_dp5_advance(&dp, 20.0, NULL), OSCSIM_REACHED_END);
	assert_true(dp.t == 20.0);
	assert_near(dp.y[0], cos(20.0), 1e-8);
	assert_near(dp.y[1], -sin(20.0), 1e-8);

	init_harmonic(&dp, -1, 1e-10);
	assert_int_equal(oscsim_dp5_advance(&dp, -20.0, NULL), OSCSIM_REACHED_END);
	assert_near(dp.y[0], cos(20.0), 1e-8);
	assert_near(dp.y[1], sin(20.0), 1e-8);
}

static void test_dp5_error_falls_with_tolerance(void **state)
{
	double tol[3] = { 1e-5, 1e-8, 1e-11 };
	double err[3];
	uint32_t evals[3];
	int i;

	(void)state;
	for (i = 0; i < 3; i++) {
		oscsim_dp5_t dp;

		init_harmonic(&dp, 1, tol[i]);
		assert_int_equal(oscsim_dp5_advance(&dp, 10.0, NULL),
				 OSCSIM_REACHED_END);
		err[i] = hypot(dp.y[0] - cos(10.0), dp.y[1] + sin(10.0));
		evals[i] = dp.f_evals;
	}
	/* 5th order: 1000x tighter tolerance costs ~4x the work */
	assert_true(err[1] < err[0] / 100.0);
	assert_true(err[2] < err[1] / 100.0);
	assert_true(evals[2] < 8U * evals[1]);
}

typedef struct {
	double worst;
	uint32_t n;
} dense_check_t;

static void dense_step(void *ctx, const oscsim_dp5_t *dp, double t_stop)
{
	dense_check_t *c = ctx;
	double y[2];
	int k;

	for (k = 1; k < 8; k++) {
		double t = dp->t_old + (t_stop - dp->t_old) * k / 8.0;

		oscsim_dp5_dense(dp, t, y);
		c->worst = fmax(c->worst, fabs(y[0] - cos(t)));
		c->n++;
	}
}

static void test_dp5_dense_output_between_steps(void **state)
{
	oscsim_dp5_t dp;
	oscsim_watch_t w;
	dense_check_t c = { 0.0, 0U };

	(void)state;
	init_harmonic(&dp, 1, 1e-10);
	memset(&w, 0, sizeof(w));
	w.step_fn = dense_step;
	w.step_ctx = &c;
	assert_int_equal(oscsim_dp5_advance(&dp, 10.0, &w), OSCSIM_REACHED_END);
	assert_true(c.n > 50U);
	assert_true(c.worst < 1e-8);
}

static double ev_u(double t, const double *y, void *ctx)
{
	(void)t;
	(void)ctx;
	return y[0];
}

static void test_dp5_event_location_and_direction(void **state)
{
	oscsim_dp5_t dp;
	oscsim_event_t ev = { ev_u, NULL, -1 };
	oscsim_watch_t w;

	(void)state;
	memset(&w, 0, sizeof(w));
	w.ev = &ev;
	w.n_ev = 1;
	/* cos t falls through 0 at pi/2 */
	init_harmonic(&dp, 1, 1e-10);
	assert_int_equal(oscsim_dp5_advance(&dp, 10.0, &w), 0);
	assert_near(dp.t, PI / 2.0, 1e-10);
	/* rising only: the first is 3 pi / 2 */
	ev.dir = 1;
	init_harmonic(&dp, 1, 1e-10);
	assert_int_equal(oscsim_dp5_advance(&dp, 10.0, &w), 0);
	assert_near(dp.t, 1.5 * PI, 1e-10);
	/* after the restart the same crossing is not found again */
	assert_int_equal(oscsim_dp5_advance(&dp, 12.0, &w), 0);
	assert_near(dp.t, 3.5 * PI, 1e-9);
}

static void test_dp5_budget_and_bad_arguments(void **state)
{
	oscsim_dp5_t dp;
	const double y0[2] = { 1.0, 0.0 };
	const double atol[2] = { 1e-12, 1e-12 };
	const double bad_atol[2] = { -1.0, 1e-12 };

	(void)state;
	assert_int_equal(oscsim_dp5_init(&dp, 2, harmonic, NULL, 0.0, y0, 1, 0.0,
					 1e-10, atol, 5U),
			 SQ_OK);
	assert_int_equal(oscsim_dp5_advance(&dp, 100.0, NULL), SQ_ERANGE);
	assert_int_equal(oscsim_dp5_init(&dp, 0, harmonic, NULL, 0.0, y0, 1, 0.0,
					 1e-10, atol, 5U),
			 SQ_EINVAL);
	assert_int_equal(oscsim_dp5_init(&dp, 2, harmonic, NULL, 0.0, y0, 0, 0.0,
					 1e-10, atol, 5U),
			 SQ_EINVAL);
	assert_int_equal(oscsim_dp5_init(&dp, 2, harmonic, NULL, 0.0, y0, 1, 0.0,
					 0.0, atol, 5U),
			 SQ_EINVAL);
	assert_int_equal(oscsim_dp5_init(&dp, 2, harmonic, NULL, 0.0, y0, 1, 0.0,
					 1e-10, bad_atol, 5U),
			 SQ_EINVAL);
}

/* ---- the physical oscillator -------------------------------------------- */

/* With a = 0 friction is constant (mu_0 N): while sliding, the oscillator
 * is linear, z = x - x_s = e^(-zeta t)(z0 cos wd t + (v + zeta z0)/wd sin wd t). */
typedef struct {
	double zeta, wd, z0, zd0, xs;
} damped_t;

static double damped_z(const damped_t *d, double t)
{
	return exp(-d->zeta * t) *
	       (d->z0 * cos(d->wd * t) +
		(d->zd0 + d->zeta * d->z0) / d->wd * sin(d->wd * t));
}

static double damped_zd(const damped_t *d, double t)
{
	double h = 1e-7 * 2.0 * PI / d->wd;

	/* central difference of the closed form is plenty (1e-12 rel) */
	return (damped_z(d, t + h) - damped_z(d, t - h)) / (2.0 * h);
}

typedef struct {
	const damped_t *d;
	double worst;
	uint32_t n;
} sample_check_t;

static void check_sample(void *ctx, double t, double x, double v,
			 oscsim_mode_t mode)
{
	sample_check_t *c = ctx;

	(void)v;
	assert_int_equal(mode, OSCSIM_SLIP_POS);
	c->worst = fmax(c->worst, fabs(x - c->d->xs - damped_z(c->d, t)));
	c->n++;
}

static void test_sim_constant_friction_is_the_damped_oscillator(void **state)
{
	oscsim_params_t p;
	oscsim_sim_opts_t o;
	oscsim_sim_result_t r;
	damped_t d;
	sample_check_t c;
	double a0 = 1e-4;

	(void)state;
	oscsim_default_params(&p);
	p.slope_spm = 0.0;
	p.v0_mps = 10.0; /* max |x'| = a0 w0 = 0.5 m/s: never sticks */
	d.zeta = p.damping * p.omega0_radps;
	d.wd = p.omega0_radps * sqrt(1.0 - p.damping * p.damping);
	d.z0 = a0;
	d.zd0 = 0.0;
	d.xs = p.force_n * (p.mu_inf + p.delta_mu) /
	       (p.mass_kg * p.omega0_radps * p.omega0_radps);
	assert_near(oscsim_steady_x(&p), d.xs, 1e-15);
	oscsim_sim_default_opts(&o, 0.02);
	o.rtol = 1e-10;
	o.sample_dt_s = 1e-4;
	o.on_sample = check_sample;
	c.d = &d;
	c.worst = 0.0;
	c.n = 0;
	o.cb_ctx = &c;
	assert_int_equal(oscsim_simulate(&p, d.xs + a0, 0.0, &o, &r), SQ_OK);
	assert_int_equal(r.stick_entries, 0);
	assert_true(c.n >= 200U);
	assert_true(c.worst < 1e-7 * a0);
	assert_near(r.x_m - d.xs, damped_z(&d, 0.02), 1e-7 * a0);
}

typedef struct {
	double t[8];
	double x[8];
	oscsim_mode_t m[8];
	uint32_t n;
} switch_log_t;

static void log_switch(void *ctx, double t, double x, double v,
		       oscsim_mode_t mode)
{
	switch_log_t *l = ctx;

	(void)v;
	if (l->n < 8U) {
		l->t[l->n] = t;
		l->x[l->n] = x;
		l->m[l->n] = mode;
		l->n++;
	}
}

/* Find t in (lo, hi) with damped_zd = target (zd - target changes sign). */
static double solve_velocity(const damped_t *d, double target, double lo,
			     double hi)
{
	int i;

	for (i = 0; i < 200; i++) {
		double mid = 0.5 * (lo + hi);

		if ((damped_zd(d, lo) - target) * (damped_zd(d, mid) - target) <= 0.0) {
			hi = mid;
		} else {
			lo = mid;
		}
	}
	return 0.5 * (lo + hi);
}

static void test_sim_stick_and_release_with_constant_friction(void **state)
{
	oscsim_params_t p;
	oscsim_sim_opts_t o;
	oscsim_sim_result_t r;
	switch_log_t l;
	damped_t d;
	double x_exit, t_stick, x_stick, period, amp;

	(void)state;
	oscsim_default_params(&p);
	p.slope_spm = 0.0;
	p.v0_mps = 0.05;
	d.zeta = p.damping * p.omega0_radps;
	d.wd = p.omega0_radps * sqrt(1.0 - p.damping * p.damping);
	d.xs = oscsim_steady_x(&p);
	period = 2.0 * PI / d.wd;
	/* released from rest at x_s + A with A w0 = 2 v0: x' swings down,
	 * then up to ~1.8 v0, so it meets the disc speed below x_s and sticks */
	amp = 2.0 * p.v0_mps / p.omega0_radps;
	d.z0 = amp;
	d.zd0 = 0.0;
	t_stick = solve_velocity(&d, p.v0_mps, 0.25 * period, 0.75 * period);
	x_stick = d.xs + damped_z(&d, t_stick);
	/* the pad is carried until spring and damper need mu_0 N */
	x_exit = ((p.mu_inf + p.delta_mu) * p.force_n / p.mass_kg -
		  2.0 * p.damping * p.omega0_radps * p.v0_mps) /
		 (p.omega0_radps * p.omega0_radps);
	assert_true(x_stick < x_exit);

	memset(&l, 0, sizeof(l));
	oscsim_sim_default_opts(&o, 4.0 * period);
	o.rtol = 1e-11;
	o.on_switch = log_switch;
	o.cb_ctx = &l;
	assert_int_equal(oscsim_simulate(&p, d.xs + amp, 0.0, &o, &r), SQ_OK);
	assert_int_equal(l.n, 2U);
	assert_int_equal(l.m[0], OSCSIM_STICK);
	assert_near(l.t[0], t_stick, 1e-9 * t_stick);
	assert_near(l.x[0], x_stick, 1e-7 * amp);
	assert_int_equal(l.m[1], OSCSIM_SLIP_POS);
	assert_near(l.x[1], x_exit, 1e-15);
	assert_near(l.t[1], t_stick + (x_exit - x_stick) / p.v0_mps,
			    1e-9 * t_stick);
	/* with friction that does not fall with speed, steady sliding is
	 * stable: released with x' = v0 it never reaches the disc again */
	assert_int_equal(r.stick_entries, 1U);
	assert_true(r.v_max_mps <= p.v0_mps * (1.0 + 1e-9));
}

typedef struct {
	double v0;
	uint32_t n;
	uint32_t bad;
	uint32_t neg;
} mode_check_t;

static void check_mode(void *ctx, double t, double x, double v,
		       oscsim_mode_t mode)
{
	mode_check_t *c = ctx;
	double tol = 1e-6 * c->v0;

	(void)t;
	(void)x;
	c->n++;
	if ((mode == OSCSIM_SLIP_POS && v > c->v0 + tol) ||
	    (mode == OSCSIM_SLIP_NEG && v < c->v0 - tol) ||
	    (mode == OSCSIM_STICK && v != c->v0)) {
		c->bad++;
	}
}

static void count_neg(void *ctx, double t, double x, double v,
		      oscsim_mode_t mode)
{
	mode_check_t *c = ctx;

	(void)t;
	(void)x;
	(void)v;
	if (mode == OSCSIM_SLIP_NEG) {
		c->neg++;
	}
}

/* A violent start (pad pulled 1.5 mm off and released): the pad
 * overtakes the disc for a moment (w < 0) before it sticks. Every sample
 * must be in the mode its relative velocity says; a missed return through
 * w = 0 used to run on in the wrong branch until the step size died. */
static void test_sim_modes_match_relative_velocity(void **state)
{
	/* 0.68266 mm grazes: there F_req is -mu_0 N at w = 0 */
	const double dx[] = { 6.8266e-4, 7e-4, 8e-4 };
	oscsim_params_t p;
	oscsim_sim_opts_t o;
	oscsim_sim_result_t r;
	mode_check_t c = { 0.0, 0U, 0U, 0U };
	size_t i;

	(void)state;
	oscsim_default_params(&p);
	p.force_n = 20000.0;
	p.slope_spm = 4.65;
	p.v0_mps = 1.725;
	c.v0 = p.v0_mps;
	for (i = 0; i < sizeof(dx) / sizeof(dx[0]); i++) {
		oscsim_sim_default_opts(&o, 0.005);
		o.sample_dt_s = 2e-7;
		o.on_sample = check_mode;
		o.on_switch = count_neg;
		o.cb_ctx = &c;
		assert_int_equal(oscsim_simulate(&p, oscsim_steady_x(&p) + dx[i],
						 0.0, &o, &r),
				 SQ_OK);
		assert_true(r.stick_entries > 0U);
		assert_true(r.switches < 100U);
	}
	assert_true(c.n > 3U * 20000U);
	assert_int_equal(c.bad, 0);
	assert_true(c.neg >= 3U);
}

/* ---- the sliding cycle -------------------------------------------------- */

/* docs/model.md section 6: max u' of the unstable cycle, simulated there. */
static const double table6[][3] = {
	{ 0.023, 0.6, 1.2260 }, { 0.023, 1.0, 2.4874 }, { 0.023, 2.0, 3.6936 },
	{ 0.023, 3.0, 4.3102 }, { 0.1, 1.0, 2.4982 },   { 0.1, 3.0, 4.3368 },
};

static void test_cycle_reproduces_model_md_table(void **state)
{
	size_t i;

	(void)state;
	for (i = 0; i < sizeof(table6) / sizeof(table6[0]); i++) {
		oscsim_cycle_t c, c2;

		assert_int_equal(oscsim_cycle_find(table6[i][0], log(table6[i][1]),
						   D_INF, NULL, &c),
				 SQ_OK);
		assert_int_equal(c.kind, OSCSIM_CYCLE_FOUND);
		/* the table has 4 decimals and was made by plain backward
		 * integration to its own tolerance */
		assert_near(c.v_max, table6[i][2], 3e-4);
		/* the two methods agree far better than the table */
		assert_int_equal(oscsim_cycle_backward_plain(table6[i][0],
							     log(table6[i][1]), D_INF,
							     0.5, 100000U, NULL, &c2),
				 SQ_OK);
		assert_int_equal(c2.kind, OSCSIM_CYCLE_FOUND);
		assert_near(c.v_max, c2.v_max, 1e-6 * c.v_max);
		assert_near(c.r, c2.r, 1e-6 * c.r);
		/* near-harmonic: the period is close to 2 pi */
		assert_near(c.period, 2.0 * PI, 0.02 * 2.0 * PI);
		assert_true(c.v_min < 0.0 && c.u_min < 0.0);
	}
}

static void test_cycle_respects_the_stick_line(void **state)
{
	oscsim_cycle_t c;

	(void)state;
	/* D 0.023, Q 1: max u' = 2.4874 */
	assert_int_equal(oscsim_cycle_find(0.023, 0.0, 2.4, NULL, &c), SQ_OK);
	assert_int_equal(c.kind, OSCSIM_CYCLE_AT_STICK);
	assert_true(c.v_reach <= 2.4 + 1e-9);
	assert_int_equal(oscsim_cycle_find(0.023, 0.0, 2.6, NULL, &c), SQ_OK);
	assert_int_equal(c.kind, OSCSIM_CYCLE_FOUND);
	assert_near(c.v_max, 2.4874, 3e-4);
	/* no cycle around an unstable state */
	assert_int_equal(oscsim_cycle_find(0.023, log(0.4), 2.6, NULL, &c), SQ_OK);
	assert_int_equal(c.kind, OSCSIM_CYCLE_NONE);
	assert_int_equal(oscsim_cycle_find(0.0, 0.0, 2.6, NULL, &c), SQ_EINVAL);
	assert_int_equal(oscsim_cycle_find(0.023, 0.0, -1.0, NULL, &c), SQ_EINVAL);
}

static void test_linear_growth_matches_linearisation(void **state)
{
	const double qs[] = { 0.3, 0.45, 0.55, 1.0, 5.0 };
	const double d = 0.023;
	size_t i;

	(void)state;
	for (i = 0; i < sizeof(qs) / sizeof(qs[0]); i++) {
		/* u'' + 2 sigma u' + u = 0, sigma = D - kappa/2: after one
		 * revolution the section amplitude is multiplied by
		 * exp(-sigma T), T = 2 pi / sqrt(1 - sigma^2) */
		double sigma = d - 0.5 * d / qs[i];
		double expect = exp(-sigma * 2.0 * PI / sqrt(1.0 - sigma * sigma));
		double ratio;

		assert_int_equal(oscsim_linear_growth(d, log(qs[i]), &ratio), SQ_OK);
		assert_near(ratio, expect, 1e-5 * expect);
		assert_true((ratio > 1.0) == (qs[i] < 0.5));
	}
}

typedef struct {
	double v_max;
	double first[2];
	double last[2];
	uint32_t n;
} trace_check_t;

static void trace_sample(void *ctx, double t, const double *y)
{
	trace_check_t *c = ctx;

	(void)t;
	if (c->n == 0U) {
		c->first[0] = y[0];
		c->first[1] = y[1];
	}
	c->last[0] = y[0];
	c->last[1] = y[1];
	c->v_max = fmax(c->v_max, y[1]);
	c->n++;
}

static void test_cycle_trace_closes(void **state)
{
	oscsim_cycle_t c;
	trace_check_t tc;

	(void)state;
	memset(&tc, 0, sizeof(tc));
	assert_int_equal(oscsim_cycle_find(0.023, log(2.0), D_INF, NULL, &c), SQ_OK);
	assert_int_equal(oscsim_cycle_trace(0.023, log(2.0), c.r, 2.0 * PI / 512.0,
					    trace_sample, &tc),
			 SQ_OK);
	assert_true(tc.n > 500U);
	assert_near(tc.last[0], tc.first[0], 1e-7 * c.r);
	assert_near(tc.last[1], 0.0, 1e-9);
	assert_near(tc.v_max, c.v_max, 1e-3 * c.v_max);
}

/* ---- ground truth and the basin ----------------------------------------- */

static void test_truth_on_the_default_brake(void **state)
{
	oscsim_params_t p;
	oscsim_truth_t t;

	(void)state;
	oscsim_default_params(&p);
	/* v_H = 1.2315 m/s at a = 2 s/m (docs/model.md section 8) */
	p.v0_mps = 1.2;
	assert_int_equal(oscsim_truth(&p, NULL, 1, &t), SQ_OK);
	assert_int_equal(t.cls, OSCSIM_TRUTH_UNSTABLE);
	assert_int_equal(t.linear_grows, 1);
	p.v0_mps = 1.26;
	assert_int_equal(oscsim_truth(&p, NULL, 1, &t), SQ_OK);
	assert_int_equal(t.cls, OSCSIM_TRUTH_BISTABLE);
	assert_int_equal(t.linear_grows, 0);
	assert_true(t.cycle_x < t.s);
	assert_near(t.amplitude_m, t.cycle.r / (2.0 * 5000.0), 1e-18);
	/* s = 6, Q = 17.2: the cycle (max u' ~ 6.6) would cross the stick line */
	p.v0_mps = 3.0;
	assert_int_equal(oscsim_truth(&p, NULL, 0, &t), SQ_OK);
	assert_int_equal(t.cls, OSCSIM_TRUTH_STABLE);
	assert_int_equal(t.cycle.kind, OSCSIM_CYCLE_AT_STICK);
	p.slope_spm = 0.0;
	assert_int_equal(oscsim_truth(&p, NULL, 0, &t), SQ_OK);
	assert_int_equal(t.cls, OSCSIM_TRUTH_STABLE);
	p.slope_spm = 2.0;
	p.v0_mps = 0.0;
	assert_int_equal(oscsim_truth(&p, NULL, 0, &t), SQ_OK);
	assert_int_equal(t.cls, OSCSIM_TRUTH_NOT_SLIDING);
	p.v0_mps = (double)NAN;
	assert_int_equal(oscsim_truth(&p, NULL, 0, &t), SQ_EINVAL);
}

static void test_basin_inside_decays_outside_captured(void **state)
{
	oscsim_params_t p;
	oscsim_truth_t t;
	oscsim_basin_outcome_t out;
	double t_dec;

	(void)state;
	oscsim_default_params(&p);
	p.v0_mps = 1.5;
	assert_int_equal(oscsim_truth(&p, NULL, 0, &t), SQ_OK);
	assert_int_equal(t.cls, OSCSIM_TRUTH_BISTABLE);
	assert_int_equal(oscsim_basin(&p, t.cycle.r, 0.8, 4000U, &out, &t_dec), SQ_OK);
	assert_int_equal(out, OSCSIM_BASIN_DECAYED);
	assert_int_equal(oscsim_basin(&p, t.cycle.r, 1.2, 4000U, &out, &t_dec), SQ_OK);
	assert_int_equal(out, OSCSIM_BASIN_CAPTURED);
	/* the border of the basin is the cycle: 2 % either side still tells */
	assert_int_equal(oscsim_basin(&p, t.cycle.r, 0.98, 4000U, &out, &t_dec), SQ_OK);
	assert_int_equal(out, OSCSIM_BASIN_DECAYED);
	assert_int_equal(oscsim_basin(&p, t.cycle.r, 1.02, 4000U, &out, &t_dec), SQ_OK);
	assert_int_equal(out, OSCSIM_BASIN_CAPTURED);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_dp5_harmonic_forward_and_backward),
		cmocka_unit_test(test_dp5_error_falls_with_tolerance),
		cmocka_unit_test(test_dp5_dense_output_between_steps),
		cmocka_unit_test(test_dp5_event_location_and_direction),
		cmocka_unit_test(test_dp5_budget_and_bad_arguments),
		cmocka_unit_test(test_sim_constant_friction_is_the_damped_oscillator),
		cmocka_unit_test(test_sim_stick_and_release_with_constant_friction),
		cmocka_unit_test(test_sim_modes_match_relative_velocity),
		cmocka_unit_test(test_cycle_reproduces_model_md_table),
		cmocka_unit_test(test_cycle_respects_the_stick_line),
		cmocka_unit_test(test_linear_growth_matches_linearisation),
		cmocka_unit_test(test_cycle_trace_closes),
		cmocka_unit_test(test_truth_on_the_default_brake),
		cmocka_unit_test(test_basin_inside_decays_outside_captured),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
