/* SPDX-License-Identifier: MIT */
/*
 * squeal-sim classify: one operating point through the firmware's model.
 * squeal-sim sweep: a readable stability table over speed and force.
 */
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "calib.h"
#include "calib_text.h"
#include "cli_args.h"
#include "sim_commands.h"
#include "sim_num.h"
#include "squeal_model.h"
#include "squeal_sigma.h"

/* Vehicle speed for display: v_car = (r_w / r_p) v0, with the wheel and
 * effective pad radius of --calib's corner (its own keys, else the flat
 * ones), without --calib the defaults (0.30 m, 0.12 m) of docs/model.md
 * section 8. */
#define WHEEL_OVER_PAD_RADIUS (0.30 / 0.12)

typedef struct {
	sim_params_d_t params;
	double v0_mps;
	double force_n;
	bool have_v0;
	bool have_force;
	squeal_criterion_t criterion;
	bool have_criterion;
	bool have_model_option;      /* --slope .. --delta-mu given         */
	const char *calib_path;      /* --calib: brake and deviations from it */
	const char *corner;          /* --corner POS: that corner's brake     */
	bool json;
	double wheel_over_pad;       /* r_w / r_p for the vehicle speed       */
} classify_args_t;

static const char *const criterion_names[] = { "exact", "cubic", NULL };

static int classify_parse(int argc, char **argv, classify_args_t *a)
{
	bool model_opt[6] = { false, false, false, false, false, false };
	int criterion = 0;
	const cli_opt_t opts[] = {
		CLI_OPT_ANY_REAL("v0", &a->v0_mps, &a->have_v0, "MPS",
			     "disc surface speed at the pad radius [m/s] (required)"),
		CLI_OPT_ANY_REAL("force", &a->force_n, &a->have_force, "N",
			     "pad normal force [N] (required)"),
		CLI_OPT_ANY_REAL("slope", &a->params.slope_spm, &model_opt[0], "A",
			     "friction slope a [s/m] (default 2)"),
		CLI_OPT_ANY_REAL("damping", &a->params.damping, &model_opt[1], "D",
			     "damping ratio D [-] (default 0.023)"),
		CLI_OPT_ANY_REAL("omega0", &a->params.omega0_radps, &model_opt[2],
			     "W", "natural angular frequency [rad/s] (default 5000)"),
		CLI_OPT_ANY_REAL("mass", &a->params.mass_kg, &model_opt[3], "M",
			     "moving mass m [kg] (default 1)"),
		CLI_OPT_ANY_REAL("mu-inf", &a->params.mu_inf, &model_opt[4], "X",
			     "friction coefficient at high speed (default 0.25)"),
		CLI_OPT_ANY_REAL("delta-mu", &a->params.delta_mu, &model_opt[5], "Y",
			     "mu_0 - mu_inf (default 0.15)"),
		CLI_OPT_CHOICE("criterion", &criterion, &a->have_criterion, criterion_names, "C",
			       "exact (I1(s)/s, default) or cubic (the paper's)"),
		CLI_OPT_TEXT("calib", &a->calib_path, NULL, "FILE",
			     "the brake of a calibration file (its flat keys) with its\n"
			     "standard deviations: also the margin to the border next\n"
			     "to the class in sigmas (docs/uncertainty.md)"),
		CLI_OPT_TEXT("corner", &a->corner, NULL, "POS",
			     "with --calib: the brake of [corner POS] (FL, FR, RL, RR)"),
		CLI_OPT_FLAG("json", 0, &a->json, "one JSON object on stdout"),
	};
	const cli_spec_t spec = {
		.cmd = "classify",
		CLI_SPEC_OPTS(opts),
		.synopsis = "squeal-sim classify --v0 MPS --force N [--slope A] [--damping D]\n"
			    "         [--omega0 W] [--mass M] [--mu-inf X] [--delta-mu Y]\n"
			    "         [--criterion exact|cubic] [--json]\n"
			    "       squeal-sim classify --v0 MPS --force N --calib FILE [--corner POS] [--json]",
		.description = "Classifies one operating point of the friction oscillator as stable,\n"
			       "bistable, unstable or not sliding (docs/model.md), with its margins.",
		.closing = "The vehicle speed shown is v0 x wheel radius / pad radius (--calib: its\n"
			   "corner's radii; else 0.30 m / 0.12 m).\n"
			   "Exit status: 0 classified, 1 input outside the model's domain\n"
			   "(state \"invalid\") or a --calib file that does not load and set up\n"
			   "(one line FILE:LINE: reason), 2 bad usage.",
	};
	cli_result_t r;
	size_t i;

	memset(a, 0, sizeof(*a));
	a->wheel_over_pad = WHEEL_OVER_PAD_RADIUS;
	sim_params_default(&a->params);
	r = cli_parse(&spec, argc, argv, NULL, NULL);
	if (r != CLI_OK) {
		return r;
	}
	a->criterion = (criterion == 1) ? SQUEAL_CRITERION_CUBIC : SQUEAL_CRITERION_EXACT;
	for (i = 0U; i < CLI_COUNT(model_opt); i++) {
		a->have_model_option = a->have_model_option || model_opt[i];
	}
	if (!a->have_v0 || !a->have_force) {
		return cli_usage_error(&spec, "--v0 and --force are required (see --help)");
	}
	if ((a->calib_path != NULL) && a->have_model_option) {
		return cli_usage_error(&spec, "--calib gives the brake; leave out --slope .. --delta-mu");
	}
	if ((a->corner != NULL) && (a->calib_path == NULL)) {
		return cli_usage_error(&spec, "--corner needs --calib");
	}
	return CLI_OK;
}

