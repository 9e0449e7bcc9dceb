/* SPDX-License-Identifier: MIT */
/*
 * STM32G474 parts of the shared bare-metal HAL (chip_api.h): clocks, BOR
 * level, CAN pins and the calibration flash, register by register from
 * RM0440. The generic files (startup, systick, iwdg, board, selftest,
 * calib_flash) are hal/stm32f4's.
 *
 * Clocks: the 24 MHz crystal is measured against the HSI16 (TIM17 capture
 * of HSE/32) before anything depends on it; a crystal outside +-10 % of
 * CHIP_HSE_HZ, a ready flag that never comes, or wait states that do not
 * read back leave the chip on the HSI16 (16 MHz core, APB1, FDCAN kernel
 * clock) and the caller reports HAL_FAULT_CLOCK_FALLBACK. Every wait is
 * bounded in real time (stm32_wait_reg), so a chip without this RCC (QEMU
 * runs the image on an F4 memory map) falls back instead of hanging.
 */
#include <stddef.h>

#include "chip.h"
#include "stm32_hse_meter.h"
#include "stm32_time.h"
#include "sq_status.h"

/* Bounds, DS12288 with margin: HSE start-up 2 ms typical (crystal
 * dependent), PLL lock 40 us, a clock switch a few cycles, VOSF 20 us. */
#define HSE_TIMEOUT_US    100000U
#define PLL_TIMEOUT_US      5000U
#define SWITCH_TIMEOUT_US   5000U
#define VOS_TIMEOUT_US      5000U
/* HSE measurement: HSE/32 into TIM17 CH1 (stm32_hse_meter.h); 16 captures
 * of 8 * 32 HSE periods (170.7 HSI16 ticks at 24 MHz: 2731 in all,
 * resolution 0.04 %). */
/* RM0440 6.1.5: the AHB prescaler stays at /2 for at least 1 us after the
 * switch to the boost frequency; 1 us = 85 cycles at 85 MHz, a loop
 * iteration takes at least one. */
#define BOOST_SETTLE_LOOPS 256U
/* DS12288: 2 KiB page erase max 24.5 ms, double word max 90.8 us */
#define ERASE_TIMEOUT_US   100000U
#define PROGRAM_TIMEOUT_US   1000U
#define PAGE_BYTES_DUAL_BANK   2048U
#define PAGE_BYTES_SINGLE_BANK 4096U
#define SLOT_PAGES_MAX 4U /* bound of the erase loop */

extern const uint8_t __calib_start[];
extern const uint8_t __calib_slot_size[];

/* the core and APB1 rates: chip_common.c (chip_clock_rates_set) */
static uint32_t fdcan_hz = CHIP_HSI_HZ;
static uint32_t hse_measured_hz;

/* The HSE in Hz, timed by TIM17 on the HSI16 (APB2 = 16 MHz now); 0 if no
 * edge comes. HSE/32 reaches TI1 through TISEL 0011 once TIM17_OR1 HSE32EN
 * requests it (RM0440 TIM15/TIM16/TIM17 chapter: TIMx_TISEL, TIMx_OR1). */
static uint32_t hse_measure(void)
{
	uint32_t hz;

	RCC_APB2ENR |= RCC_APB2ENR_TIM17EN;
	(void)RCC_APB2ENR; /* read back: the enable needs two cycles */
	TIM17_OR1 = TIM17_OR1_HSE32EN;
	TIM17_TISEL = TIM17_TISEL_TI1_HSE_32;
	hz = stm32_hse_meter_run(TIM17_BASE, CHIP_HSE_RTC_DIV, CHIP_HSI_HZ);
	TIM17_OR1 = 0U;
	RCC_APB2ENR &= ~RCC_APB2ENR_TIM17EN;
	return hz;
}

uint32_t chip_hse_measured_hz(void)
{
	return hse_measured_hz;
}

/*
 * chip_api.h's scale (3 = the level the board needs ... 0 = no brown-out
 * reset above the power-down reset): BOR_LEV 100 (2.8 V, the nearest to the
 * F4's 2.7 V; the 3.3 V rail and its CAN transceiver are out of their
 * range below it) = 3, 011 (2.5 V) = 2, 010 (2.2 V) = 1, 001 (2.0 V) and
 * 000 (1.7 V, BOR0 = the power-down reset itself) = 0; 101..111 are
 * reserved (RM0440 3.7, FLASH_OPTR) and read as 0, not protected.
 */
