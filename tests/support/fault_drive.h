/* SPDX-License-Identifier: MIT */
/*
 * The steady drive the input-fault tests of the monitor and the application
 * start from (test_monitor_faults.c, test_squeal_app_fault_injection.c):
 * boot at T0, both inputs every 10 ms at T0 + 5 ms + k x 10 ms (off the
 * 10 ms status grid, so every state change adds exactly one status frame),
 * 25 rad/s and 9000 N, stale after 3 periods.
 */
#ifndef FAULT_DRIVE_H
#define FAULT_DRIVE_H

#include <stdint.h>

#define T0_US 1000000ULL
#define IN_OFFSET_US 5000ULL
#define IN_PERIOD_US 10000ULL
#define SPEED_RAW 2500U   /* 25 rad/s: v0 = 3 m/s */
#define FORCE_RAW 18000U  /* 9000 N */
#define STALE_US 30000ULL /* 3 x 10 ms */

/* the time of the k-th input pair */
static inline uint64_t in_time(uint32_t k)
{
	return T0_US + IN_OFFSET_US + IN_PERIOD_US * k;
}

#endif /* FAULT_DRIVE_H */
