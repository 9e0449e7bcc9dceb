/* SPDX-License-Identifier: MIT */
/*
 * What every host CAN controller simulation (stm32f4/bxcan_sim.c,
 * stm32g4/fdcan_sim.c) gives its tests and the shared conformance harness
 * (conf_can_sim.c), whichever controller it models. Each simulation's own
 * header (bxcan_sim.h, fdcan_sim.h) adds its controller's details.
 */
#ifndef CAN_SIM_H
#define CAN_SIM_H

#include <stdbool.h>
#include <stdint.h>

#include "cortex_sim.h"
#include "hal.h"
#include "wire_sim.h"

#define SIM_BUSES 2U

/* Power-on reset of the controllers, the wires and the core. */
void sim_reset(void);
/* Another node sends f on bus's wire; true when the controller ACKed it. */
bool sim_inject(uint8_t bus, const hal_can_frame_t *f);
/* Another node signals an error on bus's wire. */
void sim_error_frame(uint8_t bus);
/* on: the controller goes bus-off; off: the bus lets it recover. True
 * when it is (still or now) not bus-off. */
bool sim_bus_off(uint8_t bus, bool on);
/* While blocked nothing ACKs the controller's frames: they stay pending. */
void sim_block_tx(uint8_t bus, bool blocked);

#endif