uint32_t chip_bor_level(void)
{
	static const uint8_t level[8] = { 0U, 0U, 1U, 2U, 3U, 0U, 0U, 0U };

	return level[(FLASH_OPTR & FLASH_OPTR_BOR_LEV_MSK) >> FLASH_OPTR_BOR_LEV_SHIFT];
}

/* Back on the HSI16 from wherever the start-up stopped: the switch first,
 * then the wait states down (RM0440 3.3.3: lower them only after the
 * frequency), range 1 normal mode again (R1MODE 1), FDCAN on PCLK1. */
static void g4_clock_back_to_hsi(void)
{
	RCC_CFGR = (RCC_CFGR & ~(RCC_CFGR_SW_MSK | RCC_CFGR_HPRE_MSK | RCC_CFGR_PPRE1_MSK |
				 RCC_CFGR_PPRE2_MSK)) | RCC_CFGR_SW_HSI;
	(void)stm32_wait_reg(&RCC_CFGR, RCC_CFGR_SWS_MSK, RCC_CFGR_SWS_HSI, SWITCH_TIMEOUT_US);
	RCC_CR &= ~(RCC_CR_CSSON | RCC_CR_PLLON | RCC_CR_HSEON);
	FLASH_ACR = FLASH_ACR_PRFTEN | FLASH_ACR_ICEN | FLASH_ACR_DCEN; /* 0 WS at 16 MHz */
	PWR_CR5 |= PWR_CR5_R1MODE;
	RCC_CCIPR = (RCC_CCIPR & ~RCC_CCIPR_FDCANSEL_MSK) | RCC_CCIPR_FDCANSEL_PCLK1;
	chip_clock_rates_set(false);
	fdcan_hz = CHIP_HSI_HZ;
}

static int g4_fail(void)
{
	g4_clock_back_to_hsi();
	return SQ_EAGAIN;
}

int chip_clock_init(void)
{
	uint32_t i;

	chip_clock_rates_set(false);
	fdcan_hz = CHIP_HSI_HZ;
	hse_measured_hz = 0U;
	stm32_time_early_init(CHIP_HSI_HZ);

	/* A crystal (HSEBYP 0): NUCLEO-G474RE's X3 or the board's own. */
	RCC_CR = (RCC_CR & ~RCC_CR_HSEBYP) | RCC_CR_HSEON;
	if (stm32_wait_reg(&RCC_CR, RCC_CR_HSERDY, RCC_CR_HSERDY, HSE_TIMEOUT_US) != SQ_OK) {
		return g4_fail();
	}
	hse_measured_hz = hse_measure();
	if (!stm32_hse_in_tolerance(hse_measured_hz, CHIP_HSE_HZ)) {
		return g4_fail();
	}
	/* Range 1 (the reset value, kept), boost mode: R1MODE 0 while the
	 * core still runs at 16 MHz (RM0440 6.1.5), then VOSF clear. */
	RCC_APB1ENR1 |= RCC_APB1ENR1_PWREN;
	(void)RCC_APB1ENR1;
	PWR_CR1 = (PWR_CR1 & ~PWR_CR1_VOS_MSK) | PWR_CR1_VOS_RANGE1;
	PWR_CR5 &= ~PWR_CR5_R1MODE;
	if (stm32_wait_reg(&PWR_SR2, PWR_SR2_VOSF, 0U, VOS_TIMEOUT_US) != SQ_OK) {
		return g4_fail();
	}
	/* PLL (RM0440 7.4, RCC_PLLCFGR): written while off; only R enabled. */
	RCC_PLLCFGR = RCC_PLLCFGR_PLLSRC_HSE | ((CHIP_PLL_M - 1U) << RCC_PLLCFGR_PLLM_SHIFT) |
		      (CHIP_PLL_N << RCC_PLLCFGR_PLLN_SHIFT) |
		      (((CHIP_PLL_R / 2U) - 1U) << RCC_PLLCFGR_PLLR_SHIFT) | RCC_PLLCFGR_PLLREN;
	RCC_CR |= RCC_CR_PLLON;
	if (stm32_wait_reg(&RCC_CR, RCC_CR_PLLRDY, RCC_CR_PLLRDY, PLL_TIMEOUT_US) != SQ_OK) {
		return g4_fail();
	}
	/* Wait states before the frequency rises, checked by reading back
	 * (RM0440 3.3.3, wait states per HCLK: 4 WS up to 170 MHz in boost mode). */
	FLASH_ACR = FLASH_ACR_LATENCY_4WS | FLASH_ACR_PRFTEN | FLASH_ACR_ICEN | FLASH_ACR_DCEN;
	if ((FLASH_ACR & FLASH_ACR_LATENCY_MSK) != FLASH_ACR_LATENCY_4WS) {
		return g4_fail();
	}
	/* RM0440 6.1.5: into boost frequency through AHB /2, 1 us, then /1. */
	RCC_CFGR = (RCC_CFGR & ~(RCC_CFGR_HPRE_MSK | RCC_CFGR_PPRE1_MSK | RCC_CFGR_PPRE2_MSK)) |
		   RCC_CFGR_HPRE_DIV2;
	RCC_CFGR = (RCC_CFGR & ~RCC_CFGR_SW_MSK) | RCC_CFGR_SW_PLL;
	if (stm32_wait_reg(&RCC_CFGR, RCC_CFGR_SWS_MSK, RCC_CFGR_SWS_PLL, SWITCH_TIMEOUT_US) != SQ_OK) {
		return g4_fail();
	}
	for (i = 0U; i < BOOST_SETTLE_LOOPS; i++) {
		(void)RCC_CFGR;
	}
	RCC_CFGR &= ~RCC_CFGR_HPRE_MSK;
	/* FDCAN kernel clock: the crystal (RM0440 7.4, RCC_CCIPR FDCANSEL). */
	RCC_CCIPR = (RCC_CCIPR & ~RCC_CCIPR_FDCANSEL_MSK) | RCC_CCIPR_FDCANSEL_HSE;
	/* A crystal that stops from now on: NMI (startup.c records it). */
	RCC_CR |= RCC_CR_CSSON;
	chip_clock_rates_set(true);
	fdcan_hz = CHIP_HSE_HZ;
	return SQ_OK;
}

