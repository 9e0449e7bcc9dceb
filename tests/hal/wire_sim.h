/* SPDX-License-Identifier: MIT */
/*
 * The CAN wires of a host peripheral simulation (stm32f4/bxcan_sim.c,
 * stm32g4/fdcan_sim.c): per bus, the frames the simulated controllers put
 * on the wire, oldest first, for the test to take (a full wire drops), and
 * the dominant bits others drive into a controller's frames (an ACK, an
 * error flag).
 */
#ifndef WIRE_SIM_H
#define WIRE_SIM_H

#include <stdbool.h>
#include <stdint.h>

#include "hal.h"

#define WIRE_SIM_BUSES 2U
#define WIRE_SIM_LEN 512U

void wire_sim_reset(void);
void wire_sim_push(uint32_t bus, const hal_can_frame_t *f);
void wire_sim_dominant(uint32_t bus);

bool sim_wire_take(uint8_t bus, hal_can_frame_t *f);
uint32_t sim_wire_count(uint8_t bus);
uint32_t sim_dominant_count(uint8_t bus);

#endif
