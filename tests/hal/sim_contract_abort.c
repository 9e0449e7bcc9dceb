/* SPDX-License-Identifier: MIT */
/* Host contract handler for programs built on the bxCAN simulation without
 * cmocka's assert catching (the conformance program): FILE:LINE, abort. */
#include <stdio.h>
#include <stdlib.h>

#include "hal.h"

_Noreturn void hal_contract_failed(const char *file, uint32_t line)
{
	fprintf(stderr, "%s:%u: contract violated\n", file, (unsigned)line);
	abort();
}
