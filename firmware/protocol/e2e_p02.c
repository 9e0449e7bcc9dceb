/* SPDX-License-Identifier: MIT */
#include "e2e_p02.h"

#include "sq_contract.h"
#include "sq_status.h"

#define CRC8_H2F_POLY 0x2FU
#define COUNTER_MASK 0x0FU

/* Bitwise: 8 steps per byte, a CAN frame has at most 8 bytes, so a table
 * would buy little and cost 256 bytes of flash. */
uint8_t crc8_h2f_update(uint8_t crc, const uint8_t *data, size_t len)
{
	size_t i;
	uint32_t k;
	uint32_t c = crc;

	for (i = 0U; i < len; i++) {
		c ^= data[i];
		for (k = 0U; k < 8U; k++) {
			c = ((c & 0x80U) != 0U) ? (((c << 1) ^ CRC8_H2F_POLY) & 0xFFU) :
				((c << 1) & 0xFFU);
		}
	}
	return (uint8_t)c;
}

uint8_t crc8_h2f(const uint8_t *data, size_t len)
{
	return (uint8_t)(crc8_h2f_update(0xFFU, data, len) ^ 0xFFU);
}

int e2e_p02_config_check(const e2e_p02_config_t *cfg)
{
	HAL_REQUIRE(cfg != NULL);
	if ((cfg->data_len < 2U) || (cfg->data_len > 8U) ||
	    (cfg->max_delta_counter < 1U) || (cfg->max_delta_counter > 15U)) {
		return SQ_EINVAL;
	}
	return SQ_OK;
}

uint8_t e2e_p02_crc(const e2e_p02_config_t *cfg, const uint8_t *data, uint8_t len)
{
	uint8_t id;
	uint8_t c;

	HAL_REQUIRE((cfg != NULL) && (data != NULL) && (len >= 2U) && (len <= 8U));
	id = cfg->data_id_list[data[1] & COUNTER_MASK];
	c = crc8_h2f_update(0xFFU, &data[1], (size_t)len - 1U);
	return (uint8_t)(crc8_h2f_update(c, &id, 1U) ^ 0xFFU);
}

int e2e_p02_protect(const e2e_p02_config_t *cfg, e2e_p01_tx_t *tx,
		    uint8_t *data, uint8_t len)
{
	HAL_REQUIRE((e2e_p02_config_check(cfg) == SQ_OK) && (tx != NULL) && (data != NULL));
	HAL_REQUIRE((len == cfg->data_len) && (tx->counter <= COUNTER_MASK));
	data[1] = (uint8_t)((data[1] & 0xF0U) | tx->counter);
	data[0] = e2e_p02_crc(cfg, data, len);
	tx->counter = (uint8_t)((tx->counter + 1U) % E2E_P02_MODULUS);
	return SQ_OK;
}

e2e_p01_status_t e2e_p02_check(const e2e_p02_config_t *cfg, e2e_p01_rx_t *rx,
			       const uint8_t *data, uint8_t len)
{
	bool ok;

	/* a bad configuration is the caller's error, never a wrong CRC */
	HAL_REQUIRE((rx != NULL) && (e2e_p02_config_check(cfg) == SQ_OK));
	ok = (data != NULL) && (len == cfg->data_len) && (data[0] == e2e_p02_crc(cfg, data, len));
	return e2e_rx_frame(rx, (uint16_t)E2E_P02_MODULUS, data != NULL, ok,
			    ok ? (uint8_t)(data[1] & COUNTER_MASK) : 0U, cfg->max_delta_counter);
}
