/* SPDX-License-Identifier: MIT */
/*
 * oscsim_map: simulation against the firmware model over the (a, v0)
 * plane, see oscsim_map.h.
 */
#include "oscsim_map.h"

#include <math.h>
#include <string.h>
#include <time.h>

#include "sim_num.h"
#include "squeal_model.h"

#define LN_HALF (-0.69314718055994530942)
#define DNAN ((double)NAN)

/* The operating point of the default: v0 1 m/s at the paper's N 9000 N. */
#define DEFAULT_V0_MPS 1.0
#define DEFAULT_FORCE_N 9000.0

void oscsim_default_params(oscsim_params_t *p)
{
	sim_params_d_t brake;

	sim_params_default(&brake);
	p->mass_kg = brake.mass_kg;
	p->omega0_radps = brake.omega0_radps;
	p->damping = brake.damping;
	p->mu_inf = brake.mu_inf;
	p->delta_mu = brake.delta_mu;
	p->slope_spm = brake.slope_spm;
	p->v0_mps = DEFAULT_V0_MPS;
	p->force_n = DEFAULT_FORCE_N;
}

/* The seven brakes: the default, and the default with one of w0, D, N
 * changed (0: the default's). */
typedef struct {
	const char *name;
	const char *what;
	double omega0_radps;
	double damping;
	double force_n;
} variation_row_t;

static const variation_row_t variation_rows[] = {
	{ "default", "paper's brake: D 0.023, w0 5000 rad/s, N 9000 N", 0.0, 0.0, 0.0 },
	{ "d0.05", "damping D 0.05", 0.0, 0.05, 0.0 },
	{ "d0.1", "damping D 0.1", 0.0, 0.1, 0.0 },
	{ "k2", "stiffness x2 (w0 x sqrt 2, D kept)", 7071.067811865475, 0.0, 0.0 },
	{ "k0.5", "stiffness x0.5 (w0 x sqrt 0.5, D kept)", 3535.5339059327378, 0.0, 0.0 },
	{ "n5000", "pad force N 5000 N", 0.0, 0.0, 5000.0 },
	{ "n20000", "pad force N 20000 N", 0.0, 0.0, 20000.0 },
};
#define VARIATIONS (sizeof(variation_rows) / sizeof(variation_rows[0]))

static const oscsim_variation_t *variations(void)
{
	static oscsim_variation_t table[VARIATIONS];
	static int built;
	size_t i;

	if (!built) {
		for (i = 0; i < VARIATIONS; i++) {
			const variation_row_t *r = &variation_rows[i];
			oscsim_variation_t *v = &table[i];

			v->name = r->name;
			v->what = r->what;
			oscsim_default_params(&v->params);
			if (r->omega0_radps > 0.0) {
				v->params.omega0_radps = r->omega0_radps;
			}
			if (r->damping > 0.0) {
				v->params.damping = r->damping;
			}
			if (r->force_n > 0.0) {
				v->params.force_n = r->force_n;
			}
		}
		built = 1;
	}
	return table;
}

size_t oscsim_variation_count(void)
{
	return VARIATIONS;
}

const oscsim_variation_t *oscsim_variation_get(size_t i)
{
	return (i < oscsim_variation_count()) ? &variations()[i] : NULL;
}

const oscsim_variation_t *oscsim_variation_find(const char *name)
{
	size_t i;

	for (i = 0; i < oscsim_variation_count(); i++) {
		if (strcmp(variations()[i].name, name) == 0) {
			return &variations()[i];
		}
	}
	return NULL;
}

void oscsim_map_default_opts(oscsim_map_opts_t *o)
{
	memset(o, 0, sizeof(*o));
	o->n_a = 100U;
	o->n_v = 100U;
	o->a_max_spm = 6.0;
	o->v_max_mps = 3.0;
	o->border_margin = 0.01;
	o->check_linear = 1;
	o->basin_every = 0U;
	o->basin_min_dist = 0.05;
	o->basin_periods = 3000U;
	oscsim_cycle_default_opts(&o->cyc);
	/* a classification needs far less than the table's 1e-10 */
	o->cyc.rtol = 1e-9;
	o->cyc.r_tol = 1e-7;
}

