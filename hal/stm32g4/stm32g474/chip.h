/* SPDX-License-Identifier: MIT */
/*
 * STM32G474xE (RM0440, Cortex-M4F, 170 MHz, 512 KiB flash, SRAM1 + SRAM2
 * 96 KiB, CCM SRAM 32 KiB): addresses, bits and interrupt numbers of the
 * peripherals the shared bare-metal HAL files (hal/stm32f4/) and this chip's
 * own file (chip_g4.c) touch, with the same names where the F4 has the same
 * register, RM0440's names otherwise. The CAN controllers are FDCAN
 * (hal/stm32g4/fdcan.c), not bxCAN.
 */
#ifndef CHIP_H
#define CHIP_H

#include <stdbool.h>
#include <stdint.h>

#include "cortex_m.h"
#include "chip_api.h" /* what this chip provides to the shared HAL files */

#define CHIP_NAME "STM32G474"
/* RM0440 NVIC chapter, vector table: device interrupts 0..101 (FMAC last) */
#define CHIP_IRQ_COUNT 102U
#define CHIP_HAS_CCM 1 /* 32 KiB CCM SRAM at 0x10000000 (RM0440 2.3, memory map) */
/* DBGMCU_IDCODE DEV_ID (RM0440 DBGMCU chapter): 0x469 = STM32G47x/G48x */
#define CHIP_DEV_ID 0x469U
#define DBGMCU_IDCODE REG32(0xE0042000U)
#define DBGMCU_IDCODE_DEV_ID_MSK 0xFFFU

/* Interrupt numbers (RM0440 vector table). FDCAN1 = bus 0, FDCAN2 = bus 1;
 * FDCAN3 is not used. Each FDCAN has two lines (FDCAN_ILS chooses). */
#define CHIP_IRQ_FDCAN1_IT0 21U
#define CHIP_IRQ_FDCAN1_IT1 22U
#define CHIP_IRQ_FDCAN2_IT0 86U
#define CHIP_IRQ_FDCAN2_IT1 87U
#define CHIP_CAN_BUSES 2U

/* The CAN controllers' interrupt handlers (fdcan.c) and their slots in the
 * vector table (startup.c). */
void FDCAN1_IT0_IRQHandler(void);
void FDCAN2_IT0_IRQHandler(void);
/* fdcan.c routes every interrupt to line 0 (FDCAN_ILS 0) */
#define CHIP_CAN_VECTORS                                                   \
	[16U + CHIP_IRQ_FDCAN1_IT0] = { .handler = FDCAN1_IT0_IRQHandler }, \
	[16U + CHIP_IRQ_FDCAN2_IT0] = { .handler = FDCAN2_IT0_IRQHandler },

/*
 * Clock plan (RM0440 7.2, clocks): HSE 24 MHz (NUCLEO-G474RE: crystal X3)
 * -> PLL M 6 (4 MHz VCO input, RM0440 7.2.4: 2.66..16 MHz), N 85 (VCO
 * 340 MHz, 96..344 MHz), R 2 -> SYSCLK 170 MHz; AHB = APB1 = APB2 = 170 MHz;
 * range 1 boost mode, 4 wait states. FDCAN kernel clock = HSE 24 MHz
 * (RCC_CCIPR FDCANSEL 00, RM0440 7.4): the crystal itself, no PLL jitter, and it divides
 * exactly into 500 k, 1 M, 2 M and 4 Mbit/s (48, 24, 12, 6 quanta); 340 MHz
 * divided by PLLQ's 2/4/6/8 gives none of them exactly. On the HSI
 * fallback the kernel clock is PCLK1 = HSI16 (FDCANSEL 10).
 */
#define CHIP_HSI_HZ      16000000U
#define CHIP_HSE_HZ      24000000U
#define CHIP_SYSCLK_HZ  170000000U
#define CHIP_APB1_HZ    170000000U
#define CHIP_PLL_M 6U
#define CHIP_PLL_N 85U
#define CHIP_PLL_R 2U

