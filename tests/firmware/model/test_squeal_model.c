/* SPDX-License-Identifier: MIT */
/*
 * Golden-vector test of firmware/model against the independent Python
 * reference (tests/support/reference/squeal_reference.py, written from docs/model.md with
 * scipy). Compiled twice: float build (build/test/tests/firmware/model/test_squeal_model) and fixed build
 * (build/test-fixed/tests/firmware/model/test_squeal_model). Reads tests/support/golden/model_vectors.csv (or the
 * file named by argv[1]) at run time.
 *
 * Tolerances (why each bound is what it is):
 *   REL: relative error on every value: 1e-5 float, 1e-3 fixed (the brief).
 *   DLNQ: absolute uncertainty of ln Q. ln Q is a sum of six logarithms and
 *     s = a v0, each of which a float build can only hold to half an ulp of
 *     its own size, so its error grows with L = s + sum |ln input|:
 *       float: 1e-6 + 8 * 2^-24 * L (1e-6 for the ln approximation itself,
 *              8 half-ulp roundings over the 7 terms and the sums);
 *       fixed: 2^-12 (16 LSB of ln_q's Q16) + 1e-6 * L.
 *     Every other value is a function of ln Q, so near zero its error is
 *     what DLNQ becomes through that function (absolute, "near zero" bound):
 *   v_H = ln r / a and the margin v0 - v_H: DLNQ / a absolute (v_H -> 0 as
 *     ln r -> 0, where no relative bound can hold);
 *   N_H = e^(...): relative REL + DLNQ (never near zero);
 *   cycle x: dx = min(2 K DLNQ, 2 sqrt(8 DLNQ)), K = dx/dlnQ, which is
 *     I1(x)/I2(x) <= 1 + 4/x (exact) or x/2 + 4/x (cubic); near the Hopf
 *     border x ~ sqrt(8 (ln Q - ln 1/2)), so x itself is only known to
 *     sqrt(8 DLNQ) there; A_LC, trigger and basin are x times an exact
 *     factor (1e6/(a w0), 1/a, 1/s) and get dx times that factor;
 *   plus 2 LSB of the field's Q-format in the fixed build, FLT_MIN in the
 *   float build (below the normal range a float has no relative precision).
 * The class must equal the reference wherever border_dist > 1e-3 (closer,
 * any of stable/bistable/unstable is accepted, but the flags must agree
 * with the class returned).
 */
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "sq_num.h"
#include "squeal_model.h"

/* math.h defines NAN and INFINITY as float constants. */
#define D_NAN ((double)NAN)
#define D_INF ((double)INFINITY)

#define CLASS_BORDER_TOL 1e-3
#define MAX_REPORTS 40

#if defined(SQUEAL_NUMERIC_FIXED)
#define REL_TOL 1e-3
#else
#define REL_TOL 1e-5
#endif

enum col {
	C_ID, C_TAG, C_VARIANT, C_CRIT,
	C_V0, C_FORCE, C_SLOPE, C_DAMPING, C_OMEGA0, C_MASS, C_MU_INF, C_DMU,
	C_STATE, C_LNQ, C_LNR, C_HOPF_V0, C_HOPF_MARGIN, C_HOPF_FORCE,
	C_CYCLE_X, C_AMPL, C_TRIGGER, C_BASIN, C_BORDER,
	C_COUNT
};

static const char *const col_names[C_COUNT] = {
	"id", "tag", "variant", "criterion",
	"v0", "force", "slope", "damping", "omega0", "mass", "mu_inf", "delta_mu",
	"state", "ln_q", "ln_r", "hopf_v0", "hopf_margin", "hopf_force",
	"cycle_x", "lc_amplitude_um", "trigger_v", "basin_ratio", "border_dist",
};

typedef struct {
	long id;
	char tag[24];
	char variant[8];
	squeal_criterion_t criterion;
	double in[8]; /* C_V0 .. C_DMU */
	squeal_state_t state;
	double val[C_COUNT];  /* numeric columns; D_NAN where empty */
	bool has[C_COUNT];    /* column not empty */
} vec_t;

/* Output fields checked against the reference. */
enum fld {
	F_LNQ, F_HOPF_V0, F_HOPF_MARGIN, F_HOPF_FORCE, F_CYCLE_X, F_AMPL,
	F_TRIGGER, F_BASIN, F_COUNT
};

typedef struct {
	const char *name;
	int col;
	int q;
	uint32_t has_flag;
	uint32_t sat_flag; /* 0: cannot saturate */
	size_t offset;
} field_t;

