/* SPDX-License-Identifier: MIT */
#include "plant_scenario.h"

#include <ctype.h>
#include <errno.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "num_text.h"
#include "text_errf.h"

const char *const plant_scenario_names[] = { "stop", "creep", "sweep", "point", NULL };

/* stop: 30 m/s -> 0 at 6 m/s^2 (5 s), the paper's 9 kN pad force. The
 * half-second holds let the ECU see a settled stable state first and a
 * settled "not sliding" last. */
static const plant_row_t stop_rows[] = {
	{ 0.0, 30.0, 9000.0 },
	{ 0.5, 30.0, 9000.0 },
	{ 5.5, 0.0, 9000.0 },
	{ 6.0, 0.0, 9000.0 },
};

/* creep: rolling at walking pace with a light brake: v0 = 0.4 .. 0.16 m/s
 * at the pad, around the Hopf border of 1500 N (v_H = 0.336 m/s). */
static const plant_row_t creep_rows[] = {
	{ 0.0, 1.0, 1500.0 },
	{ 6.0, 0.4, 1500.0 },
	{ 12.0, 1.0, 1500.0 },
};

static void set_name(plant_scenario_t *out, const char *name)
{
	snprintf(out->name, sizeof(out->name), "%s", name);
}

static void copy_rows(plant_scenario_t *out, const plant_row_t *rows, size_t n)
{
	memcpy(out->rows, rows, n * sizeof(rows[0]));
	out->count = n;
}

int plant_scenario_builtin(const char *name, double point_speed_mps,
			   double point_force_n, plant_scenario_t *out)
{
	if ((name == NULL) || (out == NULL)) {
		return -1;
	}
	if (strcmp(name, "stop") == 0) {
		copy_rows(out, stop_rows, sizeof(stop_rows) / sizeof(stop_rows[0]));
	} else if (strcmp(name, "creep") == 0) {
		copy_rows(out, creep_rows, sizeof(creep_rows) / sizeof(creep_rows[0]));
	} else if (strcmp(name, "sweep") == 0) {
		static const double forces_n[] = { 3000.0, 6000.0, 9000.0, 12000.0 };
		size_t i;
		size_t n = 0;

		/* each force: 10 m/s down to 0.5 m/s and back up; the force steps
		 * at the top (3 kN per step: within the plausibility rate limit) */
		for (i = 0; i < sizeof(forces_n) / sizeof(forces_n[0]); i++) {
			const double t0 = 8.0 * (double)i;

			out->rows[n++] = (plant_row_t){ t0 + 0.01, 10.0, forces_n[i] };
			out->rows[n++] = (plant_row_t){ t0 + 4.0, 0.5, forces_n[i] };
			out->rows[n++] = (plant_row_t){ t0 + 8.0, 10.0, forces_n[i] };
		}
		out->rows[0].time_s = 0.0;
		out->count = n;
	} else if (strcmp(name, "point") == 0) {
		if (!(point_speed_mps >= 0.0) || !(point_force_n >= 0.0)) {
			return -1;
		}
		out->rows[0] = (plant_row_t){ 0.0, point_speed_mps, point_force_n };
		out->rows[1] = (plant_row_t){ 10.0, point_speed_mps, point_force_n };
		out->count = 2;
	} else {
		return -1;
	}
	set_name(out, name);
	return 0;
}

/* One number token (num_text.h's decimal); false if it is not one. */
static bool take_number(char **p, double *out)
{
	char token[64];
	char *s = *p;
	size_t len;

	while (isspace((unsigned char)*s)) {
		s++;
	}
	len = strcspn(s, " \t\r\n\v\f");
	if ((len == 0U) || (len >= sizeof(token))) {
		return false;
	}
	memcpy(token, s, len);
	token[len] = '\0';
	if (!num_text_real(token, out)) {
		return false;
	}
	*p = s + len;
	return true;
}

