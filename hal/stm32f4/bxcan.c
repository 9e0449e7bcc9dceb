/* SPDX-License-Identifier: MIT */
/*
 * bxCAN1 driver (RM0090 section 32): the hal_can_* functions of hal.h.
 *
 *   RX: FIFO 0 interrupt -> lock-free single-producer (ISR) / single-
 *       consumer (hal_can_receive) ring; a full ring or a hardware FIFO
 *       overrun (FOVR0) counts in rx_overruns.
 *   TX: hal_can_send() queues in software; the three mailboxes are fed
 *       from the queue in order (TXFP: chronological transmit order) by the
 *       sender and by the mailbox-empty interrupt.
 *   Errors: status-change interrupt counts error frames (LEC), bus-off
 *       events; the controller leaves bus-off by itself (ABOM: after 128 x
 *       11 recessive bits), and TEC/REC are read live.
 * Every wait on the controller is bounded; a controller that does not enter
 * initialisation mode (no clock, no peripheral: QEMU) leaves the interface
 * stopped with HAL_FAULT_CAN_INIT raised, and every call says SQ_ENETDOWN.
 */
#include "bxcan_regs.h"
#include "chip.h"
#include "hal_stm32.h"

#define CAN_BASE CAN1_BASE
#define RX_RING_LEN 32U  /* power of two; 32 frames = 3 ms of a full bus */
#define TX_QUEUE_LEN 16U
#define INAK_TIMEOUT_US 10000UL  /* enter init: end of the current frame  */
#define JOIN_TIMEOUT_US 20000UL  /* leave init: 11 recessive bits         */
#define CAN1_FILTER_BANKS 14U    /* banks 0..13 (CAN2SB reset value 14)  */

_Static_assert((RX_RING_LEN & (RX_RING_LEN - 1U)) == 0U, "ring length must be a power of two");
_Static_assert(HAL_CAN_MAX_FILTERS <= CAN1_FILTER_BANKS, "more filters than CAN1 has banks");

/* This driver runs CAN1 only: bus 0. Any other valid bus is SQ_ENODEV; an
 * index beyond HAL_CAN_BUSES is a programming error. */
static int bus_check(uint8_t bus)
{
	HAL_REQUIRE(bus < HAL_CAN_BUSES);
	return (bus == 0U) ? SQ_OK : SQ_ENODEV;
}

static struct {
	bool started;                 /* controller reached init mode       */
	uint32_t bitrate_bps;         /* rate of the last start attempt     */
	/* RX ring: rx_head written only by the ISR, rx_tail only by
	 * hal_can_receive(); free-running indices, count = head - tail. */
	volatile uint32_t rx_head;
	volatile uint32_t rx_tail;
	hal_can_frame_t rx_ring[RX_RING_LEN];
	/* TX queue: touched with interrupts masked only. */
	hal_can_frame_t tx_queue[TX_QUEUE_LEN];
	uint32_t tx_first;
	uint32_t tx_count;
	volatile uint32_t rx_overruns;
	volatile uint32_t tx_dropped;
	volatile uint32_t error_frames;
	volatile uint32_t bus_off_count;
	volatile bool bus_off_seen;
} can;

static uint32_t pack_word(const uint8_t *d)
{
	return (uint32_t)d[0] | ((uint32_t)d[1] << 8) | ((uint32_t)d[2] << 16) | ((uint32_t)d[3] << 24);
}

static void unpack_word(uint32_t w, uint8_t *d)
{
	d[0] = (uint8_t)(w & 0xFFU);
	d[1] = (uint8_t)((w >> 8) & 0xFFU);
	d[2] = (uint8_t)((w >> 16) & 0xFFU);
	d[3] = (uint8_t)((w >> 24) & 0xFFU);
}

