/* SPDX-License-Identifier: MIT */
#include "e2e_p05.h"

#include <stddef.h>

#include "crc16_ccitt.h"
#include "sq_contract.h"
#include "sq_status.h"

int e2e_p05_config_check(const e2e_p05_config_t *cfg)
{
	HAL_REQUIRE(cfg != NULL);
	if ((cfg->data_len < E2E_P05_HEADER_LEN) || (cfg->data_len > E2E_P05_MAX_LEN) ||
	    (((uint32_t)cfg->offset_byte + E2E_P05_HEADER_LEN) > cfg->data_len) ||
	    (cfg->max_delta_counter < 1U)) {
		return SQ_EINVAL;
	}
	return SQ_OK;
}

uint16_t e2e_p05_crc(const e2e_p05_config_t *cfg, const uint8_t *data, uint8_t len)
{
	const uint32_t off = cfg->offset_byte;
	uint8_t id[2];
	uint16_t c;

	HAL_REQUIRE((e2e_p05_config_check(cfg) == SQ_OK) && (data != NULL) &&
		    (len == cfg->data_len));
	id[0] = (uint8_t)(cfg->data_id & 0xFFU);
	id[1] = (uint8_t)(cfg->data_id >> 8);
	c = crc16_ccitt_update((uint16_t)CRC16_CCITT_INIT, data, off);
	c = crc16_ccitt_update(c, &data[off + 2U], (size_t)len - off - 2U);
	return crc16_ccitt_update(c, id, sizeof(id));
}

/* The CRC as stored: little-endian at the offset. */
static uint16_t stored_crc(const e2e_p05_config_t *cfg, const uint8_t *data)
{
	return (uint16_t)(data[cfg->offset_byte] |
			  ((uint32_t)data[cfg->offset_byte + 1U] << 8));
}

int e2e_p05_protect(const e2e_p05_config_t *cfg, e2e_p01_tx_t *tx,
		    uint8_t *data, uint8_t len)
{
	uint16_t c;

	HAL_REQUIRE((e2e_p05_config_check(cfg) == SQ_OK) && (tx != NULL) && (data != NULL));
	HAL_REQUIRE(len == cfg->data_len);
	data[cfg->offset_byte + 2U] = tx->counter;
	c = e2e_p05_crc(cfg, data, len);
	data[cfg->offset_byte] = (uint8_t)(c & 0xFFU);
	data[cfg->offset_byte + 1U] = (uint8_t)(c >> 8);
	tx->counter = (uint8_t)((tx->counter + 1U) % E2E_P05_MODULUS);
	return SQ_OK;
}

e2e_p01_status_t e2e_p05_check(const e2e_p05_config_t *cfg, e2e_p01_rx_t *rx,
			       const uint8_t *data, uint8_t len)
{
	bool ok;

	/* a bad configuration is the caller's error, never a wrong CRC */
	HAL_REQUIRE((rx != NULL) && (e2e_p05_config_check(cfg) == SQ_OK));
	ok = (data != NULL) && (len == cfg->data_len) &&
	     (stored_crc(cfg, data) == e2e_p05_crc(cfg, data, len));
	return e2e_rx_frame(rx, (uint16_t)E2E_P05_MODULUS, data != NULL, ok,
			    ok ? data[cfg->offset_byte + 2U] : 0U, cfg->max_delta_counter);
}
