/* SPDX-License-Identifier: MIT */
/*
 * hal_can_set_bitrate's range on the bxCAN driver (hal/stm32f4/bxcan.c, on
 * its register simulation): 1..1000 kbit/s. Beyond 1000 the rate is
 * refused before it is turned into bit/s: 536871412 kbit/s times 1000 is
 * 536871412000 = 125 * 2^32 + 500000, which a 32-bit product would take
 * for 500 kbit/s, the rate the bus runs at. Refused (SQ_EINVAL), the bus
 * left as it was.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "bxcan.h"
#include "bxcan_sim.h"
#include "sq_status.h"

/* Host contract handler: cmocka's expect_assert_failure() catches it. */
_Noreturn void hal_contract_failed(const char *file, uint32_t line)
{
	mock_assert(0, "hal_contract_failed", file, (int)line);
	abort();
}

static void test_rate_beyond_1000_kbps_refused(void **state)
{
	uint32_t btr;

	(void)state;
	sim_reset();
	assert_int_equal(bxcan_start(0U, 500000U), SQ_OK);
	btr = sim_btr(0U);
	assert_int_equal(hal_can_set_bitrate(0U, 1000U), SQ_OK);
	assert_int_equal(hal_can_set_bitrate(0U, 500U), SQ_OK);
	assert_int_equal(sim_btr(0U), btr);
	assert_int_equal(hal_can_set_bitrate(0U, 536871412U), SQ_EINVAL);
	assert_int_equal(hal_can_set_bitrate(0U, 1001U), SQ_EINVAL);
	assert_int_equal(sim_btr(0U), btr);
	assert_int_equal(sim_aborts(0U), 0U);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_rate_beyond_1000_kbps_refused),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
