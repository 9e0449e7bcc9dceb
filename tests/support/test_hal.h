/* SPDX-License-Identifier: MIT */
/*
 * test_hal: the unit tests' layer on top of the in-memory backend
 * (hal/vbus/hal_vbus.h, which implements every hal.h function). Link
 * test_hal.o with build/<variant>/libhal_vbus.a.
 *
 * - Clock: virtual microseconds, moved only by the test
 *   (test_hal_set_time_us / test_hal_advance_us) and by hal_idle_until()
 *   (to its deadline, or to the next queued frame if earlier).
 * - RX (bus 0): test_hal_rx_push() queues a frame that becomes receivable at
 *   frame->timestamp_us (a whole bus schedule may be queued up front, each
 *   sender's separately). Filters set by hal_can_set_rx_filter() are
 *   recorded; they are applied only after test_hal_apply_rx_filter(true), so
 *   a test can also prove that the firmware itself ignores identifiers it
 *   does not use.
 * - TX (bus 0): every accepted frame is logged with the clock at send time
 *   (timestamp_us). test_hal_set_tx_full(true) makes hal_can_send() return
 *   SQ_ENOBUFS (nothing logged) until cleared; bus-off makes it return
 *   SQ_ENETUNREACH, stopped SQ_ENETDOWN.
 * - CAN status: state and counters set by the test; test_hal_bus_off()
 *   and test_hal_bus_recover() model a controller going bus-off and back.
 * - Calibration storage: absent (SQ_ENOENT), present, or unreadable
 *   (SQ_EIO); writes land in it.
 * - Watchdog: start timeout and kick counter. Platform fault bits and the
 *   reset reason are set by the test.
 * - hal_cycles(): TEST_HAL_CYCLES_PER_US cycles per virtual microsecond,
 *   plus test_hal_set_cycles_per_call() extra cycles on every call (to make
 *   a task look slow).
 *
 * test_hal_reset() puts everything back to its power-on state: call it at
 * the start of every test.
 */
#ifndef TEST_HAL_H
#define TEST_HAL_H

#include <stdbool.h>
#include <stdint.h>

#include "hal.h"

/* the backend's (test_hal.c checks that they agree with hal_vbus.h) */
#define TEST_HAL_RX_CAP 4096U
#define TEST_HAL_CYCLES_PER_US 168U
#define TEST_HAL_TX_CAP 65536U

void test_hal_reset(void);

/* clock */
void test_hal_set_time_us(uint64_t t_us);
void test_hal_advance_us(uint64_t dt_us);
void test_hal_set_cycles_per_call(uint32_t cycles);

/* RX: queue a frame that becomes receivable at frame->timestamp_us.
 * Returns SQ_OK or SQ_ENOBUFS (queue full: the test is wrong). */
int test_hal_rx_push(const hal_can_frame_t *frame);
uint32_t test_hal_rx_pending(void);   /* queued, delivered or not yet */
void test_hal_apply_rx_filter(bool on);
uint32_t test_hal_rx_filter(uint32_t *ids, uint32_t max); /* the last set */

/* TX log */
uint32_t test_hal_tx_count(void);
const hal_can_frame_t *test_hal_tx_frame(uint32_t i); /* NULL if i >= count */
void test_hal_tx_clear(void);
void test_hal_set_tx_full(bool full);
uint32_t test_hal_tx_rejected(void);  /* SQ_ENOBUFS/ENETUNREACH/ENETDOWN answers */

/* CAN status */
void test_hal_set_can_status(const hal_can_status_t *status);
void test_hal_bus_off(void);          /* state BUS_OFF, TEC 255, bus_off_count + 1 */
void test_hal_bus_recover(void);      /* ERROR_ACTIVE, counters 0                  */
void test_hal_set_can_stopped(bool stopped);

/* calibration storage */
void test_hal_calib_absent(void);
void test_hal_calib_store(const uint8_t *buf, uint32_t len);
void test_hal_calib_read_error(bool on);
uint32_t test_hal_calib_stored(uint8_t *buf, uint32_t max); /* length, 0 if absent */

/* watchdog, platform */
uint32_t test_hal_watchdog_kicks(void);
uint32_t test_hal_watchdog_timeout_ms(void); /* 0 until started */
void test_hal_set_platform_faults(uint32_t bits);
void test_hal_set_reset_reason(hal_reset_reason_t why);

/* ---- bus helpers: a sender as a real ECU would be, a TX log reader ------ */

/* One simulated sender of DiscSpeed and PadForce: packs with the protocol's
 * pack functions and protects with e2e_p01_protect (its own counters). */
typedef struct {
	uint8_t speed_counter;
	uint8_t force_counter;
} test_sender_t;

void test_sender_init(test_sender_t *s);
/* A protected frame, stamped t_us. */
hal_can_frame_t test_frame_speed(test_sender_t *s, uint16_t raw, uint64_t t_us);
hal_can_frame_t test_frame_force(test_sender_t *s, uint16_t raw, uint64_t t_us);
/* queue both (speed first) at t_us; asserts nothing, returns SQ_OK or error */
int test_send_pair(test_sender_t *s, uint16_t speed_raw, uint16_t force_raw,
		   uint64_t t_us);

/* Index of the first logged TX frame with this id at index >= from, or -1. */
int32_t test_hal_tx_find(uint32_t id, uint32_t from);

/* The last logged TX frame with this id, or NULL. */
const hal_can_frame_t *test_hal_tx_last(uint32_t id);

/* The first logged TX frame with this id sent at exactly t_us, or NULL. */
const hal_can_frame_t *test_hal_tx_at(uint32_t id, uint64_t t_us);

/* A raw signal of a frame: Intel byte order, start bit and length as in the
 * DBC. Read here, independently of firmware/protocol's decoder. */
uint64_t test_frame_sig(const uint8_t data[8], uint32_t start, uint32_t len);

#endif /* TEST_HAL_H */
