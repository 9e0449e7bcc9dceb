/* SPDX-License-Identifier: MIT */
/*
 * oscsim: simulator of the nonsmooth friction oscillator, see oscsim.h.
 */
#include "oscsim.h"

#include <float.h>
#include <stdbool.h>
#include <math.h>
#include <string.h>

#define LN_HALF (-0.69314718055994530942)
#define TWO_PI 6.28318530717958647692
/* libm gives float-typed NAN/INFINITY; -Wdouble-promotion wants them cast */
#define DNAN ((double)NAN)
#define DINF ((double)INFINITY)

/* An enum's name from its table ("?" outside it). */
static const char *name_of(const char *const *names, size_t n, unsigned int i)
{
	return (i < n) ? names[i] : "?";
}

int oscsim_params_check(const oscsim_params_t *p)
{
	if (p == NULL) {
		return SQ_EINVAL;
	}
	if (!isfinite(p->mass_kg) || !isfinite(p->omega0_radps) ||
	    !isfinite(p->damping) || !isfinite(p->mu_inf) ||
	    !isfinite(p->delta_mu) || !isfinite(p->slope_spm) ||
	    !isfinite(p->v0_mps) || !isfinite(p->force_n)) {
		return SQ_EINVAL;
	}
	if (p->mass_kg <= 0.0 || p->omega0_radps <= 0.0 ||
	    p->damping <= 0.0 || p->slope_spm < 0.0 || p->v0_mps < 0.0 ||
	    p->force_n < 0.0 || p->mu_inf < 0.0 ||
	    p->mu_inf + p->delta_mu < 0.0) {
		return SQ_EINVAL;
	}
	return SQ_OK;
}

int oscsim_ln_q(const oscsim_params_t *p, double *ln_q, double *s)
{
	int rc = oscsim_params_check(p);

	if (rc != SQ_OK) {
		return rc;
	}
	if (p->slope_spm <= 0.0 || p->force_n <= 0.0 || p->delta_mu <= 0.0) {
		return SQ_EINVAL;
	}
	/* log domain: exp(a v0) alone overflows for plausible inputs */
	*ln_q = log(p->damping * p->omega0_radps * p->mass_kg /
		    (p->slope_spm * p->force_n * p->delta_mu)) +
		p->slope_spm * p->v0_mps;
	*s = p->slope_spm * p->v0_mps;
	return SQ_OK;
}

/* ---- Dormand-Prince 5(4) ------------------------------------------------ */

/* Butcher tableau of Dormand & Prince (1980), the 5th-order solution is
 * propagated (local extrapolation), the embedded 4th-order one only
 * estimates the error. */
static const double C2 = 1.0 / 5.0, C3 = 3.0 / 10.0, C4 = 4.0 / 5.0,
		    C5 = 8.0 / 9.0;
static const double A21 = 1.0 / 5.0;
static const double A31 = 3.0 / 40.0, A32 = 9.0 / 40.0;
static const double A41 = 44.0 / 45.0, A42 = -56.0 / 15.0, A43 = 32.0 / 9.0;
static const double A51 = 19372.0 / 6561.0, A52 = -25360.0 / 2187.0,
		    A53 = 64448.0 / 6561.0, A54 = -212.0 / 729.0;
static const double A61 = 9017.0 / 3168.0, A62 = -355.0 / 33.0,
		    A63 = 46732.0 / 5247.0, A64 = 49.0 / 176.0,
		    A65 = -5103.0 / 18656.0;
static const double A71 = 35.0 / 384.0, A73 = 500.0 / 1113.0,
		    A74 = 125.0 / 192.0, A75 = -2187.0 / 6784.0,
		    A76 = 11.0 / 84.0;
/* b5 - b4 */
static const double E1 = 71.0 / 57600.0, E3 = -71.0 / 16695.0,
		    E4 = 71.0 / 1920.0, E5 = -17253.0 / 339200.0,
		    E6 = 22.0 / 525.0, E7 = -1.0 / 40.0;
/* continuous extension (Hairer, Norsett & Wanner, Solving ODE I, II.6) */
static const double D1 = -12715105075.0 / 11282082432.0,
		    D3 = 87487479700.0 / 32700410799.0,
		    D4 = -10690763975.0 / 1880347072.0,
		    D5 = 701980252875.0 / 199316789632.0,
		    D6 = -1453857185.0 / 822651844.0,
		    D7 = 69997945.0 / 29380423.0;

static double dp5_norm(const oscsim_dp5_t *me, const double *v,
		       const double *ref)
{
	double sum = 0.0;
	size_t i;

	for (i = 0; i < me->n; i++) {
		double sc = me->atol[i] + me->rtol * fabs(ref[i]);
		double q = v[i] / sc;

		sum += q * q;
	}
	return sqrt(sum / (double)me->n);
}

/* First step size: the usual estimate from the size of y, f and f'. */
static double dp5_first_step(oscsim_dp5_t *me, int dir)
{
	double y1[OSCSIM_MAX_DIM], f1[OSCSIM_MAX_DIM], df[OSCSIM_MAX_DIM];
	double d0 = dp5_norm(me, me->y, me->y);
	double d1 = dp5_norm(me, me->f, me->y);
	double d2, h0, h1;
	size_t i;

	h0 = (d0 < 1e-5 || d1 < 1e-5) ? 1e-6 : 0.01 * d0 / d1;
	for (i = 0; i < me->n; i++) {
		y1[i] = me->y[i] + (double)dir * h0 * me->f[i];
	}
	me->rhs(me->t + (double)dir * h0, y1, f1, me->ctx);
	me->f_evals++;
	for (i = 0; i < me->n; i++) {
		df[i] = f1[i] - me->f[i];
	}
	d2 = dp5_norm(me, df, me->y) / h0;
	if (fmax(d1, d2) <= 1e-15) {
		h1 = fmax(1e-6, h0 * 1e-3);
	} else {
		h1 = pow(0.01 / fmax(d1, d2), 0.2);
	}
	h0 = fmin(100.0 * h0, h1);
	if (me->h_max > 0.0) {
		h0 = fmin(h0, me->h_max);
	}
	return (double)dir * h0;
}

