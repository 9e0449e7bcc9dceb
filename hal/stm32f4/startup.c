/* SPDX-License-Identifier: MIT */
/*
 * Start-up: the vector table, the reset handler (FPU on, .data copy, .bss
 * clear, stack painted, then main) and the fault handlers, which record the
 * cause in no-init RAM and reset the core (hal_reset_reason() then says
 * HAL_RESET_FAULT). The fault handlers first move MSP to a stack of their
 * own: after a stack overflow the MSP points below SRAM, and C code on it
 * would fault again (lockup, no record). hal_contract_failed() records the
 * file and line the same way.
 * No C library start-up code is linked (newlib's crt0 sets its stack from
 * semihosting and does things an ECU does not want).
 */
#include <stddef.h>
#include <stdint.h>

#include "chip.h"
#include "hal.h"
#include "stm32_fault.h"
#include "stm32_test.h"
#include "stm32_time.h"

/* Linker symbols (linker/stm32f405xg.ld, linker/stm32f103xb.ld) */
extern uint32_t _sstack, _estack;
extern uint32_t _sidata, _sdata, _edata, _sbss, _ebss;
#if defined(CHIP_HAS_CCM)
extern uint32_t _sccm, _eccm;
#endif

int main(void);
void Reset_Handler(void) __attribute__((noreturn));
void Fault_Handler(void) __attribute__((naked));
/* An unexpected interrupt is recorded like a fault: the same handler (the
 * record's vector tells them apart). */
void Default_Handler(void) __attribute__((alias("Fault_Handler")));
#if defined(CHIP_FLASH_HAS_ECC)
void NMI_Handler(void) __attribute__((naked));
#define NMI_VECTOR NMI_Handler
#else
#define NMI_VECTOR Fault_Handler
#endif
void stm32_fault_entry(const uint32_t *frame, uint32_t exc_return, uint32_t msp) __attribute__((noreturn, used));

/* The fault handlers' own stack, in .bss above the main stack: an overflow
 * of the main stack runs downwards, away from it. 512 bytes: the handler
 * and, in test builds, the semihosting print. */
#define FAULT_STACK_WORDS 128U
__attribute__((used, aligned(8))) uint32_t stm32_fault_stack[FAULT_STACK_WORDS];

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
	[2] = { .handler = NMI_VECTOR },     /* NMI                  */
	[3] = { .handler = Fault_Handler },  /* HardFault            */
	[4] = { .handler = Fault_Handler },  /* MemManage            */
	[5] = { .handler = Fault_Handler },  /* BusFault             */
	[6] = { .handler = Fault_Handler },  /* UsageFault           */
	[7 ... 10] = { .handler = NULL },    /* reserved             */
	[13] = { .handler = NULL },          /* reserved             */
	[15] = { .handler = SysTick_Handler },
	CHIP_CAN_VECTORS /* the chip's CAN controller (chip.h) */
};
#pragma GCC diagnostic pop

/* Survives a system reset (linker: .noinit, never copied nor cleared). */
__attribute__((section(".noinit"))) static volatile stm32_fault_record_t fault_noinit;
#define STM32_FAULT_ARMED 0xA53A0000UL
/* Set once this run has painted its stack: the next boot may measure it. */
__attribute__((section(".noinit"))) static volatile uint32_t stack_painted_noinit;
#define STACK_PAINTED 0x57AC4ED1UL
#define STACK_PAINT 0xC5AC5AC5UL
#define STACK_PAINT_MARGIN_WORDS 16U /* below the reset handler's frame */
static uint32_t stack_hwm_prev = STM32_STACK_HWM_UNKNOWN;

static stm32_fault_record_t last_fault;
static bool last_fault_valid;

/*
 * The previous run left its paint below the deepest point it reached (the
 * stack reserve is NOLOAD: neither cleared nor loaded, and a system reset
 * keeps SRAM). Count the untouched words from the bottom, then paint this
 * run's stack up to just below the current frame.
 */
static void stack_measure_and_paint(void)
{
	uint32_t *p;
	uint32_t *limit;
	uint32_t untouched = 0U;
	uintptr_t sp;

	__asm__ volatile("mov %0, sp" : "=r"(sp));
	limit = (uint32_t *)(sp - 4U * STACK_PAINT_MARGIN_WORDS);
	if (stack_painted_noinit == STACK_PAINTED) {
		for (p = &_sstack; p < limit && *p == STACK_PAINT; p++) {
			untouched++;
		}
		stack_hwm_prev = (uint32_t)((uintptr_t)&_estack - (uintptr_t)&_sstack) - 4U * untouched;
	}
	for (p = &_sstack; p < limit; p++) {
		*p = STACK_PAINT;
	}
	stack_painted_noinit = STACK_PAINTED;
}

uint32_t stm32_stack_hwm_prev(void)
{
	return stack_hwm_prev;
}