/* LSI (IWDG clock), datasheet DS12288 worst case 34 kHz: the reload is
 * computed for the fastest one, so the watchdog never fires early. */
#define CHIP_LSI_MAX_HZ 34000U
/* DBGMCU_APB1FZR1 (RM0440 DBGMCU chapter): DBG_IWDG_STOP, same place as the F4's */
#define CHIP_DBGMCU_IWDG_REG REG32(0xE0042008U)
#define CHIP_DBGMCU_IWDG_STOP (1U << 12)

/* Peripheral bases (RM0440 2.2.2, memory map and register boundaries) */
#define FDCAN1_BASE  0x40006400U
#define FDCAN2_BASE  0x40006800U
#define FDCAN_SRAM_BASE 0x4000A400U
#define IWDG_BASE    0x40003000U
#define PWR_BASE     0x40007000U
#define TIM17_BASE   0x40014800U
#define RCC_BASE     0x40021000U
#define FLASH_R_BASE 0x40022000U
#define GPIOA_BASE   0x48000000U
#define GPIOB_BASE   0x48000400U

/* RCC (RM0440 7.4) */
#define RCC_CR       REG32(RCC_BASE + 0x00U)
#define RCC_CFGR     REG32(RCC_BASE + 0x08U)
#define RCC_PLLCFGR  REG32(RCC_BASE + 0x0CU)
#define RCC_CICR     REG32(RCC_BASE + 0x20U)
#define RCC_AHB2ENR  REG32(RCC_BASE + 0x4CU)
#define RCC_APB1ENR1 REG32(RCC_BASE + 0x58U)
#define RCC_APB2ENR  REG32(RCC_BASE + 0x60U)
#define RCC_CCIPR    REG32(RCC_BASE + 0x88U)
#define RCC_CSR      REG32(RCC_BASE + 0x94U)

#define RCC_CR_HSION  (1U << 8)
#define RCC_CR_HSIRDY (1U << 10)
#define RCC_CR_HSEON  (1U << 16)
#define RCC_CR_HSERDY (1U << 17)
#define RCC_CR_HSEBYP (1U << 18)
#define RCC_CR_CSSON  (1U << 19)
#define RCC_CR_PLLON  (1U << 24)
#define RCC_CR_PLLRDY (1U << 25)

/* RCC_CFGR (RM0440 7.4): SW 01 HSI16, 10 HSE, 11 PLL (00 reserved) */
#define RCC_CFGR_SW_MSK    3U
#define RCC_CFGR_SW_HSI    1U
#define RCC_CFGR_SW_PLL    3U
#define RCC_CFGR_SWS_MSK   (3U << 2)
#define RCC_CFGR_SWS_HSI   (1U << 2)
#define RCC_CFGR_SWS_PLL   (3U << 2)
#define RCC_CFGR_HPRE_MSK  (0xFU << 4)
#define RCC_CFGR_HPRE_DIV2 (8U << 4)
#define RCC_CFGR_PPRE1_MSK (7U << 8)
#define RCC_CFGR_PPRE2_MSK (7U << 11)

/* RCC_PLLCFGR (RM0440 7.4) */
#define RCC_PLLCFGR_PLLSRC_HSE 3U
#define RCC_PLLCFGR_PLLM_SHIFT 4U  /* M = PLLM + 1 */
#define RCC_PLLCFGR_PLLN_SHIFT 8U
#define RCC_PLLCFGR_PLLREN (1U << 24)
#define RCC_PLLCFGR_PLLR_SHIFT 25U /* 00: /2 */

#define RCC_CICR_CSSC (1U << 8)
#define RCC_AHB2ENR_GPIOAEN (1U << 0)
#define RCC_AHB2ENR_GPIOBEN (1U << 1)
#define RCC_APB1ENR1_FDCANEN (1U << 25)
#define RCC_APB1ENR1_PWREN   (1U << 28)
#define RCC_APB2ENR_TIM17EN  (1U << 18)