int oscsim_dp5_init(oscsim_dp5_t *me, size_t n, oscsim_rhs_fn rhs, void *ctx,
		    double t0, const double *y0, int dir, double h0,
		    double rtol, const double *atol, uint32_t max_steps)
{
	size_t i;

	if (me == NULL || rhs == NULL || y0 == NULL || atol == NULL ||
	    n == 0 || n > OSCSIM_MAX_DIM || !(rtol > 0.0) ||
	    (dir != 1 && dir != -1) || !isfinite(t0) || !isfinite(h0)) {
		return SQ_EINVAL;
	}
	memset(me, 0, sizeof(*me));
	me->n = n;
	me->rhs = rhs;
	me->ctx = ctx;
	me->rtol = rtol;
	me->max_steps = max_steps;
	me->t = t0;
	me->t_old = t0;
	for (i = 0; i < n; i++) {
		if (!isfinite(y0[i]) || !(atol[i] >= 0.0)) {
			return SQ_EINVAL;
		}
		me->atol[i] = atol[i];
		me->y[i] = y0[i];
	}
	rhs(t0, me->y, me->f, ctx);
	me->f_evals++;
	me->h = (h0 != 0.0) ? (double)dir * fabs(h0) : dp5_first_step(me, dir);
	return SQ_OK;
}

void oscsim_dp5_restart(oscsim_dp5_t *me, double t, const double *y)
{
	size_t i;

	me->t = t;
	me->t_old = t;
	me->h_last = 0.0;
	for (i = 0; i < me->n; i++) {
		me->y[i] = y[i];
	}
	me->rhs(t, me->y, me->f, me->ctx);
	me->f_evals++;
}

int oscsim_dp5_step(oscsim_dp5_t *me, double t_end)
{
	double k2[OSCSIM_MAX_DIM], k3[OSCSIM_MAX_DIM], k4[OSCSIM_MAX_DIM];
	double k5[OSCSIM_MAX_DIM], k6[OSCSIM_MAX_DIM], k7[OSCSIM_MAX_DIM];
	double yt[OSCSIM_MAX_DIM], y5[OSCSIM_MAX_DIM], ev[OSCSIM_MAX_DIM];
	double ref[OSCSIM_MAX_DIM];
	const double *k1 = me->f;
	size_t n = me->n;
	size_t i;
	int dir = (me->h >= 0.0) ? 1 : -1;
	int last_rejected = 0;

	for (;;) {
		double h = me->h;
		double err, fac;
		int to_end = 0;

		if (me->attempts >= me->max_steps) {
			return SQ_ERANGE;
		}
		me->attempts++;
		if (me->h_max > 0.0 && fabs(h) > me->h_max) {
			h = (double)dir * me->h_max;
		}
		if ((double)dir * (me->t + h - t_end) >= 0.0) {
			h = t_end - me->t;
			to_end = 1;
		}
		if (fabs(h) <= 16.0 * DBL_EPSILON * fmax(fabs(me->t), 1e-300)) {
			return SQ_ERANGE;
		}
		for (i = 0; i < n; i++) {
			yt[i] = me->y[i] + h * A21 * k1[i];
		}
		me->rhs(me->t + C2 * h, yt, k2, me->ctx);
		for (i = 0; i < n; i++) {
			yt[i] = me->y[i] + h * (A31 * k1[i] + A32 * k2[i]);
		}
		me->rhs(me->t + C3 * h, yt, k3, me->ctx);
		for (i = 0; i < n; i++) {
			yt[i] = me->y[i] + h * (A41 * k1[i] + A42 * k2[i] +
						A43 * k3[i]);
		}
		me->rhs(me->t + C4 * h, yt, k4, me->ctx);
		for (i = 0; i < n; i++) {
			yt[i] = me->y[i] + h * (A51 * k1[i] + A52 * k2[i] +
						A53 * k3[i] + A54 * k4[i]);
		}
		me->rhs(me->t + C5 * h, yt, k5, me->ctx);
		for (i = 0; i < n; i++) {
			yt[i] = me->y[i] + h * (A61 * k1[i] + A62 * k2[i] +
						A63 * k3[i] + A64 * k4[i] +
						A65 * k5[i]);
		}
		me->rhs(me->t + h, yt, k6, me->ctx);
		for (i = 0; i < n; i++) {
			y5[i] = me->y[i] + h * (A71 * k1[i] + A73 * k3[i] +
						A74 * k4[i] + A75 * k5[i] +
						A76 * k6[i]);
		}
		me->rhs(me->t + h, y5, k7, me->ctx);
		me->f_evals += 6U;
		for (i = 0; i < n; i++) {
			ev[i] = h * (E1 * k1[i] + E3 * k3[i] + E4 * k4[i] +
				     E5 * k5[i] + E6 * k6[i] + E7 * k7[i]);
			ref[i] = fmax(fabs(me->y[i]), fabs(y5[i]));
		}
		err = dp5_norm(me, ev, ref);
		if (!isfinite(err)) {
			/* overflow in a trial stage: just try a smaller step */
			me->rejected++;
			me->h = 0.1 * h;
			last_rejected = 1;
			continue;
		}
		if (err > 1.0) {
			fac = fmax(0.2, 0.9 * pow(err, -0.2));
			me->rejected++;
			me->h = fac * h;
			last_rejected = 1;
			continue;
		}
		/* accepted: keep the dense-output coefficients */
		for (i = 0; i < n; i++) {
			double ydiff = y5[i] - me->y[i];
			double bspl = h * k1[i] - ydiff;

			me->rc[0][i] = me->y[i];
			me->rc[1][i] = ydiff;
			me->rc[2][i] = bspl;
			me->rc[3][i] = ydiff - h * k7[i] - bspl;
			me->rc[4][i] = h * (D1 * k1[i] + D3 * k3[i] +
					    D4 * k4[i] + D5 * k5[i] +
					    D6 * k6[i] + D7 * k7[i]);
		}
		for (i = 0; i < n; i++) {
			if (!isfinite(y5[i])) {
				return SQ_EIO;
			}
			me->y[i] = y5[i];
			me->f[i] = k7[i];
		}
		me->t_old = me->t;
		me->t = to_end ? t_end : me->t + h;
		me->h_last = h;
		me->steps++;
		fac = (err > 0.0) ? 0.9 * pow(err, -0.2) : 5.0;
		fac = fmin(5.0, fmax(0.2, fac));
		if (last_rejected && fac > 1.0) {
			fac = 1.0;
		}
		/* a step shortened to hit t_end says nothing about the next */
		if (!to_end || fabs(h) >= fabs(me->h)) {
			me->h = h * fac;
		}
		return SQ_OK;
	}
}

