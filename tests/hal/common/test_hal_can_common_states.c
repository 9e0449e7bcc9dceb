/* SPDX-License-Identifier: MIT */
/*
 * The rules every CAN backend shares (hal/common/hal_can_common.c): the
 * frame check of hal_can_send(), the filter check of
 * hal_can_set_rx_filter(), the one bus-state change and its counts; run
 * through the in-memory backend (hal/vbus), whose send and filter answer
 * the same before its bus. Both numeric builds, ASan+UBSan. The expected
 * values are written out by hand from hal.h's definitions (11-bit ids end
 * at 0x7FF, 29-bit ones at 0x1FFFFFFF, flags EXT 0x01, RTR 0x02, ERR 0x04),
 * never taken from the code.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "hal_can_common.h"
#include "hal_vbus.h"

static int set_up(void **state)
{
	(void)state;
	hal_vbus_reset();
	hal_vbus_set_time_us(1000U);
	return 0;
}

static void test_state_change_counts_every_transition(void **state)
{
	hal_can_status_t st;

	(void)state;
	memset(&st, 0, sizeof(st));
	st.state = HAL_CAN_STATE_STOPPED;
	assert_false(hal_can_state_change(&st, HAL_CAN_STATE_STOPPED));
	assert_int_equal(st.state_changes, 0U);
	assert_true(hal_can_state_change(&st, HAL_CAN_STATE_ERROR_ACTIVE));
	assert_true(hal_can_state_change(&st, HAL_CAN_STATE_ERROR_WARNING));
	assert_true(hal_can_state_change(&st, HAL_CAN_STATE_ERROR_PASSIVE));
	assert_true(hal_can_state_change(&st, HAL_CAN_STATE_BUS_OFF));
	assert_false(hal_can_state_change(&st, HAL_CAN_STATE_BUS_OFF));
	assert_true(hal_can_state_change(&st, HAL_CAN_STATE_ERROR_ACTIVE));
	assert_true(hal_can_state_change(&st, HAL_CAN_STATE_BUS_OFF));
	assert_int_equal(st.state, HAL_CAN_STATE_BUS_OFF);
	assert_int_equal(st.state_changes, 6U);
	assert_int_equal(st.bus_off_count, 2U);
	expect_assert_failure(hal_can_state_change(NULL, HAL_CAN_STATE_STOPPED));
	expect_assert_failure(hal_can_state_change(&st, (hal_can_state_t)5));
}

typedef struct {
	uint32_t id;
	uint8_t flags;
	uint8_t dlc;
	int expect;
} frame_case_t;

static void test_frame_check_table(void **state)
{
	static const frame_case_t cases[] = {
		{ 0x000U, 0x00U, 0U, SQ_OK },
		{ 0x7FFU, 0x00U, 8U, SQ_OK },          /* largest 11-bit id */
		{ 0x800U, 0x00U, 8U, SQ_EINVAL },
		{ 0x1FFFFFFFU, 0x01U, 8U, SQ_OK },     /* largest 29-bit id */
		{ 0x20000000U, 0x01U, 8U, SQ_EINVAL },
		{ 0x7FFU, 0x02U, 8U, SQ_OK },          /* remote frame, DLC 8 */
		{ 0x1FFFFFFFU, 0x03U, 0U, SQ_OK },     /* extended remote frame */
		{ 0x100U, 0x00U, 9U, SQ_EINVAL },
		{ 0x100U, 0x02U, 15U, SQ_EINVAL },
		{ 0x100U, 0x04U, 8U, SQ_EINVAL },      /* error frame */
		{ 0x100U, 0x08U, 1U, SQ_OK },          /* FDF: an FD frame of 1 byte */
		{ 0x100U, 0x10U, 1U, SQ_EINVAL },      /* BRS without FDF */
		{ 0x100U, 0x20U, 1U, SQ_EINVAL },      /* ESI without FDF */
		{ 0x100U, 0x40U, 1U, SQ_EINVAL },      /* undefined bits */
		{ 0x100U, 0x81U, 1U, SQ_EINVAL },
	};
	size_t i;

	(void)state;
	for (i = 0U; i < sizeof(cases) / sizeof(cases[0]); i++) {
		hal_can_frame_t f;

		memset(&f, 0, sizeof(f));
		f.id = cases[i].id;
		f.flags = cases[i].flags;
		f.dlc = cases[i].dlc;
		assert_int_equal(hal_can_frame_check(&f), cases[i].expect);
		/* hal_can_send of this backend answers the same before its bus */
		assert_int_equal(hal_can_send(0U, &f), cases[i].expect);
	}
	expect_assert_failure(hal_can_frame_check(NULL));
}

static void test_filter_check_table(void **state)
{
	const hal_can_filter_t ok[3] = { { 0x7FFU, 0x7FFU, 0x00U },
					 { 0x1FFFFFFFU, 0x1FFFFFFFU, 0x01U },
					 { 0x000U, 0x000U, 0x00U } };
	const hal_can_filter_t bad[5] = { { 0x800U, 0x7FFU, 0x00U }, { 0x100U, 0x800U, 0x00U },
					  { 0x20000000U, 0x0U, 0x01U }, { 0x100U, 0x7FFU, 0x02U },
					  { 0x100U, 0x7FFU, 0x04U } };
	hal_can_filter_t many[HAL_CAN_MAX_FILTERS + 1U];
	size_t i;

	(void)state;
	assert_int_equal(hal_can_filter_check(ok, 3U), SQ_OK);
	assert_int_equal(hal_can_filter_check(NULL, 0U), SQ_OK);
	for (i = 0U; i < 5U; i++) {
		const hal_can_filter_t two[2] = { ok[0], bad[i] };

		assert_int_equal(hal_can_filter_check(two, 2U), SQ_EINVAL);
		assert_int_equal(hal_can_set_rx_filter(0U, two, 2U), SQ_EINVAL);
	}
	memset(many, 0, sizeof(many));
	expect_assert_failure(hal_can_filter_check(many, HAL_CAN_MAX_FILTERS + 1U));
	expect_assert_failure(hal_can_filter_check(NULL, 1U));
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup(test_state_change_counts_every_transition, set_up),
		cmocka_unit_test_setup(test_frame_check_table, set_up),
		cmocka_unit_test_setup(test_filter_check_table, set_up),
	};

	return cmocka_run_group_tests_name("hal_can_common", tests, NULL, NULL);
}
