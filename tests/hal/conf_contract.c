/* SPDX-License-Identifier: MIT */
/* The conformance suite's contract handler: see conformance_contract.h. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "conformance_contract.h"
#include "hal.h"

jmp_buf conf_contract_jmp;
volatile bool conf_contract_armed;

_Noreturn void hal_contract_failed(const char *file, uint32_t line)
{
	if (conf_contract_armed) {
		conf_contract_armed = false;
		longjmp(conf_contract_jmp, 1);
	}
	(void)fprintf(stderr, "%s:%u: contract violated (programming error)\n",
		      (file != NULL) ? file : "?", (unsigned int)line);
	abort();
}
