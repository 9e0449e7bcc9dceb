/* SPDX-License-Identifier: MIT */
/*
 * STM32F405/407 (RM0090): addresses, bits and interrupt numbers of the
 * peripherals this HAL touches, and the chip's clock plan. The F103 port has
 * its own chip.h with the same names (hal/stm32f103/stm32f103xb/chip.h). Kept in its own
 * directory so that the -I order picks the chip.
 */
#ifndef CHIP_H
#define CHIP_H

#include "cortex_m.h"
#include "stm32_common_regs.h"
#include "chip_api.h" /* what this chip provides to the shared HAL files */

#define CHIP_NAME "STM32F405"
#define CHIP_IRQ_COUNT 82U /* vector table: 16 system + 82 device entries */
#define CHIP_HAS_CCM 1     /* 64 KiB core-coupled data RAM at 0x10000000 */

/* Interrupt numbers (RM0090 table 61) */
#define CHIP_IRQ_CAN1_TX  19U
#define CHIP_IRQ_CAN1_RX0 20U
#define CHIP_IRQ_CAN1_RX1 21U
#define CHIP_IRQ_CAN1_SCE 22U
#define CHIP_IRQ_CAN2_TX  63U
#define CHIP_IRQ_CAN2_RX0 64U
#define CHIP_IRQ_CAN2_RX1 65U
#define CHIP_IRQ_CAN2_SCE 66U

/* bxCAN: CAN1 (master, owns the 28 filter banks) and CAN2 (slave). */
#define CHIP_CAN_BUSES 2U
#define CHIP_CAN_FILTER_BANKS 28U

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
	[16U + CHIP_IRQ_CAN1_SCE] = { .handler = CAN1_SCE_IRQHandler }, \
	[16U + CHIP_IRQ_CAN2_TX] = { .handler = CAN2_TX_IRQHandler },   \
	[16U + CHIP_IRQ_CAN2_RX0] = { .handler = CAN2_RX0_IRQHandler }, \
	[16U + CHIP_IRQ_CAN2_SCE] = { .handler = CAN2_SCE_IRQHandler },

/* Clock plan: HSE 8 MHz -> PLL (M 4: 2 MHz VCO input as RM0090 recommends,
 * N 168, P 2, Q 7) -> 168 MHz SYSCLK,
 * AHB 168 MHz, APB1 42 MHz (bxCAN), APB2 84 MHz, USB/SDIO 48 MHz. */
#define CHIP_HSI_HZ      16000000U
#define CHIP_HSE_HZ       8000000U
#define CHIP_SYSCLK_HZ  168000000U
#define CHIP_APB1_HZ     42000000U

/* LSI (IWDG clock), datasheet worst case: the reload is computed for the
 * fastest one, so the watchdog never fires before its timeout. */
#define CHIP_LSI_MAX_HZ 47000U
/* DBGMCU: IWDG stopped while the core is halted by a debugger. */
#define CHIP_DBGMCU_IWDG_REG REG32(0xE0042008U)
#define CHIP_DBGMCU_IWDG_STOP (1U << 12)

/* Peripheral bases */
#define CAN1_BASE  0x40006400U
#define CAN2_BASE  0x40006800U
#define IWDG_BASE  0x40003000U
#define PWR_BASE   0x40007000U
#define TIM11_BASE 0x40014800U
#define GPIOB_BASE 0x40020400U
#define RCC_BASE   0x40023800U
#define FLASH_R_BASE 0x40023C00U

/* RCC (RM0090 section 7.3) */
#define RCC_CR       REG32(RCC_BASE + 0x00U)
#define RCC_PLLCFGR  REG32(RCC_BASE + 0x04U)
#define RCC_CFGR     REG32(RCC_BASE + 0x08U)
#define RCC_CIR      REG32(RCC_BASE + 0x0CU)
#define RCC_AHB1ENR  REG32(RCC_BASE + 0x30U)
#define RCC_APB1RSTR REG32(RCC_BASE + 0x20U)
#define RCC_APB1ENR  REG32(RCC_BASE + 0x40U)
#define RCC_APB2ENR  REG32(RCC_BASE + 0x44U)
#define RCC_CSR      REG32(RCC_BASE + 0x74U)

#define RCC_CR_HSION  (1U << 0)
#define RCC_CR_HSIRDY (1U << 1)
#define RCC_CR_HSEON  (1U << 16)
#define RCC_CR_HSERDY (1U << 17)
#define RCC_CR_HSEBYP (1U << 18)
#define RCC_CR_CSSON  (1U << 19)
#define RCC_CR_PLLON  (1U << 24)
#define RCC_CR_PLLRDY (1U << 25)