/* Move queued frames into empty mailboxes. Interrupts masked by caller. */
static void tx_pump(void)
{
	uint32_t i;

	for (i = 0; i < 3U && can.tx_count > 0U; i++) {
		uint32_t tsr = CAN_TSR(CAN_BASE);
		uint32_t mb;
		const hal_can_frame_t *f;
		uint32_t tir;

		if ((tsr & CAN_TSR_TME_ALL) == 0U) {
			return; /* all three busy */
		}
		mb = (tsr & CAN_TSR_CODE_MSK) >> CAN_TSR_CODE_SHIFT; /* next empty */
		if (mb > 2U || (tsr & CAN_TSR_TME(mb)) == 0U) {
			return;
		}
		f = &can.tx_queue[can.tx_first];
		if ((f->flags & HAL_CAN_FLAG_EXT) != 0U) {
			tir = (f->id << CAN_TIR_EXID_SHIFT) | CAN_TIR_IDE;
		} else {
			tir = f->id << CAN_TIR_STID_SHIFT;
		}
		if ((f->flags & HAL_CAN_FLAG_RTR) != 0U) {
			tir |= CAN_TIR_RTR;
		}
		CAN_TDTR(CAN_BASE, mb) = f->dlc;
		CAN_TDLR(CAN_BASE, mb) = pack_word(&f->data[0]);
		CAN_TDHR(CAN_BASE, mb) = pack_word(&f->data[4]);
		CAN_TIR(CAN_BASE, mb) = tir | CAN_TIR_TXRQ;
		can.tx_first = (can.tx_first + 1U) % TX_QUEUE_LEN;
		can.tx_count--;
	}
}

static void filters_accept_all(void)
{
	CAN_FMR(CAN_BASE) |= CAN_FMR_FINIT;
	CAN_FA1R(CAN_BASE) &= ~((1UL << CAN1_FILTER_BANKS) - 1U);
	CAN_FM1R(CAN_BASE) &= ~1UL;  /* bank 0: mask mode            */
	CAN_FS1R(CAN_BASE) |= 1UL;   /* 32-bit                       */
	CAN_FFA1R(CAN_BASE) &= ~1UL; /* FIFO 0                       */
	CAN_FR1(CAN_BASE, 0U) = 0U;  /* id: anything                 */
	CAN_FR2(CAN_BASE, 0U) = 0U;  /* mask: no bit must match      */
	CAN_FA1R(CAN_BASE) |= 1UL;
	CAN_FMR(CAN_BASE) &= ~CAN_FMR_FINIT;
}

int bxcan_start(uint32_t bitrate_bps)
{
	uint32_t btr;
	int rc;

	can.started = false;
	rc = bxcan_bit_timing(chip_apb1_hz(), bitrate_bps, &btr);
	if (rc != SQ_OK) {
		return rc;
	}
	can.bitrate_bps = bitrate_bps;
	chip_can_pins_init();

	/* Leave sleep, request initialisation, wait for the acknowledge. */
	CAN_MCR(CAN_BASE) = (CAN_MCR(CAN_BASE) & ~CAN_MCR_SLEEP) | CAN_MCR_INRQ;
	rc = stm32_wait_reg(&CAN_MSR(CAN_BASE), CAN_MSR_INAK | CAN_MSR_SLAK, CAN_MSR_INAK,
			    INAK_TIMEOUT_US);
	if (rc != SQ_OK) {
		/* Undo the request: leave the controller as we found it. */
		CAN_MCR(CAN_BASE) &= ~CAN_MCR_INRQ;
		stm32_fault_raise(HAL_FAULT_CAN_INIT);
		STM32_TEST_EVENT("can_init_timeout", INAK_TIMEOUT_US);
		return SQ_EAGAIN;
	}
	/* Automatic bus-off recovery, FIFO transmit order, automatic
	 * retransmission, overwrite-protection off (overruns are counted). */
	CAN_MCR(CAN_BASE) = (CAN_MCR(CAN_BASE) & CAN_MCR_DBF) | CAN_MCR_INRQ | CAN_MCR_ABOM | CAN_MCR_TXFP;
	CAN_BTR(CAN_BASE) = btr;
	filters_accept_all();
	can.rx_head = 0U;
	can.rx_tail = 0U;
	can.tx_first = 0U;
	can.tx_count = 0U;
	CAN_ESR(CAN_BASE) = CAN_ESR_LEC_USER << CAN_ESR_LEC_SHIFT;
	CAN_IER(CAN_BASE) = CAN_IER_TMEIE | CAN_IER_FMPIE0 | CAN_IER_FOVIE0 | CAN_IER_EWGIE |
			    CAN_IER_EPVIE | CAN_IER_BOFIE | CAN_IER_LECIE | CAN_IER_ERRIE;
	cm_nvic_enable(CHIP_IRQ_CAN1_TX, CM_PRIO_CAN);
	cm_nvic_enable(CHIP_IRQ_CAN1_RX0, CM_PRIO_CAN);
	cm_nvic_enable(CHIP_IRQ_CAN1_SCE, CM_PRIO_CAN);
	can.started = true;

	/* Join the bus: needs 11 recessive bits. Without a transceiver or with
	 * the bus stuck dominant this does not happen; the controller keeps
	 * trying on its own, and the state reads STOPPED until it has joined. */
	CAN_MCR(CAN_BASE) &= ~CAN_MCR_INRQ;
	rc = stm32_wait_reg(&CAN_MSR(CAN_BASE), CAN_MSR_INAK, 0U, JOIN_TIMEOUT_US);
	if (rc != SQ_OK) {
		stm32_fault_raise(HAL_FAULT_CAN_INIT);
		STM32_TEST_EVENT("can_join_timeout", JOIN_TIMEOUT_US);
		return SQ_EAGAIN;
	}
	return SQ_OK;
}

