/* SPDX-License-Identifier: MIT */
/*
 * The no-init fault record (startup.c): what a fault handler or the contract
 * handler left before it reset the core, and the previous run's stack
 * high-water mark (the stack is painted at every start).
 */
#ifndef STM32_FAULT_H
#define STM32_FAULT_H

#include <stdbool.h>
#include <stdint.h>

typedef struct {
	uint32_t magic;     /* STM32_FAULT_MAGIC when valid                    */
	uint32_t vector;    /* exception number (2 NMI, 3 HardFault ...) or
			     * STM32_FAULT_VECTOR_CONTRACT                      */
	uint32_t pc;        /* stacked PC of the faulting code                 */
	uint32_t lr;        /* stacked LR                                      */
	uint32_t cfsr;      /* SCB CFSR                                        */
	uint32_t hfsr;      /* SCB HFSR                                        */
	uint32_t fault_addr; /* MMFAR or BFAR when valid, else 0               */
	uint32_t count;     /* faults since power-on                           */
	uint32_t file;      /* contract: address of the __FILE__ string        */
	uint32_t line;      /* contract: __LINE__                              */
	uint32_t msp;       /* MSP when the fault was taken                    */
} stm32_fault_record_t;
#define STM32_FAULT_MAGIC 0xFA017EC0UL
/* Not an exception number (VECTACTIVE is 9 bits): hal_contract_failed(). */
#define STM32_FAULT_VECTOR_CONTRACT 0x400UL

/* Called once at boot: the record of the fault that caused this reset. */
bool stm32_fault_record_take(stm32_fault_record_t *out);
/* The record of the fault that caused this reset (NULL if none). */
const stm32_fault_record_t *stm32_last_fault(void);

/* Bytes of the stack reserve the previous run used at its deepest
 * (STM32_STACK_HWM_UNKNOWN after power-on: nothing was painted before). */
uint32_t stm32_stack_hwm_prev(void);
#define STM32_STACK_HWM_UNKNOWN 0xFFFFFFFFUL
/* Size of the main stack reserve (linker script). */
uint32_t stm32_stack_reserve_bytes(void);

/* Record a recorded-fault reset (SYSRESETREQ); in test builds print it. */
void stm32_fault_reset(void) __attribute__((noreturn));

#endif /* STM32_FAULT_H */
