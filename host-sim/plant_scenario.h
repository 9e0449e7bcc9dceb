/* SPDX-License-Identifier: MIT */
/*
 * plant_scenario: what the test rig does over time, for `squeal-sim plant`:
 * vehicle speed [m/s] and pad normal force [N] as functions of time, given
 * as a table of rows with linear interpolation between them (the built-in
 * scenarios are tables too, so every scenario behaves the same way).
 *
 * Scenario file (e.g. scenarios/stop.txt):
 *   # comment; blank lines ignored; '#' may also end a row
 *   time_s  speed_mps  force_n      one row per line, whitespace separated
 *   - time_s: seconds from the start, >= 0, strictly increasing;
 *   - speed_mps: VEHICLE speed [m/s] (the disc turns at speed / r_w), >= 0;
 *   - force_n: pad normal force [N], >= 0;
 *   - at least one row; before the first row the first row's values hold,
 *     after the last row the last row's values hold.
 * Errors read `FILE:LINE: message`.
 */
#ifndef PLANT_SCENARIO_H
#define PLANT_SCENARIO_H

#include <stddef.h>
#include <stdio.h>

#define PLANT_SCENARIO_MAX_ROWS 4096U

typedef struct {
	double time_s;
	double speed_mps;  /* vehicle speed */
	double force_n;
} plant_row_t;

typedef struct {
	char name[64];
	size_t count;
	plant_row_t rows[PLANT_SCENARIO_MAX_ROWS];
} plant_scenario_t;

/*
 * The built-in scenarios (vehicle speeds; see the table in the .c file):
 *   stop   hold 30 m/s for 0.5 s, brake at a constant 6 m/s^2 to standstill
 *          (5 s), hold 0.5 s; pad force 9000 N throughout
 *   creep  slow rolling 1.0 -> 0.4 -> 1.0 m/s over 12 s at 1500 N
 *   sweep  for pad forces 3, 6, 9 and 12 kN: 10 m/s down to 0.5 m/s and
 *          back up (8 s each, 32 s in all): across the stability map
 *   point  constant; needs point_speed_mps (vehicle) and point_force_n,
 *          lasts 10 s
 * Returns 0, or -1 for an unknown name.
 */
int plant_scenario_builtin(const char *name, double point_speed_mps,
			   double point_force_n, plant_scenario_t *out);

/* Names of the built-ins, NULL-terminated. */
extern const char *const plant_scenario_names[];

/* Parse a scenario file. 0, or -1 with err holding `NAME:LINE: message`. */
int plant_scenario_parse(FILE *f, const char *name, plant_scenario_t *out,
			 char *err, size_t errlen);
int plant_scenario_load(const char *path, plant_scenario_t *out, char *err,
			size_t errlen);

/* Values at t_s (linear interpolation, held outside the table). */
void plant_scenario_eval(const plant_scenario_t *sc, double t_s,
			 double *speed_mps, double *force_n);

/* Time of the last row. */
double plant_scenario_end_s(const plant_scenario_t *sc);

#endif /* PLANT_SCENARIO_H */
