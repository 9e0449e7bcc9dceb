/* SPDX-License-Identifier: MIT */
/*
 * hal_contract_abort.c: sq_contract.h's contract handler for every host
 * build (the Linux backend, the in-memory backend, the firmware library's
 * host programs): a programming error prints FILE:LINE on stderr and aborts, so
 * a debugger or the sanitizers show where. Alone in its file (and its own
 * object in each archive) so that a test links its own handler instead
 * (tests/support/test_contract.c: cmocka's expect_assert_failure).
 */
#include <stdio.h>
#include <stdlib.h>

#include "sq_contract.h"

_Noreturn void hal_contract_failed(const char *file, uint32_t line)
{
	(void)fprintf(stderr, "%s:%u: contract violated (programming error)\n",
		      (file != NULL) ? file : "?", (unsigned int)line);
	abort();
}
