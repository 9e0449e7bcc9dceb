/* SPDX-License-Identifier: MIT */
/*
 * Benchmark of squeal_model_classify(): cost of one classification with
 * each criterion, in the numeric build this file is compiled for
 * (build/host/tests/firmware/model/bench_squeal_model: float, build/host-fixed/tests/firmware/model/bench_squeal_model: fixed),
 * and the cost of deciding the same points by brute-force simulation
 * (brute_force.c).
 *
 * The operating points: the default brake (docs/model.md section 8) with the
 * friction slope a uniform in [0.5, 6] s/m, v0 uniform in [0, 40] m/s and N
 * uniform in [0, 30] kN, drawn from a fixed xorshift64* sequence and kept
 * until each class (by the exact criterion, decided here in double
 * precision, independently of the model) holds a third of the set, then
 * shuffled. Points within 1e-3 of a class border in ln Q are skipped, so
 * every build must give the reference class. Inputs are converted to the
 * model's numbers before any timing.
 *
 * Usage:
 *   bench_model [--repeats R] [--calls C]
 *       R timed repeats (default 15) of C calls (default 20000) with each
 *       criterion, interleaved; prints "sample <criterion> <ns/call>" per
 *       repeat and "result <criterion> median min max" per criterion.
 *   bench_model --callgrind N [--criterion exact|cubic]
 *       exactly N calls and nothing else timed, for valgrind: instructions
 *       per call = (Ir(N) - Ir(0)) / N.
 *   bench_model --brute K
 *       brute-force decision of the first K points with Q > 1/2; prints the
 *       per-decision time and the check of docs/model.md section 6.
 */
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "brute_force.h"
#include "sim_num.h"
#include "squeal_model.h"

#define BENCH_POINTS 4096U /* power of two: index with a mask */
#define BENCH_SEED UINT64_C(0x9e3779b97f4a7c15)
#define BENCH_MAX_DRAWS 50000000L
#define BENCH_BORDER_GAP 1e-3 /* min distance of ln Q from a class border */
#define BENCH_MAX_REPEATS 1000

typedef struct {
	squeal_params_t params;
	squeal_point_t point;
} bench_case_t;

/* The same point in double precision, for the references. */
typedef struct {
	double slope_spm;
	double v0_mps;
	double force_n;
	double ln_q;
	double stick; /* s = a v0 */
	squeal_state_t ref_exact;
	squeal_state_t ref_cubic;
} bench_meta_t;

static bench_case_t cases[BENCH_POINTS];
static bench_meta_t meta[BENCH_POINTS];
static volatile uint32_t bench_sink;

static uint64_t rng_state = BENCH_SEED;

/* xorshift64*: a fixed, portable sequence. */
static uint64_t rng_next(void)
{
	rng_state ^= rng_state >> 12;
	rng_state ^= rng_state << 25;
	rng_state ^= rng_state >> 27;
	return rng_state * UINT64_C(2685821657736338717);
}

/* Uniform in [0, 1). */
static double rng_unit(void)
{
	return (double)(rng_next() >> 11) * 0x1.0p-53;
}

/* ln(I1(s)/s) by its power series, I1(s)/s = 1/2 sum (s^2/4)^k/(k!(k+1)!):
 * positive terms only, so no cancellation; s <= 240 keeps the sum finite. */
static double ref_ln_i1_over_s(double s)
{
	double x = s * s / 4.0;
	double term = 1.0;
	double sum = 1.0;
	int k;

	for (k = 0; k < 4000; k++) {
		double kk = (double)k;

		term *= x / ((kk + 1.0) * (kk + 2.0));
		sum += term;
		if ((kk + 1.0) * (kk + 2.0) > x && term < 1e-17 * sum) {
			break;
		}
	}
	return log(0.5 * sum);
}

static squeal_state_t ref_class(double ln_q, double ln_border)
{
	if (ln_q <= log(0.5)) {
		return SQUEAL_STATE_UNSTABLE;
	}
	return ln_q < ln_border ? SQUEAL_STATE_BISTABLE : SQUEAL_STATE_STABLE;
}

