/* SPDX-License-Identifier: MIT */
/*
 * oscsim: a host-side simulator of the real, nonsmooth friction oscillator
 * (docs/model.md section 1), used as ground truth for the firmware's
 * closed-form classifier. Double precision, libm, no firmware types.
 *
 * Equation of motion, relative velocity w = v0 - x':
 *   m x'' + 2 D w0 m x' + m w0^2 x = N mu(|w|) sign(w),
 *   mu(w) = mu_inf + dmu exp(-a |w|)            (mu_0 = mu_inf + dmu)
 * with sticking (Filippov / event switching): when w reaches 0 the pad
 * sticks if the friction force needed to keep x' = v0,
 *   F_req = m (w0^2 x + 2 D w0 v0),
 * satisfies |F_req| <= mu_0 N; in stick x' = v0; it slips again when
 * |F_req| exceeds mu_0 N.
 *
 * Pieces, bottom up:
 *   - oscsim_dp5_*: an adaptive Dormand-Prince 5(4) integrator with error
 *     control, 4th-order dense output and event location on the dense
 *     output (Illinois method), forward or backward in time;
 *   - oscsim_cycle_find: the unstable sliding limit cycle of the
 *     dimensionless sliding system (docs/model.md section 5)
 *       u'' + 2 D u' + u = kappa (exp(u') - 1),   kappa = D / Q,
 *     found by integrating it BACKWARDS in time (where the unstable cycle
 *     attracts) over single revolutions between crossings of the section
 *     {u' = 0, u > 0}, accelerated by a bracketed root search on the
 *     backward return map, stopping whenever u' reaches the stick line s;
 *   - oscsim_simulate: the full oscillator with sticking, in physical units;
 *   - oscsim_truth: the ground-truth class of an operating point;
 *   - oscsim_basin: start inside / outside the cycle, watch what happens.
 *
 * Every loop is bounded (step, revolution, evaluation and switch budgets);
 * running out is reported as SQ_ERANGE, never hidden.
 * Errors: 0 or a negative SQ_E* code from sq_status.h.
 */
#ifndef OSCSIM_H
#define OSCSIM_H

#include <stddef.h>
#include <stdint.h>

#include "sq_status.h"

/* Physical parameters and the operating point, SI units. */
typedef struct {
	double mass_kg;      /* m                               */
	double omega0_radps; /* w0                              */
	double damping;      /* D                               */
	double mu_inf;       /* mu_inf                          */
	double delta_mu;     /* dmu = mu_0 - mu_inf             */
	double slope_spm;    /* a                               */
	double v0_mps;       /* disc surface speed              */
	double force_n;      /* pad normal force N              */
} oscsim_params_t;

/* The paper's disc brake (docs/model.md section 8) at a = 2 s/m, v0 = 1 m/s,
 * N = 9000 N: the brake is the firmware's default (sim_params_default), so
 * this one function lives with the firmware-facing part, oscsim_map.c. */
void oscsim_default_params(oscsim_params_t *p);

/* Returns SQ_OK if every field is finite and physically meaningful
 * (m, w0, D > 0; a, v0, N, mu_inf >= 0; mu_inf + dmu >= 0). */
int oscsim_params_check(const oscsim_params_t *p);

/*
 * ln Q = ln(D w0 m / (a N dmu)) + a v0, and s = a v0 (the stick line in the
 * dimensionless velocity u' = a x'). Needs a, N, dmu > 0: SQ_EINVAL otherwise.
 */
int oscsim_ln_q(const oscsim_params_t *p, double *ln_q, double *s);

/* ---- Dormand-Prince 5(4) ------------------------------------------------ */

#define OSCSIM_MAX_DIM 4U

typedef void (*oscsim_rhs_fn)(double t, const double *y, double *dydt,
			      void *ctx);
typedef double (*oscsim_event_fn)(double t, const double *y, void *ctx);

