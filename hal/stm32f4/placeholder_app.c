/* SPDX-License-Identifier: MIT */
/*
 * Stand-in for firmware/app/ while it does not exist yet: the smallest
 * squeal_main() that exercises the HAL the way the real one does (filters,
 * watchdog, drain RX, kick, idle). mk/target.mk links it only when
 * firmware/app/ has no C sources.
 */
#include "hal.h"
#include "squeal_app.h"

#define PLACEHOLDER_WDG_MS 100U

int squeal_app_init(void)
{
	static const hal_can_filter_t filters[2] = { { 0x100U, HAL_CAN_STD_ID_MAX, 0U },
						     { 0x101U, HAL_CAN_STD_ID_MAX, 0U } };
	int rc = hal_can_set_rx_filter(0U, filters, 2U);

	if (hal_watchdog_start(PLACEHOLDER_WDG_MS) != SQ_OK) {
		rc = SQ_EIO;
	}
	return rc;
}

uint64_t squeal_app_poll(void)
{
	hal_can_frame_t f;
	uint32_t n;

	for (n = 0; n < 32U && hal_can_receive(0U, &f) == SQ_OK; n++) {
		(void)hal_can_send(0U, &f); /* echo: something to do with it */
	}
	hal_watchdog_kick();
	return hal_time_us() + 1000U;
}

int squeal_main(volatile const bool *stop)
{
	int rc = squeal_app_init();

	while (stop == NULL || !*stop) {
		hal_idle_until(squeal_app_poll());
	}
	return rc;
}
