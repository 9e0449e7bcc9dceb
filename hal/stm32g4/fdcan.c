/* SPDX-License-Identifier: MIT */
/*
 * FDCAN driver of the STM32G474 (RM0440 chapter 44, "FD controller area
 * network (FDCAN)"): the hal_can_* calls of hal.h for FDCAN1 (bus 0, the
 * vehicle bus) and FDCAN2 (bus 1, the output bus), classic and FD frames of
 * up to 64 bytes with FDF/BRS/ESI, and the board's controller-neutral calls
 * (can_ctrl_start, can_ctrl_selftest_loopback, can_ctrl_rx_pending).
 *
 *   Message RAM: the G4's fixed layout (RM0440 section 44.3.3,
 *       fdcan_regs.h): 14 of the 28 standard and all 8 extended filter
 *       elements, RX FIFO 0 (3 elements of 64 data bytes), the TX FIFO
 *       (3 elements); FIFO 1 and the TX event FIFO unused.
 *   RX: every interrupt on line 0; RX FIFO 0 new message -> lock-free
 *       single-producer (ISR) / single-consumer (hal_can_receive) ring per
 *       bus; message lost (IR.RF0L, FIFO 0 in blocking mode) or a full ring
 *       counts in rx_overruns.
 *   TX: hal_can_send() queues in software; the TX FIFO (TXBC.TFQM = 0:
 *       sent in the order put) is fed from the queue by the sender and the
 *       transmission-complete interrupt. Queue and FIFO full: SQ_ENOBUFS.
 *   Errors: a protocol error (IR.PEA, IR.PED) counts in error_frames and is
 *       handed on as a HAL_CAN_FLAG_ERR frame (SocketCAN's classes, as every
 *       backend); PSR's EW/EP/BO go through hal_can_state_change(); TEC/REC
 *       from ECR, read live. Bus-off: the controller sets CCCR.INIT itself
 *       and, unlike bxCAN, never leaves bus-off alone: the interrupt clears
 *       INIT, and the controller rejoins after 129 x 11 recessive bits
 *       (RM0440 section 44.4, FDCAN_CCCR.INIT and FDCAN_PSR.BO).
 *   Protocol exception (PSR.PXE: a frame with the res bit recessive, e.g. a
 *       format newer than CAN FD): CCCR.PXHD = 0 keeps ISO 11898-1:2015's
 *       handling (the controller waits for bus idle instead of sending an
 *       error frame, so it does not destroy frames it cannot read); each
 *       one seen counts in error_frames.
 *   Filters: one classic (filter + mask) element per hal_can_filter_t, the
 *       kind decides the list (standard or extended); RXGFC rejects what no
 *       element accepts. More than 8 extended filters: SQ_ENOTSUP.
 *   Listen-only: bus monitoring mode (CCCR.MON): the controller sends
 *       nothing, not even an ACK or an error flag; sends refused (SQ_EPERM,
 *       counted).
 * Every wait on the controller is bounded in real time; a controller that
 * does not acknowledge INIT (no clock, QEMU) leaves its bus stopped with
 * HAL_FAULT_CAN_INIT raised, and its calls say SQ_ENETDOWN. A restart (bit
 * rate, mode) checks the new timing first, then masks the bus's interrupt
 * and reconfigures in initialisation mode.
 *
 * ES0430 (STM32G471/473/474/483/484 errata), FDCAN limitations checked:
 *   "Desynchronization under specific condition with edge filtering
 *   enabled": worked around (CCCR.EFBI kept 0, in configure()).
 *   "Tx FIFO messages inverted under specific buffer usage and priority
 *   setting": needs dedicated TX buffers beside the FIFO; the driver uses
 *   the TX FIFO only (in configure()), so it does not apply.
 *   "DAR mode transmission failure due to lost arbitration": needs
 *   CCCR.DAR = 1; the driver keeps automatic retransmission (DAR = 0).
 */
#include <stddef.h>

#include "can_queue.h"
#include "chip.h"
#include "fdcan.h"
#include "fdcan_regs.h"
#include "hal.h"
#include "hal_can_common.h"
#include "stm32_platform_faults.h"
#include "stm32_test.h"
#include "stm32_time.h"

#define FDCAN_BUSES 2U
#define INIT_TIMEOUT_US 10000U    /* INIT read back: end of the current frame */
#define JOIN_TIMEOUT_US 20000U    /* leave INIT: 11 recessive bits */
#define LOOPBACK_TIMEOUT_US 5000U /* one 16-byte frame at 500k/2M: 0.1 ms */
#define STD_FILTERS HAL_CAN_MAX_FILTERS

_Static_assert(HAL_CAN_MAX_FILTERS <= SRAMCAN_FLS_NBR, "more filters than standard elements");
_Static_assert(HAL_CAN_MAX_DLEN == HAL_CAN_FD_MAX_DLEN, "the FDCAN image carries FD frames");
_Static_assert(FDCAN_BUSES == HAL_CAN_BUSES, "bus count");

