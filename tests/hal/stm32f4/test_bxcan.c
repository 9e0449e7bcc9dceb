/* SPDX-License-Identifier: MIT */
/*
 * The two-bus bxCAN driver (hal/stm32f4/bxcan.c) on the simulated registers
 * (tests/hal/stm32f4/bxcan_sim.c): filter banks split by CAN2SB, masked 11/29-bit
 * filters, silent mode for listen-only (nothing dominant on the wire), bus
 * separation, CAN2 needing CAN1's clock, the exact bit-rate check
 * (rate checked before any state is touched; restart aborts the mailboxes),
 * the error state from CAN_ESR (passive is not bus-off) and the error
 * frames' class from its LEC, the silent-loopback self-test, and the
 * contract handler for programming errors. Expected values come from
 * RM0090 and hal.h, never from the driver.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "bxcan.h"
#include "bxcan_sim.h"
#include "sq_status.h"

#define APB1_HZ 42000000U /* RM0090 clock plan: 168 MHz / 4 */
#define RCC_CAN1EN (1U << 25) /* RM0090 7.3.13 */
#define RCC_CAN2EN (1U << 26)

/* Host contract handler: cmocka's expect_assert_failure() catches it. */
_Noreturn void hal_contract_failed(const char *file, uint32_t line)
{
	mock_assert(0, "hal_contract_failed", file, (int)line);
	abort();
}

static hal_can_frame_t std_frame(uint32_t id, uint8_t seed)
{
	hal_can_frame_t f;
	uint32_t i;

	memset(&f, 0, sizeof(f));
	f.id = id;
	f.dlc = 8U;
	for (i = 0; i < 8U; i++) {
		f.data[i] = (uint8_t)(seed + i);
	}
	return f;
}

static hal_can_frame_t ext_frame(uint32_t id, uint8_t seed)
{
	hal_can_frame_t f = std_frame(id, seed);

	f.flags = HAL_CAN_FLAG_EXT;
	return f;
}

static int setup_both(void **state)
{
	(void)state;
	sim_reset();
	assert_int_equal(bxcan_start(0U, 500000U), SQ_OK);
	assert_int_equal(bxcan_start(1U, 500000U), SQ_OK);
	return 0;
}

/* Does a frame injected on `bus` come out of hal_can_receive(bus)? */
static bool passes(uint8_t bus, const hal_can_frame_t *f)
{
	hal_can_frame_t got;

	(void)sim_inject(bus, f);
	if (hal_can_receive(bus, &got) != SQ_OK) {
		return false;
	}
	assert_int_equal(got.id, f->id);
	assert_int_equal(got.flags, f->flags);
	assert_int_equal(got.dlc, f->dlc);
	assert_memory_equal(got.data, f->data, 8U);
	return true;
}

static void test_banks_split_by_can2sb(void **state)
{
	hal_can_frame_t f = std_frame(0x10U, 0U);
	const hal_can_filter_t one = { 0x10U, 0x7FFU, 0U };

	(void)state;
	/* whatever CAN2SB was before (a bootloader may have moved it) */
	sim_reset();
	sim_poke_can2sb(20U);
	assert_int_equal(bxcan_start(0U, 500000U), SQ_OK);
	assert_int_equal(bxcan_start(1U, 500000U), SQ_OK);
	assert_int_equal(hal_can_set_rx_filter(1U, &one, 1U), SQ_OK);
	assert_true(passes(1U, &f));
	assert_true(passes(0U, &f));
	/* 28 banks, half each: CAN2SB = 14 (bits 13:8 of CAN_FMR), FINIT off */
	assert_int_equal((sim_fmr() >> 8) & 0x3FU, 14U);
	assert_int_equal(sim_fmr() & 1U, 0U);
}