void oscsim_dp5_dense(const oscsim_dp5_t *me, double t, double *y)
{
	size_t i;
	double th, th1;

	if (me->h_last == 0.0) {
		for (i = 0; i < me->n; i++) {
			y[i] = me->y[i];
		}
		return;
	}
	th = (t - me->t_old) / me->h_last;
	th1 = 1.0 - th;
	for (i = 0; i < me->n; i++) {
		y[i] = me->rc[0][i] +
		       th * (me->rc[1][i] +
			     th1 * (me->rc[2][i] +
				    th * (me->rc[3][i] + th1 * me->rc[4][i])));
	}
}

static double event_at(const oscsim_dp5_t *me, const oscsim_event_t *ev,
		       double t)
{
	double y[OSCSIM_MAX_DIM];

	oscsim_dp5_dense(me, t, y);
	return ev->fn(t, y, ev->ctx);
}

/*
 * Illinois (modified regula falsi) on the dense output. a has g's sign
 * before the crossing, b after it; returns the end of the final bracket
 * on the far side, so a restart there sees g already past zero and the
 * same crossing is not found twice.
 */
static double event_locate(const oscsim_dp5_t *me, const oscsim_event_t *ev,
			   double a, double ga, double b, double gb)
{
	double tol = 8.0 * DBL_EPSILON * fmax(fabs(a), fabs(b)) +
		     1e-13 * fabs(b - a);
	int side = 0;
	unsigned int it;

	for (it = 0; it < 200U; it++) {
		double c, gc;

		if (fabs(b - a) <= tol) {
			break;
		}
		c = (a * gb - b * ga) / (gb - ga);
		if (!(c > fmin(a, b) && c < fmax(a, b))) {
			c = 0.5 * (a + b);
		}
		gc = event_at(me, ev, c);
		if (gc == 0.0) {
			return c;
		}
		if ((gc < 0.0) == (gb < 0.0)) {
			/* root between a and c: keep a, damp its value if it
			 * stays twice in a row (the Illinois fix) */
			b = c;
			gb = gc;
			if (side == -1) {
				ga *= 0.5;
			}
			side = -1;
		} else {
			a = c;
			ga = gc;
			if (side == 1) {
				gb *= 0.5;
			}
			side = 1;
		}
	}
	return b;
}

static int crossed(double g0, double g1, int dir)
{
	if (g0 < 0.0 && g1 >= 0.0) {
		return dir >= 0;
	}
	if (g0 > 0.0 && g1 <= 0.0) {
		return dir <= 0;
	}
	return 0;
}

#define OSCSIM_MAX_EVENTS 4U
#define EVENT_SUBSTEPS 4U

int oscsim_dp5_advance(oscsim_dp5_t *me, double t_end, oscsim_watch_t *watch)
{
	double g_old[OSCSIM_MAX_EVENTS];
	size_t n_ev = 0;
	size_t k;
	int dir;

	if (me == NULL || !isfinite(t_end)) {
		return SQ_EINVAL;
	}
	dir = (t_end >= me->t) ? 1 : -1;
	if (me->h * (double)dir < 0.0) {
		me->h = -me->h;
	}
	if (watch != NULL) {
		n_ev = watch->n_ev;
		if (n_ev > OSCSIM_MAX_EVENTS || (n_ev > 0 && watch->ev == NULL)) {
			return SQ_EINVAL;
		}
		if (watch->sample_fn != NULL && !(watch->sample_dt > 0.0)) {
			return SQ_EINVAL;
		}
	}
	for (k = 0; k < n_ev; k++) {
		g_old[k] = watch->ev[k].fn(me->t, me->y, watch->ev[k].ctx);
		if (g_old[k] == 0.0 && watch->ev[k].dir != 0) {
			/* starting on the surface of a one-way event (a mode
			 * just switched there): we leave it to the side the
			 * event comes back from, so an excursion that returns
			 * within the first sub-step is still a crossing */
			g_old[k] = -(double)watch->ev[k].dir * DBL_MIN;
		}
	}
	while ((double)dir * (t_end - me->t) > 0.0) {
		double t_stop;
		int hit = -1;
		int rc = oscsim_dp5_step(me, t_end);

		if (rc != SQ_OK) {
			return rc;
		}
		t_stop = me->t;
		for (k = 0; k < n_ev; k++) {
			const oscsim_event_t *ev = &watch->ev[k];
			double g1 = ev->fn(me->t, me->y, ev->ctx);
			double ta = me->t_old, ga = g_old[k];
			unsigned int j;

			/* look inside the step too: a graze (g dips through
			 * zero and back within one step) leaves no sign change
			 * at the ends */
			for (j = 1; j <= EVENT_SUBSTEPS; j++) {
				double tb, gb;

				if (j == EVENT_SUBSTEPS) {
					tb = me->t;
					gb = g1;
				} else {
					tb = me->t_old + me->h_last * (double)j /
								 (double)EVENT_SUBSTEPS;
					gb = event_at(me, ev, tb);
				}
				if (crossed(ga, gb, ev->dir)) {
					double tr = event_locate(me, ev, ta, ga,
								 tb, gb);

					if (hit < 0 ||
					    (double)dir * (tr - t_stop) < 0.0) {
						hit = (int)k;
						t_stop = tr;
					}
					break;
				}
				ta = tb;
				ga = gb;
			}
			g_old[k] = g1;
		}
		if (watch != NULL && watch->sample_fn != NULL) {
			double y[OSCSIM_MAX_DIM];
			uint32_t guard = 0;

			while ((double)dir * (t_stop - watch->t_sample_next) >= 0.0 &&
			       guard < 1000000U) {
				oscsim_dp5_dense(me, watch->t_sample_next, y);
				watch->sample_fn(watch->sample_ctx,
						 watch->t_sample_next, y);
				watch->t_sample_next += (double)dir * watch->sample_dt;
				guard++;
			}
		}
		if (watch != NULL && watch->step_fn != NULL) {
			watch->step_fn(watch->step_ctx, me, t_stop);
		}
		if (hit >= 0) {
			double y[OSCSIM_MAX_DIM];

			oscsim_dp5_dense(me, t_stop, y);
			oscsim_dp5_restart(me, t_stop, y);
			return hit;
		}
	}
	return OSCSIM_REACHED_END;
}

/* ---- the sliding system, dimensionless ---------------------------------- */

void oscsim_slide_rhs(double t, const double *y, double *dydt, void *ctx)
{
	const oscsim_slide_t *sl = ctx;

	(void)t;
	dydt[0] = y[1];
	dydt[1] = -y[0] - 2.0 * sl->damping * y[1] + sl->kappa * expm1(y[1]);
}

