/* SPDX-License-Identifier: MIT */
/*
 * squeal_app: the firmware proper, identical on every platform.
 * A platform's main() sets its HAL up and calls squeal_main(); the host-sim
 * and tests may drive squeal_app_init()/squeal_app_poll() themselves.
 */
#ifndef SQUEAL_APP_H
#define SQUEAL_APP_H

#include <stdbool.h>
#include <stdint.h>

#include "monitor.h"

/* Load calibration through the HAL (defaults if none or corrupt), set CAN
 * filters, start the watchdog. Returns SQ_OK or a negative SQ_E* code
 * (the app still runs with defaults and reports the fault). */
int squeal_app_init(void);

/* Do all work that is due at hal_time_us(): drain CAN RX, run the 1 ms
 * tasks, transmit. Bounded time per call. Returns the next deadline (us). */
uint64_t squeal_app_poll(void);

/* The earliest time (hal_time_us()'s clock) at which squeal_app_poll() has
 * work to do without a new frame: a periodic message, an input's staleness
 * timeout, or its next 1 ms tick when something is pending (a frame taken
 * since the last tick, a queued frame, a new input pair, a state change to
 * send, a new CAN status). Every tick before it changes nothing, so a
 * virtual scheduler may skip those ticks and the output stays the same.
 * Never earlier than the next tick. A frame offered to the HAL, or a change
 * of the controller's status, is the caller's event: poll when it arrives.
 * The ECU keeps polling every tick; this is for virtual time. */
uint64_t squeal_app_next_event_us(void);

/* Virtual time: the ticks up to and including t_us are skipped ones (t_us
 * is before squeal_app_next_event_us()). Leaves the clocks where running
 * the last of them would: the next tick after t_us, and each monitor's
 * clock at t_us (a frame then taken gets t_us as its receive time at the
 * latest, as after that tick). Changes nothing else: those ticks change
 * nothing else. A t_us before the last tick run changes nothing. */
void squeal_app_skip_to_us(uint64_t t_us);

/* init, then poll + hal_idle_until() until *stop becomes true (never, on the
 * ECU). Returns the init status. */
int squeal_main(volatile const bool *stop);

/* The running monitor, read-only: host tools print its counters and tests
 * inspect it. */
const monitor_t *squeal_app_monitor(void);

/* The corners' monitors (1..4; corner 0 is squeal_app_monitor()). NULL
 * beyond the count. */
uint32_t squeal_app_corner_count(void);
const monitor_t *squeal_app_corner(uint32_t k);

/* What squeal_app_init() returned. */
int squeal_app_init_status(void);

#endif /* SQUEAL_APP_H */
