/* SPDX-License-Identifier: MIT */
/*
 * hal_vbus: a virtual CAN bus and a virtual clock behind the same hal.h, for
 * running the unchanged firmware offline (squeal-sim replay, the demo without
 * vcan0) deterministically in virtual time.
 *
 * Once hal_vbus_enable() is called, hal_can_*, hal_time_us, hal_cycles,
 * hal_idle_until and hal_calib_read/write of the Linux HAL are served from
 * here instead of SocketCAN and the system clock. The driver program moves
 * time forward and frames in and out; nothing waits.
 */
#ifndef HAL_VBUS_H
#define HAL_VBUS_H

#include <stdbool.h>
#include <stdint.h>

#include "hal.h"

#define HAL_VBUS_RX_LEN 256U /* frames waiting for the firmware          */
#define HAL_VBUS_TX_LEN 256U /* frames sent by the firmware, not yet taken */

void hal_vbus_enable(void);
bool hal_vbus_active(void);

/* Virtual time; never goes back (an earlier value is ignored). */
void hal_vbus_set_time_us(uint64_t t_us);

/*
 * Offer a received frame to the firmware, stamped with the current virtual
 * time, as the controller would: frames the firmware's RX filter rejects are
 * dropped here (SQ_ENOENT), a full RX queue drops and counts (SQ_ENOBUFS).
 */
int hal_vbus_push_rx(const hal_can_frame_t *frame);

/* Take the oldest frame the firmware sent: SQ_OK or SQ_EAGAIN. */
int hal_vbus_pop_tx(hal_can_frame_t *frame);

/* Controller status the firmware will read (bus-off etc.). */
void hal_vbus_set_status(const hal_can_status_t *status);

/* Calibration storage content (NULL/0: nothing stored). Copied. */
int hal_vbus_set_calib(const uint8_t *block, uint32_t len);

/* While set, hal_can_send() answers SQ_ENOBUFS (TX queue full injection). */
void hal_vbus_set_tx_full(bool full);

typedef struct {
	uint64_t rx_pushed;
	uint64_t rx_filtered;
	uint64_t rx_overflow;
	uint64_t tx_frames;
	uint64_t tx_refused;
} hal_vbus_stats_t;
void hal_vbus_get_stats(hal_vbus_stats_t *stats);

/* Used by the Linux HAL's hal_* functions while the virtual bus is active. */
int hal_vbus_can_send(const hal_can_frame_t *frame);
int hal_vbus_can_receive(hal_can_frame_t *frame);
int hal_vbus_can_get_status(hal_can_status_t *status);
int hal_vbus_can_set_rx_filter(const hal_can_filter_t *filters, uint32_t count);
uint64_t hal_vbus_time_us(void);
int hal_vbus_calib_read(uint8_t *buf, uint32_t len);
int hal_vbus_calib_write(const uint8_t *buf, uint32_t len);

#endif /* HAL_VBUS_H */