void oscsim_cycle_default_opts(oscsim_cycle_opts_t *o)
{
	o->rtol = 1e-10;
	o->r_tol = 1e-9;
	o->max_evals = 120U;
	o->max_steps = 20000U;
}

static double ev_velocity(double t, const double *y, void *ctx)
{
	(void)t;
	(void)ctx;
	return y[1];
}

static double ev_stick(double t, const double *y, void *ctx)
{
	const double *s = ctx;

	(void)t;
	return y[1] - *s;
}

static double ev_accel(double t, const double *y, void *ctx)
{
	double d[2];

	oscsim_slide_rhs(t, y, d, ctx);
	return d[1];
}

/* One backward revolution, all the extremes of it. */
typedef struct {
	double r_next;
	double u_min;
	double v_max;
	double v_min;
	double period;
	int hit_stick;
	uint32_t steps;
} revolution_t;

static int revolve(const oscsim_slide_t *sl, double s, double r,
		   const oscsim_cycle_opts_t *o, int dir, revolution_t *out)
{
	oscsim_dp5_t dp;
	oscsim_event_t ev[3];
	oscsim_watch_t w;
	double y0[2] = { r, 0.0 };
	double atol[2];
	double t_lim = 200.0;
	uint32_t guard;
	int rc;

	/* absolute tolerance scaled to the orbit: relative accuracy holds
	 * also for the tiny orbits near the Hopf point */
	atol[0] = o->rtol * fmax(r, 1e-12);
	atol[1] = atol[0];
	rc = oscsim_dp5_init(&dp, 2, oscsim_slide_rhs, (void *)sl, 0.0, y0, dir,
			     0.0, o->rtol, atol, o->max_steps);
	if (rc != SQ_OK) {
		return rc;
	}
	dp.h_max = 0.5;
	/* the section u' = 0: its half u > 0 ends the revolution, the half
	 * u < 0 gives u_min */
	/* both halves; the sign of u tells them apart */
	ev[0] = (oscsim_event_t){ .fn = ev_velocity, .ctx = NULL, .dir = 0 };
	/* extremes of u' (u'' = 0), both kinds */
	ev[1] = (oscsim_event_t){ .fn = ev_accel, .ctx = (void *)sl, .dir = 0 };
	/* the stick line u' = s */
	ev[2] = (oscsim_event_t){ .fn = ev_stick, .ctx = &s, .dir = 1 };
	memset(&w, 0, sizeof(w));
	w.ev = ev;
	w.n_ev = isfinite(s) ? 3U : 2U;
	*out = (revolution_t){ .r_next = DNAN }; /* the extremes start at 0 */
	for (guard = 0; guard < 64U; guard++) {
		rc = oscsim_dp5_advance(&dp, (double)dir * t_lim, &w);
		if (rc < 0) {
			out->steps = dp.steps;
			return rc;
		}
		if (rc == OSCSIM_REACHED_END) {
			out->steps = dp.steps;
			return SQ_ERANGE;
		}
		if (rc == 0) {
			if (dp.y[0] > 0.0) {
				out->r_next = dp.y[0];
				out->period = fabs(dp.t);
				break;
			}
			/* the other half of the section: note u_min and go on */
			out->u_min = dp.y[0];
			continue;
		}
		if (rc == 1) {
			out->v_max = fmax(out->v_max, dp.y[1]);
			out->v_min = fmin(out->v_min, dp.y[1]);
			if (dp.y[1] >= s) {
				/* a peak located exactly above the line: the
				 * crossing grazed inside a step */
				out->hit_stick = 1;
				break;
			}
			continue;
		}
		/* rc == 2: reached the stick line */
		out->hit_stick = 1;
		out->v_max = fmax(out->v_max, dp.y[1]);
		break;
	}
	out->steps = dp.steps;
	if (guard >= 64U) {
		return SQ_ERANGE;
	}
	return SQ_OK;
}

static int slide_setup(double damping, double ln_q, oscsim_slide_t *sl)
{
	if (!(damping > 0.0) || !isfinite(damping) || !isfinite(ln_q)) {
		return SQ_EINVAL;
	}
	sl->damping = damping;
	sl->kappa = damping * exp(-ln_q);
	return SQ_OK;
}

int oscsim_cycle_return_map(double damping, double ln_q, double s, double r,
			    const oscsim_cycle_opts_t *opts, double *r_next,
			    double *v_peak, uint32_t *steps)
{
	oscsim_slide_t sl;
	revolution_t rev;
	int rc = slide_setup(damping, ln_q, &sl);

	if (rc != SQ_OK || opts == NULL || !(r > 0.0) || !isfinite(r) ||
	    isnan(s) || !(s > 0.0)) {
		return SQ_EINVAL;
	}
	rc = revolve(&sl, s, r, opts, -1, &rev);
	if (steps != NULL) {
		*steps = rev.steps;
	}
	if (rc != SQ_OK) {
		return rc;
	}
	*r_next = rev.r_next;
	*v_peak = rev.v_max;
	return rev.hit_stick ? 1 : 0;
}

static void cycle_clear(oscsim_cycle_t *out)
{
	/* every field unknown (NaN) or zero until a search fills it */
	*out = (oscsim_cycle_t){ .r = DNAN, .u_min = DNAN, .v_max = DNAN, .v_min = DNAN,
				 .period = DNAN, .v_reach = DNAN };
}

/* cycle_begin's answer when Q <= 1/2: no cycle, out says so. */
#define CYCLE_NONE 1

/* The start of both cycle searches: out cleared, the options (the defaults
 * for NULL, in *def), the sliding equations. SQ_OK to search; CYCLE_NONE;
 * SQ_EINVAL for bad arguments (args_ok: the caller's own). */
static int cycle_begin(double damping, double ln_q, double s, bool args_ok,
		       const oscsim_cycle_opts_t **opts, oscsim_cycle_opts_t *def,
		       oscsim_slide_t *sl, oscsim_cycle_t *out)
{
	if (out == NULL) {
		return SQ_EINVAL;
	}
	cycle_clear(out);
	if (*opts == NULL) {
		oscsim_cycle_default_opts(def);
		*opts = def;
	}
	if ((slide_setup(damping, ln_q, sl) != SQ_OK) || !args_ok || isnan(s) || !(s > 0.0)) {
		return SQ_EINVAL;
	}
	if (ln_q <= LN_HALF) {
		out->kind = OSCSIM_CYCLE_NONE;
		return CYCLE_NONE;
	}
	return SQ_OK;
}

