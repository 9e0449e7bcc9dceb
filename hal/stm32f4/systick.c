/* SPDX-License-Identifier: MIT */
/*
 * Time: SysTick at 1 kHz on the processor clock is the time base of
 * hal_time_us() (milliseconds from the interrupt plus the counter's
 * position), DWT CYCCNT the cycle counter for task timing, WFI the idle.
 * Before the 1 kHz tick runs, SysTick free-runs so that start-up waits are
 * bounded in real time too (stm32_timeout_*).
 */
#include "chip.h"
#include "hal.h"
#include "stm32_time.h"

static volatile uint32_t tick_ms;     /* written only by SysTick_Handler */
static volatile uint32_t tick_ms_hi;  /* wraps of tick_ms (every 49 days)  */
static uint32_t ticks_per_ms;         /* SysTick reload + 1              */
static uint32_t core_mhz = 16U;
static bool cyccnt_ok;

void stm32_time_early_init(uint32_t core_hz)
{
	core_mhz = core_hz / 1000000UL;
	SYST_CSR = 0U;
	SYST_RVR = SYST_RVR_MAX;
	SYST_CVR = 0U;
	SYST_CSR = SYST_CSR_CLKSOURCE | SYST_CSR_ENABLE;
}

void stm32_time_start(uint32_t core_hz)
{
	uint32_t before;
	uint32_t i;

	core_mhz = core_hz / 1000000UL;
	ticks_per_ms = core_hz / 1000UL;
	SYST_CSR = 0U;
	SYST_RVR = ticks_per_ms - 1U;
	SYST_CVR = 0U;
	SCB_SHPR3 = (SCB_SHPR3 & 0x00FFFFFFUL) | ((uint32_t)CM_PRIO_SYSTICK << 24);
	SYST_CSR = SYST_CSR_CLKSOURCE | SYST_CSR_TICKINT | SYST_CSR_ENABLE;

	/* DWT cycle counter: present on every F4/F1, but some debug set-ups
	 * (and QEMU) leave it reading 0. Check that it counts, or fall back
	 * to SysTick-derived cycles. */
	DEMCR |= DEMCR_TRCENA;
	DWT_LAR = DWT_LAR_KEY;
	DWT_CYCCNT = 0U;
	DWT_CTRL |= DWT_CTRL_CYCCNTENA;
	before = DWT_CYCCNT;
	for (i = 0; i < 16U; i++) {
		__asm__ volatile("nop");
	}
	cyccnt_ok = DWT_CYCCNT != before;
}

void SysTick_Handler(void)
{
	uint32_t ms = tick_ms + 1U;

	tick_ms = ms;
	if (ms == 0U) {
		tick_ms_hi = tick_ms_hi + 1U;
	}
}

uint32_t stm32_uptime_ms(void)
{
	return tick_ms;
}

/*
 * Milliseconds and the counter's position must belong together. Read with
 * interrupts masked (a few instructions), so the millisecond count cannot
 * change underneath; if the counter wrapped but the interrupt has not run
 * yet, the pending bit says so and the count is one higher. Where the
 * pending bit lags the counter's reload (QEMU's SysTick does), a position
 * below the last one in the same millisecond is that wrap too; a last guard
 * keeps the result monotonic whatever happens: never go back.
 * *ms_out gets the 64-bit millisecond count, *sub_out the ticks into it.
 */
static uint64_t last_ms;
static uint32_t last_sub;

static void systick_read(uint64_t *ms_out, uint32_t *sub_out)
{
	uint32_t primask = cm_irq_save();
	uint64_t ms = ((uint64_t)tick_ms_hi << 32) | tick_ms;
	uint32_t val = SYST_CVR;
	uint32_t pend = SCB_ICSR & SCB_ICSR_PENDSTSET;
	uint32_t val2 = SYST_CVR;
	uint32_t sub;

	if (pend != 0U) {
		/* wrapped before ICSR was read: val2 is after the wrap */
		ms++;
		sub = ticks_per_ms - 1U - val2;
	} else {
		sub = ticks_per_ms - 1U - val;
	}
	if (ms == last_ms && sub < last_sub) {
		/* The counter reloaded, but neither the interrupt nor its
		 * pending bit shows it yet: count the wrap here. */
		ms++;
	}
	if (ms < last_ms || (ms == last_ms && sub < last_sub)) {
		ms = last_ms;
		sub = last_sub;
	} else {
		last_ms = ms;
		last_sub = sub;
	}
	cm_irq_restore(primask);
	*ms_out = ms;
	*sub_out = sub;
}

uint64_t hal_time_us(void)
{
	uint64_t ms;
	uint32_t sub;

	if (ticks_per_ms == 0U) {
		return 0U; /* before stm32_time_start() */
	}
	systick_read(&ms, &sub);
	return ms * 1000U + sub / core_mhz;
}

uint32_t hal_cycles(void)
{
	uint64_t ms;
	uint32_t sub;

	if (cyccnt_ok) {
		return DWT_CYCCNT;
	}
	systick_read(&ms, &sub);
	return (uint32_t)ms * ticks_per_ms + sub;
}

uint32_t hal_cycles_per_us(void)
{
	return core_mhz;
}

void stm32_timeout_start(stm32_timeout_t *t, uint32_t timeout_us)
{
	uint64_t limit = (uint64_t)timeout_us * core_mhz;

	t->last_val = SYST_CVR;
	t->elapsed_ticks = 0U;
	t->limit_ticks = limit > 0xFFFFFFFFULL ? 0xFFFFFFFFUL : (uint32_t)limit;
	t->polls = 0U;
}

bool stm32_timeout_expired(stm32_timeout_t *t)
{
	uint32_t now = SYST_CVR;
	uint32_t reload = SYST_RVR & SYST_RVR_MAX;
	uint32_t delta;

	/* SysTick counts down from the reload value to 0 and reloads. */
	if (now <= t->last_val) {
		delta = t->last_val - now;
	} else {
		delta = t->last_val + (reload + 1U - now);
	}
	t->last_val = now;
	if (t->elapsed_ticks > 0xFFFFFFFFUL - delta) {
		t->elapsed_ticks = 0xFFFFFFFFUL;
	} else {
		t->elapsed_ticks += delta;
	}
	t->polls++;
	return t->elapsed_ticks >= t->limit_ticks || t->polls >= t->limit_ticks;
}

int stm32_wait_reg(volatile const uint32_t *reg, uint32_t mask, uint32_t value,
		   uint32_t timeout_us)
{
	stm32_timeout_t t;

	stm32_timeout_start(&t, timeout_us);
	for (;;) {
		if ((*reg & mask) == value) {
			return SQ_OK;
		}
		if (stm32_timeout_expired(&t)) {
			/* one last look: the flag may have come while we counted */
			return ((*reg & mask) == value) ? SQ_OK : SQ_EAGAIN;
		}
	}
}
