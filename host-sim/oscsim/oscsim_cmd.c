/* SPDX-License-Identifier: MIT */
/*
 * squeal-sim map / simulate: the simulator's command-line faces, see
 * oscsim_cmd.h.
 */
#include "oscsim_cmd.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli_args.h"
#include "oscsim.h"
#include "oscsim_map.h"
#include "squeal_model.h"

#define TWO_PI 6.28318530717958647692

/* ---- simulate ----------------------------------------------------------- */

typedef struct {
	oscsim_params_t p;
	double t_end_s;
	double dt_s;
	double dx_m;
	double x0_m;
	double xd0_mps;
	double rtol;
	double basin;
	double q;
	double s;
	bool have_x0;
	bool have_q;
	int mode; /* 0 trajectory, 1 cycle, 2 truth, 3 basin, 4 dimless */
	bool plain;
} sim_args_t;

static void print_trace(const char *kind, double t_s, double x_m,
			double v_mps, oscsim_mode_t mode)
{
	printf("%s,%.9e,%.12e,%.12e,%s\n", kind, t_s, x_m, v_mps,
	       oscsim_mode_name(mode));
}

static void print_sample(void *ctx, double t_s, double x_m, double v_mps,
			 oscsim_mode_t mode)
{
	(void)ctx;
	print_trace("sample", t_s, x_m, v_mps, mode);
}

static void print_switch(void *ctx, double t_s, double x_m, double v_mps,
			 oscsim_mode_t mode)
{
	(void)ctx;
	print_trace("switch", t_s, x_m, v_mps, mode);
}

typedef struct {
	const oscsim_params_t *p;
	double xs;
} cycle_print_t;

static void print_cycle(void *ctx, double tau, const double *y)
{
	const cycle_print_t *cp = ctx;
	double k = cp->p->slope_spm * cp->p->omega0_radps;

	/* u = a w0 (x - x_s), u' = a x' */
	printf("cycle,%.9e,%.12e,%.12e,slip\n", tau / cp->p->omega0_radps,
	       cp->xs + y[0] / k, y[1] / cp->p->slope_spm);
}