static void test_buses_are_separate(void **state)
{
	hal_can_frame_t a = std_frame(0x123U, 1U);
	hal_can_frame_t b = ext_frame(0x1234567U, 9U);
	hal_can_frame_t got;

	(void)state;
	(void)sim_inject(0U, &a);
	(void)sim_inject(1U, &b);
	assert_int_equal(hal_can_receive(0U, &got), SQ_OK);
	assert_int_equal(got.id, 0x123U);
	assert_int_equal(hal_can_receive(0U, &got), SQ_EAGAIN);
	assert_int_equal(hal_can_receive(1U, &got), SQ_OK);
	assert_int_equal(got.id, 0x1234567U);
	assert_int_equal(got.flags, HAL_CAN_FLAG_EXT);
	assert_int_equal(hal_can_receive(1U, &got), SQ_EAGAIN);

	assert_int_equal(hal_can_send(1U, &a), SQ_OK);
	sim_advance_us(1000U);
	assert_int_equal(sim_wire_count(0U), 0U);
	assert_true(sim_wire_take(1U, &got));
	assert_int_equal(got.id, 0x123U);
	assert_memory_equal(got.data, a.data, 8U);
}

static void test_masked_filters_std_and_ext(void **state)
{
	const hal_can_filter_t f0[2] = {
		{ 0x100U, 0x7F0U, 0U },                          /* 0x100..0x10F std */
		{ 0x18DAF100U, 0x1FFFFF00U, HAL_CAN_FLAG_EXT }, /* 0x18DAF1xx ext   */
	};
	hal_can_frame_t f;

	/* id, extended, passes: the ext id 0x10F << 18 is the wrong kind whose
	 * register image matches the standard filter's STID bits (it puts
	 * 0x10F in STID[10:0]): only the IDE bit in the mask keeps it out */
	static const struct {
		uint32_t id;
		bool ext;
		bool passes;
	} cases[] = {
		{ 0x100U, false, true },        { 0x10FU, false, true },
		{ 0x110U, false, false },       { 0x0FFU, false, false },
		{ 0x10FU, true, false },        { 0x10FU << 18, true, false },
		{ 0x18DAF1F1U, true, true },    { 0x18DAF200U, true, false },
	};
	size_t i;

	(void)state;
	assert_int_equal(hal_can_set_rx_filter(0U, f0, 2U), SQ_OK);
	for (i = 0U; i < sizeof(cases) / sizeof(cases[0]); i++) {
		f = cases[i].ext ? ext_frame(cases[i].id, 0U) : std_frame(cases[i].id, 0U);
		assert_int_equal(passes(0U, &f), cases[i].passes);
	}
	f = std_frame(0x100U, 0U);
	f.flags = HAL_CAN_FLAG_RTR; /* remote frames pass like data frames */
	f.dlc = 0U;
	memset(f.data, 0, sizeof(f.data));
	assert_true(passes(0U, &f));
	/* CAN2's banks are its own: still accepting everything */
	f = std_frame(0x7FFU, 0U);
	assert_true(passes(1U, &f));
	f = ext_frame(0x1FFFFFFFU, 0U);
	assert_true(passes(1U, &f));
	/* an extended filter on the STID-aligned bits only must not pass the
	 * standard frame with the same bits there (0x18C00000 >> 18 = 0x630) */
	{
		const hal_can_filter_t hi = { 0x18C00000U, 0x1FFC0000U, HAL_CAN_FLAG_EXT };

		assert_int_equal(hal_can_set_rx_filter(0U, &hi, 1U), SQ_OK);
		f = std_frame(0x630U, 0U);
		assert_false(passes(0U, &f));
		f = ext_frame(0x18C12345U, 0U);
		assert_true(passes(0U, &f));
	}
}