static int class_index(squeal_state_t state)
{
	switch (state) {
	case SQUEAL_STATE_STABLE:
		return 0;
	case SQUEAL_STATE_BISTABLE:
		return 1;
	case SQUEAL_STATE_UNSTABLE:
		return 2;
	default:
		return 3;
	}
}

/* Fill cases[] and meta[]; returns 0, or -1 when the draws ran out or a
 * value did not convert. */
static int make_points(void)
{
	const double ln_half = log(0.5);
	sim_params_d_t pd;
	unsigned int target[3];
	unsigned int count[3] = { 0, 0, 0 };
	unsigned int n = 0;
	unsigned int i;
	long draws;

	sim_params_default(&pd);
	target[1] = BENCH_POINTS / 3U;
	target[2] = BENCH_POINTS / 3U;
	target[0] = BENCH_POINTS - target[1] - target[2];
	for (draws = 0; draws < BENCH_MAX_DRAWS && n < BENCH_POINTS; draws++) {
		double a = 0.5 + 5.5 * rng_unit();
		double v0 = 40.0 * rng_unit();
		double force = 30000.0 * rng_unit();
		double s = a * v0;
		double ln_q, ln_exact, ln_cubic;
		bench_meta_t *m;
		int c;

		if (v0 <= 0.0 || force <= 0.0) {
			continue; /* not sliding: nothing to classify */
		}
		ln_q = log(pd.damping * pd.omega0_radps * pd.mass_kg /
			   (a * force * pd.delta_mu)) + s;
		ln_exact = ref_ln_i1_over_s(s);
		ln_cubic = log(0.5 + s * s / 16.0);
		if (fabs(ln_q - ln_half) < BENCH_BORDER_GAP ||
		    fabs(ln_q - ln_exact) < BENCH_BORDER_GAP ||
		    fabs(ln_q - ln_cubic) < BENCH_BORDER_GAP) {
			continue;
		}
		c = class_index(ref_class(ln_q, ln_exact));
		if (c > 2 || count[c] >= target[c]) {
			continue;
		}
		count[c]++;
		pd.slope_spm = a;
		if (sim_params_to_model(&pd, &cases[n].params) != 0 ||
		    sim_point_to_model(v0, force, &cases[n].point) != 0) {
			fprintf(stderr, "bench_model: conversion failed\n");
			return -1;
		}
		m = &meta[n];
		m->slope_spm = a;
		m->v0_mps = v0;
		m->force_n = force;
		m->ln_q = ln_q;
		m->stick = s;
		m->ref_exact = ref_class(ln_q, ln_exact);
		m->ref_cubic = ref_class(ln_q, ln_cubic);
		n++;
	}
	if (n < BENCH_POINTS) {
		fprintf(stderr, "bench_model: only %u points after %ld draws\n", n, draws);
		return -1;
	}
	/* Fisher-Yates, so the classes are interleaved as on a real road. */
	for (i = BENCH_POINTS - 1U; i > 0U; i--) {
		unsigned int j = (unsigned int)(rng_next() % (uint64_t)(i + 1U));
		bench_case_t tc = cases[i];
		bench_meta_t tm = meta[i];

		cases[i] = cases[j];
		meta[i] = meta[j];
		cases[j] = tc;
		meta[j] = tm;
	}
	return 0;
}

static const char *criterion_name(squeal_criterion_t crit)
{
	return crit == SQUEAL_CRITERION_CUBIC ? "cubic" : "exact";
}

/* The work that is timed (and counted by callgrind): calls classifications
 * cycling through the set. The accumulated states go to a volatile so no
 * call can be dropped. */
static void run_calls(squeal_criterion_t crit, unsigned long calls)
{
	squeal_result_t res;
	uint32_t acc = 0;
	unsigned long i;

	for (i = 0; i < calls; i++) {
		const bench_case_t *c = &cases[i & (BENCH_POINTS - 1U)];
		int rc = squeal_model_classify(&c->params, &c->point, crit, &res);

		acc += (uint32_t)rc + (uint32_t)res.state;
	}
	bench_sink = acc;
}

/* The same with the points of one reference class only (exact criterion's
 * class), to show where the time goes. */
