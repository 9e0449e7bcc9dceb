/* SPDX-License-Identifier: MIT */
/*
 * hal_can_common.h: the rules every CAN backend of hal.h shares, each
 * written once (hal/common/hal_can_common.c, linked into every backend:
 * hal/linux, hal/vbus, the bxCAN driver), as Zephyr's common CAN send path
 * checks a frame once before any driver sees it. Backends only; the
 * firmware uses hal.h.
 */
#ifndef HAL_CAN_COMMON_H
#define HAL_CAN_COMMON_H

#include <stdbool.h>
#include <stdint.h>

#include "hal.h"

/* The flags a frame to send may carry: an error frame is something a
 * controller reports, never something the firmware sends. */
#define HAL_CAN_SEND_FLAGS ((uint8_t)(HAL_CAN_FLAG_EXT | HAL_CAN_FLAG_RTR))
/* The flags a filter may carry (its kind; RTR is never filtered on). */
#define HAL_CAN_FILTER_FLAGS ((uint8_t)HAL_CAN_FLAG_EXT)

/*
 * hal_can_send()'s frame check, before the backend looks at its bus:
 * SQ_OK, or SQ_EINVAL for a DLC > 8, a flag outside HAL_CAN_SEND_FLAGS
 * (ERR, or a bit hal.h does not define: refused, never ignored), or an
 * identifier beyond hal_can_id_max() of its kind. NULL is a programming
 * error (hal_contract_failed).
 */
int hal_can_frame_check(const hal_can_frame_t *frame);

/*
 * hal_can_set_rx_filter()'s check: SQ_OK, or SQ_EINVAL when a filter has a
 * flag outside HAL_CAN_FILTER_FLAGS or an id or mask beyond its kind's
 * range. More than HAL_CAN_MAX_FILTERS, or NULL with count > 0, is a
 * programming error.
 */
int hal_can_filter_check(const hal_can_filter_t *filters, uint32_t count);

/*
 * The one bus-state change of every backend: status->state becomes next.
 * A change counts in status->state_changes, and an entry into BUS_OFF in
 * status->bus_off_count (so a bus-off that lasts is counted once).
 * Returns true when the state changed. NULL or a state hal.h does not
 * define is a programming error.
 */
bool hal_can_state_change(hal_can_status_t *status, hal_can_state_t next);

#endif /* HAL_CAN_COMMON_H */