int oscsim_model_classify(const oscsim_params_t *p, int cubic, int *state,
			  double *cycle_x, double *ln_q)
{
	sim_params_d_t pd;
	squeal_params_t mp;
	squeal_point_t pt;
	squeal_result_t r;
	int rc;

	pd.mass_kg = p->mass_kg;
	pd.omega0_radps = p->omega0_radps;
	pd.damping = p->damping;
	pd.mu_inf = p->mu_inf;
	pd.delta_mu = p->delta_mu;
	pd.slope_spm = p->slope_spm;
	/* a value rounded to the fixed build's resolution is what the
	 * firmware would see too; only a refused conversion is an error */
	(void)sim_params_to_model(&pd, &mp);
	(void)sim_point_to_model(p->v0_mps, p->force_n, &pt);
	memset(&r, 0, sizeof(r));
	rc = squeal_model_classify(&mp, &pt,
				   cubic ? SQUEAL_CRITERION_CUBIC :
					   SQUEAL_CRITERION_EXACT,
				   &r);
	*state = (int)r.state;
	*cycle_x = ((r.flags & SQUEAL_HAS_CYCLE) != 0U) ?
			   sim_num_to_double(r.cycle_x, SQUEAL_Q_CYCLE_X) :
			   DNAN;
	*ln_q = ((r.flags & SQUEAL_HAS_LNQ) != 0U) ?
			sim_num_to_double(r.ln_q, SQUEAL_Q_LNQ) :
			DNAN;
	return rc;
}

/* ---- the simulated border ----------------------------------------------- */

int oscsim_border_build(oscsim_border_t *b, double damping, double s_max,
			const oscsim_cycle_opts_t *cyc)
{
	/* ln(Q - 1/2) from -14 to 22: cycles from u' ~ 0.004 to beyond 25 */
	const double lo = -14.0, hi = 22.0;
	uint32_t i;

	if (b == NULL || !(damping > 0.0) || !(s_max > 0.0)) {
		return SQ_EINVAL;
	}
	memset(b, 0, sizeof(*b));
	b->damping = damping;
	for (i = 0; i < OSCSIM_BORDER_POINTS; i++) {
		double le = lo + (hi - lo) * (double)i /
					 (double)(OSCSIM_BORDER_POINTS - 1U);
		double lq = log(0.5 + exp(le));
		oscsim_cycle_t c;
		int rc = oscsim_cycle_find(damping, lq, (double)INFINITY, cyc, &c);

		if (rc != SQ_OK || c.kind != OSCSIM_CYCLE_FOUND) {
			/* beyond what the integration resolves: stop here */
			break;
		}
		b->ln_q[i] = lq;
		b->x[i] = c.v_max;
		b->n = i + 1U;
		if (i > 0U && !(b->x[i] > b->x[i - 1U])) {
			return SQ_ERANGE; /* the cycle must grow with Q */
		}
		if (c.v_max > 1.05 * s_max) {
			break;
		}
	}
	if (b->n < 2U) {
		return SQ_ERANGE;
	}
	b->ln_q_lo = b->ln_q[0];
	b->ln_q_hi = b->ln_q[b->n - 1U];
	return SQ_OK;
}

double oscsim_border_ln_q(const oscsim_border_t *b, double s)
{
	uint32_t lo = 0, hi;

	if (b->n < 2U || !(s >= b->x[0]) || !(s <= b->x[b->n - 1U])) {
		return DNAN;
	}
	hi = b->n - 1U;
	while (hi - lo > 1U) {
		uint32_t mid = lo + (hi - lo) / 2U;

		if (b->x[mid] <= s) {
			lo = mid;
		} else {
			hi = mid;
		}
	}
	{
		/* ln(Q - 1/2) is close to linear in ln x on each interval */
		double e0 = log(exp(b->ln_q[lo]) - 0.5);
		double e1 = log(exp(b->ln_q[hi]) - 0.5);
		double f = (log(s) - log(b->x[lo])) /
			   (log(b->x[hi]) - log(b->x[lo]));

		return log(0.5 + exp(e0 + f * (e1 - e0)));
	}
}

/* ---- the sweep ---------------------------------------------------------- */

static int severity(int state)
{
	switch (state) {
	case 0:
		return 0; /* stable */
	case 1:
		return 1; /* bistable */
	case 2:
		return 2; /* unstable */
	default:
		return -1;
	}
}