/* The search's end: the cycle reaches the stick line (from r on). */
static int cycle_at_stick(oscsim_cycle_t *out, double r, double v_reach)
{
	out->kind = OSCSIM_CYCLE_AT_STICK;
	out->v_reach = v_reach;
	out->r = r;
	return SQ_OK;
}

/* The search's end: a closed sliding cycle, its shape from one revolution. */
static int cycle_found(oscsim_cycle_t *out, double r, const revolution_t *rev)
{
	out->kind = OSCSIM_CYCLE_FOUND;
	out->r = r;
	out->u_min = rev->u_min;
	out->v_max = rev->v_max;
	out->v_min = rev->v_min;
	out->period = rev->period;
	out->v_reach = rev->v_max;
	return SQ_OK;
}

/* Evaluate g(r) = B(r) - r (B the backward return map). */
typedef struct {
	const oscsim_slide_t *sl;
	double s;
	const oscsim_cycle_opts_t *o;
	oscsim_cycle_t *out;
} search_t;

/* Returns SQ_OK with *hit, *g and the revolution, or a negative code. */
static int g_eval(search_t *se, double r, int *hit, double *g,
		  revolution_t *rev)
{
	int rc;

	if (se->out->evals >= se->o->max_evals) {
		return SQ_ERANGE;
	}
	se->out->evals++;
	rc = revolve(se->sl, se->s, r, se->o, -1, rev);
	se->out->steps += rev->steps;
	if (rc != SQ_OK) {
		return rc;
	}
	*hit = rev->hit_stick;
	*g = rev->hit_stick ? DNAN : rev->r_next - r;
	return SQ_OK;
}

/*
 * Why the search is sound: orbits cannot cross, so an orbit started inside
 * the cycle (r < r*) stays inside it and its u' stays below the cycle's
 * max. Hence if the orbit from r reaches the stick line, either r > r* or
 * the cycle itself reaches the stick line: in both cases r bounds every
 * sliding cycle below the stick line from above. Inside points have
 * B(r) > r (backward time expands towards the cycle), outside points
 * B(r) < r.
 */
int oscsim_cycle_find(double damping, double ln_q, double s,
		      const oscsim_cycle_opts_t *opts, oscsim_cycle_t *out)
{
	oscsim_cycle_opts_t def;
	oscsim_slide_t sl;
	search_t se;
	revolution_t rev;
	double r_lo = 0.0, g_lo = DNAN;
	double r_hi = DNAN, g_hi = DNAN;
	int hi_outside = 0; /* r_hi is a genuine outside point (g < 0)  */
	double v_reach = 0.0;
	double q_excess, r;
	int rc, hit, side = 0;
	double g;
	uint32_t guard;

	rc = cycle_begin(damping, ln_q, s, true, &opts, &def, &sl, out);
	if (rc != SQ_OK) {
		return (rc == CYCLE_NONE) ? SQ_OK : rc;
	}
	se.sl = &sl;
	se.s = s;
	se.o = opts;
	se.out = out;

	/* seed from the small-amplitude scaling r ~ 4 sqrt(Q - 1/2); only a
	 * starting point, the brackets below decide */
	q_excess = (ln_q < 5.0) ? exp(ln_q) - 0.5 : 148.0;
	r = fmin(4.0 * sqrt(q_excess), 40.0);
	if (isfinite(s)) {
		r = fmin(r, s);
	}
	r = fmax(r, 1e-6);

	/* bracket: walk up until an upper bound, down until an inside point */
	for (guard = 0; guard < 80U; guard++) {
		rc = g_eval(&se, r, &hit, &g, &rev);
		if (rc != SQ_OK) {
			return rc;
		}
		if (!hit && g > 0.0) {
			r_lo = r;
			g_lo = g;
			v_reach = rev.v_max;
			if (!isnan(r_hi)) {
				break;
			}
			r *= 1.5;
			continue;
		}
		r_hi = r;
		g_hi = g;
		hi_outside = !hit;
		if (r_lo > 0.0) {
			break;
		}
		r *= 0.5;
		if (r < 1e-9) {
			/* the cycle is smaller than any orbit we can resolve */
			r_lo = 0.0;
			break;
		}
	}
	if (guard >= 80U) {
		return SQ_ERANGE;
	}

	/* shrink the bracket: bisection while the upper bound is only a
	 * stick hit, Illinois regula falsi once both ends have a value */
	for (guard = 0; guard < 200U; guard++) {
		if (r_hi - r_lo <= opts->r_tol * r_hi) {
			break;
		}
		if (hi_outside && r_lo > 0.0) {
			r = (r_lo * g_hi - r_hi * g_lo) / (g_hi - g_lo);
			if (!(r > r_lo && r < r_hi)) {
				r = 0.5 * (r_lo + r_hi);
			}
		} else {
			r = 0.5 * (r_lo + r_hi);
		}
		rc = g_eval(&se, r, &hit, &g, &rev);
		if (rc != SQ_OK) {
			return rc;
		}
		if (!hit && g == 0.0) {
			r_lo = r;
			r_hi = r;
			hi_outside = 1;
			break;
		}
		if (!hit && g > 0.0) {
			r_lo = r;
			g_lo = g;
			v_reach = rev.v_max;
			if (side == 1) {
				g_hi *= 0.5;
			}
			side = 1;
		} else {
			r_hi = r;
			g_hi = g;
			hi_outside = !hit;
			if (side == -1) {
				g_lo *= 0.5;
			}
			side = -1;
		}
	}
	if (!hi_outside) {
		return cycle_at_stick(out, r_lo, v_reach);
	}
	/* one more revolution on the cycle for its shape */
	r = 0.5 * (r_lo + r_hi);
	rc = g_eval(&se, r, &hit, &g, &rev);
	if (rc != SQ_OK) {
		return rc;
	}
	if (hit) {
		/* the cycle grazes the stick line within the root tolerance */
		return cycle_at_stick(out, r_lo, v_reach);
	}
	return cycle_found(out, r, &rev);
}

