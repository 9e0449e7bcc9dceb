/* SPDX-License-Identifier: MIT */
/*
 * The unit tests' layer on top of the in-memory backend (hal/vbus): see
 * test_hal.h. Every hal.h function is the backend's; this file only adds
 * what a test steers (fault injection: TX full, bus-off, stopped, clock
 * jumps, calibration storage faults) and what it reads back (an indexed
 * log of every frame sent, the filters set).
 */
#include "test_hal.h"

#include <stddef.h>
#include <string.h>

#include "hal_vbus.h"

_Static_assert(TEST_HAL_RX_CAP == HAL_VBUS_RX_LEN, "test_hal.h: RX capacity of hal_vbus");
_Static_assert(TEST_HAL_CYCLES_PER_US == HAL_VBUS_CYCLES_PER_US, "test_hal.h: cycle rate of hal_vbus");

static struct {
	hal_can_frame_t tx[TEST_HAL_TX_CAP];
	uint32_t tx_count;
	bool tx_full;
} th;

/* The node on bus 0 that takes what the firmware sends: the log. */
static int log_sink(uint8_t bus, const hal_can_frame_t *frame)
{
	(void)bus;
	if (th.tx_full || (th.tx_count >= TEST_HAL_TX_CAP)) {
		return SQ_ENOBUFS;
	}
	th.tx[th.tx_count] = *frame;
	th.tx_count++;
	return SQ_OK;
}

void test_hal_reset(void)
{
	memset(&th, 0, sizeof(th));
	hal_vbus_reset();
	/* the tests prove that the firmware ignores unused identifiers itself;
	 * test_hal_apply_rx_filter(true) turns the controller's filters on */
	hal_vbus_enforce_filters(false);
	hal_vbus_set_sink(0U, log_sink);
}

/* ---- clock ---------------------------------------------------------------- */

void test_hal_set_time_us(uint64_t t_us)
{
	hal_vbus_set_time_us(t_us);
}

void test_hal_advance_us(uint64_t dt_us)
{
	hal_vbus_set_time_us(hal_time_us() + dt_us);
}

void test_hal_set_cycles_per_call(uint32_t cycles)
{
	hal_vbus_set_cycles_per_call(cycles);
}

/* ---- CAN RX --------------------------------------------------------------- */

int test_hal_rx_push(const hal_can_frame_t *frame)
{
	if (frame == NULL) {
		return SQ_ENOBUFS;
	}
	/* a frame the controller's filter drops was still sent: not an error */
	return (hal_vbus_rx_push(0U, frame) == SQ_ENOBUFS) ? SQ_ENOBUFS : SQ_OK;
}

uint32_t test_hal_rx_pending(void)
{
	return hal_vbus_rx_pending(0U);
}

void test_hal_apply_rx_filter(bool on)
{
	hal_vbus_enforce_filters(on);
}

uint32_t test_hal_rx_filter(uint32_t *ids, uint32_t max)
{
	hal_can_filter_t f[HAL_CAN_MAX_FILTERS];
	const uint32_t n = hal_vbus_rx_filters(0U, f, HAL_CAN_MAX_FILTERS);
	uint32_t i;

	for (i = 0U; (ids != NULL) && (i < n) && (i < max); i++) {
		ids[i] = f[i].id;
	}
	return n;
}

/* ---- CAN TX --------------------------------------------------------------- */

uint32_t test_hal_tx_count(void)
{
	return th.tx_count;
}

const hal_can_frame_t *test_hal_tx_frame(uint32_t i)
{
	return (i < th.tx_count) ? &th.tx[i] : NULL;
}

void test_hal_tx_clear(void)
{
	th.tx_count = 0U;
}

void test_hal_set_tx_full(bool full)
{
	th.tx_full = full;
}

uint32_t test_hal_tx_rejected(void)
{
	hal_vbus_stats_t st;

	hal_vbus_get_stats(0U, &st);
	return (uint32_t)st.tx_refused;
}

/* ---- CAN status ----------------------------------------------------------- */

static hal_can_status_t status_now(void)
{
	hal_can_status_t st;

	(void)hal_can_get_status(0U, &st);
	return st;
}

void test_hal_set_can_status(const hal_can_status_t *status)
{
	if (status != NULL) {
		hal_vbus_set_status(0U, status);
	}
}

void test_hal_bus_off(void)
{
	hal_can_status_t st = status_now();

	/* bus_off_count + 1 is the backend's: it counts the entry */
	st.state = HAL_CAN_STATE_BUS_OFF;
	st.tx_error_count = 255U;
	hal_vbus_set_status(0U, &st);
}

void test_hal_bus_recover(void)
{
	hal_can_status_t st = status_now();

	st.state = HAL_CAN_STATE_ERROR_ACTIVE;
	st.tx_error_count = 0U;
	st.rx_error_count = 0U;
	hal_vbus_set_status(0U, &st);
}

void test_hal_set_can_stopped(bool stopped)
{
	hal_can_status_t st = status_now();

	st.state = stopped ? HAL_CAN_STATE_STOPPED : HAL_CAN_STATE_ERROR_ACTIVE;
	hal_vbus_set_status(0U, &st);
}

/* ---- calibration storage -------------------------------------------------- */