int hal_can_set_bitrate(uint8_t bus, uint32_t bitrate_kbps)
{
	if (bus_check(bus) != SQ_OK) {
		return SQ_ENODEV;
	}
	if ((bitrate_kbps == 0U) || (bitrate_kbps > 1000U)) {
		return SQ_EINVAL;
	}
	if (can.started && (can.bitrate_bps == bitrate_kbps * 1000U)) {
		return SQ_OK; /* already running at that rate */
	}
	return bxcan_start(bitrate_kbps * 1000U);
}

bool stm32_can_rx_pending(void)
{
	return can.rx_head != can.rx_tail;
}

/* Interface usable for traffic: started and synchronised to the bus. */
static bool can_online(void)
{
	return can.started && (CAN_MSR(CAN_BASE) & CAN_MSR_INAK) == 0U;
}

int hal_can_set_mode(uint8_t bus, hal_can_mode_t mode)
{
	if (bus_check(bus) != SQ_OK) {
		return SQ_ENODEV;
	}
	return (mode == HAL_CAN_MODE_NORMAL) ? SQ_OK : SQ_ENOTSUP;
}

int hal_can_send(uint8_t bus, const hal_can_frame_t *frame)
{
	uint32_t primask;
	uint32_t slot;

	HAL_REQUIRE(frame != NULL);
	if (bus_check(bus) != SQ_OK) {
		return SQ_ENODEV;
	}
	if (frame->dlc > HAL_CAN_MAX_DLEN ||
	    (frame->flags & HAL_CAN_FLAG_ERR) != 0U ||
	    (frame->flags & ~(uint8_t)(HAL_CAN_FLAG_EXT | HAL_CAN_FLAG_RTR)) != 0U) {
		return SQ_EINVAL;
	}
	if ((frame->flags & HAL_CAN_FLAG_EXT) != 0U ? frame->id > 0x1FFFFFFFUL : frame->id > 0x7FFUL) {
		return SQ_EINVAL;
	}
	if (!can_online()) {
		return SQ_ENETDOWN;
	}
	if ((CAN_ESR(CAN_BASE) & CAN_ESR_BOFF) != 0U) {
		return SQ_ENETUNREACH;
	}
	primask = cm_irq_save();
	if (can.tx_count >= TX_QUEUE_LEN) {
		cm_irq_restore(primask);
		return SQ_ENOBUFS;
	}
	slot = (can.tx_first + can.tx_count) % TX_QUEUE_LEN;
	can.tx_queue[slot] = *frame;
	can.tx_count++;
	tx_pump();
	cm_irq_restore(primask);
	return SQ_OK;
}

