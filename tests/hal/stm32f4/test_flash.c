/* SPDX-License-Identifier: MIT */
/*
 * STM32F405 flash erase and program (hal/stm32f4/flash.c) on the host, its
 * registers in plain words behind a hook (tests/support/regsim/f4/chip.h,
 * REGSIM_F4_FLASH_HOOK). The simulated interface answers as RM0090 says:
 *   3.5.1  FLASH_CR is locked out of reset (LOCK = 1, reset value
 *          0x80000000, 3.8.5); KEY1 = 0x45670123 then KEY2 = 0xCDEF89AB
 *          unlocks it; any other sequence locks it until the next reset; a
 *          store to FLASH_CR while locked is ignored.
 *   3.8.4  FLASH_SR: EOP, OPERR, WRPERR, PGAERR, PGPERR, PGSERR are cleared
 *          by writing 1 (a 0 leaves them); BSY is read-only.
 *   3.5.3  sector erase: SER with SNB = the sector, then STRT; BSY until done.
 *   3.5.4  programming: PG, then one store per word (PSIZE x32 at 2.7..3.6 V,
 *          3.5.2 Table 13); a store turns bits from 1 to 0 only.
 *   3.4.1  wait states (Table 10): at 2.7..3.6 V one more per 30 MHz of
 *          HCLK, 5 WS for 150..168 MHz.
 *   3.4.2  the data cache is reset with DCRST only while DCEN = 0.
 * The waits are bounded by the datasheet's maxima (DS8626, flash memory
 * programming): a 32-bit word 100 us, a 16 KiB sector (x32) 500 ms. The
 * slots are sectors 1 and 2 (linker/stm32f405xg.ld: __calib_first_sector = 1,
 * given to the link by mk/hal-stm32-regs.mk); without PIE the simulated
 * array lies below 4 GiB, so its address is a 32-bit flash address.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "chip.h"
#include "chip_api.h"
#include "flash_rm0090.h" /* RM0090: FLASH_CR, FLASH_SR bits, the keys */
#include "sq_status.h"
#include "stm32_time.h"

#define RM_ACR_LATENCY(acr) ((acr) & 7U) /* RM0090 3.8.1 */
#define RM_ACR_PRFTEN (1U << 8)
#define RM_ACR_ICEN (1U << 9)
#define RM_ACR_DCEN (1U << 10)
#define RM_ACR_DCRST (1U << 12)
#define DS_WORD_PROGRAM_MAX_US 100U     /* DS8626: t_PROG, x32 */
#define DS_ERASE_16K_MAX_US 500000U     /* DS8626: t_ERASE16KB, x32 */
#define WAIT_CEILING_US 10000000U       /* "bounded": well under the IWDG's reach */
#define FIRST_SECTOR 1U
#define NOR_WORDS 8U
#define LOG_MAX 16U

enum op { OP_NONE, OP_ERASE, OP_PROGRAM };

static struct {
	uint32_t acr, sr, cr;           /* what the interface holds */
	struct regsim_flash_keys k;     /* RM0090 3.5.1's key sequence */
	uint32_t keys[LOG_MAX];         /* every store to FLASH_KEYR, in order */
	unsigned n_keys;
	uint32_t sr_stores[LOG_MAX];
	unsigned n_sr_stores;
	unsigned ignored_cr_stores;     /* while locked */
	unsigned dcache_resets, dcrst_with_dcen;
	enum op busy;
	uint32_t cr_at_start, acr_at_start;
	unsigned erases, words_programmed, program_faults;
	uint32_t erased_sector;
	uint32_t wait_timeout_us[LOG_MAX];
	unsigned waits;
	int stuck_wait;                 /* BSY never clears in this wait (-1: none) */
	uint32_t end_error;             /* SR flag the next operation ends with */
} sim;

/* The flash array the driver programs; nor_hw is what the cells really hold. */
static uint32_t nor[NOR_WORDS], nor_hw[NOR_WORDS];

