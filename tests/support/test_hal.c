/* SPDX-License-Identifier: MIT */
/* In-memory HAL for unit tests: see test_hal.h. */
#include "test_hal.h"

#include <stddef.h>
#include <string.h>

static struct {
	uint64_t now_us;
	uint32_t cycles_per_call;
	uint32_t cycles_extra;

	hal_can_frame_t rx[TEST_HAL_RX_CAP];
	uint32_t rx_head;
	uint32_t rx_count;
	bool filter_on;
	hal_can_filter_t filters[HAL_CAN_MAX_FILTERS];
	uint32_t filter_count;
	bool filter_set;

	hal_can_frame_t tx[TEST_HAL_TX_CAP];
	uint32_t tx_count;
	bool tx_full;
	uint32_t tx_rejected;

	hal_can_status_t status;

	uint8_t calib[HAL_CALIB_MAX_LEN];
	uint32_t calib_len;
	bool calib_present;
	bool calib_read_error;

	uint32_t wd_kicks;
	uint32_t wd_timeout_ms;
	uint32_t platform_faults;
	hal_reset_reason_t reset_reason;
} th;

void test_hal_reset(void)
{
	memset(&th, 0, sizeof(th));
	th.status.state = HAL_CAN_STATE_ERROR_ACTIVE;
	th.reset_reason = HAL_RESET_POWER_ON;
}

/* ---- clock ---------------------------------------------------------------- */

void test_hal_set_time_us(uint64_t t_us)
{
	if (t_us > th.now_us) {
		th.now_us = t_us; /* monotonic, as hal.h promises */
	}
}

void test_hal_advance_us(uint64_t dt_us)
{
	th.now_us += dt_us;
}

void test_hal_set_cycles_per_call(uint32_t cycles)
{
	th.cycles_per_call = cycles;
}

uint64_t hal_time_us(void)
{
	return th.now_us;
}

void hal_idle_until(uint64_t deadline_us)
{
	uint64_t t = deadline_us;

	if ((th.rx_count > 0U) && (th.rx[th.rx_head].timestamp_us < t)) {
		t = th.rx[th.rx_head].timestamp_us;
	}
	test_hal_set_time_us(t);
}

uint32_t hal_cycles(void)
{
	th.cycles_extra += th.cycles_per_call;
	return (uint32_t)(th.now_us * TEST_HAL_CYCLES_PER_US) + th.cycles_extra;
}

uint32_t hal_cycles_per_us(void)
{
	return TEST_HAL_CYCLES_PER_US;
}

/* ---- CAN RX --------------------------------------------------------------- */

int test_hal_rx_push(const hal_can_frame_t *frame)
{
	uint32_t i;

	if ((frame == NULL) || (th.rx_count >= TEST_HAL_RX_CAP)) {
		return SQ_ENOBUFS;
	}
	/* keep the queue in timestamp order (stable: after every frame with
	 * the same or an earlier time), as a real bus delivers them, so a
	 * test may queue each sender's schedule separately */
	i = th.rx_count;
	while ((i > 0U) &&
	       (th.rx[(th.rx_head + i - 1U) % TEST_HAL_RX_CAP].timestamp_us > frame->timestamp_us)) {
		th.rx[(th.rx_head + i) % TEST_HAL_RX_CAP] =
			th.rx[(th.rx_head + i - 1U) % TEST_HAL_RX_CAP];
		i--;
	}
	th.rx[(th.rx_head + i) % TEST_HAL_RX_CAP] = *frame;
	th.rx_count++;
	return SQ_OK;
}

uint32_t test_hal_rx_pending(void)
{
	return th.rx_count;
}

void test_hal_apply_rx_filter(bool on)
{
	th.filter_on = on;
}

uint32_t test_hal_rx_filter(uint32_t *ids, uint32_t max)
{
	uint32_t i;

	for (i = 0U; (ids != NULL) && (i < th.filter_count) && (i < max); i++) {
		ids[i] = th.filters[i].id;
	}
	return th.filter_set ? th.filter_count : 0U;
}

static bool filter_pass(const hal_can_frame_t *f)
{
	uint32_t i;

	if (!th.filter_on || !th.filter_set || ((f->flags & HAL_CAN_FLAG_ERR) != 0U)) {
		return true; /* error frames are never filtered */
	}
	for (i = 0U; i < th.filter_count; i++) {
		const hal_can_filter_t *flt = &th.filters[i];

		if ((((flt->flags ^ f->flags) & HAL_CAN_FLAG_EXT) == 0U) &&
		    ((f->id & flt->mask) == (flt->id & flt->mask))) {
			return true;
		}
	}
	return false;
}