static const field_t fields[F_COUNT] = {
	{ "ln_q", C_LNQ, SQUEAL_Q_LNQ, SQUEAL_HAS_LNQ, 0U,
	  offsetof(squeal_result_t, ln_q) },
	{ "hopf_v0_mps", C_HOPF_V0, SQUEAL_Q_V0, SQUEAL_HAS_HOPF_V0,
	  SQUEAL_SAT_HOPF_V0, offsetof(squeal_result_t, hopf_v0_mps) },
	{ "hopf_margin_mps", C_HOPF_MARGIN, SQUEAL_Q_V0, SQUEAL_HAS_HOPF_V0,
	  SQUEAL_SAT_HOPF_V0, offsetof(squeal_result_t, hopf_margin_mps) },
	{ "hopf_force_n", C_HOPF_FORCE, SQUEAL_Q_FORCE, SQUEAL_HAS_HOPF_FORCE,
	  SQUEAL_SAT_HOPF_FORCE, offsetof(squeal_result_t, hopf_force_n) },
	{ "cycle_x", C_CYCLE_X, SQUEAL_Q_CYCLE_X, SQUEAL_HAS_CYCLE,
	  SQUEAL_SAT_CYCLE_X, offsetof(squeal_result_t, cycle_x) },
	{ "lc_amplitude_um", C_AMPL, SQUEAL_Q_AMPL_UM, SQUEAL_HAS_CYCLE,
	  SQUEAL_SAT_AMPLITUDE, offsetof(squeal_result_t, lc_amplitude_um) },
	{ "trigger_velocity_mps", C_TRIGGER, SQUEAL_Q_V0, SQUEAL_HAS_CYCLE,
	  SQUEAL_SAT_TRIGGER, offsetof(squeal_result_t, trigger_velocity_mps) },
	{ "basin_ratio", C_BASIN, SQUEAL_Q_RATIO, SQUEAL_HAS_BASIN,
	  SQUEAL_SAT_BASIN, offsetof(squeal_result_t, basin_ratio) },
};

static const int input_q[8] = {
	SQUEAL_Q_V0, SQUEAL_Q_FORCE, SQUEAL_Q_SLOPE, SQUEAL_Q_DAMPING,
	SQUEAL_Q_OMEGA0, SQUEAL_Q_MASS, SQUEAL_Q_MU, SQUEAL_Q_MU,
};

/* Findings of the one pass over the vectors, asserted by separate tests. */
enum fail_kind {
	K_STATUS, K_CLASS, K_FLAGS, K_VALUE, K_SAT, K_INVALID, K_COUNT
};
static const char *const kind_names[K_COUNT] = {
	"return code", "class", "HAS flags", "value", "SAT flag", "invalid output",
};

typedef struct {
	vec_t *vecs;
	size_t n_vecs;
	size_t n_run;
	size_t n_class_checked;
	size_t n_values_checked[F_COUNT];
	size_t n_sat_seen[F_COUNT];
	size_t fails[K_COUNT];
	size_t reports;
	double max_rel[F_COUNT];
	long max_rel_id[F_COUNT];
	double max_ratio[F_COUNT]; /* error / tolerance */
	long max_ratio_id[F_COUNT];
	double max_abs[F_COUNT];
	double max_rel_dom[F_COUNT]; /* rel err where the REL part dominates tol */
	long max_rel_dom_id[F_COUNT];
} run_t;

static run_t g_run;

static const char *csv_path = "tests/support/golden/model_vectors.csv";

static bool parse_state(const char *s, squeal_state_t *st)
{
	static const struct {
		const char *name;
		squeal_state_t st;
	} names[] = {
		{ "stable", SQUEAL_STATE_STABLE },
		{ "bistable", SQUEAL_STATE_BISTABLE },
		{ "unstable", SQUEAL_STATE_UNSTABLE },
		{ "not_sliding", SQUEAL_STATE_NOT_SLIDING },
		{ "invalid", SQUEAL_STATE_INVALID },
	};
	size_t i;

	for (i = 0; i < sizeof(names) / sizeof(names[0]); i++) {
		if (strcmp(s, names[i].name) == 0) {
			*st = names[i].st;
			return true;
		}
	}
	return false;
}

/* Splits line at commas in place; returns the number of fields. */
static int split(char *line, char **out, int max)
{
	int n = 0;
	char *p = line;

	for (;;) {
		if (n == max) {
			return -1;
		}
		out[n++] = p;
		p = strchr(p, ',');
		if (p == NULL) {
			break;
		}
		*p++ = '\0';
	}
	return n;
}

static bool parse_line(char *line, vec_t *v)
{
	char *f[C_COUNT + 1];
	char *end;
	int i;
	int n;

	line[strcspn(line, "\r\n")] = '\0';
	n = split(line, f, C_COUNT + 1);
	if (n != C_COUNT) {
		return false;
	}
	memset(v, 0, sizeof(*v));
	v->id = strtol(f[C_ID], &end, 10);
	if (*end != '\0') {
		return false;
	}
	snprintf(v->tag, sizeof(v->tag), "%s", f[C_TAG]);
	snprintf(v->variant, sizeof(v->variant), "%s", f[C_VARIANT]);
	if (strcmp(f[C_CRIT], "exact") == 0) {
		v->criterion = SQUEAL_CRITERION_EXACT;
	} else if (strcmp(f[C_CRIT], "cubic") == 0) {
		v->criterion = SQUEAL_CRITERION_CUBIC;
	} else {
		return false;
	}
	if (!parse_state(f[C_STATE], &v->state)) {
		return false;
	}
	for (i = C_V0; i < C_COUNT; i++) {
		if (i == C_STATE) {
			continue;
		}
		v->val[i] = D_NAN;
		if (f[i][0] == '\0') {
			continue;
		}
		v->val[i] = strtod(f[i], &end);
		if (*end != '\0') {
			return false;
		}
		v->has[i] = true;
		if (i <= C_DMU) {
			v->in[i - C_V0] = v->val[i];
		}
	}
	for (i = C_V0; i <= C_DMU; i++) {
		if (!v->has[i]) {
			return false;
		}
	}
	return true;
}

