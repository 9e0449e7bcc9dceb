/* SPDX-License-Identifier: MIT */
/*
 * The platform's bring-up self-test through the app: what
 * hal_selftest() reports at start-up reaches SquealDiag page 4 in the DBC's
 * raw units, and a platform without a self-test (SQ_ENOTSUP: Linux, the
 * in-memory bus) leaves the page "not measured". Frames are read back with
 * the hand-derived bit positions of squeal.dbc (HseFreq_MHz 32|8 at
 * 0.1 MHz, ResetCause 40|3, BorLevel 43|3, LoopbackCan1 46|2, LoopbackCan2
 * 48|2, StackHighWater_B 50|14, SquealDiag_Page 12|4, Fault_SelfTest 27),
 * not with the protocol layer's decoder.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "calib.h"
#include "hal_vbus.h"
#include "sq_status.h"
#include "squeal_app.h"
#include "test_hal.h"

#define T0_US 1000000ULL

/* Boot on the defaults, run 5.5 s (every diag page once) and return the
 * last page-4 SquealDiag frame. */
static const hal_can_frame_t *boot_and_find_page4(void)
{
	const hal_can_frame_t *page4 = NULL;
	calib_t cal;

	test_hal_set_time_us(T0_US);
	calib_default(&cal);
	assert_int_equal(squeal_app_init(), SQ_OK);
	while (hal_time_us() < T0_US + 5500000ULL) {
		test_hal_advance_us(1000U);
		(void)squeal_app_poll();
	}
	for (uint32_t i = 0U; i < test_hal_tx_count(); i++) {
		const hal_can_frame_t *f = test_hal_tx_frame(i);

		if ((f->id == cal.diag_id) && (test_frame_sig(f->data, 12U, 4U) == 4U)) {
			page4 = f;
		}
	}
	assert_non_null(page4);
	return page4;
}

static void test_selftest_figures_reach_diag_page4(void **state)
{
	/* 8.000 MHz crystal, BOR level 2 (below 3: a failed check), CAN1
	 * loopback passed, no CAN2, 612 bytes of stack in the previous run */
	const hal_selftest_t st = { 8000000U, 612U, 2U, { HAL_LOOPBACK_PASS, HAL_LOOPBACK_NO_BUS },
				    true };
	const hal_can_frame_t *f;

	(void)state;
	test_hal_reset();
	hal_vbus_set_selftest(&st);
	test_hal_set_reset_reason(HAL_RESET_WATCHDOG);
	f = boot_and_find_page4();
	assert_int_equal(test_frame_sig(f->data, 32U, 8U), 80U); /* 8.0 MHz */
	assert_int_equal(test_frame_sig(f->data, 40U, 3U), 2U);  /* watchdog */
	assert_int_equal(test_frame_sig(f->data, 43U, 3U), 2U);
	assert_int_equal(test_frame_sig(f->data, 46U, 2U), 0U);
	assert_int_equal(test_frame_sig(f->data, 48U, 2U), 3U);
	assert_int_equal(test_frame_sig(f->data, 50U, 14U), 612U);
	assert_int_equal(test_frame_sig(f->data, 27U, 1U), 1U);  /* Fault_SelfTest */
}

static void test_crystal_rounds_to_100khz_and_saturates(void **state)
{
	hal_selftest_t st = { 11998000U, HAL_SELFTEST_NOT_MEASURED, HAL_SELFTEST_NO_BOR,
			      { HAL_LOOPBACK_UNAVAILABLE, HAL_LOOPBACK_UNAVAILABLE }, false };
	const hal_can_frame_t *f;

	(void)state;
	test_hal_reset();
	hal_vbus_set_selftest(&st);
	f = boot_and_find_page4();
	assert_int_equal(test_frame_sig(f->data, 32U, 8U), 120U);   /* 12.0 MHz */
	assert_int_equal(test_frame_sig(f->data, 43U, 3U), 7U);     /* no BOR */
	assert_int_equal(test_frame_sig(f->data, 46U, 2U), 2U);
	assert_int_equal(test_frame_sig(f->data, 50U, 14U), 16383U); /* unknown */
	assert_int_equal(test_frame_sig(f->data, 27U, 1U), 0U);

	test_hal_reset();
	st.hse_hz = 26000000U; /* beyond the signal: its largest value, not N/A */
	st.stack_high_water_prev_b = 100000U;
	hal_vbus_set_selftest(&st);
	f = boot_and_find_page4();
	assert_int_equal(test_frame_sig(f->data, 32U, 8U), 254U);
	assert_int_equal(test_frame_sig(f->data, 50U, 14U), 16382U);
}

static void test_no_selftest_leaves_page4_not_measured(void **state)
{
	const hal_can_frame_t *f;

	(void)state;
	test_hal_reset(); /* the in-memory bus: hal_selftest() says SQ_ENOTSUP */
	f = boot_and_find_page4();
	assert_int_equal(test_frame_sig(f->data, 32U, 8U), 255U);
	assert_int_equal(test_frame_sig(f->data, 43U, 3U), 7U);
	assert_int_equal(test_frame_sig(f->data, 50U, 14U), 16383U);
	assert_int_equal(test_frame_sig(f->data, 27U, 1U), 0U);
}

SQ_CMOCKA_MAIN(
	cmocka_unit_test(test_selftest_figures_reach_diag_page4),
	cmocka_unit_test(test_crystal_rounds_to_100khz_and_saturates),
	cmocka_unit_test(test_no_selftest_leaves_page4_not_measured))