typedef struct {
	size_t n;
	oscsim_rhs_fn rhs;
	void *ctx;
	double rtol;
	double atol[OSCSIM_MAX_DIM];
	double h_max;        /* largest |h|; 0 = no limit            */
	uint32_t max_steps;  /* budget of attempted steps           */
	/* state */
	double t;
	double y[OSCSIM_MAX_DIM];
	double f[OSCSIM_MAX_DIM]; /* rhs at (t, y) (FSAL)          */
	double h;                 /* next step, signed             */
	/* dense output of the last accepted step [t_old, t] */
	double t_old;
	double h_last;
	double rc[5][OSCSIM_MAX_DIM];
	uint32_t steps;     /* accepted */
	uint32_t rejected;
	uint32_t attempts;
	uint32_t f_evals;
} oscsim_dp5_t;

/*
 * Start an integration at (t0, y0) in direction dir (+1 forward, -1
 * backward); h0 = 0 picks the first step automatically.
 * Returns SQ_EINVAL for n outside 1..OSCSIM_MAX_DIM, a non-positive rtol,
 * negative atol, a zero dir or non-finite values.
 */
int oscsim_dp5_init(oscsim_dp5_t *me, size_t n, oscsim_rhs_fn rhs, void *ctx,
		    double t0, const double *y0, int dir, double h0,
		    double rtol, const double *atol, uint32_t max_steps);

/*
 * Take one accepted step towards t_end (never beyond it).
 * Returns SQ_OK, or SQ_ERANGE when the step budget is spent or the step
 * size underflows, SQ_EIO when the solution stops being finite.
 */
int oscsim_dp5_step(oscsim_dp5_t *me, double t_end);

/* Dense output of the last accepted step at t in [t_old, t]. */
void oscsim_dp5_dense(const oscsim_dp5_t *me, double t, double *y);

/* Restart at (t, y), e.g. after a located event (recomputes the rhs). */
void oscsim_dp5_restart(oscsim_dp5_t *me, double t, const double *y);

/* An event g(t, y) = 0 crossed in direction dir (+1: g rises through 0 in
 * the direction of integration, -1: falls, 0: either). */
typedef struct {
	oscsim_event_fn fn;
	void *ctx;
	int dir;
} oscsim_event_t;

/* Called at every multiple of dt while advancing (dt > 0 in |t|). */
typedef void (*oscsim_sample_fn)(void *ctx, double t, const double *y);
/* Called after every accepted step; t_stop is where the step's valid part
 * ends (the event time when the step contains an event). */
typedef void (*oscsim_step_fn)(void *ctx, const oscsim_dp5_t *dp,
			       double t_stop);

/* What to watch while advancing; any member may be 0/NULL. */
typedef struct {
	const oscsim_event_t *ev;
	size_t n_ev;
	oscsim_sample_fn sample_fn;
	void *sample_ctx;
	double sample_dt;      /* > 0 with sample_fn                       */
	double t_sample_next;  /* next sample time, updated while advancing */
	oscsim_step_fn step_fn;
	void *step_ctx;
} oscsim_watch_t;

/*
 * Advance to t_end or to the first event of watch->ev, whichever comes
 * first. An event is a strict sign change of g over a step (g = 0 at the
 * start of the advance is not one), located on the dense output to
 * ~1e-13 relative in t; the integrator is then restarted exactly at it.
 * Samples are written at t_sample_next, t_sample_next +- sample_dt, ...
 * Returns the index of the event found (>= 0), OSCSIM_REACHED_END, or a
 * negative SQ_E* code from oscsim_dp5_step. watch may be NULL.
 */
#define OSCSIM_REACHED_END 1000
int oscsim_dp5_advance(oscsim_dp5_t *me, double t_end, oscsim_watch_t *watch);

/* ---- the unstable sliding cycle (dimensionless) ------------------------- */

typedef struct {
	double damping; /* D                                            */
	double kappa;   /* D / Q                                        */
} oscsim_slide_t;

/* Right-hand side of u'' + 2 D u' + u = kappa (exp(u') - 1), y = (u, u'). */
void oscsim_slide_rhs(double t, const double *y, double *dydt, void *ctx);

