/* SPDX-License-Identifier: MIT */
/*
 * STM32G474 chip part (hal/stm32g4/chip_g4.c) on the host, its registers in
 * plain arrays (tests/support/regsim/g4/chip.h). The "hardware" answers each
 * bounded wait the way RM0440 says: HSERDY once HSEON is set and a crystal
 * is fitted, PLLRDY after PLLON, SWS following SW, VOSF clear, TIM17
 * capturing every 8th edge of HSE/32 on the HSI16-clocked counter only when
 * TI1SEL routes HSE/32 (0011) and HSE32EN requests it; a page erase fills
 * the page of FLASH_CR PNB/BKER with 0xFF. Expected values are RM0440's
 * formulas and tables worked by hand: f_VCO = 24 MHz / M * N = 340 MHz,
 * SYSCLK = f_VCO / R = 170 MHz; 4 wait states for 136..170 MHz in boost
 * mode; BOR_LEV codes; RCC_CSR flags; 2 KiB pages with DBANK 1 (bank 2
 * from 0x08040000), 4 KiB with DBANK 0, pages 0..127 in a bank either
 * way. The chip part has no numeric-build
 * dependence, so one build covers both.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <setjmp.h>

#include <cmocka.h>

#include "chip.h"
/* TIM17's capture registers (RM0440 TIM16/TIM17), which hse_meter.c drives */
#define TIM17_CR1   REG32(TIM17_BASE + 0x00U)
#define TIM17_SR    REG32(TIM17_BASE + 0x10U)
#define TIM17_CCMR1 REG32(TIM17_BASE + 0x18U)
#define TIM17_CCER  REG32(TIM17_BASE + 0x20U)
#define TIM17_CCR1  REG32(TIM17_BASE + 0x34U)
#include "regsim/calib_pattern.h"
#include "hal.h"
#include "sq_status.h"
#include "stm32_calib.h"
#include "stm32_fault.h"
#include "stm32_iwdg.h"
#include "stm32_platform_faults.h"
#include "stm32_time.h"

uint32_t regsim_rcc[64], regsim_pwr[40], regsim_flash[16], regsim_tim17[32], regsim_gpioa[16],
	regsim_gpiob[16], regsim_keyr_log[8], regsim_keyr_n;
uint32_t regsim_iwdg[4], regsim_dbgmcu[4];
uint8_t regsim_flash_mem[8192] __attribute__((aligned(8)));
uint32_t regsim_flash_mem_at = 0x7E000U;
/* the linker symbols of the calibration slots (chip_g4.c) */
extern const uint8_t __calib_start[];

static uint32_t flash_cr;
static uint32_t keys_seen; /* keys since the last lock */
static bool crystal_fitted;
static uint32_t crystal_hz;
static uint64_t capture_num;
/* state at the moment SW asked for the PLL */
static bool switched_to_pll;
static uint32_t acr_at_switch, r1mode_at_switch, hpre_at_switch;
static uint32_t erased[8][2]; /* bker, page */
static uint32_t n_erased;

void stm32_time_early_init(uint32_t core_hz)
{
	(void)core_hz;
}

void cm_dsb(void) { }

/* FLASH_CR: LOCK stays set until KEY1 then KEY2 arrive in FLASH_KEYR; a
 * write of LOCK locks it again (RM0440 3.3.5). */
volatile uint32_t *regsim_flash_cr(void)
{
	static uint32_t seen_n;

	while (seen_n < regsim_keyr_n) {
		uint32_t k = regsim_keyr_log[seen_n & 7U];

		keys_seen = (k == FLASH_KEY1) ? 1U : ((keys_seen == 1U && k == FLASH_KEY2) ? 2U : 0U);
		seen_n++;
	}
	if (keys_seen == 2U) {
		flash_cr &= ~FLASH_CR_LOCK;
		keys_seen = 3U;
	} else if ((flash_cr & FLASH_CR_LOCK) != 0U && keys_seen == 3U) {
		keys_seen = 0U;
	}
	return &flash_cr;
}

/* FLASH_SR: write 1 to clear. The cell the code sees holds the flags; a
 * value found there that differs from what was handed out was written, and
 * clears its 1s (a write equal to the flags themselves is not told apart,
 * which no test needs). */