static void key_store(uint32_t key)
{
	if (sim.n_keys < LOG_MAX) {
		sim.keys[sim.n_keys++] = key;
	}
	regsim_flash_key_store(&sim.k, &sim.cr, key);
}

static void cr_store(uint32_t v)
{
	if ((sim.cr & RM_CR_LOCK) != 0U) {
		sim.ignored_cr_stores++;
		return;
	}
	sim.cr = v;
	if ((v & RM_CR_STRT) != 0U) {
		sim.cr_at_start = v;
		sim.acr_at_start = sim.acr;
		if ((v & RM_CR_SER) != 0U && (v & RM_CR_PG) == 0U) {
			sim.busy = OP_ERASE;
			sim.sr |= RM_SR_BSY;
		} else {
			sim.sr |= RM_SR_PGSERR;
		}
	}
}

static void acr_store(uint32_t v)
{
	if ((v & RM_ACR_DCRST) != 0U) {
		if ((v & RM_ACR_DCEN) != 0U) {
			sim.dcrst_with_dcen++;
		} else {
			sim.dcache_resets++;
		}
	}
	sim.acr = v;
}

static void nor_store(uint32_t i)
{
	bool configured = (sim.cr & (RM_CR_LOCK | RM_CR_PG | RM_CR_SER)) == RM_CR_PG &&
			  RM_CR_PSIZE(sim.cr) == 2U;

	if (configured) {
		nor_hw[i] &= nor[i]; /* 1 -> 0 only */
		sim.acr_at_start = sim.acr;
		sim.cr_at_start = sim.cr;
		sim.busy = OP_PROGRAM;
		sim.sr |= RM_SR_BSY;
	} else {
		sim.program_faults++;
		sim.sr |= RM_SR_PGSERR;
	}
	nor[i] = nor_hw[i];
}

/* Plays the stores since the last access; a store of exactly the value a
 * register already shows cannot be told from no store (the tests avoid it). */
static void flash_sync(void)
{
	/* compare with what the registers showed, before any store is played */
	bool sr_stored = regsim_flash[3] != sim.sr, cr_stored = regsim_flash[4] != sim.cr,
	     acr_stored = regsim_flash[0] != sim.acr;
	uint32_t i;

	if (regsim_flash[1] != 0U) {
		key_store(regsim_flash[1]);
	}
	if (sr_stored) {
		if (sim.n_sr_stores < LOG_MAX) {
			sim.sr_stores[sim.n_sr_stores++] = regsim_flash[3];
		}
		sim.sr &= ~(regsim_flash[3] & RM_SR_W1C);
	}
	if (cr_stored) {
		cr_store(regsim_flash[4]);
	}
	if (acr_stored) {
		acr_store(regsim_flash[0]);
	}
	for (i = 0; i < NOR_WORDS; i++) {
		if (nor[i] != nor_hw[i]) {
			nor_store(i);
		}
	}
	regsim_flash[0] = sim.acr;
	regsim_flash[1] = 0U; /* FLASH_KEYR reads 0 */
	regsim_flash[3] = sim.sr;
	regsim_flash[4] = sim.cr;
}

volatile uint32_t *regsim_flash_reg(uint32_t offset)
{
	flash_sync();
	return &regsim_flash[offset / 4U];
}

void cm_dsb(void)
{
	flash_sync();
}

/* One poll of a bounded wait: the operation under way ends here, unless this
 * is the wait the test keeps busy (then the wait times out, as systick.c's). */