static int load_vectors(void **state)
{
	FILE *fp;
	char line[1024];
	size_t cap = 0;
	bool header_seen = false;

	(void)state;
	fp = fopen(csv_path, "r");
	if (fp == NULL) {
		fprintf(stderr, "cannot open %s\n", csv_path);
		return -1;
	}
	while (fgets(line, sizeof(line), fp) != NULL) {
		if (line[0] == '#') {
			continue;
		}
		if (!header_seen) {
			char *f[C_COUNT + 1];
			int i;

			line[strcspn(line, "\r\n")] = '\0';
			if (split(line, f, C_COUNT + 1) != C_COUNT) {
				fprintf(stderr, "bad CSV header\n");
				fclose(fp);
				return -1;
			}
			for (i = 0; i < C_COUNT; i++) {
				if (strcmp(f[i], col_names[i]) != 0) {
					fprintf(stderr, "CSV column %d is %s, want %s\n",
						i, f[i], col_names[i]);
					fclose(fp);
					return -1;
				}
			}
			header_seen = true;
			continue;
		}
		if (g_run.n_vecs == cap) {
			size_t ncap = (cap == 0) ? 4096U : cap * 2U;
			vec_t *nv = realloc(g_run.vecs, ncap * sizeof(*nv));

			if (nv == NULL) {
				fclose(fp);
				return -1;
			}
			g_run.vecs = nv;
			cap = ncap;
		}
		if (!parse_line(line, &g_run.vecs[g_run.n_vecs])) {
			fprintf(stderr, "bad CSV line after row %zu\n", g_run.n_vecs);
			fclose(fp);
			return -1;
		}
		g_run.n_vecs++;
	}
	fclose(fp);
	if (g_run.n_vecs < 1000U) {
		fprintf(stderr, "only %zu vectors in %s\n", g_run.n_vecs, csv_path);
		return -1;
	}
	return 0;
}

static void to_inputs(const vec_t *v, squeal_params_t *p, squeal_point_t *pt)
{
	pt->v0_mps = sq_num_from_double(v->in[0], SQUEAL_Q_V0);
	pt->force_n = sq_num_from_double(v->in[1], SQUEAL_Q_FORCE);
	p->slope_spm = sq_num_from_double(v->in[2], SQUEAL_Q_SLOPE);
	p->damping = sq_num_from_double(v->in[3], SQUEAL_Q_DAMPING);
	p->omega0_radps = sq_num_from_double(v->in[4], SQUEAL_Q_OMEGA0);
	p->mass_kg = sq_num_from_double(v->in[5], SQUEAL_Q_MASS);
	p->mu_inf = sq_num_from_double(v->in[6], SQUEAL_Q_MU);
	p->delta_mu = sq_num_from_double(v->in[7], SQUEAL_Q_MU);
}

/* An input as the build holds it, back in double. */
static double held(const vec_t *v, int i)
{
	return sq_num_to_double(sq_num_from_double(v->in[i], input_q[i]), input_q[i]);
}

static double get_field(const squeal_result_t *r, int f)
{
	squeal_num_t n;

	memcpy(&n, (const char *)r + fields[f].offset, sizeof(n));
	return sq_num_to_double(n, fields[f].q);
}

/* Failures counted per kind and field (F_COUNT: not about one field);
 * the first few of each are printed in full. */
static size_t fail_tally[K_COUNT][F_COUNT + 1];

static void report(const vec_t *v, const squeal_result_t *r, int ret,
		   enum fail_kind kind, int field, const char *fmt, ...)
	__attribute__((format(printf, 6, 7)));

static void report(const vec_t *v, const squeal_result_t *r, int ret,
		   enum fail_kind kind, int field, const char *fmt, ...)
{
	va_list ap;
	int f;

	g_run.fails[kind]++;
	fail_tally[kind][field]++;
	if (g_run.reports >= MAX_REPORTS || fail_tally[kind][field] > 3U) {
		return;
	}
	g_run.reports++;
	printf("FAIL %s row %ld (%s, %s, %s): ", kind_names[kind], v->id, v->tag,
	       v->variant, v->criterion == SQUEAL_CRITERION_EXACT ? "exact" : "cubic");
	va_start(ap, fmt);
	vprintf(fmt, ap);
	va_end(ap);
	printf("\n     in: v0=%.9g N=%.9g a=%.9g D=%.9g w0=%.9g m=%.9g mu=%.9g dmu=%.9g\n",
	       v->in[0], v->in[1], v->in[2], v->in[3], v->in[4], v->in[5], v->in[6],
	       v->in[7]);
	printf("     want %s border_dist=%.3g;", squeal_model_state_name(v->state),
	       v->val[C_BORDER]);
	for (f = 0; f < F_COUNT; f++) {
		if (v->has[fields[f].col]) {
			printf(" %s=%.9g", fields[f].name, v->val[fields[f].col]);
		}
	}
	printf("\n     got  %s ret=%d flags=0x%x;", squeal_model_state_name(r->state),
	       ret, (unsigned)r->flags);
	for (f = 0; f < F_COUNT; f++) {
		if ((r->flags & fields[f].has_flag) != 0U) {
			printf(" %s=%.9g", fields[f].name, get_field(r, f));
		}
	}
	printf("\n");
}

