/* SPDX-License-Identifier: MIT */
/*
 * hal_can_common.c: the frame check, the send admission, the filter check
 * and the bus-state change that every CAN backend shares (see
 * hal_can_common.h).
 */
#include "hal_can_common.h"

#include <stddef.h>

bool hal_can_format_ok(uint8_t flags, uint8_t len)
{
	const bool fd = (flags & HAL_CAN_FLAG_FDF) != 0U;
	bool ok;

	if (fd) {
		ok = ((flags & (HAL_CAN_FLAG_RTR | HAL_CAN_FLAG_ERR)) == 0U) &&
		     (hal_can_len_to_dlc(len) != 0xFFU);
	} else {
		ok = ((flags & (HAL_CAN_FLAG_BRS | HAL_CAN_FLAG_ESI)) == 0U) &&
		     (len <= HAL_CAN_CLASSIC_MAX_DLEN);
	}
	return ok;
}

int hal_can_frame_check(const hal_can_frame_t *frame)
{
	int rc = SQ_OK;

	HAL_REQUIRE(frame != NULL);
	if (!hal_can_format_ok(frame->flags, frame->dlc) ||
	    ((frame->flags & (uint8_t)~HAL_CAN_SEND_FLAGS) != 0U) ||
	    (frame->id > hal_can_id_max(frame->flags))) {
		rc = SQ_EINVAL;
	}
	return rc;
}

int hal_can_send_admit(const hal_can_frame_t *frame, hal_can_status_t *status, bool fd_on)
{
	int rc = hal_can_frame_check(frame);

	HAL_REQUIRE(!fd_on || (HAL_CAN_MAX_DLEN >= HAL_CAN_FD_MAX_DLEN));
	if (rc != SQ_OK) {
		/* malformed: whatever the bus */
	} else if (status == NULL) {
		rc = SQ_ENODEV;
	} else if (((frame->flags & HAL_CAN_FLAG_FDF) != 0U) && !fd_on) {
		/* never truncated to a classic frame: refused, counted */
		status->fd_unsupported++;
		rc = SQ_ENOTSUP;
	} else if (status->mode == HAL_CAN_MODE_LISTEN_ONLY) {
		status->tx_refused_listen_only++;
		rc = SQ_EPERM;
	} else {
		/* admitted: the backend's own state decides */
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
