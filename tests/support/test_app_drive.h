/* SPDX-License-Identifier: MIT */
/*
 * Driving the application through the test HAL (tests/support/test_hal.h):
 * boot with a calibration, advance virtual time one 1 ms poll at a time, and
 * find output frames by one of their signals. For cmocka tests.
 */
#ifndef TEST_APP_DRIVE_H
#define TEST_APP_DRIVE_H

#include <stdbool.h>
#include <stdint.h>

#include "calib.h"
#include "hal.h"

/* Reset the test HAL, set the clock to t0_us, store cal (NULL: none stored,
 * the firmware takes its defaults), init the app and poll once. */
void test_app_boot(const calib_t *cal, uint64_t t0_us);

/* One poll per virtual millisecond up to and including t_us. */
void test_app_run_to(uint64_t t_us);

/* Another node's frame reaches the receive queue (asserted accepted). */
void test_app_push(const hal_can_frame_t *f);

/* The time of the first frame with identifier id sent at or after t_us whose
 * signal (Intel start, len) equals (want) or differs from (!want) value; 0
 * if none. */
uint64_t test_app_tx_first(uint32_t id, uint64_t t_us, uint32_t start, uint32_t len,
			   uint64_t value, bool want);

/* The signal (Intel start, len) of the last frame sent with identifier id
 * (fails the test when there is none). */
uint64_t test_app_tx_last_sig(uint32_t id, uint32_t start, uint32_t len);

/* The SquealDiag frame (identifier diag_id) sent at exactly t_us (fails the
 * test when there is none): its fault bits; its page and payload if asked. */
uint16_t test_app_diag_at(uint32_t diag_id, uint64_t t_us, uint32_t *page, const uint8_t **data);

#endif /* TEST_APP_DRIVE_H */