int oscsim_cycle_backward_plain(double damping, double ln_q, double s,
				double r_start, uint32_t max_revs,
				const oscsim_cycle_opts_t *opts,
				oscsim_cycle_t *out)
{
	oscsim_cycle_opts_t def;
	oscsim_slide_t sl;
	revolution_t rev;
	double r = r_start;
	uint32_t i;
	int rc;

	rc = cycle_begin(damping, ln_q, s, r_start > 0.0, &opts, &def, &sl, out);
	if (rc != SQ_OK) {
		return (rc == CYCLE_NONE) ? SQ_OK : rc;
	}
	for (i = 0; i < max_revs; i++) {
		rc = revolve(&sl, s, r, opts, -1, &rev);
		out->evals++;
		out->steps += rev.steps;
		if (rc != SQ_OK) {
			return rc;
		}
		if (rev.hit_stick) {
			return cycle_at_stick(out, r, rev.v_max);
		}
		if (fabs(rev.r_next - r) <= opts->r_tol * r) {
			return cycle_found(out, rev.r_next, &rev);
		}
		r = rev.r_next;
	}
	return SQ_ERANGE;
}

int oscsim_cycle_trace(double damping, double ln_q, double r, double dt,
		       oscsim_sample_fn fn, void *ctx)
{
	oscsim_cycle_opts_t o;
	oscsim_slide_t sl;
	oscsim_dp5_t dp;
	oscsim_event_t ev;
	oscsim_watch_t w;
	double y0[2] = { r, 0.0 };
	double atol[2];
	uint32_t guard;
	int rc = slide_setup(damping, ln_q, &sl);

	if (rc != SQ_OK || fn == NULL || !(r > 0.0) || !(dt > 0.0)) {
		return SQ_EINVAL;
	}
	oscsim_cycle_default_opts(&o);
	atol[0] = o.rtol * r;
	atol[1] = atol[0];
	rc = oscsim_dp5_init(&dp, 2, oscsim_slide_rhs, &sl, 0.0, y0, -1, 0.0,
			     o.rtol, atol, o.max_steps);
	if (rc != SQ_OK) {
		return rc;
	}
	dp.h_max = 0.5;
	ev.fn = ev_velocity;
	ev.ctx = NULL;
	ev.dir = 0;
	memset(&w, 0, sizeof(w));
	w.ev = &ev;
	w.n_ev = 1;
	w.sample_fn = fn;
	w.sample_ctx = ctx;
	w.sample_dt = dt;
	w.t_sample_next = 0.0;
	for (guard = 0; guard < 4U; guard++) {
		rc = oscsim_dp5_advance(&dp, -200.0, &w);
		if (rc < 0) {
			return rc;
		}
		if (rc != 0) {
			return SQ_ERANGE;
		}
		if (dp.y[0] > 0.0) {
			fn(ctx, dp.t, dp.y); /* close the curve */
			return SQ_OK;
		}
	}
	return SQ_ERANGE;
}

static double ev_escape(double t, const double *y, void *ctx)
{
	const double *lim = ctx;

	(void)t;
	return y[0] * y[0] + y[1] * y[1] - *lim * *lim;
}

int oscsim_linear_growth(double damping, double ln_q, double *ratio)
{
	oscsim_slide_t sl;
	oscsim_dp5_t dp;
	oscsim_event_t ev[2];
	oscsim_watch_t w;
	const double r0 = 1e-6;
	/* far above the start, still far below where exp() bends */
	double escape = 1e3 * r0;
	double y0[2] = { r0, 0.0 };
	double atol[2] = { 1e-12 * r0, 1e-12 * r0 };
	uint32_t guard;
	int rc = slide_setup(damping, ln_q, &sl);

	if (rc != SQ_OK || ratio == NULL) {
		return SQ_EINVAL;
	}
	rc = oscsim_dp5_init(&dp, 2, oscsim_slide_rhs, &sl, 0.0, y0, 1, 0.0,
			     1e-12, atol, 100000U);
	if (rc != SQ_OK) {
		return rc;
	}
	dp.h_max = 0.5;
	/* forward, the half u > 0 of the section is crossed with u' falling */
	ev[0] = (oscsim_event_t){ .fn = ev_velocity, .ctx = NULL, .dir = 0 };
	/* with strong negative damping (kappa > 2 + 2D) there is no
	 * oscillation left to count revolutions by: leaving the ball
	 * of radius 1000 r0 is growth */
	ev[1] = (oscsim_event_t){ .fn = ev_escape, .ctx = &escape, .dir = 1 };
	memset(&w, 0, sizeof(w));
	w.ev = ev;
	w.n_ev = 2;
	for (guard = 0; guard < 8U; guard++) {
		rc = oscsim_dp5_advance(&dp, 200.0, &w);
		if (rc < 0) {
			return rc;
		}
		if (rc == 1) {
			*ratio = DINF;
			return SQ_OK;
		}
		if (rc != 0) {
			return SQ_ERANGE;
		}
		if (dp.y[0] > 0.0) {
			*ratio = dp.y[0] / r0;
			return SQ_OK;
		}
	}
	return SQ_ERANGE;
}

/* ---- the full oscillator with sticking ---------------------------------- */

const char *oscsim_mode_name(oscsim_mode_t mode)
{
	static const char *const names[] = { "slip", "slip_neg", "stick" };

	return name_of(names, sizeof(names) / sizeof(names[0]), (unsigned int)mode);
}

double oscsim_steady_x(const oscsim_params_t *p)
{
	double mu = p->mu_inf + p->delta_mu * exp(-p->slope_spm * p->v0_mps);

	return p->force_n * mu /
	       (p->mass_kg * p->omega0_radps * p->omega0_radps);
}

typedef struct {
	const oscsim_params_t *p;
	oscsim_mode_t mode;
} phys_t;

static void phys_rhs(double t, const double *y, double *dydt, void *ctx)
{
	const phys_t *ph = ctx;
	const oscsim_params_t *p = ph->p;
	double w = p->v0_mps - y[1];
	double fr;

	(void)t;
	/* the branch is fixed by the mode, not by the sign of w, so a trial
	 * stage that overshoots w = 0 stays smooth; the event decides */
	if (ph->mode == OSCSIM_SLIP_NEG) {
		fr = -(p->mu_inf + p->delta_mu * exp(p->slope_spm * w));
	} else {
		fr = p->mu_inf + p->delta_mu * exp(-p->slope_spm * w);
	}
	dydt[0] = y[1];
	dydt[1] = p->force_n / p->mass_kg * fr -
		  2.0 * p->damping * p->omega0_radps * y[1] -
		  p->omega0_radps * p->omega0_radps * y[0];
}