/* Absolute uncertainty of ln Q for the inputs as held (see the top). */
static double dlnq(const vec_t *v)
{
	double l = held(v, 2) * held(v, 0);
	int i;

	for (i = 1; i < 8; i++) {
		if (i == 6) {
			continue; /* mu_inf is not in Q */
		}
		l += fabs(log(held(v, i)));
	}
#if defined(SQUEAL_NUMERIC_FIXED)
	return 0x1p-12 + 1e-6 * l;
#else
	return 1e-6 + 8.0 * 0x1p-24 * l;
#endif
}

static double cycle_dx(const vec_t *v, double x, double d)
{
	double k;
	double lin;
	double root;

	if (v->criterion == SQUEAL_CRITERION_EXACT) {
		k = 1.0 + 4.0 / x;
	} else {
		k = x / 2.0 + 4.0 / x;
	}
	lin = 2.0 * k * d;
	root = 2.0 * sqrt(8.0 * d);
	return (lin < root) ? lin : root;
}

/* Absolute tolerance of field f for reference value ref. */
static double tolerance(const vec_t *v, int f, double ref)
{
	double d = dlnq(v);
	double a = held(v, 2);
	double v0 = held(v, 0);
	double w0 = held(v, 4);
	/* Floor: 2 LSB of the fixed format; in float, FLT_MIN: values below
	 * the normal range have no relative precision left and an FPU in
	 * flush-to-zero mode (as Cortex-M4F code often runs) makes them 0. */
	double lsb2 = sq_num_is_fixed() ? 2.0 * sq_num_lsb(fields[f].q) : (double)FLT_MIN;
	double x = v->val[C_CYCLE_X];

	switch (f) {
	case F_LNQ:
		return d + lsb2;
	case F_HOPF_V0:
		return REL_TOL * fabs(ref) + d / a + lsb2;
	case F_HOPF_MARGIN:
		return REL_TOL * fmax(fabs(ref), v0) + d / a + lsb2;
	case F_HOPF_FORCE:
		return (REL_TOL + d) * fabs(ref) + lsb2;
	case F_CYCLE_X:
		return REL_TOL * ref + cycle_dx(v, x, d) + lsb2;
	case F_AMPL:
		return REL_TOL * ref + cycle_dx(v, x, d) * 1e6 / (a * w0) + lsb2;
	case F_TRIGGER:
		return REL_TOL * ref + cycle_dx(v, x, d) / a + lsb2;
	case F_BASIN:
		return REL_TOL * ref + cycle_dx(v, x, d) / (a * v0) + lsb2;
	default:
		return 0.0;
	}
}

static bool all_zero(const squeal_result_t *r)
{
	int f;

	for (f = 0; f < F_COUNT; f++) {
		if (get_field(r, f) != 0.0) {
			return false;
		}
	}
	return r->flags == 0U;
}

static bool is_class(squeal_state_t s)
{
	return s == SQUEAL_STATE_STABLE || s == SQUEAL_STATE_BISTABLE ||
	       s == SQUEAL_STATE_UNSTABLE;
}

static void check_values(const vec_t *v, const squeal_result_t *r, int ret)
{
	int f;

	for (f = 0; f < F_COUNT; f++) {
		const field_t *fd = &fields[f];
		double ref = v->val[fd->col];
		double max = sq_num_field_max(fd->q);
		double got;
		double tol;
		double err;

		if (!v->has[fd->col] || (r->flags & fd->has_flag) == 0U) {
			continue; /* presence was judged by check_flags */
		}
		got = get_field(r, f);
		tol = tolerance(v, f, ref);
		if (fd->sat_flag != 0U && (r->flags & fd->sat_flag) != 0U) {
			/* Clamped: legal only when the true value does not fit. */
			g_run.n_sat_seen[f]++;
			if (!(fabs(ref) + tol >= max)) {
				report(v, r, ret, K_SAT, f, "%s saturated but ref %.9g fits (max %.9g)",
				       fd->name, ref, max);
			} else if (!(fabs(got) >= max * (1.0 - 1e-6) - 2.0 * sq_num_lsb(fd->q))) {
				report(v, r, ret, K_SAT, f, "%s saturated to %.9g, not to max %.9g",
				       fd->name, got, max);
			}
			continue;
		}
		if (fabs(ref) - tol > max) {
			report(v, r, ret, K_SAT, f, "%s ref %.9g exceeds max %.9g but SAT not set (got %.9g)",
			       fd->name, ref, max, got);
			continue;
		}
		g_run.n_values_checked[f]++;
		err = fabs(got - ref);
		if (!(err <= tol)) {
			report(v, r, ret, K_VALUE, f, "%s = %.9g, want %.9g +- %.3g", fd->name,
			       got, ref, tol);
		}
		if (isfinite(err)) {
			double rel = err / fmax(fabs(ref), 1e-300);
			double ratio = (tol > 0.0) ? err / tol : 0.0;

			if (rel > g_run.max_rel[f]) {
				g_run.max_rel[f] = rel;
				g_run.max_rel_id[f] = v->id;
			}
			if (ratio > g_run.max_ratio[f]) {
				g_run.max_ratio[f] = ratio;
				g_run.max_ratio_id[f] = v->id;
			}
			if (REL_TOL * fabs(ref) >= 0.5 * tol && rel > g_run.max_rel_dom[f]) {
				g_run.max_rel_dom[f] = rel;
				g_run.max_rel_dom_id[f] = v->id;
			}
			if (err > g_run.max_abs[f]) {
				g_run.max_abs[f] = err;
			}
		}
	}
}

