/* SPDX-License-Identifier: MIT */
/*
 * The HAL conformance harness for the bxCAN driver (hal/stm32f4/bxcan.c,
 * built with -DBXCAN_SIM) on the simulated registers of
 * tests/hal/stm32f4/bxcan_sim.c: CAN1 = bus 0, CAN2 = bus 1. All but these
 * two answers: tests/hal/conf_can_sim.c.
 */
#include "conformance_backend.h"

const char *conf_backend_name(void)
{
	return "bxcan-sim";
}

bool conf_bus_fd(uint8_t bus)
{
	(void)bus;
	return false; /* bxCAN is a classic controller */
}
