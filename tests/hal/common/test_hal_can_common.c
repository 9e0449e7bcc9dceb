/* SPDX-License-Identifier: MIT */
/*
 * test_hal_can_common.c: the CAN FD rules every backend shares
 * (hal/common/hal_can_common.c): the format rules, the one frame check,
 * the send and receive admissions, ASan+UBSan. Built twice (mk/fd-hal.mk): as the host
 * builds are (frames of 64 bytes) and as the ECU images are
 * (-DHAL_CAN_CLASSIC_ONLY: frames of 8 bytes). Expected values are written
 * out by hand from ISO 11898-1:2015 (DLC codes 9..15 are 12, 16, 20, 24,
 * 32, 48, 64 bytes) and hal.h's flag bits (EXT 0x01, RTR 0x02, ERR 0x04,
 * FDF 0x08, BRS 0x10, ESI 0x20), never taken from the code.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "hal_can_common.h"

typedef struct {
	uint8_t flags;
	uint8_t len;
	bool ok;
} format_case_t;

static void test_format_rules(void **state)
{
	static const format_case_t cases[] = {
		{ 0x00U, 0U, true },   { 0x00U, 8U, true },   { 0x00U, 9U, false },
		{ 0x00U, 12U, false }, { 0x00U, 64U, false }, /* > 8 needs FDF */
		{ 0x02U, 8U, true },   /* classic remote */
		{ 0x04U, 8U, true },   /* error frame (received) */
		{ 0x08U, 0U, true },   { 0x08U, 1U, true },   { 0x08U, 8U, true },
		{ 0x08U, 9U, false },  { 0x08U, 11U, false }, { 0x08U, 12U, true },
		{ 0x08U, 13U, false }, { 0x08U, 16U, true },  { 0x08U, 20U, true },
		{ 0x08U, 24U, true },  { 0x08U, 25U, false }, { 0x08U, 32U, true },
		{ 0x08U, 40U, false }, { 0x08U, 48U, true },  { 0x08U, 63U, false },
		{ 0x08U, 64U, true },  { 0x08U, 65U, false }, { 0x08U, 255U, false },
		{ 0x09U, 64U, true },  /* extended FD */
		{ 0x18U, 24U, true },  { 0x28U, 24U, true },  { 0x38U, 64U, true },
		{ 0x10U, 8U, false },  /* BRS without FDF */
		{ 0x20U, 8U, false },  /* ESI without FDF */
		{ 0x0AU, 8U, false },  /* FDF with RTR */
		{ 0x0CU, 8U, false },  /* FDF with ERR */
	};
	size_t i;

	(void)state;
	for (i = 0U; i < sizeof(cases) / sizeof(cases[0]); i++) {
		if (hal_can_format_ok(cases[i].flags, cases[i].len) != cases[i].ok) {
			fail_msg("flags 0x%02x len %u: expected %s", cases[i].flags,
				 (unsigned int)cases[i].len, cases[i].ok ? "ok" : "malformed");
		}
	}
}

static hal_can_frame_t fd_frame(uint8_t len)
{
	hal_can_frame_t f;

	memset(&f, 0, sizeof(f));
	f.id = 0x0A0U;
	f.flags = HAL_CAN_FLAG_FDF;
	f.dlc = len;
	return f;
}

static void test_frame_check(void **state)
{
	hal_can_frame_t f = fd_frame(64U);

	(void)state;
	assert_int_equal(hal_can_frame_check(&f), SQ_OK);
	f.flags = (uint8_t)(HAL_CAN_FLAG_FDF | HAL_CAN_FLAG_BRS | HAL_CAN_FLAG_ESI | HAL_CAN_FLAG_EXT);
	f.id = 0x1FFFFFFFU;
	assert_int_equal(hal_can_frame_check(&f), SQ_OK);
	f.id = 0x20000000U;
	assert_int_equal(hal_can_frame_check(&f), SQ_EINVAL);
	f = fd_frame(48U);
	f.id = 0x800U; /* 12 bits on a standard FD frame */
	assert_int_equal(hal_can_frame_check(&f), SQ_EINVAL);
	f = fd_frame(8U);
	f.flags |= HAL_CAN_FLAG_ERR; /* never sent */
	assert_int_equal(hal_can_frame_check(&f), SQ_EINVAL);
	f = fd_frame(8U);
	f.flags |= 0x40U; /* undefined */
	assert_int_equal(hal_can_frame_check(&f), SQ_EINVAL);
	f = fd_frame(20U);
	assert_int_equal(hal_can_frame_check(&f), SQ_OK);
	f.dlc = 21U;
	assert_int_equal(hal_can_frame_check(&f), SQ_EINVAL);
}