static void check_flags(const vec_t *v, const squeal_result_t *r, int ret, bool class_amb)
{
	bool hopf_amb = v->has[C_LNR] && fabs(v->val[C_LNR]) <= CLASS_BORDER_TOL;
	uint32_t want = 0U;
	uint32_t mask = SQUEAL_HAS_LNQ | SQUEAL_HAS_HOPF_V0 | SQUEAL_HAS_HOPF_FORCE |
			SQUEAL_HAS_CYCLE | SQUEAL_HAS_BASIN;
	uint32_t sat_mask = SQUEAL_SAT_HOPF_V0 | SQUEAL_SAT_HOPF_FORCE |
			    SQUEAL_SAT_CYCLE_X | SQUEAL_SAT_AMPLITUDE |
			    SQUEAL_SAT_TRIGGER | SQUEAL_SAT_BASIN;
	int f;

	for (f = 0; f < F_COUNT; f++) {
		if (v->has[fields[f].col]) {
			want |= fields[f].has_flag;
		}
	}
	if (hopf_amb) {
		mask &= ~SQUEAL_HAS_HOPF_V0;
	}
	if (class_amb) {
		/* Whatever class was returned, the cycle exists exactly when the
		 * steady state is stable (Q > 1/2), and basin with it (s > 0). */
		uint32_t cyc = SQUEAL_HAS_CYCLE | SQUEAL_HAS_BASIN;
		bool got_cycle_state = r->state != SQUEAL_STATE_UNSTABLE;

		if (((r->flags & cyc) == cyc) != got_cycle_state ||
		    ((r->flags & cyc) != 0U && (r->flags & cyc) != cyc)) {
			report(v, r, ret, K_FLAGS, F_COUNT, "cycle flags disagree with returned class");
		}
		mask &= ~cyc;
	}
	if ((r->flags & mask) != (want & mask)) {
		report(v, r, ret, K_FLAGS, F_COUNT, "HAS flags 0x%x, want 0x%x (mask 0x%x)",
		       (unsigned)(r->flags & mask), (unsigned)(want & mask), (unsigned)mask);
	}
	if ((r->flags & ~(mask | sat_mask | SQUEAL_HAS_HOPF_V0 | SQUEAL_HAS_CYCLE |
			  SQUEAL_HAS_BASIN)) != 0U) {
		report(v, r, ret, K_FLAGS, F_COUNT, "unknown flag bits 0x%x", (unsigned)r->flags);
	}
	/* A SAT flag without its field is meaningless. */
	for (f = 0; f < F_COUNT; f++) {
		if (fields[f].sat_flag != 0U && (r->flags & fields[f].sat_flag) != 0U &&
		    (r->flags & fields[f].has_flag) == 0U) {
			report(v, r, ret, K_FLAGS, F_COUNT, "SAT for %s without its HAS flag",
			       fields[f].name);
		}
	}
}

static void run_one(const vec_t *v)
{
	squeal_params_t p;
	squeal_point_t pt;
	squeal_result_t r;
	bool class_amb;
	int ret;

	to_inputs(v, &p, &pt);
	memset(&r, 0xa5, sizeof(r)); /* garbage the model must overwrite */
	ret = squeal_model_classify(&p, &pt, v->criterion, &r);
	g_run.n_run++;

	if (v->state == SQUEAL_STATE_INVALID) {
		if (ret != SQ_EINVAL || r.state != SQUEAL_STATE_INVALID) {
			report(v, &r, ret, K_INVALID, F_COUNT, "want SQ_EINVAL and INVALID");
		} else if (!all_zero(&r)) {
			report(v, &r, ret, K_INVALID, F_COUNT, "invalid result not cleared");
		}
		return;
	}
	if (ret != SQ_OK) {
		report(v, &r, ret, K_STATUS, F_COUNT, "want SQ_OK");
		return;
	}
	class_amb = v->has[C_BORDER] && v->val[C_BORDER] <= CLASS_BORDER_TOL;
	if (class_amb) {
		if (!is_class(r.state)) {
			report(v, &r, ret, K_CLASS, F_COUNT, "near a border, but not a class");
		}
	} else {
		g_run.n_class_checked++;
		if (r.state != v->state) {
			report(v, &r, ret, K_CLASS, F_COUNT, "class differs");
		}
	}
	check_flags(v, &r, ret, class_amb);
	check_values(v, &r, ret);
}

