/* SPDX-License-Identifier: MIT */
/*
 * Register names the STM32F1 and F4 share bit for bit (RM0008, RM0090):
 * the reset flags of RCC_CSR and the flash interface's first registers
 * and unlock keys. Each chip.h includes this next to its own names (its
 * FLASH_R_BASE, its RCC_CSR address and the flags that differ).
 */
#ifndef STM32_COMMON_REGS_H
#define STM32_COMMON_REGS_H

#define RCC_CSR_RMVF     (1U << 24)
#define RCC_CSR_PINRSTF  (1U << 26)
#define RCC_CSR_PORRSTF  (1U << 27)
#define RCC_CSR_SFTRSTF  (1U << 28)
#define RCC_CSR_IWDGRSTF (1U << 29)
#define RCC_CSR_WWDGRSTF (1U << 30)
#define RCC_CSR_LPWRRSTF (1U << 31)

#define FLASH_ACR  REG32(FLASH_R_BASE + 0x00U)
#define FLASH_KEYR REG32(FLASH_R_BASE + 0x04U)
#define FLASH_SR   REG32(FLASH_R_BASE + 0x0CU)
#define FLASH_CR   REG32(FLASH_R_BASE + 0x10U)
#define FLASH_KEY1 0x45670123U
#define FLASH_KEY2 0xCDEF89ABU

#endif /* STM32_COMMON_REGS_H */
