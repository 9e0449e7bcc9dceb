/* SPDX-License-Identifier: MIT */
/*
 * STM32F103xB (RM0008, medium density, Cortex-M3 without FPU): the same
 * names as hal/stm32f4/chip.h for what the shared HAL files use, plus the
 * F1's own RCC, flash and GPIO registers. The fixed-point build runs here.
 */
#ifndef CHIP_H
#define CHIP_H

#include <stdbool.h>
#include <stdint.h>

#include "cortex_m.h"
#include "stm32_common_regs.h"
#include "chip_api.h" /* what this chip provides to the shared HAL files */

#define CHIP_NAME "STM32F103"
#define CHIP_IRQ_COUNT 43U

/* Interrupt numbers (RM0008 table 63): CAN1 shares 19/20 with USB */
#define CHIP_IRQ_CAN1_TX  19U
#define CHIP_IRQ_CAN1_RX0 20U
#define CHIP_IRQ_CAN1_RX1 21U
#define CHIP_IRQ_CAN1_SCE 22U

/* bxCAN: CAN1 only on the F103 (14 filter banks); bus 1 is SQ_ENODEV. */
#define CHIP_CAN_BUSES 1U
#define CHIP_CAN_FILTER_BANKS 14U

/* bxCAN's interrupt handlers (bxcan.c) and their vector slots (startup.c) */
void CAN1_TX_IRQHandler(void);
void CAN1_RX0_IRQHandler(void);
void CAN1_SCE_IRQHandler(void);
void CAN2_TX_IRQHandler(void);
void CAN2_RX0_IRQHandler(void);
void CAN2_SCE_IRQHandler(void);
#define CHIP_CAN_VECTORS                                                 \
	[16U + CHIP_IRQ_CAN1_TX] = { .handler = CAN1_TX_IRQHandler },   \
	[16U + CHIP_IRQ_CAN1_RX0] = { .handler = CAN1_RX0_IRQHandler }, \
	[16U + CHIP_IRQ_CAN1_SCE] = { .handler = CAN1_SCE_IRQHandler },

/* Clock plan: HSE 8 MHz x 9 -> 72 MHz SYSCLK, APB1 36 MHz (bxCAN), APB2 72. */
#define CHIP_HSI_HZ      8000000U
#define CHIP_HSE_HZ      8000000U
#define CHIP_SYSCLK_HZ  72000000U
#define CHIP_APB1_HZ    36000000U

/* LSI (IWDG clock), datasheet worst case: the reload is computed for the
 * fastest one, so the watchdog never fires before its timeout. */
#define CHIP_LSI_MAX_HZ 60000U
/* DBGMCU: IWDG stopped while the core is halted by a debugger. */
#define CHIP_DBGMCU_IWDG_REG REG32(0xE0042004U)
#define CHIP_DBGMCU_IWDG_STOP (1U << 8)

#define CAN1_BASE  0x40006400U
#define IWDG_BASE  0x40003000U
#define AFIO_BASE  0x40010000U
#define GPIOB_BASE 0x40010C00U
#define RCC_BASE   0x40021000U
#define FLASH_R_BASE 0x40022000U

/* RCC (RM0008 section 7.3) */
#define RCC_CR      REG32(RCC_BASE + 0x00U)
#define RCC_CFGR    REG32(RCC_BASE + 0x04U)
#define RCC_APB2ENR REG32(RCC_BASE + 0x18U)
#define RCC_APB1ENR REG32(RCC_BASE + 0x1CU)
#define RCC_CSR     REG32(RCC_BASE + 0x24U)
#define RCC_CR_HSEON  (1U << 16)
#define RCC_CR_HSERDY (1U << 17)
#define RCC_CR_PLLON  (1U << 24)
#define RCC_CR_PLLRDY (1U << 25)
#define RCC_CFGR_SW_MSK     3U
#define RCC_CFGR_SW_PLL     2U
#define RCC_CFGR_SWS_MSK    (3U << 2)
#define RCC_CFGR_SWS_PLL    (2U << 2)
#define RCC_CFGR_HPRE_MSK   (0xFU << 4)
#define RCC_CFGR_PPRE1_MSK  (7U << 8)
#define RCC_CFGR_PPRE1_DIV2 (4U << 8)
#define RCC_CFGR_PPRE2_MSK  (7U << 11)
#define RCC_CFGR_PLLSRC_HSE (1U << 16)
#define RCC_CFGR_PLLXTPRE   (1U << 17)
#define RCC_CFGR_PLLMUL_MSK (0xFU << 18)
#define RCC_CFGR_PLLMUL9    (7U << 18)
#define RCC_APB2ENR_AFIOEN  (1U << 0)
#define RCC_APB2ENR_IOPBEN  (1U << 3)
#define RCC_APB1ENR_CAN1EN  (1U << 25)

#define RCC_CSR_BORRSTF  0U /* the F1 has no separate brown-out flag */

/* Flash (RM0008 section 3.3.3, PM0075) */
#define FLASH_AR   REG32(FLASH_R_BASE + 0x14U)
#define FLASH_ACR_LATENCY_MSK 7U
#define FLASH_ACR_LATENCY_2WS 2U /* 48..72 MHz */
#define FLASH_ACR_PRFTBE (1U << 4)
#define FLASH_SR_BSY      (1U << 0)
#define FLASH_SR_PGERR    (1U << 2)
#define FLASH_SR_WRPRTERR (1U << 4)
#define FLASH_SR_EOP      (1U << 5)
#define FLASH_SR_ERRORS   (FLASH_SR_PGERR | FLASH_SR_WRPRTERR)
#define FLASH_CR_PG   (1U << 0)
#define FLASH_CR_PER  (1U << 1)
#define FLASH_CR_STRT (1U << 6)
#define FLASH_CR_LOCK (1U << 7)
#define CHIP_FLASH_PROGRAM_BYTES 2U /* half-words */

/* GPIO and AFIO */
#define GPIO_CRH(b) REG32((b) + 0x04U)
#define GPIO_ODR(b) REG32((b) + 0x0CU)
#define AFIO_MAPR   REG32(AFIO_BASE + 0x04U)
#define AFIO_MAPR_CAN_REMAP_MSK  (3U << 13)
#define AFIO_MAPR_CAN_REMAP_PB89 (2U << 13)
#define AFIO_MAPR_SWJ_CFG_MSK    (7U << 24) /* write-only, reads undefined */
#define AFIO_MAPR_SWJ_CFG_FULL   (0U << 24) /* JTAG + SWD (reset state)    */


#endif /* CHIP_H */
