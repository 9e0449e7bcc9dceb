/* SPDX-License-Identifier: MIT */
/*
 * AUTOSAR E2E Profile 1 (variant 1A) protect and check, written from the
 * profile's description (see e2e_p01.h for the exact behaviour).
 */
#include "e2e_p01.h"

#include <stddef.h>

#include "crc8_p01.h"
#include "sq_contract.h"
#include "sq_status.h"

#define COUNTER_MODULO 15U /* counters 0..14 */
#define COUNTER_MASK   0x0FU

int e2e_p01_config_check(const e2e_p01_config_t *cfg)
{
	if (cfg == NULL) {
		return SQ_EINVAL;
	}
	if (cfg->data_len < E2E_P01_MIN_LEN || cfg->data_len > E2E_P01_MAX_LEN) {
		return SQ_EINVAL;
	}
	if (cfg->max_delta_counter < 1U ||
	    cfg->max_delta_counter > E2E_P01_COUNTER_MAX) {
		return SQ_EINVAL;
	}
	return SQ_OK;
}

/* CRC over data ID (low, high) and bytes 1..len-1; caller checked args. */
static uint8_t frame_crc(const e2e_p01_config_t *cfg, const uint8_t *data,
			 uint8_t len)
{
	uint8_t id[2];
	uint8_t crc;

	id[0] = (uint8_t)(cfg->data_id & 0xFFU);
	id[1] = (uint8_t)(cfg->data_id >> 8);
	crc = crc8_p01_update(0x00U, id, sizeof(id));
	return crc8_p01_update(crc, &data[1], (size_t)len - 1U);
}

int e2e_p01_crc(const e2e_p01_config_t *cfg, const uint8_t *data,
		uint8_t len, uint8_t *crc)
{
	/* a bad configuration or length is the caller's error, not the data's */
	HAL_REQUIRE((e2e_p01_config_check(cfg) == SQ_OK) && (data != NULL) && (crc != NULL));
	HAL_REQUIRE(len == cfg->data_len);
	*crc = frame_crc(cfg, data, len);
	return SQ_OK;
}

void e2e_p01_tx_init(e2e_p01_tx_t *tx)
{
	HAL_REQUIRE(tx != NULL);
	tx->counter = 0U;
}

int e2e_p01_protect(const e2e_p01_config_t *cfg, e2e_p01_tx_t *tx,
		    uint8_t *data, uint8_t len)
{
	HAL_REQUIRE((e2e_p01_config_check(cfg) == SQ_OK) && (tx != NULL) && (data != NULL));
	HAL_REQUIRE((len == cfg->data_len) && (tx->counter <= E2E_P01_COUNTER_MAX));
	data[1] = (uint8_t)((data[1] & 0xF0U) | tx->counter);
	data[0] = frame_crc(cfg, data, len);
	tx->counter = (uint8_t)((tx->counter + 1U) % COUNTER_MODULO);
	return SQ_OK;
}

void e2e_p01_rx_reset(e2e_p01_rx_t *rx)
{
	HAL_REQUIRE(rx != NULL);
	rx->last_valid_counter = 0U;
	rx->max_delta_counter = 0U;
	rx->lost_data = 0U;
	rx->wait_for_first_data = true;
	rx->resync = false;
	rx->status = E2E_P01_STATUS_NONEWDATA;
}

void e2e_p01_rx_init(e2e_p01_rx_t *rx)
{
	size_t i;

	HAL_REQUIRE(rx != NULL);
	e2e_p01_rx_reset(rx);
	for (i = 0; i < (size_t)E2E_P01_STATUS_COUNT; i++) {
		rx->status_count[i] = 0U;
	}
}

/*
 * The sequence part of the check, for a frame whose CRC is good, with the
 * counter running 0 .. modulus - 1 (P01: 15, P02: 16, P05: 256, a maker's
 * counter 2..16). Shared by every protection that has a counter.
 */