static int bus_check(uint8_t bus)
{
	HAL_REQUIRE(bus < HAL_CAN_BUSES);
	return (bus == 0U) ? SQ_OK : SQ_ENODEV;
}

int hal_can_receive(uint8_t bus, hal_can_frame_t *frame)
{
	HAL_REQUIRE(frame != NULL);
	if (bus_check(bus) != SQ_OK) {
		return SQ_ENODEV;
	}
	if (th.status.state == HAL_CAN_STATE_STOPPED) {
		return SQ_ENETDOWN;
	}
	while ((th.rx_count > 0U) && (th.rx[th.rx_head].timestamp_us <= th.now_us)) {
		const hal_can_frame_t f = th.rx[th.rx_head];

		th.rx_head = (th.rx_head + 1U) % TEST_HAL_RX_CAP;
		th.rx_count--;
		if (filter_pass(&f)) {
			*frame = f;
			return SQ_OK;
		}
	}
	return SQ_EAGAIN;
}

int hal_can_set_mode(uint8_t bus, hal_can_mode_t mode)
{
	if (bus_check(bus) != SQ_OK) {
		return SQ_ENODEV;
	}
	return (mode == HAL_CAN_MODE_NORMAL) ? SQ_OK : SQ_ENOTSUP;
}

int hal_can_set_bitrate(uint8_t bus, uint32_t bitrate_kbps)
{
	if (bus_check(bus) != SQ_OK) {
		return SQ_ENODEV;
	}
	return (bitrate_kbps == 0U || bitrate_kbps > 1000U) ? SQ_EINVAL : SQ_OK;
}

int hal_can_set_rx_filter(uint8_t bus, const hal_can_filter_t *filters, uint32_t count)
{
	uint32_t i;

	HAL_REQUIRE((count <= HAL_CAN_MAX_FILTERS) && ((filters != NULL) || (count == 0U)));
	if (bus_check(bus) != SQ_OK) {
		return SQ_ENODEV;
	}
	for (i = 0U; i < count; i++) {
		const uint32_t max = ((filters[i].flags & HAL_CAN_FLAG_EXT) != 0U) ? 0x1FFFFFFFU : 0x7FFU;

		if ((filters[i].id > max) || (filters[i].mask > max)) {
			return SQ_EINVAL;
		}
	}
	for (i = 0U; i < count; i++) {
		th.filters[i] = filters[i];
	}
	th.filter_count = count;
	th.filter_set = true;
	return SQ_OK;
}

/* ---- CAN TX --------------------------------------------------------------- */

int hal_can_send(uint8_t bus, const hal_can_frame_t *frame)
{
	HAL_REQUIRE(frame != NULL);
	if (bus_check(bus) != SQ_OK) {
		return SQ_ENODEV;
	}
	if ((frame->dlc > HAL_CAN_MAX_DLEN) ||
	    (frame->id > (((frame->flags & HAL_CAN_FLAG_EXT) != 0U) ? 0x1FFFFFFFU : 0x7FFU))) {
		return SQ_EINVAL;
	}
	if (th.status.state == HAL_CAN_STATE_STOPPED) {
		th.tx_rejected++;
		return SQ_ENETDOWN;
	}
	if (th.status.state == HAL_CAN_STATE_BUS_OFF) {
		th.tx_rejected++;
		return SQ_ENETUNREACH;
	}
	if (th.tx_full || (th.tx_count >= TEST_HAL_TX_CAP)) {
		th.tx_rejected++;
		return SQ_ENOBUFS;
	}
	th.tx[th.tx_count] = *frame;
	th.tx[th.tx_count].timestamp_us = th.now_us;
	th.tx_count++;
	return SQ_OK;
}

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
	return th.tx_rejected;
}

/* ---- CAN status ----------------------------------------------------------- */

int hal_can_get_status(uint8_t bus, hal_can_status_t *status)
{
	HAL_REQUIRE(status != NULL);
	if (bus_check(bus) != SQ_OK) {
		return SQ_ENODEV;
	}
	*status = th.status;
	return SQ_OK;
}

void test_hal_set_can_status(const hal_can_status_t *status)
{
	if (status != NULL) {
		th.status = *status;
	}
}

