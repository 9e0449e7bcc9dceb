/* SPDX-License-Identifier: MIT */
/*
 * plant_vehicle: `squeal-sim plant --calib car.cal` with an input map sends
 * the inputs in that vehicle's layout: one sender per distinct frame
 * (identifier, format, multiplexer value) of the map, each input's value
 * converted from the scenario's operating point back into the input's unit
 * and raw value (the inverse of the monitor's conversion, in double), the
 * frame protected as its inputs say (P01, P02, P05 or the alive counter).
 * An FD message (fd = yes) is sent as an FD frame of its inputs' largest
 * min_dlc; a classic one as 8 bytes (or exactly min_dlc).
 *
 * The physical value of an input comes from the first corner that uses it
 * (its radii, piston area, efficiency, axle factor): a pressure shared by an
 * axle is the pressure that gives that corner the scenario's force; another
 * corner on the same pressure sees its own N = p A eta k.
 */
#ifndef PLANT_VEHICLE_H
#define PLANT_VEHICLE_H

#include <stdbool.h>
#include <stdint.h>

#include "calib.h"
#include "e2e_p01.h"
#include "hal.h"

typedef struct {
	uint32_t id;
	bool ext;
	bool fd;                            /* sent as a CAN FD frame          */
	uint8_t dlc;
	bool has_mux;
	uint32_t mux_value;                 /* written: the low end of the range */
	bool has_mux2;
	uint32_t mux2_value;
	uint8_t n;                          /* inputs in this frame            */
	uint8_t in[CALIB_MAX_INPUTS];
	uint8_t prot;                       /* input whose protection applies, 0xFF none */
	uint16_t period_ms;
} plant_vframe_t;

/* The frames of a map calibration. Returns their number (0: legacy form). */
uint32_t plant_vehicle_frames(const calib_t *cal, plant_vframe_t frames[CALIB_MAX_INPUTS]);

/* Build one frame at the operating point (vehicle speed, pad force). tx is
 * the frame's counter state (advanced); *saturated counts clamped values. */
void plant_vehicle_pack(const calib_t *cal, const plant_vframe_t *fr, e2e_p01_tx_t *tx,
			double vehicle_mps, double force_n, hal_can_frame_t *f,
			uint64_t *saturated);

/* The physical value of input i (in its unit) at the operating point. */
double plant_vehicle_physical(const calib_t *cal, uint32_t i, double vehicle_mps,
			      double force_n);

#endif /* PLANT_VEHICLE_H */