/* The brake and its deviations from --calib (criterion too, unless given),
 * and its corner's wheel over pad radius. 0; 1 the file is refused; 2
 * --corner is not one of its corners. */
static int load_brake(classify_args_t *a, squeal_params_t *params, squeal_param_sd_t *sd)
{
	calib_t cal;
	calib_corner_t brake;
	char err[300];

	if (calib_text_load(a->calib_path, &cal, err, sizeof(err)) != SQ_OK) {
		fprintf(stderr, "squeal-sim classify: %s\n", err);
		return 1;  /* the file does not load or set up: exit 1 */
	}
	if (calib_text_brake(&cal, a->corner, &brake, err, sizeof(err)) != 0) {
		fprintf(stderr, "squeal-sim classify: %s: %s\n", a->calib_path, err);
		return 2;  /* --corner names a corner the file lacks: usage */
	}
	calib_corner_params(&brake, params);
	calib_corner_sd(&brake, sd);
	if (brake.pad_radius_um != 0U) { /* calib_validate keeps it > 0; no division by 0 */
		a->wheel_over_pad = (double)brake.wheel_radius_um / (double)brake.pad_radius_um;
	}
	if (!a->have_criterion) {
		a->criterion = (squeal_criterion_t)brake.criterion;
	}
	return 0;
}

/* A field as a JSON number, or null where the model gives none (never the
 * last field of the object: a comma follows). */
static void json_field(const char *key, bool present, double value)
{
	if (present && isfinite(value)) {
		printf("  \"%s\": %.9g,\n", key, value);
	} else {
		printf("  \"%s\": null,\n", key);
	}
}

typedef struct {
	double ln_q;
	double hopf_v0_mps;
	double hopf_margin_mps;
	double hopf_force_n;
	double cycle_x;
	double lc_amplitude_m;
	double trigger_velocity_mps;
	double basin_ratio;
} result_d_t;

