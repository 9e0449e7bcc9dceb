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

/* Clock plan: HSE 8 MHz x 9 -> 72 MHz SYSCLK, APB1 36 MHz (bxCAN), APB2 72. */
#define CHIP_HSI_HZ      8000000UL
#define CHIP_HSE_HZ      8000000UL
#define CHIP_SYSCLK_HZ  72000000UL
#define CHIP_APB1_HZ    36000000UL

/* LSI (IWDG clock), datasheet worst case: the reload is computed for the
 * fastest one, so the watchdog never fires before its timeout. */
#define CHIP_LSI_MAX_HZ 60000UL
/* DBGMCU: IWDG stopped while the core is halted by a debugger. */
#define CHIP_DBGMCU_IWDG_REG REG32(0xE0042004UL)
#define CHIP_DBGMCU_IWDG_STOP (1UL << 8)

#define CAN1_BASE  0x40006400UL
#define IWDG_BASE  0x40003000UL
#define AFIO_BASE  0x40010000UL
#define GPIOB_BASE 0x40010C00UL
#define RCC_BASE   0x40021000UL
#define FLASH_R_BASE 0x40022000UL

/* RCC (RM0008 section 7.3) */
#define RCC_CR      REG32(RCC_BASE + 0x00UL)
#define RCC_CFGR    REG32(RCC_BASE + 0x04UL)
#define RCC_APB2ENR REG32(RCC_BASE + 0x18UL)
#define RCC_APB1ENR REG32(RCC_BASE + 0x1CUL)
#define RCC_CSR     REG32(RCC_BASE + 0x24UL)
#define RCC_CR_HSEON  (1UL << 16)
#define RCC_CR_HSERDY (1UL << 17)
#define RCC_CR_PLLON  (1UL << 24)
#define RCC_CR_PLLRDY (1UL << 25)
#define RCC_CFGR_SW_MSK     3UL
#define RCC_CFGR_SW_PLL     2UL
#define RCC_CFGR_SWS_MSK    (3UL << 2)
#define RCC_CFGR_SWS_PLL    (2UL << 2)
#define RCC_CFGR_HPRE_MSK   (0xFUL << 4)
#define RCC_CFGR_PPRE1_MSK  (7UL << 8)
#define RCC_CFGR_PPRE1_DIV2 (4UL << 8)
#define RCC_CFGR_PPRE2_MSK  (7UL << 11)
#define RCC_CFGR_PLLSRC_HSE (1UL << 16)
#define RCC_CFGR_PLLXTPRE   (1UL << 17)
#define RCC_CFGR_PLLMUL_MSK (0xFUL << 18)
#define RCC_CFGR_PLLMUL9    (7UL << 18)
#define RCC_APB2ENR_AFIOEN  (1UL << 0)
#define RCC_APB2ENR_IOPBEN  (1UL << 3)
#define RCC_APB1ENR_CAN1EN  (1UL << 25)

#define RCC_CSR_RMVF     (1UL << 24)
#define RCC_CSR_BORRSTF  0UL /* the F1 has no separate brown-out flag */
#define RCC_CSR_PINRSTF  (1UL << 26)
#define RCC_CSR_PORRSTF  (1UL << 27)
#define RCC_CSR_SFTRSTF  (1UL << 28)
#define RCC_CSR_IWDGRSTF (1UL << 29)
#define RCC_CSR_WWDGRSTF (1UL << 30)
#define RCC_CSR_LPWRRSTF (1UL << 31)

/* Flash (RM0008 section 3.3.3, PM0075) */
#define FLASH_ACR  REG32(FLASH_R_BASE + 0x00UL)
#define FLASH_KEYR REG32(FLASH_R_BASE + 0x04UL)
#define FLASH_SR   REG32(FLASH_R_BASE + 0x0CUL)
#define FLASH_CR   REG32(FLASH_R_BASE + 0x10UL)
#define FLASH_AR   REG32(FLASH_R_BASE + 0x14UL)
#define FLASH_ACR_LATENCY_MSK 7UL
#define FLASH_ACR_LATENCY_2WS 2UL /* 48..72 MHz */
#define FLASH_ACR_PRFTBE (1UL << 4)
#define FLASH_KEY1 0x45670123UL
#define FLASH_KEY2 0xCDEF89ABUL
#define FLASH_SR_BSY      (1UL << 0)
#define FLASH_SR_PGERR    (1UL << 2)
#define FLASH_SR_WRPRTERR (1UL << 4)
#define FLASH_SR_EOP      (1UL << 5)
#define FLASH_CR_PG   (1UL << 0)
#define FLASH_CR_PER  (1UL << 1)
#define FLASH_CR_STRT (1UL << 6)
#define FLASH_CR_LOCK (1UL << 7)

/* GPIO and AFIO */
#define GPIO_CRH(b) REG32((b) + 0x04UL)
#define GPIO_ODR(b) REG32((b) + 0x0CUL)
#define AFIO_MAPR   REG32(AFIO_BASE + 0x04UL)
#define AFIO_MAPR_CAN_REMAP_MSK  (3UL << 13)
#define AFIO_MAPR_CAN_REMAP_PB89 (2UL << 13)
#define AFIO_MAPR_SWJ_CFG_MSK    (7UL << 24) /* write-only, reads undefined */
#define AFIO_MAPR_SWJ_CFG_FULL   (0UL << 24) /* JTAG + SWD (reset state)    */

int chip_clock_init(void);
uint32_t chip_hse_measured_hz(void); /* the F103 has no TIM11: not measured */
#define CHIP_HSE_NOT_MEASURED 0xFFFFFFFFUL
uint32_t chip_bor_level(void);       /* no BOR option on the F103 (fixed PDR) */
#define CHIP_BOR_NONE 0xFFUL
uint32_t chip_core_hz(void);
uint32_t chip_apb1_hz(void);
void chip_can_pins_init(uint8_t bus);
int chip_flash_erase_slot(uint32_t slot);
int chip_flash_program(uint32_t addr, const uint8_t *data, uint32_t len);

#endif /* CHIP_H */