/* RCC_CCIPR FDCANSEL (RM0440 7.4): 00 HSE, 01 PLL "Q", 10 PCLK1 */
#define RCC_CCIPR_FDCANSEL_SHIFT 24U
#define RCC_CCIPR_FDCANSEL_MSK (3U << 24)
#define RCC_CCIPR_FDCANSEL_HSE   (0U << 24)
#define RCC_CCIPR_FDCANSEL_PCLK1 (2U << 24)

/* RCC_CSR (RM0440 7.4). The G4 has no PORRSTF: BORRSTF is set by a
 * power-on and by a brown-out alike, so both read as a power-on here
 * (iwdg.c tests PORRSTF before BORRSTF). */
#define RCC_CSR_LSION    (1U << 0)
#define RCC_CSR_RMVF     (1U << 23)
#define RCC_CSR_OBLRSTF  (1U << 25)
#define RCC_CSR_PINRSTF  (1U << 26)
#define RCC_CSR_BORRSTF  (1U << 27)
#define RCC_CSR_PORRSTF  RCC_CSR_BORRSTF
#define RCC_CSR_SFTRSTF  (1U << 28)
#define RCC_CSR_IWDGRSTF (1U << 29)
#define RCC_CSR_WWDGRSTF (1U << 30)
#define RCC_CSR_LPWRRSTF (1U << 31)

/* PWR (RM0440 6.4): range 1 (VOS 01, the reset value); boost mode =
 * PWR_CR5 R1MODE 0, needed above 150 MHz (RM0440 6.1.5) */
#define PWR_CR1 REG32(PWR_BASE + 0x00U)
#define PWR_SR2 REG32(PWR_BASE + 0x14U)
#define PWR_CR5 REG32(PWR_BASE + 0x80U)
#define PWR_CR1_VOS_MSK (3U << 9)
#define PWR_CR1_VOS_RANGE1 (1U << 9)
#define PWR_SR2_VOSF (1U << 10)
#define PWR_CR5_R1MODE (1U << 8)

/* Embedded flash (RM0440 3.7) */
#define FLASH_ACR  REG32(FLASH_R_BASE + 0x00U)
#define FLASH_KEYR REG32(FLASH_R_BASE + 0x08U)
#define FLASH_SR   REG32(FLASH_R_BASE + 0x10U)
#define FLASH_CR   REG32(FLASH_R_BASE + 0x14U)
#define FLASH_ECCR REG32(FLASH_R_BASE + 0x18U)
#define FLASH_OPTR REG32(FLASH_R_BASE + 0x20U)
/* RM0440 3.3.3, wait states per HCLK (range 1 boost): 4 wait states for 136..170 MHz */
#define FLASH_ACR_LATENCY_MSK 0xFU
#define FLASH_ACR_LATENCY_4WS 4U
#define FLASH_ACR_PRFTEN (1U << 8)
#define FLASH_ACR_ICEN   (1U << 9)
#define FLASH_ACR_DCEN   (1U << 10)
#define FLASH_ACR_ICRST  (1U << 11)
#define FLASH_ACR_DCRST  (1U << 12)
#define FLASH_KEY1 0x45670123U
#define FLASH_KEY2 0xCDEF89ABU
/* FLASH_SR (RM0440 3.7) */
#define FLASH_SR_EOP     (1U << 0)
#define FLASH_SR_OPERR   (1U << 1)
#define FLASH_SR_PROGERR (1U << 3)
#define FLASH_SR_WRPERR  (1U << 4)
#define FLASH_SR_PGAERR  (1U << 5)
#define FLASH_SR_SIZERR  (1U << 6)
#define FLASH_SR_PGSERR  (1U << 7)
#define FLASH_SR_MISERR  (1U << 8)
#define FLASH_SR_FASTERR (1U << 9)
#define FLASH_SR_RDERR   (1U << 14)
#define FLASH_SR_OPTVERR (1U << 15)
#define FLASH_SR_BSY     (1U << 16)
#define FLASH_SR_ERRORS (FLASH_SR_OPERR | FLASH_SR_PROGERR | FLASH_SR_WRPERR | FLASH_SR_PGAERR | \
			 FLASH_SR_SIZERR | FLASH_SR_PGSERR | FLASH_SR_MISERR | FLASH_SR_FASTERR | \
			 FLASH_SR_RDERR | FLASH_SR_OPTVERR)
