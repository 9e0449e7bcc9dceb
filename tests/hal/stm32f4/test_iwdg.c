/* SPDX-License-Identifier: MIT */
/*
 * STM32F405 independent watchdog and reset reason (hal/stm32f4/iwdg.c) on
 * the host, its registers in plain arrays (tests/support/regsim/f4/chip.h).
 * Expected values come from RM0090 section 21 (timeout = 4 * 2^PR *
 * (RLR + 1) / f_LSI, key values 0xCCCC start, 0x5555 unlock, 0xAAAA
 * reload), the datasheet's LSI range (17..47 kHz) and RM0090 section 7.3.21
 * (RCC_CSR: BORRSTF 25, PINRSTF 26, PORRSTF 27, SFTRSTF 28, IWDGRSTF 29,
 * WWDGRSTF 30, RMVF 24). The reload is for the fastest LSI, the DBGMCU
 * freeze bit DBG_IWDG_STOP is bit 12 of DBGMCU_APB1_FZ.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "chip.h"
#include "hal.h"
#include "sq_status.h"
#include "stm32_fault.h"
#include "stm32_iwdg.h"
#include "stm32_time.h"

static bool fault_recorded;

bool stm32_fault_record_take(stm32_fault_record_t *out)
{
	(void)out;
	return fault_recorded;
}

/* The IWDG's PVU/RVU flags are never set here: an update is done at once. */
int stm32_wait_reg(volatile const uint32_t *reg, uint32_t mask, uint32_t value, uint32_t timeout_us)
{
	(void)timeout_us;
	return ((*reg & mask) == value) ? SQ_OK : SQ_EAGAIN;
}

static int setup(void **state)
{
	(void)state;
	regsim_f4_reset();
	fault_recorded = false;
	return 0;
}

#define IWDG_PR  regsim_iwdg[1]
#define IWDG_RLR regsim_iwdg[2]
#define LSI_FASTEST_HZ 47000U /* STM32F405 datasheet, LSI max */
#define LSI_SLOWEST_HZ 17000U

static void test_iwdg_fastest_lsi_and_debug_freeze(void **state)
{
	static const uint32_t timeouts_ms[] = { 1U, 50U, 100U, 1000U, 5000U, 20000U };
	uint32_t i;

	(void)state;
	assert_false(stm32_watchdog_running());
	for (i = 0; i < sizeof(timeouts_ms) / sizeof(timeouts_ms[0]); i++) {
		uint32_t div;
		uint64_t ticks;

		assert_int_equal(hal_watchdog_start(timeouts_ms[i]), SQ_OK);
		div = 4U << IWDG_PR;
		ticks = (uint64_t)div * (IWDG_RLR + 1U);
		/* never early at the fastest LSI: ticks / 47 kHz >= timeout */
		assert_true(ticks * 1000U >= (uint64_t)timeouts_ms[i] * LSI_FASTEST_HZ);
		/* and not more than one count late there */
		assert_true((ticks - div) * 1000U < (uint64_t)timeouts_ms[i] * LSI_FASTEST_HZ);
		/* the finest prescaler whose 12-bit reload reaches it */
		if (IWDG_PR > 0U) {
			assert_true((uint64_t)timeouts_ms[i] * LSI_FASTEST_HZ > (uint64_t)(div / 2U) * 4096U * 1000U);
		}
	}
	assert_true((regsim_dbgmcu[2] & (1U << 12)) != 0U); /* DBG_IWDG_STOP */
	assert_int_equal(regsim_iwdg[0], 0xAAAAU);            /* last key: reload */
	assert_true(stm32_watchdog_running());
	/* a reload of exactly 4096 counts (RLR 0xFFF, the 12-bit field's
	 * largest) is used, not the next prescaler: 5577 ms at 47 kHz are
	 * 262119 LSI periods, / 64 = 4095.6, rounded up 4096 (PR 4, /64);
	 * /32 would need 8192 */
	assert_int_equal(hal_watchdog_start(5577U), SQ_OK);
	assert_int_equal(IWDG_PR, 4U);
	assert_int_equal(IWDG_RLR, 0xFFFU);
	/* 30 s cannot be reached at 47 kHz (4096 * 256 / 47 kHz = 22.3 s) */
	assert_int_equal(hal_watchdog_start(30000U), SQ_EINVAL);
	assert_int_equal(hal_watchdog_start(0U), SQ_EINVAL);
	(void)LSI_SLOWEST_HZ;
}

#define RCC_CSR_REG regsim_rcc[0x74U / 4U]

/* RCC_CSR flags -> the reason, in the order iwdg.c documents: a recorded
 * fault first, then watchdog, software, power-on (POR also sets PIN and BOR),
 * brown-out, pin; RMVF written afterwards so the next reset shows its own. */
static void test_reset_reason_from_rcc_csr(void **state)
{
	static const struct {
		uint32_t csr;
		bool fault;
		hal_reset_reason_t want;
	} cases[] = {
		{ 0U, false, HAL_RESET_UNKNOWN },
		{ 1U << 29, false, HAL_RESET_WATCHDOG },               /* IWDGRSTF */
		{ 1U << 30, false, HAL_RESET_WATCHDOG },               /* WWDGRSTF */
		{ (1U << 28) | (1U << 26), false, HAL_RESET_SOFTWARE }, /* SFTRSTF + PIN */
		{ (1U << 27) | (1U << 26) | (1U << 25), false, HAL_RESET_POWER_ON },
		{ (1U << 25) | (1U << 26), false, HAL_RESET_BROWNOUT },
		{ 1U << 26, false, HAL_RESET_PIN },
		{ 1U << 28, true, HAL_RESET_FAULT }, /* the fault reset via SYSRESETREQ */
	};
	size_t i;

	(void)state;
	for (i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
		RCC_CSR_REG = cases[i].csr;
		fault_recorded = cases[i].fault;
		stm32_reset_reason_capture();
		assert_int_equal(hal_reset_reason(), cases[i].want);
		assert_true((RCC_CSR_REG & (1U << 24)) != 0U); /* RMVF */
	}
}

SQ_CMOCKA_MAIN(
	cmocka_unit_test_setup(test_iwdg_fastest_lsi_and_debug_freeze, setup),
	cmocka_unit_test_setup(test_reset_reason_from_rcc_csr, setup))
