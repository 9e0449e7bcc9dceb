/* SPDX-License-Identifier: MIT */
/*
 * The HAL conformance harness (conformance_backend.h) for an STM32 CAN
 * driver on a host controller simulation (can_sim.h): bus 0 and bus 1 are
 * the two controllers, each with its own wire; "another node" is the
 * simulation's side of that wire. The driver starts through can_ctrl.h.
 * Each simulation's harness adds its name and whether it carries FD frames
 * (stm32f4/conf_bxcan.c, stm32g4/conf_fdcan.c).
 */
#include "conformance_backend.h"

#include <stddef.h>

#include "can_ctrl.h"
#include "can_sim.h"
#include "sq_status.h"

int conf_backend_setup(void)
{
	uint8_t bus;

	sim_reset();
	for (bus = 0U; bus < SIM_BUSES; bus++) {
		const int rc = can_ctrl_start(bus, CAN_CTRL_DEFAULT_BITRATE);

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