static double ev_rel_velocity(double t, const double *y, void *ctx)
{
	const phys_t *ph = ctx;

	(void)t;
	return ph->p->v0_mps - y[1];
}

/* F_req / m: the friction force per mass that keeps x' = v0, x'' = 0 */
static double stick_force_per_mass(const oscsim_params_t *p, double x)
{
	return p->omega0_radps * p->omega0_radps * x +
	       2.0 * p->damping * p->omega0_radps * p->v0_mps;
}

void oscsim_sim_default_opts(oscsim_sim_opts_t *o, double t_end_s)
{
	memset(o, 0, sizeof(*o));
	o->t_end_s = t_end_s;
	o->rtol = 1e-9;
	o->max_steps = 5000000U;
	o->max_switches = 100000U;
}

typedef struct {
	const oscsim_sim_opts_t *o;
	oscsim_sim_result_t *res;
	oscsim_mode_t mode;
} sim_obs_t;

static void stats_add(oscsim_sim_result_t *res, const oscsim_sim_opts_t *o,
		      double t, double x, double v)
{
	if (t < o->stats_from_s) {
		return;
	}
	res->x_min_m = fmin(res->x_min_m, x);
	res->x_max_m = fmax(res->x_max_m, x);
	res->v_min_mps = fmin(res->v_min_mps, v);
	res->v_max_mps = fmax(res->v_max_mps, v);
}

static void sim_sample(void *ctx, double t, const double *y)
{
	sim_obs_t *ob = ctx;

	ob->o->on_sample(ob->o->cb_ctx, t, y[0], y[1], ob->mode);
}

/* extremes of x and x' within a step: dense output at 16 sub-points */
static void sim_step(void *ctx, const oscsim_dp5_t *dp, double t_stop)
{
	sim_obs_t *ob = ctx;
	double y[OSCSIM_MAX_DIM];
	unsigned int i;

	for (i = 1; i <= 16U; i++) {
		double t = dp->t_old + (t_stop - dp->t_old) * (double)i / 16.0;

		oscsim_dp5_dense(dp, t, y);
		stats_add(ob->res, ob->o, t, y[0], y[1]);
	}
}

static oscsim_mode_t mode_at_zero_w(const oscsim_params_t *p, double x)
{
	double f = stick_force_per_mass(p, x) * p->mass_kg;
	double f_max = (p->mu_inf + p->delta_mu) * p->force_n;

	if (fabs(f) <= f_max) {
		return OSCSIM_STICK;
	}
	return (f > 0.0) ? OSCSIM_SLIP_POS : OSCSIM_SLIP_NEG;
}

int oscsim_simulate(const oscsim_params_t *p, double x0_m, double xd0_mps,
		    const oscsim_sim_opts_t *o, oscsim_sim_result_t *res)
{
	sim_obs_t ob;
	phys_t ph;
	oscsim_event_t ev;
	oscsim_watch_t w;
	double t = 0.0, x = x0_m, v = xd0_mps;
	double t_sample = 0.0;
	double atol[2], xs;
	oscsim_mode_t mode;
	uint32_t steps = 0;
	int rc = oscsim_params_check(p);

	if (rc != SQ_OK || o == NULL || res == NULL || !isfinite(x0_m) ||
	    !isfinite(xd0_mps) || !(p->v0_mps > 0.0) ||
	    !(o->t_end_s >= 0.0) || !isfinite(o->t_end_s) ||
	    !(o->rtol > 0.0) ||
	    (o->on_sample != NULL && !(o->sample_dt_s > 0.0))) {
		return SQ_EINVAL;
	}
	memset(res, 0, sizeof(*res));
	res->first_stick_s = -1.0;
	res->x_min_m = DINF;
	res->x_max_m = -DINF;
	res->v_min_mps = DINF;
	res->v_max_mps = -DINF;
	xs = oscsim_steady_x(p);
	/* error scales: the static deflection and the disc speed */
	atol[0] = o->rtol * fmax(fmax(fabs(xs), fabs(x0_m)),
				 p->v0_mps / p->omega0_radps);
	atol[1] = o->rtol * fmax(p->v0_mps, fabs(xd0_mps));

	if (v < p->v0_mps) {
		mode = OSCSIM_SLIP_POS;
	} else if (v > p->v0_mps) {
		mode = OSCSIM_SLIP_NEG;
	} else {
		mode = mode_at_zero_w(p, x);
	}
	ph.p = p;
	ob.o = o;
	ob.res = res;
	stats_add(res, o, t, x, v);

	while (t < o->t_end_s) {
		if (mode == OSCSIM_STICK) {
			/* stick: x' = v0, exact; ends when the spring and
			 * damper ask for more than mu_0 N */
			double x_exit = ((p->mu_inf + p->delta_mu) * p->force_n /
						 p->mass_kg -
					 2.0 * p->damping * p->omega0_radps *
						 p->v0_mps) /
					(p->omega0_radps * p->omega0_radps);
			double t_exit = t + fmax(0.0, x_exit - x) / p->v0_mps;
			double t_to = fmin(t_exit, o->t_end_s);
			uint32_t guard = 0;

			while (o->on_sample != NULL && t_sample <= t_to &&
			       guard < 10000000U) {
				o->on_sample(o->cb_ctx, t_sample,
					     x + p->v0_mps * (t_sample - t),
					     p->v0_mps, OSCSIM_STICK);
				t_sample += o->sample_dt_s;
				guard++;
			}
			if (t_to >= o->stats_from_s) {
				double t_in = fmax(t, o->stats_from_s);

				stats_add(res, o, t_in, x + p->v0_mps * (t_in - t),
					  p->v0_mps);
			}
			x += p->v0_mps * (t_to - t);
			t = t_to;
			v = p->v0_mps;
			stats_add(res, o, t, x, v);
			if (t_exit > o->t_end_s) {
				break;
			}
			mode = OSCSIM_SLIP_POS;
		} else {
			oscsim_dp5_t dp;
			double y0[2] = { x, v };
			uint32_t budget;

			if (steps >= o->max_steps) {
				rc = SQ_ERANGE;
				break;
			}
			budget = o->max_steps - steps;
			ph.mode = mode;
			ob.mode = mode;
			rc = oscsim_dp5_init(&dp, 2, phys_rhs, &ph, t, y0, 1,
					     0.0, o->rtol, atol, budget);
			if (rc != SQ_OK) {
				break;
			}
			dp.h_max = 0.25 / p->omega0_radps;
			ev.fn = ev_rel_velocity;
			ev.ctx = &ph;
			ev.dir = (mode == OSCSIM_SLIP_POS) ? -1 : 1;
			memset(&w, 0, sizeof(w));
			w.ev = &ev;
			w.n_ev = 1;
			if (o->on_sample != NULL) {
				w.sample_fn = sim_sample;
				w.sample_ctx = &ob;
				w.sample_dt = o->sample_dt_s;
				w.t_sample_next = t_sample;
			}
			w.step_fn = sim_step;
			w.step_ctx = &ob;
			rc = oscsim_dp5_advance(&dp, o->t_end_s, &w);
			steps += dp.steps;
			t_sample = w.t_sample_next;
			t = dp.t;
			x = dp.y[0];
			v = dp.y[1];
			if (rc < 0) {
				break;
			}
			rc = SQ_OK;
			if (t >= o->t_end_s) {
				break;
			}
			/* w reached 0: snap it and decide stick or cross */
			v = p->v0_mps;
			mode = mode_at_zero_w(p, x);
			if (mode == OSCSIM_STICK) {
				res->stick_entries++;
				if (res->first_stick_s < 0.0) {
					res->first_stick_s = t;
				}
			}
		}
		res->switches++;
		if (o->on_switch != NULL) {
			o->on_switch(o->cb_ctx, t, x, v, mode);
		}
		if (o->stop_at_stick && mode == OSCSIM_STICK) {
			break;
		}
		if (res->switches >= o->max_switches) {
			rc = SQ_ERANGE;
			break;
		}
	}
	res->t_s = t;
	res->x_m = x;
	res->v_mps = v;
	res->mode = mode;
	res->steps = steps;
	return rc;
}

