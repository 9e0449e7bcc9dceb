/* SPDX-License-Identifier: MIT */
/*
 * hal_vbus: the in-memory backend of hal/hal.h, the only one: a virtual
 * clock and HAL_CAN_BUSES virtual CAN buses, for running the unchanged
 * firmware deterministically in virtual time (squeal-sim replay), for the
 * unit tests (tests/support/test_hal.c is a thin test layer on top of it)
 * and for the HAL conformance suite (tests/hal/conf_vbus.c).
 *
 * It is chosen at link time (build/<variant>/libhal_vbus.a instead of
 * libhal_linux.a); nothing switches at run time. The program that links it
 * is "the rest of the bus": it moves time, offers frames other nodes sent
 * and takes the frames the firmware sent. Nothing here waits.
 *
 * Behaviour, per bus:
 *  - RX: hal_vbus_rx_push() offers a frame that arrives at its
 *    timestamp_us (a frame may be queued ahead of time; the queue is kept in
 *    arrival order, equal times in push order). hal_can_receive() hands it
 *    over once the clock has reached that time. The bus's filters
 *    (hal_can_set_rx_filter) are applied when the frame is offered, as a
 *    controller applies them on reception; error frames always pass and
 *    count in status.error_frames when received. A full queue drops the
 *    frame and counts it in status.rx_overruns.
 *  - Frames: classic and CAN FD (up to 64 bytes, FDF/BRS/ESI kept) on
 *    every bus, both ways, as a bus of FD controllers carries both.
 *  - TX: hal_can_send() puts the frame on the wire stamped with the clock:
 *    into the bus's wire FIFO (hal_vbus_tx_pop() takes it), or, when a sink
 *    is registered, straight to the sink (another node; it may refuse with
 *    SQ_ENOBUFS: "no room", nothing sent). Bus-off answers SQ_ENETUNREACH,
 *    stopped SQ_ENETDOWN, listen-only SQ_EPERM (counted in
 *    tx_refused_listen_only); every refusal counts in the stats.
 *  - Status: state and counters as the bus's other nodes make them
 *    (hal_vbus_set_status); the mode is the firmware's (hal_can_set_mode)
 *    and survives every injected status.
 *  - Clock: virtual microseconds; hal_idle_until() moves it to the deadline
 *    or to the next queued frame's arrival, whichever is first. hal_cycles()
 *    is HAL_VBUS_CYCLES_PER_US per virtual microsecond plus a fixed amount
 *    per call (0 by default: the firmware takes no time, so task times and
 *    replay output are deterministic).
 *  - Calibration storage: absent, a stored block (bytes beyond it read as
 *    erased flash, 0xFF), or unreadable (SQ_EIO).
 */
#ifndef HAL_VBUS_H
#define HAL_VBUS_H

#include <stdbool.h>
#include <stdint.h>

#include "hal.h"

#define HAL_VBUS_RX_LEN 4096U /* frames queued for the firmware, per bus  */
#define HAL_VBUS_TX_LEN 256U  /* sent frames on the wire, not yet taken  */
#define HAL_VBUS_CYCLES_PER_US 168U

/* Power-on state: clock 0, every bus started (ERROR_ACTIVE, NORMAL, no
 * filter: everything passes), queues empty, no sink, storage absent,
 * watchdog stopped, no platform fault, reset reason POWER_ON. */
void hal_vbus_reset(void);

/* How many buses exist (1 .. HAL_CAN_BUSES; default HAL_CAN_BUSES): a valid
 * index beyond it answers SQ_ENODEV, as a single-bus chip would. */
void hal_vbus_set_bus_count(uint32_t count);

/* ---- clock ---------------------------------------------------------------- */

/* Never goes back: an earlier time is ignored. */
void hal_vbus_set_time_us(uint64_t t_us);
void hal_vbus_set_cycles_per_call(uint32_t cycles);

/* ---- the wire ------------------------------------------------------------- */