#define RCC_PLLCFGR_PLLM_SHIFT 0U
#define RCC_PLLCFGR_PLLN_SHIFT 6U
#define RCC_PLLCFGR_PLLP_SHIFT 16U /* 0: /2 */
#define RCC_PLLCFGR_PLLSRC_HSE (1U << 22)
#define RCC_PLLCFGR_PLLQ_SHIFT 24U

#define RCC_CFGR_SW_MSK    3U
#define RCC_CFGR_SW_HSI    0U
#define RCC_CFGR_SW_PLL    2U
#define RCC_CFGR_SWS_MSK   (3U << 2)
#define RCC_CFGR_SWS_PLL   (2U << 2)
#define RCC_CFGR_HPRE_MSK  (0xFU << 4)
#define RCC_CFGR_PPRE1_MSK (7U << 10)
#define RCC_CFGR_PPRE1_DIV4 (5U << 10)
#define RCC_CFGR_PPRE2_MSK (7U << 13)
#define RCC_CFGR_PPRE2_DIV2 (4U << 13)
#define RCC_CFGR_RTCPRE_SHIFT 16U
#define RCC_CFGR_RTCPRE_MSK (0x1FU << 16)
#define RCC_CIR_CSSC (1U << 23)
#define RCC_APB2ENR_TIM11EN (1U << 18)

#define RCC_AHB1ENR_GPIOBEN (1U << 1)
#define RCC_APB1ENR_CAN1EN  (1U << 25)
#define RCC_APB1ENR_CAN2EN  (1U << 26)
#define RCC_APB1ENR_PWREN   (1U << 28)
#define RCC_APB1RSTR_CAN1RST (1U << 25)

#define RCC_CSR_LSION    (1U << 0)
#define RCC_CSR_BORRSTF  (1U << 25)

/* PWR: regulator scale 1 is needed above 144 MHz */
#define PWR_CR     REG32(PWR_BASE + 0x00U)
#define PWR_CR_VOS (1U << 14)

/* Embedded flash interface (RM0090 section 3.9) */
#define FLASH_OPTCR REG32(FLASH_R_BASE + 0x14U)
#define FLASH_OPTCR_BOR_LEV_SHIFT 2U
#define FLASH_OPTCR_BOR_LEV_MSK (3U << 2) /* 00 level 3 (2.7 V) .. 11 off */

/* TIM11 (RM0090 section 17): input capture of HSE_RTC on channel 1; its
 * capture registers are hse_meter.c's, the input remap is the F4's */
#define TIM11_OR    REG32(TIM11_BASE + 0x50U)
#define TIM11_OR_TI1_HSE_RTC 2U
#define FLASH_ACR_LATENCY_MSK 7U
#define FLASH_ACR_LATENCY_5WS 5U /* 150..168 MHz at 2.7..3.6 V */
#define FLASH_ACR_PRFTEN (1U << 8)
#define FLASH_ACR_ICEN   (1U << 9)
#define FLASH_ACR_DCEN   (1U << 10)
#define FLASH_ACR_ICRST  (1U << 11)
#define FLASH_ACR_DCRST  (1U << 12)
#define FLASH_SR_EOP    (1U << 0)
#define FLASH_SR_OPERR  (1U << 1)
#define FLASH_SR_WRPERR (1U << 4)
#define FLASH_SR_PGAERR (1U << 5)
#define FLASH_SR_PGPERR (1U << 6)
#define FLASH_SR_PGSERR (1U << 7)
#define FLASH_SR_BSY    (1U << 16)
#define FLASH_SR_ERRORS (FLASH_SR_OPERR | FLASH_SR_WRPERR | FLASH_SR_PGAERR | \
			 FLASH_SR_PGPERR | FLASH_SR_PGSERR)
#define FLASH_CR_PG   (1U << 0)
#define FLASH_CR_SER  (1U << 1)
#define FLASH_CR_SNB_SHIFT 3U
#define FLASH_CR_SNB_MSK (0xFU << 3)
#define FLASH_CR_PSIZE_X32 (2U << 8)
#define FLASH_CR_PSIZE_MSK (3U << 8)
#define FLASH_CR_STRT (1U << 16)
#define FLASH_CR_LOCK (1U << 31)
#define CHIP_FLASH_PROGRAM_BYTES 4U /* x32 programming */

/* GPIO (RM0090 section 8.4) */
#define GPIO_MODER(b)   REG32((b) + 0x00U)
#define GPIO_OTYPER(b)  REG32((b) + 0x04U)
#define GPIO_OSPEEDR(b) REG32((b) + 0x08U)
#define GPIO_PUPDR(b)   REG32((b) + 0x0CU)
#define GPIO_AFRL(b)    REG32((b) + 0x20U)
#define GPIO_AFRH(b)    REG32((b) + 0x24U)
#define GPIO_MODE_AF 2U
#define GPIO_PUPD_UP 1U
#define GPIO_SPEED_HIGH 2U
#define GPIO_AF9_CAN1 9U


#endif /* CHIP_H */
