/* SPDX-License-Identifier: MIT */
/*
 * hal_linux_time.c: the time base. hal_time_us() is CLOCK_MONOTONIC in
 * microseconds (it never steps back, whatever NTP or the user do to the wall
 * clock); hal_cycles() is the same clock in nanoseconds, truncated to 32 bits
 * (wraps every 4.29 s, so task timings up to 4 s subtract correctly), hence
 * hal_cycles_per_us() is 1000.
 */
#include <time.h>

#include "hal_linux.h"

#define NS_PER_US 1000LL
#define NS_PER_S 1000000000LL

static int64_t clock_ns(clockid_t clk)
{
	struct timespec ts;

	/* CLOCK_MONOTONIC/REALTIME cannot fail with a valid pointer; stay
	 * defined anyway. */
	if (clock_gettime(clk, &ts) != 0) {
		return 0;
	}
	return (int64_t)ts.tv_sec * NS_PER_S + (int64_t)ts.tv_nsec;
}

uint64_t hal_time_us(void)
{
	return (uint64_t)(clock_ns(CLOCK_MONOTONIC) / NS_PER_US);
}

uint32_t hal_cycles(void)
{
	return (uint32_t)((uint64_t)clock_ns(CLOCK_MONOTONIC) & 0xFFFFFFFFU);
}

uint32_t hal_cycles_per_us(void)
{
	return 1000U;
}

/*
 * Socket timestamps (SO_TIMESTAMP) are CLOCK_REALTIME; the kernel has no
 * monotonic receive stamp for sockets. The offset between the two clocks is
 * read now, between two monotonic reads (their midpoint pairs with the
 * realtime read to well under a microsecond). The result is wrong only if
 * the wall clock was stepped between the frame's arrival and this call;
 * hal_linux_can.c clamps it to [previous frame, now] so it stays monotonic.
 */
uint64_t hal_linux_realtime_to_mono_us(int64_t real_s, int64_t real_ns)
{
	int64_t mono1 = clock_ns(CLOCK_MONOTONIC);
	int64_t real = clock_ns(CLOCK_REALTIME);
	int64_t mono2 = clock_ns(CLOCK_MONOTONIC);
	int64_t offset_ns = real - (mono1 + (mono2 - mono1) / 2);
	int64_t stamp_ns = real_s * NS_PER_S + real_ns - offset_ns;

	if (stamp_ns < 0) {
		return 0U;
	}
	return (uint64_t)(stamp_ns / NS_PER_US);
}