/* ---- ground truth and basin test ---------------------------------------- */

const char *oscsim_truth_name(oscsim_truth_class_t c)
{
	static const char *const names[] = { "stable", "bistable", "unstable", "not_sliding" };

	return name_of(names, sizeof(names) / sizeof(names[0]), (unsigned int)c);
}

int oscsim_truth(const oscsim_params_t *p, const oscsim_cycle_opts_t *opts,
		 int check_linear, oscsim_truth_t *out)
{
	int rc = oscsim_params_check(p);

	if (rc != SQ_OK || out == NULL) {
		return SQ_EINVAL;
	}
	memset(out, 0, sizeof(*out));
	cycle_clear(&out->cycle);
	out->ln_q = DNAN;
	out->s = p->slope_spm * p->v0_mps;
	out->linear_grows = -1;
	out->growth_ratio = DNAN;
	out->cycle_x = DNAN;
	out->amplitude_m = DNAN;
	if (p->v0_mps == 0.0 || p->force_n == 0.0) {
		out->cls = OSCSIM_TRUTH_NOT_SLIDING;
		return SQ_OK;
	}
	if (p->slope_spm == 0.0 || p->delta_mu <= 0.0) {
		/* friction does not fall with speed: damping >= D w0 */
		out->cls = OSCSIM_TRUTH_STABLE;
		return SQ_OK;
	}
	rc = oscsim_ln_q(p, &out->ln_q, &out->s);
	if (rc != SQ_OK) {
		return rc;
	}
	if (check_linear) {
		rc = oscsim_linear_growth(p->damping, out->ln_q,
					  &out->growth_ratio);
		if (rc != SQ_OK) {
			return rc;
		}
		out->linear_grows = out->growth_ratio > 1.0;
	}
	if (out->ln_q <= LN_HALF) {
		out->cls = OSCSIM_TRUTH_UNSTABLE;
		out->cycle.kind = OSCSIM_CYCLE_NONE;
		return SQ_OK;
	}
	rc = oscsim_cycle_find(p->damping, out->ln_q, out->s, opts,
			       &out->cycle);
	if (rc != SQ_OK) {
		return rc;
	}
	if (out->cycle.kind == OSCSIM_CYCLE_FOUND &&
	    out->cycle.v_max < out->s) {
		out->cls = OSCSIM_TRUTH_BISTABLE;
		out->cycle_x = out->cycle.v_max;
		out->amplitude_m = out->cycle.r /
				   (p->slope_spm * p->omega0_radps);
	} else {
		out->cls = OSCSIM_TRUTH_STABLE;
	}
	return SQ_OK;
}

const char *oscsim_basin_name(oscsim_basin_outcome_t o)
{
	static const char *const names[] = { "undecided", "decayed", "captured" };

	return name_of(names, sizeof(names) / sizeof(names[0]), (unsigned int)o);
}

int oscsim_basin(const oscsim_params_t *p, double r_cycle, double factor,
		 uint32_t max_periods, oscsim_basin_outcome_t *outcome,
		 double *t_decided_s)
{
	oscsim_sim_opts_t o;
	oscsim_sim_result_t res;
	const uint32_t chunk = 5U;
	double period, xs, a0, x, v, t = 0.0;
	uint32_t done;
	int rc = oscsim_params_check(p);

	if (rc != SQ_OK || outcome == NULL || !(r_cycle > 0.0) ||
	    !(factor > 0.0) || !(p->slope_spm > 0.0) || !(p->v0_mps > 0.0)) {
		return SQ_EINVAL;
	}
	*outcome = OSCSIM_BASIN_UNDECIDED;
	period = TWO_PI / p->omega0_radps;
	xs = oscsim_steady_x(p);
	a0 = factor * r_cycle / (p->slope_spm * p->omega0_radps);
	x = xs + a0;
	v = 0.0;
	for (done = 0; done < max_periods; done += chunk) {
		oscsim_sim_default_opts(&o, (double)chunk * period);
		o.stop_at_stick = 1;
		o.rtol = 1e-10;
		/* the last period of the chunk measures the amplitude */
		o.stats_from_s = (double)(chunk - 1U) * period;
		rc = oscsim_simulate(p, x, v, &o, &res);
		if (rc != SQ_OK) {
			return rc;
		}
		if (res.stick_entries > 0U) {
			*outcome = OSCSIM_BASIN_CAPTURED;
			t += res.first_stick_s;
			break;
		}
		t += res.t_s;
		if (0.5 * (res.x_max_m - res.x_min_m) < 0.25 * a0) {
			*outcome = OSCSIM_BASIN_DECAYED;
			break;
		}
		x = res.x_m;
		v = res.v_mps;
	}
	if (t_decided_s != NULL) {
		*t_decided_s = t;
	}
	return SQ_OK;
}