static void result_to_double(const squeal_result_t *r, result_d_t *d)
{
	d->ln_q = sim_num_to_double(r->ln_q, SQUEAL_Q_LNQ);
	d->hopf_v0_mps = sim_num_to_double(r->hopf_v0_mps, SQUEAL_Q_V0);
	d->hopf_margin_mps = sim_num_to_double(r->hopf_margin_mps, SQUEAL_Q_V0);
	d->hopf_force_n = sim_num_to_double(r->hopf_force_n, SQUEAL_Q_FORCE);
	d->cycle_x = sim_num_to_double(r->cycle_x, SQUEAL_Q_CYCLE_X);
	d->lc_amplitude_m = sim_num_to_double(r->lc_amplitude_um, SQUEAL_Q_AMPL_UM) * 1e-6;
	d->trigger_velocity_mps = sim_num_to_double(r->trigger_velocity_mps, SQUEAL_Q_V0);
	d->basin_ratio = sim_num_to_double(r->basin_ratio, SQUEAL_Q_RATIO);
}

static bool has(const squeal_result_t *r, uint32_t has_flag, uint32_t sat_flag)
{
	return ((r->flags & has_flag) != 0U) && ((r->flags & sat_flag) == 0U);
}

/* The margin in sigmas, or none (NAN): no deviations, no border, no class. */
static double margin_of(const squeal_sigma_result_t *sig, bool have_sig)
{
	if (!have_sig || (sig->margin_sigma >= SQUEAL_SIGMA_MARGIN_MAX)) {
		return (double)NAN;
	}
	return sim_num_to_double(sig->margin_sigma, SQUEAL_Q_MARGIN);
}

/* The model's numbers, null where it gives none. */
static void json_model_fields(const squeal_result_t *r, const result_d_t *d, double margin)
{
	const bool lnq = has(r, SQUEAL_HAS_LNQ, 0U);
	const struct {
		const char *key;
		bool present;
		double value;
	} fields[] = {
		{ "q", lnq, exp(d->ln_q) },
		{ "ln_q", lnq, d->ln_q },
		{ "hopf_v0_mps", has(r, SQUEAL_HAS_HOPF_V0, SQUEAL_SAT_HOPF_V0), d->hopf_v0_mps },
		{ "hopf_margin_mps", has(r, SQUEAL_HAS_HOPF_V0, SQUEAL_SAT_HOPF_V0), d->hopf_margin_mps },
		{ "hopf_force_n", has(r, SQUEAL_HAS_HOPF_FORCE, SQUEAL_SAT_HOPF_FORCE), d->hopf_force_n },
		{ "cycle_x", has(r, SQUEAL_HAS_CYCLE, SQUEAL_SAT_CYCLE_X), d->cycle_x },
		{ "lc_amplitude_m", has(r, SQUEAL_HAS_CYCLE, SQUEAL_SAT_AMPLITUDE), d->lc_amplitude_m },
		{ "trigger_velocity_mps", has(r, SQUEAL_HAS_CYCLE, SQUEAL_SAT_TRIGGER),
		  d->trigger_velocity_mps },
		{ "basin_ratio", has(r, SQUEAL_HAS_BASIN, SQUEAL_SAT_BASIN), d->basin_ratio },
		{ "border_margin_sigma", !isnan(margin), margin },
	};
	size_t i;

	for (i = 0U; i < sizeof(fields) / sizeof(fields[0]); i++) {
		json_field(fields[i].key, fields[i].present, fields[i].value);
	}
}

static void print_json(const classify_args_t *a, const squeal_result_t *r, double margin)
{
	result_d_t d;

	result_to_double(r, &d);
	printf("{\n");
	printf("  \"state\": \"%s\",\n", squeal_model_state_name(r->state));
	printf("  \"criterion\": \"%s\",\n",
	       (a->criterion == SQUEAL_CRITERION_CUBIC) ? "cubic" : "exact");
	printf("  \"numeric\": \"%s\",\n", SQUEAL_NUMERIC_NAME);
	printf("  \"v0_mps\": %.9g,\n", a->v0_mps);
	printf("  \"force_n\": %.9g,\n", a->force_n);
	printf("  \"vehicle_kmh\": %.9g,\n", a->v0_mps * a->wheel_over_pad * 3.6);
	json_model_fields(r, &d, margin);
	printf("  \"saturated\": %s\n", ((r->flags & 0xff00U) != 0U) ? "true" : "false");
	printf("}\n");
}