static void test_full_bank_set_on_each_bus(void **state)
{
	hal_can_filter_t f[HAL_CAN_MAX_FILTERS];
	hal_can_frame_t fr;
	uint32_t i;

	(void)state;
	for (i = 0; i < HAL_CAN_MAX_FILTERS; i++) {
		f[i] = (hal_can_filter_t){ 0x200U + i, 0x7FFU, 0U };
	}
	assert_int_equal(hal_can_set_rx_filter(0U, f, HAL_CAN_MAX_FILTERS), SQ_OK);
	for (i = 0; i < HAL_CAN_MAX_FILTERS; i++) {
		f[i] = (hal_can_filter_t){ 0x300U + i, 0x7FFU, 0U };
	}
	assert_int_equal(hal_can_set_rx_filter(1U, f, HAL_CAN_MAX_FILTERS), SQ_OK);
	for (i = 0; i < HAL_CAN_MAX_FILTERS; i++) {
		fr = std_frame(0x200U + i, 0U);
		assert_true(passes(0U, &fr));
		assert_false(passes(1U, &fr));
		fr = std_frame(0x300U + i, 0U);
		assert_true(passes(1U, &fr));
		assert_false(passes(0U, &fr));
	}
	fr = std_frame(0x200U + HAL_CAN_MAX_FILTERS, 0U);
	assert_false(passes(0U, &fr));
	/* count 0: nothing passes */
	assert_int_equal(hal_can_set_rx_filter(0U, NULL, 0U), SQ_OK);
	fr = std_frame(0x200U, 0U);
	assert_false(passes(0U, &fr));
}

static void test_bad_filter_rejected_and_old_kept(void **state)
{
	const hal_can_filter_t good = { 0x100U, 0x7FFU, 0U };
	const hal_can_filter_t bad_id = { 0x800U, 0x7FFU, 0U };
	const hal_can_filter_t bad_mask = { 0x100U, 0xFFFU, 0U };
	const hal_can_filter_t bad_flags = { 0x100U, 0x7FFU, HAL_CAN_FLAG_RTR };
	hal_can_frame_t f = std_frame(0x100U, 0U);

	(void)state;
	assert_int_equal(hal_can_set_rx_filter(0U, &good, 1U), SQ_OK);
	assert_int_equal(hal_can_set_rx_filter(0U, &bad_id, 1U), SQ_EINVAL);
	assert_int_equal(hal_can_set_rx_filter(0U, &bad_mask, 1U), SQ_EINVAL);
	assert_int_equal(hal_can_set_rx_filter(0U, &bad_flags, 1U), SQ_EINVAL);
	assert_true(passes(0U, &f));
	f = std_frame(0x101U, 0U);
	assert_false(passes(0U, &f));
}

static void test_listen_only_is_silent(void **state)
{
	hal_can_frame_t f = std_frame(0x321U, 4U);
	hal_can_frame_t got;
	hal_can_status_t st;
	uint32_t dom0;

	(void)state;
	assert_int_equal(hal_can_set_mode(1U, HAL_CAN_MODE_LISTEN_ONLY), SQ_OK);
	assert_true((sim_btr(1U) & (1U << 31)) != 0U); /* BTR.SILM (RM0090 32.9.2) */
	assert_int_equal(sim_btr(0U) & (1U << 31), 0U);
	/* receives, but drives no ACK and no error flag */
	assert_false(sim_inject(1U, &f));
	assert_int_equal(hal_can_receive(1U, &got), SQ_OK);
	assert_int_equal(got.id, 0x321U);
	sim_error_frame(1U);
	assert_int_equal(sim_dominant_count(1U), 0U);
	/* sends nothing: refused and counted */
	assert_int_equal(hal_can_send(1U, &f), SQ_EPERM);
	assert_int_equal(hal_can_send(1U, &f), SQ_EPERM);
	sim_advance_us(1000U);
	assert_int_equal(sim_wire_count(1U), 0U);
	assert_int_equal(hal_can_get_status(1U, &st), SQ_OK);
	assert_int_equal(st.mode, HAL_CAN_MODE_LISTEN_ONLY);
	assert_int_equal(st.tx_refused_listen_only, 2U);
	assert_int_equal(st.error_frames, 1U);
	/* the other bus keeps working, ACKs and sends */
	dom0 = sim_dominant_count(0U);
	assert_true(sim_inject(0U, &f));
	assert_int_equal(sim_dominant_count(0U), dom0 + 1U);
	assert_int_equal(hal_can_send(0U, &f), SQ_OK);
	sim_advance_us(1000U);
	assert_true(sim_wire_take(0U, &got));
	assert_int_equal(hal_can_get_status(0U, &st), SQ_OK);
	assert_int_equal(st.mode, HAL_CAN_MODE_NORMAL);
	assert_int_equal(st.tx_refused_listen_only, 0U);
	/* and back to normal */
	assert_int_equal(hal_can_set_mode(1U, HAL_CAN_MODE_NORMAL), SQ_OK);
	assert_int_equal(sim_btr(1U) & (1U << 31), 0U);
	assert_int_equal(hal_can_send(1U, &f), SQ_OK);
	sim_advance_us(1000U);
	assert_int_equal(sim_wire_count(1U), 1U);
}