int stm32_wait_reg(volatile const uint32_t *reg, uint32_t mask, uint32_t value, uint32_t timeout_us)
{
	unsigned n = sim.waits++;

	flash_sync();
	if (n < LOG_MAX) {
		sim.wait_timeout_us[n] = timeout_us;
	}
	if ((int)n == sim.stuck_wait) {
		sim.sr |= RM_SR_BSY;
	} else if (sim.busy != OP_NONE) {
		if (sim.busy == OP_ERASE) {
			sim.erases++;
			sim.erased_sector = RM_CR_SNB(sim.cr);
		} else {
			sim.words_programmed++;
		}
		sim.busy = OP_NONE;
		sim.sr = (sim.sr & ~RM_SR_BSY) | sim.end_error;
		sim.cr &= ~RM_CR_STRT;
		sim.end_error = 0U;
	}
	regsim_flash[3] = sim.sr;
	regsim_flash[4] = sim.cr;
	return ((*reg & mask) == value) ? SQ_OK : SQ_EAGAIN;
}

static void sim_reset(uint32_t acr)
{
	memset(&sim, 0, sizeof(sim));
	sim.cr = RM_CR_RESET;
	sim.acr = acr;
	sim.stuck_wait = -1;
	memset(nor, 0xFF, sizeof(nor));
	memset(nor_hw, 0xFF, sizeof(nor_hw));
	regsim_f4_reset();
	regsim_flash[0] = sim.acr;
	regsim_flash[3] = sim.sr;
	regsim_flash[4] = sim.cr;
}

#define BOARD_ACR (5U | RM_ACR_PRFTEN | RM_ACR_ICEN | RM_ACR_DCEN) /* clock.c at 168 MHz */

static int setup(void **state)
{
	(void)state;
	sim_reset(BOARD_ACR);
	return 0;
}

static uint32_t nor_addr(uint32_t word)
{
	uintptr_t a = (uintptr_t)&nor[word];

	assert_true(a <= UINT32_MAX);
	return (uint32_t)a;
}

/* After every operation, good or failed: locked again, the cache as before. */
static void assert_locked_and_acr(uint32_t acr)
{
	flash_sync(); /* the driver's last store */
	assert_true((sim.cr & RM_CR_LOCK) != 0U);
	assert_int_equal(sim.acr, acr);
}

static void test_unlock_key1_then_key2(void **state)
{
	(void)state;
	assert_int_equal(chip_flash_erase_slot(0U), SQ_OK);
	assert_int_equal(sim.n_keys, 2U);
	assert_int_equal(sim.keys[0], RM_KEY1);
	assert_int_equal(sim.keys[1], RM_KEY2);
	assert_false(sim.k.locked_until_reset);
	assert_int_equal(sim.ignored_cr_stores, 0U);
	assert_int_equal(sim.erases, 1U);
	assert_locked_and_acr(BOARD_ACR);
}

/* The simulation holds RM0090's rule (KEY2 first, or KEY1 twice, locks until
 * reset); the driver, finding FLASH_CR still locked, starts nothing. */
static void test_wrong_key_sequence_locks_until_reset(void **state)
{
	static const uint32_t wrong[][2] = { { RM_KEY2, RM_KEY1 }, { RM_KEY1, RM_KEY1 }, { RM_KEY1, 0x12345678U } };
	uint32_t i;

	(void)state;
	for (i = 0; i < sizeof(wrong) / sizeof(wrong[0]); i++) {
		sim_reset(BOARD_ACR);
		FLASH_KEYR = wrong[i][0];
		FLASH_KEYR = wrong[i][1];
		assert_true((FLASH_CR & RM_CR_LOCK) != 0U);
		assert_true(sim.k.locked_until_reset);
		assert_int_equal(chip_flash_erase_slot(0U), SQ_EIO);
		assert_int_equal(chip_flash_program(nor_addr(0U), (const uint8_t *)"\x00\x00\x00\x00", 4U), SQ_EIO);
		assert_int_equal(sim.erases, 0U);
		assert_int_equal(sim.words_programmed, 0U);
		assert_int_equal(nor[0], 0xFFFFFFFFU);
		assert_int_equal(sim.cr, RM_CR_RESET);
		assert_locked_and_acr(BOARD_ACR);
	}
}

