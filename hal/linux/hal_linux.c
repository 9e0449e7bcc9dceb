/* SPDX-License-Identifier: MIT */
/*
 * hal_linux.c: what the other hal_linux_*.c files share: the last-error text
 * for the user and the platform fault bits for the monitor.
 */
#include <stdarg.h>
#include <stdio.h>

#include "hal_linux.h"

/* One line for a user; longer messages are cut, never overrun. */
static char last_error[256];
static uint32_t platform_faults;

void hal_linux_set_error(const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	/* A truncated message is still useful: the result is deliberately unused. */
	(void)vsnprintf(last_error, sizeof(last_error), fmt, ap);
	va_end(ap);
}

const char *hal_linux_strerror(void)
{
	return last_error;
}

void hal_linux_add_fault(uint32_t fault_bits)
{
	platform_faults |= fault_bits;
}

uint32_t hal_platform_faults(void)
{
	return platform_faults;
}

/* A Linux host has no bring-up self-test: its clock and CAN adapter are the
 * OS's (ip -details link show can0 tells their state). */
int hal_selftest(hal_selftest_t *result)
{
	HAL_REQUIRE(result != NULL);
	*result = (hal_selftest_t){ .hse_hz = HAL_SELFTEST_NOT_MEASURED,
				    .stack_high_water_prev_b = HAL_SELFTEST_NOT_MEASURED,
				    .bor_level = HAL_SELFTEST_NO_BOR };
	return SQ_ENOTSUP;
}
