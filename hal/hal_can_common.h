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
#define HAL_CAN_SEND_FLAGS ((uint8_t)(HAL_CAN_FLAG_EXT | HAL_CAN_FLAG_RTR | HAL_CAN_FLAG_FDF | \
				      HAL_CAN_FLAG_BRS | HAL_CAN_FLAG_ESI))
/* The flags a filter may carry (its kind; RTR is never filtered on). */
#define HAL_CAN_FILTER_FLAGS ((uint8_t)HAL_CAN_FLAG_EXT)

/*
 * The format rules of a frame's flags and data length (hal.h), for a frame
 * to send and for one received alike: BRS and ESI only with FDF; FDF never
 * with RTR or ERR; without FDF at most 8 bytes; with FDF a DLC-code length
 * (hal_can_len_to_dlc). true when the frame obeys them.
 */
bool hal_can_format_ok(uint8_t flags, uint8_t len);

/*
 * The one frame check: SQ_OK, or SQ_EINVAL for a frame that breaks
 * hal_can_format_ok(), has a flag outside HAL_CAN_SEND_FLAGS (ERR, or a bit
 * hal.h does not define: refused, never ignored), or an identifier beyond
 * hal_can_id_max() of its kind. NULL is a programming error
 * (hal_contract_failed).
 */
int hal_can_frame_check(const hal_can_frame_t *frame);

/*
 * hal_can_send()'s admission of frame, before the backend touches its bus,
 * in hal.h's order: SQ_EINVAL (hal_can_frame_check, whatever the bus);
 * SQ_ENODEV (status NULL: the bus does not exist here); SQ_ENOTSUP (an FD
 * frame and fd_on false: the bus carries classic frames only; counted in
 * status->fd_unsupported); SQ_EPERM (status->mode is listen-only; counted
 * in status->tx_refused_listen_only); else SQ_OK, and the backend goes on
 * with its own state (stopped, bus-off, queue room). fd_on in a build
 * whose frames hold 8 bytes is a programming error.
 */
int hal_can_send_admit(const hal_can_frame_t *frame, hal_can_status_t *status, bool fd_on);

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