typedef struct {
	double rtol;           /* integrator tolerance, e.g. 1e-10        */
	double r_tol;          /* root tolerance on the section, relative */
	uint32_t max_evals;    /* revolutions of the root search           */
	uint32_t max_steps;    /* steps per revolution                     */
} oscsim_cycle_opts_t;

void oscsim_cycle_default_opts(oscsim_cycle_opts_t *o);

typedef enum {
	OSCSIM_CYCLE_NONE = 0,      /* Q <= 1/2: no cycle around a stable state */
	OSCSIM_CYCLE_FOUND = 1,     /* closed sliding cycle below the stick line */
	OSCSIM_CYCLE_AT_STICK = 2   /* every candidate reaches u' = s: no sliding
				     * cycle below the stick line */
} oscsim_cycle_kind_t;

typedef struct {
	oscsim_cycle_kind_t kind;
	double r;        /* u where the cycle crosses {u' = 0, u > 0}          */
	double u_min;    /* u where it crosses {u' = 0, u < 0}                 */
	double v_max;    /* max u' on the cycle (the x of docs/model.md section 3)  */
	double v_min;    /* min u' on the cycle                                */
	double period;   /* period in tau = w0 t                              */
	double v_reach;  /* AT_STICK: largest u' seen on an inside orbit       */
	uint32_t evals;  /* revolutions integrated                            */
	uint32_t steps;  /* integrator steps in total                          */
} oscsim_cycle_t;

/*
 * Find the unstable sliding cycle for damping D, ln Q and stick line s
 * (s = INFINITY for no stick line). ln_q <= ln(1/2) gives kind NONE.
 * Returns SQ_OK, SQ_EINVAL on bad arguments, SQ_ERANGE if a budget ran out.
 */
int oscsim_cycle_find(double damping, double ln_q, double s,
		      const oscsim_cycle_opts_t *opts, oscsim_cycle_t *out);

/*
 * The backward return map on {u' = 0, u > 0}: one backward revolution from
 * (r, 0). *r_next gets the next crossing; *v_peak the largest u' seen.
 * Returns 0 on a crossing, 1 when u' reached s first (then *r_next = NAN),
 * negative SQ_E* on failure.
 */
int oscsim_cycle_return_map(double damping, double ln_q, double s, double r,
			    const oscsim_cycle_opts_t *opts, double *r_next,
			    double *v_peak, uint32_t *steps);

/*
 * Reference method (slow, for checks): brute-force backward integration
 * from (r_start, 0) for up to max_revs revolutions, until the section point
 * changes by less than r_tol relative between revolutions. Same output.
 */
int oscsim_cycle_backward_plain(double damping, double ln_q, double s,
				double r_start, uint32_t max_revs,
				const oscsim_cycle_opts_t *opts,
				oscsim_cycle_t *out);

/*
 * Trace one backward revolution of the sliding system from (r, 0) with a
 * sample every dt (tau units): fn(ctx, tau, y) with y = (u, u'), tau <= 0.
 * Used to draw the unstable cycle. Returns SQ_OK or a negative code.
 */
int oscsim_cycle_trace(double damping, double ln_q, double r, double dt,
		       oscsim_sample_fn fn, void *ctx);

/*
 * Forward-time linear check: ratio of the section amplitude after one
 * forward revolution to the start, from the small perturbation r = 1e-5.
 * > 1 means the steady state is unstable (grows).
 */
int oscsim_linear_growth(double damping, double ln_q, double *ratio);

/* ---- the full oscillator with sticking --------------------------------- */

typedef enum {
	OSCSIM_SLIP_POS = 0, /* w > 0: disc faster than pad (normal sliding) */
	OSCSIM_SLIP_NEG = 1, /* w < 0: pad overtakes the disc               */
	OSCSIM_STICK = 2     /* w = 0: pad carried by the disc              */
} oscsim_mode_t;

const char *oscsim_mode_name(oscsim_mode_t mode);

typedef void (*oscsim_trace_fn)(void *ctx, double t_s, double x_m,
				double v_mps, oscsim_mode_t mode);

