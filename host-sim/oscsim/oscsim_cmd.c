/* SPDX-License-Identifier: MIT */
/*
 * squeal-sim map / simulate: the simulator's command-line faces, see
 * oscsim_cmd.h.
 */
#include "oscsim_cmd.h"

#include <errno.h>
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "oscsim.h"
#include "oscsim_map.h"
#include "squeal_model.h"

#define TWO_PI 6.28318530717958647692

static int parse_num(const char *cmd, const char *flag, const char *text,
		     double *out)
{
	char *end = NULL;
	double v;

	errno = 0;
	v = strtod(text, &end);
	if (end == text || *end != '\0' || errno == ERANGE || !isfinite(v)) {
		fprintf(stderr, "squeal-sim %s: %s needs a number, got '%s'\n",
			cmd, flag, text);
		return -1;
	}
	*out = v;
	return 0;
}

static int parse_count(const char *cmd, const char *flag, const char *text,
		       uint32_t max, uint32_t *out)
{
	double v;

	if (parse_num(cmd, flag, text, &v) != 0) {
		return -1;
	}
	if (v < 1.0 || v > (double)max || v != floor(v)) {
		fprintf(stderr, "squeal-sim %s: %s must be a whole number in 1..%u\n",
			cmd, flag, max);
		return -1;
	}
	*out = (uint32_t)v;
	return 0;
}

/* ---- simulate ----------------------------------------------------------- */

