/* SPDX-License-Identifier: MIT */
/*
 * oscsim_map: sweep the (a, v0) plane, classify every point by simulation
 * (oscsim_truth) and by the firmware model (squeal_model_classify, both
 * criteria), and measure how well they agree.
 *
 * Distance to a border is measured in ln Q at the point's own s = a v0:
 * to the Hopf border ln(1/2) and to the simulated bistable/stable border,
 * the ln Q at which the simulated cycle's max u' equals s (found from a
 * table of the cycle over ln Q, built per damping by the same backward
 * integration, and inverted by monotone interpolation).
 */
#ifndef OSCSIM_MAP_H
#define OSCSIM_MAP_H

#include <stddef.h>
#include <stdint.h>

#include "oscsim.h"

/* A brake: the paper's default and its variations (docs/model.md section 8). */
typedef struct {
	const char *name;
	const char *what; /* one line for humans */
	oscsim_params_t params; /* slope_spm and v0_mps are set per point */
} oscsim_variation_t;

/* The seven brakes: default, D 0.05, D 0.1, stiffness x2 and x0.5 (w0
 * scaled by sqrt(2), sqrt(0.5): the damping RATIO D is kept), N 5000 N and
 * 20000 N. */
size_t oscsim_variation_count(void);
const oscsim_variation_t *oscsim_variation_get(size_t i);
const oscsim_variation_t *oscsim_variation_find(const char *name);

typedef struct {
	uint32_t n_a;            /* grid points in a: a_i = a_max i / n_a  */
	uint32_t n_v;            /* grid points in v0: v_j = v_max j / n_v */
	double a_max_spm;
	double v_max_mps;
	double border_margin;    /* |d ln Q| counted as "near a border"  */
	int check_linear;        /* simulate the linear test per point   */
	uint32_t basin_every;    /* basin-test every n-th bistable point
				  * farther than basin_min_dist from a
				  * border (0: none)                     */
	double basin_min_dist;
	uint32_t basin_periods;  /* budget per start, natural periods    */
	oscsim_cycle_opts_t cyc;
} oscsim_map_opts_t;

void oscsim_map_default_opts(oscsim_map_opts_t *o);

/* Model classes, as squeal_state_t values (0 stable, 1 bistable,
 * 2 unstable, 3 not sliding, 15 invalid). */
typedef struct {
	double a_spm;
	double v0_mps;
	double ln_q;
	double s;
	oscsim_truth_class_t truth;
	double sim_x;         /* BISTABLE: simulated max u' of the cycle     */
	int linear_grows;     /* -1 not checked                              */
	int exact_state;
	double exact_x;       /* model's cycle_x (NaN when it has none)      */
	int cubic_state;
	double cubic_x;
	double ln_q_border;   /* simulated bistable/stable border at this s  */
	double border_dist;   /* min |ln Q - border| over both borders       */
	int basin_in;         /* oscsim_basin_outcome_t of the full stick-slip
			       * oscillator started at 0.8 x the exact model's
			       * predicted cycle, -1 when not tested          */
	int basin_out;        /* the same at 1.2 x                           */
	int basin_cubic_in;   /* started at 0.8 x the cubic cycle            */
} oscsim_map_point_t;

typedef struct {
	uint32_t points;
	uint32_t truth_count[4];      /* by oscsim_truth_class_t            */
	uint32_t exact_agree;
	uint32_t cubic_agree;
	uint32_t exact_under;         /* model less alarmed than the truth  */
	uint32_t exact_over;          /* model more alarmed                 */
	uint32_t cubic_under;
	uint32_t cubic_over;
	uint32_t far_points;          /* border_dist > border_margin        */
	uint32_t exact_far_disagree;  /* disagreements among those          */
	uint32_t cubic_far_disagree;
	double exact_worst_dist;      /* largest border_dist of a disagreement */
	double cubic_worst_dist;
	double exact_amp_err;         /* worst |x_model - x_sim| / x_sim    */
	double cubic_amp_err;         /*  over truth-bistable points         */
	double exact_amp_err_at_q;    /* ln Q where the worst error is       */
	double cubic_amp_err_at_q;
	double exact_amp_err_far;     /* the same, only points farther than */
	double cubic_amp_err_far;     /*  border_margin from the Hopf border */
	uint32_t amp_points;
	uint32_t linear_checked;
	uint32_t linear_mismatch;     /* simulated growth vs Q <= 1/2, far */
	uint32_t basin_tested;        /* points basin-tested               */
	uint32_t basin_ok;            /* 0.8 decayed and 1.2 captured      */
	uint32_t basin_undecided;     /* a start undecided within budget   */
	uint32_t basin_wrong;         /* a start went the other way        */
	uint32_t basin_cubic_tested;  /* 0.8 x the cubic cycle ...         */
	uint32_t basin_cubic_captured; /* ... ended in stick-slip anyway   */
	uint32_t cycle_evals;
	uint64_t cycle_steps;
	double seconds;
} oscsim_map_stats_t;

/* Called for every point (e.g. to write CSV); may be NULL. */
typedef void (*oscsim_map_point_fn)(void *ctx, const oscsim_variation_t *var,
				    const oscsim_map_point_t *pt);

/*
 * Sweep one brake. Returns SQ_OK, SQ_EINVAL, or the first failure of the
 * simulation (SQ_ERANGE: a budget ran out) or of the model (SQ_EINVAL).
 */
int oscsim_map_run(const oscsim_variation_t *var, const oscsim_map_opts_t *o,
		   oscsim_map_point_fn fn, void *ctx, oscsim_map_stats_t *st);

/*
 * The simulated bistable/stable border as ln Q(s): a table of the cycle's
 * max u' over ln Q for one damping, inverted. ln Q below which the cycle
 * stays under the stick line s; NaN when s is beyond the table.
 */
#define OSCSIM_BORDER_POINTS 400U
typedef struct {
	double damping;
	double ln_q_lo, ln_q_hi;
	uint32_t n;
	double ln_q[OSCSIM_BORDER_POINTS];
	double x[OSCSIM_BORDER_POINTS];
} oscsim_border_t;

int oscsim_border_build(oscsim_border_t *b, double damping, double s_max,
			const oscsim_cycle_opts_t *cyc);
double oscsim_border_ln_q(const oscsim_border_t *b, double s);

/* Classify one point with the firmware model (float or fixed build),
 * converted to doubles. Returns the model's code. */
int oscsim_model_classify(const oscsim_params_t *p, int cubic, int *state,
			  double *cycle_x, double *ln_q);

#endif /* OSCSIM_MAP_H */
