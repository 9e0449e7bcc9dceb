/* SPDX-License-Identifier: MIT */
/*
 * hal_can_common.c: the frame and filter checks and the bus-state change
 * that every CAN backend shares (see hal_can_common.h).
 */
#include "hal_can_common.h"

#include <stddef.h>

int hal_can_frame_check(const hal_can_frame_t *frame)
{
	int rc = SQ_OK;

	HAL_REQUIRE(frame != NULL);
	if ((frame->dlc > HAL_CAN_MAX_DLEN) ||
	    ((frame->flags & (uint8_t)~HAL_CAN_SEND_FLAGS) != 0U) ||
	    (frame->id > hal_can_id_max(frame->flags))) {
		rc = SQ_EINVAL;
	}
	return rc;
}

int hal_can_filter_check(const hal_can_filter_t *filters, uint32_t count)
{
	uint32_t i;
	int rc = SQ_OK;

	HAL_REQUIRE((count <= HAL_CAN_MAX_FILTERS) && ((filters != NULL) || (count == 0U)));
	for (i = 0U; i < count; i++) {
		const uint32_t max = hal_can_id_max(filters[i].flags);

		if (((filters[i].flags & (uint8_t)~HAL_CAN_FILTER_FLAGS) != 0U) ||
		    (filters[i].id > max) || (filters[i].mask > max)) {
			rc = SQ_EINVAL;
		}
	}
	return rc;
}

bool hal_can_state_change(hal_can_status_t *status, hal_can_state_t next)
{
	bool changed = false;

	HAL_REQUIRE((status != NULL) && ((uint32_t)next <= (uint32_t)HAL_CAN_STATE_STOPPED));
	if (status->state != next) {
		status->state_changes++;
		if (next == HAL_CAN_STATE_BUS_OFF) {
			status->bus_off_count++;
		}
		status->state = next;
		changed = true;
	}
	return changed;
}
