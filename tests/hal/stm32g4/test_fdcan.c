/* SPDX-License-Identifier: MIT */
/*
 * The FDCAN driver (hal/stm32g4/fdcan.c) on the simulated FDCAN pair and
 * message RAM (tests/hal/stm32g4/fdcan_sim.c): the register sequences and
 * the words it leaves in the controller, checked against values derived
 * by hand from RM0440 chapter 44 (register and element layouts written out
 * here as numbers, not taken from fdcan_regs.h): initialisation, bit
 * timing written, the nominal rate's range, filter elements, the TX element layout, bus monitoring
 * (no ACK, no error flag; the other instance on the same wire gets no ACK),
 * the internal loopback self-test, bus-off recovery, FIFO message lost,
 * error states, protocol exceptions, a controller that never acknowledges
 * INIT.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "cortex_m.h"
#include "fdcan.h"
#include "fdcan_sim.h"
#include "test_frame.h"
#include "hal.h"
#include "sq_status.h"

_Noreturn void hal_contract_failed(const char *file, uint32_t line);
_Noreturn void hal_contract_failed(const char *file, uint32_t line)
{
	mock_assert(0, "hal_contract_failed", file, (int)line);
	abort();
}

/* RM0440 register offsets and bits, written out for the test */
#define R_CCCR 0x018U
#define R_TEST 0x010U
#define R_NBTP 0x01CU
#define R_DBTP 0x00CU
#define R_TDCR 0x048U
#define R_RXGFC 0x080U
#define R_TXBC 0x0C0U
#define R_TXBRP 0x0C8U
#define R_IE 0x054U
#define R_ILS 0x058U
#define R_ILE 0x05CU
#define R_RXF0S 0x090U
#define CCCR_INIT 0x1U
#define CCCR_CCE 0x2U
#define CCCR_MON 0x20U
#define CCCR_DAR 0x40U
#define CCCR_TEST 0x80U
#define CCCR_FDOE 0x100U
#define CCCR_BRSE 0x200U
#define CCCR_PXHD 0x1000U
#define CCCR_EFBI 0x2000U
#define RAM_FLS 0x000U
#define RAM_FLE 0x070U
#define RAM_TXB 0x278U

static int setup(void **state)
{
	(void)state;
	sim_reset();
	return 0;
}

static hal_can_frame_t frame(uint32_t id, uint8_t flags, uint8_t dlc, uint8_t seed)
{
	return test_frame(id, flags, dlc, seed, 7U);
}

static void start_both(void)
{
	assert_int_equal(can_ctrl_start(0U, 500000U), SQ_OK);
	assert_int_equal(can_ctrl_start(1U, 500000U), SQ_OK);
}

/* Start at 170 MHz: the words of the configuration. */
static void test_init_registers(void **state)
{
	(void)state;
	start_both();
	/* running: INIT and CCE clear; FD with BRS; no MON, DAR, TEST; EFBI
	 * off (ES0430's edge-filtering desynchronisation); PXHD 0 */
	assert_int_equal(sim_reg(0U, R_CCCR), CCCR_FDOE | CCCR_BRSE);
	assert_int_equal(sim_reg(0U, R_CCCR) & (CCCR_EFBI | CCCR_DAR | CCCR_PXHD | CCCR_TEST), 0U);
	/* 500 kbit/s: NBRP 2, NTSEG1 148, NTSEG2 21, NSJW 21 (fields - 1) */
	assert_int_equal(sim_reg(0U, R_NBTP), (20U << 25) | (1U << 16) | (147U << 8) | 20U);
	/* 2 Mbit/s: TDC, DBRP 5, DTSEG1 12, DTSEG2 4, DSJW 4; TDCO 65 */
	assert_int_equal(sim_reg(0U, R_DBTP), (1U << 23) | (4U << 16) | (11U << 8) | (3U << 4) | 3U);
	assert_int_equal(sim_reg(0U, R_TDCR), 65U << 8);
	/* RXGFC: LSE 8, LSS 14, ANFS = ANFE = 2 (reject), remote frames
	 * filtered, FIFO 0 blocking */
	assert_int_equal(sim_reg(0U, R_RXGFC), (8U << 24) | (14U << 16) | (2U << 4) | (2U << 2));
	assert_int_equal(sim_reg(0U, R_TXBC), 0U); /* TX FIFO mode */
	/* line 0 only, enabled: RF0N, RF0L, TC, EP, EW, BO, PEA, PED */
	assert_int_equal(sim_reg(0U, R_ILS), 0U);
	assert_int_equal(sim_reg(0U, R_ILE), 1U);
	assert_int_equal(sim_reg(0U, R_IE), (1U << 0) | (1U << 2) | (1U << 7) | (1U << 17) | (1U << 18) |
						   (1U << 19) | (1U << 21) | (1U << 22));
	/* every protected write was made with INIT and CCE set */
	assert_int_equal(sim_protected_writes_ignored(0U), 0U);
	assert_int_equal(sim_protected_writes_ignored(1U), 0U);
	/* the accept-all filters: standard id 0 mask 0 (SFT 2, SFEC 1),
	 * extended id 0 mask 0 (EFEC 1 / EFT 2) */
	assert_int_equal(sim_ram(0U, RAM_FLS), 0x88000000U);
	assert_int_equal(sim_ram(0U, RAM_FLE), 0x20000000U);
	assert_int_equal(sim_ram(0U, RAM_FLE + 4U), 0x80000000U);
	assert_int_equal(sim_fault_bits(), 0U);
}