static int parse_sim_args(int argc, char **argv, sim_args_t *a)
{
	/* the modes besides the trajectory, as sim_args_t.mode numbers them */
	bool mode_given[5] = { false, false, false, false, false };
	const cli_opt_t opts[] = {
		CLI_OPT_ANY_REAL("v0", &a->p.v0_mps, NULL, "MPS", "disc surface speed [m/s] (default 1)"),
		CLI_OPT_ANY_REAL("force", &a->p.force_n, NULL, "N", "pad normal force [N] (default 9000)"),
		CLI_OPT_ANY_REAL("slope", &a->p.slope_spm, NULL, "A", "friction slope a [s/m] (default 2)"),
		CLI_OPT_ANY_REAL("damping", &a->p.damping, NULL, "D", "damping ratio D [-]"),
		CLI_OPT_ANY_REAL("omega0", &a->p.omega0_radps, NULL, "W",
			     "natural angular frequency [rad/s]"),
		CLI_OPT_ANY_REAL("mass", &a->p.mass_kg, NULL, "M", "moving mass m [kg]"),
		CLI_OPT_ANY_REAL("mu-inf", &a->p.mu_inf, NULL, "X",
			     "friction coefficient at high speed"),
		CLI_OPT_ANY_REAL("delta-mu", &a->p.delta_mu, NULL, "Y", "mu_0 - mu_inf"),
		CLI_OPT_ANY_REAL("t-end", &a->t_end_s, NULL, "S", "simulated time [s] (default 0.05)"),
		CLI_OPT_ANY_REAL("dt", &a->dt_s, NULL, "S",
			     "sample interval [s] (default one 64th of 2 pi / w0)"),
		CLI_OPT_ANY_REAL("dx", &a->dx_m, NULL, "M", "start at x = x_s + dx [m] (default 0)"),
		CLI_OPT_ANY_REAL("x0", &a->x0_m, &a->have_x0, "M", "start at x = x0 [m] instead"),
		CLI_OPT_ANY_REAL("xd0", &a->xd0_mps, NULL, "MPS", "start velocity x' [m/s] (default 0)"),
		CLI_OPT_ANY_REAL("rtol", &a->rtol, NULL, "R", "integrator tolerance (default 1e-9)"),
		CLI_OPT_FLAG("cycle", 0, &mode_given[1],
			     "the unstable sliding cycle (backward-time integration) in the\n"
			     "same CSV with kind 'cycle'; exit 1 when there is none"),
		CLI_OPT_FLAG("truth", 0, &mode_given[2], "ground-truth class by simulation, key=value"),
		CLI_OPT_ANY_REAL("basin", &a->basin, &mode_given[3], "F",
			     "start at F times the cycle (on x' = 0) and report whether the\n"
			     "oscillator decays to steady sliding or is captured by stick-slip"),
		CLI_OPT_FLAG("dimless", 0, &mode_given[4],
			     "the cycle of u'' + 2 D u' + u = (D/Q)(exp(u') - 1) for --damping\n"
			     "and --q, stick line --s (default none): key=value"),
		CLI_OPT_ANY_REAL("q", &a->q, &a->have_q, "Q", "--dimless: Q"),
		CLI_OPT_ANY_REAL("s", &a->s, NULL, "S", "--dimless: the stick line s"),
		CLI_OPT_FLAG("plain", 0, &a->plain,
			     "--dimless: brute-force backward integration instead of the\n"
			     "return-map search"),
	};
	const cli_spec_t spec = {
		.cmd = "simulate",
		CLI_SPEC_OPTS(opts),
		.synopsis = "squeal-sim simulate [--v0 MPS] [--force N] [--slope A] [--damping D]\n"
			    "         [--omega0 W] [--mass M] [--mu-inf X] [--delta-mu Y]\n"
			    "         [--t-end S] [--dt S] [--dx M | --x0 M] [--xd0 MPS] [--rtol R]\n"
			    "         [--cycle | --truth | --basin F | --dimless --q Q [--s S] [--plain]]",
		.description = "Simulates the friction oscillator with sliding and sticking (Dormand-Prince\n"
			       "5(4), event switching at relative velocity 0). Defaults: the paper's brake\n"
			       "(docs/model.md) at a = 2 s/m, v0 = 1 m/s, N = 9000 N.\n\n"
			       "Without a mode option: the trajectory from x = x_s + dx, x' = xd0 for\n"
			       "t-end seconds, CSV kind,t_s,x_m,v_mps,mode on stdout, kind 'sample'\n"
			       "every dt and 'switch' at each change of mode (slip, slip_neg, stick).",
		.closing = "Exit status: 0 done, 1 the simulation failed or found no cycle, 2 bad usage.",
	};
	cli_result_t r;
	int m;

	oscsim_default_params(&a->p);
	a->t_end_s = 0.05;
	a->dt_s = 0.0;
	a->rtol = 1e-9;
	a->s = (double)INFINITY;
	r = cli_parse(&spec, argc, argv, NULL, NULL);
	if (r != CLI_OK) {
		return (int)r;
	}
	for (m = 1; m < 5; m++) {
		if (mode_given[m]) {
			if (a->mode != 0) {
				return (int)cli_usage_error(&spec, "give one of --cycle, --truth, --basin, --dimless");
			}
			a->mode = m;
		}
	}
	return CLI_OK;
}