typedef struct {
	bool started;                 /* controller configured             */
	uint32_t bitrate_bps;         /* nominal rate of the last start    */
	can_queue_t q;                /* RX ring and TX queue (can_queue.h) */
	volatile uint32_t rx_overruns;
	volatile uint32_t tx_dropped;
} bus_state_t;

typedef struct {
	uintptr_t base;
	uintptr_t ram;
	uint32_t irq;
} bus_hw_t;

static const bus_hw_t bus_hw[FDCAN_BUSES] = {
	{ FDCAN1_BASE, SRAMCAN_INSTANCE(0U), CHIP_IRQ_FDCAN1_IT0 },
	{ FDCAN2_BASE, SRAMCAN_INSTANCE(1U), CHIP_IRQ_FDCAN2_IT0 },
};

static bus_state_t can_bus[FDCAN_BUSES];
/* Each bus's state and its counts (hal_can_state_change), error_frames:
 * touched with interrupts masked or from the bus's interrupt only; and the
 * firmware's mode and send refusals (hal_can_send_admit), which only the
 * firmware's thread touches. Apart from can_bus so that only these few
 * bytes are initialised data. */
#define TRACK_STOPPED { .state = HAL_CAN_STATE_STOPPED }
static hal_can_status_t can_track[FDCAN_BUSES] = { TRACK_STOPPED, TRACK_STOPPED };

static bus_state_t *fdcan_bus_get(uint8_t bus)
{
	HAL_REQUIRE(bus < HAL_CAN_BUSES);
	return &can_bus[bus];
}

static uint32_t reg_rd(uint8_t bus, uint32_t off)
{
	return fd_rd(bus_hw[bus].base + off);
}

static void reg_wr(uint8_t bus, uint32_t off, uint32_t v)
{
	fd_wr(bus_hw[bus].base + off, v);
}

static uint32_t ram_rd(uint8_t bus, uintptr_t off)
{
	return fd_rd(bus_hw[bus].ram + off);
}

static void ram_wr(uint8_t bus, uintptr_t off, uint32_t v)
{
	fd_wr(bus_hw[bus].ram + off, v);
}

static int reg_wait(uint8_t bus, uint32_t off, uint32_t mask, uint32_t value, bool equal,
		    uint32_t timeout_us)
{
	stm32_timeout_t t;

	stm32_timeout_start(&t, timeout_us);
	for (;;) {
		if (((reg_rd(bus, off) & mask) == value) == equal) {
			return SQ_OK;
		}
		if (stm32_timeout_expired(&t)) {
			return (((reg_rd(bus, off) & mask) == value) == equal) ? SQ_OK : SQ_EAGAIN;
		}
	}
}

/* The FDCAN kernel clock as the chip selected it (RCC_CCIPR.FDCANSEL: the
 * crystal on the G474 board, PCLK1 after a fall-back to HSI16);
 * FDCAN_CKDIV stays at /1. */
static uint32_t kernel_hz(void)
{
	return chip_fdcan_kernel_hz();
}

/* ---- message RAM elements --------------------------------------------------- */

static void elem_write(uint8_t bus, uintptr_t at, const hal_can_frame_t *f)
{
	const bool rtr = (f->flags & HAL_CAN_FLAG_RTR) != 0U;
	const uint8_t len = rtr ? 0U : f->dlc;
	uint32_t w0;
	uint32_t w1;
	uint32_t i;

	if ((f->flags & HAL_CAN_FLAG_EXT) != 0U) {
		w0 = (f->id & FDCAN_E0_EXTID_MSK) | FDCAN_E0_XTD;
	} else {
		w0 = f->id << FDCAN_E0_STDID_SHIFT;
	}
	w0 |= rtr ? FDCAN_E0_RTR : 0U;
	w0 |= ((f->flags & HAL_CAN_FLAG_ESI) != 0U) ? FDCAN_E0_ESI : 0U;
	/* a remote frame's DLC is the length it asks for (at most 8) */
	w1 = (uint32_t)(rtr ? f->dlc : hal_can_len_to_dlc(f->dlc)) << FDCAN_E1_DLC_SHIFT;
	w1 |= ((f->flags & HAL_CAN_FLAG_FDF) != 0U) ? FDCAN_E1_FDF : 0U;
	w1 |= ((f->flags & HAL_CAN_FLAG_BRS) != 0U) ? FDCAN_E1_BRS : 0U;
	ram_wr(bus, at, w0);
	ram_wr(bus, at + 4U, w1);
	for (i = 0U; (4U * i) < len; i++) {
		uint32_t w = 0U;
		uint32_t b;

		for (b = 0U; (b < 4U) && ((4U * i + b) < len); b++) {
			w |= (uint32_t)f->data[4U * i + b] << (8U * b);
		}
		ram_wr(bus, at + 8U + 4U * i, w);
	}
}

/* An RX FIFO element into *f: true when it is a frame hal.h allows (the
 * controller never gives another, but a corrupt RAM word must not become
 * a malformed frame). */