void test_hal_calib_absent(void)
{
	hal_vbus_calib_erase();
}

void test_hal_calib_store(const uint8_t *buf, uint32_t len)
{
	if (buf != NULL) {
		(void)hal_vbus_calib_store(buf, len);
	}
}

void test_hal_calib_read_error(bool on)
{
	hal_vbus_calib_set_unreadable(on);
}

uint32_t test_hal_calib_stored(uint8_t *buf, uint32_t max)
{
	return hal_vbus_calib_stored(buf, max);
}

/* ---- watchdog, reset, platform -------------------------------------------- */

uint32_t test_hal_watchdog_kicks(void)
{
	return hal_vbus_watchdog_kicks();
}

uint32_t test_hal_watchdog_timeout_ms(void)
{
	return hal_vbus_watchdog_timeout_ms();
}

void test_hal_set_reset_reason(hal_reset_reason_t why)
{
	hal_vbus_set_reset_reason(why);
}

void test_hal_set_platform_faults(uint32_t bits)
{
	hal_vbus_set_platform_faults(bits);
}

/* ---- bus helpers ---------------------------------------------------------- */

#include "e2e_p01.h"
#include "squeal_msgs.h"

void test_sender_init(test_sender_t *s)
{
	s->speed_counter = 0U;
	s->force_counter = 0U;
}

static hal_can_frame_t protect(uint32_t id, uint16_t data_id, uint8_t *counter,
			       const uint8_t data[8], uint8_t dlc, uint64_t t_us)
{
	hal_can_frame_t f;
	const e2e_p01_config_t cfg = { data_id, dlc, 1U };
	e2e_p01_tx_t tx = { *counter };

	memset(&f, 0, sizeof(f));
	f.id = id;
	f.dlc = dlc;
	memcpy(f.data, data, 8U);
	if (e2e_p01_protect(&cfg, &tx, f.data, dlc) != SQ_OK) {
		f.dlc = 0U; /* unusable: the test will notice */
	}
	*counter = tx.counter;
	f.timestamp_us = t_us;
	return f;
}

/* One input's frame (DiscSpeed or PadForce, the same layout), packed by
 * the firmware and protected with the sender's next counter. */
static hal_can_frame_t input_frame(test_sender_t *s, bool speed, uint16_t raw, uint64_t t_us)
{
	const msg_disc_speed_t ds = { 0U, 0U, raw };
	const msg_pad_force_t pf = { 0U, 0U, raw };
	uint8_t data[8] = { 0 };
	uint8_t dlc = 0U;
	const int rc = speed ? msg_disc_speed_pack(&ds, data, &dlc) : msg_pad_force_pack(&pf, data, &dlc);

	if (rc != SQ_OK) {
		dlc = 0U;
	}
	if (speed) {
		return protect(MSG_DISC_SPEED_ID, MSG_DISC_SPEED_DATA_ID, &s->speed_counter, data, dlc, t_us);
	}
	return protect(MSG_PAD_FORCE_ID, MSG_PAD_FORCE_DATA_ID, &s->force_counter, data, dlc, t_us);
}

hal_can_frame_t test_frame_speed(test_sender_t *s, uint16_t raw, uint64_t t_us)
{
	return input_frame(s, true, raw, t_us);
}

hal_can_frame_t test_frame_force(test_sender_t *s, uint16_t raw, uint64_t t_us)
{
	return input_frame(s, false, raw, t_us);
}

int test_send_pair(test_sender_t *s, uint16_t speed_raw, uint16_t force_raw,
		   uint64_t t_us)
{
	hal_can_frame_t f = test_frame_speed(s, speed_raw, t_us);
	int rc = test_hal_rx_push(&f);

	if (rc != SQ_OK) {
		return rc;
	}
	f = test_frame_force(s, force_raw, t_us);
	return test_hal_rx_push(&f);
}

int32_t test_hal_tx_find(uint32_t id, uint32_t from)
{
	uint32_t i;

	for (i = from; i < th.tx_count; i++) {
		if (th.tx[i].id == id) {
			return (int32_t)i;
		}
	}
	return -1;
}

const hal_can_frame_t *test_hal_tx_last(uint32_t id)
{
	int32_t i = -1;
	int32_t last = -1;

	while ((i = test_hal_tx_find(id, (uint32_t)(i + 1))) >= 0) {
		last = i;
	}
	return (last >= 0) ? test_hal_tx_frame((uint32_t)last) : NULL;
}

const hal_can_frame_t *test_hal_tx_at(uint32_t id, uint64_t t_us)
{
	int32_t i = -1;

	while ((i = test_hal_tx_find(id, (uint32_t)(i + 1))) >= 0) {
		const hal_can_frame_t *f = test_hal_tx_frame((uint32_t)i);

		if (f->timestamp_us == t_us) {
			return f;
		}
	}
	return NULL;
}

uint64_t test_frame_sig(const uint8_t data[8], uint32_t start, uint32_t len)
{
	uint64_t v = 0U;
	uint32_t i;

	for (i = 0U; i < 8U; i++) {
		v |= (uint64_t)data[i] << (8U * i);
	}
	return (v >> start) & ((1ULL << len) - 1U);
}