static int sim_dimless(const sim_args_t *a)
{
	oscsim_cycle_t c;
	int rc;

	if (!a->have_q || !(a->q > 0.0) || !(a->p.damping > 0.0)) {
		fprintf(stderr, "squeal-sim simulate --dimless: needs --damping D > 0 and --q Q > 0\n");
		return 2;
	}
	if (a->plain) {
		rc = oscsim_cycle_backward_plain(a->p.damping, log(a->q), a->s,
						 0.5, 200000U, NULL, &c);
	} else {
		rc = oscsim_cycle_find(a->p.damping, log(a->q), a->s, NULL, &c);
	}
	if (rc != SQ_OK) {
		fprintf(stderr, "squeal-sim simulate: cycle search failed (%d)\n", rc);
		return 1;
	}
	printf("kind=%s r=%.10f v_max=%.10f v_min=%.10f u_min=%.10f period=%.10f v_reach=%.10f evals=%u steps=%u\n",
	       c.kind == OSCSIM_CYCLE_FOUND ? "found" :
	       c.kind == OSCSIM_CYCLE_AT_STICK ? "at_stick" : "none",
	       c.r, c.v_max, c.v_min, c.u_min, c.period, c.v_reach, c.evals,
	       c.steps);
	return 0;
}

int oscsim_cmd_simulate(int argc, char **argv)
{
	sim_args_t a;
	oscsim_truth_t tr;
	int rc;

	memset(&a, 0, sizeof(a));
	rc = parse_sim_args(argc, argv, &a);
	if (rc != CLI_OK) {
		return cli_exit_status((cli_result_t)rc);
	}
	if (a.mode == 4) {
		return sim_dimless(&a);
	}
	if (oscsim_params_check(&a.p) != SQ_OK || !(a.p.v0_mps > 0.0) ||
	    !(a.t_end_s > 0.0) || a.dt_s < 0.0 || !(a.rtol > 0.0)) {
		fprintf(stderr, "squeal-sim simulate: parameters out of range (v0 > 0, m, w0, D > 0, ...)\n");
		return 2;
	}
	if (a.mode == 0) {
		oscsim_sim_opts_t o;
		oscsim_sim_result_t res;
		double x0 = a.have_x0 ? a.x0_m : oscsim_steady_x(&a.p) + a.dx_m;

		oscsim_sim_default_opts(&o, a.t_end_s);
		o.rtol = a.rtol;
		o.sample_dt_s = (a.dt_s > 0.0) ? a.dt_s :
				TWO_PI / a.p.omega0_radps / 64.0;
		o.on_sample = print_sample;
		o.on_switch = print_switch;
		printf("kind,t_s,x_m,v_mps,mode\n");
		rc = oscsim_simulate(&a.p, x0, a.xd0_mps, &o, &res);
		if (rc != SQ_OK) {
			fprintf(stderr, "squeal-sim simulate: failed (%d) at t = %g s\n",
				rc, res.t_s);
			return 1;
		}
		fprintf(stderr, "x_s=%.9e steps=%u switches=%u stick_entries=%u first_stick_s=%.9e x=[%.9e,%.9e] v=[%.9e,%.9e]\n",
			oscsim_steady_x(&a.p), res.steps, res.switches,
			res.stick_entries, res.first_stick_s, res.x_min_m,
			res.x_max_m, res.v_min_mps, res.v_max_mps);
		return 0;
	}
	rc = oscsim_truth(&a.p, NULL, 1, &tr);
	if (rc != SQ_OK) {
		fprintf(stderr, "squeal-sim simulate: truth failed (%d)\n", rc);
		return 1;
	}
	if (a.mode == 2) {
		printf("truth=%s ln_q=%.9f s=%.9f linear_growth=%.9f cycle_x=%.9f r=%.9f amplitude_m=%.9e v_reach=%.9f\n",
		       oscsim_truth_name(tr.cls), tr.ln_q, tr.s, tr.growth_ratio,
		       tr.cycle_x, tr.cycle.r, tr.amplitude_m, tr.cycle.v_reach);
		return 0;
	}
	if (tr.cycle.kind != OSCSIM_CYCLE_FOUND) {
		fprintf(stderr, "squeal-sim simulate: no sliding cycle below the stick line (%s)\n",
			oscsim_truth_name(tr.cls));
		return 1;
	}
	if (a.mode == 1) {
		cycle_print_t cp = { &a.p, oscsim_steady_x(&a.p) };

		printf("kind,t_s,x_m,v_mps,mode\n");
		rc = oscsim_cycle_trace(a.p.damping, tr.ln_q, tr.cycle.r,
					TWO_PI / 256.0, print_cycle, &cp);
		if (rc != SQ_OK) {
			fprintf(stderr, "squeal-sim simulate: cycle trace failed (%d)\n", rc);
			return 1;
		}
		return 0;
	}
	{
		oscsim_basin_outcome_t out;
		double t_dec = 0.0;

		rc = oscsim_basin(&a.p, tr.cycle.r, a.basin, 4000U, &out, &t_dec);
		if (rc != SQ_OK) {
			fprintf(stderr, "squeal-sim simulate: basin test failed (%d)\n", rc);
			return 1;
		}
		printf("basin factor=%.6f outcome=%s t_s=%.9e cycle_x=%.9f\n",
		       a.basin, oscsim_basin_name(out), t_dec, tr.cycle_x);
	}
	return 0;
}