static bool elem_read(uint8_t bus, uintptr_t at, hal_can_frame_t *f)
{
	const uint32_t w0 = ram_rd(bus, at);
	const uint32_t w1 = ram_rd(bus, at + 4U);
	const uint8_t code = (uint8_t)((w1 & FDCAN_E1_DLC_MSK) >> FDCAN_E1_DLC_SHIFT);
	uint8_t len;
	uint32_t i;

	f->flags = 0U;
	if ((w0 & FDCAN_E0_XTD) != 0U) {
		f->id = w0 & FDCAN_E0_EXTID_MSK;
		f->flags |= HAL_CAN_FLAG_EXT;
	} else {
		f->id = (w0 >> FDCAN_E0_STDID_SHIFT) & HAL_CAN_STD_ID_MAX;
	}
	if ((w1 & FDCAN_E1_FDF) != 0U) {
		f->flags |= HAL_CAN_FLAG_FDF;
		f->flags |= ((w1 & FDCAN_E1_BRS) != 0U) ? HAL_CAN_FLAG_BRS : 0U;
		f->flags |= ((w0 & FDCAN_E0_ESI) != 0U) ? HAL_CAN_FLAG_ESI : 0U;
		len = hal_can_dlc_to_len(code);
	} else {
		/* a classic DLC code 9..15 means 8 bytes */
		len = (code > HAL_CAN_CLASSIC_MAX_DLEN) ? (uint8_t)HAL_CAN_CLASSIC_MAX_DLEN : code;
	}
	if ((w0 & FDCAN_E0_RTR) != 0U) {
		f->flags |= HAL_CAN_FLAG_RTR;
	}
	f->dlc = len;
	for (i = 0U; ((f->flags & HAL_CAN_FLAG_RTR) == 0U) && ((4U * i) < len); i++) {
		const uint32_t w = ram_rd(bus, at + 8U + 4U * i);
		uint32_t b;

		for (b = 0U; (b < 4U) && ((4U * i + b) < len); b++) {
			f->data[4U * i + b] = (uint8_t)((w >> (8U * b)) & 0xFFU);
		}
	}
	return hal_can_format_ok(f->flags, f->dlc);
}

/* ---- filters ------------------------------------------------------------------ */

/*
 * This bus's filter elements: one classic (id, mask) element per filter in
 * the list of its kind, every other element of the lists RXGFC.LSS/LSE
 * scan disabled (SFEC/EFEC = 0). filters == NULL with count 1: accept every
 * frame (id 0, mask 0 in both lists). Remote frames are filtered as data
 * frames (RXGFC.RRFS/RRFE = 0). The old elements are disabled first, so a
 * frame arriving meanwhile is rejected, never accepted by half a list.
 */
static void filters_write(uint8_t bus, const hal_can_filter_t *filters, uint32_t count)
{
	uint32_t n_std = 0U;
	uint32_t n_ext = 0U;
	uint32_t i;

	for (i = 0U; i < STD_FILTERS; i++) {
		ram_wr(bus, SRAMCAN_FLS + 4U * i, 0U);
	}
	for (i = 0U; i < SRAMCAN_FLE_NBR; i++) {
		ram_wr(bus, SRAMCAN_FLE + SRAMCAN_FLE_BYTES * i, 0U);
	}
	for (i = 0U; i < count; i++) {
		const hal_can_filter_t all_std = { 0U, 0U, 0U };
		const hal_can_filter_t *f = (filters != NULL) ? &filters[i] : &all_std;

		if ((f->flags & HAL_CAN_FLAG_EXT) != 0U) {
			const uintptr_t at = SRAMCAN_FLE + SRAMCAN_FLE_BYTES * n_ext;

			ram_wr(bus, at + 4U, FDCAN_EFT_CLASSIC | f->mask);
			ram_wr(bus, at, FDCAN_EFEC_FIFO0 | f->id);
			n_ext++;
		} else {
			ram_wr(bus, SRAMCAN_FLS + 4U * n_std,
			       FDCAN_SFT_CLASSIC | FDCAN_SFEC_FIFO0 | (f->id << FDCAN_SFID1_SHIFT) | f->mask);
			n_std++;
		}
		if (filters == NULL) {
			ram_wr(bus, SRAMCAN_FLE + 4U, FDCAN_EFT_CLASSIC);
			ram_wr(bus, SRAMCAN_FLE, FDCAN_EFEC_FIFO0);
		}
	}
}

/* ---- state ---------------------------------------------------------------------- */

/* Usable for traffic: started, out of initialisation, joined (not
 * integrating any more). */
static bool can_online(uint8_t bus)
{
	return can_bus[bus].started && ((reg_rd(bus, FDCAN_CCCR) & FDCAN_CCCR_INIT) == 0U) &&
	       (((reg_rd(bus, FDCAN_PSR) & FDCAN_PSR_ACT_MSK) >> FDCAN_PSR_ACT_SHIFT) != FDCAN_PSR_ACT_SYNC);
}