static const char *state_explanation(squeal_state_t state)
{
	switch (state) {
	case SQUEAL_STATE_STABLE:
		return "steady sliding is safe up to the stick line";
	case SQUEAL_STATE_BISTABLE:
		return "stable, but a disturbance above the trigger velocity tips it into stick-slip";
	case SQUEAL_STATE_UNSTABLE:
		return "steady sliding is unstable: grows into stick-slip (squeal)";
	case SQUEAL_STATE_NOT_SLIDING:
		return "no sliding (standstill or no pad force)";
	default:
		return "input outside the model's domain";
	}
}

static void print_text(const classify_args_t *a, const squeal_result_t *r, double margin)
{
	result_d_t d;

	result_to_double(r, &d);
	printf("operating point  v0 = %.4g m/s (vehicle %.1f km/h), N = %.6g N\n",
	       a->v0_mps, a->v0_mps * a->wheel_over_pad * 3.6, a->force_n);
	printf("state            %s: %s\n", squeal_model_state_name(r->state),
	       state_explanation(r->state));
	if (has(r, SQUEAL_HAS_LNQ, 0U)) {
		printf("Q                %.6g (ln Q = %.6g; unstable at Q <= 0.5)\n",
		       exp(d.ln_q), d.ln_q);
	}
	if (has(r, SQUEAL_HAS_HOPF_V0, SQUEAL_SAT_HOPF_V0)) {
		printf("Hopf speed       v_H = %.6g m/s, margin v0 - v_H = %+.6g m/s\n",
		       d.hopf_v0_mps, d.hopf_margin_mps);
	} else if (has(r, SQUEAL_HAS_LNQ, 0U)) {
		printf("Hopf speed       none: steady sliding is stable at every speed\n");
	}
	if (has(r, SQUEAL_HAS_HOPF_FORCE, SQUEAL_SAT_HOPF_FORCE)) {
		printf("Hopf force       N_H = %.6g N, margin N_H - N = %+.6g N\n",
		       d.hopf_force_n, d.hopf_force_n - a->force_n);
	}
	if (has(r, SQUEAL_HAS_CYCLE, SQUEAL_SAT_AMPLITUDE)) {
		printf("unstable cycle   A_LC = %.6g um, trigger velocity %.6g m/s\n",
		       d.lc_amplitude_m * 1e6, d.trigger_velocity_mps);
	}
	if (has(r, SQUEAL_HAS_BASIN, SQUEAL_SAT_BASIN)) {
		printf("basin ratio      rho = %.6g (< 1: cycle below the stick line)\n",
		       d.basin_ratio);
	}
	if (!isnan(margin)) {
		printf("border margin    %.3g sigma to the border next to this class\n", margin);
	}
}

int cmd_classify(int argc, char **argv)
{
	classify_args_t a;
	squeal_params_t params;
	squeal_param_sd_t sd;
	squeal_point_t point;
	squeal_result_t result;
	squeal_sigma_result_t sig;
	bool have_sig = false;
	int rc;

	rc = classify_parse(argc, argv, &a);
	if (rc != CLI_OK) {
		return cli_exit_status((cli_result_t)rc);
	}
	squeal_sigma_sd_zero(&sd);
	if (a.calib_path != NULL) {
		rc = load_brake(&a, &params, &sd);
		if (rc != 0) {
			return rc;
		}
	} else {
		/* A value the fixed build cannot represent saturates; the model
		 * then rejects it like any other value outside its domain. */
		(void)sim_params_to_model(&a.params, &params);
	}
	(void)sim_point_to_model(a.v0_mps, a.force_n, &point);
	rc = squeal_model_classify(&params, &point, a.criterion, &result);
	if ((rc == SQ_OK) && (a.calib_path != NULL)) {
		/* the margin of the class reported, on the borders of the
		 * criterion classified with (as the monitor's corner does) */
		squeal_result_t again;

		have_sig = (squeal_sigma_classify(&params, &sd, &point, a.criterion, &again,
						  &sig) == SQ_OK) &&
			   (squeal_sigma_margin(&sig, result.state, &sig.margin_sigma) == SQ_OK);
	}
	if (a.json) {
		print_json(&a, &result, margin_of(&sig, have_sig));
	} else {
		print_text(&a, &result, margin_of(&sig, have_sig));
	}
	if (rc != SQ_OK) {
		fprintf(stderr,
			"squeal-sim classify: input outside the model's domain "
			"(see firmware/model/squeal_model.h): mass (0,10000] kg, omega0 (0,500000] rad/s, "
			"damping (0,1], mu-inf [0,1.5], delta-mu [-1.5,1.5] with mu-inf+delta-mu >= 0, "
			"slope [0,20] s/m, v0 [0,100] m/s, force [0,500000] N\n");
		return 1;
	}
	return 0;
}

