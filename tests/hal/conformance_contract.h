/* SPDX-License-Identifier: MIT */
/*
 * conformance_contract.h: how the conformance suite sees a contract failure
 * (hal.h's hal_contract_failed) without dying: conf_contract.c defines the
 * handler for the suite's programs; inside CONF_EXPECT_CONTRACT(call) it
 * jumps back, anywhere else it prints FILE:LINE and aborts as on the host.
 */
#ifndef CONFORMANCE_CONTRACT_H
#define CONFORMANCE_CONTRACT_H

#include <setjmp.h>
#include <stdbool.h>

extern jmp_buf conf_contract_jmp;
extern volatile bool conf_contract_armed;

/* true when call went to the contract handler (call is not finished then) */
#define CONF_EXPECT_CONTRACT(call)                                  \
	__extension__({                                             \
		volatile bool caught_ = false;                      \
		conf_contract_armed = true;                         \
		if (setjmp(conf_contract_jmp) == 0) {               \
			(void)(call);                               \
		} else {                                            \
			caught_ = true;                             \
		}                                                   \
		conf_contract_armed = false;                        \
		caught_;                                            \
	})

#endif /* CONFORMANCE_CONTRACT_H */