/* FLASH_CR (RM0440 3.7) */
#define FLASH_CR_PG   (1U << 0)
#define FLASH_CR_PER  (1U << 1)
#define FLASH_CR_PNB_SHIFT 3U
#define FLASH_CR_PNB_MSK (0x7FU << 3)
#define FLASH_CR_BKER (1U << 11)
#define FLASH_CR_STRT (1U << 16)
#define FLASH_CR_LOCK (1U << 31)
/* FLASH_OPTR (RM0440 3.7): BOR_LEV 000 1.7 V (BOR0, the power-down
 * reset), 001 2.0 V, 010 2.2 V, 011 2.5 V, 100 2.8 V; DBANK 1 = two banks of
 * 2 KiB pages (factory value), 0 = one bank of 4 KiB pages */
#define FLASH_OPTR_BOR_LEV_SHIFT 8U
#define FLASH_OPTR_BOR_LEV_MSK (7U << 8)
#define FLASH_OPTR_DBANK (1U << 22)
/* FLASH_ECCR (RM0440 3.7): the failing double word's offset in its bank
 * (DBANK 1; in the whole flash with DBANK 0), its bank, system flash, the
 * ECC correction interrupt enable, ECCD (double error: NMI, write 1 to
 * clear) */
#define FLASH_ECCR_ADDR_ECC_MSK 0x7FFFFU
#define FLASH_ECCR_BK_ECC (1U << 21)
#define FLASH_ECCR_SYSF_ECC (1U << 22)
#define FLASH_ECCR_ECCIE (1U << 24)
#define FLASH_ECCR_ECCD (1U << 31)
/* The flash has ECC: a double error raises NMI (chip_nmi_flash_ecc) */
#define CHIP_FLASH_HAS_ECC 1
/* A byte of flash read by the chip part (the host test reads through its
 * simulation, which raises the ECC NMI) */
#define CHIP_FLASH_LOAD8(addr) (*(const volatile uint8_t *)(uintptr_t)(addr))
#define CHIP_FLASH_BASE 0x08000000U
#define CHIP_FLASH_BANK2 0x08040000U /* DBANK 1: bank 2 (RM0440 3.3.1, flash organisation) */
/* 64-bit double words, each programmed once after an erase (ECC) */
#define CHIP_FLASH_PROGRAM_BYTES 8U

/* TIM17 (RM0440 TIM15/TIM16/TIM17 chapter, registers): input capture of
 * HSE/32 on channel 1; its capture registers are hse_meter.c's, the input
 * selection the G4's */
#define TIM17_TISEL REG32(TIM17_BASE + 0x5CU)
#define TIM17_OR1   REG32(TIM17_BASE + 0x68U)
#define TIM17_TISEL_TI1_HSE_32 3U /* TI1SEL 0011: HSE/32 */
#define TIM17_OR1_HSE32EN (1U << 0) /* HSE/32 requested for TI1SEL */
#define CHIP_HSE_RTC_DIV 32U

/* GPIO (RM0440 9.4) */
#define GPIO_MODER(b)   REG32((b) + 0x00U)
#define GPIO_OTYPER(b)  REG32((b) + 0x04U)
#define GPIO_OSPEEDR(b) REG32((b) + 0x08U)
#define GPIO_PUPDR(b)   REG32((b) + 0x0CU)
#define GPIO_AFRL(b)    REG32((b) + 0x20U)
#define GPIO_AFRH(b)    REG32((b) + 0x24U)
#define GPIO_MODE_AF 2U
#define GPIO_PUPD_UP 1U
#define GPIO_SPEED_HIGH 2U
#define GPIO_AF9_FDCAN 9U

/* Beyond chip_api.h (chip_g4.c): the FDCAN kernel clock the FDCAN driver
 * times its bits with. */
uint32_t chip_fdcan_kernel_hz(void);

#endif /* CHIP_H */
