/* SPDX-License-Identifier: MIT */
/*
 * hal_linux_open() (hal/linux/hal_linux_can.c) up to its socket, on any
 * kernel: the link wraps socket() (-Wl,--wrap=socket), which answers a
 * PF_CAN request with the error this test chooses and counts the calls.
 * Checked by hand against <net/if.h> and socket(2):
 *   - an interface name holds at most IFNAMSIZ - 1 = 15 characters (the
 *     kernel's struct ifreq keeps a terminating NUL): 15 reach socket(),
 *     16 are refused (SQ_EINVAL) before any system call;
 *   - the socket is PF_CAN, SOCK_RAW | SOCK_NONBLOCK | SOCK_CLOEXEC,
 *     CAN_RAW (1);
 *   - "no CAN in this kernel" is EAFNOSUPPORT (no PF_CAN: CONFIG_CAN off)
 *     or EPROTONOSUPPORT (PF_CAN but no CAN_RAW: can-raw not loaded):
 *     both SQ_ENOTSUP with the remedy; EACCES/EPERM a permission message,
 *     anything else SQ_EIO; each raises HAL_FAULT_CAN_INIT.
 */
#include <errno.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>
#include <sys/socket.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "hal_linux.h"

int __real_socket(int domain, int type, int protocol);
int __wrap_socket(int domain, int type, int protocol);

static int can_errno;
static unsigned int can_calls;
static int last_type;
static int last_protocol;

int __wrap_socket(int domain, int type, int protocol)
{
	if (domain != PF_CAN) {
		return __real_socket(domain, type, protocol);
	}
	can_calls++;
	last_type = type;
	last_protocol = protocol;
	errno = can_errno;
	return -1;
}

static int setup(void **state)
{
	(void)state;
	can_calls = 0U;
	can_errno = EAFNOSUPPORT;
	return 0;
}

static void test_name_of_15_characters_reaches_the_socket(void **state)
{
	(void)state;
	assert_int_equal(hal_linux_open(0U, "can-0123456789a", NULL), SQ_ENOTSUP);
	assert_int_equal(can_calls, 1U);
	assert_int_equal(last_type, SOCK_RAW | SOCK_NONBLOCK | SOCK_CLOEXEC);
	assert_int_equal(last_protocol, 1);
	assert_non_null(strstr(hal_linux_strerror(), "can-0123456789a: this kernel has no CAN support"));
}

static void test_name_of_16_characters_is_refused_before_any_call(void **state)
{
	(void)state;
	assert_int_equal(hal_linux_open(0U, "can-0123456789ab", NULL), SQ_EINVAL);
	assert_int_equal(can_calls, 0U);
	assert_non_null(strstr(hal_linux_strerror(), "bad CAN interface name (1 to 15 characters)"));
}

static void test_no_can_raw_protocol_is_no_can_support(void **state)
{
	(void)state;
	can_errno = EPROTONOSUPPORT;
	assert_int_equal(hal_linux_open(0U, "vcan0", NULL), SQ_ENOTSUP);
	assert_int_equal(can_calls, 1U);
	assert_non_null(strstr(hal_linux_strerror(), "vcan0: this kernel has no CAN support"));
	assert_non_null(strstr(hal_linux_strerror(), "modprobe can-raw / vcan"));
	assert_true((hal_platform_faults() & HAL_FAULT_CAN_INIT) != 0U);
}

static void test_other_socket_errors_are_eio(void **state)
{
	(void)state;
	can_errno = EACCES;
	assert_int_equal(hal_linux_open(0U, "vcan0", NULL), SQ_EIO);
	assert_non_null(strstr(hal_linux_strerror(), "vcan0: permission denied opening a CAN socket"));
	can_errno = EMFILE;
	assert_int_equal(hal_linux_open(1U, "vcan1", NULL), SQ_EIO);
	assert_non_null(strstr(hal_linux_strerror(), "vcan1: socket(PF_CAN, CAN_RAW): "));
	assert_null(strstr(hal_linux_strerror(), "no CAN support"));
	assert_int_equal(can_calls, 2U);
	/* nothing opened: the bus answers as closed */
	assert_int_equal(hal_linux_can_fd(0U), -1);
	assert_int_equal(hal_linux_can_fd(1U), -1);
}

SQ_CMOCKA_MAIN(cmocka_unit_test_setup(test_name_of_15_characters_reaches_the_socket, setup),
	       cmocka_unit_test_setup(test_name_of_16_characters_is_refused_before_any_call, setup),
	       cmocka_unit_test_setup(test_no_can_raw_protocol_is_no_can_support, setup),
	       cmocka_unit_test_setup(test_other_socket_errors_are_eio, setup))