typedef struct {
	double t_end_s;
	double rtol;              /* e.g. 1e-9                             */
	double sample_dt_s;       /* 0: no samples                         */
	double stats_from_s;      /* extremes recorded for t >= this       */
	uint32_t max_steps;       /* integrator steps in total             */
	uint32_t max_switches;    /* mode changes in total                 */
	int stop_at_stick;        /* stop at the first stick entry         */
	oscsim_trace_fn on_sample;
	oscsim_trace_fn on_switch; /* at every mode change (new mode)      */
	void *cb_ctx;
} oscsim_sim_opts_t;

void oscsim_sim_default_opts(oscsim_sim_opts_t *o, double t_end_s);

typedef struct {
	double t_s;
	double x_m;
	double v_mps;
	oscsim_mode_t mode;
	uint32_t steps;
	uint32_t switches;
	uint32_t stick_entries;
	double first_stick_s;  /* time of first stick entry, -1 if none    */
	double x_min_m, x_max_m, v_min_mps, v_max_mps; /* for t >= stats_from */
} oscsim_sim_result_t;

/*
 * Simulate from x(0) = x0_m, x'(0) = xd0_mps to opts->t_end_s (or the first
 * stick entry with stop_at_stick). Needs v0 > 0.
 * Returns SQ_OK, SQ_EINVAL, SQ_ERANGE (a budget ran out; *res holds the
 * state reached).
 */
int oscsim_simulate(const oscsim_params_t *p, double x0_m, double xd0_mps,
		    const oscsim_sim_opts_t *opts, oscsim_sim_result_t *res);

/* Steady sliding position x_s = N mu(v0) / (m w0^2). */
double oscsim_steady_x(const oscsim_params_t *p);

/* ---- ground truth and basin test --------------------------------------- */

typedef enum {
	OSCSIM_TRUTH_STABLE = 0,
	OSCSIM_TRUTH_BISTABLE = 1,
	OSCSIM_TRUTH_UNSTABLE = 2,
	OSCSIM_TRUTH_NOT_SLIDING = 3 /* v0 == 0, N == 0, a == 0 or dmu <= 0 */
} oscsim_truth_class_t;

const char *oscsim_truth_name(oscsim_truth_class_t c);

typedef struct {
	oscsim_truth_class_t cls;
	double ln_q;
	double s;
	int linear_grows;      /* forward simulation of a small perturbation
				* grows (1) or decays (0); -1 not checked  */
	double growth_ratio;   /* per revolution, see oscsim_linear_growth */
	oscsim_cycle_t cycle;  /* valid when ln_q > ln(1/2)                */
	double cycle_x;        /* BISTABLE: max u' of the cycle (= a w0 A) */
	double amplitude_m;    /* BISTABLE: (r / (a w0)), displacement on
				* the section {x' = 0}                      */
} oscsim_truth_t;

/*
 * Classify by simulation: UNSTABLE if ln Q <= ln(1/2) (and linear_grows
 * records the simulated check when check_linear), BISTABLE if the backward
 * search finds a closed sliding cycle with max u' < s, STABLE otherwise.
 */
int oscsim_truth(const oscsim_params_t *p, const oscsim_cycle_opts_t *opts,
		 int check_linear, oscsim_truth_t *out);

typedef enum {
	OSCSIM_BASIN_UNDECIDED = 0,
	OSCSIM_BASIN_DECAYED = 1,   /* back to steady sliding               */
	OSCSIM_BASIN_CAPTURED = 2   /* reached the stick line: stick-slip   */
} oscsim_basin_outcome_t;

const char *oscsim_basin_name(oscsim_basin_outcome_t o);

/*
 * Start the full oscillator at x = x_s + factor * r / (a w0), x' = 0, i.e.
 * on the cycle's section scaled by factor, and run up to max_periods
 * natural periods. DECAYED when the displacement amplitude falls below
 * 1/4 of the start without sticking; CAPTURED at the first stick entry.
 */
int oscsim_basin(const oscsim_params_t *p, double r_cycle, double factor,
		 uint32_t max_periods, oscsim_basin_outcome_t *outcome,
		 double *t_decided_s);

#endif /* OSCSIM_H */
