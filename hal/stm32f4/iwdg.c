/* SPDX-License-Identifier: MIT */
/*
 * Independent watchdog (RM0090 section 21; same block on the F1) and the
 * reset reason from RCC_CSR plus the fault record.
 *
 * The IWDG runs from the LSI RC oscillator, whose frequency varies widely
 * over parts and temperature (F4: 17..47 kHz, F103: 30..60 kHz; chip.h
 * CHIP_LSI_MAX_HZ). The reload is computed for the FASTEST LSI, so the
 * real timeout is never shorter than the requested one (a healthy ECU is
 * never reset early); with the slowest LSI it is up to 2.8x (F4) / 2x
 * (F103) longer. Once started the IWDG cannot be stopped (only a reset
 * does); DBGMCU freezes it while a debugger halts the core, so bench
 * debugging does not reset the board.
 */
#include <stddef.h>

#include "chip.h"
#include "hal.h"
#include "sq_status.h"
#include "stm32_fault.h"
#include "stm32_iwdg.h"
#include "stm32_test.h"
#include "stm32_time.h"

#define IWDG_KR  REG32(IWDG_BASE + 0x00U)
#define IWDG_PR  REG32(IWDG_BASE + 0x04U)
#define IWDG_RLR REG32(IWDG_BASE + 0x08U)
#define IWDG_SR  REG32(IWDG_BASE + 0x0CU)
#define IWDG_KR_START  0xCCCCU
#define IWDG_KR_RELOAD 0xAAAAU
#define IWDG_KR_UNLOCK 0x5555U
#define IWDG_SR_PVU (1U << 0)
#define IWDG_SR_RVU (1U << 1)
#define IWDG_RLR_MAX 0xFFFU
/* A register update crosses into the LSI domain: up to 5 LSI periods of the
 * slowest prescaler (256 / 17 kHz * 5 = 75 ms). */
#define IWDG_UPDATE_TIMEOUT_US 100000U

static hal_reset_reason_t reset_reason = HAL_RESET_UNKNOWN;
static bool running;
#if defined(SQ_TARGET_TEST)
static uint32_t kicks;
#endif

int hal_watchdog_start(uint32_t timeout_ms)
{
	uint32_t pr;
	uint32_t ticks = 0U;

	if (timeout_ms == 0U) {
		return SQ_EINVAL;
	}
	/* Smallest prescaler 4 << pr whose 12-bit reload reaches the timeout:
	 * finest resolution. */
	for (pr = 0; pr <= 6U; pr++) {
		uint32_t div = 4U << pr;

		/* rounded up: never shorter than asked at the fastest LSI */
		ticks = (uint32_t)(((uint64_t)timeout_ms * CHIP_LSI_MAX_HZ + 1000U * div - 1U) /
				   (1000U * div));
		if (ticks <= IWDG_RLR_MAX + 1U) {
			break;
		}
	}
	if (pr > 6U || ticks == 0U) {
		return SQ_EINVAL;
	}
	CHIP_DBGMCU_IWDG_REG |= CHIP_DBGMCU_IWDG_STOP; /* frozen while halted */
	running = true; /* from the start command on, nothing stops it */
	IWDG_KR = IWDG_KR_START; /* starts the LSI too */
	IWDG_KR = IWDG_KR_UNLOCK;
	if (stm32_wait_reg(&IWDG_SR, IWDG_SR_PVU | IWDG_SR_RVU, 0U, IWDG_UPDATE_TIMEOUT_US) != SQ_OK) {
		return SQ_EIO;
	}
	IWDG_PR = pr;
	IWDG_RLR = ticks - 1U;
	if (stm32_wait_reg(&IWDG_SR, IWDG_SR_PVU | IWDG_SR_RVU, 0U, IWDG_UPDATE_TIMEOUT_US) != SQ_OK) {
		return SQ_EIO;
	}
	IWDG_KR = IWDG_KR_RELOAD;
	STM32_TEST_EVENT("wdg_start", timeout_ms);
	return SQ_OK;
}

bool stm32_watchdog_running(void)
{
	return running;
}

void hal_watchdog_kick(void)
{
	IWDG_KR = IWDG_KR_RELOAD;
#if defined(SQ_TARGET_TEST)
	kicks++;
	STM32_TEST_EVENT("wdg_kick", kicks);
#endif
}

typedef struct {
	uint32_t flags;            /* RCC_CSR reset flags */
	hal_reset_reason_t reason; /* what any of them means */
} reset_cause_t;

/* Read once at boot (board.c), then clear the flags so that the next reset
 * reports its own cause. A recorded fault wins: it reset through SYSRESETREQ,
 * which RCC_CSR only shows as a software reset. */
void stm32_reset_reason_capture(void)
{
	/* RCC_CSR's flags, the first that is set wins (POR also sets PIN and
	 * BOR; the F1 has no BOR flag: 0, never set) */
	static const reset_cause_t causes[] = {
		{ RCC_CSR_IWDGRSTF | RCC_CSR_WWDGRSTF, HAL_RESET_WATCHDOG },
		{ RCC_CSR_SFTRSTF, HAL_RESET_SOFTWARE },
		{ RCC_CSR_PORRSTF, HAL_RESET_POWER_ON },
		{ RCC_CSR_BORRSTF, HAL_RESET_BROWNOUT },
		{ RCC_CSR_PINRSTF, HAL_RESET_PIN },
	};
	const uint32_t csr = RCC_CSR;

	reset_reason = HAL_RESET_UNKNOWN;
	if (stm32_fault_record_take(NULL)) {
		reset_reason = HAL_RESET_FAULT;
	} else {
		uint32_t i;

		for (i = 0U; i < (sizeof causes / sizeof causes[0]); i++) {
			if ((csr & causes[i].flags) != 0U) {
				reset_reason = causes[i].reason;
				break;
			}
		}
	}
	RCC_CSR |= RCC_CSR_RMVF;
}

hal_reset_reason_t hal_reset_reason(void)
{
	return reset_reason;
}