int plant_scenario_parse(FILE *f, const char *name, plant_scenario_t *out,
			 char *err, size_t errlen)
{
	static const char *const cols[3] = { "time_s", "speed_mps", "force_n" };
	char line[512];
	unsigned int lineno = 0;
	size_t n = 0;

	if ((f == NULL) || (out == NULL)) {
		text_errf(err, errlen, "plant_scenario_parse: NULL argument");
		return -1;
	}
	if (name == NULL) {
		name = "<scenario>";
	}
	while (fgets(line, sizeof(line), f) != NULL) {
		char *hash = strchr(line, '#');
		char *p = line;
		double v[3];
		int c;

		lineno++;
		if ((strchr(line, '\n') == NULL) && !feof(f)) {
			text_errf(err, errlen, "%s:%u: line too long", name, lineno);
			return -1;
		}
		if (hash != NULL) {
			*hash = '\0';
		}
		while (isspace((unsigned char)*p)) {
			p++;
		}
		if (*p == '\0') {
			continue;
		}
		for (c = 0; c < 3; c++) {
			if (!take_number(&p, &v[c])) {
				char *tok = p;

				while (isspace((unsigned char)*tok)) {
					tok++;
				}
				tok[strcspn(tok, " \t\r\n")] = '\0';
				if (*tok == '\0') {
					text_errf(err, errlen, "%s:%u: expected 3 columns (time_s speed_mps force_n), missing %s",
						name, lineno, cols[c]);
				} else {
					text_errf(err, errlen, "%s:%u: %s is not a number: '%s'",
						name, lineno, cols[c], tok);
				}
				return -1;
			}
		}
		while (isspace((unsigned char)*p)) {
			p++;
		}
		if (*p != '\0') {
			text_errf(err, errlen, "%s:%u: more than 3 columns (time_s speed_mps force_n)",
				name, lineno);
			return -1;
		}
		if (v[0] < 0.0) {
			text_errf(err, errlen, "%s:%u: time_s must be >= 0", name, lineno);
			return -1;
		}
		if ((n > 0U) && !(v[0] > out->rows[n - 1U].time_s)) {
			text_errf(err, errlen, "%s:%u: time_s %g is not after the previous row's %g",
				name, lineno, v[0], out->rows[n - 1U].time_s);
			return -1;
		}
		if (v[1] < 0.0) {
			text_errf(err, errlen, "%s:%u: speed_mps must be >= 0", name, lineno);
			return -1;
		}
		if (v[2] < 0.0) {
			text_errf(err, errlen, "%s:%u: force_n must be >= 0", name, lineno);
			return -1;
		}
		if (n >= PLANT_SCENARIO_MAX_ROWS) {
			text_errf(err, errlen, "%s:%u: more than %u rows", name, lineno,
				PLANT_SCENARIO_MAX_ROWS);
			return -1;
		}
		out->rows[n++] = (plant_row_t){ v[0], v[1], v[2] };
	}
	if (ferror(f)) {
		text_errf(err, errlen, "%s: read error", name);
		return -1;
	}
	if (n == 0U) {
		text_errf(err, errlen, "%s: no rows (expected lines 'time_s speed_mps force_n')", name);
		return -1;
	}
	out->count = n;
	set_name(out, name);
	return 0;
}

int plant_scenario_load(const char *path, plant_scenario_t *out, char *err,
			size_t errlen)
{
	FILE *f = fopen(path, "r");
	int rc;

	if (f == NULL) {
		text_errf(err, errlen, "%s: cannot open: %s", path, strerror(errno));
		return -1;
	}
	rc = plant_scenario_parse(f, path, out, err, errlen);
	fclose(f);
	return rc;
}

void plant_scenario_eval(const plant_scenario_t *sc, double t_s,
			 double *speed_mps, double *force_n)
{
	size_t lo = 0;
	size_t hi;
	double w;

	if (t_s <= sc->rows[0].time_s) {
		*speed_mps = sc->rows[0].speed_mps;
		*force_n = sc->rows[0].force_n;
		return;
	}
	if (t_s >= sc->rows[sc->count - 1U].time_s) {
		*speed_mps = sc->rows[sc->count - 1U].speed_mps;
		*force_n = sc->rows[sc->count - 1U].force_n;
		return;
	}
	/* binary search: rows[lo].time_s <= t < rows[hi].time_s */
	hi = sc->count - 1U;
	while (hi - lo > 1U) {
		const size_t mid = lo + (hi - lo) / 2U;

		if (sc->rows[mid].time_s <= t_s) {
			lo = mid;
		} else {
			hi = mid;
		}
	}
	w = (t_s - sc->rows[lo].time_s) / (sc->rows[hi].time_s - sc->rows[lo].time_s);
	*speed_mps = sc->rows[lo].speed_mps + w * (sc->rows[hi].speed_mps - sc->rows[lo].speed_mps);
	*force_n = sc->rows[lo].force_n + w * (sc->rows[hi].force_n - sc->rows[lo].force_n);
}

double plant_scenario_end_s(const plant_scenario_t *sc)
{
	return sc->rows[sc->count - 1U].time_s;
}