static uint32_t flash_sr_hw, flash_sr_cell;
volatile uint32_t *regsim_flash_sr(void)
{
	if (flash_sr_cell != flash_sr_hw) {
		flash_sr_hw &= ~flash_sr_cell;
	}
	flash_sr_cell = flash_sr_hw;
	return &flash_sr_cell;
}

static void tim17_capture(void)
{
	bool routed = (RCC_APB2ENR & (1U << 18)) != 0U && (TIM17_CR1 & 1U) != 0U &&
		      (TIM17_TISEL & 0xFU) == 3U && (TIM17_OR1 & 1U) != 0U &&
		      (TIM17_CCMR1 & 3U) == 1U && (TIM17_CCER & 1U) != 0U;
	uint32_t psc = 1U << ((TIM17_CCMR1 >> 2) & 3U);

	if (!routed || !crystal_fitted) {
		return;
	}
	capture_num += (uint64_t)16000000U * 32U * psc; /* counter on the HSI16 */
	TIM17_CCR1 = (uint32_t)((capture_num / crystal_hz) & 0xFFFFU);
	TIM17_SR |= 1U << 1;
}

/* The power: flash operations (a page erase, a double word) it still
 * allows, -1 without limit. A cut lands in the middle of the operation
 * that would exceed it: an erased page then holds garbage, a double word
 * its new bits only partly, with an ECC double error in either case, and
 * the test continues at the setjmp (the next boot). */
static long power_ops = -1;
static jmp_buf power_cut;
static bool ecc_broken[sizeof(regsim_flash_mem) / 8U];
static uint8_t shadow[sizeof(regsim_flash_mem)]; /* the flash after the last whole operation */
static uint32_t nmi_count, nmi_fault_path;

static void power_spend(bool erase, uint32_t page_off, uint32_t page_bytes)
{
	uint32_t i;

	if (power_ops == 0) {
		if (erase) {
			for (i = 0U; i < page_bytes; i++) {
				regsim_flash_mem[page_off + i] = (uint8_t)(0x3CU + i);
				ecc_broken[(page_off + i) / 8U] = true;
			}
		} else {
			/* the double word just written (it differs from the shadow) */
			for (i = 0U; i < sizeof(regsim_flash_mem); i += 8U) {
				if (memcmp(&regsim_flash_mem[i], &shadow[i], 8U) != 0) {
					regsim_flash_mem[i] ^= 0x5AU;
					ecc_broken[i / 8U] = true;
				}
			}
		}
		power_ops = -1;
		longjmp(power_cut, 1);
	}
	if (power_ops > 0) {
		power_ops--;
	}
}

/* The core reading the flash: a double word with an ECC double error sets
 * FLASH_ECCR (ECCD, the double word's offset in its bank, BK_ECC) and
 * takes the NMI, which the chip part must claim (never the fault path, or
 * the ECU would reset into the same read); the read returns garbage. */
uint8_t regsim_flash_load8(uint32_t addr)
{
	const uint32_t off = addr - (uint32_t)(uintptr_t)regsim_flash_mem;

	assert_true(off < sizeof(regsim_flash_mem));
	if (ecc_broken[off / 8U]) {
		const uint32_t in_flash = regsim_flash_mem_at + (off & ~7U);
		const bool dual_bank = (FLASH_OPTR & (1U << 22)) != 0U;

		FLASH_ECCR = (1U << 31) | (dual_bank ? ((1U << 21) | (in_flash - 0x40000U)) : in_flash);
		nmi_count++;
		if (!chip_nmi_flash_ecc()) {
			nmi_fault_path++;
		}
		assert_int_equal(FLASH_ECCR, 1U << 31); /* ECCD written back: cleared */
		return (uint8_t)(0xA5U ^ off);
	}
	return regsim_flash_mem[off];
}

static void flash_erase(void)
{
	uint32_t page_bytes = (FLASH_OPTR & (1U << 22)) != 0U ? 2048U : 4096U;
	uint32_t bker = (flash_cr >> 11) & 1U;
	uint32_t pnb = (flash_cr >> 3) & 0x7FU;
	uint32_t bank = (bker != 0U) ? 0x40000U : 0U;
	uint32_t off = bank + pnb * page_bytes; /* from the flash's start */

	if (n_erased < 8U) { /* the first erases of a test, for its checks */
		erased[n_erased][0] = bker;
		erased[n_erased][1] = pnb;
		n_erased++;
	}
	/* calibration only, inside the 512 KiB */
	assert_true(off >= regsim_flash_mem_at && off + page_bytes <= regsim_flash_mem_at + sizeof(regsim_flash_mem));
	assert_true(off + page_bytes <= 0x80000U);
	off -= regsim_flash_mem_at;
	power_spend(true, off, page_bytes);
	memset(&regsim_flash_mem[off], 0xFF, page_bytes);
	memset(&ecc_broken[off / 8U], 0, page_bytes / 8U);
	memcpy(&shadow[off], &regsim_flash_mem[off], page_bytes);
	flash_cr &= ~(1U << 16);
}