/* The state PSR shows: bus-off over passive over warning; stopped until
 * the bus has been joined (and while initialising, bus-off apart). */
static hal_can_state_t state_of(uint8_t bus, uint32_t psr)
{
	hal_can_state_t state = HAL_CAN_STATE_STOPPED;

	if (!can_bus[bus].started) {
		/* stopped */
	} else if ((psr & FDCAN_PSR_BO) != 0U) {
		state = HAL_CAN_STATE_BUS_OFF;
	} else if (((reg_rd(bus, FDCAN_CCCR) & FDCAN_CCCR_INIT) != 0U) ||
		   (((psr & FDCAN_PSR_ACT_MSK) >> FDCAN_PSR_ACT_SHIFT) == FDCAN_PSR_ACT_SYNC)) {
		/* stopped: initialising or integrating */
	} else if ((psr & FDCAN_PSR_EP) != 0U) {
		state = HAL_CAN_STATE_ERROR_PASSIVE;
	} else if ((psr & FDCAN_PSR_EW) != 0U) {
		state = HAL_CAN_STATE_ERROR_WARNING;
	} else {
		state = HAL_CAN_STATE_ERROR_ACTIVE;
	}
	return state;
}

/* ---- initialisation --------------------------------------------------------------- */

static void irq_enable(uint8_t bus, bool on)
{
	if (on) {
		cm_nvic_enable(bus_hw[bus].irq, CM_PRIO_CAN);
	} else {
		cm_nvic_disable(bus_hw[bus].irq);
	}
}

/* Stop the bus (its interrupt off) and enter initialisation with the
 * configuration unlocked (CCCR.INIT, then CCE; RM0440 section 44.4,
 * FDCAN_CCCR): INIT is read back before CCE is set, since
 * the write crosses into the CAN clock domain. Setting CCE resets the TX
 * FIFO's requests (TXBRP): the frames still queued are given up, counted.
 * SQ_OK or SQ_EAGAIN (fault raised). */
static int enter_init(uint8_t bus)
{
	bus_state_t *st = &can_bus[bus];
	uint32_t primask;
	uint32_t pending;
	uint32_t b;
	int rc;

	chip_can_pins_init(bus);
	primask = cm_irq_save();
	st->started = false;
	(void)hal_can_state_change(&can_track[bus], HAL_CAN_STATE_STOPPED);
	irq_enable(bus, false);
	reg_wr(bus, FDCAN_CCCR, reg_rd(bus, FDCAN_CCCR) | FDCAN_CCCR_INIT);
	cm_irq_restore(primask);
	rc = reg_wait(bus, FDCAN_CCCR, FDCAN_CCCR_INIT, FDCAN_CCCR_INIT, true, INIT_TIMEOUT_US);
	if (rc != SQ_OK) {
		stm32_fault_raise(HAL_FAULT_CAN_INIT);
		STM32_TEST_EVENT("can_init_timeout", bus);
		return SQ_EAGAIN;
	}
	pending = reg_rd(bus, FDCAN_TXBRP) & FDCAN_TXB_ALL;
	for (b = 0U; b < SRAMCAN_TXB_NBR; b++) {
		st->tx_dropped += (pending >> b) & 1U;
	}
	st->tx_dropped += st->q.tx_count;
	reg_wr(bus, FDCAN_CCCR, reg_rd(bus, FDCAN_CCCR) | FDCAN_CCCR_CCE);
	return SQ_OK;
}

#define CCCR_LOOPBACK (FDCAN_CCCR_TEST | FDCAN_CCCR_MON)

/*
 * In initialisation mode with CCE: the operating mode (cccr_mode: 0, MON,
 * or TEST | MON for the internal loopback), FD with bit rate switching,
 * bit timing with transmitter delay compensation, the accept-all filters,
 * FIFO 0 blocking, the TX FIFO, the interrupts (all on line 0), empty
 * software queues.
 */
