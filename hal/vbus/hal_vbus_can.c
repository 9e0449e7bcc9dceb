/* SPDX-License-Identifier: MIT */
/*
 * hal_vbus_can.c: hal.h's CAN functions on HAL_CAN_BUSES virtual buses
 * (see hal_vbus.h for the behaviour).
 */
#include <stddef.h>
#include <string.h>

#include "hal_can_common.h"
#include "hal_vbus.h"
#include "hal_vbus_internal.h"

typedef struct {
	hal_can_status_t status;
	bool filter_set;
	uint32_t filter_count;
	hal_can_filter_t filters[HAL_CAN_MAX_FILTERS];
	uint32_t rx_head;
	uint32_t rx_count;
	uint32_t tx_head;
	uint32_t tx_count;
	hal_vbus_sink_t sink;
	hal_vbus_stats_t stats;
	/* the queues' frames last: a reset empties a queue by its count and
	 * never writes its frames (only those within the count are read), so
	 * a process that queues few frames touches few of their pages */
	hal_can_frame_t rx[HAL_VBUS_RX_LEN];
	hal_can_frame_t tx[HAL_VBUS_TX_LEN];
} vbus_t;

static vbus_t buses[HAL_CAN_BUSES];
static uint32_t bus_count = HAL_CAN_BUSES;
static bool filters_enforced = true;

void hal_vbus_can_reset(void)
{
	uint32_t b;

	for (b = 0U; b < HAL_CAN_BUSES; b++) {
		(void)memset(&buses[b], 0, offsetof(vbus_t, rx));
		buses[b].status.state = HAL_CAN_STATE_ERROR_ACTIVE;
		buses[b].status.mode = HAL_CAN_MODE_NORMAL;
	}
	bus_count = HAL_CAN_BUSES;
	filters_enforced = true;
}

void hal_vbus_set_bus_count(uint32_t count)
{
	HAL_REQUIRE((count >= 1U) && (count <= HAL_CAN_BUSES));
	bus_count = count;
}

/* The bus, or NULL for a valid index this backend does not have. */
static vbus_t *vbus_can_bus_of(uint8_t bus)
{
	HAL_REQUIRE(bus < HAL_CAN_BUSES);
	return (bus < bus_count) ? &buses[bus] : NULL;
}

/* ---- RX ------------------------------------------------------------------- */

static bool filter_pass(const vbus_t *b, const hal_can_frame_t *f)
{
	uint32_t i;

	if (!filters_enforced || !b->filter_set || ((f->flags & HAL_CAN_FLAG_ERR) != 0U)) {
		return true; /* error frames are never filtered */
	}
	for (i = 0U; i < b->filter_count; i++) {
		const hal_can_filter_t *flt = &b->filters[i];

		if ((((flt->flags ^ f->flags) & HAL_CAN_FLAG_EXT) == 0U) &&
		    ((f->id & flt->mask) == (flt->id & flt->mask))) {
			return true;
		}
	}
	return false;
}

int hal_vbus_rx_push(uint8_t bus, const hal_can_frame_t *frame)
{
	vbus_t *b = vbus_can_bus_of(bus);
	uint32_t i;

	HAL_REQUIRE((frame != NULL) && hal_can_format_ok(frame->flags, frame->dlc));
	if (b == NULL) {
		return SQ_ENODEV;
	}
	b->stats.rx_pushed++;
	if (!filter_pass(b, frame)) {
		b->stats.rx_filtered++;
		return SQ_ENOENT;
	}
	if (b->rx_count >= HAL_VBUS_RX_LEN) {
		b->stats.rx_overflow++;
		b->status.rx_overruns++;
		return SQ_ENOBUFS;
	}
	/* arrival order (stable: after every frame arriving at the same time
	 * or earlier), as a bus delivers them, so that each sender's schedule
	 * may be queued separately */
	i = b->rx_count;
	while ((i > 0U) &&
	       (b->rx[(b->rx_head + i - 1U) % HAL_VBUS_RX_LEN].timestamp_us > frame->timestamp_us)) {
		b->rx[(b->rx_head + i) % HAL_VBUS_RX_LEN] = b->rx[(b->rx_head + i - 1U) % HAL_VBUS_RX_LEN];
		i--;
	}
	b->rx[(b->rx_head + i) % HAL_VBUS_RX_LEN] = *frame;
	b->rx_count++;
	return SQ_OK;
}

uint32_t hal_vbus_rx_pending(uint8_t bus)
{
	const vbus_t *b = vbus_can_bus_of(bus);

	return (b != NULL) ? b->rx_count : 0U;
}

bool hal_vbus_next_arrival_us(uint64_t *t_us)
{
	bool any = false;
	uint32_t i;

	for (i = 0U; i < bus_count; i++) {
		const vbus_t *b = &buses[i];

		if ((b->rx_count > 0U) && (!any || (b->rx[b->rx_head].timestamp_us < *t_us))) {
			*t_us = b->rx[b->rx_head].timestamp_us;
			any = true;
		}
	}
	return any;
}

int hal_can_receive(uint8_t bus, hal_can_frame_t *frame)
{
	vbus_t *b = vbus_can_bus_of(bus);
	const int rc = hal_can_receive_admit(frame, b != NULL,
					     (b != NULL) && (b->status.state != HAL_CAN_STATE_STOPPED));

	if (rc != SQ_OK) {
		return rc;
	}
	if ((b->rx_count == 0U) || (b->rx[b->rx_head].timestamp_us > hal_time_us())) {
		return SQ_EAGAIN;
	}
	*frame = b->rx[b->rx_head];
	b->rx_head = (b->rx_head + 1U) % HAL_VBUS_RX_LEN;
	b->rx_count--;
	if ((frame->flags & HAL_CAN_FLAG_ERR) != 0U) {
		b->status.error_frames++;
	}
	return SQ_OK;
}