static void flash_programmed(void)
{
	power_spend(false, 0U, 0U);
	memcpy(shadow, regsim_flash_mem, sizeof(shadow));
}

int stm32_wait_reg(volatile const uint32_t *reg, uint32_t mask, uint32_t value, uint32_t timeout_us)
{
	(void)timeout_us;
	if (reg == &RCC_CR) {
		RCC_CR = (RCC_CR & ~((1U << 17) | (1U << 25))) |
			 (((RCC_CR & (1U << 16)) != 0U && crystal_fitted) ? (1U << 17) : 0U) |
			 ((RCC_CR & (1U << 24)) != 0U ? (1U << 25) : 0U);
	} else if (reg == &RCC_CFGR) {
		if ((RCC_CFGR & 3U) == 3U && !switched_to_pll) {
			switched_to_pll = true;
			acr_at_switch = FLASH_ACR;
			r1mode_at_switch = PWR_CR5 & (1U << 8);
			hpre_at_switch = (RCC_CFGR >> 4) & 0xFU;
		}
		RCC_CFGR = (RCC_CFGR & ~(3U << 2)) | ((RCC_CFGR & 3U) << 2);
	} else if (reg == &TIM17_SR) {
		tim17_capture();
	} else if (reg == &flash_sr_cell && (flash_cr & ((1U << 16) | (1U << 1))) == ((1U << 16) | (1U << 1))) {
		flash_erase();
	} else if (reg == &flash_sr_cell && (flash_cr & FLASH_CR_PG) != 0U && (*reg & mask) == value) {
		flash_programmed(); /* a double word written, the flash idle again */
	}
	return ((*reg & mask) == value) ? SQ_OK : SQ_EAGAIN;
}

static int setup(void **state)
{
	(void)state;
	memset(regsim_rcc, 0, sizeof(regsim_rcc));
	memset(regsim_pwr, 0, sizeof(regsim_pwr));
	memset(regsim_flash, 0, sizeof(regsim_flash));
	memset(regsim_tim17, 0, sizeof(regsim_tim17));
	memset(regsim_gpioa, 0, sizeof(regsim_gpioa));
	memset(regsim_gpiob, 0, sizeof(regsim_gpiob));
	memset(regsim_flash_mem, 0x00, sizeof(regsim_flash_mem)); /* "old data" */
	regsim_flash_mem_at = 0x7E000U;
	RCC_CFGR = 5U;                 /* reset: SW = SWS = HSI16 */
	PWR_CR1 = 1U << 9;             /* reset: range 1 */
	PWR_CR5 = 1U << 8;             /* reset: R1MODE 1 (normal) */
	FLASH_OPTR = 0xFFEFF8AAU;      /* factory value: DBANK 1, BOR_LEV 000 */
	flash_cr = FLASH_CR_LOCK;
	keys_seen = 0U;
	flash_sr_hw = 0U;
	flash_sr_cell = 0U;
	crystal_fitted = true;
	crystal_hz = 24000000U;
	capture_num = 0U;
	switched_to_pll = false;
	n_erased = 0U;
	power_ops = -1;
	memset(ecc_broken, 0, sizeof(ecc_broken));
	memcpy(shadow, regsim_flash_mem, sizeof(shadow));
	nmi_count = 0U;
	nmi_fault_path = 0U;
	return 0;
}