/* BTR -> bit rate, from RM0090 32.7.7: BRP+1 clocks per quantum, 1 + (TS1+1)
 * + (TS2+1) quanta per bit. */
static uint32_t btr_rate(uint32_t btr)
{
	uint32_t brp = (btr & 0x3FFU) + 1U;
	uint32_t ts1 = ((btr >> 16) & 0xFU) + 1U;
	uint32_t ts2 = ((btr >> 20) & 0x7U) + 1U;
	uint32_t clocks = brp * (1U + ts1 + ts2);

	return APB1_HZ % clocks == 0U ? APB1_HZ / clocks : 0U;
}

/* an inexact rate (800 kbit/s at 42 MHz: 52.5 clocks per bit) is
 * refused before anything changes: still running, same timing, RX and TX
 * working, nothing aborted. */
static void test_inexact_rate_leaves_bus_running(void **state)
{
	hal_can_frame_t f = std_frame(0x55U, 2U);
	hal_can_frame_t got;
	hal_can_status_t st;
	uint32_t btr = sim_btr(0U);

	(void)state;
	assert_int_equal(btr_rate(btr), 500000U);
	assert_int_equal(hal_can_set_bitrate(0U, 800U), SQ_EINVAL);
	assert_int_equal(hal_can_set_bitrate(0U, 0U), SQ_EINVAL);
	assert_int_equal(hal_can_set_bitrate(0U, 1001U), SQ_EINVAL);
	assert_int_equal(sim_btr(0U), btr);
	assert_int_equal(sim_aborts(0U), 0U);
	assert_int_equal(hal_can_get_status(0U, &st), SQ_OK);
	assert_int_equal(st.state, HAL_CAN_STATE_ERROR_ACTIVE);
	assert_true(passes(0U, &f));
	assert_int_equal(hal_can_send(0U, &f), SQ_OK);
	sim_advance_us(1000U);
	assert_true(sim_wire_take(0U, &got));
	assert_int_equal(sim_fault_bits(), 0U);
}

/* A real change: new exact timing, pending mailboxes aborted (ABRQ), the
 * queue dropped, filters back to accept-all; the other bus untouched. */