uint32_t chip_fdcan_kernel_hz(void)
{
	return fdcan_hz;
}

/* ---- CAN pins (DS12288 alternate functions, AF9) ---------------------------------- */

typedef struct {
	uintptr_t port;
	uint32_t port_en;
	uint8_t rx_pin;
	uint8_t tx_pin;
} can_pins_t;

/* FDCAN1 on PA11 RX / PA12 TX by default: PB8 is also BOOT0 (RM0440 2.6, boot configuration),
 * and a transceiver's recessive RX output on it at reset would boot the
 * system bootloader unless the option bit nSWBOOT0 is cleared; boards that
 * have done so may build with -DSQ_FDCAN1_PINS_PB8_PB9. FDCAN2: PB12 RX,
 * PB13 TX. */
static const can_pins_t can_pins[CHIP_CAN_BUSES] = {
#if defined(SQ_FDCAN1_PINS_PB8_PB9)
	{ GPIOB_BASE, RCC_AHB2ENR_GPIOBEN, 8U, 9U },
#else
	{ GPIOA_BASE, RCC_AHB2ENR_GPIOAEN, 11U, 12U },
#endif
	{ GPIOB_BASE, RCC_AHB2ENR_GPIOBEN, 12U, 13U },
};

static void field_set(uintptr_t reg_addr, uint32_t shift, uint32_t width_mask, uint32_t value)
{
	uint32_t v = REG32(reg_addr) & ~(width_mask << shift);

	REG32(reg_addr) = v | (value << shift);
}

static void pin_af9(uintptr_t port, uint32_t pin, bool pull_up)
{
	uintptr_t afr = (uintptr_t)&GPIO_AFRL(port) + (pin >= 8U ? 4U : 0U);

	field_set(afr, 4U * (pin & 7U), 0xFU, GPIO_AF9_FDCAN);
	field_set((uintptr_t)&GPIO_OSPEEDR(port), 2U * pin, 3U, GPIO_SPEED_HIGH);
	field_set((uintptr_t)&GPIO_OTYPER(port), pin, 1U, 0U);
	field_set((uintptr_t)&GPIO_PUPDR(port), 2U * pin, 3U, pull_up ? GPIO_PUPD_UP : 0U);
	field_set((uintptr_t)&GPIO_MODER(port), 2U * pin, 3U, GPIO_MODE_AF);
}

