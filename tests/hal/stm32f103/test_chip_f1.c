/* SPDX-License-Identifier: MIT */
/*
 * STM32F103 specifics on the host (hal/stm32f103/chip_f1.c, the shared
 * iwdg.c and bxcan.c built for the F103's chip.h, its registers in arrays:
 * tests/support/regsim/f103/chip.h). The bring-up and contract checks:
 *   - AFIO_MAPR: SWJ_CFG (bits 26:24) is write-only and reads back
 *     undefined (RM0008 9.4.2); the CAN remap must write it as 000 (full
 *     SWJ) whatever it reads, and keep the other remap bits;
 *   - IWDG reload for the fastest F103 LSI (60 kHz, datasheet), DBGMCU_CR
 *     DBG_IWDG_STOP (bit 8);
 *   - single bus: every CAN call on bus 1 answers SQ_ENODEV and touches no
 *     register; bus 2 is a programming error;
 *   - calibration flash (RM0008 3.3.3, PM0075 2.3-2.4): the two slots of
 *     two 1 KiB pages (the link's __calib_slot_size, 2048, as in
 *     linker/stm32f103xb.ld) are erased page by page, FLASH_AR = the page's
 *     address, the slot's first page first; slot 2 does not exist. Flash
 *     is programmed in half-words at even addresses (FLASH_CR.PG): an odd
 *     address is refused, an odd length's last byte goes with an 0xFF
 *     above it, the byte after it left erased. The unlock sequence is
 *     chip_common.c's (tests/hal/stm32f4/test_chip_common.c): here FLASH_CR
 *     is left unlocked before each call, and the test's wait on FLASH_SR
 *     performs the page erase FLASH_CR.STRT asks for.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "bxcan.h"
#include "chip.h"
#include "sq_status.h"
#include "stm32_board.h"
#include "stm32_fault.h"
#include "stm32_time.h"

uint32_t regsim_rcc[64], regsim_afio[8], regsim_gpiob[8], regsim_flash[8], regsim_iwdg[4], regsim_dbgmcu[4];
/* the two calibration slots: the link puts __calib_start here
 * (--defsym), with no PIE so that their addresses fit in 32 bits */
uint8_t regsim_f1_flash_mem[2U * 2048U] __attribute__((aligned(4)));
static uint32_t can_accesses;

#define F1_FLASH_SR regsim_flash[0x0CU / 4U]
#define F1_FLASH_CR regsim_flash[0x10U / 4U]
#define F1_FLASH_AR regsim_flash[0x14U / 4U]
#define F1_CR_PG (1U << 0)
#define F1_CR_PER (1U << 1)
#define F1_CR_STRT (1U << 6)
#define F1_CR_LOCK (1U << 7)
static uint32_t erased_at[8]; /* FLASH_AR of each page erase */
static uint32_t n_erased;

static uint32_t flash_addr(uint32_t off)
{
	return (uint32_t)(uintptr_t)regsim_f1_flash_mem + off;
}

/* A page erase (PER, then STRT) runs while the code waits for BSY: the
 * 1 KiB page at FLASH_AR becomes 0xFF, STRT clears. */
static void flash_page_erase(void)
{
	const uint32_t off = F1_FLASH_AR - flash_addr(0U);

	if (n_erased < 8U) {
		erased_at[n_erased] = F1_FLASH_AR;
	}
	n_erased++;
	assert_true(off < sizeof(regsim_f1_flash_mem) && off % 1024U == 0U);
	memset(&regsim_f1_flash_mem[off], 0xFF, 1024U);
	F1_FLASH_CR &= ~F1_CR_STRT;
}

/* ---- what the files under test need --------------------------------------- */

void stm32_time_early_init(uint32_t core_hz)
{
	(void)core_hz;
}

int stm32_wait_reg(volatile const uint32_t *reg, uint32_t mask, uint32_t value, uint32_t timeout_us)
{
	(void)timeout_us;
	if (reg == &F1_FLASH_SR) {
		/* FLASH_SR's flags are write-1-to-clear and this flash raises
		 * none: what the code wrote there is cleared */
		F1_FLASH_SR = 0U;
		if ((F1_FLASH_CR & (F1_CR_PER | F1_CR_STRT)) == (F1_CR_PER | F1_CR_STRT)) {
			flash_page_erase();
		}
	}
	return ((*reg & mask) == value) ? SQ_OK : SQ_EAGAIN;
}

void stm32_timeout_start(stm32_timeout_t *t, uint32_t timeout_us)
{
	t->polls = 0U;
	t->limit_ticks = timeout_us;
}

bool stm32_timeout_expired(stm32_timeout_t *t)
{
	return ++t->polls >= t->limit_ticks;
}

bool stm32_fault_record_take(stm32_fault_record_t *out)
{
	(void)out;
	return false;
}

void stm32_fault_raise(uint32_t hal_fault_bits)
{
	(void)hal_fault_bits;
}

uint64_t hal_time_us(void)
{
	return 0U;
}