/* ---- map ---------------------------------------------------------------- */

static void csv_point(void *ctx, const oscsim_variation_t *var,
		      const oscsim_map_point_t *pt)
{
	FILE *f = ctx;

	fprintf(f, "%s,%.6f,%.6f,%.9f,%.9f,%s,%.9f,%d,%s,%.9f,%s,%.9f,%.9f,%.9f,%s,%s\n",
		var->name, pt->a_spm, pt->v0_mps, pt->ln_q, pt->s,
		oscsim_truth_name(pt->truth), pt->sim_x, pt->linear_grows,
		squeal_model_state_name((squeal_state_t)pt->exact_state),
		pt->exact_x,
		squeal_model_state_name((squeal_state_t)pt->cubic_state),
		pt->cubic_x, pt->ln_q_border, pt->border_dist,
		pt->basin_in < 0 ? "" : oscsim_basin_name((oscsim_basin_outcome_t)pt->basin_in),
		pt->basin_out < 0 ? "" : oscsim_basin_name((oscsim_basin_outcome_t)pt->basin_out));
}

static double pct(uint32_t num, uint32_t den)
{
	return (den == 0U) ? 0.0 : 100.0 * (double)num / (double)den;
}

static void map_report(FILE *f, const oscsim_variation_t *var,
		       const oscsim_map_opts_t *o, const oscsim_map_stats_t *st)
{
	fprintf(f, "brake %s (%s): %u points in %.2f s (%.0f us/point), %u backward revolutions\n",
		var->name, var->what, st->points, st->seconds,
		1e6 * st->seconds / (double)st->points, st->cycle_evals);
	fprintf(f, "  simulated truth: %u unstable, %u bistable, %u stable; %u points farther than %.3g in ln Q from a border\n",
		st->truth_count[OSCSIM_TRUTH_UNSTABLE],
		st->truth_count[OSCSIM_TRUTH_BISTABLE],
		st->truth_count[OSCSIM_TRUTH_STABLE], st->far_points,
		o->border_margin);
	fprintf(f, "  exact: %.2f %% agree (%u disagree: %u under-warn, %u over-warn; %u far from a border; all within %.4f in ln Q); worst cycle error %.3f %% (at ln Q %.3f), %.3f %% off the Hopf border\n",
		pct(st->exact_agree, st->points), st->points - st->exact_agree,
		st->exact_under, st->exact_over, st->exact_far_disagree,
		st->exact_worst_dist, 100.0 * st->exact_amp_err,
		st->exact_amp_err_at_q, 100.0 * st->exact_amp_err_far);
	fprintf(f, "  cubic: %.2f %% agree (%u disagree: %u under-warn, %u over-warn; %u far from a border; all within %.4f in ln Q); worst cycle error %.3f %% (at ln Q %.3f), %.3f %% off the Hopf border\n",
		pct(st->cubic_agree, st->points), st->points - st->cubic_agree,
		st->cubic_under, st->cubic_over, st->cubic_far_disagree,
		st->cubic_worst_dist, 100.0 * st->cubic_amp_err,
		st->cubic_amp_err_at_q, 100.0 * st->cubic_amp_err_far);
	if (st->basin_tested > 0U) {
		fprintf(f, "  basin test at %u bistable points (full oscillator from 0.8 / 1.2 x the exact cycle): %u decay inside and stick-slip outside, %u wrong, %u undecided\n",
			st->basin_tested, st->basin_ok, st->basin_wrong,
			st->basin_undecided);
		fprintf(f, "  the same from 0.8 x the cubic cycle: %u of %u end in stick-slip (its cycle is too large)\n",
			st->basin_cubic_captured, st->basin_cubic_tested);
	}
	if (st->linear_checked > 0U) {
		fprintf(f, "  linear test simulated at %u points: %u disagree with Q <= 1/2 away from the Hopf border\n",
			st->linear_checked, st->linear_mismatch);
	}
}