static void assert_on_hsi(void)
{
	assert_int_equal(RCC_CFGR & 3U, 1U);        /* SW = HSI16 */
	assert_int_equal(RCC_CR & (1U << 24), 0U);  /* PLL off */
	assert_int_equal(RCC_CR & (1U << 16), 0U);  /* HSE off */
	assert_int_equal(RCC_CR & (1U << 19), 0U);  /* CSS off */
	assert_int_equal(FLASH_ACR & 0xFU, 0U);     /* 0 WS at 16 MHz */
	assert_true((PWR_CR5 & (1U << 8)) != 0U);   /* normal mode again */
	assert_int_equal((RCC_CCIPR >> 24) & 3U, 2U); /* FDCAN on PCLK1 */
	assert_int_equal(chip_core_hz(), 16000000U);
	assert_int_equal(chip_apb1_hz(), 16000000U);
	assert_int_equal(chip_fdcan_kernel_hz(), 16000000U);
}

static void test_24mhz_crystal_runs_pll_at_170(void **state)
{
	uint32_t pll;
	uint32_t m, n, r;

	(void)state;
	assert_int_equal(chip_clock_init(), SQ_OK);
	/* 16 captures x 8 edges x 32 HSE periods at 24 MHz = 2730.7 ticks */
	assert_true(chip_hse_measured_hz() > 23990000U && chip_hse_measured_hz() < 24010000U);
	pll = RCC_PLLCFGR;
	m = ((pll >> 4) & 0xFU) + 1U;
	n = (pll >> 8) & 0x7FU;
	r = 2U * (((pll >> 25) & 3U) + 1U);
	assert_int_equal(pll & 3U, 3U);                   /* PLLSRC = HSE */
	assert_int_equal(24000000U / m, 4000000U);        /* VCO input 4 MHz */
	assert_int_equal(24000000U / m * n, 340000000U);  /* VCO <= 344 MHz */
	assert_int_equal(24000000U / m * n / r, 170000000U);
	assert_true((pll & (1U << 24)) != 0U);            /* PLLREN */
	assert_int_equal(pll & ((1U << 16) | (1U << 20)), 0U); /* P, Q off */
	assert_int_equal(RCC_CFGR & 3U, 3U);              /* SW = PLL */
	assert_int_equal((RCC_CFGR >> 4) & 0xFU, 0U);     /* AHB /1 again */
	assert_true((RCC_CR & (1U << 19)) != 0U);         /* CSSON */
	assert_int_equal((RCC_CCIPR >> 24) & 3U, 0U);     /* FDCAN on HSE */
	assert_int_equal(chip_core_hz(), 170000000U);
	assert_int_equal(chip_apb1_hz(), 170000000U);
	assert_int_equal(chip_fdcan_kernel_hz(), 24000000U);
}

/* RM0440 6.1.5 and 3.3.3: boost mode and 4 wait states in place, and the
 * AHB at /2, at the moment SW asks for the 170 MHz PLL. */
static void test_wait_states_and_boost_before_the_rise(void **state)
{
	(void)state;
	assert_int_equal(chip_clock_init(), SQ_OK);
	assert_true(switched_to_pll);
	assert_int_equal(acr_at_switch & 0xFU, 4U);
	assert_int_equal(r1mode_at_switch, 0U);
	assert_int_equal(hpre_at_switch, 8U); /* /2 */
}

static void test_wrong_crystal_falls_back_to_hsi(void **state)
{
	uint32_t hz;

	(void)state;
	crystal_hz = 8000000U; /* an 8 MHz part fitted */
	assert_int_equal(chip_clock_init(), SQ_EAGAIN);
	hz = chip_hse_measured_hz();
	assert_true(hz > 7992000U && hz < 8008000U);
	assert_on_hsi();
	assert_false(switched_to_pll);
	assert_int_equal(RCC_APB2ENR & (1U << 18), 0U); /* TIM17 clock off again */
}

static void test_tolerance_window(void **state)
{
	(void)state;
	crystal_hz = 25200000U; /* +5 % */
	assert_int_equal(chip_clock_init(), SQ_OK);
	setup(NULL);
	crystal_hz = 27000000U; /* +12.5 % */
	assert_int_equal(chip_clock_init(), SQ_EAGAIN);
	assert_on_hsi();
}

static void test_no_crystal(void **state)
{
	(void)state;
	crystal_fitted = false;
	assert_int_equal(chip_clock_init(), SQ_EAGAIN);
	assert_int_equal(chip_hse_measured_hz(), 0U);
	assert_on_hsi();
}