uint32_t stm32_stack_reserve_bytes(void)
{
	return (uint32_t)((uintptr_t)&_estack - (uintptr_t)&_sstack);
}

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
	stack_measure_and_paint();
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
			 "mrs r2, msp\n\t"
			 /* a good stack before any C */
			 "movw r3, #:lower16:stm32_fault_stack+512\n\t"
			 "movt r3, #:upper16:stm32_fault_stack+512\n\t"
			 "msr msp, r3\n\t"
			 "b stm32_fault_entry\n\t");
}

_Static_assert(FAULT_STACK_WORDS * 4U == 512U, "Fault_Handler's movw/movt use 512");

#if defined(CHIP_FLASH_HAS_ECC)
/* A chip with flash ECC: a power cut in the middle of programming a
 * calibration double word leaves it with an ECC double error, and reading
 * it raises the NMI on every boot. Recording that as a fault would reset
 * into the same read: an NMI reset loop. The chip part clears and counts
 * such an error and the NMI returns (the read finishes, the slot is
 * treated as corrupt); any other NMI takes the fault path with the stack
 * as it was at entry (r4 only keeps the 8-byte alignment). */
void NMI_Handler(void)
{
	__asm__ volatile("push {r4, lr}\n\t"
			 "bl chip_nmi_flash_ecc\n\t"
			 "pop {r4, lr}\n\t"
			 "cbz r0, 1f\n\t"
			 "bx lr\n\t"
			 "1: b Fault_Handler\n\t");
}
#endif

static uint32_t next_fault_count(void)
{
	if (fault_noinit.magic == STM32_FAULT_MAGIC || fault_noinit.magic == STM32_FAULT_ARMED) {
		return fault_noinit.count + 1U;
	}
	return 1U;
}

void stm32_fault_reset(void)
{
	cm_dsb();
#if defined(SQ_TARGET_TEST) && !defined(SQ_TARGET_TEST_FAULT)
	semihost_exit(0x80U + (fault_noinit.vector & 0x7FU));
#else
	SCB_AIRCR = SCB_AIRCR_VECTKEY | SCB_AIRCR_SYSRESETREQ;
	for (;;) {
		cm_dsb();
	}
#endif
}

/* The ECU's contract handler (hal.h): a programming error is recorded like
 * a fault (vector STM32_FAULT_VECTOR_CONTRACT, file and line, the caller's
 * address as PC) and resets the core the same way; the next boot reports
 * HAL_RESET_FAULT. Were the reset request lost, the IWDG would still end it:
 * interrupts stay masked, nothing kicks it. */
void hal_contract_failed(const char *file, uint32_t line)
{
	cm_irq_disable();
	fault_noinit.count = next_fault_count();
	fault_noinit.vector = STM32_FAULT_VECTOR_CONTRACT;
	fault_noinit.pc = (uint32_t)(uintptr_t)__builtin_return_address(0);
	fault_noinit.lr = 0U;
	fault_noinit.cfsr = 0U;
	fault_noinit.hfsr = 0U;
	fault_noinit.fault_addr = 0U;
	fault_noinit.file = (uint32_t)(uintptr_t)file;
	fault_noinit.line = line;
	fault_noinit.msp = 0U;
	fault_noinit.magic = STM32_FAULT_MAGIC;
#if defined(SQ_TARGET_TEST)
	semihost_write0("EVT contract file=");
	semihost_write0(file);
	semihost_print_u32(" line=", line, "\n");
#endif
	stm32_fault_reset();
}

void stm32_fault_entry(const uint32_t *frame, uint32_t exc_return, uint32_t msp)
{
	uint32_t vector = SCB_ICSR & SCB_ICSR_VECTACTIVE_MSK;
	uint32_t cfsr = SCB_CFSR;
	uint32_t count = next_fault_count();
	uint32_t fault_addr = 0U;

	(void)exc_return;
	if ((cfsr & (1UL << 7)) != 0U) {        /* MMARVALID */
		fault_addr = SCB_MMFAR;
	} else if ((cfsr & (1UL << 15)) != 0U) { /* BFARVALID */
		fault_addr = SCB_BFAR;
	}
	/* The frame pointer may be bad (stack overflow): check it points into
	 * RAM before reading the stacked PC and LR. */
	if ((uintptr_t)frame >= (uintptr_t)&_sstack && (uintptr_t)frame + 32U <= (uintptr_t)&_estack &&
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
	fault_noinit.file = 0U;
	fault_noinit.line = 0U;
	fault_noinit.msp = msp;
	fault_noinit.magic = STM32_FAULT_MAGIC;
	cm_dsb();
#if defined(SQ_TARGET_TEST)
	semihost_print_u32("EVT fault vector=", vector, NULL);
	semihost_print_hex(" pc=0x", fault_noinit.pc, NULL);
	semihost_print_hex(" msp=0x", msp, NULL);
	semihost_print_hex(" cfsr=0x", cfsr, "\n");
#endif
	stm32_fault_reset();
}

/* Called once at boot, before anything can fault again. */
bool stm32_fault_record_take(stm32_fault_record_t *out)
{
	if (fault_noinit.magic == STM32_FAULT_MAGIC) {
		last_fault = fault_noinit; /* every field, out of the volatile record */
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