static void configure(uint8_t bus, const fdcan_timing_t *t, uint32_t cccr_mode, uint32_t ie)
{
	bus_state_t *st = &can_bus[bus];
	const uint32_t primask = cm_irq_save();

	/* CCCR: FDOE + BRSE (FD frames, BRS honoured); DAR = 0 (automatic
	 * retransmission: ES0430 "DAR mode transmission failure due to lost
	 * arbitration" needs DAR = 1, so it does not apply); EFBI = 0: ES0430
	 * "Desynchronization under specific condition with edge filtering
	 * enabled", worked around by keeping edge filtering off; PXHD = 0
	 * (protocol exception handling on); NISO = 0 (ISO 11898-1:2015 CRC). */
	reg_wr(bus, FDCAN_CCCR, FDCAN_CCCR_INIT | FDCAN_CCCR_CCE | FDCAN_CCCR_FDOE | FDCAN_CCCR_BRSE |
					cccr_mode);
	/* TEST is writable only once CCCR.TEST is set (and reset while it is
	 * clear); LBCK with MON is the internal loopback (RM0440 section 44.4,
	 * FDCAN_TEST.LBCK). */
	if ((cccr_mode & FDCAN_CCCR_TEST) != 0U) {
		reg_wr(bus, FDCAN_TEST, FDCAN_TEST_LBCK);
	}
	reg_wr(bus, FDCAN_NBTP, t->nbtp);
	reg_wr(bus, FDCAN_DBTP, t->dbtp);
	reg_wr(bus, FDCAN_TDCR, t->tdcr);
	/* Non-matching frames of either kind rejected; remote frames filtered
	 * like data frames; FIFO 0 blocking (F0OM = 0: a full FIFO loses the
	 * new frame, IR.RF0L); the two lists' lengths fixed, their unused
	 * elements disabled (filters_write). */
	reg_wr(bus, FDCAN_RXGFC, ((uint32_t)SRAMCAN_FLE_NBR << FDCAN_RXGFC_LSE_SHIFT) |
					 ((uint32_t)STD_FILTERS << FDCAN_RXGFC_LSS_SHIFT) |
					 (FDCAN_RXGFC_ANF_REJECT << FDCAN_RXGFC_ANFS_SHIFT) |
					 (FDCAN_RXGFC_ANF_REJECT << FDCAN_RXGFC_ANFE_SHIFT));
	reg_wr(bus, FDCAN_XIDAM, FDCAN_E0_EXTID_MSK);
	/* TX FIFO mode (TFQM = 0), the G4's three TX buffers all in it, no
	 * dedicated buffer: ES0430 "Tx FIFO messages inverted under specific
	 * buffer usage and priority setting" needs a dedicated buffer beside
	 * the FIFO, so it does not apply. */
	reg_wr(bus, FDCAN_TXBC, 0U);
	reg_wr(bus, FDCAN_TXBTIE, (ie != 0U) ? FDCAN_TXB_ALL : 0U);
	filters_write(bus, NULL, 1U);
	can_queue_reset(&st->q);
	reg_wr(bus, FDCAN_IR, FDCAN_IR_ALL);
	reg_wr(bus, FDCAN_ILS, 0U);
	reg_wr(bus, FDCAN_IE, ie);
	reg_wr(bus, FDCAN_ILE, (ie != 0U) ? FDCAN_ILE_EINT0 : 0U);
	cm_irq_restore(primask);
}

/* Leave initialisation (clearing INIT also clears CCE) and wait for the
 * join: 11 recessive bits (PSR.ACT leaves "synchronizing"). */
static int leave_init(uint8_t bus)
{
	reg_wr(bus, FDCAN_CCCR, reg_rd(bus, FDCAN_CCCR) & ~(FDCAN_CCCR_INIT | FDCAN_CCCR_CCE));
	return reg_wait(bus, FDCAN_PSR, FDCAN_PSR_ACT_MSK, FDCAN_PSR_ACT_SYNC << FDCAN_PSR_ACT_SHIFT, false,
			JOIN_TIMEOUT_US);
}

#define IE_RUN (FDCAN_IR_RF0N | FDCAN_IR_RF0L | FDCAN_IR_TC | FDCAN_IR_EP | FDCAN_IR_EW | FDCAN_IR_BO | \
		FDCAN_IR_PEA | FDCAN_IR_PED)

int can_ctrl_start(uint8_t bus, uint32_t bitrate_bps)
{
	bus_state_t *st = fdcan_bus_get(bus);
	fdcan_timing_t t;
	uint32_t primask;
	int rc;

	/* The new timing first: a rate the clock cannot make leaves the
	 * running controller untouched. */
	rc = fdcan_bit_timing(kernel_hz(), bitrate_bps, FDCAN_DEFAULT_DATA_BITRATE, &t);
	if (rc != SQ_OK) {
		return rc;
	}
	rc = enter_init(bus);
	if (rc != SQ_OK) {
		return rc;
	}
	st->bitrate_bps = bitrate_bps;
	configure(bus, &t, (can_track[bus].mode == HAL_CAN_MODE_LISTEN_ONLY) ? FDCAN_CCCR_MON : 0U, IE_RUN);
	primask = cm_irq_save();
	st->started = true;
	irq_enable(bus, true);
	cm_irq_restore(primask);
	/* Without a transceiver or with the bus stuck dominant the join does
	 * not happen; the controller keeps integrating, and the state reads
	 * STOPPED until it has joined. */
	rc = leave_init(bus);
	if (rc != SQ_OK) {
		stm32_fault_raise(HAL_FAULT_CAN_INIT);
		STM32_TEST_EVENT("can_join_timeout", bus);
		return SQ_EAGAIN;
	}
	primask = cm_irq_save();
	(void)hal_can_state_change(&can_track[bus], state_of(bus, reg_rd(bus, FDCAN_PSR)));
	cm_irq_restore(primask);
	return SQ_OK;
}

