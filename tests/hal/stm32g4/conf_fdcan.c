/* SPDX-License-Identifier: MIT */
/*
 * The HAL conformance harness (conformance_backend.h) for the FDCAN driver
 * (hal/stm32g4/fdcan.c, built with -DFDCAN_SIM) on the simulated registers
 * and message RAM of tests/hal/stm32g4/fdcan_sim.c: FDCAN1 = bus 0, FDCAN2 =
 * bus 1, each on its own wire; "another node" is the simulation's side of
 * that wire. Both buses carry FD frames.
 */
#include "conformance_backend.h"

#include <stddef.h>

#include "fdcan.h"
#include "fdcan_sim.h"
#include "sq_status.h"

const char *conf_backend_name(void)
{
	return "fdcan";
}

int conf_backend_setup(void)
{
	uint8_t bus;

	sim_reset();
	for (bus = 0U; bus < SIM_BUSES; bus++) {
		const int rc = can_ctrl_start(bus, FDCAN_DEFAULT_BITRATE);

		if (rc != SQ_OK) {
			return rc;
		}
	}
	return SQ_OK;
}

void conf_backend_teardown(void)
{
	sim_reset();
}

uint32_t conf_bus_count(void)
{
	return SIM_BUSES;
}

bool conf_bus_fd(uint8_t bus)
{
	(void)bus;
	return true; /* FDCAN carries FD frames on both buses */
}

int conf_wire_inject(uint8_t bus, const hal_can_frame_t *frame)
{
	if (bus >= SIM_BUSES || frame == NULL) {
		return SQ_EINVAL;
	}
	(void)sim_inject(bus, frame);
	return SQ_OK;
}

int conf_wire_take(uint8_t bus, hal_can_frame_t *frame)
{
	if (bus >= SIM_BUSES || frame == NULL) {
		return SQ_EINVAL;
	}
	return sim_wire_take(bus, frame) ? SQ_OK : SQ_EAGAIN;
}

int conf_force_error_frame(uint8_t bus)
{
	if (bus >= SIM_BUSES) {
		return SQ_EINVAL;
	}
	sim_error_frame(bus);
	return SQ_OK;
}

int conf_force_bus_off(uint8_t bus, bool on)
{
	if (bus >= SIM_BUSES) {
		return SQ_EINVAL;
	}
	(void)sim_bus_off(bus, on);
	return SQ_OK;
}

int conf_block_tx(uint8_t bus, bool blocked)
{
	if (bus >= SIM_BUSES) {
		return SQ_EINVAL;
	}
	sim_block_tx(bus, blocked);
	return SQ_OK;
}

void conf_let_time_pass(uint32_t us)
{
	sim_advance_us(us);
}