/* Other kernel clocks; an inexact rate leaves the controller untouched. */
static void test_other_clocks_and_inexact_rate(void **state)
{
	(void)state;
	sim_set_kernel_hz(80000000U);
	assert_int_equal(can_ctrl_start(0U, 500000U), SQ_OK);
	assert_int_equal(sim_reg(0U, R_NBTP), (19U << 25) | (0U << 16) | (138U << 8) | 19U);
	assert_int_equal(sim_reg(0U, R_DBTP), (1U << 23) | (0U << 16) | (28U << 8) | (9U << 4) | 9U);
	assert_int_equal(sim_reg(0U, R_TDCR), 30U << 8);
	sim_set_kernel_hz(170000000U);
	assert_int_equal(can_ctrl_start(1U, 500000U), SQ_OK);
	assert_int_equal(hal_can_set_bitrate(1U, 333U), SQ_EINVAL);
	assert_int_equal(sim_reg(1U, R_NBTP), (20U << 25) | (1U << 16) | (147U << 8) | 20U);
	assert_int_equal(sim_reg(1U, R_CCCR) & CCCR_INIT, 0U); /* still running */
}

/* hal_can_set_bitrate takes 1..1000 kbit/s, refused beyond before the
 * rate is turned into bit/s: 536871412 kbit/s times 1000 is 536871412000 =
 * 125 * 2^32 + 500000, which a 32-bit product would take for the
 * 500 kbit/s the bus runs at. Refused (SQ_EINVAL), the bus left running
 * with its timing. */
static void test_rate_beyond_1000_kbps_refused(void **state)
{
	(void)state;
	start_both();
	assert_int_equal(hal_can_set_bitrate(0U, 536871412U), SQ_EINVAL);
	assert_int_equal(hal_can_set_bitrate(0U, 1001U), SQ_EINVAL);
	assert_int_equal(hal_can_set_bitrate(0U, 0U), SQ_EINVAL);
	assert_int_equal(sim_reg(0U, R_NBTP), (20U << 25) | (1U << 16) | (147U << 8) | 20U);
	assert_int_equal(sim_reg(0U, R_CCCR) & CCCR_INIT, 0U);
	assert_int_equal(hal_can_set_bitrate(0U, 1000U), SQ_OK);
}