uint32_t bxcan_sim_read(uintptr_t base, uint32_t off);
void bxcan_sim_write(uintptr_t base, uint32_t off, uint32_t value);
uint32_t bxcan_sim_read(uintptr_t base, uint32_t off)
{
	(void)base;
	(void)off;
	can_accesses++;
	return 0U;
}

void bxcan_sim_write(uintptr_t base, uint32_t off, uint32_t value)
{
	(void)base;
	(void)off;
	(void)value;
	can_accesses++;
}

void cm_dsb(void) {}
void cm_isb(void) {}
void cm_dmb(void) {}
void cm_wfi(void) {}
void cm_irq_enable(void) {}
void cm_irq_disable(void) {}
uint32_t cm_irq_save(void) { return 0U; }
void cm_irq_restore(uint32_t primask) { (void)primask; }
void cm_nvic_enable(uint32_t irq, uint8_t prio) { (void)irq; (void)prio; }
void cm_nvic_disable(uint32_t irq) { (void)irq; }

_Noreturn void hal_contract_failed(const char *file, uint32_t line)
{
	mock_assert(0, "hal_contract_failed", file, (int)line);
	abort();
}

static int setup(void **state)
{
	(void)state;
	memset(regsim_rcc, 0, sizeof(regsim_rcc));
	memset(regsim_afio, 0, sizeof(regsim_afio));
	memset(regsim_gpiob, 0, sizeof(regsim_gpiob));
	memset(regsim_iwdg, 0, sizeof(regsim_iwdg));
	memset(regsim_dbgmcu, 0, sizeof(regsim_dbgmcu));
	memset(regsim_flash, 0, sizeof(regsim_flash));
	memset(regsim_f1_flash_mem, 0x00, sizeof(regsim_f1_flash_mem)); /* old data */
	n_erased = 0U;
	can_accesses = 0U;
	return 0;
}

/* ---- tests ---------------------------------------------------------------- */

#define MAPR regsim_afio[1] /* AFIO_MAPR at +0x04 */

static void test_afio_swj_cfg_masked(void **state)
{
	(void)state;
	/* SWJ_CFG reads back as garbage (here 100: "JTAG and SWD off" if
	 * written back), SPI1_REMAP (bit 0) and USART1_REMAP (bit 2) set */
	MAPR = (4U << 24) | (1U << 2) | 1U;
	chip_can_pins_init(0U);
	assert_int_equal((MAPR >> 24) & 7U, 0U);      /* full SWJ: SWD stays on */
	assert_int_equal((MAPR >> 13) & 3U, 2U);      /* CAN_REMAP 10: PB8/PB9  */
	assert_int_equal(MAPR & ((1U << 2) | 1U), (1U << 2) | 1U); /* others kept */
	assert_true((regsim_rcc[0x1CU / 4U] & (1U << 25)) != 0U);  /* CAN1EN */
}

static void test_can_pins_bus1_untouched(void **state)
{
	(void)state;
	chip_can_pins_init(1U);
	assert_int_equal(MAPR, 0U);
	assert_int_equal(regsim_rcc[0x1CU / 4U], 0U);
	assert_int_equal(regsim_gpiob[1], 0U);
}

#define LSI_FASTEST_HZ 60000U /* STM32F103 datasheet: LSI 30..60 kHz */

static void test_iwdg_fastest_lsi_and_debug_freeze(void **state)
{
	static const uint32_t timeouts_ms[] = { 1U, 100U, 1000U, 10000U };
	uint32_t i;

	(void)state;
	for (i = 0; i < sizeof(timeouts_ms) / sizeof(timeouts_ms[0]); i++) {
		uint32_t div;
		uint64_t ticks;

		assert_int_equal(hal_watchdog_start(timeouts_ms[i]), SQ_OK);
		div = 4U << regsim_iwdg[1];
		ticks = (uint64_t)div * (regsim_iwdg[2] + 1U);
		assert_true(ticks * 1000U >= (uint64_t)timeouts_ms[i] * LSI_FASTEST_HZ);
		assert_true((ticks - div) * 1000U < (uint64_t)timeouts_ms[i] * LSI_FASTEST_HZ);
	}
	/* 100 ms: 4 * 1500 / 60 kHz exactly (was 4 * 800 / 32 kHz: 53 ms at 60 kHz) */
	assert_int_equal(hal_watchdog_start(100U), SQ_OK);
	assert_int_equal(regsim_iwdg[1], 0U);
	assert_int_equal(regsim_iwdg[2], 1499U);
	assert_true((regsim_dbgmcu[1] & (1U << 8)) != 0U); /* DBG_IWDG_STOP */
	/* 4096 * 256 / 60 kHz = 17.5 s is the longest */
	assert_int_equal(hal_watchdog_start(18000U), SQ_EINVAL);
}