/* BOR_LEV (FLASH_OPTR 10:8) onto chip_api.h's 0..3, 3 = 2.8 V */
static void test_bor_level(void **state)
{
	static const uint32_t want[8] = { 0U, 0U, 1U, 2U, 3U, 0U, 0U, 0U };
	uint32_t code;

	(void)state;
	for (code = 0U; code < 8U; code++) {
		FLASH_OPTR = (0xFFEFF8AAU & ~(7U << 8)) | (code << 8);
		assert_int_equal(chip_bor_level(), want[code]);
	}
}

/* iwdg.c's decode of RCC_CSR with the G4's bits (RM0440 7.4): no PORRSTF,
 * BORRSTF is a power-on; IWDG wins over the pin flag it also sets. */
static bool fault_recorded;
bool stm32_fault_record_take(stm32_fault_record_t *out)
{
	(void)out;
	return fault_recorded;
}

static void test_reset_cause_decode(void **state)
{
	static const struct {
		uint32_t csr;
		hal_reset_reason_t want;
	} cases[] = {
		{ (1U << 27) | (1U << 26), HAL_RESET_POWER_ON }, /* BOR + PIN at power-up */
		{ 1U << 26, HAL_RESET_PIN },
		{ (1U << 29) | (1U << 26), HAL_RESET_WATCHDOG },
		{ (1U << 30) | (1U << 26), HAL_RESET_WATCHDOG },
		{ (1U << 28) | (1U << 26), HAL_RESET_SOFTWARE },
		{ 1U << 25, HAL_RESET_UNKNOWN }, /* option-byte loader */
	};
	size_t i;

	(void)state;
	for (i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
		RCC_CSR = cases[i].csr;
		stm32_reset_reason_capture();
		assert_int_equal(hal_reset_reason(), cases[i].want);
		assert_true((RCC_CSR & (1U << 23)) != 0U); /* RMVF written */
	}
	fault_recorded = true;
	RCC_CSR = 1U << 28;
	stm32_reset_reason_capture();
	assert_int_equal(hal_reset_reason(), HAL_RESET_FAULT);
	fault_recorded = false;
}

/* DBANK 1: slot 1 = bank 2 pages 126, 127, the header's page first */
static void test_erase_dual_bank(void **state)
{
	(void)state;
	assert_int_equal(chip_flash_erase_slot(1U), SQ_OK);
	assert_int_equal(n_erased, 2U);
	assert_int_equal(erased[0][0], 1U);
	assert_int_equal(erased[0][1], 126U);
	assert_int_equal(erased[1][1], 127U);
	assert_int_equal(regsim_flash_mem[4096], 0xFFU);
	assert_int_equal(regsim_flash_mem[8191], 0xFFU);
	assert_int_equal(regsim_flash_mem[4095], 0x00U); /* slot 0 untouched */
	assert_int_equal(regsim_keyr_log[(regsim_keyr_n - 2U) & 7U], 0x45670123U);
	assert_int_equal(regsim_keyr_log[(regsim_keyr_n - 1U) & 7U], 0xCDEF89ABU);
	assert_int_equal(flash_cr, FLASH_CR_LOCK); /* locked again */
	assert_int_equal(chip_flash_erase_slot(2U), SQ_EINVAL);
}

/* DBANK 0: 4 KiB pages from the start of the one bank: slot 0 = page 126 */
static void test_erase_single_bank(void **state)
{
	(void)state;
	FLASH_OPTR &= ~(1U << 22);
	assert_int_equal(chip_flash_erase_slot(0U), SQ_OK);
	assert_int_equal(n_erased, 1U);
	assert_int_equal(erased[0][0], 0U);
	assert_int_equal(erased[0][1], 126U);
	assert_int_equal(regsim_flash_mem[0], 0xFFU);
	assert_int_equal(regsim_flash_mem[4095], 0xFFU);
	assert_int_equal(regsim_flash_mem[4096], 0x00U);
}

/* The slots one page further up (DBANK 0: 4 KiB pages 0..127 of the one
 * bank, 512 KiB): slot 0 is page 127, the flash's last; slot 1 would be
 * page 128, beyond the flash: refused, nothing erased. */
static void test_erase_single_bank_last_page(void **state)
{
	(void)state;
	FLASH_OPTR &= ~(1U << 22);
	regsim_flash_mem_at = 0x7F000U;
	assert_int_equal(chip_flash_erase_slot(0U), SQ_OK);
	assert_int_equal(n_erased, 1U);
	assert_int_equal(erased[0][0], 0U);
	assert_int_equal(erased[0][1], 127U);
	assert_int_equal(regsim_flash_mem[4095], 0xFFU);
	assert_int_equal(chip_flash_erase_slot(1U), SQ_EINVAL);
	assert_int_equal(n_erased, 1U);
	assert_int_equal(regsim_flash_mem[4096], 0x00U);
}