/* the order of hal.h: malformed, no bus, FD on classic, listen-only */
static void test_send_admit_order_and_counts(void **state)
{
	hal_can_status_t st;
	hal_can_frame_t bad = fd_frame(13U);
	const hal_can_frame_t fd = fd_frame(24U);
	hal_can_frame_t classic = fd_frame(8U);

	(void)state;
	classic.flags = 0U;
	memset(&st, 0, sizeof(st));
	assert_int_equal(hal_can_send_admit(&bad, &st, false), SQ_EINVAL);
	assert_int_equal(hal_can_send_admit(&bad, NULL, false), SQ_EINVAL);
	assert_int_equal(hal_can_send_admit(&fd, NULL, false), SQ_ENODEV);
	assert_int_equal(hal_can_send_admit(&fd, &st, false), SQ_ENOTSUP);
	assert_int_equal(hal_can_send_admit(&fd, &st, false), SQ_ENOTSUP);
	assert_int_equal(st.fd_unsupported, 2U);
	assert_int_equal(hal_can_send_admit(&classic, &st, false), SQ_OK);
	st.mode = HAL_CAN_MODE_LISTEN_ONLY;
	assert_int_equal(hal_can_send_admit(&fd, &st, false), SQ_ENOTSUP); /* never sendable */
	assert_int_equal(hal_can_send_admit(&classic, &st, false), SQ_EPERM);
	assert_int_equal(st.tx_refused_listen_only, 1U);
	assert_int_equal(st.fd_unsupported, 3U);
	assert_int_equal(st.tx_dropped, 0U);
#if !defined(HAL_CAN_CLASSIC_ONLY)
	assert_int_equal(hal_can_send_admit(&fd, &st, true), SQ_EPERM);
	st.mode = HAL_CAN_MODE_NORMAL;
	assert_int_equal(hal_can_send_admit(&fd, &st, true), SQ_OK);
	assert_int_equal(st.fd_unsupported, 3U);
#else
	/* 8-byte frames cannot carry FD data: an FD bus is a programming error */
	expect_assert_failure(hal_can_send_admit(&fd, &st, true));
#endif
	expect_assert_failure(hal_can_send_admit(NULL, &st, false));
}

static void test_receive_admit(void **state)
{
	const hal_can_frame_t f = fd_frame(0U);

	(void)state;
	assert_int_equal(hal_can_receive_admit(&f, false, false), SQ_ENODEV);
	assert_int_equal(hal_can_receive_admit(&f, false, true), SQ_ENODEV);
	assert_int_equal(hal_can_receive_admit(&f, true, false), SQ_ENETDOWN);
	assert_int_equal(hal_can_receive_admit(&f, true, true), SQ_OK);
	expect_assert_failure(hal_can_receive_admit(NULL, true, true));
}

/* the frame's size is the build's: 64 data bytes on the host, 8 (and the
 * classic images' RAM) with HAL_CAN_CLASSIC_ONLY */
static void test_frame_size_of_the_build(void **state)
{
	const hal_can_frame_t f = fd_frame(0U);

	(void)state;
#if defined(HAL_CAN_CLASSIC_ONLY)
	assert_int_equal(sizeof(f.data), 8U);
#else
	assert_int_equal(sizeof(f.data), 64U);
#endif
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_format_rules),
		cmocka_unit_test(test_frame_check),
		cmocka_unit_test(test_send_admit_order_and_counts),
		cmocka_unit_test(test_receive_admit),
		cmocka_unit_test(test_frame_size_of_the_build),
	};

	return cmocka_run_group_tests_name(HAL_CAN_COMMON_TEST_NAME, tests, NULL, NULL);
}
