/* SPDX-License-Identifier: MIT */
/*
 * Brute-force decision by backward integration of the sliding oscillator,
 * see brute_force.h. Written from docs/model.md section 5, independent of
 * firmware/model.
 */
#include "brute_force.h"

#include <math.h>
#include <stddef.h>

typedef struct {
	double u;  /* displacement          */
	double du; /* u' (velocity)         */
} bf_state_t;

/* Right-hand side: (u, u')' = (u', -2 D u' - u + kappa (e^u' - 1)).
 * expm1 keeps the small-perturbation start accurate. */
static bf_state_t bf_rhs(bf_state_t y, double damping, double kappa)
{
	bf_state_t d;

	d.u = y.du;
	d.du = -2.0 * damping * y.du - y.u + kappa * expm1(y.du);
	return d;
}

static bf_state_t bf_axpy(bf_state_t y, double h, bf_state_t k)
{
	bf_state_t r;

	r.u = y.u + h * k.u;
	r.du = y.du + h * k.du;
	return r;
}

static bf_state_t bf_rk4_step(bf_state_t y, double h, double damping, double kappa)
{
	bf_state_t k1 = bf_rhs(y, damping, kappa);
	bf_state_t k2 = bf_rhs(bf_axpy(y, 0.5 * h, k1), damping, kappa);
	bf_state_t k3 = bf_rhs(bf_axpy(y, 0.5 * h, k2), damping, kappa);
	bf_state_t k4 = bf_rhs(bf_axpy(y, h, k3), damping, kappa);
	bf_state_t r;

	r.u = y.u + h / 6.0 * (k1.u + 2.0 * k2.u + 2.0 * k3.u + k4.u);
	r.du = y.du + h / 6.0 * (k1.du + 2.0 * k2.du + 2.0 * k3.du + k4.du);
	return r;
}

/* Acceleration u'' = d(u')/dtau at a state: zero at a maximum of u'. */
static double bf_accel(bf_state_t y, double damping, double kappa)
{
	return bf_rhs(y, damping, kappa).du;
}

/*
 * The maximum of u' inside the step h from y0 to the next grid point, where
 * the slope of u' along the direction of integration goes from g0 > 0 to
 * g1 <= 0: find the partial
 * step t in (0, h] whose RK4 end point has zero acceleration, by regula
 * falsi (Illinois), and return u' there. Doing a real RK4 step to the peak
 * (instead of interpolating the samples) keeps the peak values free of the
 * grid's phase jitter, so successive peaks converge smoothly.
 */
static double bf_peak_du(bf_state_t y0, double h, double g0, double g1,
			 double damping, double kappa)
{
	double t_lo = 0.0, t_hi = h;
	double g_lo = g0, g_hi = g1;
	double du = 0.0;
	int side = 0;
	int it;

	for (it = 0; it < 30; it++) {
		double t = (t_lo * g_hi - t_hi * g_lo) / (g_hi - g_lo);
		bf_state_t y = bf_rk4_step(y0, t, damping, kappa);
		/* slope of u' along the direction of integration */
		double g = copysign(1.0, h) * bf_accel(y, damping, kappa);

		du = y.du;
		if (fabs(g) <= 1e-13 * (1.0 + fabs(y.u)) ||
		    fabs(t_hi - t_lo) <= 1e-15 * fabs(h)) {
			break;
		}
		if (g > 0.0) {
			t_lo = t;
			g_lo = g;
			if (side == -1) {
				g_hi *= 0.5;
			}
			side = -1;
		} else {
			t_hi = t;
			g_hi = g;
			if (side == 1) {
				g_lo *= 0.5;
			}
			side = 1;
		}
	}
	return du;
}

int bf_decide(double damping, double q, double stick, bf_result_t *out)
{
	/* Backwards in time: negative step. */
	const double h = -2.0 * M_PI / BF_STEPS_PER_PERIOD;
	double kappa;
	double g_prev, g;
	double peak_last = 0.0;
	double diff_last = 0.0;
	bf_state_t y, y_prev;
	long step;

	if (out == NULL || !(damping > 0.0 && damping <= 1.0) ||
	    !(q > 0.5 && isfinite(q)) || !(stick > 0.0)) {
		return -1;
	}
	kappa = damping / q;
	out->decision = BF_STABLE;
	out->cycle_max_du = 0.0;
	out->last_peak_du = 0.0;
	out->steps = 0;
	out->peaks = 0;

	y.u = 0.0;
	y.du = BF_START_DU * fmin(1.0, stick);
	g = bf_accel(y, damping, kappa);
	for (step = 1; step <= BF_MAX_STEPS; step++) {
		y_prev = y;
		g_prev = g;
		y = bf_rk4_step(y, h, damping, kappa);
		g = bf_accel(y, damping, kappa);
		out->steps = step;
		if (y.du >= stick) {
			out->decision = BF_STABLE;
			return 0;
		}
		/* u' rises in the direction of integration (d u'/d tau has the
		 * sign opposite to g, since tau runs backwards), i.e. a maximum
		 * of u' where -g changes from > 0 to <= 0. */
		if (-g_prev > 0.0 && -g <= 0.0 && y.du > 0.0) {
			double peak = bf_peak_du(y_prev, h, -g_prev, -g, damping,
						 kappa);
			double diff = peak - peak_last;

			out->peaks++;
			out->last_peak_du = peak;
			/* Settled: the change is small AND shrinking. While the
			 * perturbation still grows linearly the changes grow, so a
			 * slow growth near Q = 1/2 is not mistaken for a cycle. */
			if (out->peaks >= 3 && fabs(diff) <= BF_SETTLE_TOL * peak &&
			    fabs(diff) <= fabs(diff_last)) {
				out->decision = BF_BISTABLE;
				out->cycle_max_du = peak;
				return 0;
			}
			diff_last = diff;
			peak_last = peak;
		}
	}
	return -2;
}