/* DBANK 1 with slot 1 starting exactly at bank 2 (0x08040000): bank 2's
 * pages 0 and 1 (BKER 1); slot 0 the last two pages of bank 1, 126 and
 * 127 (BKER 0). */
static void test_erase_dual_bank_at_bank2_start(void **state)
{
	(void)state;
	regsim_flash_mem_at = 0x3F000U;
	assert_int_equal(chip_flash_erase_slot(1U), SQ_OK);
	assert_int_equal(n_erased, 2U);
	assert_int_equal(erased[0][0], 1U);
	assert_int_equal(erased[0][1], 0U);
	assert_int_equal(erased[1][0], 1U);
	assert_int_equal(erased[1][1], 1U);
	assert_int_equal(chip_flash_erase_slot(0U), SQ_OK);
	assert_int_equal(n_erased, 4U);
	assert_int_equal(erased[2][0], 0U);
	assert_int_equal(erased[2][1], 126U);
	assert_int_equal(erased[3][0], 0U);
	assert_int_equal(erased[3][1], 127U);
	assert_int_equal(regsim_flash_mem[0], 0xFFU);
	assert_int_equal(regsim_flash_mem[8191], 0xFFU);
}

/* DBANK 1 with slot 0 across the banks (bank 1's page 127, bank 2's page
 * 0): bank 1 has pages 0..127 only, so no page number of one bank erases
 * it: refused, nothing erased; slot 1 is bank 2's pages 1 and 2. */
static void test_erase_dual_bank_slot_across_banks_refused(void **state)
{
	(void)state;
	regsim_flash_mem_at = 0x3F800U;
	assert_int_equal(chip_flash_erase_slot(0U), SQ_EINVAL);
	assert_int_equal(n_erased, 0U);
	assert_int_equal(regsim_flash_mem[0], 0x00U);
	assert_int_equal(chip_flash_erase_slot(1U), SQ_OK);
	assert_int_equal(n_erased, 2U);
	assert_int_equal(erased[0][0], 1U);
	assert_int_equal(erased[0][1], 1U);
	assert_int_equal(erased[1][1], 2U);
}

/* 64-bit double words, little-endian, the tail padded with 0xFF; the
 * address must be double-word aligned; locked afterwards. */
static void test_program_double_words(void **state)
{
	static const uint8_t data[11] = { 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11 };
	static const uint8_t want[16] = { 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11,
					  0xFF, 0xFF, 0xFF, 0xFF, 0xFF };
	uint32_t addr = (uint32_t)(uintptr_t)__calib_start;

	(void)state;
	memset(regsim_flash_mem, 0xFF, sizeof(regsim_flash_mem));
	assert_int_equal(chip_flash_program(addr + 16U, data, sizeof(data)), SQ_OK);
	assert_memory_equal(&regsim_flash_mem[16], want, sizeof(want));
	assert_int_equal(regsim_flash_mem[15], 0xFFU);
	assert_int_equal(regsim_flash_mem[32], 0xFFU);
	assert_int_equal(flash_cr, FLASH_CR_LOCK);
	assert_int_equal(chip_flash_program(addr + 4U, data, 4U), SQ_EINVAL);
	assert_int_equal(regsim_flash_mem[4], 0xFFU);
	flash_sr_hw = FLASH_SR_PROGERR; /* left from before: cleared first */
	flash_sr_cell = flash_sr_hw;
	assert_int_equal(chip_flash_program(addr, data, 8U), SQ_OK); /* cleared first */
}

/* FDCAN1 on PA11/PA12, FDCAN2 on PB12/PB13: AF9, alternate mode, pull-up
 * on RX; no port clock that reads back: pins untouched. */