/* Filter elements' words (RM0440 standard/extended filter elements). */
static void test_filter_elements(void **state)
{
	const hal_can_filter_t f[3] = { { 0x120U, 0x7FFU, 0U },
					{ 0x18DAF110U, 0x1FFFFFFFU, HAL_CAN_FLAG_EXT },
					{ 0x100U, 0x700U, 0U } };
	hal_can_filter_t many_ext[9];
	uint32_t i;

	(void)state;
	start_both();
	assert_int_equal(hal_can_set_rx_filter(1U, f, 3U), SQ_OK);
	/* SFT 2 (classic), SFEC 1 (FIFO 0): 0x88000000 | SFID1 << 16 | SFID2 */
	assert_int_equal(sim_ram(1U, RAM_FLS + 0U), 0x892007FFU);
	assert_int_equal(sim_ram(1U, RAM_FLS + 4U), 0x89000700U);
	for (i = 2U; i < 14U; i++) {
		assert_int_equal(sim_ram(1U, RAM_FLS + 4U * i) >> 27, 0U); /* SFEC 0: disabled */
	}
	/* F0: EFEC 1 << 29 | EFID1; F1: EFT 2 << 30 | EFID2 */
	assert_int_equal(sim_ram(1U, RAM_FLE), 0x38DAF110U);
	assert_int_equal(sim_ram(1U, RAM_FLE + 4U), 0x9FFFFFFFU);
	for (i = 1U; i < 8U; i++) {
		assert_int_equal(sim_ram(1U, RAM_FLE + 8U * i) >> 29, 0U);
	}
	/* bus 0's elements are its own (its RAM block 0x350 bytes lower) */
	assert_int_equal(sim_ram(0U, RAM_FLS), 0x88000000U);
	/* nine extended filters: only 8 elements, refused, nothing changed */
	for (i = 0U; i < 9U; i++) {
		many_ext[i] = (hal_can_filter_t){ 0x1000U + i, 0x1FFFFFFFU, HAL_CAN_FLAG_EXT };
	}
	assert_int_equal(hal_can_set_rx_filter(1U, many_ext, 9U), SQ_ENOTSUP);
	assert_int_equal(sim_ram(1U, RAM_FLE), 0x38DAF110U);
	assert_int_equal(sim_ram(1U, RAM_FLS + 0U), 0x892007FFU);
}

/* The TX buffer element layout: T0 ESI | XTD | RTR | id (standard in
 * 28:18), T1 FDF | BRS | DLC << 16, data little-endian per word. */
static void test_tx_element_layout(void **state)
{
	const hal_can_frame_t fd = frame(0x1ABCDE01U, HAL_CAN_FLAG_EXT | HAL_CAN_FLAG_FDF | HAL_CAN_FLAG_BRS |
							    HAL_CAN_FLAG_ESI, 12U, 0x10U);
	const hal_can_frame_t classic = frame(0x123U, 0U, 3U, 0x40U);
	const hal_can_frame_t remote = { .id = 0x7FFU, .flags = HAL_CAN_FLAG_RTR, .dlc = 5U };

	(void)state;
	start_both();
	sim_block_tx(0U, true); /* nothing leaves: the elements stay */
	assert_int_equal(hal_can_send(0U, &fd), SQ_OK);
	assert_int_equal(hal_can_send(0U, &classic), SQ_OK);
	assert_int_equal(hal_can_send(0U, &remote), SQ_OK);
	assert_int_equal(sim_reg(0U, R_TXBRP), 7U);
	assert_int_equal(sim_ram(0U, RAM_TXB), 0xC0000000U | 0x1ABCDE01U);
	assert_int_equal(sim_ram(0U, RAM_TXB + 4U), (1U << 21) | (1U << 20) | (9U << 16)); /* 12 bytes: DLC 9 */
	assert_int_equal(sim_ram(0U, RAM_TXB + 8U), 0x251E1710U);  /* 0x10, 0x17, 0x1E, 0x25 */
	assert_int_equal(sim_ram(0U, RAM_TXB + 12U), 0x413A332CU); /* 0x2C, 0x33, 0x3A, 0x41 */
	assert_int_equal(sim_ram(0U, RAM_TXB + 16U), 0x5D564F48U); /* bytes 8..11 */
	/* second buffer 72 bytes on */
	assert_int_equal(sim_ram(0U, RAM_TXB + 72U), 0x123U << 18);
	assert_int_equal(sim_ram(0U, RAM_TXB + 72U + 4U), 3U << 16);
	assert_int_equal(sim_ram(0U, RAM_TXB + 72U + 8U) & 0xFFFFFFU, 0x4E4740U);
	assert_int_equal(sim_ram(0U, RAM_TXB + 144U), (1U << 29) | (0x7FFU << 18));
	assert_int_equal(sim_ram(0U, RAM_TXB + 144U + 4U), 5U << 16);
	sim_block_tx(0U, false);
	sim_advance_us(100U);
	assert_int_equal(sim_wire_count(0U), 3U);
}

/* Received frames through RX FIFO 0; a fourth frame while the interrupt
 * is held: message lost, counted once, the three kept in order. */
