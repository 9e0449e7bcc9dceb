/* SPDX-License-Identifier: MIT */
/*
 * calib_map: what the input map and corners of a calibration mean
 * (calib.h, docs/calib-input-map.md): the checks beyond each field's stored
 * range, and one corner's view (its brake, its speed and force inputs)
 * whether the calibration has an input map or only the legacy flat keys.
 */
#ifndef CALIB_MAP_H
#define CALIB_MAP_H

#include <stdint.h>

#include "calib.h"

/* Where a check failed: the input or corner index and a one-line reason. */
typedef struct {
	int8_t input;     /* -1: not an input's problem */
	int8_t corner;    /* -1: not a corner's problem */
	const char *why;
} calib_map_error_t;

/* SQ_OK or SQ_EINVAL (with *err when err != NULL). */
int calib_map_check(const calib_t *cal, calib_map_error_t *err);
int calib_map_validate(const calib_t *cal);

/* One input alone: SQ_OK or SQ_EINVAL with *why. Includes the plausible
 * range (min .. max must hold a raw value) and every selector. */
int calib_input_check(const calib_input_t *in, const char **why);

/*
 * Everything input_rx_setup() does with an input for a corner's geometry:
 * calib_input_check(), the conversion (with in->conv_share_ppm) and the
 * raw bounds. calib_validate() runs it for every corner, so a calibration
 * that validates always sets up. SQ_OK or SQ_EINVAL with *why.
 */
int calib_input_prepare(const calib_input_t *in, const input_geom_t *geom,
			input_conv_t *conv, input_raw_bounds_t *bounds, const char **why);

/* The conversion geometry of a corner. */
input_geom_t calib_corner_geom(const calib_corner_t *corner);

/* The smallest data length in bytes that holds every bit the input uses
 * (the value, selectors, qualifier, E2E header; 0: a bad signal). */
uint8_t calib_input_needed_dlc(const calib_input_t *in);

/* The same, rounded up to a length a frame of the input's format has
 * (fd: 12, 16, 20, 24, 32, 48 or 64 above 8): the default min_dlc. */
uint8_t calib_input_frame_len(const calib_input_t *in);

/* Corners in use: n_corners, or 1 for the legacy form. */
uint32_t calib_corner_count(const calib_t *cal);

/*
 * Corner k of a valid calibration, with copies of its speed and force
 * input descriptors (the legacy form synthesizes DiscSpeed and PadForce);
 * the force copy of a torque input carries the corner's torque_share_ppm
 * in conv_share_ppm.
 * SQ_OK or SQ_EINVAL (k out of range).
 */
int calib_corner_view(const calib_t *cal, uint32_t k, calib_corner_t *corner,
		      calib_input_t *speed, calib_input_t *force);

/* A corner filled with the flat keys (brake and geometry) and the default
 * output identifiers of position pos (0x300.. + 0x10 pos). */
void calib_corner_defaults(const calib_t *cal, uint8_t pos, calib_corner_t *corner);

/* A corner's brake and output identifiers <-> the flat keys of the same
 * names (the text front end converts a corner's keys with the flat rules). */
void calib_corner_from_flat(const calib_t *cal, calib_corner_t *corner);
void calib_flat_from_corner(const calib_corner_t *corner, calib_t *cal);

#endif /* CALIB_MAP_H */
