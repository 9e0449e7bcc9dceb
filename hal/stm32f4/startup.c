/* SPDX-License-Identifier: MIT */
/*
 * Start-up: the vector table, the reset handler (FPU on, .data copy, .bss
 * clear, then main) and the fault handlers, which record the cause in no-init
 * RAM and reset the core (hal_reset_reason() then says HAL_RESET_FAULT).
 * No C library start-up code is linked (newlib's crt0 sets its stack from
 * semihosting and does things an ECU does not want).
 */
#include <stddef.h>
#include <stdint.h>

#include "chip.h"
#include "hal_stm32.h"

/* Linker symbols (linker/stm32f405xg.ld, linker/stm32f103xb.ld) */
extern uint32_t _estack;
extern uint32_t _sidata, _sdata, _edata, _sbss, _ebss;
#if defined(CHIP_HAS_CCM)
extern uint32_t _sccm, _eccm;
#endif

int main(void);
void Reset_Handler(void) __attribute__((noreturn));
void Fault_Handler(void) __attribute__((naked));
void Default_Handler(void) __attribute__((naked));
void stm32_fault_entry(const uint32_t *frame, uint32_t exc_return) __attribute__((noreturn, used));

typedef union {
	void (*handler)(void);
	const void *stack_top;
} vector_t;

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Woverride-init"
/* Every device interrupt defaults to Default_Handler, then the few the HAL
 * uses are named; an unexpected interrupt is recorded like a fault. */
__attribute__((section(".isr_vector"), used))
const vector_t stm32_vectors[16U + CHIP_IRQ_COUNT] = {
	[0] = { .stack_top = &_estack },
	[1] = { .handler = Reset_Handler },
	[2 ... 15U + CHIP_IRQ_COUNT] = { .handler = Default_Handler },
	[2] = { .handler = Fault_Handler },  /* NMI                  */
	[3] = { .handler = Fault_Handler },  /* HardFault            */
	[4] = { .handler = Fault_Handler },  /* MemManage            */
	[5] = { .handler = Fault_Handler },  /* BusFault             */
	[6] = { .handler = Fault_Handler },  /* UsageFault           */
	[7 ... 10] = { .handler = NULL },    /* reserved             */
	[13] = { .handler = NULL },          /* reserved             */
	[15] = { .handler = SysTick_Handler },
	[16U + CHIP_IRQ_CAN1_TX] = { .handler = CAN1_TX_IRQHandler },
	[16U + CHIP_IRQ_CAN1_RX0] = { .handler = CAN1_RX0_IRQHandler },
	[16U + CHIP_IRQ_CAN1_SCE] = { .handler = CAN1_SCE_IRQHandler },
};
#pragma GCC diagnostic pop

/* Survives a system reset (linker: .noinit, never copied nor cleared). */
__attribute__((section(".noinit"))) static volatile stm32_fault_record_t fault_noinit;
#define STM32_FAULT_ARMED 0xA53A0000UL

static stm32_fault_record_t last_fault;
static bool last_fault_valid;

void Reset_Handler(void)
{
	uint32_t *src;
	uint32_t *dst;

#if defined(__ARM_FP)
	/* Before any floating-point instruction: CP10/CP11 full access. */
	SCB_CPACR |= SCB_CPACR_CP10_CP11_FULL;
	cm_dsb();
	cm_isb();
#endif
	src = &_sidata;
	for (dst = &_sdata; dst < &_edata; dst++) {
		*dst = *src;
		src++;
	}
	for (dst = &_sbss; dst < &_ebss; dst++) {
		*dst = 0U;
	}
#if defined(CHIP_HAS_CCM)
	for (dst = &_sccm; dst < &_eccm; dst++) {
		*dst = 0U;
	}
#endif
	SCB_VTOR = (uint32_t)(uintptr_t)&stm32_vectors[0];
	/* Separate handlers for MemManage/BusFault/UsageFault (better causes
	 * in the record); trap integer division by zero instead of giving 0. */
	SCB_SHCSR |= SCB_SHCSR_MEMFAULTENA | SCB_SHCSR_BUSFAULTENA | SCB_SHCSR_USGFAULTENA;
	SCB_CCR |= SCB_CCR_DIV_0_TRP;
	cm_dsb();
	cm_isb();

	(void)main();
	/* main never returns on the ECU; if it does, start again cleanly. */
	SCB_AIRCR = SCB_AIRCR_VECTKEY | SCB_AIRCR_SYSRESETREQ;
	for (;;) {
		cm_dsb();
	}
}

/* Hand the stacked exception frame (MSP or PSP) to C. */
void Fault_Handler(void)
{
	__asm__ volatile("tst lr, #4\n\t"
			 "ite eq\n\t"
			 "mrseq r0, msp\n\t"
			 "mrsne r0, psp\n\t"
			 "mov r1, lr\n\t"
			 "b stm32_fault_entry\n\t");
}

