/* SPDX-License-Identifier: MIT */
/*
 * The STM32F405 peripherals of tests/support/regsim/f4/chip.h as plain
 * words, shared by the tests of the chip files, and their reset: every
 * register 0 before each test (the test then sets what its case needs).
 */
#include <string.h>

#include "chip.h"

uint32_t regsim_rcc[64], regsim_pwr[4], regsim_flash[8], regsim_tim11[32], regsim_iwdg[4],
	regsim_dbgmcu[4], regsim_gpiob[16];

void regsim_f4_reset(void)
{
	memset(regsim_rcc, 0, sizeof(regsim_rcc));
	memset(regsim_pwr, 0, sizeof(regsim_pwr));
	memset(regsim_flash, 0, sizeof(regsim_flash));
	memset(regsim_tim11, 0, sizeof(regsim_tim11));
	memset(regsim_iwdg, 0, sizeof(regsim_iwdg));
	memset(regsim_dbgmcu, 0, sizeof(regsim_dbgmcu));
	memset(regsim_gpiob, 0, sizeof(regsim_gpiob));
}

/* cmocka setup for a test that needs nothing but the reset */
int regsim_f4_setup(void **state)
{
	(void)state;
	regsim_f4_reset();
	return 0;
}
