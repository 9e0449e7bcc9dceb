/* SPDX-License-Identifier: MIT */
/*
 * The F4/F103 common chip part (hal/stm32f4/chip_common.c) on the host,
 * called directly, its flash registers behind the hook of
 * tests/support/regsim/f4/chip.h (REGSIM_F4_FLASH_HOOK). Expected values
 * are RM0090's, not the chip header's:
 *   6.2.2  the HSI is 16 MHz and clocks the core out of reset;
 *   6.3.2  with the PLL at 168 MHz and APB1 prescaler 4, PCLK1 = 42 MHz
 *          (the bus's maximum, DS8626);
 *   3.5.1  FLASH_CR is locked out of reset (LOCK, bit 31, reset value
 *          0x80000000, 3.8.5); KEY1 = 0x45670123 then KEY2 = 0xCDEF89AB
 *          unlocks it; any other sequence locks it until the next reset
 *          (these bits and the key sequence: tests/support/regsim/f4/flash_rm0090.h);
 *   3.8.4  FLASH_SR: EOP (bit 0), OPERR (1), WRPERR (4), PGAERR (5),
 *          PGPERR (6), PGSERR (7) are cleared by writing 1; BSY (16) is
 *          read-only and set while an operation runs.
 * The bounded wait (systick.c's stm32_wait_reg) is this test's: it records
 * the timeout asked for and answers SQ_EAGAIN, as the real one does when
 * the time runs out, while the test keeps BSY set.
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

#define RM_HSI_HZ 16000000U       /* RM0090 6.2.2 */
#define RM_PLL_HZ 168000000U      /* RM0090 6.3.2: the F405's maximum */
#define RM_APB1_HZ (168000000U / 4U)
#define LOG_MAX 8U

/* What the flash interface holds, and every store the code under test made. */
static struct {
	uint32_t sr, cr;
	struct regsim_flash_keys k; /* RM0090 3.5.1's key sequence */
	uint32_t keys[LOG_MAX];
	unsigned n_keys;
	uint32_t sr_stores[LOG_MAX];
	unsigned n_sr_stores;
	uint32_t wait_timeout_us[LOG_MAX];
	unsigned waits;
	bool bsy_stuck; /* the operation under way never ends */
} sim;

static void key_store(uint32_t key)
{
	if (sim.n_keys < LOG_MAX) {
		sim.keys[sim.n_keys++] = key;
	}
	regsim_flash_key_store(&sim.k, &sim.cr, key);
}

/* Plays the stores since the last access: FLASH_KEYR reads 0, so any other
 * value there is a key; a store to FLASH_SR is seen when it differs from
 * what the register showed (the cases avoid storing exactly that). */
static void flash_sync(void)
{
	/* compared with what the register showed, before a key is played */
	if (regsim_flash[4] != sim.cr) {
		fail_msg("chip_common.c stored to FLASH_CR (0x%08x)", regsim_flash[4]);
	}
	if (regsim_flash[1] != 0U) {
		key_store(regsim_flash[1]);
	}
	if (regsim_flash[3] != sim.sr) {
		if (sim.n_sr_stores < LOG_MAX) {
			sim.sr_stores[sim.n_sr_stores++] = regsim_flash[3];
		}
		sim.sr &= ~(regsim_flash[3] & RM_SR_W1C);
	}
	regsim_flash[1] = 0U;
	regsim_flash[3] = sim.sr;
	regsim_flash[4] = sim.cr;
}

volatile uint32_t *regsim_flash_reg(uint32_t offset)
{
	flash_sync();
	return &regsim_flash[offset / 4U];
}

int stm32_wait_reg(volatile const uint32_t *reg, uint32_t mask, uint32_t value, uint32_t timeout_us)
{
	flash_sync();
	if (sim.waits < LOG_MAX) {
		sim.wait_timeout_us[sim.waits] = timeout_us;
	}
	sim.waits++;
	if (!sim.bsy_stuck) {
		sim.sr &= ~RM_SR_BSY;
	}
	regsim_flash[3] = sim.sr;
	return ((*reg & mask) == value) ? SQ_OK : SQ_EAGAIN;
}

static void sim_reset(uint32_t sr)
{
	memset(&sim, 0, sizeof(sim));
	regsim_f4_reset();
	sim.cr = RM_CR_LOCK; /* reset value 0x80000000 */
	sim.sr = sr;
	regsim_flash[3] = sim.sr;
	regsim_flash[4] = sim.cr;
}

static int setup(void **state)
{
	(void)state;
	sim_reset(0U);
	return 0;
}

/* First in the run: nothing has called chip_clock_rates_set() yet. */
static void test_rates_out_of_reset_are_the_hsi(void **state)
{
	(void)state;
	assert_int_equal(chip_core_hz(), RM_HSI_HZ);
	assert_int_equal(chip_apb1_hz(), RM_HSI_HZ);
}

static void test_rates_follow_the_clock_source(void **state)
{
	(void)state;
	chip_clock_rates_set(true);
	assert_int_equal(chip_core_hz(), RM_PLL_HZ);
	assert_int_equal(chip_apb1_hz(), RM_APB1_HZ);
	chip_clock_rates_set(false); /* the fall-back after a failed PLL start */
	assert_int_equal(chip_core_hz(), RM_HSI_HZ);
	assert_int_equal(chip_apb1_hz(), RM_HSI_HZ);
	chip_clock_rates_set(true);
	assert_int_equal(chip_core_hz(), RM_PLL_HZ);
	assert_int_equal(chip_apb1_hz(), RM_APB1_HZ);
	chip_clock_rates_set(false);
}