static void test_stale_error_flags_cleared_by_writing_one(void **state)
{
	static const uint32_t stale[] = { RM_SR_PGSERR | RM_SR_PGPERR, RM_SR_WRPERR | RM_SR_EOP, RM_SR_OPERR | RM_SR_PGAERR };
	uint32_t i;

	(void)state;
	for (i = 0; i < sizeof(stale) / sizeof(stale[0]); i++) {
		sim_reset(BOARD_ACR);
		sim.sr = stale[i];
		regsim_flash[3] = sim.sr;
		assert_int_equal(chip_flash_erase_slot(1U), SQ_OK);
		assert_int_equal(sim.n_sr_stores, 1U);
		assert_int_equal(sim.sr_stores[0] & stale[i], stale[i]);
		assert_int_equal(sim.sr & RM_SR_W1C, 0U);

		sim.sr = stale[i];
		regsim_flash[3] = sim.sr;
		assert_int_equal(chip_flash_program(nor_addr(0U), (const uint8_t *)"\x01\x02\x03\x04", 4U), SQ_OK);
		assert_int_equal(sim.sr & RM_SR_W1C, 0U);
	}
	/* a 0 leaves a flag: the write is 1-to-clear, not a plain store */
	sim_reset(BOARD_ACR);
	sim.sr = RM_SR_PGSERR;
	regsim_flash[3] = sim.sr;
	FLASH_SR = RM_SR_EOP;
	assert_int_equal(FLASH_SR, RM_SR_PGSERR);
}

static void test_sector_erase_sequence(void **state)
{
	uint32_t slot;

	(void)state;
	for (slot = 0; slot < 2U; slot++) {
		sim_reset(BOARD_ACR);
		assert_int_equal(chip_flash_erase_slot(slot), SQ_OK);
		assert_int_equal(sim.erases, 1U);
		assert_int_equal(sim.erased_sector, FIRST_SECTOR + slot);
		assert_int_equal(sim.cr_at_start & (RM_CR_SER | RM_CR_PG | RM_CR_STRT), RM_CR_SER | RM_CR_STRT);
		assert_int_equal(RM_CR_SNB(sim.cr_at_start), FIRST_SECTOR + slot);
		assert_int_equal(RM_CR_PSIZE(sim.cr_at_start), 2U);
		assert_int_equal(sim.acr_at_start & RM_ACR_DCEN, 0U);
		assert_int_equal(sim.waits, 2U); /* not busy before, then the erase */
		assert_locked_and_acr(BOARD_ACR);
	}
	/* a third slot is no slot: nothing is touched */
	sim_reset(BOARD_ACR);
	assert_int_equal(chip_flash_erase_slot(2U), SQ_EINVAL);
	assert_int_equal(sim.n_keys, 0U);
	assert_int_equal(sim.waits, 0U);
}

static void test_erase_error_flag_fails(void **state)
{
	static const uint32_t errors[] = { RM_SR_WRPERR, RM_SR_OPERR, RM_SR_PGSERR };
	uint32_t i;

	(void)state;
	for (i = 0; i < sizeof(errors) / sizeof(errors[0]); i++) {
		sim_reset(BOARD_ACR);
		sim.end_error = errors[i];
		assert_int_equal(chip_flash_erase_slot(0U), SQ_EIO);
		assert_locked_and_acr(BOARD_ACR);
	}
}

/* Words little-endian, one store and one wait per word, the tail padded with
 * 0xFF (erased flash: the padding changes nothing there). */
