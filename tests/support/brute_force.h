/* SPDX-License-Identifier: MIT */
/*
 * Brute-force decision of an operating point by simulation, for comparison
 * with the closed-form classification of firmware/model (docs/model.md
 * sections 4 to 6). Host only: double precision, libm.
 *
 * The sliding oscillator in dimensionless form (docs/model.md section 5):
 *
 *     u'' + 2 D u' + u = kappa (exp(u') - 1),   kappa = D / Q
 *
 * with the stick line u' = s = a v0. For Q > 1/2 the steady state u = 0 is
 * stable and surrounded by an unstable limit cycle. Integrated BACKWARDS in
 * time the cycle attracts, so a small perturbation grows onto it. We stop
 *   - when u' reaches the stick line: no sliding cycle below it -> STABLE;
 *   - when successive maxima of u' have settled: the cycle exists below the
 *     stick line -> BISTABLE, and its max u' is returned.
 * Q <= 1/2 (unstable) is decided by the linear test, not by simulation, so
 * it is rejected here.
 */
#ifndef BRUTE_FORCE_H
#define BRUTE_FORCE_H

/* Fixed-step RK4, this many steps per natural period 2 pi (64: the cycle
 * maxima of docs/model.md section 6 agree within 0.005 %, as with 128). */
#define BF_STEPS_PER_PERIOD 64
/* Relative change of successive maxima of u' that counts as settled. */
#define BF_SETTLE_TOL 1e-6
/* Initial perturbation u' = BF_START_DU * min(1, s), u = 0. */
#define BF_START_DU 1e-3
/* Bound on the work of one decision (steps); beyond it: undecided. */
#define BF_MAX_STEPS 20000000L

typedef enum {
	BF_STABLE = 0,   /* u' reached the stick line before a cycle settled */
	BF_BISTABLE = 1, /* an unstable cycle below the stick line was found */
} bf_class_t;

typedef struct {
	bf_class_t decision;
	double cycle_max_du; /* settled max u' of the cycle (BISTABLE only) */
	double last_peak_du; /* last maximum of u' seen                    */
	long steps;          /* RK4 steps taken                             */
	long peaks;          /* maxima of u' seen                           */
} bf_result_t;

/*
 * Decide one point given by its dimensionless numbers: damping D in (0, 1],
 * Q > 1/2 (finite), stick line s > 0 (HUGE_VAL: no stick line, so only a
 * settled cycle ends the run).
 * Returns 0 and fills out; -1 when an argument is outside that domain;
 * -2 when BF_MAX_STEPS passed without a decision (out holds the progress).
 */
int bf_decide(double damping, double q, double stick, bf_result_t *out);

#endif /* BRUTE_FORCE_H */