/*
 * Another node sends frame on bus; it arrives at frame->timestamp_us.
 * SQ_OK (queued), SQ_ENOENT (the bus's filters reject it: dropped, as the
 * controller would), SQ_ENOBUFS (queue full: dropped, rx_overruns + 1),
 * SQ_ENODEV. Classic and FD frames alike (64 bytes, FDF/BRS/ESI kept); a
 * frame that breaks hal.h's format rules (hal_can_format_ok: a length above
 * 8 without FDF, an FD length that is no DLC code's ...) is a programming
 * error of the caller, who reads the log or makes the traffic.
 */
int hal_vbus_rx_push(uint8_t bus, const hal_can_frame_t *frame);

/* Frames queued on bus, delivered or not yet (0 for a bus that is absent). */
uint32_t hal_vbus_rx_pending(uint8_t bus);

/* Take the oldest frame the firmware sent on bus: SQ_OK or SQ_EAGAIN. */
int hal_vbus_tx_pop(uint8_t bus, hal_can_frame_t *frame);

/* A node that takes every frame sent on bus at once (NULL: back to the wire
 * FIFO). It returns SQ_OK or SQ_ENOBUFS (refused: hal_can_send() says
 * SQ_ENOBUFS and nothing was sent). */
typedef int (*hal_vbus_sink_t)(uint8_t bus, const hal_can_frame_t *frame);
void hal_vbus_set_sink(uint8_t bus, hal_vbus_sink_t sink);

/* Controller state and counters as the bus made them: the state, TEC,
 * REC, rx_overruns, tx_dropped and error_frames are taken from *status.
 * The mode and the refusals (tx_refused_listen_only, fd_unsupported) stay
 * the firmware's (a bus-off or a recovery never turns listen-only off),
 * and bus_off_count and
 * state_changes are counted from the state change, as on every backend
 * (hal_can_state_change): an injected bus-off counts once, whatever count
 * *status carries. */
void hal_vbus_set_status(uint8_t bus, const hal_can_status_t *status);

/* Whether the bus's filters are applied (default on). Off models a
 * controller in promiscuous mode, so a test can show that the firmware
 * itself ignores identifiers it does not use. */
void hal_vbus_enforce_filters(bool on);

/* The filters last set on bus (copied up to max); returns how many, 0 if
 * none was ever set. */
uint32_t hal_vbus_rx_filters(uint8_t bus, hal_can_filter_t *filters, uint32_t max);

typedef struct {
	uint64_t rx_pushed;   /* frames offered by hal_vbus_rx_push         */
	uint64_t rx_filtered; /* ... rejected by the filters                */
	uint64_t rx_overflow; /* ... dropped: queue full                    */
	uint64_t tx_frames;   /* frames put on the wire                     */
	uint64_t tx_refused;  /* sends answered ENOBUFS/ENETUNREACH/ENETDOWN/EPERM/ENOTSUP */
} hal_vbus_stats_t;
void hal_vbus_get_stats(uint8_t bus, hal_vbus_stats_t *stats);

/* ---- calibration storage, watchdog, platform ------------------------------ */

/* Store a block (len <= HAL_CALIB_MAX_LEN; copied): SQ_OK or SQ_EINVAL. */
int hal_vbus_calib_store(const uint8_t *block, uint32_t len);
void hal_vbus_calib_erase(void);
void hal_vbus_calib_set_unreadable(bool unreadable);
/* Length of the stored block (0 if none); copies up to max bytes. */
uint32_t hal_vbus_calib_stored(uint8_t *buf, uint32_t max);

uint32_t hal_vbus_watchdog_kicks(void);
uint32_t hal_vbus_watchdog_timeout_ms(void); /* 0 until started */
void hal_vbus_set_platform_faults(uint32_t bits);
void hal_vbus_set_reset_reason(hal_reset_reason_t why);
/* What hal_selftest() reports (NULL: SQ_ENOTSUP, the default). Copied. */
void hal_vbus_set_selftest(const hal_selftest_t *result);

#endif /* HAL_VBUS_H */
