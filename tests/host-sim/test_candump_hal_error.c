/* SPDX-License-Identifier: MIT */
/*
 * An error frame from the HAL to a candump line's frame
 * (host-sim/candump_hal.c): its identifier keeps only the error class bits
 * (CANDUMP_ERR_MASK, the 29 bits of a candump error line; a HAL error
 * frame carries flag bits above them), it is written as an extended
 * frame, its data kept.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "candump_hal.h"
#include "candump_log.h"

static void test_error_frame_id_masked(void **state)
{
	hal_can_frame_t hf;
	candump_frame_t f;

	(void)state;
	memset(&hf, 0, sizeof(hf));
	hf.id = 0xE0000004U; /* flag bits above bit 28, class 0x004 (controller) */
	hf.flags = HAL_CAN_FLAG_ERR;
	hf.dlc = 8U;
	hf.data[1] = 0x04U;
	candump_from_hal(&hf, 1500000000ULL, "can0", &f);
	assert_int_equal(f.kind, CANDUMP_KIND_ERROR);
	assert_int_equal(f.id, 0x00000004U);
	assert_true(f.ext);
	assert_int_equal(f.len, 8U);
	assert_int_equal(f.data[1], 0x04U);
	assert_string_equal(f.iface, "can0");
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_error_frame_id_masked),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
