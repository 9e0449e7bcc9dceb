/* SPDX-License-Identifier: MIT */
/*
 * replay_summary: what replay --summary-json adds to the text summary, per
 * corner, taken from the frames the ECU sends (not from the monitor's
 * internals, so it reads a log of 1..4 corners the same way a logger on the
 * bus would):
 *
 *   - episodes: each a maximal time span in which one corner reported one
 *     state (SquealStatus), with the highest warning level, the v0 range
 *     (SquealDetail), the pad force range (SquealDetail2) and the lowest Hopf
 *     margin seen in it; streamed into the JSON document as each one ends,
 *     so memory stays constant however long the log;
 *   - time in each state per corner;
 *   - occupancy: time in each (v0, force) cell per state and corner on a
 *     fixed grid (RS_V0_BINS x RS_FORCE_BINS), for the fleet heat map.
 *
 * Corner k's messages are the base identifiers + k * RS_CORNER_ID_STEP
 * (the default layout: FL keeps 0x300.., FR 0x310.., RL 0x320.., RR 0x330..);
 * replay_summary_set_corner() sets other identifiers.
 *
 * Time accounting: a corner's time starts at its first SquealStatus; the time
 * between two of its frames counts for the state and (v0, force) cell that
 * held before the later one; replay_summary_finish() closes at the end time.
 * Physical values come from the raw signals with the DBC's factors
 * (msg_sig_table), written as exact decimals.
 */
#ifndef REPLAY_SUMMARY_H
#define REPLAY_SUMMARY_H

#include <stdbool.h>
#include <stdint.h>

#include "hal.h"
#include "json_writer.h"
#include "squeal_msgs.h"

#define RS_CORNERS_MAX    4U
#define RS_CORNER_ID_STEP 0x10U
#define RS_N_STATES       MSG_SQUEAL_STATE_SLOTS /* stable, bistable, unstable, not_sliding, fault */
/* The occupancy grid covers a car's pad speeds and forces (30 m/s on the
 * road is v0 = 12 m/s at the default radii); values beyond count in the
 * last cell. 5 states x 80 x 64 cells x 8 bytes = 205 kB per corner. */
#define RS_V0_BIN_CMPS    20U  /* 0.2 m/s per cell (V0_mps raw is 0.01 m/s)  */
#define RS_V0_BINS        80U  /* 0 .. 16 m/s                                */
#define RS_FORCE_BIN_N    500U /* 500 N per cell (Force_N raw is 0.5 N)      */
#define RS_FORCE_BINS     64U  /* 0 .. 32 kN                                 */

typedef struct {
	uint16_t status_id;
	uint16_t detail_id;
	uint16_t detail2_id;
} rs_corner_ids_t;

typedef struct {
	bool open;
	uint8_t state;             /* 0..RS_N_STATES-1                  */
	uint8_t warning_max;
	uint64_t start_us;
	bool have_v0;
	int32_t v0_min;            /* raw V0_mps                        */
	int32_t v0_max;
	bool have_force;
	int32_t force_min;         /* raw Force_N                       */
	int32_t force_max;
	bool have_margin;
	int32_t margin_min;        /* raw HopfMargin_mps                */
} rs_episode_t;

typedef struct {
	rs_corner_ids_t ids;
	bool seen;                 /* a SquealStatus arrived            */
	uint64_t first_us;
	uint64_t last_us;          /* time accounted up to              */
	uint8_t state;
	bool have_v0;              /* last operating point reported     */
	int32_t v0_raw;
	bool have_force;
	int32_t force_raw;
	rs_episode_t ep;
	uint64_t episodes;
	uint64_t state_us[RS_N_STATES];
	bool cells_used;           /* a cell below was written          */
	uint64_t cell_us[RS_N_STATES][RS_V0_BINS][RS_FORCE_BINS]; /* last: see init */
} rs_corner_t;

typedef struct {
	json_writer_t *w;          /* episodes are streamed here        */
	bool finished;
	rs_corner_t corner[RS_CORNERS_MAX];
} replay_summary_t;

/* State slot i (0..RS_N_STATES-1, msg_squeal_state_slot) by its DBC name
 * (msg_squeal_state_name). */
const char *rs_state_name(unsigned i);

/* "key": { state name: seconds, ... } of a time per state slot. */
void rs_json_state_times(json_writer_t *w, const char *key, const uint64_t us[RS_N_STATES]);
extern const char *const rs_corner_names[RS_CORNERS_MAX];

/* Starts with the DBC's identifiers and opens the document's "episodes"
 * array (the caller has begun the top-level object). rs is zero the first
 * time (static storage): the cells, most of rs, are cleared only where a
 * previous use wrote them, so a short replay touches few of its pages. */
void replay_summary_init(replay_summary_t *rs, json_writer_t *w);
/* Corner k (0..3) listens to base + k * RS_CORNER_ID_STEP. */
void replay_summary_set_ids(replay_summary_t *rs, const rs_corner_ids_t *base);
/* Corner k listens to ids (a calibration with other identifiers). */
void replay_summary_set_corner(replay_summary_t *rs, unsigned k, const rs_corner_ids_t *ids);

/* One frame the ECU sent (its timestamp_us is the virtual time). */
void replay_summary_on_frame(replay_summary_t *rs, const hal_can_frame_t *f);

/* Accounts up to end_us, writes the open episodes, closes "episodes" and
 * writes "corners" (per corner: identifiers, time per state, occupancy). */
void replay_summary_finish(replay_summary_t *rs, uint64_t end_us);

#endif /* REPLAY_SUMMARY_H */
