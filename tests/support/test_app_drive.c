/* SPDX-License-Identifier: MIT */
/* Driving the application through the test HAL: see test_app_drive.h. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "squeal_app.h"
#include "sq_status.h"
#include "test_app_drive.h"
#include "test_hal.h"

void test_app_boot(const calib_t *cal, uint64_t t0_us)
{
	uint8_t buf[CALIB_BLOCK_LEN];

	test_hal_reset();
	test_hal_set_time_us(t0_us);
	if (cal != NULL) {
		assert_int_equal(calib_encode(cal, buf, sizeof(buf)), SQ_OK);
		test_hal_calib_store(buf, sizeof(buf));
	}
	assert_int_equal(squeal_app_init(), SQ_OK);
	(void)squeal_app_poll();
}

void test_app_run_to(uint64_t t_us)
{
	while (hal_time_us() < t_us) {
		test_hal_advance_us(1000U);
		(void)squeal_app_poll();
	}
}

void test_app_push(const hal_can_frame_t *f)
{
	assert_int_equal(test_hal_rx_push(f), SQ_OK);
}

uint64_t test_app_tx_first(uint32_t id, uint64_t t_us, uint32_t start, uint32_t len,
			   uint64_t value, bool want)
{
	int32_t i = -1;

	while ((i = test_hal_tx_find(id, (uint32_t)(i + 1))) >= 0) {
		const hal_can_frame_t *f = test_hal_tx_frame((uint32_t)i);

		if ((f->timestamp_us >= t_us) && ((test_frame_sig(f->data, start, len) == value) == want)) {
			return f->timestamp_us;
		}
	}
	return 0U;
}

uint64_t test_app_tx_last_sig(uint32_t id, uint32_t start, uint32_t len)
{
	const hal_can_frame_t *f = test_hal_tx_last(id);

	assert_non_null(f);
	return (f != NULL) ? test_frame_sig(f->data, start, len) : 0U;
}

uint16_t test_app_diag_at(uint32_t diag_id, uint64_t t_us, uint32_t *page, const uint8_t **data)
{
	const hal_can_frame_t *f = test_hal_tx_at(diag_id, t_us);

	if (f == NULL) {
		fail_msg("no SquealDiag at %llu us", (unsigned long long)t_us);
		return 0U;
	}
	if (page != NULL) {
		*page = (uint32_t)test_frame_sig(f->data, 12, 4);
	}
	if (data != NULL) {
		*data = f->data;
	}
	return (uint16_t)test_frame_sig(f->data, 16, 11);
}