static void test_rate_change_aborts_and_restarts(void **state)
{
	hal_can_frame_t f = std_frame(0x66U, 3U);
	const hal_can_filter_t only = { 0x7U, 0x7FFU, 0U };
	hal_can_frame_t got;
	uint32_t btr1 = sim_btr(1U);
	uint32_t i;

	(void)state;
	assert_int_equal(hal_can_set_rx_filter(0U, &only, 1U), SQ_OK);
	sim_block_tx(0U, true);
	for (i = 0; i < 5U; i++) {
		assert_int_equal(hal_can_send(0U, &f), SQ_OK);
	}
	assert_int_equal(hal_can_set_bitrate(0U, 250U), SQ_OK);
	assert_int_equal(btr_rate(sim_btr(0U)), 250000U);
	assert_int_equal(sim_aborts(0U), 3U); /* all three mailboxes were busy */
	sim_block_tx(0U, false);
	sim_advance_us(1000U);
	assert_int_equal(sim_wire_count(0U), 0U); /* nothing old goes out */
	f = std_frame(0x123U, 0U);
	assert_true(passes(0U, &f)); /* accept-all after the restart */
	assert_int_equal(hal_can_set_bitrate(0U, 250U), SQ_OK); /* no-op */
	assert_int_equal(sim_aborts(0U), 3U);
	assert_int_equal(sim_btr(1U), btr1);
	assert_int_equal(hal_can_send(1U, &f), SQ_OK);
	sim_advance_us(1000U);
	assert_true(sim_wire_take(1U, &got));
}

static void test_tx_queue_full_and_drain_in_order(void **state)
{
	hal_can_frame_t f;
	hal_can_frame_t got;
	uint32_t n = 0U;
	uint32_t i;

	(void)state;
	sim_block_tx(0U, true);
	for (i = 0; i < 64U; i++) {
		f = std_frame(0x400U + i, (uint8_t)i);
		if (hal_can_send(0U, &f) != SQ_OK) {
			assert_int_equal(hal_can_send(0U, &f), SQ_ENOBUFS);
			break;
		}
		n++;
	}
	assert_int_equal(n, 3U + 8U); /* three mailboxes + the 8-frame queue */
	sim_block_tx(0U, false);
	sim_advance_us(1000U);
	for (i = 0; i < n; i++) {
		assert_true(sim_wire_take(0U, &got));
		assert_int_equal(got.id, 0x400U + i);
	}
	assert_false(sim_wire_take(0U, &got));
}

static void test_bus_off_and_error_frames_per_bus(void **state)
{
	hal_can_status_t st;
	hal_can_frame_t f = std_frame(0x1U, 0U);

	(void)state;
	sim_bus_off(1U, true);
	assert_int_equal(hal_can_get_status(1U, &st), SQ_OK);
	assert_int_equal(st.state, HAL_CAN_STATE_BUS_OFF);
	assert_int_equal(st.bus_off_count, 1U);
	assert_int_equal(hal_can_send(1U, &f), SQ_ENETUNREACH);
	assert_int_equal(hal_can_get_status(0U, &st), SQ_OK);
	assert_int_equal(st.state, HAL_CAN_STATE_ERROR_ACTIVE);
	assert_int_equal(st.bus_off_count, 0U);
	sim_bus_off(1U, false);
	assert_int_equal(hal_can_get_status(1U, &st), SQ_OK);
	assert_int_equal(st.state, HAL_CAN_STATE_ERROR_ACTIVE);
	sim_error_frame(0U);
	sim_error_frame(0U);
	assert_int_equal(hal_can_get_status(0U, &st), SQ_OK);
	assert_int_equal(st.error_frames, 2U);
	assert_int_equal(hal_can_get_status(1U, &st), SQ_OK);
	assert_int_equal(st.error_frames, 0U);
}

/* The state from CAN_ESR (RM0090 32.9.2): EWGF at a counter >= 96 is
 * warning, EPVF above 127 passive, and only BOFF (TEC beyond 255) is
 * bus-off: an error-passive node still sends (its frames are ACKed), and a
 * bus-off count there would report a fault that did not happen. */