void test_hal_bus_off(void)
{
	if (th.status.state != HAL_CAN_STATE_BUS_OFF) {
		th.status.bus_off_count++;
	}
	th.status.state = HAL_CAN_STATE_BUS_OFF;
	th.status.tx_error_count = 255U;
}

void test_hal_bus_recover(void)
{
	th.status.state = HAL_CAN_STATE_ERROR_ACTIVE;
	th.status.tx_error_count = 0U;
	th.status.rx_error_count = 0U;
}

void test_hal_set_can_stopped(bool stopped)
{
	th.status.state = stopped ? HAL_CAN_STATE_STOPPED : HAL_CAN_STATE_ERROR_ACTIVE;
}

/* ---- calibration storage -------------------------------------------------- */

void test_hal_calib_absent(void)
{
	th.calib_present = false;
	th.calib_len = 0U;
}

void test_hal_calib_store(const uint8_t *buf, uint32_t len)
{
	if ((buf == NULL) || (len > HAL_CALIB_MAX_LEN)) {
		return;
	}
	memset(th.calib, 0xFF, sizeof(th.calib)); /* erased flash */
	memcpy(th.calib, buf, len);
	th.calib_len = len;
	th.calib_present = true;
}

void test_hal_calib_read_error(bool on)
{
	th.calib_read_error = on;
}

uint32_t test_hal_calib_stored(uint8_t *buf, uint32_t max)
{
	if (!th.calib_present) {
		return 0U;
	}
	if (buf != NULL) {
		memcpy(buf, th.calib, (th.calib_len < max) ? th.calib_len : max);
	}
	return th.calib_len;
}

int hal_calib_read(uint8_t *buf, uint32_t len)
{
	if ((buf == NULL) || (len > HAL_CALIB_MAX_LEN)) {
		return SQ_EINVAL;
	}
	if (th.calib_read_error) {
		return SQ_EIO;
	}
	if (!th.calib_present) {
		return SQ_ENOENT;
	}
	/* like flash: the bytes beyond what was written read as erased */
	memcpy(buf, th.calib, len);
	return SQ_OK;
}

int hal_calib_write(const uint8_t *buf, uint32_t len)
{
	if ((buf == NULL) || (len > HAL_CALIB_MAX_LEN)) {
		return SQ_EINVAL;
	}
	test_hal_calib_store(buf, len);
	return SQ_OK;
}

/* ---- watchdog, reset, platform -------------------------------------------- */

int hal_watchdog_start(uint32_t timeout_ms)
{
	if (timeout_ms == 0U) {
		return SQ_EINVAL;
	}
	th.wd_timeout_ms = timeout_ms;
	return SQ_OK;
}

void hal_watchdog_kick(void)
{
	th.wd_kicks++;
}

uint32_t test_hal_watchdog_kicks(void)
{
	return th.wd_kicks;
}

uint32_t test_hal_watchdog_timeout_ms(void)
{
	return th.wd_timeout_ms;
}

hal_reset_reason_t hal_reset_reason(void)
{
	return th.reset_reason;
}

void test_hal_set_reset_reason(hal_reset_reason_t why)
{
	th.reset_reason = why;
}

uint32_t hal_platform_faults(void)
{
	return th.platform_faults;
}

void test_hal_set_platform_faults(uint32_t bits)
{
	th.platform_faults = bits;
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

hal_can_frame_t test_frame_speed(test_sender_t *s, uint16_t raw, uint64_t t_us)
{
	const msg_disc_speed_t m = { 0U, 0U, raw };
	uint8_t data[8] = { 0 };
	uint8_t dlc = 0U;

	if (msg_disc_speed_pack(&m, data, &dlc) != SQ_OK) {
		dlc = 0U;
	}
	return protect(MSG_DISC_SPEED_ID, MSG_DISC_SPEED_DATA_ID, &s->speed_counter,
		       data, dlc, t_us);
}

hal_can_frame_t test_frame_force(test_sender_t *s, uint16_t raw, uint64_t t_us)
{
	const msg_pad_force_t m = { 0U, 0U, raw };
	uint8_t data[8] = { 0 };
	uint8_t dlc = 0U;

	if (msg_pad_force_pack(&m, data, &dlc) != SQ_OK) {
		dlc = 0U;
	}
	return protect(MSG_PAD_FORCE_ID, MSG_PAD_FORCE_DATA_ID, &s->force_counter,
		       data, dlc, t_us);
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