int can_ctrl_selftest_loopback(uint8_t bus)
{
	static const hal_can_frame_t probe = {
		.id = 0x15A5C3E7U, .flags = HAL_CAN_FLAG_EXT | HAL_CAN_FLAG_FDF | HAL_CAN_FLAG_BRS, .dlc = 16U,
		.data = { 0x55U, 0xAAU, 0x01U, 0x80U, 0xFFU, 0x00U, 0x3CU, 0xC3U,
			  0x12U, 0x34U, 0x56U, 0x78U, 0x9AU, 0xBCU, 0xDEU, 0xF0U },
	};
	hal_can_frame_t got;
	fdcan_timing_t t;
	int rc;

	(void)fdcan_bus_get(bus);
	if (fdcan_bit_timing(kernel_hz(), FDCAN_DEFAULT_BITRATE, FDCAN_DEFAULT_DATA_BITRATE, &t) != SQ_OK) {
		return SQ_EIO;
	}
	rc = enter_init(bus);
	if (rc != SQ_OK) {
		return rc;
	}
	configure(bus, &t, CCCR_LOOPBACK, 0U);
	rc = leave_init(bus);
	if (rc == SQ_OK) {
		const uint32_t put = (reg_rd(bus, FDCAN_TXFQS) & FDCAN_TXFQS_TFQPI_MSK) >> FDCAN_TXFQS_TFQPI_SHIFT;

		elem_write(bus, SRAMCAN_TXB + SRAMCAN_ELEM_BYTES * put, &probe);
		reg_wr(bus, FDCAN_TXBAR, 1U << put);
		rc = reg_wait(bus, FDCAN_RXF0S, FDCAN_RXF0S_F0FL_MSK, 0U, false, LOOPBACK_TIMEOUT_US);
	}
	if (rc == SQ_OK) {
		const uint32_t get = (reg_rd(bus, FDCAN_RXF0S) & FDCAN_RXF0S_F0GI_MSK) >> FDCAN_RXF0S_F0GI_SHIFT;
		uint32_t i;

		got.timestamp_us = 0U;
		if (!elem_read(bus, SRAMCAN_RF0 + SRAMCAN_ELEM_BYTES * get, &got) || (got.id != probe.id) ||
		    (got.flags != probe.flags) || (got.dlc != probe.dlc)) {
			rc = SQ_EIO;
		}
		for (i = 0U; (i < probe.dlc) && (rc == SQ_OK); i++) {
			if (got.data[i] != probe.data[i]) {
				rc = SQ_EIO;
			}
		}
		reg_wr(bus, FDCAN_RXF0A, get);
	} else {
		rc = SQ_EIO;
	}
	/* Back to initialisation, test mode off (clearing CCCR.TEST resets
	 * TEST): can_ctrl_start() follows. */
	reg_wr(bus, FDCAN_CCCR, reg_rd(bus, FDCAN_CCCR) | FDCAN_CCCR_INIT);
	(void)reg_wait(bus, FDCAN_CCCR, FDCAN_CCCR_INIT, FDCAN_CCCR_INIT, true, INIT_TIMEOUT_US);
	reg_wr(bus, FDCAN_CCCR, reg_rd(bus, FDCAN_CCCR) | FDCAN_CCCR_CCE);
	reg_wr(bus, FDCAN_CCCR, reg_rd(bus, FDCAN_CCCR) & ~CCCR_LOOPBACK);
	return rc;
}

bool can_ctrl_rx_pending(void)
{
	uint32_t bus;

	for (bus = 0U; bus < FDCAN_BUSES; bus++) {
		if (can_queue_rx_pending(&can_bus[bus].q)) {
			return true;
		}
	}
	return false;
}

/* ---- hal.h -------------------------------------------------------------------------- */

int hal_can_set_bitrate(uint8_t bus, uint32_t bitrate_kbps)
{
	bus_state_t *st = fdcan_bus_get(bus);
	fdcan_timing_t t;

	if ((bitrate_kbps == 0U) || (bitrate_kbps > 1000U) ||
	    (fdcan_bit_timing(kernel_hz(), bitrate_kbps * 1000U, FDCAN_DEFAULT_DATA_BITRATE, &t) != SQ_OK)) {
		return SQ_EINVAL; /* checked before anything is touched */
	}
	if (st->started && (st->bitrate_bps == bitrate_kbps * 1000U)) {
		return SQ_OK; /* already running at that rate */
	}
	return can_ctrl_start(bus, bitrate_kbps * 1000U);
}

int hal_can_set_mode(uint8_t bus, hal_can_mode_t mode)
{
	bus_state_t *st = fdcan_bus_get(bus);
	int rc;

	HAL_REQUIRE((mode == HAL_CAN_MODE_NORMAL) || (mode == HAL_CAN_MODE_LISTEN_ONLY));
	if (st->started && (can_track[bus].mode == mode)) {
		return SQ_OK;
	}
	/* CCCR.MON is a protected bit: a restart sets it */
	can_track[bus].mode = mode;
	rc = can_ctrl_start(bus, (st->bitrate_bps != 0U) ? st->bitrate_bps : FDCAN_DEFAULT_BITRATE);
	return (rc == SQ_OK) ? SQ_OK : SQ_EAGAIN;
}