void Default_Handler(void)
{
	__asm__ volatile("tst lr, #4\n\t"
			 "ite eq\n\t"
			 "mrseq r0, msp\n\t"
			 "mrsne r0, psp\n\t"
			 "mov r1, lr\n\t"
			 "b stm32_fault_entry\n\t");
}

void stm32_fault_entry(const uint32_t *frame, uint32_t exc_return)
{
	uint32_t vector = SCB_ICSR & SCB_ICSR_VECTACTIVE_MSK;
	uint32_t cfsr = SCB_CFSR;
	uint32_t count = 1U;
	uint32_t fault_addr = 0U;

	(void)exc_return;
	if (fault_noinit.magic == STM32_FAULT_MAGIC || fault_noinit.magic == STM32_FAULT_ARMED) {
		count = fault_noinit.count + 1U;
	}
	if ((cfsr & (1UL << 7)) != 0U) {        /* MMARVALID */
		fault_addr = SCB_MMFAR;
	} else if ((cfsr & (1UL << 15)) != 0U) { /* BFARVALID */
		fault_addr = SCB_BFAR;
	}
	/* The frame pointer may be bad (stack overflow): check it points into
	 * RAM before reading the stacked PC and LR. */
	if ((uintptr_t)frame >= 0x20000000UL && (uintptr_t)frame < 0x20100000UL &&
	    ((uintptr_t)frame & 3U) == 0U) {
		fault_noinit.pc = frame[6];
		fault_noinit.lr = frame[5];
	} else {
		fault_noinit.pc = 0U;
		fault_noinit.lr = 0U;
	}
	fault_noinit.vector = vector;
	fault_noinit.cfsr = cfsr;
	fault_noinit.hfsr = SCB_HFSR;
	fault_noinit.fault_addr = fault_addr;
	fault_noinit.count = count;
	fault_noinit.magic = STM32_FAULT_MAGIC;
	cm_dsb();
#if defined(SQ_TARGET_TEST)
	semihost_print_u32("EVT fault vector=", vector, NULL);
	semihost_print_hex(" pc=0x", fault_noinit.pc, NULL);
	semihost_print_hex(" cfsr=0x", cfsr, "\n");
#if !defined(SQ_TARGET_TEST_FAULT)
	semihost_exit(0x80U + (vector & 0x7FU));
#endif
#endif
#if !defined(SQ_TARGET_TEST) || defined(SQ_TARGET_TEST_FAULT)
	SCB_AIRCR = SCB_AIRCR_VECTKEY | SCB_AIRCR_SYSRESETREQ;
	for (;;) {
		cm_dsb();
	}
#endif
}

/*
 * hal.h's contract handler: a programming error is recorded like a fault
 * (vector 0, pc = the file name's address, lr = the line) and the core
 * resets; the next boot reports HAL_RESET_FAULT.
 */
_Noreturn void hal_contract_failed(const char *file, uint32_t line)
{
	uint32_t count = 1U;

	if (fault_noinit.magic == STM32_FAULT_MAGIC || fault_noinit.magic == STM32_FAULT_ARMED) {
		count = fault_noinit.count + 1U;
	}
	fault_noinit.vector = 0U;
	fault_noinit.pc = (uint32_t)(uintptr_t)file;
	fault_noinit.lr = line;
	fault_noinit.cfsr = 0U;
	fault_noinit.hfsr = 0U;
	fault_noinit.fault_addr = 0U;
	fault_noinit.count = count;
	fault_noinit.magic = STM32_FAULT_MAGIC;
	cm_dsb();
#if defined(SQ_TARGET_TEST)
	semihost_print_u32("EVT contract line=", line, "\n");
#endif
	SCB_AIRCR = SCB_AIRCR_VECTKEY | SCB_AIRCR_SYSRESETREQ;
	for (;;) {
		cm_dsb();
	}
}

/* Called once at boot, before anything can fault again. */
bool stm32_fault_record_take(stm32_fault_record_t *out)
{
	if (fault_noinit.magic == STM32_FAULT_MAGIC) {
		last_fault.magic = fault_noinit.magic;
		last_fault.vector = fault_noinit.vector;
		last_fault.pc = fault_noinit.pc;
		last_fault.lr = fault_noinit.lr;
		last_fault.cfsr = fault_noinit.cfsr;
		last_fault.hfsr = fault_noinit.hfsr;
		last_fault.fault_addr = fault_noinit.fault_addr;
		last_fault.count = fault_noinit.count;
		last_fault_valid = true;
		/* Keep the count for the next fault, but never report this one
		 * again after a later, ordinary reset. */
		fault_noinit.magic = STM32_FAULT_ARMED;
	} else if (fault_noinit.magic != STM32_FAULT_ARMED) {
		fault_noinit.count = 0U; /* power-on: RAM holds noise */
		fault_noinit.magic = STM32_FAULT_ARMED;
	}
	if (last_fault_valid && out != NULL) {
		*out = last_fault;
	}
	return last_fault_valid;
}

const stm32_fault_record_t *stm32_last_fault(void)
{
	return last_fault_valid ? &last_fault : NULL;
}
