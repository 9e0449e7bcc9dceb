/* SPDX-License-Identifier: MIT */
/*
 * test_contract.c: hal.h's contract handler for cmocka tests. Linked before
 * the libraries, it replaces the host's print-and-abort handler: a contract
 * failure inside expect_assert_failure(call) is caught (cmocka jumps back to
 * the test); anywhere else it fails the running test with FILE:LINE.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include <cmocka.h>

#include "hal.h"

_Noreturn void hal_contract_failed(const char *file, uint32_t line)
{
	mock_assert(0, "HAL_REQUIRE", file, (int)line);
	abort(); /* not reached: mock_assert never returns on a failed check */
}
