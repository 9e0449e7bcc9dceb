/* SPDX-License-Identifier: MIT */
/*
 * hal/linux without a CAN bus, on the build host itself: the "kernel
 * without CAN" message (when this host's kernel really has none, through
 * hal_linux.c's error text and fault bits), the closed-socket contract. The
 * CAN socket itself is tested on vcan in the guest (selftest_hal_linux.c),
 * the open's name check and socket errors on a wrapped socket() in
 * test_hal_linux_can_open.c; time, idle and calibration file:
 * test_hal_linux_time.c, test_hal_linux_idle.c, test_hal_linux_calib.c.
 */
#include <errno.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "hal_linux.h"

static void test_open_on_kernel_without_can_names_the_remedy(void **state)
{
	int fd;
	int rc;

	(void)state;
	fd = socket(PF_CAN, SOCK_RAW, 1 /* CAN_RAW */);
	if (fd >= 0 || errno != EAFNOSUPPORT) {
		if (fd >= 0) {
			(void)close(fd);
		}
		printf("# this host's kernel has CAN: the no-CAN message is not testable here\n");
		skip();
	}
	rc = hal_linux_open(0U, "vcan0", NULL);
	assert_int_equal(rc, SQ_ENOTSUP);
	assert_non_null(strstr(hal_linux_strerror(), "this kernel has no CAN support"));
	assert_non_null(strstr(hal_linux_strerror(), "modprobe can-raw / vcan"));
	assert_true((hal_platform_faults() & HAL_FAULT_CAN_INIT) != 0U);
}

static void test_closed_can_reports_stopped_and_checks_arguments(void **state)
{
	hal_can_frame_t f = { .id = 0x123U, .dlc = 1U };
	hal_can_status_t st;
	hal_can_filter_t flt[HAL_CAN_MAX_FILTERS + 1U] = {
		{ 0x100U, HAL_CAN_STD_ID_MAX, 0U }, { 0x101U, HAL_CAN_STD_ID_MAX, 0U }
	};

	(void)state;
	hal_linux_close();
	assert_int_equal(hal_linux_can_fd(0U), -1);
	assert_int_equal(hal_can_send(0U, &f), SQ_ENETDOWN);
	assert_int_equal(hal_can_receive(0U, &f), SQ_ENETDOWN);
	/* programming errors go to the contract handler, not to a return code */
	expect_assert_failure(hal_can_receive(0U, NULL));
	expect_assert_failure(hal_can_send(0U, NULL));
	expect_assert_failure(hal_can_get_status(0U, NULL));
	expect_assert_failure(hal_can_send(HAL_CAN_BUSES, &f));
	assert_int_equal(hal_can_get_status(0U, &st), SQ_OK);
	assert_int_equal(st.state, HAL_CAN_STATE_STOPPED);
	f.dlc = 9U;
	assert_int_equal(hal_can_send(0U, &f), SQ_EINVAL);
	f.dlc = 1U;
	f.id = 0x800U;
	assert_int_equal(hal_can_send(0U, &f), SQ_EINVAL);
	f.flags = HAL_CAN_FLAG_EXT;
	f.id = 0x20000000U;
	assert_int_equal(hal_can_send(0U, &f), SQ_EINVAL);
	expect_assert_failure(hal_can_set_rx_filter(0U, flt, HAL_CAN_MAX_FILTERS + 1U));
	expect_assert_failure(hal_can_set_rx_filter(0U, NULL, 1U));
	flt[1].id = 0x800U;
	assert_int_equal(hal_can_set_rx_filter(0U, flt, 2U), SQ_EINVAL);
	flt[1].id = 0x7FFU;
	/* Kept for the next open. */
	assert_int_equal(hal_can_set_rx_filter(0U, flt, 2U), SQ_OK);
	assert_int_equal(hal_linux_can_accept_all(0U), SQ_OK);
	assert_int_equal(hal_linux_open(0U, NULL, NULL), SQ_EINVAL);
	assert_int_equal(hal_linux_open(0U, "", NULL), SQ_EINVAL);
	assert_int_equal(hal_linux_open(0U, "a-name-longer-than-ifnamsiz", NULL), SQ_EINVAL);
}

SQ_CMOCKA_MAIN(
	cmocka_unit_test(test_open_on_kernel_without_can_names_the_remedy),
	cmocka_unit_test(test_closed_can_reports_stopped_and_checks_arguments))