/* ---- sweep ---------------------------------------------------------------- */

static char state_glyph(squeal_state_t s)
{
	switch (s) {
	case SQUEAL_STATE_STABLE:
		return '.';
	case SQUEAL_STATE_BISTABLE:
		return 'b';
	case SQUEAL_STATE_UNSTABLE:
		return 'U';
	case SQUEAL_STATE_NOT_SLIDING:
		return '-';
	default:
		return '?';
	}
}

int cmd_sweep(int argc, char **argv)
{
	static const double forces_n[] = { 2000.0, 5000.0, 9000.0, 15000.0, 20000.0, 30000.0 };
	const int n_v0 = 61;
	sim_params_d_t pd;
	squeal_params_t params;
	size_t fi;
	int crit;

	static const cli_spec_t spec = {
		.cmd = "sweep",
		.synopsis = "squeal-sim sweep",
		.description = "Prints the stability of the default brake over disc speed 0..3 m/s and\n"
			       "pad force 2..30 kN, for both criteria.",
	};
	const cli_result_t cr = cli_parse(&spec, argc, argv, NULL, NULL);

	if (cr != CLI_OK) {
		return cli_exit_status(cr);
	}
	sim_params_default(&pd);
	if (sim_params_to_model(&pd, &params) != 0) {
		return 1;
	}
	printf("Stability of the default brake (a = 2 s/m, D = 0.023, w0 = 5000 rad/s, m = 1 kg,\n"
	       "mu_inf = 0.25, dmu = 0.15); numeric build: %s\n"
	       "U unstable (squeal)   b bistable (a disturbance can start it)   . stable   - not sliding\n",
	       SQUEAL_NUMERIC_NAME);
	for (crit = 0; crit < 2; crit++) {
		const squeal_criterion_t c = (crit == 0) ? SQUEAL_CRITERION_EXACT : SQUEAL_CRITERION_CUBIC;
		int i;

		printf("\ncriterion %s\n", (crit == 0) ? "exact (default)" : "cubic (paper)");
		printf("%9s  v0 = 0 m/s %*s 3 m/s   v_H [m/s]\n", "force", n_v0 - 16, "");
		for (fi = 0; fi < sizeof(forces_n) / sizeof(forces_n[0]); fi++) {
			char row[128];
			double vh = NAN;

			for (i = 0; i < n_v0; i++) {
				squeal_point_t pt;
				squeal_result_t r;

				(void)sim_point_to_model(3.0 * i / (n_v0 - 1), forces_n[fi], &pt);
				(void)squeal_model_classify(&params, &pt, c, &r);
				row[i] = state_glyph(r.state);
				if ((r.flags & SQUEAL_HAS_HOPF_V0) != 0U) {
					vh = sim_num_to_double(r.hopf_v0_mps, SQUEAL_Q_V0);
				}
			}
			row[n_v0] = '\0';
			if (isnan(vh)) {
				printf("%7.0f N  %s   none\n", forces_n[fi], row);
			} else {
				printf("%7.0f N  %s   %.4f\n", forces_n[fi], row, vh);
			}
		}
	}
	return 0;
}
