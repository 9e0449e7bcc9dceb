/* SPDX-License-Identifier: MIT */
/*
 * input_rx: one configured input (calib_input_t) applied to received frames,
 * the only thing the monitor calls for its inputs, and the same code that
 * `squeal-sim decode --inputs-csv` uses to show what the monitor sees:
 *
 *   input_rx_matches()  identifier, 11/29-bit and every selector's range
 *   input_rx_frame()    DLC -> protection (none, P01, P02, counter) ->
 *                       raw value -> "not available" -> qualifier bit
 *   input_rx_plausible() range and rate in the raw domain (the physical
 *                       min/max/step_max of the calibration converted once)
 *   input_conv_apply(&cfg->conv, value)  v0 [um/s], N [mN] or T [mNm]
 */
#ifndef INPUT_RX_H
#define INPUT_RX_H

#include <stdbool.h>
#include <stdint.h>

#include "calib.h"
#include "e2e_p01.h"
#include "hal.h"
#include "input_conv.h"

/* The first check a frame failed (decode's `reason` column, in order). */
typedef enum {
	INPUT_RX_OK = 0,
	INPUT_RX_DLC,          /* shorter than min_dlc (or not exactly it)   */
	INPUT_RX_NA,           /* a "not available" raw value                */
	INPUT_RX_QUALIFIER,    /* the qualifier bit says invalid             */
	INPUT_RX_CRC,          /* P01/P02 CRC                                */
	INPUT_RX_COUNTER,      /* counter jump beyond max_delta_counter      */
	INPUT_RX_REPEATED,     /* same counter again: no new data            */
	INPUT_RX_IMPLAUSIBLE,  /* out of range or rate                       */
	INPUT_RX_REASON_COUNT
} input_rx_reason_t;

typedef struct {
	calib_input_t desc;
	input_conv_t conv;
	int64_t raw_min;       /* plausible sign-extended raw values         */
	int64_t raw_max;
	int64_t raw_step;      /* largest plausible change between frames    */
} input_rx_cfg_t;

typedef struct {
	uint8_t reason;        /* input_rx_reason_t (before plausibility)    */
	uint8_t e2e_status;    /* e2e_p01_status_t; NONEWDATA when unprotected */
	uint8_t lost;          /* frames lost (OKSOMELOST)                   */
	uint32_t raw;          /* extracted bits (not for DLC)               */
	int64_t value;         /* raw, sign-extended when signed             */
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

/* Check and extract one matching frame, advancing the E2E/counter state. */
input_rx_result_t input_rx_frame(const input_rx_cfg_t *cfg, e2e_p01_rx_t *e2e,
				 const hal_can_frame_t *f);

/* Range, then rate against the previous value; every value checked here
 * becomes the previous one (as the monitor always did: a real step costs
 * one frame, a spike two). */
bool input_rx_plausible(const input_rx_cfg_t *cfg, bool *has_prev, int64_t *prev,
			int64_t value);

/* "ok", "dlc", "na", "qualifier", "crc", "counter", "repeated", "implausible" */
const char *input_rx_reason_name(input_rx_reason_t r);

#endif /* INPUT_RX_H */