static void test_unlock_stores_key1_then_key2(void **state)
{
	(void)state;
	assert_int_equal(chip_flash_unlock(), SQ_OK);
	flash_sync();
	assert_int_equal(sim.n_keys, 2U);
	assert_int_equal(sim.keys[0], RM_KEY1);
	assert_int_equal(sim.keys[1], RM_KEY2);
	assert_false(sim.k.locked_until_reset);
	assert_int_equal(sim.cr & RM_CR_LOCK, 0U);
	assert_int_equal(sim.waits, 1U);      /* idle first: one bounded wait */
	assert_true(sim.wait_timeout_us[0] > 0U);
}

static void test_unlock_when_unlocked_stores_no_key(void **state)
{
	(void)state;
	sim.cr = 0U;
	regsim_flash[4] = 0U;
	assert_int_equal(chip_flash_unlock(), SQ_OK);
	flash_sync();
	/* a key while unlocked would be a wrong sequence on the real part */
	assert_int_equal(sim.n_keys, 0U);
	assert_int_equal(sim.cr, 0U);
}

static void test_unlock_clears_stale_flags_by_writing_one(void **state)
{
	static const uint32_t stale[] = { RM_SR_PGSERR | RM_SR_PGPERR, RM_SR_WRPERR | RM_SR_EOP,
					  RM_SR_OPERR | RM_SR_PGAERR };
	uint32_t i;

	(void)state;
	for (i = 0; i < sizeof(stale) / sizeof(stale[0]); i++) {
		sim_reset(stale[i]);
		assert_int_equal(chip_flash_unlock(), SQ_OK);
		flash_sync();
		assert_int_equal(sim.n_sr_stores, 1U);
		assert_int_equal(sim.sr_stores[0] & stale[i], stale[i]);
		assert_int_equal(sim.sr_stores[0] & RM_SR_BSY, 0U); /* read-only bit left alone */
		assert_int_equal(sim.sr & RM_SR_W1C, 0U);
	}
}

static void test_unlock_locked_until_reset_fails(void **state)
{
	(void)state;
	sim.k.locked_until_reset = true; /* an earlier wrong sequence */
	assert_int_equal(chip_flash_unlock(), SQ_EIO);
	flash_sync();
	assert_int_equal(sim.cr, RM_CR_LOCK);
	assert_int_equal(sim.n_sr_stores, 0U); /* nothing after the failed unlock */
}

static void test_unlock_while_busy_stores_nothing(void **state)
{
	(void)state;
	sim_reset(RM_SR_BSY);
	sim.bsy_stuck = true;
	assert_int_equal(chip_flash_unlock(), SQ_EIO);
	flash_sync();
	assert_int_equal(sim.waits, 1U);
	/* bounded: at least the longest word program (DS8626: 100 us), well
	 * under the watchdog's reach (10 s) */
	assert_true(sim.wait_timeout_us[0] >= 100U && sim.wait_timeout_us[0] <= 10000000U);
	assert_int_equal(sim.n_keys, 0U);
	assert_int_equal(sim.n_sr_stores, 0U);
	assert_int_equal(sim.cr, RM_CR_LOCK);
}

static const struct {
	const char *what;
	uint32_t sr_at_end;
	bool stuck;
	int expect;
} done_cases[] = {
	{ "ends clean", RM_SR_EOP, false, SQ_OK },
	{ "ends with nothing set", 0U, false, SQ_OK },
	{ "programming sequence error", RM_SR_PGSERR, false, SQ_EIO },
	{ "parallelism error", RM_SR_PGPERR, false, SQ_EIO },
	{ "alignment error", RM_SR_PGAERR, false, SQ_EIO },
	{ "write protection", RM_SR_WRPERR | RM_SR_EOP, false, SQ_EIO },
	{ "operation error", RM_SR_OPERR, false, SQ_EIO },
	{ "never ends", 0U, true, SQ_EIO },
};

static void test_wait_done_table(void **state)
{
	static const uint32_t timeouts_us[] = { 100U, 500000U };
	uint32_t i, k;

	(void)state;
	for (i = 0; i < sizeof(done_cases) / sizeof(done_cases[0]); i++) {
		for (k = 0; k < sizeof(timeouts_us) / sizeof(timeouts_us[0]); k++) {
			sim_reset(RM_SR_BSY | done_cases[i].sr_at_end);
			sim.cr = 0U;
			regsim_flash[4] = 0U;
			sim.bsy_stuck = done_cases[i].stuck;
			if (chip_flash_wait_done(timeouts_us[k]) != done_cases[i].expect) {
				fail_msg("%s, %u us: not %d", done_cases[i].what, timeouts_us[k],
					 done_cases[i].expect);
			}
			assert_int_equal(sim.waits, 1U);
			assert_int_equal(sim.wait_timeout_us[0], timeouts_us[k]); /* the caller's bound */
			flash_sync();
			assert_int_equal(sim.n_sr_stores, 0U); /* flags left for the caller */
		}
	}
}

SQ_CMOCKA_MAIN(
	cmocka_unit_test(test_rates_out_of_reset_are_the_hsi),
	cmocka_unit_test(test_rates_follow_the_clock_source),
	cmocka_unit_test_setup(test_unlock_stores_key1_then_key2, setup),
	cmocka_unit_test_setup(test_unlock_when_unlocked_stores_no_key, setup),
	cmocka_unit_test_setup(test_unlock_clears_stale_flags_by_writing_one, setup),
	cmocka_unit_test_setup(test_unlock_locked_until_reset_fails, setup),
	cmocka_unit_test_setup(test_unlock_while_busy_stores_nothing, setup),
	cmocka_unit_test_setup(test_wait_done_table, setup))
