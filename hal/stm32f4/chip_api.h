/* SPDX-License-Identifier: MIT */
/*
 * What every chip directory provides to the shared bare-metal HAL files
 * (hal/stm32f4/stm32f405/, hal/stm32f103/): clocks, CAN pins, flash. Each
 * chip.h includes this after its register names.
 */
#ifndef CHIP_API_H
#define CHIP_API_H

#include <stdbool.h>
#include <stdint.h>

int chip_clock_init(void);            /* SQ_OK or SQ_EAGAIN (fell back to HSI) */
/* HSE frequency measured against the HSI at start-up: Hz, 0 (no crystal
 * started), CHIP_HSE_NOT_MEASURED (the chip cannot measure it: F103). */
uint32_t chip_hse_measured_hz(void);
#define CHIP_HSE_NOT_MEASURED 0xFFFFFFFFU
/* Brown-out reset level from the option bytes: 3 (2.7 V, needed for 5 wait
 * states and x32 flash programming), 2, 1, 0 (off), CHIP_BOR_NONE (F103:
 * fixed power-down reset, no BOR option). */
uint32_t chip_bor_level(void);
#define CHIP_BOR_NONE 0xFFU
uint32_t chip_core_hz(void);
uint32_t chip_apb1_hz(void);
/* The chip's clock code records the clocks it runs on: the PLL's
 * CHIP_SYSCLK_HZ / CHIP_APB1_HZ, or the HSI (chip_common.c). */
void chip_clock_rates_set(bool on_pll);
/* GPIO and RCC clock of bus 0 (CAN1) or 1 (CAN2, which also needs CAN1's
 * clock: its filters live in CAN1); a bus the chip lacks: nothing. */
void chip_can_pins_init(uint8_t bus);
int chip_flash_erase_slot(uint32_t slot);
/* Flash idle, unlocked with the key sequence, its error flags cleared:
 * SQ_OK, or SQ_EIO (still busy, or still locked) (chip_common.c). */
int chip_flash_unlock(void);
/* The operation started finished within timeout_us without an error flag:
 * SQ_OK, else SQ_EIO (chip_common.c). */
int chip_flash_wait_done(uint32_t timeout_us);
int chip_flash_program(uint32_t addr, const uint8_t *data, uint32_t len);
/* n bytes of calibration flash from addr into dst: SQ_OK, or SQ_EIO when a
 * read hit an ECC double error (the G4: a double word a power cut left
 * half-programmed; the NMI counted it, chip_nmi_flash_ecc); chips without
 * flash ECC always SQ_OK (chip_common.c). */
int chip_flash_read(uint32_t addr, uint8_t *dst, uint32_t n);
/* Chips with flash ECC (chip.h: CHIP_FLASH_HAS_ECC, the G4), from the NMI: an ECC double error in the calibration pages is cleared
 * and counted and the NMI returns (true): the read finishes and
 * chip_flash_read() says SQ_EIO. Anything else (the clock security
 * system, an ECC error in the code): false, the fault path. */
bool chip_nmi_flash_ecc(void);

#endif /* CHIP_API_H */
