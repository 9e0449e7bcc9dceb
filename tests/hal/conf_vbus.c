/* SPDX-License-Identifier: MIT */
/*
 * conf_vbus.c: the conformance harness of the in-memory backend (hal/vbus):
 * the wire is the backend's own (hal_vbus_rx_push, hal_vbus_tx_pop), time
 * is its virtual clock. A blocked TX path is a node that refuses every
 * frame (the in-memory controller has no queue of its own: the wire takes a
 * frame at once or refuses it, and hal_can_send says SQ_ENOBUFS).
 */
#include <string.h>

#include "conformance_backend.h"
#include "hal_vbus.h"

/* The CAN error class of another node's protocol error (linux/can/error.h
 * CAN_ERR_PROT): only the HAL_CAN_FLAG_ERR flag matters to hal.h. */
#define ERR_CLASS_PROT 0x08U

const char *conf_backend_name(void)
{
	return "vbus";
}

int conf_backend_setup(void)
{
	hal_vbus_reset();
	hal_vbus_set_time_us(1000000U);
	return SQ_OK;
}

void conf_backend_teardown(void)
{
}

uint32_t conf_bus_count(void)
{
	return HAL_CAN_BUSES;
}

bool conf_bus_fd(uint8_t bus)
{
	(void)bus;
	return true; /* every in-memory bus carries FD frames */
}

int conf_wire_inject(uint8_t bus, const hal_can_frame_t *frame)
{
	hal_can_frame_t f = *frame;
	int rc;

	f.timestamp_us = hal_time_us();
	rc = hal_vbus_rx_push(bus, &f);
	return (rc == SQ_ENOENT) ? SQ_OK : rc; /* filtered: still sent on the wire */
}

int conf_wire_take(uint8_t bus, hal_can_frame_t *frame)
{
	return hal_vbus_tx_pop(bus, frame);
}

int conf_force_error_frame(uint8_t bus)
{
	hal_can_frame_t f;

	memset(&f, 0, sizeof(f));
	f.id = ERR_CLASS_PROT;
	f.flags = HAL_CAN_FLAG_ERR;
	f.dlc = 8U;
	f.timestamp_us = hal_time_us();
	return hal_vbus_rx_push(bus, &f);
}

int conf_force_bus_off(uint8_t bus, bool on)
{
	hal_can_status_t st;
	int rc = hal_can_get_status(bus, &st);

	if (rc != SQ_OK) {
		return rc;
	}
	/* What the bus hands in knows nothing of the firmware: mode NORMAL,
	 * no refusals, no bus-off count (the backend's own: it counts the
	 * entry). The backend must keep its mode and counts. */
	st.mode = HAL_CAN_MODE_NORMAL;
	st.tx_refused_listen_only = 0U;
	st.bus_off_count = 0U;
	st.state_changes = 0U;
	st.state = on ? HAL_CAN_STATE_BUS_OFF : HAL_CAN_STATE_ERROR_ACTIVE;
	st.tx_error_count = on ? 255U : 0U;
	hal_vbus_set_status(bus, &st);
	return SQ_OK;
}

static int refuse_all(uint8_t bus, const hal_can_frame_t *frame)
{
	(void)bus;
	(void)frame;
	return SQ_ENOBUFS;
}

int conf_block_tx(uint8_t bus, bool blocked)
{
	hal_vbus_set_sink(bus, blocked ? refuse_all : NULL);
	return SQ_OK;
}

void conf_let_time_pass(uint32_t us)
{
	hal_vbus_set_time_us(hal_time_us() + us);
}