static bool runs_here(const vec_t *v)
{
	return strcmp(v->variant, "both") == 0 ||
	       strcmp(v->variant, sq_num_build_name()) == 0;
}

static int setup(void **state)
{
	size_t i;
	int f;

	if (load_vectors(state) != 0) {
		return -1;
	}
	for (i = 0; i < g_run.n_vecs; i++) {
		if (runs_here(&g_run.vecs[i])) {
			run_one(&g_run.vecs[i]);
		}
	}
	printf("%s build: %zu of %zu vectors run, class checked on %zu (border_dist > %g)\n",
	       sq_num_build_name(), g_run.n_run, g_run.n_vecs, g_run.n_class_checked,
	       CLASS_BORDER_TOL);
	/* "rel(rel-dom)": largest relative error among values whose tolerance
	 * is mostly the relative part, i.e. away from zero. */
	printf("%-22s %7s %5s %10s %6s %12s %6s %10s %6s %10s\n", "largest errors:",
	       "checked", "sat", "max rel", "row", "rel(rel-dom)", "row", "err/tol", "row",
	       "max abs");
	for (f = 0; f < F_COUNT; f++) {
		printf("%-22s %7zu %5zu %10.3g %6ld %12.3g %6ld %10.3g %6ld %10.3g\n",
		       fields[f].name, g_run.n_values_checked[f], g_run.n_sat_seen[f],
		       g_run.max_rel[f], g_run.max_rel_id[f], g_run.max_rel_dom[f],
		       g_run.max_rel_dom_id[f], g_run.max_ratio[f], g_run.max_ratio_id[f],
		       g_run.max_abs[f]);
	}
	return 0;
}

static int teardown(void **state)
{
	(void)state;
	free(g_run.vecs);
	g_run.vecs = NULL;
	return 0;
}

static void expect_no_fail(enum fail_kind k)
{
	int f;

	for (f = 0; f <= F_COUNT; f++) {
		if (fail_tally[k][f] != 0U) {
			print_error("  %zu failures of %s%s%s\n", fail_tally[k][f], kind_names[k],
				    f < F_COUNT ? " on " : "", f < F_COUNT ? fields[f].name : "");
		}
	}
	if (g_run.fails[k] != 0U) {
		print_error("%zu vectors failed the %s check (first ones above)\n",
			    g_run.fails[k], kind_names[k]);
	}
	assert_int_equal(g_run.fails[k], 0);
}

static void test_golden_return_codes(void **state)
{
	(void)state;
	assert_true(g_run.n_run > 1000U);
	expect_no_fail(K_STATUS);
}

static void test_golden_classes_match_reference(void **state)
{
	(void)state;
	assert_true(g_run.n_class_checked > 1000U);
	expect_no_fail(K_CLASS);
}

static void test_golden_has_flags_match_reference(void **state)
{
	(void)state;
	expect_no_fail(K_FLAGS);
}

static void test_golden_values_within_tolerance(void **state)
{
	(void)state;
	assert_true(g_run.n_values_checked[F_HOPF_V0] > 100U);
	assert_true(g_run.n_values_checked[F_CYCLE_X] > 100U);
	expect_no_fail(K_VALUE);
}

static void test_golden_saturation_only_when_out_of_range(void **state)
{
	(void)state;
	expect_no_fail(K_SAT);
}

static void test_golden_invalid_inputs_give_einval(void **state)
{
	(void)state;
	expect_no_fail(K_INVALID);
}

/* ---- direct tests --------------------------------------------------------- */

static void set_defaults_by_hand(squeal_params_t *p)
{
	p->mass_kg = sq_num_from_double(1.0, SQUEAL_Q_MASS);
	p->omega0_radps = sq_num_from_double(5000.0, SQUEAL_Q_OMEGA0);
	p->damping = sq_num_from_double(0.023, SQUEAL_Q_DAMPING);
	p->mu_inf = sq_num_from_double(0.25, SQUEAL_Q_MU);
	p->delta_mu = sq_num_from_double(0.15, SQUEAL_Q_MU);
	p->slope_spm = sq_num_from_double(2.0, SQUEAL_Q_SLOPE);
}