/* The port and FDCAN clocks (one FDCANEN for all three, RM0440 7.4 RCC_APB1ENR1);
 * the port is touched only once its enable reads back set: a part without
 * this RCC (QEMU's F4 map has no GPIO at 0x48000000) leaves the pins
 * alone, and the driver then finds its controller not answering. */
void chip_can_pins_init(uint8_t bus)
{
	const can_pins_t *p;

	if (bus >= CHIP_CAN_BUSES) {
		return;
	}
	p = &can_pins[bus];
	RCC_AHB2ENR |= p->port_en;
	RCC_APB1ENR1 |= RCC_APB1ENR1_FDCANEN;
	if ((RCC_AHB2ENR & p->port_en) == 0U) {
		return;
	}
	pin_af9(p->port, p->rx_pin, true);
	pin_af9(p->port, p->tx_pin, false);
}

/* ---- calibration flash (RM0440 3.3, program and erase) ---------------------------- */

static uint32_t saved_acr;

/* Also turns the data cache off for the operation (verify reads come from
 * the array) and resets it afterwards: with DBANK 1 the calibration pages
 * are in bank 2 while the code runs from bank 1 (read-while-write), where
 * ES0430 "data cache might be corrupted during Flash memory read-while-write
 * operation" asks for exactly that. */
static int g4_flash_unlock(void)
{
	saved_acr = FLASH_ACR;
	FLASH_ACR = saved_acr & ~FLASH_ACR_DCEN;
	/* the key sequence and the bounded wait (chip_common.c) on the G4's
	 * FLASH_KEYR/SR/CR; it clears the error flags too: one left from
	 * before makes PGSERR (RM0440 3.3, programming) */
	return chip_flash_unlock();
}

/* ECC double errors in the calibration pages since start (the NMI) */
static volatile uint32_t calib_ecc_errors;

static bool in_calibration(uint32_t addr)
{
	const uint32_t start = (uint32_t)(uintptr_t)__calib_start;

	return (addr >= start) && ((addr - start) < 2U * (uint32_t)(uintptr_t)__calib_slot_size);
}

/* RM0440 3.3 (error code correction): a double error sets ECCD and raises
 * the NMI; ADDR_ECC is the double word's offset in its bank (BK_ECC) with
 * DBANK 1, in the whole flash with DBANK 0. */
bool chip_nmi_flash_ecc(void)
{
	const uint32_t eccr = FLASH_ECCR;
	const bool dual_bank = (FLASH_OPTR & FLASH_OPTR_DBANK) != 0U;
	const uint32_t base = (dual_bank && ((eccr & FLASH_ECCR_BK_ECC) != 0U)) ? CHIP_FLASH_BANK2 :
										  CHIP_FLASH_BASE;
	bool ours = false;

	if (((eccr & FLASH_ECCR_ECCD) != 0U) && ((eccr & FLASH_ECCR_SYSF_ECC) == 0U) &&
	    in_calibration(base + (eccr & FLASH_ECCR_ADDR_ECC_MSK))) {
		FLASH_ECCR = (eccr & FLASH_ECCR_ECCIE) | FLASH_ECCR_ECCD; /* write 1 to clear */
		calib_ecc_errors++;
		ours = true;
	}
	return ours;
}

int chip_flash_read(uint32_t addr, uint8_t *dst, uint32_t n)
{
	const uint32_t before = calib_ecc_errors;
	uint32_t i;

	for (i = 0U; i < n; i++) {
		dst[i] = CHIP_FLASH_LOAD8(addr + i); /* a double error: the NMI runs here */
	}
	return (calib_ecc_errors == before) ? SQ_OK : SQ_EIO;
}

static void g4_flash_lock_and_flush(void)
{
	uint32_t acr = saved_acr;

	FLASH_CR = FLASH_CR_LOCK;
	/* RM0440 3.3 (caches): the data cache is reset only while it is off */
	FLASH_ACR = acr & ~FLASH_ACR_DCEN;
	FLASH_ACR = (acr & ~FLASH_ACR_DCEN) | FLASH_ACR_DCRST;
	FLASH_ACR = acr;
}