static bench_case_t class_cases[3][BENCH_POINTS];
static unsigned int class_count[3];

static void split_classes(void)
{
	unsigned int i;

	for (i = 0; i < BENCH_POINTS; i++) {
		int c = class_index(meta[i].ref_exact);

		if (c <= 2) {
			class_cases[c][class_count[c]++] = cases[i];
		}
	}
}

static void run_class_calls(int cls, squeal_criterion_t crit, unsigned long calls)
{
	const bench_case_t *set = class_cases[cls];
	unsigned int n = class_count[cls];
	unsigned int j = 0;
	squeal_result_t res;
	uint32_t acc = 0;
	unsigned long i;

	for (i = 0; i < calls; i++) {
		int rc = squeal_model_classify(&set[j].params, &set[j].point, crit, &res);

		acc += (uint32_t)rc + (uint32_t)res.state;
		j = (j + 1U == n) ? 0U : j + 1U;
	}
	bench_sink = acc;
}

static double now_ns(void)
{
	struct timespec ts;

	if (clock_gettime(CLOCK_MONOTONIC, &ts) != 0) {
		perror("clock_gettime");
		exit(2);
	}
	return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}

static double time_calls(squeal_criterion_t crit, unsigned long calls)
{
	double t0 = now_ns();

	run_calls(crit, calls);
	return (now_ns() - t0) / (double)calls;
}

static int cmp_double(const void *pa, const void *pb)
{
	double a = *(const double *)pa;
	double b = *(const double *)pb;

	return (a > b) - (a < b);
}