/* Move queued frames into the TX FIFO while it has room. Interrupts masked
 * by the caller. */
static void tx_pump(uint8_t bus)
{
	bus_state_t *st = &can_bus[bus];
	uint32_t i;

	for (i = 0U; (i < SRAMCAN_TXB_NBR) && (can_queue_tx_peek(&st->q) != NULL); i++) {
		const uint32_t txfqs = reg_rd(bus, FDCAN_TXFQS);
		uint32_t put;

		if ((txfqs & FDCAN_TXFQS_TFQF) != 0U) {
			return; /* all three busy */
		}
		put = (txfqs & FDCAN_TXFQS_TFQPI_MSK) >> FDCAN_TXFQS_TFQPI_SHIFT;
		elem_write(bus, SRAMCAN_TXB + SRAMCAN_ELEM_BYTES * put, can_queue_tx_peek(&st->q));
		reg_wr(bus, FDCAN_TXBAR, 1U << put);
		can_queue_tx_pop(&st->q);
	}
}

int hal_can_send(uint8_t bus, const hal_can_frame_t *frame)
{
	bus_state_t *st = fdcan_bus_get(bus);
	uint32_t primask;
	int queued;
	/* FDCAN carries FD frames: only malformed ones and listen-only refuse */
	const int rc = hal_can_send_admit(frame, &can_track[bus], true);

	if (rc != SQ_OK) {
		return rc;
	}
	if (!st->started) {
		return SQ_ENETDOWN;
	}
	/* before the online check: bus-off sets CCCR.INIT */
	if ((reg_rd(bus, FDCAN_PSR) & FDCAN_PSR_BO) != 0U) {
		return SQ_ENETUNREACH;
	}
	if (!can_online(bus)) {
		return SQ_ENETDOWN;
	}
	primask = cm_irq_save();
	queued = can_queue_tx_push(&st->q, frame);
	if (queued == SQ_OK) {
		tx_pump(bus);
	}
	cm_irq_restore(primask);
	return queued;
}

int hal_can_receive(uint8_t bus, hal_can_frame_t *frame)
{
	bus_state_t *st = fdcan_bus_get(bus);
	const int rc = hal_can_receive_admit(frame, true, st->started);

	if (rc != SQ_OK) {
		return rc;
	}
	return can_queue_rx_pop(&st->q, frame);
}

int hal_can_get_status(uint8_t bus, hal_can_status_t *status)
{
	bus_state_t *st = fdcan_bus_get(bus);
	uint32_t ecr;
	uint32_t primask;

	HAL_REQUIRE(status != NULL);
	ecr = st->started ? reg_rd(bus, FDCAN_ECR) : 0U;
	primask = cm_irq_save();
	/* a join after a slow start raises no interrupt: follow it here */
	(void)hal_can_state_change(&can_track[bus], state_of(bus, reg_rd(bus, FDCAN_PSR)));
	*status = can_track[bus];
	cm_irq_restore(primask);
	status->tx_error_count = (uint8_t)(ecr & FDCAN_ECR_TEC_MSK);
	status->rx_error_count = (uint8_t)((ecr & FDCAN_ECR_REC_MSK) >> FDCAN_ECR_REC_SHIFT);
	status->rx_overruns = st->rx_overruns;
	status->tx_dropped = st->tx_dropped;
	return SQ_OK;
}

int hal_can_set_rx_filter(uint8_t bus, const hal_can_filter_t *filters, uint32_t count)
{
	uint32_t n_ext = 0U;
	uint32_t i;
	const int rc = hal_can_filter_check(filters, count);

	(void)fdcan_bus_get(bus);
	if (rc != SQ_OK) {
		return rc;
	}
	for (i = 0U; i < count; i++) {
		n_ext += ((filters[i].flags & HAL_CAN_FLAG_EXT) != 0U) ? 1U : 0U;
	}
	if (n_ext > SRAMCAN_FLE_NBR) {
		return SQ_ENOTSUP; /* 8 extended filter elements: nothing changed */
	}
	if (!can_bus[bus].started) {
		/* a controller that never acknowledged INIT (no kernel clock, or
		 * QEMU, which maps no FDCAN message RAM): its RAM is not touched */
		return SQ_ENETDOWN;
	}
	filters_write(bus, filters, count);
	return SQ_OK;
}

/* ---- the interrupt ---------------------------------------------------------------- */

/*
 * An error the controller saw, handed on like every other backend does: a
 * HAL_CAN_FLAG_ERR frame in the receive ring, its id the error class in
 * SocketCAN's numbering (linux/can/error.h: 0x20 no ACK, 0x08 protocol
 * violation), TEC/REC in bytes 6 and 7. From the interrupt only.
 */
