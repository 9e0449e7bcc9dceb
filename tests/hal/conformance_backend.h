/* SPDX-License-Identifier: MIT */
/*
 * conformance_backend: what one HAL backend's test harness gives the one
 * HAL conformance suite (tests/hal/conformance.c), so that the same test
 * source runs on every backend (the in-memory bus, SocketCAN on vcan0 +
 * vcan1 in the QEMU guest, bxCAN on simulated registers), as Zephyr's CAN
 * driver tests do.
 *
 * The suite talks to the backend under test only through hal/hal.h. This
 * header is the "other side of the wire": another node on each bus, and the
 * few things a test must provoke that no hal.h call can (error frames,
 * bus-off, a TX path that does not drain). A harness answers SQ_ENOTSUP for
 * something its backend cannot provoke; the suite then prints a SKIP line
 * naming the check and the backend, never a fake PASS.
 *
 * Every function returns SQ_OK or a negative SQ_E* code unless noted.
 */
#ifndef CONFORMANCE_BACKEND_H
#define CONFORMANCE_BACKEND_H

#include <stdbool.h>
#include <stdint.h>

#include "hal.h"

/* Short name for the PASS/FAIL lines: "vbus", "socketcan", "bxcan-sim". */
const char *conf_backend_name(void);

/* Fresh backend: every bus that exists started at its default bit rate in
 * NORMAL mode, accepting every frame, queues empty, counters zero. Called
 * before each test case. */
int conf_backend_setup(void);
void conf_backend_teardown(void);

/* How many buses this backend really has (1 or HAL_CAN_BUSES). */
uint32_t conf_bus_count(void);

/* Whether `bus` carries CAN FD frames, as the harness knows its backend
 * (the in-memory bus: yes; bxCAN: no, a classic controller; SocketCAN: the
 * interface's MTU, asked by the harness itself). The suite then checks FD
 * round trips, or that FD frames are refused with SQ_ENOTSUP and counted
 * (and says SKIP for the round trips). */
bool conf_bus_fd(uint8_t bus);

/* Another node on `bus` sends this frame (classic or FD): it reaches the
 * backend's receive path as a real frame on the wire would (its filters
 * apply). */
int conf_wire_inject(uint8_t bus, const hal_can_frame_t *frame);

/* The next frame this node put on `bus`'s wire, oldest first:
 * SQ_OK or SQ_EAGAIN (nothing was sent). */
int conf_wire_take(uint8_t bus, hal_can_frame_t *frame);

/* Another node signals an error on `bus` (an error frame is seen). */
int conf_force_error_frame(uint8_t bus);

/* The controller on `bus` goes bus-off (on = true) or recovers (false). */
int conf_force_bus_off(uint8_t bus, bool on);

/* While blocked, nothing leaves the controller on `bus` (no ACK from the
 * bus): its TX queue fills and hal_can_send() must answer SQ_ENOBUFS;
 * unblocking drains it. */
int conf_block_tx(uint8_t bus, bool blocked);

/* Let `us` microseconds pass for the backend (interrupts, kernel queues,
 * the virtual clock), so that sent frames reach the wire and injected ones
 * reach the receive queue. */
void conf_let_time_pass(uint32_t us);

#endif /* CONFORMANCE_BACKEND_H */