static void test_rx_fifo_lost(void **state)
{
	hal_can_frame_t in[4];
	hal_can_frame_t got;
	hal_can_status_t st;
	uint32_t primask;
	uint32_t i;

	(void)state;
	start_both();
	primask = cm_irq_save();
	for (i = 0U; i < 4U; i++) {
		in[i] = frame(0x200U + i, HAL_CAN_FLAG_FDF, 64U, (uint8_t)i);
		(void)sim_inject(0U, &in[i]);
	}
	assert_int_equal(sim_rx_lost(0U), 1U);
	cm_irq_restore(primask);
	for (i = 0U; i < 3U; i++) {
		assert_int_equal(hal_can_receive(0U, &got), SQ_OK);
		assert_int_equal(got.id, in[i].id);
		assert_int_equal(got.dlc, 64U);
		assert_memory_equal(got.data, in[i].data, 64U);
	}
	assert_int_equal(hal_can_receive(0U, &got), SQ_EAGAIN);
	assert_int_equal(sim_reg(0U, R_RXF0S) & 0xFU, 0U); /* all acknowledged */
	assert_int_equal(hal_can_get_status(0U, &st), SQ_OK);
	assert_int_equal(st.rx_overruns, 1U);
}

/* Listen-only = bus monitoring: CCCR.MON, no ACK, no error flag, sends
 * refused; FDCAN2 on the same wire gets no ACK from FDCAN1 and its frame
 * stays pending until FDCAN1 is back to normal. */
static void test_monitoring_mode(void **state)
{
	const hal_can_frame_t f = frame(0x321U, HAL_CAN_FLAG_FDF | HAL_CAN_FLAG_BRS, 16U, 1U);
	hal_can_frame_t got;

	(void)state;
	start_both();
	sim_connect(true);
	assert_int_equal(hal_can_set_mode(0U, HAL_CAN_MODE_LISTEN_ONLY), SQ_OK);
	assert_int_equal(sim_reg(0U, R_CCCR), CCCR_FDOE | CCCR_BRSE | CCCR_MON);
	assert_int_equal(hal_can_send(0U, &f), SQ_EPERM);
	sim_error_frame(0U);
	assert_int_equal(sim_dominant_count(0U), 0U); /* no error flag */
	assert_int_equal(hal_can_send(1U, &f), SQ_OK);
	sim_advance_us(1000U);
	assert_int_equal(sim_reg(1U, R_TXBRP), 1U); /* no ACK: still pending */
	assert_int_equal(sim_dominant_count(0U), 0U);
	(void)hal_can_receive(0U, &got); /* the error frame of the error above */
	assert_int_equal(hal_can_receive(0U, &got), SQ_EAGAIN);
	assert_int_equal(hal_can_set_mode(0U, HAL_CAN_MODE_NORMAL), SQ_OK);
	sim_advance_us(1000U);
	assert_int_equal(sim_reg(1U, R_TXBRP), 0U);
	assert_int_equal(sim_dominant_count(0U), 1U); /* its ACK */
	assert_int_equal(hal_can_receive(0U, &got), SQ_OK);
	assert_int_equal(got.id, 0x321U);
	assert_int_equal(got.flags, HAL_CAN_FLAG_FDF | HAL_CAN_FLAG_BRS);
	assert_memory_equal(got.data, f.data, 16U);
}

/* The self-test: internal loopback (CCCR.TEST + MON, TEST.LBCK), nothing
 * on the wire, the controller left in INIT with test mode off. */
static void test_loopback_selftest(void **state)
{
	(void)state;
	assert_int_equal(can_ctrl_selftest_loopback(0U), SQ_OK);
	assert_int_equal(sim_wire_count(0U), 0U);
	assert_int_equal(sim_dominant_count(0U), 0U);
	assert_int_equal(sim_reg(0U, R_CCCR) & (CCCR_INIT | CCCR_TEST | CCCR_MON), CCCR_INIT);
	assert_int_equal(sim_reg(0U, R_TEST), 0U);
	assert_int_equal(can_ctrl_start(0U, 500000U), SQ_OK);
	assert_int_equal(sim_reg(0U, R_CCCR), CCCR_FDOE | CCCR_BRSE);
	/* a controller that never acknowledges INIT */
	sim_controller_dead(1U, true);
	assert_int_equal(can_ctrl_selftest_loopback(1U), SQ_EAGAIN);
	assert_int_equal(can_ctrl_start(1U, 500000U), SQ_EAGAIN);
	assert_int_equal(sim_fault_bits(), HAL_FAULT_CAN_INIT);
	assert_false(can_ctrl_rx_pending());
}