static void test_error_passive_is_not_bus_off(void **state)
{
	hal_can_status_t st;
	hal_can_frame_t f = std_frame(0x2U, 0U);

	(void)state;
	sim_error_counters(0U, 96U, 0U);
	assert_int_equal(hal_can_get_status(0U, &st), SQ_OK);
	assert_int_equal(st.state, HAL_CAN_STATE_ERROR_WARNING);
	assert_int_equal(st.tx_error_count, 96U);
	sim_error_counters(0U, 128U, 5U);
	assert_int_equal(hal_can_get_status(0U, &st), SQ_OK);
	assert_int_equal(st.state, HAL_CAN_STATE_ERROR_PASSIVE);
	assert_int_equal(st.tx_error_count, 128U);
	assert_int_equal(st.rx_error_count, 5U);
	assert_int_equal(st.bus_off_count, 0U);
	assert_int_equal(hal_can_send(0U, &f), SQ_OK);
	sim_error_counters(0U, 0U, 200U); /* a receive-side passive node */
	assert_int_equal(hal_can_get_status(0U, &st), SQ_OK);
	assert_int_equal(st.state, HAL_CAN_STATE_ERROR_PASSIVE);
	assert_int_equal(st.bus_off_count, 0U);
	sim_error_counters(0U, 0U, 0U);
	assert_int_equal(hal_can_get_status(0U, &st), SQ_OK);
	assert_int_equal(st.state, HAL_CAN_STATE_ERROR_ACTIVE);
	assert_int_equal(st.bus_off_count, 0U);
}

/* Each error the controller saw is handed on as an error frame whose id is
 * SocketCAN's error class (linux/can/error.h): CAN_ESR.LEC 3, an
 * acknowledgment error, is 0x20 (CAN_ERR_ACK: nobody acknowledged, e.g. the
 * ECU alone on the bus); the other codes (stuff 1, form 2, bit 4 and 5, CRC
 * 6) are protocol violations, 0x08 (CAN_ERR_PROT); data[6] = TEC and
 * data[7] = REC as SocketCAN puts them. */
static void test_error_frame_class_from_lec(void **state)
{
	static const struct {
		uint32_t lec;
		uint32_t id;
	} cases[] = { { 3U, 0x20U }, { 1U, 0x08U }, { 2U, 0x08U }, { 4U, 0x08U },
		      { 5U, 0x08U }, { 6U, 0x08U } };
	hal_can_frame_t got;
	uint32_t i;

	(void)state;
	for (i = 0U; i < sizeof(cases) / sizeof(cases[0]); i++) {
		sim_error_code(0U, cases[i].lec);
		assert_int_equal(hal_can_receive(0U, &got), SQ_OK);
		assert_int_equal(got.flags, HAL_CAN_FLAG_ERR);
		assert_int_equal(got.id, cases[i].id);
		assert_int_equal(got.dlc, 8U);
		assert_int_equal(got.data[6], 0U);
		assert_int_equal(got.data[7], i + 1U); /* REC: one per error */
		assert_int_equal(hal_can_receive(0U, &got), SQ_EAGAIN);
	}
}

/* CAN2 alone: the driver must clock CAN1 too (its filters live there). The
 * second half shows the simulation would notice: without CAN1's clock
 * CAN2 receives nothing. */
static void test_can2_needs_can1_clock(void **state)
{
	hal_can_frame_t f = std_frame(0x2AAU, 7U);

	(void)state;
	sim_reset();
	assert_int_equal(bxcan_start(1U, 500000U), SQ_OK);
	assert_true((bxcan_sim_rcc[SIM_RCC_APB1ENR_IDX] & RCC_CAN1EN) != 0U);
	assert_true((bxcan_sim_rcc[SIM_RCC_APB1ENR_IDX] & RCC_CAN2EN) != 0U);
	assert_true(passes(1U, &f));
	bxcan_sim_rcc[SIM_RCC_APB1ENR_IDX] &= ~RCC_CAN1EN;
	assert_false(passes(1U, &f));
}

