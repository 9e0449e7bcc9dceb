/* SPDX-License-Identifier: MIT */
/*
 * The HAL conformance harness for the FDCAN driver (hal/stm32g4/fdcan.c,
 * built with -DFDCAN_SIM) on the simulated registers and message RAM of
 * tests/hal/stm32g4/fdcan_sim.c: FDCAN1 = bus 0, FDCAN2 = bus 1. Both buses
 * carry FD frames. All but these two answers: tests/hal/conf_can_sim.c.
 */
#include "conformance_backend.h"

const char *conf_backend_name(void)
{
	return "fdcan";
}

bool conf_bus_fd(uint8_t bus)
{
	(void)bus;
	return true; /* FDCAN carries FD frames on both buses */
}
