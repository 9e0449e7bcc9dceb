/* SPDX-License-Identifier: MIT */
/*
 * Independent watchdog (RM0090 section 21; same block on the F1) and the
 * reset reason from RCC_CSR plus the fault record.
 *
 * The IWDG runs from the LSI RC oscillator: nominally 32 kHz, but anywhere
 * from 17 to 47 kHz over parts and temperature. The reload is computed for
 * the nominal value, so the real timeout lies between 0.68 and 1.9 times
 * the requested one; callers choose timeout_ms with that in mind.
 * Once started the IWDG cannot be stopped (only a reset does).
 */
#include "chip.h"
#include "hal_stm32.h"

#define IWDG_KR  REG32(IWDG_BASE + 0x00UL)
#define IWDG_PR  REG32(IWDG_BASE + 0x04UL)
#define IWDG_RLR REG32(IWDG_BASE + 0x08UL)
#define IWDG_SR  REG32(IWDG_BASE + 0x0CUL)
#define IWDG_KR_START  0xCCCCUL
#define IWDG_KR_RELOAD 0xAAAAUL
#define IWDG_KR_UNLOCK 0x5555UL
#define IWDG_SR_PVU (1UL << 0)
#define IWDG_SR_RVU (1UL << 1)
#define IWDG_RLR_MAX 0xFFFUL
#define LSI_NOMINAL_HZ 32000UL
/* A register update crosses into the LSI domain: up to 5 LSI periods of the
 * slowest prescaler (256 / 17 kHz * 5 = 75 ms). */
#define IWDG_UPDATE_TIMEOUT_US 100000UL

static hal_reset_reason_t reset_reason = HAL_RESET_UNKNOWN;
#if defined(SQ_TARGET_TEST)
static uint32_t kicks;
#endif

int hal_watchdog_start(uint32_t timeout_ms)
{
	uint32_t pr;
	uint32_t ticks = 0U;

	if (timeout_ms == 0U || timeout_ms > 32000UL) {
		return SQ_EINVAL;
	}
	/* Smallest prescaler 4 << pr whose 12-bit reload reaches the timeout:
	 * finest resolution. */
	for (pr = 0; pr <= 6U; pr++) {
		uint32_t div = 4UL << pr;

		ticks = (uint32_t)(((uint64_t)timeout_ms * LSI_NOMINAL_HZ) / (1000UL * div));
		if (ticks <= IWDG_RLR_MAX + 1U) {
			break;
		}
	}
	if (pr > 6U || ticks == 0U) {
		return SQ_EINVAL;
	}
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

void hal_watchdog_kick(void)
{
	IWDG_KR = IWDG_KR_RELOAD;
#if defined(SQ_TARGET_TEST)
	kicks++;
	stm32_test_event("wdg_kick", kicks);
#endif
}

/* Read once at boot (board.c), then clear the flags so that the next reset
 * reports its own cause. A recorded fault wins: it reset through SYSRESETREQ,
 * which RCC_CSR only shows as a software reset. */
void stm32_reset_reason_capture(void)
{
	uint32_t csr = RCC_CSR;

	if (stm32_fault_record_take(NULL)) {
		reset_reason = HAL_RESET_FAULT;
	} else if ((csr & (RCC_CSR_IWDGRSTF | RCC_CSR_WWDGRSTF)) != 0U) {
		reset_reason = HAL_RESET_WATCHDOG;
	} else if ((csr & RCC_CSR_SFTRSTF) != 0U) {
		reset_reason = HAL_RESET_SOFTWARE;
	} else if ((csr & RCC_CSR_PORRSTF) != 0U) {
		reset_reason = HAL_RESET_POWER_ON; /* POR also sets PIN and BOR */
	} else if ((csr & RCC_CSR_BORRSTF) != 0U) {
		reset_reason = HAL_RESET_BROWNOUT;
	} else if ((csr & RCC_CSR_PINRSTF) != 0U) {
		reset_reason = HAL_RESET_PIN;
	} else {
		reset_reason = HAL_RESET_UNKNOWN;
	}
	RCC_CSR |= RCC_CSR_RMVF;
}

hal_reset_reason_t hal_reset_reason(void)
{
	return reset_reason;
}
