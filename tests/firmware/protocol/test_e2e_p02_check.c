/* SPDX-License-Identifier: MIT */
/*
 * AUTOSAR E2E Profile 2 (firmware/protocol/e2e_p02.c): the configuration's
 * bounds and the receiver's verdicts, both numeric builds. Every frame's
 * CRC comes from the bitwise CRC-8H2F written here (MSB first, poly 0x2F,
 * init 0xFF, xorout 0xFF, over bytes 1..len-1 then DataIDList[counter];
 * check value 0xDF over "123456789"), never from the code under test.
 *
 *   config: data_len 2..8, max_delta_counter 1..15 (the counter has 16
 *           values: 15 is the largest jump that is not a repetition)
 *   a frame one byte shorter or longer than data_len is WRONGCRC, even
 *   when its CRC is right for its own length
 *   counter 0, 1 (OK), 1 again (REPEATED), a jump of 15 with
 *   max_delta_counter 15 (OKSOMELOST, 14 lost)
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "e2e_p01.h"
#include "e2e_p02.h"
#include "sq_status.h"

/* one byte into the bitwise CRC-8H2F register */
static uint32_t ref_byte(uint32_t c, uint8_t byte)
{
	c ^= byte;
	for (int k = 0; k < 8; k++) {
		c = ((c & 0x80U) != 0U) ? (((c << 1) ^ 0x2FU) & 0xFFU) : ((c << 1) & 0xFFU);
	}
	return c;
}

static uint8_t ref_crc8h2f(const uint8_t *d, size_t n, uint8_t id)
{
	uint32_t c = 0xFFU;

	for (size_t i = 0U; i < n; i++) {
		c = ref_byte(c, d[i]);
	}
	return (uint8_t)(ref_byte(c, id) ^ 0xFFU);
}

static e2e_p02_config_t config(uint8_t len, uint8_t max_delta)
{
	e2e_p02_config_t c;

	for (uint32_t i = 0U; i < E2E_P02_DATA_ID_COUNT; i++) {
		c.data_id_list[i] = (uint8_t)(0x31U + 7U * i);
	}
	c.data_len = len;
	c.max_delta_counter = max_delta;
	return c;
}

/* a frame of len bytes with the counter, its CRC by the reference */
static void frame(const e2e_p02_config_t *c, uint8_t counter, uint8_t *d, uint8_t len)
{
	for (uint8_t i = 2U; i < len; i++) {
		d[i] = (uint8_t)(0x10U * i + 3U);
	}
	d[1] = (uint8_t)(0x50U | counter);
	d[0] = ref_crc8h2f(&d[1], (size_t)len - 1U, c->data_id_list[counter]);
}

static void test_reference_check_value(void **state)
{
	const uint8_t s[] = "123456789";
	uint32_t c = 0xFFU;

	(void)state;
	for (size_t i = 0U; i < 9U; i++) {
		c = ref_byte(c, s[i]);
	}
	assert_int_equal(c ^ 0xFFU, 0xDFU);
	assert_int_equal(crc8_h2f(s, 9U), 0xDFU);
}

static void test_config_bounds(void **state)
{
	e2e_p02_config_t c;

	(void)state;
	c = config(8U, 15U);
	assert_int_equal(e2e_p02_config_check(&c), SQ_OK);
	c = config(8U, 16U);
	assert_int_equal(e2e_p02_config_check(&c), SQ_EINVAL);
	c = config(8U, 1U);
	assert_int_equal(e2e_p02_config_check(&c), SQ_OK);
	c = config(8U, 0U);
	assert_int_equal(e2e_p02_config_check(&c), SQ_EINVAL);
	c = config(2U, 1U);
	assert_int_equal(e2e_p02_config_check(&c), SQ_OK);
	c = config(1U, 1U);
	assert_int_equal(e2e_p02_config_check(&c), SQ_EINVAL);
	c = config(9U, 1U);
	assert_int_equal(e2e_p02_config_check(&c), SQ_EINVAL);
}

static void test_wrong_length_is_wrong_crc(void **state)
{
	const e2e_p02_config_t c = config(7U, 2U);
	e2e_p01_rx_t rx;
	uint8_t d[8];

	(void)state;
	e2e_p01_rx_init(&rx);
	frame(&c, 3U, d, 7U);
	assert_int_equal(e2e_p02_check(&c, &rx, d, 7U), E2E_P01_STATUS_INITIAL);
	/* right CRC for 6 and for 8 bytes, but not the configured 7 */
	frame(&c, 4U, d, 6U);
	assert_int_equal(e2e_p02_check(&c, &rx, d, 6U), E2E_P01_STATUS_WRONGCRC);
	frame(&c, 4U, d, 8U);
	assert_int_equal(e2e_p02_check(&c, &rx, d, 8U), E2E_P01_STATUS_WRONGCRC);
	/* and a wrong CRC of the right length */
	frame(&c, 4U, d, 7U);
	d[0] ^= 0x01U;
	assert_int_equal(e2e_p02_check(&c, &rx, d, 7U), E2E_P01_STATUS_WRONGCRC);
	assert_int_equal(e2e_p02_check(&c, &rx, NULL, 7U), E2E_P01_STATUS_NONEWDATA);
}

static void test_sequence_up_to_the_largest_jump(void **state)
{
	const e2e_p02_config_t c = config(8U, 15U);
	e2e_p01_rx_t rx;
	uint8_t d[8];

	(void)state;
	e2e_p01_rx_init(&rx);
	frame(&c, 0U, d, 8U);
	assert_int_equal(e2e_p02_check(&c, &rx, d, 8U), E2E_P01_STATUS_INITIAL);
	frame(&c, 1U, d, 8U);
	assert_int_equal(e2e_p02_check(&c, &rx, d, 8U), E2E_P01_STATUS_OK);
	assert_int_equal(e2e_p02_check(&c, &rx, d, 8U), E2E_P01_STATUS_REPEATED);
	/* 1 -> 0: a jump of 15, the largest max_delta_counter 15 allows */
	frame(&c, 0U, d, 8U);
	assert_int_equal(e2e_p02_check(&c, &rx, d, 8U), E2E_P01_STATUS_OKSOMELOST);
	assert_int_equal(rx.lost_data, 14U);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_reference_check_value),
		cmocka_unit_test(test_config_bounds),
		cmocka_unit_test(test_wrong_length_is_wrong_crc),
		cmocka_unit_test(test_sequence_up_to_the_largest_jump),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