static void test_can_pins(void **state)
{
	(void)state;
	chip_can_pins_init(0U);
	assert_true((RCC_APB1ENR1 & (1U << 25)) != 0U);
	assert_int_equal((GPIO_AFRH(GPIOA_BASE) >> 12) & 0xFU, 9U); /* PA11 */
	assert_int_equal((GPIO_AFRH(GPIOA_BASE) >> 16) & 0xFU, 9U); /* PA12 */
	assert_int_equal((GPIO_MODER(GPIOA_BASE) >> 22) & 3U, 2U);
	assert_int_equal((GPIO_MODER(GPIOA_BASE) >> 24) & 3U, 2U);
	assert_int_equal((GPIO_PUPDR(GPIOA_BASE) >> 22) & 3U, 1U);
	assert_int_equal((GPIO_PUPDR(GPIOA_BASE) >> 24) & 3U, 0U);
	chip_can_pins_init(1U);
	assert_int_equal((GPIO_AFRH(GPIOB_BASE) >> 16) & 0xFU, 9U); /* PB12 */
	assert_int_equal((GPIO_AFRH(GPIOB_BASE) >> 20) & 0xFU, 9U); /* PB13 */
	assert_int_equal((GPIO_MODER(GPIOB_BASE) >> 24) & 3U, 2U);
	setup(NULL);
	chip_can_pins_init(2U); /* no such bus: nothing */
	assert_int_equal(RCC_AHB2ENR, 0U);
}

/* RM0440 3.3 (error code correction): the NMI of an ECC double error in
 * the calibration pages is claimed (ECCD cleared with ECCIE kept, counted),
 * any other NMI is not: one in the code's bank, in system flash, or no
 * ECCD at all (the clock security system). ADDR_ECC counts in its bank
 * with DBANK 1 (bank 2 from 0x08040000), in the whole flash with DBANK 0. */
static void test_nmi_flash_ecc_claims_calibration_only(void **state)
{
	static const struct {
		bool dual_bank;
		uint32_t eccr;
		bool claimed;
	} cases[] = {
		{ true, (1U << 31) | (1U << 21) | 0x3E000U, true },  /* 0x0807E000: slot 0 */
		{ true, (1U << 31) | (1U << 21) | 0x3FFF8U, true },  /* the last double word of slot 1 */
		{ true, (1U << 31) | 0x3E000U, false },              /* 0x0803E000: code in bank 1 */
		{ true, (1U << 31) | (1U << 21) | 0x3D000U, false }, /* below the slots */
		{ false, (1U << 31) | 0x7E008U, true },              /* one bank: 0x0807E008 */
		{ false, (1U << 31) | 0x3E000U, false },
		{ true, (1U << 31) | (1U << 22) | (1U << 21) | 0x3E000U, false }, /* system flash */
		{ true, (1U << 21) | 0x3E000U, false },              /* no ECCD: CSS */
	};
	size_t i;
	uint8_t b[8];

	(void)state;
	for (i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
		FLASH_OPTR = cases[i].dual_bank ? (FLASH_OPTR | (1U << 22)) : (FLASH_OPTR & ~(1U << 22));
		FLASH_ECCR = cases[i].eccr | (1U << 24); /* ECCIE on */
		assert_int_equal(chip_nmi_flash_ecc(), cases[i].claimed);
		if (cases[i].claimed) {
			assert_int_equal(FLASH_ECCR, (1U << 31) | (1U << 24));
		} else {
			assert_int_equal(FLASH_ECCR, cases[i].eccr | (1U << 24)); /* left for the record */
		}
	}
	/* chip_flash_read: SQ_EIO when its read took such an NMI */
	FLASH_OPTR |= 1U << 22;
	memset(regsim_flash_mem, 0x11, 16U);
	assert_int_equal(chip_flash_read((uint32_t)(uintptr_t)__calib_start, b, 8U), SQ_OK);
	assert_int_equal(b[7], 0x11U);
	ecc_broken[1] = true;
	assert_int_equal(chip_flash_read((uint32_t)(uintptr_t)__calib_start + 4U, b, 8U), SQ_EIO);
	assert_int_equal(nmi_count, 4U); /* bytes 8..11 */
	assert_int_equal(nmi_fault_path, 0U);
	assert_int_equal(chip_flash_read((uint32_t)(uintptr_t)__calib_start, b, 8U), SQ_OK);
}

static uint32_t faults_raised;
void stm32_fault_raise(uint32_t hal_fault_bits)
{
	faults_raised |= hal_fault_bits;
}