/* Bus-off: the controller sets INIT, the driver clears it (recovery), the
 * bus reads BUS_OFF until the recessive bits have passed, then active. */
static void test_bus_off_recovery(void **state)
{
	const hal_can_frame_t f = frame(0x100U, 0U, 1U, 0U);
	hal_can_status_t st;

	(void)state;
	start_both();
	assert_false(sim_bus_off(0U, true));
	assert_int_equal(sim_reg(0U, R_CCCR) & CCCR_INIT, 0U); /* recovery started */
	assert_int_equal(hal_can_get_status(0U, &st), SQ_OK);
	assert_int_equal(st.state, HAL_CAN_STATE_BUS_OFF);
	assert_int_equal(st.bus_off_count, 1U);
	assert_int_equal(hal_can_send(0U, &f), SQ_ENETUNREACH);
	assert_true(sim_bus_off(0U, false));
	assert_int_equal(hal_can_get_status(0U, &st), SQ_OK);
	assert_int_equal(st.state, HAL_CAN_STATE_ERROR_ACTIVE);
	assert_int_equal(st.tx_error_count, 0U);
	assert_int_equal(hal_can_send(0U, &f), SQ_OK);
}

/* ECR and PSR: warning at 96, passive at 128; a protocol exception and an
 * error frame each count. */
static void test_error_states(void **state)
{
	hal_can_status_t st;
	hal_can_frame_t got;

	(void)state;
	start_both();
	sim_set_counters(1U, 100U, 5U);
	assert_int_equal(hal_can_get_status(1U, &st), SQ_OK);
	assert_int_equal(st.state, HAL_CAN_STATE_ERROR_WARNING);
	assert_int_equal(st.tx_error_count, 100U);
	assert_int_equal(st.rx_error_count, 5U);
	sim_set_counters(1U, 130U, 5U);
	assert_int_equal(hal_can_get_status(1U, &st), SQ_OK);
	assert_int_equal(st.state, HAL_CAN_STATE_ERROR_PASSIVE);
	assert_int_equal(st.state_changes, 3U); /* stopped->active->warning->passive */
	sim_protocol_exception(1U);
	sim_error_frame(1U);
	assert_int_equal(hal_can_get_status(1U, &st), SQ_OK);
	assert_int_equal(st.error_frames, 2U);
	assert_int_equal(hal_can_receive(1U, &got), SQ_OK);
	assert_int_equal(got.flags, HAL_CAN_FLAG_ERR);
	assert_int_equal(got.id, 0x08U);
	assert_int_equal(got.data[6], 130U);
	assert_int_equal(got.data[7], 6U);
}

/* TX full: 3 in the FIFO + 8 queued, then SQ_ENOBUFS. */
static void test_tx_full(void **state)
{
	const hal_can_frame_t f = frame(0x300U, 0U, 8U, 0U);
	uint32_t i;

	(void)state;
	start_both();
	sim_block_tx(1U, true);
	for (i = 0U; i < 11U; i++) {
		assert_int_equal(hal_can_send(1U, &f), SQ_OK);
	}
	assert_int_equal(hal_can_send(1U, &f), SQ_ENOBUFS);
	sim_block_tx(1U, false);
	sim_advance_us(1000U);
	assert_int_equal(sim_wire_count(1U), 11U);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup(test_init_registers, setup),
		cmocka_unit_test_setup(test_other_clocks_and_inexact_rate, setup),
		cmocka_unit_test_setup(test_rate_beyond_1000_kbps_refused, setup),
		cmocka_unit_test_setup(test_filter_elements, setup),
		cmocka_unit_test_setup(test_tx_element_layout, setup),
		cmocka_unit_test_setup(test_rx_fifo_lost, setup),
		cmocka_unit_test_setup(test_monitoring_mode, setup),
		cmocka_unit_test_setup(test_loopback_selftest, setup),
		cmocka_unit_test_setup(test_bus_off_recovery, setup),
		cmocka_unit_test_setup(test_error_states, setup),
		cmocka_unit_test_setup(test_tx_full, setup),
	};

	return cmocka_run_group_tests_name("fdcan", tests, NULL, NULL);
}