static void test_null_pointers_give_einval_untouched(void **state)
{
	squeal_params_t p;
	squeal_point_t pt;
	squeal_result_t r;
	squeal_result_t before;

	(void)state;
	set_defaults_by_hand(&p);
	pt.v0_mps = sq_num_from_double(1.0, SQUEAL_Q_V0);
	pt.force_n = sq_num_from_double(9000.0, SQUEAL_Q_FORCE);
	memset(&r, 0x5a, sizeof(r));
	before = r;
	/* NULL pointers: programming errors, the contract handler */
	expect_assert_failure(squeal_model_classify(NULL, &pt, SQUEAL_CRITERION_EXACT, &r));
	assert_memory_equal(&r, &before, sizeof(r));
	expect_assert_failure(squeal_model_classify(&p, NULL, SQUEAL_CRITERION_EXACT, &r));
	assert_memory_equal(&r, &before, sizeof(r));
	expect_assert_failure(squeal_model_classify(&p, &pt, SQUEAL_CRITERION_EXACT, NULL));
	expect_assert_failure(squeal_model_classify(NULL, NULL, SQUEAL_CRITERION_CUBIC, NULL));
	expect_assert_failure(squeal_model_params_check(NULL));
}

static void test_unknown_criterion_gives_invalid(void **state)
{
	static const int bad[] = { 2, 3, 15, 255, -1 };
	squeal_params_t p;
	squeal_point_t pt;
	squeal_result_t r;
	size_t i;

	(void)state;
	set_defaults_by_hand(&p);
	pt.v0_mps = sq_num_from_double(1.5, SQUEAL_Q_V0);
	pt.force_n = sq_num_from_double(9000.0, SQUEAL_Q_FORCE);
	for (i = 0; i < sizeof(bad) / sizeof(bad[0]); i++) {
		squeal_criterion_t c;

		_Static_assert(sizeof(c) == sizeof(bad[0]), "enum is int-sized");
		/* An out-of-range enum value, as a corrupted calibration
		 * would deliver it. */
		memcpy(&c, &bad[i], sizeof(c));
		memset(&r, 0xa5, sizeof(r));
		assert_int_equal(squeal_model_classify(&p, &pt, c, &r), SQ_EINVAL);
		assert_int_equal(r.state, SQUEAL_STATE_INVALID);
		assert_true(all_zero(&r));
	}
}

static void test_default_params_are_model_md_section_8(void **state)
{
	squeal_params_t p;
	squeal_params_t want;
	static const struct {
		size_t offset;
		int q;
	} f[] = {
		{ offsetof(squeal_params_t, mass_kg), SQUEAL_Q_MASS },
		{ offsetof(squeal_params_t, omega0_radps), SQUEAL_Q_OMEGA0 },
		{ offsetof(squeal_params_t, damping), SQUEAL_Q_DAMPING },
		{ offsetof(squeal_params_t, mu_inf), SQUEAL_Q_MU },
		{ offsetof(squeal_params_t, delta_mu), SQUEAL_Q_MU },
		{ offsetof(squeal_params_t, slope_spm), SQUEAL_Q_SLOPE },
	};
	size_t i;

	(void)state;
	memset(&p, 0, sizeof(p));
	squeal_model_default_params(&p);
	set_defaults_by_hand(&want);
	for (i = 0; i < sizeof(f) / sizeof(f[0]); i++) {
		squeal_num_t a;
		squeal_num_t b;
		double da;
		double db;

		memcpy(&a, (const char *)&p + f[i].offset, sizeof(a));
		memcpy(&b, (const char *)&want + f[i].offset, sizeof(b));
		da = sq_num_to_double(a, f[i].q);
		db = sq_num_to_double(b, f[i].q);
		/* The same decimal, rounded once: at most one LSB or ulp apart. */
		if (!(fabs(da - db) <= fmax(sq_num_lsb(f[i].q), 1.2e-7 * fabs(db)))) {
			print_error("default field %zu is %.9g, want %.9g\n", i, da, db);
			fail();
		}
	}
	assert_int_equal(squeal_model_params_check(&p), SQ_OK);
}

static void test_params_check_rejects_each_field_outside_domain(void **state)
{
	struct {
		size_t offset;
		int q;
		double bad[6];
		double good[3];
	} cases[] = {
		{ offsetof(squeal_params_t, mass_kg), SQUEAL_Q_MASS,
		  { 0.0, -1.0, 10001.0, D_NAN, D_INF, -D_INF }, { 10000.0, 1e-3, 1.0 } },
		{ offsetof(squeal_params_t, omega0_radps), SQUEAL_Q_OMEGA0,
		  { 0.0, -1.0, 500001.0, D_NAN, D_INF, -D_INF }, { 500000.0, 1.0, 5000.0 } },
		{ offsetof(squeal_params_t, damping), SQUEAL_Q_DAMPING,
		  { 0.0, -0.5, 1.0 + 1e-6, D_NAN, D_INF, -D_INF }, { 1.0, 1e-6, 0.023 } },
		{ offsetof(squeal_params_t, slope_spm), SQUEAL_Q_SLOPE,
		  { -1e-3, -1.0, 20.001, D_NAN, D_INF, -D_INF }, { 0.0, 20.0, 2.0 } },
		{ offsetof(squeal_params_t, mu_inf), SQUEAL_Q_MU,
		  { -1e-3, -1.0, 1.501, D_NAN, D_INF, -D_INF }, { 0.0, 1.5, 0.25 } },
		{ offsetof(squeal_params_t, delta_mu), SQUEAL_Q_MU,
		  { -1.501, -0.26, 1.501, D_NAN, D_INF, -D_INF }, { -0.25, 1.5, 0.0 } },
	};
	size_t i;
	size_t j;

	(void)state;
	for (i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
		for (j = 0; j < 6; j++) {
			squeal_params_t p;
			squeal_num_t n = sq_num_from_double(cases[i].bad[j], cases[i].q);

			set_defaults_by_hand(&p);
			memcpy((char *)&p + cases[i].offset, &n, sizeof(n));
			if (squeal_model_params_check(&p) != SQ_EINVAL) {
				print_error("case %zu: %g accepted\n", i, cases[i].bad[j]);
				fail();
			}
		}
		for (j = 0; j < 3; j++) {
			squeal_params_t p;
			squeal_num_t n = sq_num_from_double(cases[i].good[j], cases[i].q);

			set_defaults_by_hand(&p);
			memcpy((char *)&p + cases[i].offset, &n, sizeof(n));
			if (squeal_model_params_check(&p) != SQ_OK) {
				print_error("case %zu: %g rejected\n", i, cases[i].good[j]);
				fail();
			}
		}
	}
}