static double median_of(double *v, int n)
{
	qsort(v, (size_t)n, sizeof(v[0]), cmp_double);
	return (n % 2) ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* Classes given by the model for each criterion, against the reference.
 * Returns the number of disagreements (printed). */
static unsigned int check_classes(void)
{
	unsigned int bad_total = 0;
	int ci;

	for (ci = 0; ci < 2; ci++) {
		squeal_criterion_t crit = ci ? SQUEAL_CRITERION_CUBIC : SQUEAL_CRITERION_EXACT;
		unsigned int cnt[4] = { 0, 0, 0, 0 };
		unsigned int bad = 0;
		unsigned int i;

		for (i = 0; i < BENCH_POINTS; i++) {
			squeal_result_t res;
			int rc = squeal_model_classify(&cases[i].params, &cases[i].point, crit, &res);
			squeal_state_t ref = ci ? meta[i].ref_cubic : meta[i].ref_exact;

			cnt[class_index(res.state)]++;
			if (rc != SQ_OK || res.state != ref) {
				bad++;
			}
		}
		printf("classes %s %s: %u stable, %u bistable, %u unstable, %u other;"
		       " %u differ from the double-precision reference\n",
		       SQUEAL_NUMERIC_NAME, criterion_name(crit), cnt[0], cnt[1], cnt[2],
		       cnt[3], bad);
		bad_total += bad;
	}
	return bad_total;
}

static int bench_timing(int repeats, unsigned long calls)
{
	double samples[2][BENCH_MAX_REPEATS];
	double med[2];
	int r, ci;

	printf("bench_model: build %s, %u points, %d repeats x %lu calls per criterion\n",
	       SQUEAL_NUMERIC_NAME, BENCH_POINTS, repeats, calls);
	(void)check_classes();
	/* Warm-up: caches, branch predictors, CPU clock. */
	run_calls(SQUEAL_CRITERION_EXACT, calls);
	run_calls(SQUEAL_CRITERION_CUBIC, calls);
	for (r = 0; r < repeats; r++) {
		/* Alternate the order so neither criterion always runs second. */
		int first = r % 2;

		samples[first][r] = time_calls(first ? SQUEAL_CRITERION_CUBIC : SQUEAL_CRITERION_EXACT, calls);
		samples[1 - first][r] = time_calls(first ? SQUEAL_CRITERION_EXACT : SQUEAL_CRITERION_CUBIC, calls);
	}
	for (ci = 0; ci < 2; ci++) {
		for (r = 0; r < repeats; r++) {
			printf("sample %s %.3f\n", ci ? "cubic" : "exact", samples[ci][r]);
		}
	}
	for (ci = 0; ci < 2; ci++) {
		med[ci] = median_of(samples[ci], repeats);
		printf("result %s %s median %.2f min %.2f max %.2f ns/call\n",
		       SQUEAL_NUMERIC_NAME, ci ? "cubic" : "exact", med[ci],
		       samples[ci][0], samples[ci][repeats - 1]);
	}
	printf("ratio cubic/exact %.3f (medians)\n", med[1] / med[0]);

	/* Where the time goes: each reference class alone, 5 repeats. */
	split_classes();
	for (ci = 0; ci < 2; ci++) {
		squeal_criterion_t crit = ci ? SQUEAL_CRITERION_CUBIC : SQUEAL_CRITERION_EXACT;
		static const char *const names[3] = { "stable", "bistable", "unstable" };
		double cls_med[3];
		int cls;

		for (cls = 0; cls < 3; cls++) {
			double v[5];

			run_class_calls(cls, crit, calls);
			for (r = 0; r < 5; r++) {
				double t0 = now_ns();

				run_class_calls(cls, crit, calls);
				v[r] = (now_ns() - t0) / (double)calls;
			}
			cls_med[cls] = median_of(v, 5);
		}
		printf("byclass %s %s: %s %.1f, %s %.1f, %s %.1f ns/call (median of 5)\n",
		       SQUEAL_NUMERIC_NAME, criterion_name(crit), names[0], cls_med[0],
		       names[1], cls_med[1], names[2], cls_med[2]);
	}
	return 0;
}

/* docs/model.md section 6: simulated max u' of the unstable cycle. */
static const struct {
	double damping, q, max_du;
} md_table[] = {
	{ 0.023, 0.6, 1.2260 }, { 0.023, 1.0, 2.4874 }, { 0.023, 2.0, 3.6936 },
	{ 0.023, 3.0, 4.3102 }, { 0.1, 1.0, 2.4982 },   { 0.1, 3.0, 4.3368 },
};

static int bench_brute(unsigned int k)
{
	sim_params_d_t pd;
	double *ns;
	unsigned int n = 0, i;
	unsigned int agree_exact = 0, agree_cubic = 0, agree_ref = 0, undecided = 0;
	unsigned int n_bistable = 0;
	double total = 0.0, med, t;
	int rc_all = 0;
	size_t ti;

	sim_params_default(&pd);
	for (ti = 0; ti < sizeof(md_table) / sizeof(md_table[0]); ti++) {
		bf_result_t br;
		double err;
		int rc;

		t = now_ns();
		rc = bf_decide(md_table[ti].damping, md_table[ti].q, HUGE_VAL, &br);
		t = now_ns() - t;
		err = (br.cycle_max_du / md_table[ti].max_du - 1.0) * 100.0;
		printf("check D=%.3f Q=%.1f: brute-force cycle max u' %.5f, docs/model.md %.4f,"
		       " error %+.4f %% (%s), %ld RK4 steps, %.0f us\n",
		       md_table[ti].damping, md_table[ti].q, br.cycle_max_du,
		       md_table[ti].max_du, err,
		       (rc == 0 && fabs(err) <= 0.2) ? "ok" : "FAIL", br.steps, t / 1e3);
		if (rc != 0 || fabs(err) > 0.2) {
			rc_all = 1;
		}
	}

	ns = calloc(k ? k : 1U, sizeof(*ns));
	if (ns == NULL) {
		perror("calloc");
		return 2;
	}
	for (i = 0; i < BENCH_POINTS && n < k; i++) {
		const bench_meta_t *m = &meta[i];
		squeal_result_t rex, rcu;
		bf_result_t br;
		squeal_state_t bf_state;
		int rc;

		if (m->ref_exact == SQUEAL_STATE_UNSTABLE) {
			continue; /* decided by the linear test, not by simulation */
		}
		t = now_ns();
		rc = bf_decide(pd.damping, exp(m->ln_q), m->stick, &br);
		ns[n] = now_ns() - t;
		total += ns[n];
		n++;
		if (rc != 0) {
			undecided++;
			continue;
		}
		bf_state = br.decision == BF_BISTABLE ? SQUEAL_STATE_BISTABLE : SQUEAL_STATE_STABLE;
		n_bistable += bf_state == SQUEAL_STATE_BISTABLE;
		if (squeal_model_classify(&cases[i].params, &cases[i].point, SQUEAL_CRITERION_EXACT, &rex) != SQ_OK ||
		    squeal_model_classify(&cases[i].params, &cases[i].point, SQUEAL_CRITERION_CUBIC, &rcu) != SQ_OK) {
			fprintf(stderr, "bench_model: classify failed\n");
			free(ns);
			return 2;
		}
		agree_exact += rex.state == bf_state;
		agree_cubic += rcu.state == bf_state;
		agree_ref += m->ref_exact == bf_state;
	}
	if (n == 0) {
		free(ns);
		printf("brute no points\n");
		return rc_all;
	}
	printf("brute points %u (Q > 1/2): %u bistable, %u stable, %u undecided;"
	       " agrees with model exact %u, model cubic %u, double reference %u\n",
	       n, n_bistable, n - n_bistable - undecided, undecided, agree_exact,
	       agree_cubic, agree_ref);
	med = median_of(ns, (int)n);
	printf("brute ns/decision mean %.0f median %.0f min %.0f max %.0f\n",
	       total / n, med, ns[0], ns[n - 1]);
	free(ns);
	return rc_all;
}

static int usage(void)
{
	fprintf(stderr, "usage: bench_model [--repeats R] [--calls C] |"
			" --callgrind N [--criterion exact|cubic] | --brute K\n");
	return 2;
}

static int parse_ulong(const char *s, unsigned long max, unsigned long *out)
{
	char *end;
	unsigned long v;

	errno = 0;
	v = strtoul(s, &end, 10);
	if (errno != 0 || end == s || *end != '\0' || v > max || s[0] == '-') {
		return -1;
	}
	*out = v;
	return 0;
}

int main(int argc, char **argv)
{
	unsigned long repeats = 15, calls = 20000, n = 0;
	squeal_criterion_t crit = SQUEAL_CRITERION_EXACT;
	enum { MODE_TIME, MODE_CALLGRIND, MODE_BRUTE } mode = MODE_TIME;
	int i;

	for (i = 1; i < argc; i++) {
		const char *arg = argv[i];
		const char *val = i + 1 < argc ? argv[i + 1] : NULL;

		if (val == NULL) {
			return usage();
		}
		i++;
		if (strcmp(arg, "--repeats") == 0) {
			if (parse_ulong(val, BENCH_MAX_REPEATS, &repeats) != 0 || repeats == 0) {
				return usage();
			}
		} else if (strcmp(arg, "--calls") == 0) {
			if (parse_ulong(val, 1000000000UL, &calls) != 0 || calls == 0) {
				return usage();
			}
		} else if (strcmp(arg, "--callgrind") == 0) {
			mode = MODE_CALLGRIND;
			if (parse_ulong(val, 1000000000UL, &n) != 0) {
				return usage();
			}
		} else if (strcmp(arg, "--brute") == 0) {
			mode = MODE_BRUTE;
			if (parse_ulong(val, BENCH_POINTS, &n) != 0) {
				return usage();
			}
		} else if (strcmp(arg, "--criterion") == 0) {
			if (strcmp(val, "exact") == 0) {
				crit = SQUEAL_CRITERION_EXACT;
			} else if (strcmp(val, "cubic") == 0) {
				crit = SQUEAL_CRITERION_CUBIC;
			} else {
				return usage();
			}
		} else {
			return usage();
		}
	}
	if (make_points() != 0) {
		return 2;
	}
	switch (mode) {
	case MODE_CALLGRIND:
		run_calls(crit, n);
		printf("callgrind %s %s calls %lu sink %u\n", SQUEAL_NUMERIC_NAME,
		       criterion_name(crit), n, (unsigned int)bench_sink);
		return 0;
	case MODE_BRUTE:
		return bench_brute((unsigned int)n);
	case MODE_TIME:
	default:
		return bench_timing((int)repeats, calls);
	}
}
