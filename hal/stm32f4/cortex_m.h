/* SPDX-License-Identifier: MIT */
/*
 * Cortex-M3/M4 core registers used by the bare-metal HAL (ARMv7-M ARM,
 * PM0214), and the few intrinsics it needs. Names follow the manuals.
 */
#ifndef CORTEX_M_H
#define CORTEX_M_H

#include <stdint.h>

#define REG32(addr) (*(volatile uint32_t *)(uintptr_t)(addr))

/* SysTick */
#define SYST_CSR REG32(0xE000E010UL)
#define SYST_RVR REG32(0xE000E014UL)
#define SYST_CVR REG32(0xE000E018UL)
#define SYST_CSR_ENABLE    (1UL << 0)
#define SYST_CSR_TICKINT   (1UL << 1)
#define SYST_CSR_CLKSOURCE (1UL << 2) /* processor clock */
#define SYST_CSR_COUNTFLAG (1UL << 16)
#define SYST_RVR_MAX       0x00FFFFFFUL

/* NVIC */
#define NVIC_ISER(n) REG32(0xE000E100UL + 4UL * (n))
#define NVIC_ICER(n) REG32(0xE000E180UL + 4UL * (n))
#define NVIC_ICPR(n) REG32(0xE000E280UL + 4UL * (n))
#define NVIC_IPR_BASE 0xE000E400UL

/* System control block */
#define SCB_ICSR  REG32(0xE000ED04UL)
#define SCB_VTOR  REG32(0xE000ED08UL)
#define SCB_AIRCR REG32(0xE000ED0CUL)
#define SCB_SCR   REG32(0xE000ED10UL)
#define SCB_CCR   REG32(0xE000ED14UL)
#define SCB_SHPR3 REG32(0xE000ED20UL)
#define SCB_SHCSR REG32(0xE000ED24UL)
#define SCB_CFSR  REG32(0xE000ED28UL)
#define SCB_HFSR  REG32(0xE000ED2CUL)
#define SCB_MMFAR REG32(0xE000ED34UL)
#define SCB_BFAR  REG32(0xE000ED38UL)
#define SCB_CPACR REG32(0xE000ED88UL)
#define SCB_ICSR_PENDSTSET      (1UL << 26)
#define SCB_ICSR_NMIPENDSET     (1UL << 31)
#define SCB_ICSR_VECTACTIVE_MSK 0x1FFUL
#define SCB_AIRCR_VECTKEY       (0x05FAUL << 16)
#define SCB_AIRCR_SYSRESETREQ   (1UL << 2)
#define SCB_SHCSR_MEMFAULTENA   (1UL << 16)
#define SCB_SHCSR_BUSFAULTENA   (1UL << 17)
#define SCB_SHCSR_USGFAULTENA   (1UL << 18)
#define SCB_CCR_DIV_0_TRP       (1UL << 4)
#define SCB_CPACR_CP10_CP11_FULL (0xFUL << 20)

/* Debug and trace: DWT cycle counter */
#define DEMCR      REG32(0xE000EDFCUL)
#define DEMCR_TRCENA (1UL << 24)
#define DWT_CTRL   REG32(0xE0001000UL)
#define DWT_CYCCNT REG32(0xE0001004UL)
#define DWT_CTRL_CYCCNTENA (1UL << 0)
#define DWT_LAR    REG32(0xE0001FB0UL)
#define DWT_LAR_KEY 0xC5ACCE55UL

#if defined(__arm__)
static inline void cm_dsb(void) { __asm__ volatile("dsb 0xF" ::: "memory"); }
static inline void cm_isb(void) { __asm__ volatile("isb 0xF" ::: "memory"); }
static inline void cm_dmb(void) { __asm__ volatile("dmb 0xF" ::: "memory"); }
static inline void cm_wfi(void) { __asm__ volatile("wfi" ::: "memory"); }
static inline void cm_irq_enable(void) { __asm__ volatile("cpsie i" ::: "memory"); }
static inline void cm_irq_disable(void) { __asm__ volatile("cpsid i" ::: "memory"); }

/* Save PRIMASK and mask interrupts; cm_irq_restore() puts it back. */
static inline uint32_t cm_irq_save(void)
{
	uint32_t primask;

	__asm__ volatile("mrs %0, primask\n\tcpsid i" : "=r"(primask)::"memory");
	return primask;
}

static inline void cm_irq_restore(uint32_t primask)
{
	__asm__ volatile("msr primask, %0" ::"r"(primask) : "memory");
}

static inline void cm_nvic_enable(uint32_t irq, uint8_t prio)
{
	*(volatile uint8_t *)(uintptr_t)(NVIC_IPR_BASE + irq) = prio;
	NVIC_ICPR(irq >> 5) = (uint32_t)1U << (irq & 31U);
	NVIC_ISER(irq >> 5) = (uint32_t)1U << (irq & 31U);
}

static inline void cm_nvic_disable(uint32_t irq)
{
	NVIC_ICER(irq >> 5) = (uint32_t)1U << (irq & 31U);
	cm_dsb();
	cm_isb();
}
#else
/* Host builds of a driver (tests/hal/stm32f4/bxcan_sim.c): the simulation provides
 * these, with an interrupt mask and NVIC enables it honours. */
void cm_dsb(void);
void cm_isb(void);
void cm_dmb(void);
void cm_wfi(void);
void cm_irq_enable(void);
void cm_irq_disable(void);
uint32_t cm_irq_save(void);
void cm_irq_restore(uint32_t primask);
void cm_nvic_enable(uint32_t irq, uint8_t prio);
void cm_nvic_disable(uint32_t irq);
#endif

/* Priorities (upper 4 bits used on STM32): SysTick preempts CAN. */
#define CM_PRIO_SYSTICK 0x40U
#define CM_PRIO_CAN     0x80U

#endif /* CORTEX_M_H */