static void test_bus1_is_enodev(void **state)
{
	hal_can_frame_t f;
	hal_can_status_t st;
	const hal_can_filter_t flt = { 0x100U, 0x7FFU, 0U };

	(void)state;
	memset(&f, 0, sizeof(f));
	assert_int_equal(hal_can_send(1U, &f), SQ_ENODEV);
	assert_int_equal(hal_can_receive(1U, &f), SQ_ENODEV);
	assert_int_equal(hal_can_get_status(1U, &st), SQ_ENODEV);
	assert_int_equal(hal_can_set_bitrate(1U, 500U), SQ_ENODEV);
	assert_int_equal(hal_can_set_rx_filter(1U, &flt, 1U), SQ_ENODEV);
	assert_int_equal(hal_can_set_mode(1U, HAL_CAN_MODE_LISTEN_ONLY), SQ_ENODEV);
	assert_int_equal(bxcan_selftest_loopback(1U), SQ_ENODEV);
	assert_int_equal(can_accesses, 0U);
	expect_assert_failure(hal_can_send(2U, &f));
}

/* Slot 0 is pages 0 and 1 of the slots, slot 1 pages 2 and 3, each slot's
 * first page first; slot 2 would be the flash after them: refused, nothing
 * erased. */
static void test_flash_erase_slot_pages(void **state)
{
	(void)state;
	assert_int_equal(chip_flash_erase_slot(1U), SQ_OK);
	assert_int_equal(n_erased, 2U);
	assert_int_equal(erased_at[0], flash_addr(2048U));
	assert_int_equal(erased_at[1], flash_addr(3072U));
	assert_int_equal(regsim_f1_flash_mem[2048], 0xFFU);
	assert_int_equal(regsim_f1_flash_mem[4095], 0xFFU);
	assert_int_equal(regsim_f1_flash_mem[2047], 0x00U); /* slot 0 untouched */
	assert_int_equal(F1_FLASH_CR, F1_CR_LOCK);           /* locked again */
	F1_FLASH_CR = 0U;
	assert_int_equal(chip_flash_erase_slot(0U), SQ_OK);
	assert_int_equal(n_erased, 4U);
	assert_int_equal(erased_at[2], flash_addr(0U));
	assert_int_equal(erased_at[3], flash_addr(1024U));
	F1_FLASH_CR = 0U;
	assert_int_equal(chip_flash_erase_slot(2U), SQ_EINVAL);
	assert_int_equal(n_erased, 4U);
	assert_int_equal(F1_FLASH_CR, 0U); /* not even unlocked */
}

/* Half-words, little-endian: 5 bytes are 0x2211, 0x4433 and 0xFF55 (the
 * odd last byte with an erased byte above it); byte 5 stays erased. */
static void test_flash_program_half_words(void **state)
{
	static const uint8_t data[5] = { 0x11, 0x22, 0x33, 0x44, 0x55 };
	static const uint8_t want[8] = { 0x11, 0x22, 0x33, 0x44, 0x55, 0xFF, 0xFF, 0xFF };

	(void)state;
	memset(regsim_f1_flash_mem, 0xFF, sizeof(regsim_f1_flash_mem)); /* erased */
	assert_int_equal(chip_flash_program(flash_addr(16U), data, sizeof(data)), SQ_OK);
	assert_memory_equal(&regsim_f1_flash_mem[16], want, sizeof(want));
	assert_int_equal(regsim_f1_flash_mem[15], 0xFFU);
	assert_int_equal(F1_FLASH_CR, F1_CR_LOCK);
}

/* A half-word starts at an even address (PM0075 2.3.3): an odd one is
 * refused before anything is written. */
static void test_flash_program_odd_address_refused(void **state)
{
	static const uint8_t data[2] = { 0x12, 0x34 };

	(void)state;
	memset(regsim_f1_flash_mem, 0xFF, sizeof(regsim_f1_flash_mem));
	assert_int_equal(chip_flash_program(flash_addr(17U), data, sizeof(data)), SQ_EINVAL);
	assert_int_equal(regsim_f1_flash_mem[16], 0xFFU);
	assert_int_equal(regsim_f1_flash_mem[17], 0xFFU);
	assert_int_equal(regsim_f1_flash_mem[18], 0xFFU);
	assert_int_equal(F1_FLASH_CR, 0U); /* not even unlocked */
	assert_int_equal(chip_flash_program(flash_addr(16U), NULL, 2U), SQ_EINVAL);
}

SQ_CMOCKA_MAIN(
	cmocka_unit_test_setup(test_afio_swj_cfg_masked, setup),
	cmocka_unit_test_setup(test_can_pins_bus1_untouched, setup),
	cmocka_unit_test_setup(test_iwdg_fastest_lsi_and_debug_freeze, setup),
	cmocka_unit_test_setup(test_bus1_is_enodev, setup),
	cmocka_unit_test_setup(test_flash_erase_slot_pages, setup),
	cmocka_unit_test_setup(test_flash_program_half_words, setup),
	cmocka_unit_test_setup(test_flash_program_odd_address_refused, setup))
