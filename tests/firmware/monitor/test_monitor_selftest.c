/* SPDX-License-Identifier: MIT */
/*
 * SquealDiag page 4, the bring-up self-test: the monitor cycles pages 0..4 and reports
 * the platform's self-test on page 4 with the DBC's raw units, "not
 * measured" until the platform passes its figures, Fault_SelfTest in every
 * page once a check failed, and refuses out-of-range figures. Frames are
 * read back with the hand-derived bit positions of squeal.dbc (HseFreq_MHz
 * 32|8, ResetCause 40|3, BorLevel 43|3, LoopbackCan1 46|2, LoopbackCan2
 * 48|2, StackHighWater_B 50|14, SquealDiag_Page 12|4, Fault_SelfTest 27),
 * not with the protocol layer's own decoder.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "calib.h"
#include "monitor.h"
#include "sq_status.h"

_Noreturn void hal_contract_failed(const char *file, uint32_t line)
{
	mock_assert(0, "hal_contract_failed", file, (int)line);
	abort();
}

static uint32_t bits(const uint8_t *d, uint32_t start, uint32_t len)
{
	uint64_t v = 0U;

	for (uint32_t i = 0U; i < 8U; i++) {
		v |= (uint64_t)d[i] << (8U * i);
	}
	return (uint32_t)((v >> start) & ((1ULL << len) - 1U));
}

/* Run the monitor for `seconds` and keep the SquealDiag frames, by page. */
static uint32_t collect(monitor_t *m, uint64_t *now, uint32_t seconds, uint8_t pages[][8], bool *seen)
{
	hal_can_frame_t f;
	uint32_t n = 0U;

	for (uint32_t ms = 0U; ms < seconds * 1000U; ms++) {
		*now += 1000U;
		monitor_step(m, *now);
		while (monitor_peek_tx(m, &f) == SQ_OK) {
			if (f.id == m->corner.diag_id) {
				uint32_t p = bits(f.data, 12U, 4U);

				assert_true(p < 5U);
				memcpy(pages[p], f.data, 8U);
				seen[p] = true;
				n++;
			}
			monitor_tx_done(m, SQ_OK);
		}
	}
	return n;
}

static void test_page4_cycle_and_values(void **state)
{
	static monitor_t m;
	calib_t cal;
	uint64_t now = 1000000U;
	uint8_t pages[5][8];
	bool seen[5] = { false };
	const monitor_selftest_t st = { 80U, 4U, 3U, { 0U, 2U }, 480U, true };

	(void)state;
	calib_default(&cal);
	assert_int_equal(monitor_init(&m, &cal, false, 0U, now), SQ_OK);
	/* before the platform's figures: not measured */
	assert_true(collect(&m, &now, 5U, pages, seen) >= 5U); /* one a second */
	for (uint32_t p = 0U; p < 5U; p++) {
		assert_true(seen[p]);
	}
	assert_int_equal(bits(pages[4], 32U, 8U), 255U);   /* not available */
	assert_int_equal(bits(pages[4], 43U, 3U), 7U);
	assert_int_equal(bits(pages[4], 50U, 14U), 16383U);
	assert_int_equal(bits(pages[4], 27U, 1U), 0U);

	assert_int_equal(monitor_set_selftest(&m, &st), SQ_OK);
	memset(seen, 0, sizeof(seen));
	assert_true(collect(&m, &now, 5U, pages, seen) >= 5U); /* one a second */
	assert_int_equal(bits(pages[4], 32U, 8U), 80U);    /* 8.0 MHz */
	assert_int_equal(bits(pages[4], 40U, 3U), 4U);     /* fault reset */
	assert_int_equal(bits(pages[4], 43U, 3U), 3U);
	assert_int_equal(bits(pages[4], 46U, 2U), 0U);
	assert_int_equal(bits(pages[4], 48U, 2U), 2U);
	assert_int_equal(bits(pages[4], 50U, 14U), 480U);
	for (uint32_t p = 0U; p < 5U; p++) {
		assert_int_equal(bits(pages[p], 27U, 1U), 1U); /* Fault_SelfTest everywhere */
	}
	/* page 3 still carries its own counters only, not the self-test */
	assert_int_equal(bits(pages[3], 32U, 32U) & 0xFFU, 0U);
}

static void test_out_of_range_refused(void **state)
{
	static monitor_t m;
	calib_t cal;
	monitor_selftest_t st = { 80U, 4U, 3U, { 0U, 0U }, 480U, false };

	(void)state;
	calib_default(&cal);
	assert_int_equal(monitor_init(&m, &cal, false, 0U, 0U), SQ_OK);
	assert_int_equal(monitor_set_selftest(&m, &st), SQ_OK);
	st.reset_cause = 7U;
	assert_int_equal(monitor_set_selftest(&m, &st), SQ_ERANGE);
	st.reset_cause = 0U;
	st.bor_level = 5U;
	assert_int_equal(monitor_set_selftest(&m, &st), SQ_ERANGE);
	st.bor_level = 7U;
	st.loopback[1] = 4U;
	assert_int_equal(monitor_set_selftest(&m, &st), SQ_ERANGE);
	st.loopback[1] = 0U;
	st.stack_high_water_b = 16384U;
	assert_int_equal(monitor_set_selftest(&m, &st), SQ_ERANGE);
	assert_int_equal(m.selftest.reset_cause, 4U); /* unchanged */
	expect_assert_failure(monitor_set_selftest(&m, NULL));
}

SQ_CMOCKA_MAIN(
	cmocka_unit_test(test_page4_cycle_and_values),
	cmocka_unit_test(test_out_of_range_refused))