static double now_s(void)
{
	struct timespec ts;

	if (clock_gettime(CLOCK_MONOTONIC, &ts) != 0) {
		return 0.0;
	}
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* One criterion's class m against the truth t. */
static void tally_model(int m, int t, int far, double border_dist, uint32_t *agree,
			uint32_t *under, uint32_t *over, uint32_t *far_disagree, double *worst_dist)
{
	if (m == t) {
		(*agree)++;
		return;
	}
	if (m < t) {
		(*under)++;
	} else {
		(*over)++;
	}
	if (far) {
		(*far_disagree)++;
	}
	*worst_dist = fmax(*worst_dist, border_dist);
}

/* One criterion's cycle x_model against the simulated one. */
static void tally_amp(double x_model, const oscsim_map_point_t *pt, int off_hopf, double *err_max,
		      double *err_at_q, double *err_far)
{
	double err;

	if (!isfinite(x_model)) {
		return;
	}
	err = fabs(x_model - pt->sim_x) / pt->sim_x;
	if (err > *err_max) {
		*err_max = err;
		*err_at_q = pt->ln_q;
	}
	if (off_hopf) {
		*err_far = fmax(*err_far, err);
	}
}

static void tally(oscsim_map_stats_t *st, const oscsim_map_opts_t *o,
		  const oscsim_map_point_t *pt)
{
	int t = severity((int)pt->truth);
	int e = severity(pt->exact_state);
	int c = severity(pt->cubic_state);
	int far = pt->border_dist > o->border_margin;

	st->points++;
	if ((unsigned int)pt->truth < 4U) {
		st->truth_count[pt->truth]++;
	}
	if (far) {
		st->far_points++;
	}
	tally_model(e, t, far, pt->border_dist, &st->exact_agree, &st->exact_under, &st->exact_over,
		    &st->exact_far_disagree, &st->exact_worst_dist);
	tally_model(c, t, far, pt->border_dist, &st->cubic_agree, &st->cubic_under, &st->cubic_over,
		    &st->cubic_far_disagree, &st->cubic_worst_dist);
	if (pt->truth == OSCSIM_TRUTH_BISTABLE && isfinite(pt->sim_x)) {
		/* right at the Hopf point the cycle shrinks to nothing and a
		 * relative error measures the model's rounding of Q - 1/2 */
		int off_hopf = fabs(pt->ln_q - LN_HALF) > o->border_margin;

		st->amp_points++;
		tally_amp(pt->exact_x, pt, off_hopf, &st->exact_amp_err, &st->exact_amp_err_at_q,
			  &st->exact_amp_err_far);
		tally_amp(pt->cubic_x, pt, off_hopf, &st->cubic_amp_err, &st->cubic_amp_err_at_q,
			  &st->cubic_amp_err_far);
	}
	if (pt->basin_in >= 0) {
		st->basin_tested++;
		if (pt->basin_in == OSCSIM_BASIN_DECAYED &&
		    pt->basin_out == OSCSIM_BASIN_CAPTURED) {
			st->basin_ok++;
		} else if (pt->basin_in == OSCSIM_BASIN_CAPTURED ||
			   pt->basin_out == OSCSIM_BASIN_DECAYED) {
			st->basin_wrong++;
		} else {
			st->basin_undecided++;
		}
	}
	if (pt->basin_cubic_in >= 0) {
		st->basin_cubic_tested++;
		if (pt->basin_cubic_in == OSCSIM_BASIN_CAPTURED) {
			st->basin_cubic_captured++;
		}
	}
	if (pt->linear_grows >= 0) {
		st->linear_checked++;
		if (fabs(pt->ln_q - LN_HALF) > o->border_margin &&
		    (pt->linear_grows != 0) != (pt->ln_q <= LN_HALF)) {
			st->linear_mismatch++;
		}
	}
}

/* The physical check of a predicted cycle: inside it the full oscillator
 * (with sticking) must settle, outside it must end in stick-slip. */
static int basin_pair(const oscsim_params_t *p, double model_x,
		      uint32_t periods, oscsim_map_point_t *pt)
{
	oscsim_basin_outcome_t in, out, cubic_in;
	int rc;

	/* the paper's cubic cycle, for contrast: it is too large, so a
	 * start "safely inside" it can already be outside the real one */
	if (isfinite(pt->cubic_x)) {
		rc = oscsim_basin(p, pt->cubic_x, 0.8, periods, &cubic_in, NULL);
		if (rc != SQ_OK) {
			return rc;
		}
		pt->basin_cubic_in = (int)cubic_in;
	}
	rc = oscsim_basin(p, model_x, 0.8, periods, &in, NULL);

	if (rc != SQ_OK) {
		return rc;
	}
	rc = oscsim_basin(p, model_x, 1.2, periods, &out, NULL);
	if (rc != SQ_OK) {
		return rc;
	}
	pt->basin_in = (int)in;
	pt->basin_out = (int)out;
	return SQ_OK;
}

int oscsim_map_run(const oscsim_variation_t *var, const oscsim_map_opts_t *o,
		   oscsim_map_point_fn fn, void *ctx, oscsim_map_stats_t *st)
{
	/* static: one table of 6.4 kB is too big for a comfortable stack
	 * frame, and the sweep is single-threaded */
	static oscsim_border_t border;
	oscsim_cycle_opts_t tab_opts;
	uint32_t basin_candidates = 0;
	double t0 = now_s();
	uint32_t i, j;
	int rc;

	if (var == NULL || o == NULL || st == NULL || o->n_a == 0U ||
	    o->n_v == 0U || !(o->a_max_spm > 0.0) || !(o->v_max_mps > 0.0)) {
		return SQ_EINVAL;
	}
	memset(st, 0, sizeof(*st));
	oscsim_cycle_default_opts(&tab_opts);
	rc = oscsim_border_build(&border, var->params.damping,
				 o->a_max_spm * o->v_max_mps, &tab_opts);
	if (rc != SQ_OK) {
		return rc;
	}
	for (j = 1; j <= o->n_v; j++) {
		for (i = 1; i <= o->n_a; i++) {
			oscsim_params_t p = var->params;
			oscsim_map_point_t pt;
			oscsim_truth_t tr;
			double lq_model;

			p.slope_spm = o->a_max_spm * (double)i / (double)o->n_a;
			p.v0_mps = o->v_max_mps * (double)j / (double)o->n_v;
			rc = oscsim_truth(&p, &o->cyc, o->check_linear, &tr);
			if (rc != SQ_OK) {
				return rc;
			}
			st->cycle_evals += tr.cycle.evals;
			st->cycle_steps += tr.cycle.steps;
			pt = (oscsim_map_point_t){ .a_spm = p.slope_spm, .v0_mps = p.v0_mps,
				.ln_q = tr.ln_q, .s = tr.s, .truth = tr.cls, .sim_x = tr.cycle_x,
				.linear_grows = tr.linear_grows, .basin_in = -1, .basin_out = -1,
				.basin_cubic_in = -1 };
			rc = oscsim_model_classify(&p, 0, &pt.exact_state,
						   &pt.exact_x, &lq_model);
			if (rc != SQ_OK) {
				return rc;
			}
			rc = oscsim_model_classify(&p, 1, &pt.cubic_state,
						   &pt.cubic_x, &lq_model);
			if (rc != SQ_OK) {
				return rc;
			}
			pt.ln_q_border = oscsim_border_ln_q(&border, pt.s);
			pt.border_dist = fabs(pt.ln_q - LN_HALF);
			if (isfinite(pt.ln_q_border)) {
				pt.border_dist = fmin(pt.border_dist,
						      fabs(pt.ln_q - pt.ln_q_border));
			}
			if (o->basin_every > 0U &&
			    pt.truth == OSCSIM_TRUTH_BISTABLE &&
			    pt.border_dist > o->basin_min_dist &&
			    isfinite(pt.exact_x)) {
				if (basin_candidates % o->basin_every == 0U) {
					rc = basin_pair(&p, pt.exact_x,
							o->basin_periods, &pt);
					if (rc != SQ_OK) {
						return rc;
					}
				}
				basin_candidates++;
			}
			tally(st, o, &pt);
			if (fn != NULL) {
				fn(ctx, var, &pt);
			}
		}
	}
	st->seconds = now_s() - t0;
	return SQ_OK;
}