static void test_state_names(void **state)
{
	(void)state;
	assert_string_equal(squeal_model_state_name(SQUEAL_STATE_STABLE), "stable");
	assert_string_equal(squeal_model_state_name(SQUEAL_STATE_BISTABLE), "bistable");
	assert_string_equal(squeal_model_state_name(SQUEAL_STATE_UNSTABLE), "unstable");
	assert_string_equal(squeal_model_state_name(SQUEAL_STATE_NOT_SLIDING), "not_sliding");
	assert_string_equal(squeal_model_state_name(SQUEAL_STATE_INVALID), "invalid");
	assert_string_equal(squeal_model_state_name((squeal_state_t)7), "?");
}

static void test_conversion_helper_saturates_out_of_domain(void **state)
{
	(void)state;
	/* The helper itself: what the golden "fixed" rows rely on. */
	if (sq_num_is_fixed()) {
		assert_int_equal(sq_num_from_double(1e9, SQUEAL_Q_V0), INT32_MAX);
		assert_int_equal(sq_num_from_double(-1e9, SQUEAL_Q_V0), INT32_MIN);
		assert_int_equal(sq_num_from_double(D_NAN, SQUEAL_Q_V0), INT32_MIN);
		assert_int_equal(sq_num_from_double(D_INF, SQUEAL_Q_FORCE), INT32_MAX);
		assert_int_equal(sq_num_from_double(0.5 * 0x1p-20, SQUEAL_Q_V0), 1);
		assert_int_equal(sq_num_from_double(0.49 * 0x1p-20, SQUEAL_Q_V0), 0);
		assert_int_equal(sq_num_from_double(1.5, SQUEAL_Q_MU), 3 << 29);
		/* Every saturated input is outside the domain (range > limit). */
		assert_true(sq_num_field_max(SQUEAL_Q_V0) > 100.0);
		assert_true(sq_num_field_max(SQUEAL_Q_FORCE) > 500000.0);
		assert_true(sq_num_field_max(SQUEAL_Q_OMEGA0) > 500000.0);
		assert_true(sq_num_field_max(SQUEAL_Q_MASS) > 10000.0);
		assert_true(sq_num_field_max(SQUEAL_Q_DAMPING) > 1.0);
		assert_true(sq_num_field_max(SQUEAL_Q_MU) > 1.5);
		assert_true(sq_num_field_max(SQUEAL_Q_SLOPE) > 20.0);
	} else {
		assert_true(isinf(sq_num_to_double(sq_num_from_double(1e39, 0), 0)));
		assert_true(isnan(sq_num_to_double(sq_num_from_double(D_NAN, 0), 0)));
		assert_true(sq_num_to_double(sq_num_from_double(3.4028235e38, 0), 0) ==
			    sq_num_field_max(0));
	}
}

int main(int argc, char **argv)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_golden_return_codes),
		cmocka_unit_test(test_golden_classes_match_reference),
		cmocka_unit_test(test_golden_has_flags_match_reference),
		cmocka_unit_test(test_golden_values_within_tolerance),
		cmocka_unit_test(test_golden_saturation_only_when_out_of_range),
		cmocka_unit_test(test_golden_invalid_inputs_give_einval),
		cmocka_unit_test(test_null_pointers_give_einval_untouched),
		cmocka_unit_test(test_unknown_criterion_gives_invalid),
		cmocka_unit_test(test_default_params_are_model_md_section_8),
		cmocka_unit_test(test_params_check_rejects_each_field_outside_domain),
		cmocka_unit_test(test_state_names),
		cmocka_unit_test(test_conversion_helper_saturates_out_of_domain),
	};

	if (argc > 1) {
		csv_path = argv[1];
	}
	return cmocka_run_group_tests_name(sq_num_is_fixed() ? "model (fixed)" : "model (float)",
					   tests, setup, teardown);
}