static void test_program_sequence(void **state)
{
	static const uint8_t data[10] = { 0x11, 0x22, 0x33, 0x44, 0x55, 0x66, 0x77, 0x08, 0x09, 0x0A };

	(void)state;
	assert_int_equal(chip_flash_program(nor_addr(1U), data, (uint32_t)sizeof(data)), SQ_OK);
	assert_int_equal(nor[0], 0xFFFFFFFFU);
	assert_int_equal(nor[1], 0x44332211U);
	assert_int_equal(nor[2], 0x08776655U);
	assert_int_equal(nor[3], 0xFFFF0A09U);
	assert_int_equal(nor[4], 0xFFFFFFFFU);
	assert_int_equal(sim.words_programmed, 3U);
	assert_int_equal(sim.waits, 4U);
	assert_int_equal(sim.program_faults, 0U);
	assert_int_equal(sim.cr_at_start & (RM_CR_SER | RM_CR_PG), RM_CR_PG);
	assert_int_equal(RM_CR_PSIZE(sim.cr_at_start), 2U);
	assert_int_equal(sim.acr_at_start & RM_ACR_DCEN, 0U);
	assert_locked_and_acr(BOARD_ACR);
}

/* A word not erased keeps its 0 bits: the read-back differs, the driver says so. */
static void test_program_over_zero_bits_fails_verify(void **state)
{
	(void)state;
	nor[0] = nor_hw[0] = 0x0000FFFFU;
	assert_int_equal(chip_flash_program(nor_addr(0U), (const uint8_t *)"\x34\x12\x78\x56", 4U), SQ_EIO);
	assert_int_equal(nor[0], 0x00001234U);
	assert_locked_and_acr(BOARD_ACR);
}

static void test_program_error_flag_fails(void **state)
{
	(void)state;
	sim.end_error = RM_SR_PGPERR;
	assert_int_equal(chip_flash_program(nor_addr(0U), (const uint8_t *)"\x01\x02\x03\x04\x05\x06\x07\x08", 8U), SQ_EIO);
	assert_int_equal(sim.words_programmed, 1U); /* stops at the failed word */
	assert_int_equal(nor[1], 0xFFFFFFFFU);
	assert_locked_and_acr(BOARD_ACR);
}

static void test_program_bad_arguments_touch_nothing(void **state)
{
	(void)state;
	assert_int_equal(chip_flash_program(nor_addr(0U) + 2U, (const uint8_t *)"\x00\x00", 2U), SQ_EINVAL);
	assert_int_equal(chip_flash_program(nor_addr(0U), NULL, 4U), SQ_EINVAL);
	assert_int_equal(sim.n_keys, 0U);
	assert_int_equal(sim.waits, 0U);
	assert_int_equal(nor[0], 0xFFFFFFFFU);
}

/* RM0090 3.4.1 Table 10, 2.7..3.6 V: the highest HCLK for each wait state. */
static const struct {
	uint32_t ws;
	uint32_t max_hclk_mhz;
} latency_table[] = { { 0U, 30U }, { 1U, 60U }, { 2U, 90U }, { 3U, 120U }, { 4U, 150U }, { 5U, 168U } };

static uint32_t ws_for_mhz(uint32_t mhz)
{
	uint32_t i;

	for (i = 0; i < sizeof(latency_table) / sizeof(latency_table[0]); i++) {
		if (mhz <= latency_table[i].max_hclk_mhz) {
			return latency_table[i].ws;
		}
	}
	fail_msg("%u MHz is above the F405's 168 MHz", mhz);
	return 0U;
}

/* Erase and program run at whatever clock the board set: the latency must
 * stay as it is through the operation and after it (fewer wait states at
 * 168 MHz read garbage), the data cache off during it and reset after. */
