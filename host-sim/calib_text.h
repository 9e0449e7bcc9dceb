/* SPDX-License-Identifier: MIT */
/*
 * calib_text: the calibration block (firmware/monitor/calib.h) as a text
 * file a person edits, for `squeal-sim ecu --calib FILE`.
 *
 * Format (docs/calib-example.txt lists every key with its unit, default and
 * range):
 *   - one `key = value` per line; blanks around `=` are optional;
 *   - `#` starts a comment (to the end of the line); blank lines are ignored;
 *   - keys are calib_t's field names with the stored unit replaced by the
 *     physical one where that is natural: `mass_kg = 1.0` (stored Q16),
 *     `pad_radius_m = 0.12` (stored in um), `speed_max_radps = 400`
 *     (stored in the DBC's 0.01 rad/s), `v0_min_mps = 0.01`, ...;
 *   - numbers are decimal (`1.5`, `2e-3`); identifiers and integer keys
 *     also take hex (`0x110`); `criterion` is `exact` or `cubic`;
 *     `e2e_check_inputs` is `0`/`1` (or `no`/`yes`);
 *   - Q-format model parameters are rounded to the nearest stored step;
 *     every other key must be a whole multiple of its resolution (e.g.
 *     `pad_radius_m = 0.1234567` is refused: the block stores whole um);
 *   - keys not given keep calib_default()'s value;
 *   - refused: unknown keys, a key given twice, a bad number, a value out
 *     of range, and a file whose keys together do not validate
 *     (calib_validate: identifiers must differ, mu_inf + delta_mu >= 0).
 *   - `input_iface = NAME` (host only, never in the ECU block): the log or
 *     SocketCAN interface the inputs come from (calib_names_t.input_iface);
 *   - a file is accepted only when every corner sets up exactly as written
 *     (calib_validate() runs the same preparation as the monitor).
 * Errors read `FILE:LINE: message` (LINE omitted for whole-file checks).
 */
#ifndef CALIB_TEXT_H
#define CALIB_TEXT_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "calib.h"
#include "calib_sections.h"

/*
 * Parse a calibration text from f; name is used in messages. *out is
 * written only on success. On failure err (if errlen > 0) holds one line.
 * Returns 0 (SQ_OK), SQ_EBADMSG (a bad line or an invalid result),
 * SQ_EIO (read error) or SQ_EINVAL (NULL arguments).
 */
int calib_text_parse(FILE *f, const char *name, calib_t *out, char *err,
		     size_t errlen);

/* Open path and parse it; SQ_ENOENT (with err) when it cannot be opened. */
int calib_text_load(const char *path, calib_t *out, char *err, size_t errlen);

/*
 * The same, also giving the names of the `[input NAME]` sections (by index
 * in out->inputs; empty for the legacy form). docs/calib-input-map.md
 * describes the sections.
 */
int calib_text_parse_map(FILE *f, const char *name, calib_t *out, calib_names_t *names,
			 char *err, size_t errlen);
int calib_text_load_map(const char *path, calib_t *out, calib_names_t *names, char *err,
			size_t errlen);

/*
 * The brake of one corner of a loaded calibration: pos_name NULL gives the
 * flat keys' brake (every corner's default), "FL".."RR" (any case) the
 * [corner] of that position. 0, or -1 with msg (unknown name, no such
 * corner in the calibration).
 */
int calib_text_brake(const calib_t *cal, const char *pos_name, calib_corner_t *brake,
		     char *msg, size_t msglen);

/*
 * Write a complete file for cal: every key, in the shortest form that parses
 * back to exactly the same stored value, with its unit and range as a
 * comment. Returns 0, SQ_EINVAL (NULL or cal does not validate), SQ_EIO.
 */
int calib_text_write(FILE *f, const calib_t *cal);

/* The same with the host-only names of a loaded file (input_iface, the
 * [input] names and their signal lines); names may be NULL. */
int calib_text_write_map(FILE *f, const calib_t *cal, const calib_names_t *names);

/* Introspection, for tests and docs: the number of keys and key i's name
 * (NULL past the end). */
size_t calib_text_key_count(void);
const char *calib_text_key_name(size_t i);

#endif /* CALIB_TEXT_H */