static void simulate_usage(FILE *f)
{
	fprintf(f,
		"usage: squeal-sim simulate [--v0 MPS] [--force N] [--slope A] [--damping D]\n"
		"         [--omega0 W] [--mass M] [--mu-inf X] [--delta-mu Y]\n"
		"         [--t-end S] [--dt S] [--dx M | --x0 M] [--xd0 MPS] [--rtol R]\n"
		"         [--cycle | --truth | --basin F | --dimless --q Q [--s S] [--plain]]\n\n"
		"Simulates the friction oscillator with sliding and sticking (Dormand-Prince\n"
		"5(4), event switching at relative velocity 0). Defaults: the paper's brake\n"
		"(shared/model.md section 8) at a = 2 s/m, v0 = 1 m/s, N = 9000 N.\n\n"
		"  (default)   trajectory from x = x_s + dx, x' = xd0 for t-end seconds:\n"
		"              CSV kind,t_s,x_m,v_mps,mode on stdout, kind 'sample' every dt\n"
		"              and 'switch' at each change of mode (slip, slip_neg, stick)\n"
		"  --cycle     the unstable sliding cycle (backward-time integration) in the\n"
		"              same CSV with kind 'cycle'; exit 1 when there is none\n"
		"  --truth     ground-truth class by simulation, key=value\n"
		"  --basin F   start at F times the cycle (on x' = 0) and report whether the\n"
		"              oscillator decays to steady sliding or is captured by stick-slip\n"
		"  --dimless   the cycle of u'' + 2 D u' + u = (D/Q)(exp(u') - 1) for --damping\n"
		"              and --q, stick line --s (default none): key=value; --plain uses\n"
		"              brute-force backward integration instead of the return-map search\n"
		"  --t-end S   simulated time [s] (default 0.05)\n"
		"  --dt S      sample interval [s] (default one 64th of 2 pi / w0)\n"
		"  --rtol R    integrator tolerance (default 1e-9)\n");
}

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
	int have_x0;
	int have_q;
	int mode; /* 0 trajectory, 1 cycle, 2 truth, 3 basin, 4 dimless */
	int plain;
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
	enum {
		O_V0 = 256, O_FORCE, O_SLOPE, O_DAMP, O_OMEGA, O_MASS, O_MUI,
		O_DMU, O_TEND, O_DT, O_DX, O_X0, O_XD0, O_RTOL, O_CYCLE,
		O_TRUTH, O_BASIN, O_DIMLESS, O_Q, O_S, O_PLAIN
	};
	static const struct option options[] = {
		{ "v0", required_argument, NULL, O_V0 },
		{ "force", required_argument, NULL, O_FORCE },
		{ "slope", required_argument, NULL, O_SLOPE },
		{ "damping", required_argument, NULL, O_DAMP },
		{ "omega0", required_argument, NULL, O_OMEGA },
		{ "mass", required_argument, NULL, O_MASS },
		{ "mu-inf", required_argument, NULL, O_MUI },
		{ "delta-mu", required_argument, NULL, O_DMU },
		{ "t-end", required_argument, NULL, O_TEND },
		{ "dt", required_argument, NULL, O_DT },
		{ "dx", required_argument, NULL, O_DX },
		{ "x0", required_argument, NULL, O_X0 },
		{ "xd0", required_argument, NULL, O_XD0 },
		{ "rtol", required_argument, NULL, O_RTOL },
		{ "cycle", no_argument, NULL, O_CYCLE },
		{ "truth", no_argument, NULL, O_TRUTH },
		{ "basin", required_argument, NULL, O_BASIN },
		{ "dimless", no_argument, NULL, O_DIMLESS },
		{ "q", required_argument, NULL, O_Q },
		{ "s", required_argument, NULL, O_S },
		{ "plain", no_argument, NULL, O_PLAIN },
		{ "help", no_argument, NULL, 'h' },
		{ NULL, 0, NULL, 0 }
	};
	int opt;

	oscsim_default_params(&a->p);
	a->t_end_s = 0.05;
	a->dt_s = 0.0;
	a->rtol = 1e-9;
	a->s = (double)INFINITY;
	optind = 1;
	opterr = 0;
	while ((opt = getopt_long(argc, argv, "h", options, NULL)) != -1) {
		double *dst = NULL;

		switch (opt) {
		case 'h':
			simulate_usage(stdout);
			return 1;
		case O_V0:
			dst = &a->p.v0_mps;
			break;
		case O_FORCE:
			dst = &a->p.force_n;
			break;
		case O_SLOPE:
			dst = &a->p.slope_spm;
			break;
		case O_DAMP:
			dst = &a->p.damping;
			break;
		case O_OMEGA:
			dst = &a->p.omega0_radps;
			break;
		case O_MASS:
			dst = &a->p.mass_kg;
			break;
		case O_MUI:
			dst = &a->p.mu_inf;
			break;
		case O_DMU:
			dst = &a->p.delta_mu;
			break;
		case O_TEND:
			dst = &a->t_end_s;
			break;
		case O_DT:
			dst = &a->dt_s;
			break;
		case O_DX:
			dst = &a->dx_m;
			break;
		case O_X0:
			dst = &a->x0_m;
			a->have_x0 = 1;
			break;
		case O_XD0:
			dst = &a->xd0_mps;
			break;
		case O_RTOL:
			dst = &a->rtol;
			break;
		case O_CYCLE:
			a->mode = 1;
			break;
		case O_TRUTH:
			a->mode = 2;
			break;
		case O_BASIN:
			a->mode = 3;
			dst = &a->basin;
			break;
		case O_DIMLESS:
			a->mode = 4;
			break;
		case O_Q:
			dst = &a->q;
			a->have_q = 1;
			break;
		case O_S:
			dst = &a->s;
			break;
		case O_PLAIN:
			a->plain = 1;
			break;
		default:
			fprintf(stderr, "squeal-sim simulate: unknown or incomplete option '%s'\n",
				argv[optind - 1]);
			return -1;
		}
		if (dst != NULL &&
		    parse_num("simulate", argv[optind - 1], optarg, dst) != 0) {
			return -1;
		}
	}
	if (optind != argc) {
		fprintf(stderr, "squeal-sim simulate: unexpected argument '%s'\n",
			argv[optind]);
		return -1;
	}
	return 0;
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
	if (rc != 0) {
		if (rc < 0) {
			simulate_usage(stderr);
			return 2;
		}
		return 0;
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

static void map_usage(FILE *f)
{
	fprintf(f,
		"usage: squeal-sim map [--brake NAME|all] [--grid N] [--na N] [--nv N]\n"
		"         [--a-max A] [--v-max V] [--margin M] [--no-linear] [--csv FILE|-]\n"
		"         [--basin K] [--check] [--list]\n\n"
		"Classifies every point of an (a, v0) grid by simulation of the oscillator\n"
		"(backward-time search for the unstable sliding cycle) and by the firmware\n"
		"model with the exact and the cubic criterion, and reports how they agree.\n\n"
		"  --brake NAME  default, d0.05, d0.1, k2, k0.5, n5000, n20000, or all\n"
		"                (default: default); --list shows them\n"
		"  --grid N      N x N points (default 100): a = a_max i/N, v0 = v_max j/N\n"
		"  --a-max A     largest friction slope [s/m] (default 6)\n"
		"  --v-max V     largest disc speed [m/s] (default 3)\n"
		"  --margin M    'near a border' = within M in ln Q (default 0.01)\n"
		"  --no-linear   skip the per-point simulation of the linear test\n"
		"  --basin K     basin test at every K-th bistable point (farther than 0.05\n"
		"                in ln Q from a border): the full oscillator started at 0.8\n"
		"                and 1.2 x the exact model's cycle must decay / stick-slip\n"
		"  --csv FILE    every point as CSV ('-' = stdout, the summary then goes\n"
		"                to stderr)\n"
		"  --check       exit 1 unless the exact criterion agrees at every point\n"
		"                farther than the margin from a border (and the simulated\n"
		"                linear test agrees with Q <= 1/2 there)\n");
}

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
	enum {
		O_BRAKE = 256, O_GRID, O_NA, O_NV, O_AMAX, O_VMAX, O_MARGIN,
		O_NOLIN, O_CSV, O_CHECK, O_LIST, O_BASIN
	};
	static const struct option options[] = {
		{ "brake", required_argument, NULL, O_BRAKE },
		{ "grid", required_argument, NULL, O_GRID },
		{ "na", required_argument, NULL, O_NA },
		{ "nv", required_argument, NULL, O_NV },
		{ "a-max", required_argument, NULL, O_AMAX },
		{ "v-max", required_argument, NULL, O_VMAX },
		{ "margin", required_argument, NULL, O_MARGIN },
		{ "no-linear", no_argument, NULL, O_NOLIN },
		{ "csv", required_argument, NULL, O_CSV },
		{ "check", no_argument, NULL, O_CHECK },
		{ "list", no_argument, NULL, O_LIST },
		{ "basin", required_argument, NULL, O_BASIN },
		{ "help", no_argument, NULL, 'h' },
		{ NULL, 0, NULL, 0 }
	};
	oscsim_map_opts_t o;
	const char *brake = "default";
	const char *csv = NULL;
	FILE *csv_f = NULL;
	FILE *rep = stdout;
	int check = 0, failed = 0, opt;
	size_t i;

	oscsim_map_default_opts(&o);
	optind = 1;
	opterr = 0;
	while ((opt = getopt_long(argc, argv, "h", options, NULL)) != -1) {
		int bad = 0;

		switch (opt) {
		case 'h':
			map_usage(stdout);
			return 0;
		case O_BRAKE:
			brake = optarg;
			break;
		case O_GRID:
			bad = parse_count("map", "--grid", optarg, 2000U, &o.n_a);
			o.n_v = o.n_a;
			break;
		case O_NA:
			bad = parse_count("map", "--na", optarg, 2000U, &o.n_a);
			break;
		case O_NV:
			bad = parse_count("map", "--nv", optarg, 2000U, &o.n_v);
			break;
		case O_AMAX:
			bad = parse_num("map", "--a-max", optarg, &o.a_max_spm) ||
			      !(o.a_max_spm > 0.0 && o.a_max_spm <= 20.0);
			break;
		case O_VMAX:
			bad = parse_num("map", "--v-max", optarg, &o.v_max_mps) ||
			      !(o.v_max_mps > 0.0 && o.v_max_mps <= 100.0);
			break;
		case O_MARGIN:
			bad = parse_num("map", "--margin", optarg, &o.border_margin) ||
			      !(o.border_margin >= 0.0);
			break;
		case O_NOLIN:
			o.check_linear = 0;
			break;
		case O_CSV:
			csv = optarg;
			break;
		case O_BASIN:
			bad = parse_count("map", "--basin", optarg, 1000000U,
					  &o.basin_every);
			break;
		case O_CHECK:
			check = 1;
			break;
		case O_LIST:
			for (i = 0; i < oscsim_variation_count(); i++) {
				const oscsim_variation_t *v = oscsim_variation_get(i);

				printf("%-8s %s\n", v->name, v->what);
			}
			return 0;
		default:
			fprintf(stderr, "squeal-sim map: unknown or incomplete option '%s'\n",
				argv[optind - 1]);
			bad = 1;
			break;
		}
		if (bad) {
			map_usage(stderr);
			return 2;
		}
	}
	if (optind != argc) {
		fprintf(stderr, "squeal-sim map: unexpected argument '%s'\n", argv[optind]);
		return 2;
	}
	if (strcmp(brake, "all") != 0 && oscsim_variation_find(brake) == NULL) {
		fprintf(stderr, "squeal-sim map: unknown brake '%s' (--list)\n", brake);
		return 2;
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
