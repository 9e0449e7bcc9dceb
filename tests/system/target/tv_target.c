/* SPDX-License-Identifier: MIT */
/*
 * Target side of the golden-vector test: the HAL boots (board.c main) and
 * calls squeal_main(), which here runs tv_run() instead of the monitor and
 * reports through semihosting, then ends QEMU.
 *
 * Timing: SysTick free-running without interrupts (bench_ticks.h). A
 * calibration loop of a known instruction count gives ticks per
 * instruction, so under "qemu-system-arm -icount shift=0" (one virtual ns
 * per instruction) the bench can print instructions per classification.
 */
#include "hal.h"
#include "bench_ticks.h"
#include "stm32_board.h"
#include "squeal_app.h"
#include "tv_vectors.h"

#define CAL_LOOPS 100000UL /* "subs; bne" = 2 instructions per loop */

int squeal_app_init(void)
{
	return SQ_OK;
}

uint64_t squeal_app_poll(void)
{
	return hal_time_us();
}

static uint32_t calib_ticks(void)
{
	uint32_t t0 = bench_ticks();
	uint32_t n = CAL_LOOPS;

	__asm__ volatile("1: subs %0, %0, #1\n\t"
			 "bne 1b\n\t"
			 : "+r"(n)::"cc");
	return bench_ticks() - t0;
}

int squeal_main(volatile const bool *stop)
{
	uint64_t total = 0U;
	uint32_t worst = 0U;
	uint32_t n;
	uint32_t cal;

	(void)stop;
	semihost_write0("TV start\n");
	bench_ticks_start();
	cal = calib_ticks();
	n = tv_run(semihost_write0, bench_ticks, &total, &worst);
	semihost_print_u32("TIMING n=", n, NULL);
	semihost_print_u32(" ticks_total_hi=", (uint32_t)(total >> 32), NULL);
	semihost_print_u32(" ticks_total_lo=", (uint32_t)total, NULL);
	semihost_print_u32(" ticks_max=", worst, NULL);
	semihost_print_u32(" cal_ticks=", cal, NULL);
	semihost_print_u32(" cal_insns=", 2U * CAL_LOOPS, "\n");
	semihost_exit(0U);
}
