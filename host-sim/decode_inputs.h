/* SPDX-License-Identifier: MIT */
/*
 * decode_inputs: `squeal-sim decode --calib FILE`: each configured input of
 * a calibration's input map as the monitor sees it, through the firmware's
 * own input_rx (same checks, same order, same conversion):
 *
 *   text   after a frame's line, one line per input it carries:
 *            "  NAME raw=R phys=P UNIT valid=1 reason=ok FL:v0_mps=11.111111"
 *          (force inputs: FL:force_N=..., torque at the corner's last v0)
 *   CAN FD frames are judged like classic ones (the input's fd setting says
 *   which format it expects); a frame the HAL of this build cannot hold (CAN
 *   XL, FD longer than HAL_CAN_MAX_DLEN) is counted and said at the end.
 *   CSV    (--inputs-csv) only these lines, header first:
 *            t_s,iface,id,input,raw,physical,unit,valid,reason
 *          (the agreed format, /work/specs: docs/calib-input-map.md)
 */
#ifndef DECODE_INPUTS_H
#define DECODE_INPUTS_H

#include <stdbool.h>
#include <stdio.h>

#include "calib.h"
#include "calib_sections.h"
#include "candump_log.h"
#include "input_rx.h"

typedef struct {
	calib_t cal;
	calib_names_t names;
	uint32_t n_inputs;
	uint32_t n_corners;
	input_rx_cfg_t rx[CALIB_MAX_INPUTS];
	input_rx_state_t st[CALIB_MAX_INPUTS];
	/* per corner: its inputs prepared with its geometry, its last v0 */
	calib_corner_t corner[CALIB_MAX_CORNERS];
	input_rx_cfg_t corner_rx[CALIB_MAX_CORNERS][2];
	int32_t corner_v0_umps[CALIB_MAX_CORNERS];
	/* frames this build's HAL cannot hold, so no input can use them */
	uint64_t skipped_xl;
	uint64_t skipped_fd;          /* CAN FD longer than HAL_CAN_MAX_DLEN */
} decode_inputs_t;

/* Load the calibration (text file). 0, or -1 with the error on stderr. */
int decode_inputs_load(decode_inputs_t *d, const char *path);

void decode_inputs_csv_header(FILE *out);

/* One frame: CSV rows or text lines for every input it carries. */
void decode_inputs_frame(decode_inputs_t *d, const candump_frame_t *f, bool csv, FILE *out);

/* After the log: one line on out for the frames no input could use because
 * this build cannot hold them (nothing when there were none). */
void decode_inputs_summary(const decode_inputs_t *d, FILE *out);

#endif /* DECODE_INPUTS_H */
