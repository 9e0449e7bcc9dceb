/* SPDX-License-Identifier: MIT */
/*
 * sq_contract.h: the one handler for programming errors, for every layer
 * (the pure model and protocol code, the monitor, the HAL backends, host
 * tools). It needs nothing but <stdint.h>, so code that never touches the
 * hardware states its preconditions without including the hardware
 * boundary (hal.h includes this header for the code that does).
 *
 * A programming error is a NULL pointer, a bad bus or array index, a bad
 * configuration: never bad data (bad data gets a counted, reported error
 * code, sq_status.h). The handler does not return: the ECU records the
 * fault (file, line) in no-init RAM and resets through the watchdog path;
 * host builds print FILE:LINE and abort; tests link their own handler and
 * catch it. Use HAL_REQUIRE().
 */
#ifndef SQ_CONTRACT_H
#define SQ_CONTRACT_H

#include <stdint.h>

_Noreturn void hal_contract_failed(const char *file, uint32_t line);

#define HAL_REQUIRE(cond)                                              \
	do {                                                           \
		if (!(cond)) {                                         \
			hal_contract_failed(__FILE__, (uint32_t)__LINE__); \
		}                                                      \
	} while (0)

#endif /* SQ_CONTRACT_H */
