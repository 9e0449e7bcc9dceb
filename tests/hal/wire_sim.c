/* SPDX-License-Identifier: MIT */
#include "wire_sim.h"

#include <stdlib.h>
#include <string.h>

static struct {
	hal_can_frame_t q[WIRE_SIM_LEN];
	uint32_t head;
	uint32_t n;
	uint32_t dominant;
} wire[WIRE_SIM_BUSES];

/* a bus the simulation does not have is the harness's mistake */
static void check_bus(uint32_t bus)
{
	if (bus >= WIRE_SIM_BUSES) {
		abort();
	}
}

void wire_sim_reset(void)
{
	memset(wire, 0, sizeof(wire));
}

void wire_sim_push(uint32_t bus, const hal_can_frame_t *f)
{
	check_bus(bus);
	if (wire[bus].n < WIRE_SIM_LEN) {
		wire[bus].q[(wire[bus].head + wire[bus].n) % WIRE_SIM_LEN] = *f;
		wire[bus].n++;
	}
}

void wire_sim_dominant(uint32_t bus)
{
	check_bus(bus);
	wire[bus].dominant++;
}

bool sim_wire_take(uint8_t bus, hal_can_frame_t *f)
{
	check_bus(bus);
	if (wire[bus].n == 0U) {
		return false;
	}
	*f = wire[bus].q[wire[bus].head];
	wire[bus].head = (wire[bus].head + 1U) % WIRE_SIM_LEN;
	wire[bus].n--;
	return true;
}

uint32_t sim_wire_count(uint8_t bus)
{
	check_bus(bus);
	return wire[bus].n;
}

uint32_t sim_dominant_count(uint8_t bus)
{
	check_bus(bus);
	return wire[bus].dominant;
}