/*
 * hal_calib_write (hal/stm32f4/calib_flash.c) on chip_g4.c's double-word
 * programming and 2 KiB pages (DBANK 1), the power cut in every one of its
 * flash operations in turn (both page erases, every double word of the
 * payload, the header's second double word, the magic's): the next boot
 * reads the old block if the cut came before the end, the new one after,
 * never a mix, never nothing; an ECC double error met on the way is
 * claimed by the chip's NMI (no fault reset), counted, and its slot treated
 * as corrupt; the next write reuses that slot and succeeds.
 */
static void test_calib_power_cut_every_double_word(void **state)
{
	static uint8_t flash_a[sizeof(regsim_flash_mem)];
	uint8_t a[200];
	uint8_t b[200];
	uint8_t c[200];
	uint8_t out[200];
	long cut;
	bool done = false;
	volatile uint32_t ecc_cuts = 0U;

	(void)state;
	calib_pattern_fill(a, sizeof(a), 1U);
	calib_pattern_fill(b, sizeof(b), 101U);
	calib_pattern_fill(c, sizeof(c), 201U);
	assert_int_equal(hal_calib_write(a, sizeof(a)), SQ_OK);
	assert_int_equal(hal_calib_read(out, sizeof(out)), SQ_OK);
	assert_memory_equal(out, a, sizeof(a));
	memcpy(flash_a, regsim_flash_mem, sizeof(flash_a));
	for (cut = 0; !done; cut++) {
		volatile bool finished = false;
		const uint32_t rejects0 = stm32_calib_ecc_rejects();

		assert_true(cut < 64);
		memcpy(regsim_flash_mem, flash_a, sizeof(flash_a));
		memcpy(shadow, flash_a, sizeof(shadow));
		memset(ecc_broken, 0, sizeof(ecc_broken));
		nmi_count = 0U;
		power_ops = cut;
		if (setjmp(power_cut) == 0) {
			assert_int_equal(hal_calib_write(b, sizeof(b)), SQ_OK);
			finished = true;
		}
		power_ops = -1;
		/* the next boot: the flash locked again, the cache as at reset */
		flash_cr = FLASH_CR_LOCK;
		keys_seen = 0U;
		flash_sr_hw = 0U;
		flash_sr_cell = 0U;
		assert_int_equal(hal_calib_read(out, sizeof(out)), SQ_OK);
		assert_memory_equal(out, finished ? b : a, sizeof(a));
		assert_int_equal(nmi_fault_path, 0U);
		if (nmi_count > 0U) {
			ecc_cuts++;
			assert_true(stm32_calib_ecc_rejects() > rejects0);
		}
		/* the slot the cut spoilt is erased and written again */
		assert_int_equal(hal_calib_write(c, sizeof(c)), SQ_OK);
		assert_int_equal(hal_calib_read(out, sizeof(out)), SQ_OK);
		assert_memory_equal(out, c, sizeof(c));
		assert_int_equal(nmi_fault_path, 0U);
		done = finished;
	}
	/* 2 erases + 25 payload double words + 2 header double words, then
	 * the write that completes */
	assert_int_equal(cut, 30);
	/* the header page's erase and the magic's double word at least: their
	 * slot is read and met the error */
	assert_true(ecc_cuts >= 2U);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup(test_24mhz_crystal_runs_pll_at_170, setup),
		cmocka_unit_test_setup(test_wait_states_and_boost_before_the_rise, setup),
		cmocka_unit_test_setup(test_wrong_crystal_falls_back_to_hsi, setup),
		cmocka_unit_test_setup(test_tolerance_window, setup),
		cmocka_unit_test_setup(test_no_crystal, setup),
		cmocka_unit_test_setup(test_bor_level, setup),
		cmocka_unit_test_setup(test_reset_cause_decode, setup),
		cmocka_unit_test_setup(test_erase_dual_bank, setup),
		cmocka_unit_test_setup(test_erase_single_bank, setup),
		cmocka_unit_test_setup(test_erase_single_bank_last_page, setup),
		cmocka_unit_test_setup(test_erase_dual_bank_at_bank2_start, setup),
		cmocka_unit_test_setup(test_erase_dual_bank_slot_across_banks_refused, setup),
		cmocka_unit_test_setup(test_program_double_words, setup),
		cmocka_unit_test_setup(test_can_pins, setup),
		cmocka_unit_test_setup(test_nmi_flash_ecc_claims_calibration_only, setup),
		cmocka_unit_test_setup(test_calib_power_cut_every_double_word, setup),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