e2e_p01_status_t e2e_rx_sequence(e2e_p01_rx_t *rx, uint8_t counter,
				 uint16_t modulus, uint8_t max_delta_counter)
{
	uint8_t delta;

	if (rx->wait_for_first_data) {
		rx->wait_for_first_data = false;
		rx->resync = false;
		rx->max_delta_counter = max_delta_counter;
		rx->last_valid_counter = counter;
		rx->lost_data = 0U;
		return E2E_P01_STATUS_INITIAL;
	}
	delta = (uint8_t)(((uint32_t)counter + modulus - rx->last_valid_counter) %
			  modulus);
	if (delta == 0U) {
		return E2E_P01_STATUS_REPEATED;
	}
	if (delta > rx->max_delta_counter) {
		/* Adopt the new sequence, but use nothing until the next frame
		 * confirms it. */
		rx->resync = true;
		rx->max_delta_counter = max_delta_counter;
		rx->last_valid_counter = counter;
		return E2E_P01_STATUS_WRONGSEQUENCE;
	}
	rx->max_delta_counter = max_delta_counter;
	rx->last_valid_counter = counter;
	rx->lost_data = (uint8_t)(delta - 1U);
	if (rx->resync) {
		rx->resync = false;
		return E2E_P01_STATUS_INITIAL;
	}
	return delta == 1U ? E2E_P01_STATUS_OK : E2E_P01_STATUS_OKSOMELOST;
}

void e2e_rx_cycle(e2e_p01_rx_t *rx, uint16_t modulus)
{
	if ((uint32_t)rx->max_delta_counter + 1U < modulus) {
		rx->max_delta_counter++;
	}
}

e2e_p01_status_t e2e_rx_record(e2e_p01_rx_t *rx, e2e_p01_status_t st)
{
	rx->status = st;
	if (rx->status_count[st] < UINT32_MAX) {
		rx->status_count[st]++;
	}
	return st;
}

e2e_p01_status_t e2e_rx_frame(e2e_p01_rx_t *rx, uint16_t modulus, bool present, bool crc_ok,
			      uint8_t counter, uint8_t max_delta_counter)
{
	e2e_p01_status_t st;

	e2e_rx_cycle(rx, modulus);
	if (!present) {
		st = E2E_P01_STATUS_NONEWDATA;
	} else if (!crc_ok) {
		st = E2E_P01_STATUS_WRONGCRC;
	} else {
		st = e2e_rx_sequence(rx, counter, modulus, max_delta_counter);
	}
	return e2e_rx_record(rx, st);
}

/* P01's sequence check: counter 15 is never sent by a P01 sender. */
static e2e_p01_status_t check_sequence(const e2e_p01_config_t *cfg,
				       e2e_p01_rx_t *rx, uint8_t counter)
{
	if (counter > E2E_P01_COUNTER_MAX) {
		/* a P01 sender never sends 15: a corrupted or foreign sender */
		return E2E_P01_STATUS_WRONGSEQUENCE;
	}
	return e2e_rx_sequence(rx, counter, (uint8_t)COUNTER_MODULO,
			       cfg->max_delta_counter);
}

e2e_p01_status_t e2e_p01_check(const e2e_p01_config_t *cfg,
			       e2e_p01_rx_t *rx,
			       const uint8_t *data, uint8_t len)
{
	e2e_p01_status_t st;

	/* A NULL or invalid configuration is a programming error, never a
	 * wrong CRC: a bad frame and a bad build must not look alike. */
	HAL_REQUIRE((rx != NULL) && (e2e_p01_config_check(cfg) == SQ_OK));
	/* Each call is one receive cycle: the tolerated jump grows, so frames
	 * lost while nothing (or nothing valid) arrived are tolerated. */
	e2e_rx_cycle(rx, (uint8_t)COUNTER_MODULO);
	if (data == NULL) {
		st = E2E_P01_STATUS_NONEWDATA;
	} else if (len != cfg->data_len ||
		   data[0] != frame_crc(cfg, data, len)) {
		st = E2E_P01_STATUS_WRONGCRC;
	} else {
		st = check_sequence(cfg, rx, (uint8_t)(data[1] & COUNTER_MASK));
	}
	return e2e_rx_record(rx, st);
}

bool e2e_p01_status_usable(e2e_p01_status_t status)
{
	return status == E2E_P01_STATUS_OK ||
	       status == E2E_P01_STATUS_OKSOMELOST ||
	       status == E2E_P01_STATUS_INITIAL;
}

const char *e2e_p01_status_name(e2e_p01_status_t status)
{
	switch (status) {
	case E2E_P01_STATUS_OK:
		return "OK";
	case E2E_P01_STATUS_INITIAL:
		return "INITIAL";
	case E2E_P01_STATUS_OKSOMELOST:
		return "OKSOMELOST";
	case E2E_P01_STATUS_REPEATED:
		return "REPEATED";
	case E2E_P01_STATUS_WRONGSEQUENCE:
		return "WRONGSEQUENCE";
	case E2E_P01_STATUS_WRONGCRC:
		return "WRONGCRC";
	case E2E_P01_STATUS_NONEWDATA:
		return "NONEWDATA";
	default:
		return "?";
	}
}