int hal_can_set_rx_filter(uint8_t bus, const hal_can_filter_t *filters, uint32_t count)
{
	vbus_t *b = vbus_can_bus_of(bus);
	const int rc = hal_can_filter_check(filters, count);
	uint32_t i;

	if (rc != SQ_OK) {
		return rc;
	}
	if (b == NULL) {
		return SQ_ENODEV;
	}
	for (i = 0U; i < count; i++) {
		b->filters[i] = filters[i];
	}
	b->filter_count = count;
	b->filter_set = true;
	return SQ_OK;
}

void hal_vbus_enforce_filters(bool on)
{
	filters_enforced = on;
}

uint32_t hal_vbus_rx_filters(uint8_t bus, hal_can_filter_t *filters, uint32_t max)
{
	const vbus_t *b = vbus_can_bus_of(bus);
	uint32_t i;

	if ((b == NULL) || !b->filter_set) {
		return 0U;
	}
	for (i = 0U; (filters != NULL) && (i < b->filter_count) && (i < max); i++) {
		filters[i] = b->filters[i];
	}
	return b->filter_count;
}

/* ---- TX ------------------------------------------------------------------- */

static int wire_put(vbus_t *b, uint8_t bus, const hal_can_frame_t *f)
{
	if (b->sink != NULL) {
		return b->sink(bus, f);
	}
	if (b->tx_count >= HAL_VBUS_TX_LEN) {
		return SQ_ENOBUFS;
	}
	b->tx[(b->tx_head + b->tx_count) % HAL_VBUS_TX_LEN] = *f;
	b->tx_count++;
	return SQ_OK;
}

int hal_can_send(uint8_t bus, const hal_can_frame_t *frame)
{
	vbus_t *b = vbus_can_bus_of(bus);
	hal_can_frame_t f;
	/* every bus of the in-memory backend carries FD frames */
	int rc = hal_can_send_admit(frame, (b != NULL) ? &b->status : NULL, true);

	if ((rc == SQ_EINVAL) || (rc == SQ_ENODEV)) {
		return rc; /* not a refusal of this bus: not in its stats */
	}
	if (rc != SQ_OK) {
		/* refused (FD, listen-only): counted below */
	} else if (b->status.state == HAL_CAN_STATE_STOPPED) {
		rc = SQ_ENETDOWN;
	} else if (b->status.state == HAL_CAN_STATE_BUS_OFF) {
		rc = SQ_ENETUNREACH;
	} else {
		f = *frame;
		f.timestamp_us = hal_time_us();
		rc = wire_put(b, bus, &f);
	}
	if (rc == SQ_OK) {
		b->stats.tx_frames++;
	} else {
		b->stats.tx_refused++;
	}
	return rc;
}

int hal_vbus_tx_pop(uint8_t bus, hal_can_frame_t *frame)
{
	vbus_t *b = vbus_can_bus_of(bus);

	HAL_REQUIRE(frame != NULL);
	if ((b == NULL) || (b->tx_count == 0U)) {
		return SQ_EAGAIN;
	}
	*frame = b->tx[b->tx_head];
	b->tx_head = (b->tx_head + 1U) % HAL_VBUS_TX_LEN;
	b->tx_count--;
	return SQ_OK;
}

void hal_vbus_set_sink(uint8_t bus, hal_vbus_sink_t sink)
{
	vbus_t *b = vbus_can_bus_of(bus);

	if (b != NULL) {
		b->sink = sink;
	}
}

/* ---- status, mode, bit rate ----------------------------------------------- */

int hal_can_get_status(uint8_t bus, hal_can_status_t *status)
{
	const vbus_t *b = vbus_can_bus_of(bus);

	HAL_REQUIRE(status != NULL);
	if (b == NULL) {
		return SQ_ENODEV;
	}
	*status = b->status;
	return SQ_OK;
}

void hal_vbus_set_status(uint8_t bus, const hal_can_status_t *status)
{
	vbus_t *b = vbus_can_bus_of(bus);

	HAL_REQUIRE(status != NULL);
	if (b != NULL) {
		/* the bus makes the error counters and losses; the firmware's
		 * mode and refusals stay, and the state changes (with
		 * bus_off_count and state_changes) are counted here, as every
		 * backend counts them */
		b->status.tx_error_count = status->tx_error_count;
		b->status.rx_error_count = status->rx_error_count;
		b->status.rx_overruns = status->rx_overruns;
		b->status.tx_dropped = status->tx_dropped;
		b->status.error_frames = status->error_frames;
		(void)hal_can_state_change(&b->status, status->state);
	}
}

int hal_can_set_mode(uint8_t bus, hal_can_mode_t mode)
{
	vbus_t *b = vbus_can_bus_of(bus);

	HAL_REQUIRE((mode == HAL_CAN_MODE_NORMAL) || (mode == HAL_CAN_MODE_LISTEN_ONLY));
	if (b == NULL) {
		return SQ_ENODEV;
	}
	b->status.mode = mode;
	return SQ_OK;
}

int hal_can_set_bitrate(uint8_t bus, uint32_t bitrate_kbps)
{
	if (vbus_can_bus_of(bus) == NULL) {
		return SQ_ENODEV;
	}
	return ((bitrate_kbps == 0U) || (bitrate_kbps > 1000U)) ? SQ_EINVAL : SQ_OK;
}

void hal_vbus_get_stats(uint8_t bus, hal_vbus_stats_t *stats)
{
	const vbus_t *b = vbus_can_bus_of(bus);

	HAL_REQUIRE(stats != NULL);
	if (b != NULL) {
		*stats = b->stats;
	} else {
		(void)memset(stats, 0, sizeof(*stats));
	}
}