static void test_selftest_loopback(void **state)
{
	(void)state;
	sim_reset();
	assert_int_equal(bxcan_selftest_loopback(0U), SQ_OK);
	assert_int_equal(bxcan_selftest_loopback(1U), SQ_OK);
	/* nothing reached either wire, not even an ACK */
	assert_int_equal(sim_wire_count(0U), 0U);
	assert_int_equal(sim_wire_count(1U), 0U);
	assert_int_equal(sim_dominant_count(0U), 0U);
	assert_int_equal(sim_dominant_count(1U), 0U);
	assert_true((sim_mcr(0U) & 1U) != 0U); /* left in initialisation mode */
	/* then a normal start works and loopback is off */
	assert_int_equal(bxcan_start(0U, 500000U), SQ_OK);
	assert_int_equal(sim_btr(0U) & (3U << 30), 0U);
	assert_int_equal(sim_fault_bits(), 0U);
}

static void test_selftest_dead_controller(void **state)
{
	hal_can_frame_t f = std_frame(0x1U, 0U);
	hal_can_status_t st;

	(void)state;
	sim_reset();
	sim_controller_dead(1U, true);
	assert_int_equal(bxcan_selftest_loopback(1U), SQ_EAGAIN);
	assert_true((sim_fault_bits() & HAL_FAULT_CAN_INIT) != 0U);
	assert_int_equal(bxcan_start(1U, 500000U), SQ_EAGAIN);
	assert_int_equal(hal_can_send(1U, &f), SQ_ENETDOWN);
	assert_int_equal(hal_can_get_status(1U, &st), SQ_OK);
	assert_int_equal(st.state, HAL_CAN_STATE_STOPPED);
	/* bus 0 is fine */
	assert_int_equal(bxcan_selftest_loopback(0U), SQ_OK);
}

static void test_contract_violations(void **state)
{
	hal_can_frame_t f = std_frame(0x1U, 0U);
	hal_can_status_t st;
	hal_can_filter_t many[HAL_CAN_MAX_FILTERS + 1U];

	(void)state;
	memset(many, 0, sizeof(many));
	expect_assert_failure(hal_can_send(HAL_CAN_BUSES, &f));
	expect_assert_failure(hal_can_send(0U, NULL));
	expect_assert_failure(hal_can_receive(0U, NULL));
	expect_assert_failure(hal_can_get_status(2U, &st));
	expect_assert_failure(hal_can_set_rx_filter(0U, many, HAL_CAN_MAX_FILTERS + 1U));
	expect_assert_failure(hal_can_set_rx_filter(0U, NULL, 1U));
	expect_assert_failure(hal_can_set_mode(0U, (hal_can_mode_t)7));
	/* bad data is not a contract violation */
	f.dlc = 9U;
	assert_int_equal(hal_can_send(0U, &f), SQ_EINVAL);
	f = std_frame(0x800U, 0U);
	assert_int_equal(hal_can_send(0U, &f), SQ_EINVAL);
}

SQ_CMOCKA_MAIN(
	cmocka_unit_test_setup(test_banks_split_by_can2sb, setup_both),
	cmocka_unit_test_setup(test_buses_are_separate, setup_both),
	cmocka_unit_test_setup(test_masked_filters_std_and_ext, setup_both),
	cmocka_unit_test_setup(test_full_bank_set_on_each_bus, setup_both),
	cmocka_unit_test_setup(test_bad_filter_rejected_and_old_kept, setup_both),
	cmocka_unit_test_setup(test_listen_only_is_silent, setup_both),
	cmocka_unit_test_setup(test_inexact_rate_leaves_bus_running, setup_both),
	cmocka_unit_test_setup(test_rate_change_aborts_and_restarts, setup_both),
	cmocka_unit_test_setup(test_tx_queue_full_and_drain_in_order, setup_both),
	cmocka_unit_test_setup(test_bus_off_and_error_frames_per_bus, setup_both),
	cmocka_unit_test_setup(test_error_passive_is_not_bus_off, setup_both),
	cmocka_unit_test_setup(test_error_frame_class_from_lec, setup_both),
	cmocka_unit_test(test_can2_needs_can1_clock),
	cmocka_unit_test(test_selftest_loopback),
	cmocka_unit_test(test_selftest_dead_controller),
	cmocka_unit_test_setup(test_contract_violations, setup_both))
