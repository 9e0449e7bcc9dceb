/* SPDX-License-Identifier: MIT */
/*
 * Timing for the bench and golden-vector images: SysTick free-running over
 * its full 24 bits with no interrupt, extended to 32 bits in software (the
 * caller reads it at least once per 2^24 ticks). No interrupt means no
 * interrupt cost inside a measurement and no dependence on when the tick
 * interrupt is taken. Under qemu-system-arm -icount shift=0 the ticks are
 * virtual time, i.e. proportional to instructions.
 */
#ifndef BENCH_TICKS_H
#define BENCH_TICKS_H

#include <stdint.h>

#include "cortex_m.h"

static uint32_t bench_ticks_hi;
static uint32_t bench_ticks_last;

static inline void bench_ticks_start(void)
{
	SYST_CSR = 0U;
	SYST_RVR = SYST_RVR_MAX;
	SYST_CVR = 0U;
	SYST_CSR = SYST_CSR_CLKSOURCE | SYST_CSR_ENABLE;
	bench_ticks_last = SYST_CVR;
	bench_ticks_hi = 0U;
}

static inline uint32_t bench_ticks(void)
{
	uint32_t v = SYST_CVR; /* counts down */

	if (v > bench_ticks_last) {
		bench_ticks_hi += SYST_RVR_MAX + 1U; /* reloaded since last read */
	}
	bench_ticks_last = v;
	return bench_ticks_hi + (SYST_RVR_MAX - v);
}

#endif /* BENCH_TICKS_H */
