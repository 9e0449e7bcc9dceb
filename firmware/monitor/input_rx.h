/* SPDX-License-Identifier: MIT */
/*
 * input_rx: one configured input (calib_input_t) applied to received frames,
 * the only thing the monitor calls for its inputs, and the same code that
 * `squeal-sim decode --inputs-csv` uses to show what the monitor sees:
 *
 *   input_rx_matches()  identifier, 11/29-bit and every selector's range
 *   input_rx_judge()    the frame's one verdict, decided here and nowhere
 *                       else: DLC -> protection (none, P01, P02, P05, counter) ->
 *                       raw value -> "not available" -> qualifier bit ->
 *                       range -> step (the physical min/max/step_max of the
 *                       calibration converted once to the raw domain)
 *   input_conv_apply(&cfg->conv, value)  v0 [um/s], N [mN] or T [mNm]
 *
 * The caller only records a verdict (counters, staleness, faults); it never
 * checks the frame again.
 */
#ifndef INPUT_RX_H
#define INPUT_RX_H

#include <stdbool.h>
#include <stdint.h>

#include "calib.h"
#include "e2e_p01.h"
#include "hal.h"
#include "input_conv.h"

/* The first check a frame failed, in the order they are made (decode's
 * `reason` column). */
typedef enum {
	INPUT_RX_OK = 0,
	INPUT_RX_DLC,          /* shorter than min_dlc (or not exactly it),
				* or of the wrong format (classic for an FD
				* message, FD for a classic one)             */
	INPUT_RX_CRC,          /* P01/P02/P05 CRC                            */
	INPUT_RX_COUNTER,      /* counter jump beyond max_delta_counter      */
	INPUT_RX_REPEATED,     /* same counter again: no new data            */
	INPUT_RX_NA,           /* a "not available" raw value                */
	INPUT_RX_QUALIFIER,    /* the qualifier bit says invalid             */
	INPUT_RX_RANGE,        /* outside the plausible min .. max           */
	INPUT_RX_STEP,         /* changed by more than step_max since the
				* previous value                             */
	INPUT_RX_REASON_COUNT
} input_rx_reason_t;

typedef struct {
	calib_input_t desc;
	input_conv_t conv;
	int64_t raw_min;       /* plausible sign-extended raw values         */
	int64_t raw_max;
	int64_t raw_step;      /* largest plausible change between frames    */
} input_rx_cfg_t;

/* What the input stage remembers of one input between its frames. */
typedef struct {
	e2e_p01_rx_t e2e;      /* protection's receiver (P01, P02, counter)  */
	bool has_prev;         /* prev holds a value (the step check applies) */
	int64_t prev;          /* the last value the range/step checks saw   */
} input_rx_state_t;

/* The verdict on one frame: used (INPUT_RX_OK) or the reason why not. */
typedef struct {
	uint8_t reason;        /* input_rx_reason_t                          */
	uint8_t e2e_status;    /* e2e_p01_status_t; NONEWDATA when unprotected */
	uint8_t lost;          /* frames lost (OKSOMELOST)                   */
	uint32_t raw;          /* extracted bits (not for DLC)               */
	int64_t value;         /* raw, sign-extended when signed (not for DLC) */
} input_rx_result_t;

/*
 * Contracts (hal.h): NULL pointers are programming errors in every
 * function here, and so is a descriptor calib_input_check() refuses (the
 * calibration is validated before its inputs are set up). Frames are data:
 * whatever they hold gives a reason, never a contract failure.
 *
 * Prepare an input for a corner's geometry: conversion and raw bounds,
 * through calib_input_prepare() (which calib_validate() runs for every
 * corner: a validated calibration always sets up). SQ_OK or SQ_EINVAL (a
 * geometry the calibration does not give, e.g. a pressure for a corner
 * without piston area).
 */
int input_rx_setup(const calib_input_t *desc, const input_geom_t *geom,
		   input_rx_cfg_t *cfg);

/* Does this frame carry the input (identifier, EXT flag, and each given
 * selector's raw value within its range)? Remote frames never do. A frame
 * too short for a selector matches (and then fails the DLC check). *id_only is set when only the identifier
 * (not the frame format) matched, so the caller can count it. */
bool input_rx_matches(const input_rx_cfg_t *cfg, const hal_can_frame_t *f, bool *id_only);

/* Start (or, after an outage, restart) an input's receive state. */
void input_rx_state_init(input_rx_state_t *st);

/*
 * The verdict on one matching frame, every check in the order of
 * input_rx_reason_t; the first that fails is the reason:
 *   DLC         the frame's format (FDF as the input's fd) and length (the
 *               protection still runs one receive
 *               cycle with the configured length, which fails: a frame of
 *               the wrong length is one cycle of the E2E state machine);
 *   protection  CRC, counter jump, repeated counter (OKSOMELOST is used,
 *               with `lost` frames);
 *   NA          na_raw / na_raw2;
 *   qualifier   the qualifier bit;
 *   range       outside raw_min .. raw_max;
 *   step        |value - previous| > raw_step.
 * Advances the E2E/counter state. Every value that reaches the range check
 * becomes the previous one (a real step costs one frame, a spike two).
 */
input_rx_result_t input_rx_judge(const input_rx_cfg_t *cfg, input_rx_state_t *st,
				 const hal_can_frame_t *f);

/* "ok", "dlc", "crc", "counter", "repeated", "na", "qualifier", "range",
 * "step" */
const char *input_rx_reason_name(input_rx_reason_t r);

#endif /* INPUT_RX_H */