int hal_can_receive(uint8_t bus, hal_can_frame_t *frame)
{
	uint32_t tail;

	HAL_REQUIRE(frame != NULL);
	if (bus_check(bus) != SQ_OK) {
		return SQ_ENODEV;
	}
	if (!can.started) {
		return SQ_ENETDOWN;
	}
	tail = can.rx_tail;
	if (tail == can.rx_head) {
		return SQ_EAGAIN;
	}
	cm_dmb(); /* read the slot only after seeing the head that covers it */
	*frame = can.rx_ring[tail % RX_RING_LEN];
	cm_dmb(); /* finish reading before handing the slot back */
	can.rx_tail = tail + 1U;
	return SQ_OK;
}

int hal_can_get_status(uint8_t bus, hal_can_status_t *status)
{
	uint32_t esr;

	HAL_REQUIRE(status != NULL);
	if (bus_check(bus) != SQ_OK) {
		return SQ_ENODEV;
	}
	status->mode = HAL_CAN_MODE_NORMAL;
	status->tx_refused_listen_only = 0U;
	esr = can.started ? CAN_ESR(CAN_BASE) : 0U;
	if (!can_online()) {
		status->state = HAL_CAN_STATE_STOPPED;
	} else if ((esr & CAN_ESR_BOFF) != 0U) {
		status->state = HAL_CAN_STATE_BUS_OFF;
	} else if ((esr & CAN_ESR_EPVF) != 0U) {
		status->state = HAL_CAN_STATE_ERROR_PASSIVE;
	} else if ((esr & CAN_ESR_EWGF) != 0U) {
		status->state = HAL_CAN_STATE_ERROR_WARNING;
	} else {
		status->state = HAL_CAN_STATE_ERROR_ACTIVE;
	}
	status->tx_error_count = (uint8_t)((esr >> CAN_ESR_TEC_SHIFT) & 0xFFU);
	status->rx_error_count = (uint8_t)((esr >> CAN_ESR_REC_SHIFT) & 0xFFU);
	status->bus_off_count = can.bus_off_count;
	status->rx_overruns = can.rx_overruns;
	status->tx_dropped = can.tx_dropped;
	status->error_frames = can.error_frames;
	return SQ_OK;
}

/* One filter per bank, 32-bit mask mode: FR1 holds the identifier and FR2
 * the mask in the RIR layout (STID 31:21 or EXID 31:3, IDE bit 2); IDE is
 * always in the mask so a filter matches its own kind only, RTR never (data
 * and remote frames alike). */
static uint32_t filter_word(uint32_t id, bool ext)
{
	return ext ? ((id << CAN_TIR_EXID_SHIFT) | CAN_TIR_IDE) : (id << CAN_TIR_STID_SHIFT);
}

int hal_can_set_rx_filter(uint8_t bus, const hal_can_filter_t *filters, uint32_t count)
{
	uint32_t b;

	HAL_REQUIRE((count <= HAL_CAN_MAX_FILTERS) && ((count == 0U) || (filters != NULL)));
	if (bus_check(bus) != SQ_OK) {
		return SQ_ENODEV;
	}
	if (!hal_can_filters_in_range(filters, count)) {
		return SQ_EINVAL;
	}
	CAN_FMR(CAN_BASE) |= CAN_FMR_FINIT;
	CAN_FA1R(CAN_BASE) &= ~((1UL << CAN1_FILTER_BANKS) - 1U);
	for (b = 0; b < count; b++) {
		const bool ext = (filters[b].flags & HAL_CAN_FLAG_EXT) != 0U;

		CAN_FM1R(CAN_BASE) &= ~(1UL << b); /* mask mode   */
		CAN_FS1R(CAN_BASE) |= 1UL << b;    /* 32-bit      */
		CAN_FFA1R(CAN_BASE) &= ~(1UL << b); /* FIFO 0     */
		CAN_FR1(CAN_BASE, b) = filter_word(filters[b].id, ext);
		CAN_FR2(CAN_BASE, b) = filter_word(filters[b].mask, ext) | CAN_TIR_IDE;
		CAN_FA1R(CAN_BASE) |= 1UL << b;
	}
	CAN_FMR(CAN_BASE) &= ~CAN_FMR_FINIT;
	return SQ_OK;
}

