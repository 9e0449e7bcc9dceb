/* SPDX-License-Identifier: MIT */
/* The HSE against the HSI by timer input capture (stm32_hse_meter.h). */
#include "stm32_hse_meter.h"

#include "stm32_time.h"
#include "sq_status.h"

/* TIMx registers, as 32-bit words from the timer's base, and the bits
 * used: the same in TIM11 (RM0090 18.5) and TIM17 (RM0440 TIM16/TIM17
 * registers). */
#define TIMX_CR1   (0x00U / 4U)
#define TIMX_SR    (0x10U / 4U)
#define TIMX_CCMR1 (0x18U / 4U)
#define TIMX_CCER  (0x20U / 4U)
#define TIMX_PSC   (0x28U / 4U)
#define TIMX_ARR   (0x2CU / 4U)
#define TIMX_CCR1  (0x34U / 4U)
#define TIMX_CR1_CEN (1U << 0)
#define TIMX_SR_CC1IF (1U << 1)
#define TIMX_CCMR1_CC1S_TI1 1U
#define TIMX_CCMR1_IC1PSC_8 (3U << 2)
#define TIMX_CCER_CC1E (1U << 0)

#define MEAS_EDGES_PER_CAPTURE 8U
#define MEAS_CAPTURES 16U
/* per capture: 8 edges of HSE/31 at 8 MHz take 31 us, of HSE/32 at 24 MHz 11 us */
#define MEAS_TIMEOUT_US 2000U
#define HSE_TOLERANCE_PERMILLE 100U

static int capture_wait(volatile uint32_t *tim, uint32_t *ccr)
{
	if (stm32_wait_reg(&tim[TIMX_SR], TIMX_SR_CC1IF, TIMX_SR_CC1IF, MEAS_TIMEOUT_US) != SQ_OK) {
		return SQ_EAGAIN;
	}
	*ccr = tim[TIMX_CCR1] & 0xFFFFU; /* reading CCR1 clears CC1IF */
	return SQ_OK;
}

uint32_t stm32_hse_meter_run(uintptr_t tim_base, uint32_t hse_div, uint32_t hsi_hz)
{
	volatile uint32_t *const tim = (volatile uint32_t *)tim_base; /* the timer's registers */
	uint32_t prev;
	uint32_t now;
	uint32_t ticks = 0U;
	uint64_t hz;

	tim[TIMX_CR1] = 0U;
	tim[TIMX_PSC] = 0U;
	tim[TIMX_ARR] = 0xFFFFU;
	tim[TIMX_CCMR1] = TIMX_CCMR1_CC1S_TI1 | TIMX_CCMR1_IC1PSC_8;
	tim[TIMX_CCER] = TIMX_CCER_CC1E;
	tim[TIMX_SR] = 0U;
	tim[TIMX_CR1] = TIMX_CR1_CEN;
	if (capture_wait(tim, &prev) == SQ_OK) {
		uint32_t i;

		for (i = 0U; i < MEAS_CAPTURES; i++) {
			if (capture_wait(tim, &now) != SQ_OK) {
				ticks = 0U;
				break;
			}
			ticks += (now - prev) & 0xFFFFU; /* 16-bit counter wraps */
			prev = now;
		}
	}
	tim[TIMX_CR1] = 0U;
	tim[TIMX_CCER] = 0U;
	if (ticks == 0U) {
		return 0U;
	}
	hz = (uint64_t)hsi_hz * hse_div * MEAS_EDGES_PER_CAPTURE * MEAS_CAPTURES;
	return (uint32_t)((hz + ticks / 2U) / ticks);
}

bool stm32_hse_in_tolerance(uint32_t hz, uint32_t nominal_hz)
{
	const uint32_t tol = (uint32_t)(((uint64_t)nominal_hz * HSE_TOLERANCE_PERMILLE) / 1000U);

	return (hz >= nominal_hz - tol) && (hz <= nominal_hz + tol);
}