static int g4_flash_wait_done(uint32_t timeout_us)
{
	if (chip_flash_wait_done(timeout_us) != SQ_OK) {
		return SQ_EIO;
	}
	FLASH_SR = FLASH_SR_EOP;
	return SQ_OK;
}

/* A slot is 1 (DBANK 0: 4 KiB pages) or 2 (DBANK 1: 2 KiB pages) pages,
 * erased first page (the slot header) first: a power cut after it leaves a
 * slot without a valid header, never a valid header over a half-erased
 * payload. Page numbers count from the start of the bank (RM0440 3.3.1, flash organisation). */
int chip_flash_erase_slot(uint32_t slot)
{
	const uint32_t size = (uint32_t)(uintptr_t)__calib_slot_size;
	const uint32_t addr = (uint32_t)(uintptr_t)__calib_start + slot * size;
	const bool dual_bank = (FLASH_OPTR & FLASH_OPTR_DBANK) != 0U;
	const uint32_t page_bytes = dual_bank ? PAGE_BYTES_DUAL_BANK : PAGE_BYTES_SINGLE_BANK;
	const uint32_t pages = size / page_bytes;
	uint32_t bank_base = CHIP_FLASH_BASE;
	uint32_t bker = 0U;
	uint32_t page;
	int rc = SQ_OK;

	if (dual_bank && addr >= CHIP_FLASH_BANK2) {
		bank_base = CHIP_FLASH_BANK2;
		bker = FLASH_CR_BKER;
	}
	if ((slot > 1U) || (pages == 0U) || (pages > SLOT_PAGES_MAX) || ((size % page_bytes) != 0U) ||
	    (addr < CHIP_FLASH_BASE) || ((addr - bank_base) / page_bytes + pages > 128U)) {
		return SQ_EINVAL;
	}
	if (g4_flash_unlock() != SQ_OK) {
		g4_flash_lock_and_flush();
		return SQ_EIO;
	}
	for (page = 0U; (page < pages) && (rc == SQ_OK); page++) {
		uint32_t pnb = (addr - bank_base) / page_bytes + page;

		FLASH_CR = FLASH_CR_PER | bker | (pnb << FLASH_CR_PNB_SHIFT);
		FLASH_CR |= FLASH_CR_STRT;
		rc = g4_flash_wait_done(ERASE_TIMEOUT_US);
	}
	g4_flash_lock_and_flush();
	return rc;
}

/*
 * RM0440 3.3 (programming): 64-bit double words, the lower word first, then the upper,
 * which starts the operation; each double word once after an erase (ECC).
 * addr double-word aligned; a tail shorter than 8 bytes is padded with 0xFF
 * (left erased-looking, never programmed twice: calib_flash.c splits its
 * writes on CHIP_FLASH_PROGRAM_BYTES).
 */
int chip_flash_program(uint32_t addr, const uint8_t *data, uint32_t len)
{
	uint32_t off;
	int rc = SQ_OK;

	if ((addr & (CHIP_FLASH_PROGRAM_BYTES - 1U)) != 0U || data == NULL) {
		return SQ_EINVAL;
	}
	if (g4_flash_unlock() != SQ_OK) {
		g4_flash_lock_and_flush();
		return SQ_EIO;
	}
	FLASH_CR = FLASH_CR_PG;
	for (off = 0; off < len && rc == SQ_OK; off += CHIP_FLASH_PROGRAM_BYTES) {
		uint32_t w[2] = { 0xFFFFFFFFUL, 0xFFFFFFFFUL };
		uint32_t k;

		for (k = 0; k < CHIP_FLASH_PROGRAM_BYTES && off + k < len; k++) {
			w[k / 4U] &= ~((uint32_t)0xFFU << (8U * (k & 3U)));
			w[k / 4U] |= (uint32_t)data[off + k] << (8U * (k & 3U));
		}
		REG32(addr + off) = w[0];
		REG32(addr + off + 4U) = w[1];
		cm_dsb();
		rc = g4_flash_wait_done(PROGRAM_TIMEOUT_US);
		if (rc == SQ_OK && (REG32(addr + off) != w[0] || REG32(addr + off + 4U) != w[1])) {
			rc = SQ_EIO;
		}
	}
	g4_flash_lock_and_flush();
	return rc;
}