#define ERR_CLASS_PROT 0x08U
#define ERR_CLASS_ACK 0x20U
static void rx_push_error(uint8_t bus, uint32_t lec)
{
	bus_state_t *st = &can_bus[bus];
	const uint32_t ecr = reg_rd(bus, FDCAN_ECR);
	hal_can_frame_t *f = can_queue_rx_slot(&st->q);
	uint32_t i;

	if (f == NULL) {
		st->rx_overruns++;
		return;
	}
	f->id = (lec == FDCAN_PSR_LEC_ACK) ? ERR_CLASS_ACK : ERR_CLASS_PROT;
	f->flags = HAL_CAN_FLAG_ERR;
	f->dlc = HAL_CAN_CLASSIC_MAX_DLEN;
	for (i = 0U; i < HAL_CAN_CLASSIC_MAX_DLEN; i++) {
		f->data[i] = 0U;
	}
	f->data[6] = (uint8_t)(ecr & FDCAN_ECR_TEC_MSK);
	f->data[7] = (uint8_t)((ecr & FDCAN_ECR_REC_MSK) >> FDCAN_ECR_REC_SHIFT);
	f->timestamp_us = hal_time_us();
	can_queue_rx_commit(&st->q);
}

/* RX FIFO 0 into the ring: at most the three elements it holds; each
 * acknowledged (RXF0A = its get index) once read. */
static void rx_fifo0(uint8_t bus)
{
	bus_state_t *st = &can_bus[bus];
	const uint64_t now_us = hal_time_us();
	uint32_t i;

	for (i = 0U; i < SRAMCAN_RF0_NBR; i++) {
		const uint32_t s = reg_rd(bus, FDCAN_RXF0S);
		const uint32_t get = (s & FDCAN_RXF0S_F0GI_MSK) >> FDCAN_RXF0S_F0GI_SHIFT;
		hal_can_frame_t *f = can_queue_rx_slot(&st->q);

		if ((s & FDCAN_RXF0S_F0FL_MSK) == 0U) {
			break;
		}
		if (f == NULL) {
			st->rx_overruns++;
		} else if (!elem_read(bus, SRAMCAN_RF0 + SRAMCAN_ELEM_BYTES * get, f)) {
			can_track[bus].error_frames++; /* malformed: dropped, counted */
		} else {
			f->timestamp_us = now_us;
			can_queue_rx_commit(&st->q);
		}
		reg_wr(bus, FDCAN_RXF0A, get);
	}
}

static void fdcan_irq(uint8_t bus)
{
	const uint32_t ir = reg_rd(bus, FDCAN_IR);

	reg_wr(bus, FDCAN_IR, ir); /* write 1 to clear what is handled below */
	if ((ir & FDCAN_IR_RF0L) != 0U) {
		can_bus[bus].rx_overruns++;
	}
	if ((ir & (FDCAN_IR_RF0N | FDCAN_IR_RF0L)) != 0U) {
		rx_fifo0(bus);
	}
	if ((ir & (FDCAN_IR_EP | FDCAN_IR_EW | FDCAN_IR_BO | FDCAN_IR_PEA | FDCAN_IR_PED)) != 0U) {
		/* one read: it resets LEC, DLEC and PXE */
		const uint32_t psr = reg_rd(bus, FDCAN_PSR);

		if ((ir & FDCAN_IR_PEA) != 0U) {
			can_track[bus].error_frames++;
			rx_push_error(bus, psr & FDCAN_PSR_LEC_MSK);
		}
		if ((ir & FDCAN_IR_PED) != 0U) {
			can_track[bus].error_frames++;
			rx_push_error(bus, (psr >> FDCAN_PSR_DLEC_SHIFT) & FDCAN_PSR_LEC_MSK);
		}
		if ((psr & FDCAN_PSR_PXE) != 0U) {
			can_track[bus].error_frames++;
		}
		(void)hal_can_state_change(&can_track[bus], state_of(bus, psr));
		if (((psr & FDCAN_PSR_BO) != 0U) && ((reg_rd(bus, FDCAN_CCCR) & FDCAN_CCCR_INIT) != 0U)) {
			/* bus-off recovery (RM0440 section 44.4, FDCAN_CCCR.INIT): clearing INIT
			 * starts it; the controller rejoins after 129 x 11
			 * recessive bits, and IR.BO tells */
			reg_wr(bus, FDCAN_CCCR, reg_rd(bus, FDCAN_CCCR) & ~FDCAN_CCCR_INIT);
		}
	}
	if ((ir & FDCAN_IR_TC) != 0U) {
		tx_pump(bus); /* interrupts of this priority are not re-entered */
	}
}

void FDCAN1_IT0_IRQHandler(void) { fdcan_irq(0U); }
void FDCAN2_IT0_IRQHandler(void) { fdcan_irq(1U); }

#if defined(FDCAN_SIM)
/* Host simulation only (tests/hal/stm32g4/fdcan_sim.c): a fresh driver per test. */
void fdcan_sim_driver_reset(void);
void fdcan_sim_driver_reset(void)
{
	uint32_t bus;

	for (bus = 0U; bus < FDCAN_BUSES; bus++) {
		can_bus[bus] = (bus_state_t){ 0 };
		can_track[bus] = (hal_can_status_t)TRACK_STOPPED;
	}
}
#endif