int oscsim_cmd_map(int argc, char **argv)
{
	oscsim_map_opts_t o;
	const char *brake = "default";
	const char *csv = NULL;
	FILE *csv_f = NULL;
	FILE *rep = stdout;
	bool check = false, list = false, no_linear = false;
	bool have_grid = false, have_na = false, have_nv = false;
	uint32_t grid = 0U, n_a = 0U, n_v = 0U;
	int failed = 0;
	const cli_opt_t opts[] = {
		CLI_OPT_TEXT("brake", &brake, NULL, "NAME",
			     "default, d0.05, d0.1, k2, k0.5, n5000, n20000, or all\n"
			     "(default: default); --list shows them"),
		CLI_OPT_U32("grid", &grid, &have_grid, 1.0, 2000.0, "N",
			    "N x N points (default 100): a = a_max i/N, v0 = v_max j/N"),
		CLI_OPT_U32("na", &n_a, &have_na, 1.0, 2000.0, "N", "points along a (overrides --grid)"),
		CLI_OPT_U32("nv", &n_v, &have_nv, 1.0, 2000.0, "N", "points along v0 (overrides --grid)"),
		CLI_OPT_REAL("a-max", &o.a_max_spm, NULL, 0.0, 20.0, CLI_LO_OPEN, "A",
			     "largest friction slope [s/m] (default 6)"),
		CLI_OPT_REAL("v-max", &o.v_max_mps, NULL, 0.0, 100.0, CLI_LO_OPEN, "V",
			     "largest disc speed [m/s] (default 3)"),
		CLI_OPT_REAL("margin", &o.border_margin, NULL, 0.0, HUGE_VAL, 0U, "M",
			     "'near a border' = within M in ln Q (default 0.01)"),
		CLI_OPT_FLAG("no-linear", 0, &no_linear, "skip the per-point simulation of the linear test"),
		CLI_OPT_U32("basin", &o.basin_every, NULL, 1.0, 1000000.0, "K",
			    "basin test at every K-th bistable point (farther than 0.05\n"
			    "in ln Q from a border): the full oscillator started at 0.8\n"
			    "and 1.2 x the exact model's cycle must decay / stick-slip"),
		CLI_OPT_TEXT("csv", &csv, NULL, "FILE",
			     "every point as CSV ('-' = stdout, the summary then goes\n"
			     "to stderr)"),
		CLI_OPT_FLAG("check", 0, &check,
			     "exit 1 unless the exact criterion agrees at every point\n"
			     "farther than the margin from a border (and the simulated\n"
			     "linear test agrees with Q <= 1/2 there)"),
		CLI_OPT_FLAG("list", 0, &list, "list the brakes and exit"),
	};
	const cli_spec_t spec = {
		.cmd = "map",
		CLI_SPEC_OPTS(opts),
		.synopsis = "squeal-sim map [--brake NAME|all] [--grid N] [--na N] [--nv N]\n"
			    "         [--a-max A] [--v-max V] [--margin M] [--no-linear] [--csv FILE|-]\n"
			    "         [--basin K] [--check] [--list]",
		.description = "Classifies every point of an (a, v0) grid by simulation of the oscillator\n"
			       "(backward-time search for the unstable sliding cycle) and by the firmware\n"
			       "model with the exact and the cubic criterion, and reports how they agree.",
		.closing = "Exit status: 0 done, 1 a brake failed or --check found a disagreement,\n"
			   "2 bad usage.",
	};
	cli_result_t r;
	size_t i;

	oscsim_map_default_opts(&o);
	r = cli_parse(&spec, argc, argv, NULL, NULL);
	if (r != CLI_OK) {
		return cli_exit_status(r);
	}
	if (have_grid) {
		o.n_a = grid;
		o.n_v = grid;
	}
	o.n_a = have_na ? n_a : o.n_a;
	o.n_v = have_nv ? n_v : o.n_v;
	if (no_linear) {
		o.check_linear = 0;
	}
	if (list) {
		for (i = 0; i < oscsim_variation_count(); i++) {
			const oscsim_variation_t *v = oscsim_variation_get(i);

			printf("%-8s %s\n", v->name, v->what);
		}
		return 0;
	}
	if (strcmp(brake, "all") != 0 && oscsim_variation_find(brake) == NULL) {
		return cli_exit_status(cli_usage_error(&spec, "unknown brake '%s' (--list)", brake));
	}
	if (csv != NULL) {
		if (strcmp(csv, "-") == 0) {
			csv_f = stdout;
			rep = stderr;
		} else {
			csv_f = fopen(csv, "w");
			if (csv_f == NULL) {
				fprintf(stderr, "squeal-sim map: cannot write %s: %s\n",
					csv, strerror(errno));
				return 1;
			}
		}
		fprintf(csv_f, "brake,a_spm,v0_mps,ln_q,s,truth,sim_x,linear_grows,exact,exact_x,cubic,cubic_x,ln_q_border,border_dist,basin_in,basin_out\n");
	}
	fprintf(rep, "model build: %s; grid %u x %u, a in (0, %g] s/m, v0 in (0, %g] m/s\n",
		SQUEAL_NUMERIC_NAME, o.n_a, o.n_v, o.a_max_spm, o.v_max_mps);
	for (i = 0; i < oscsim_variation_count(); i++) {
		const oscsim_variation_t *v = oscsim_variation_get(i);
		oscsim_map_stats_t st;
		int rc;

		if (strcmp(brake, "all") != 0 && strcmp(brake, v->name) != 0) {
			continue;
		}
		rc = oscsim_map_run(v, &o, csv_f != NULL ? csv_point : NULL,
				    csv_f, &st);
		if (rc != SQ_OK) {
			fprintf(stderr, "squeal-sim map: brake %s failed (%d)\n",
				v->name, rc);
			failed = 1;
			break;
		}
		map_report(rep, v, &o, &st);
		if (check) {
			int ok = st.exact_far_disagree == 0U &&
				 st.linear_mismatch == 0U && st.basin_wrong == 0U;

			fprintf(rep, "  check %s: %s\n", v->name, ok ? "PASS" : "FAIL");
			if (!ok) {
				failed = 1;
			}
		}
	}
	if (csv_f != NULL && csv_f != stdout) {
		if (fclose(csv_f) != 0) {
			fprintf(stderr, "squeal-sim map: writing %s failed\n", csv);
			failed = 1;
		}
	}
	return failed ? 1 : 0;
}