void CAN1_RX0_IRQHandler(void)
{
	uint32_t i;
	uint64_t now_us = hal_time_us();

	if ((CAN_RF0R(CAN_BASE) & CAN_RF0R_FOVR0) != 0U) {
		can.rx_overruns++;
		CAN_RF0R(CAN_BASE) = CAN_RF0R_FOVR0; /* write 1 to clear */
	}
	/* At most the three frames the FIFO holds. */
	for (i = 0; i < 3U && (CAN_RF0R(CAN_BASE) & CAN_RF0R_FMP0_MSK) != 0U; i++) {
		uint32_t rir = CAN_RIR(CAN_BASE, 0U);
		uint32_t rdtr = CAN_RDTR(CAN_BASE, 0U);
		uint32_t head = can.rx_head;

		if (head - can.rx_tail >= RX_RING_LEN) {
			can.rx_overruns++;
		} else {
			hal_can_frame_t *f = &can.rx_ring[head % RX_RING_LEN];
			uint32_t dlc = rdtr & CAN_RDTR_DLC_MSK;

			f->flags = 0U;
			if ((rir & CAN_RIR_IDE) != 0U) {
				f->id = rir >> CAN_TIR_EXID_SHIFT;
				f->flags |= HAL_CAN_FLAG_EXT;
			} else {
				f->id = rir >> CAN_TIR_STID_SHIFT;
			}
			if ((rir & CAN_RIR_RTR) != 0U) {
				f->flags |= HAL_CAN_FLAG_RTR;
			}
			f->dlc = (uint8_t)(dlc > HAL_CAN_MAX_DLEN ? HAL_CAN_MAX_DLEN : dlc);
			unpack_word(CAN_RDLR(CAN_BASE, 0U), &f->data[0]);
			unpack_word(CAN_RDHR(CAN_BASE, 0U), &f->data[4]);
			f->timestamp_us = now_us;
			cm_dmb(); /* the frame is complete before the head moves */
			can.rx_head = head + 1U;
		}
		CAN_RF0R(CAN_BASE) = CAN_RF0R_RFOM0; /* release the FIFO slot */
	}
}

void CAN1_TX_IRQHandler(void)
{
	uint32_t tsr = CAN_TSR(CAN_BASE);
	uint32_t clear = 0U;
	uint32_t mb;

	for (mb = 0; mb < 3U; mb++) {
		if ((tsr & CAN_TSR_RQCP(mb)) != 0U) {
			/* done: sent, or aborted with an error (TERR). With
			 * automatic retransmission only an abort ends it unsent. */
			if ((tsr & CAN_TSR_TERR(mb)) != 0U) {
				can.tx_dropped++;
			}
			clear |= CAN_TSR_RQCP(mb); /* clears TXOK, ALST, TERR too */
		}
	}
	CAN_TSR(CAN_BASE) = clear;
	tx_pump(); /* interrupts of this priority are not re-entered */
}

void CAN1_SCE_IRQHandler(void)
{
	uint32_t esr = CAN_ESR(CAN_BASE);
	uint32_t lec = (esr & CAN_ESR_LEC_MSK) >> CAN_ESR_LEC_SHIFT;
	bool boff = (esr & CAN_ESR_BOFF) != 0U;

	if (lec != 0U && lec != CAN_ESR_LEC_USER) {
		can.error_frames++;
		CAN_ESR(CAN_BASE) = CAN_ESR_LEC_USER << CAN_ESR_LEC_SHIFT;
	}
	if (boff && !can.bus_off_seen) {
		can.bus_off_count++;
	}
	can.bus_off_seen = boff;
	CAN_MSR(CAN_BASE) = CAN_MSR_ERRI; /* write 1 to clear */
}
