/* SPDX-License-Identifier: MIT */
#include "hal_vbus.h"

#include <string.h>

static struct {
	bool active;
	uint64_t now_us;
	hal_can_frame_t rx[HAL_VBUS_RX_LEN];
	uint32_t rx_head;
	uint32_t rx_count;
	hal_can_frame_t tx[HAL_VBUS_TX_LEN];
	uint32_t tx_head;
	uint32_t tx_count;
	bool filter_set;
	hal_can_filter_t filter[HAL_CAN_MAX_FILTERS];
	uint32_t filter_count;
	hal_can_status_t status;
	uint8_t calib[HAL_CALIB_MAX_LEN];
	uint32_t calib_len;
	bool tx_full;
	hal_vbus_stats_t stats;
} vb;

void hal_vbus_enable(void)
{
	memset(&vb, 0, sizeof(vb));
	vb.active = true;
	vb.status.state = HAL_CAN_STATE_ERROR_ACTIVE;
}

bool hal_vbus_active(void)
{
	return vb.active;
}

void hal_vbus_set_time_us(uint64_t t_us)
{
	if (t_us > vb.now_us) {
		vb.now_us = t_us;
	}
}

uint64_t hal_vbus_time_us(void)
{
	return vb.now_us;
}

static bool filter_accepts(const hal_can_frame_t *f)
{
	uint32_t i;

	if (!vb.filter_set || ((f->flags & HAL_CAN_FLAG_ERR) != 0U)) {
		return true; /* error frames have their own (always-on) filter */
	}
	for (i = 0; i < vb.filter_count; i++) {
		const hal_can_filter_t *flt = &vb.filter[i];

		if ((((flt->flags ^ f->flags) & HAL_CAN_FLAG_EXT) == 0U) &&
		    ((f->id & flt->mask) == (flt->id & flt->mask))) {
			return true;
		}
	}
	return false;
}

int hal_vbus_push_rx(const hal_can_frame_t *frame)
{
	hal_can_frame_t *slot;

	if (frame == NULL) {
		return SQ_EINVAL;
	}
	vb.stats.rx_pushed++;
	if (!filter_accepts(frame)) {
		vb.stats.rx_filtered++;
		return SQ_ENOENT;
	}
	if (vb.rx_count >= HAL_VBUS_RX_LEN) {
		vb.stats.rx_overflow++;
		vb.status.rx_overruns++;
		return SQ_ENOBUFS;
	}
	slot = &vb.rx[(vb.rx_head + vb.rx_count) % HAL_VBUS_RX_LEN];
	*slot = *frame;
	slot->timestamp_us = vb.now_us;
	vb.rx_count++;
	return SQ_OK;
}

int hal_vbus_can_receive(hal_can_frame_t *frame)
{
	if (frame == NULL) {
		return SQ_EINVAL;
	}
	if (vb.rx_count == 0U) {
		return SQ_EAGAIN;
	}
	*frame = vb.rx[vb.rx_head];
	vb.rx_head = (vb.rx_head + 1U) % HAL_VBUS_RX_LEN;
	vb.rx_count--;
	return SQ_OK;
}

int hal_vbus_can_send(const hal_can_frame_t *frame)
{
	hal_can_frame_t *slot;

	if ((frame == NULL) || (frame->dlc > HAL_CAN_MAX_DLEN) ||
	    ((frame->flags & HAL_CAN_FLAG_ERR) != 0U)) {
		return SQ_EINVAL;
	}
	if (vb.status.state == HAL_CAN_STATE_BUS_OFF) {
		return SQ_ENETUNREACH;
	}
	if (vb.tx_full || (vb.tx_count >= HAL_VBUS_TX_LEN)) {
		vb.stats.tx_refused++;
		return SQ_ENOBUFS;
	}
	slot = &vb.tx[(vb.tx_head + vb.tx_count) % HAL_VBUS_TX_LEN];
	*slot = *frame;
	slot->timestamp_us = vb.now_us;
	vb.tx_count++;
	vb.stats.tx_frames++;
	return SQ_OK;
}

int hal_vbus_pop_tx(hal_can_frame_t *frame)
{
	if (frame == NULL) {
		return SQ_EINVAL;
	}
	if (vb.tx_count == 0U) {
		return SQ_EAGAIN;
	}
	*frame = vb.tx[vb.tx_head];
	vb.tx_head = (vb.tx_head + 1U) % HAL_VBUS_TX_LEN;
	vb.tx_count--;
	return SQ_OK;
}

int hal_vbus_can_get_status(hal_can_status_t *status)
{
	if (status == NULL) {
		return SQ_EINVAL;
	}
	*status = vb.status;
	return SQ_OK;
}

void hal_vbus_set_status(const hal_can_status_t *status)
{
	if (status != NULL) {
		vb.status = *status;
	}
}

int hal_vbus_can_set_rx_filter(const hal_can_filter_t *filters, uint32_t count)
{
	uint32_t i;

	for (i = 0; i < count; i++) {
		const uint32_t max = ((filters[i].flags & HAL_CAN_FLAG_EXT) != 0U) ? 0x1FFFFFFFU : 0x7FFU;

		if ((filters[i].id > max) || (filters[i].mask > max)) {
			return SQ_EINVAL;
		}
	}
	for (i = 0; i < count; i++) {
		vb.filter[i] = filters[i];
	}
	vb.filter_count = count;
	vb.filter_set = true;
	return SQ_OK;
}

int hal_vbus_set_calib(const uint8_t *block, uint32_t len)
{
	if (len > HAL_CALIB_MAX_LEN || ((block == NULL) && (len > 0U))) {
		return SQ_EINVAL;
	}
	if (len > 0U) {
		memcpy(vb.calib, block, len);
	}
	vb.calib_len = len;
	return SQ_OK;
}

int hal_vbus_calib_read(uint8_t *buf, uint32_t len)
{
	if ((buf == NULL) || (len > HAL_CALIB_MAX_LEN)) {
		return SQ_EINVAL;
	}
	if (vb.calib_len == 0U) {
		return SQ_ENOENT;
	}
	if (len > vb.calib_len) {
		return SQ_EIO; /* stored block shorter than asked: corrupt */
	}
	memcpy(buf, vb.calib, len);
	return SQ_OK;
}

int hal_vbus_calib_write(const uint8_t *buf, uint32_t len)
{
	return hal_vbus_set_calib(buf, len);
}

void hal_vbus_set_tx_full(bool full)
{
	vb.tx_full = full;
}

void hal_vbus_get_stats(hal_vbus_stats_t *stats)
{
	if (stats != NULL) {
		*stats = vb.stats;
	}
}