static void test_wait_states_kept_and_dcache_reset(void **state)
{
	uint32_t i;

	(void)state;
	assert_int_equal(FLASH_ACR_LATENCY_5WS, ws_for_mhz(168U)); /* the board's clock */
	assert_int_equal(ws_for_mhz(30U), 0U);
	assert_int_equal(ws_for_mhz(31U), 1U);
	for (i = 0; i < sizeof(latency_table) / sizeof(latency_table[0]); i++) {
		uint32_t acr = latency_table[i].ws | RM_ACR_PRFTEN | RM_ACR_ICEN | RM_ACR_DCEN;

		sim_reset(acr);
		assert_int_equal(chip_flash_erase_slot(0U), SQ_OK);
		assert_int_equal(RM_ACR_LATENCY(sim.acr_at_start), latency_table[i].ws);
		assert_int_equal(sim.acr_at_start & RM_ACR_DCEN, 0U);
		assert_int_equal(sim.dcache_resets, 1U);
		assert_int_equal(sim.dcrst_with_dcen, 0U);
		assert_locked_and_acr(acr);

		assert_int_equal(chip_flash_program(nor_addr(0U), (const uint8_t *)"\x00\x11\x22\x33", 4U), SQ_OK);
		assert_int_equal(RM_ACR_LATENCY(sim.acr_at_start), latency_table[i].ws);
		assert_int_equal(sim.dcache_resets, 2U);
		assert_int_equal(sim.dcrst_with_dcen, 0U);
		assert_locked_and_acr(acr);
	}
}

/* Each bounded wait, kept busy: the call fails with SQ_EIO at once (no later
 * wait), locks again, and its bound covers the datasheet's maximum. */
static const struct {
	const char *what;
	bool erase;
	unsigned wait;
	uint32_t min_us;
} stuck_waits[] = {
	{ "erase: busy before unlock", true, 0U, DS_WORD_PROGRAM_MAX_US },
	{ "erase: the sector erase", true, 1U, DS_ERASE_16K_MAX_US },
	{ "program: busy before unlock", false, 0U, DS_WORD_PROGRAM_MAX_US },
	{ "program: the first word", false, 1U, DS_WORD_PROGRAM_MAX_US },
	{ "program: the second word", false, 2U, DS_WORD_PROGRAM_MAX_US },
};

static void test_each_wait_times_out(void **state)
{
	uint32_t i;

	(void)state;
	for (i = 0; i < sizeof(stuck_waits) / sizeof(stuck_waits[0]); i++) {
		int rc;

		sim_reset(BOARD_ACR);
		sim.stuck_wait = (int)stuck_waits[i].wait;
		rc = stuck_waits[i].erase ? chip_flash_erase_slot(0U)
					  : chip_flash_program(nor_addr(0U), (const uint8_t *)"\x01\x02\x03\x04\x05\x06\x07\x08", 8U);
		print_message("%s\n", stuck_waits[i].what);
		assert_int_equal(rc, SQ_EIO);
		assert_int_equal(sim.waits, stuck_waits[i].wait + 1U);
		assert_true(sim.wait_timeout_us[stuck_waits[i].wait] >= stuck_waits[i].min_us);
		assert_true(sim.wait_timeout_us[stuck_waits[i].wait] <= WAIT_CEILING_US);
		assert_int_equal(sim.words_programmed, stuck_waits[i].erase ? 0U : stuck_waits[i].wait - (stuck_waits[i].wait > 0U ? 1U : 0U));
		assert_locked_and_acr(BOARD_ACR);
	}
}

SQ_CMOCKA_MAIN(
	cmocka_unit_test_setup(test_unlock_key1_then_key2, setup),
	cmocka_unit_test_setup(test_wrong_key_sequence_locks_until_reset, setup),
	cmocka_unit_test_setup(test_stale_error_flags_cleared_by_writing_one, setup),
	cmocka_unit_test_setup(test_sector_erase_sequence, setup),
	cmocka_unit_test_setup(test_erase_error_flag_fails, setup),
	cmocka_unit_test_setup(test_program_sequence, setup),
	cmocka_unit_test_setup(test_program_over_zero_bits_fails_verify, setup),
	cmocka_unit_test_setup(test_program_error_flag_fails, setup),
	cmocka_unit_test_setup(test_program_bad_arguments_touch_nothing, setup),
	cmocka_unit_test_setup(test_wait_states_kept_and_dcache_reset, setup),
	cmocka_unit_test_setup(test_each_wait_times_out, setup))
