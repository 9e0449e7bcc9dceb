/* SPDX-License-Identifier: MIT */
/*
 * bxCAN driver (RM0090 section 32; RM0008 section 24): the hal_can_* calls
 * of hal.h for CAN1 and, on chips that have it, CAN2 (bus 0 and bus 1).
 *
 *   RX: FIFO 0 interrupt -> lock-free single-producer (ISR) / single-
 *       consumer (hal_can_receive) ring per bus; a full ring or a hardware
 *       FIFO overrun (FOVR0) counts in rx_overruns.
 *   TX: hal_can_send() queues in software; the three mailboxes are fed
 *       from the queue in order (TXFP: chronological transmit order) by the
 *       sender and by the mailbox-empty interrupt.
 *   Errors: the status-change interrupt counts error frames (LEC), hands
 *       each on as a HAL_CAN_FLAG_ERR frame in the receive ring (as every
 *       backend does; id = SocketCAN error class), and follows the state
 *       (ESR: warning, passive, bus-off) through hal_can_state_change(),
 *       which counts every change and each bus-off entry; the controller
 *       leaves bus-off by itself (ABOM), and TEC/REC are read live.
 *   Filters: 32-bit mask mode, one bank per hal_can_filter_t. The banks live
 *       in CAN1 (the filter master); CAN1 owns banks 0..CAN2SB-1 and CAN2
 *       the rest (CAN2SB = half of them), so CAN2 needs CAN1's clock
 *       (chip_can_pins_init() enables it for either bus).
 *   Listen-only: bxCAN silent mode (BTR.SILM): the controller drives only
 *       recessive bits, so no data frame, ACK or error frame leaves it; the
 *       driver also refuses sends (SQ_EPERM, counted).
 *   CAN FD: bxCAN is a classic controller (8 data bytes, no FDF bit): an FD
 *       frame to send is refused (SQ_ENOTSUP, counted in fd_unsupported),
 *       never cut to 8 bytes; the ECU images build their frames 8 bytes
 *       long (HAL_CAN_CLASSIC_ONLY, hal.h).
 * Every wait on the controller is bounded; a controller that does not enter
 * initialisation mode (no clock, no peripheral: QEMU) leaves that bus
 * stopped with HAL_FAULT_CAN_INIT raised, and its calls say SQ_ENETDOWN.
 * A restart (bit rate, mode) first checks the new timing, then masks the
 * bus's interrupts, aborts the TX mailboxes (ABRQ) and reconfigures.
 */
#include <stddef.h>

#include "bxcan.h"
#include "bxcan_regs.h"
#include "can_ctrl.h"
#include "can_queue.h"
#include "chip.h"
#include "hal.h"
#include "hal_can_common.h"
#include "stm32_platform_faults.h"
#include "stm32_test.h"
#include "stm32_time.h"

#define INAK_TIMEOUT_US 10000U  /* enter init: end of the current frame  */
#define JOIN_TIMEOUT_US 20000U  /* leave init: 11 recessive bits         */
#define LOOPBACK_TIMEOUT_US 5000U /* one frame at 500 kbit/s: 0.3 ms    */
#define BANKS_PER_BUS (CHIP_CAN_FILTER_BANKS / CHIP_CAN_BUSES)
#define FILTER_MASTER CAN1_BASE

_Static_assert(HAL_CAN_MAX_FILTERS <= BANKS_PER_BUS, "more filters than one bus has banks");
_Static_assert(CHIP_CAN_BUSES >= 1U && CHIP_CAN_BUSES <= HAL_CAN_BUSES, "bus count");

typedef struct {
	bool started;                 /* controller configured             */
	uint32_t bitrate_bps;         /* rate of the last start            */
	can_queue_t q;                /* RX ring and TX queue (can_queue.h) */
	volatile uint32_t rx_overruns;
	volatile uint32_t tx_dropped;
} bus_state_t;

typedef struct {
	uintptr_t base;
	uint32_t irq_tx;
	uint32_t irq_rx0;
	uint32_t irq_sce;
} bus_hw_t;

static const bus_hw_t bus_hw[CHIP_CAN_BUSES] = {
	{ CAN1_BASE, CHIP_IRQ_CAN1_TX, CHIP_IRQ_CAN1_RX0, CHIP_IRQ_CAN1_SCE },
#if CHIP_CAN_BUSES > 1
	{ CAN2_BASE, CHIP_IRQ_CAN2_TX, CHIP_IRQ_CAN2_RX0, CHIP_IRQ_CAN2_SCE },
#endif
};

static bus_state_t can_bus[CHIP_CAN_BUSES];
/* Each bus's state, state_changes and bus_off_count (hal_can_state_change),
 * stopped until it starts, and its error_frames: touched with interrupts
 * masked or from the SCE interrupt only; and the firmware's mode and send
 * refusals (mode,
 * tx_refused_listen_only, fd_unsupported: hal_can_send_admit), which only
 * the firmware's thread touches. Apart from can_bus so that only these few
 * bytes are initialised data. */
#define TRACK_STOPPED { .state = HAL_CAN_STATE_STOPPED }
static hal_can_status_t can_track[CHIP_CAN_BUSES] = {
	TRACK_STOPPED,
#if CHIP_CAN_BUSES > 1
	TRACK_STOPPED,
#endif
};

/* A bus index out of hal.h's range is a programming error; a valid index
 * this chip lacks gives NULL (the caller answers SQ_ENODEV). */
static bus_state_t *bxcan_bus_get(uint8_t bus)
{
	HAL_REQUIRE(bus < HAL_CAN_BUSES);
	return bus < CHIP_CAN_BUSES ? &can_bus[bus] : NULL;
}

static int can_wait(uintptr_t base, uint32_t off, uint32_t mask, uint32_t value, uint32_t timeout_us)
{
	stm32_timeout_t t;

	stm32_timeout_start(&t, timeout_us);
	for (;;) {
		if ((can_rd(base, off) & mask) == value) {
			return SQ_OK;
		}
		if (stm32_timeout_expired(&t)) {
			return ((can_rd(base, off) & mask) == value) ? SQ_OK : SQ_EAGAIN;
		}
	}
}

static void can_set(uintptr_t base, uint32_t off, uint32_t bits)
{
	can_wr(base, off, can_rd(base, off) | bits);
}

static void can_clear(uintptr_t base, uint32_t off, uint32_t bits)
{
	can_wr(base, off, can_rd(base, off) & ~bits);
}

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

static void mailbox_write(uintptr_t base, uint32_t mb, const hal_can_frame_t *f)
{
	uint32_t tir;

	if ((f->flags & HAL_CAN_FLAG_EXT) != 0U) {
		tir = (f->id << CAN_TIR_EXID_SHIFT) | CAN_TIR_IDE;
	} else {
		tir = f->id << CAN_TIR_STID_SHIFT;
	}
	if ((f->flags & HAL_CAN_FLAG_RTR) != 0U) {
		tir |= CAN_TIR_RTR;
	}
	can_wr(base, CAN_TDTR(mb), f->dlc);
	can_wr(base, CAN_TDLR(mb), pack_word(&f->data[0]));
	can_wr(base, CAN_TDHR(mb), pack_word(&f->data[4]));
	can_wr(base, CAN_TIR(mb), tir | CAN_TIR_TXRQ);
}

/* FIFO 0's oldest frame into *f, and release it. */
static void fifo0_read(uintptr_t base, hal_can_frame_t *f)
{
	uint32_t rir = can_rd(base, CAN_RIR(0U));
	uint32_t dlc = can_rd(base, CAN_RDTR(0U)) & CAN_RDTR_DLC_MSK;

	f->flags = 0U;
	if ((rir & CAN_RIR_IDE) != 0U) {
		f->id = rir >> CAN_RIR_EXID_SHIFT;
		f->flags |= HAL_CAN_FLAG_EXT;
	} else {
		f->id = rir >> CAN_RIR_STID_SHIFT;
	}
	if ((rir & CAN_RIR_RTR) != 0U) {
		f->flags |= HAL_CAN_FLAG_RTR;
	}
	/* a classic DLC code 9..15 means 8 bytes */
	f->dlc = (uint8_t)(dlc > HAL_CAN_CLASSIC_MAX_DLEN ? HAL_CAN_CLASSIC_MAX_DLEN : dlc);
	unpack_word(can_rd(base, CAN_RDLR(0U)), &f->data[0]);
	unpack_word(can_rd(base, CAN_RDHR(0U)), &f->data[4]);
	can_wr(base, CAN_RF0R, CAN_RF0R_RFOM0); /* release the FIFO slot */
}

/* Move queued frames into empty mailboxes. Interrupts masked by caller. */
static void tx_pump(uint8_t bus)
{
	bus_state_t *st = &can_bus[bus];
	uintptr_t base = bus_hw[bus].base;
	uint32_t i;

	for (i = 0; i < 3U && can_queue_tx_peek(&st->q) != NULL; i++) {
		uint32_t tsr = can_rd(base, CAN_TSR);
		uint32_t mb;

		if ((tsr & CAN_TSR_TME_ALL) == 0U) {
			return; /* all three busy */
		}
		mb = (tsr & CAN_TSR_CODE_MSK) >> CAN_TSR_CODE_SHIFT; /* next empty */
		if (mb > 2U || (tsr & CAN_TSR_TME(mb)) == 0U) {
			return;
		}
		mailbox_write(base, mb, can_queue_tx_peek(&st->q));
		can_queue_tx_pop(&st->q);
	}
}

/* Filter word of 32-bit scale: STID in 31:21, EXID in 31:3, IDE bit 2. */
static uint32_t filter_word(uint32_t id, bool ext)
{
	return ext ? ((id << CAN_RIR_EXID_SHIFT) | CAN_FR_IDE) : (id << CAN_RIR_STID_SHIFT);
}

/*
 * Write this bus's banks: one 32-bit mask-mode bank per filter, FIFO 0.
 * filters == NULL with count 1: accept every frame (id 0, mask 0). The IDE
 * bit is always in the mask, so a standard filter never passes an extended
 * frame and the other way round; RTR is never in the mask (hal.h: data and
 * remote frames pass alike).
 */
static void filter_banks_write(uint8_t bus, const hal_can_filter_t *filters, uint32_t count)
{
	const uint32_t first = (uint32_t)bus * BANKS_PER_BUS;
	const uint32_t own = ((1U << BANKS_PER_BUS) - 1U) << first;
	uint32_t active = 0U;
	uint32_t fmr = can_rd(FILTER_MASTER, CAN_FMR) | CAN_FMR_FINIT;
	uint32_t i;

#if CHIP_CAN_BUSES > 1
	fmr = (fmr & ~CAN_FMR_CAN2SB_MSK) | ((uint32_t)BANKS_PER_BUS << CAN_FMR_CAN2SB_SHIFT);
#endif
	can_wr(FILTER_MASTER, CAN_FMR, fmr);
	can_clear(FILTER_MASTER, CAN_FA1R, own);
	can_clear(FILTER_MASTER, CAN_FM1R, own);  /* mask mode */
	can_set(FILTER_MASTER, CAN_FS1R, own);    /* 32-bit    */
	can_clear(FILTER_MASTER, CAN_FFA1R, own); /* FIFO 0    */
	for (i = 0; i < count; i++) {
		uint32_t bank = first + i;

		if (filters == NULL) {
			can_wr(FILTER_MASTER, CAN_FR1(bank), 0U);
			can_wr(FILTER_MASTER, CAN_FR2(bank), 0U);
		} else {
			bool ext = (filters[i].flags & HAL_CAN_FLAG_EXT) != 0U;

			can_wr(FILTER_MASTER, CAN_FR1(bank), filter_word(filters[i].id, ext));
			can_wr(FILTER_MASTER, CAN_FR2(bank), filter_word(filters[i].mask, ext) | CAN_FR_IDE);
		}
		active |= 1U << bank;
	}
	can_set(FILTER_MASTER, CAN_FA1R, active);
	can_clear(FILTER_MASTER, CAN_FMR, CAN_FMR_FINIT);
}

static void irqs_enable(uint8_t bus, bool on)
{
	const bus_hw_t *hw = &bus_hw[bus];

	if (on) {
		cm_nvic_enable(hw->irq_tx, CM_PRIO_CAN);
		cm_nvic_enable(hw->irq_rx0, CM_PRIO_CAN);
		cm_nvic_enable(hw->irq_sce, CM_PRIO_CAN);
	} else {
		cm_nvic_disable(hw->irq_tx);
		cm_nvic_disable(hw->irq_rx0);
		cm_nvic_disable(hw->irq_sce);
	}
}

/* Usable for traffic: started and synchronised to the bus. */
static bool can_online(uint8_t bus)
{
	return can_bus[bus].started && (can_rd(bus_hw[bus].base, CAN_MSR) & CAN_MSR_INAK) == 0U;
}

/* The controller's state now: stopped until it has joined the bus, then
 * as ESR's flags say (bus-off over passive over warning). */
static hal_can_state_t state_now(uint8_t bus)
{
	hal_can_state_t state = HAL_CAN_STATE_STOPPED;

	if (can_online(bus)) {
		const uint32_t esr = can_rd(bus_hw[bus].base, CAN_ESR);

		if ((esr & CAN_ESR_BOFF) != 0U) {
			state = HAL_CAN_STATE_BUS_OFF;
		} else if ((esr & CAN_ESR_EPVF) != 0U) {
			state = HAL_CAN_STATE_ERROR_PASSIVE;
		} else if ((esr & CAN_ESR_EWGF) != 0U) {
			state = HAL_CAN_STATE_ERROR_WARNING;
		} else {
			state = HAL_CAN_STATE_ERROR_ACTIVE;
		}
	}
	return state;
}

/* Follow the state (counted by hal_can_state_change). From the SCE
 * interrupt, or with interrupts masked. */
static void state_follow(uint8_t bus)
{
	(void)hal_can_state_change(&can_track[bus], state_now(bus));
}

/* Stop the bus (its interrupts off, TX mailboxes aborted) and wait for
 * initialisation mode. SQ_OK or SQ_EAGAIN (fault raised). */
static int enter_init(uint8_t bus)
{
	uintptr_t base = bus_hw[bus].base;
	uint32_t primask;
	int rc;

	chip_can_pins_init(bus);
	primask = cm_irq_save();
	can_bus[bus].started = false;
	state_follow(bus);
	irqs_enable(bus, false);
	can_wr(base, CAN_TSR, CAN_TSR_ABRQ(0U) | CAN_TSR_ABRQ(1U) | CAN_TSR_ABRQ(2U));
	can_wr(base, CAN_MCR, (can_rd(base, CAN_MCR) & ~CAN_MCR_SLEEP) | CAN_MCR_INRQ);
	cm_irq_restore(primask);
	rc = can_wait(base, CAN_MSR, CAN_MSR_INAK | CAN_MSR_SLAK, CAN_MSR_INAK, INAK_TIMEOUT_US);
	if (rc != SQ_OK) {
		/* Undo the request: leave the controller as we found it. */
		can_clear(base, CAN_MCR, CAN_MCR_INRQ);
		stm32_fault_raise(HAL_FAULT_CAN_INIT);
		STM32_TEST_EVENT("can_init_timeout", bus);
		return SQ_EAGAIN;
	}
	return SQ_OK;
}

/* In initialisation mode: controller options, timing, accept-all filter,
 * empty queues. Automatic bus-off recovery, FIFO transmit order, automatic
 * retransmission, overwrite protection off (overruns are counted). */
static void configure(uint8_t bus, uint32_t btr, uint32_t ier)
{
	bus_state_t *st = &can_bus[bus];
	uintptr_t base = bus_hw[bus].base;
	uint32_t primask = cm_irq_save();

	can_wr(base, CAN_MCR, (can_rd(base, CAN_MCR) & CAN_MCR_DBF) | CAN_MCR_INRQ | CAN_MCR_ABOM | CAN_MCR_TXFP);
	can_wr(base, CAN_BTR, btr);
	filter_banks_write(bus, NULL, 1U);
	can_queue_reset(&st->q);
	can_wr(base, CAN_TSR, CAN_TSR_RQCP(0U) | CAN_TSR_RQCP(1U) | CAN_TSR_RQCP(2U));
	can_wr(base, CAN_ESR, CAN_ESR_LEC_USER << CAN_ESR_LEC_SHIFT);
	can_wr(base, CAN_IER, ier);
	cm_irq_restore(primask);
}

/* Leave initialisation mode: needs 11 recessive bits on the bus (or, in
 * loopback, internally). SQ_OK or SQ_EAGAIN. */
static int leave_init(uint8_t bus)
{
	uintptr_t base = bus_hw[bus].base;

	can_clear(base, CAN_MCR, CAN_MCR_INRQ);
	return can_wait(base, CAN_MSR, CAN_MSR_INAK, 0U, JOIN_TIMEOUT_US);
}

int bxcan_start(uint8_t bus, uint32_t bitrate_bps)
{
	bus_state_t *st = bxcan_bus_get(bus);
	uint32_t btr;
	uint32_t primask;
	int rc;

	if (st == NULL) {
		return SQ_ENODEV;
	}
	/* The new timing first: a rate the clock cannot make leaves the
	 * running controller untouched. */
	rc = bxcan_bit_timing(chip_apb1_hz(), bitrate_bps, &btr);
	if (rc != SQ_OK) {
		return rc;
	}
	if (can_track[bus].mode == HAL_CAN_MODE_LISTEN_ONLY) {
		btr |= CAN_BTR_SILM;
	}
	rc = enter_init(bus);
	if (rc != SQ_OK) {
		return rc;
	}
	st->bitrate_bps = bitrate_bps;
	configure(bus, btr, CAN_IER_TMEIE | CAN_IER_FMPIE0 | CAN_IER_FOVIE0 | CAN_IER_EWGIE |
				    CAN_IER_EPVIE | CAN_IER_BOFIE | CAN_IER_LECIE | CAN_IER_ERRIE);
	primask = cm_irq_save();
	st->started = true;
	irqs_enable(bus, true);
	cm_irq_restore(primask);

	/* Without a transceiver or with the bus stuck dominant the join does
	 * not happen; the controller keeps trying on its own, and the state
	 * reads STOPPED until it has joined. */
	rc = leave_init(bus);
	if (rc != SQ_OK) {
		stm32_fault_raise(HAL_FAULT_CAN_INIT);
		STM32_TEST_EVENT("can_join_timeout", bus);
		return SQ_EAGAIN;
	}
	return SQ_OK;
}

int bxcan_selftest_loopback(uint8_t bus)
{
	static const hal_can_frame_t probe = {
		.id = 0x15A5C3E7U, .flags = HAL_CAN_FLAG_EXT, .dlc = 8U,
		.data = { 0x55U, 0xAAU, 0x01U, 0x80U, 0xFFU, 0x00U, 0x3CU, 0xC3U },
	};
	bus_state_t *st = bxcan_bus_get(bus);
	uintptr_t base;
	hal_can_frame_t got;
	uint32_t btr;
	int rc;

	if (st == NULL) {
		return SQ_ENODEV;
	}
	base = bus_hw[bus].base;
	if (bxcan_bit_timing(chip_apb1_hz(), BXCAN_DEFAULT_BITRATE, &btr) != SQ_OK) {
		return SQ_EIO;
	}
	rc = enter_init(bus);
	if (rc != SQ_OK) {
		return rc;
	}
	configure(bus, btr | CAN_BTR_SILM | CAN_BTR_LBKM, 0U);
	rc = leave_init(bus);
	if (rc == SQ_OK) {
		mailbox_write(base, 0U, &probe);
		rc = can_wait(base, CAN_RF0R, CAN_RF0R_FMP0_MSK, 1U, LOOPBACK_TIMEOUT_US);
	}
	if (rc == SQ_OK) {
		uint32_t i;

		got.timestamp_us = 0U;
		fifo0_read(base, &got);
		if (got.id != probe.id || got.flags != probe.flags || got.dlc != probe.dlc) {
			rc = SQ_EIO;
		}
		for (i = 0; i < probe.dlc && rc == SQ_OK; i++) {
			if (got.data[i] != probe.data[i]) {
				rc = SQ_EIO;
			}
		}
	} else {
		rc = SQ_EIO;
	}
	/* Back to initialisation mode, loopback off: bxcan_start() follows. */
	can_set(base, CAN_MCR, CAN_MCR_INRQ);
	(void)can_wait(base, CAN_MSR, CAN_MSR_INAK, CAN_MSR_INAK, INAK_TIMEOUT_US);
	can_wr(base, CAN_BTR, btr);
	return rc;
}

int hal_can_set_bitrate(uint8_t bus, uint32_t bitrate_kbps)
{
	bus_state_t *st = bxcan_bus_get(bus);
	uint32_t btr;

	if (st == NULL) {
		return SQ_ENODEV;
	}
	if ((bitrate_kbps == 0U) || (bitrate_kbps > 1000U)) {
		return SQ_EINVAL;
	}
	if (bxcan_bit_timing(chip_apb1_hz(), bitrate_kbps * 1000U, &btr) != SQ_OK) {
		return SQ_EINVAL; /* checked before anything is touched */
	}
	if (st->started && (st->bitrate_bps == bitrate_kbps * 1000U)) {
		return SQ_OK; /* already running at that rate */
	}
	return bxcan_start(bus, bitrate_kbps * 1000U);
}

int hal_can_set_mode(uint8_t bus, hal_can_mode_t mode)
{
	bus_state_t *st = bxcan_bus_get(bus);
	int rc;

	HAL_REQUIRE(mode == HAL_CAN_MODE_NORMAL || mode == HAL_CAN_MODE_LISTEN_ONLY);
	if (st == NULL) {
		return SQ_ENODEV;
	}
	if (st->started && can_track[bus].mode == mode) {
		return SQ_OK;
	}
	can_track[bus].mode = mode;
	rc = bxcan_start(bus, st->bitrate_bps != 0U ? st->bitrate_bps : BXCAN_DEFAULT_BITRATE);
	return rc == SQ_OK ? SQ_OK : SQ_EAGAIN;
}

bool bxcan_rx_pending(void)
{
	uint32_t bus;

	for (bus = 0; bus < CHIP_CAN_BUSES; bus++) {
		if (can_queue_rx_pending(&can_bus[bus].q)) {
			return true;
		}
	}
	return false;
}


int hal_can_send(uint8_t bus, const hal_can_frame_t *frame)
{
	bus_state_t *st = bxcan_bus_get(bus);
	uint32_t primask;
	int queued;
	/* a classic controller: every FD frame is refused */
	const int rc = hal_can_send_admit(frame, (st != NULL) ? &can_track[bus] : NULL, false);

	if (rc != SQ_OK) {
		return rc;
	}
	if (!can_online(bus)) {
		return SQ_ENETDOWN;
	}
	if ((can_rd(bus_hw[bus].base, CAN_ESR) & CAN_ESR_BOFF) != 0U) {
		return SQ_ENETUNREACH;
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
	bus_state_t *st = bxcan_bus_get(bus);
	const int rc = hal_can_receive_admit(frame, st != NULL, (st != NULL) && st->started);

	if (rc != SQ_OK) {
		return rc;
	}
	return can_queue_rx_pop(&st->q, frame);
}

int hal_can_get_status(uint8_t bus, hal_can_status_t *status)
{
	bus_state_t *st = bxcan_bus_get(bus);
	uint32_t esr;
	uint32_t primask;

	HAL_REQUIRE(status != NULL);
	if (st == NULL) {
		return SQ_ENODEV;
	}
	esr = st->started ? can_rd(bus_hw[bus].base, CAN_ESR) : 0U;
	primask = cm_irq_save();
	state_follow(bus); /* a change the SCE interrupt does not signal (leaving bus-off) */
	*status = can_track[bus]; /* state, its counts, error frames, mode, refusals */
	cm_irq_restore(primask);
	status->tx_error_count = (uint8_t)((esr >> CAN_ESR_TEC_SHIFT) & 0xFFU);
	status->rx_error_count = (uint8_t)((esr >> CAN_ESR_REC_SHIFT) & 0xFFU);
	status->rx_overruns = st->rx_overruns;
	status->tx_dropped = st->tx_dropped;
	return SQ_OK;
}

int hal_can_set_rx_filter(uint8_t bus, const hal_can_filter_t *filters, uint32_t count)
{
	bus_state_t *st = bxcan_bus_get(bus);
	const int rc = hal_can_filter_check(filters, count);

	if (rc != SQ_OK) {
		return rc;
	}
	if (st == NULL) {
		return SQ_ENODEV;
	}
	filter_banks_write(bus, filters, count);
	return SQ_OK;
}

static void rx0_irq(uint8_t bus)
{
	bus_state_t *st = &can_bus[bus];
	uintptr_t base = bus_hw[bus].base;
	uint64_t now_us = hal_time_us();
	uint32_t i;

	if ((can_rd(base, CAN_RF0R) & CAN_RF0R_FOVR0) != 0U) {
		st->rx_overruns++;
		can_wr(base, CAN_RF0R, CAN_RF0R_FOVR0); /* write 1 to clear */
	}
	/* At most the three frames the FIFO holds. */
	for (i = 0; i < 3U && (can_rd(base, CAN_RF0R) & CAN_RF0R_FMP0_MSK) != 0U; i++) {
		hal_can_frame_t *f = can_queue_rx_slot(&st->q);

		if (f == NULL) {
			hal_can_frame_t lost;

			st->rx_overruns++;
			fifo0_read(base, &lost);
		} else {
			fifo0_read(base, f);
			f->timestamp_us = now_us;
			can_queue_rx_commit(&st->q);
		}
	}
}

static void tx_irq(uint8_t bus)
{
	uintptr_t base = bus_hw[bus].base;
	uint32_t tsr = can_rd(base, CAN_TSR);
	uint32_t clear = 0U;
	uint32_t mb;

	for (mb = 0; mb < 3U; mb++) {
		if ((tsr & CAN_TSR_RQCP(mb)) != 0U) {
			/* done: sent, or aborted with an error (TERR). With
			 * automatic retransmission only an abort ends it unsent. */
			if ((tsr & CAN_TSR_TERR(mb)) != 0U) {
				can_bus[bus].tx_dropped++;
			}
			clear |= CAN_TSR_RQCP(mb); /* clears TXOK, ALST, TERR too */
		}
	}
	can_wr(base, CAN_TSR, clear);
	tx_pump(bus); /* interrupts of this priority are not re-entered */
}

/*
 * An error the controller saw, handed on like every other backend does: a
 * HAL_CAN_FLAG_ERR frame in the receive ring, its id the error class in
 * SocketCAN's numbering (linux/can/error.h: 0x20 no ACK, 0x08 protocol
 * violation), so the monitor counts it the same way on every backend. The
 * SCE and RX0 interrupts share one priority: still a single producer.
 */
#define ERR_CLASS_PROT 0x08U
#define ERR_CLASS_ACK 0x20U
#define LEC_ACK_ERROR 3U
static void rx_push_error(bus_state_t *st, uint32_t esr, uint32_t lec)
{
	hal_can_frame_t *f = can_queue_rx_slot(&st->q);
	uint32_t i;

	if (f == NULL) {
		st->rx_overruns++;
		return;
	}
	if (lec == LEC_ACK_ERROR) {
		f->id = ERR_CLASS_ACK;
	} else {
		f->id = ERR_CLASS_PROT;
	}
	f->flags = HAL_CAN_FLAG_ERR;
	f->dlc = HAL_CAN_CLASSIC_MAX_DLEN;
	for (i = 0U; i < HAL_CAN_CLASSIC_MAX_DLEN; i++) {
		f->data[i] = 0U;
	}
	f->data[6] = (uint8_t)((esr >> CAN_ESR_TEC_SHIFT) & 0xFFU); /* as SocketCAN */
	f->data[7] = (uint8_t)((esr >> CAN_ESR_REC_SHIFT) & 0xFFU);
	f->timestamp_us = hal_time_us();
	can_queue_rx_commit(&st->q);
}

static void sce_irq(uint8_t bus)
{
	bus_state_t *st = &can_bus[bus];
	uintptr_t base = bus_hw[bus].base;
	uint32_t esr = can_rd(base, CAN_ESR);
	uint32_t lec = (esr & CAN_ESR_LEC_MSK) >> CAN_ESR_LEC_SHIFT;

	if (lec != 0U && lec != CAN_ESR_LEC_USER) {
		can_track[bus].error_frames++;
		can_wr(base, CAN_ESR, CAN_ESR_LEC_USER << CAN_ESR_LEC_SHIFT);
		rx_push_error(st, esr, lec);
	}
	state_follow(bus);
	can_wr(base, CAN_MSR, CAN_MSR_ERRI); /* write 1 to clear */
}

/* can_ctrl.h: the board's controller-neutral names for the three above */
int can_ctrl_start(uint8_t bus, uint32_t bitrate_bps)
{
	return bxcan_start(bus, bitrate_bps);
}

int can_ctrl_selftest_loopback(uint8_t bus)
{
	return bxcan_selftest_loopback(bus);
}

bool can_ctrl_rx_pending(void)
{
	return bxcan_rx_pending();
}

void CAN1_TX_IRQHandler(void) { tx_irq(0U); }
void CAN1_RX0_IRQHandler(void) { rx0_irq(0U); }
void CAN1_SCE_IRQHandler(void) { sce_irq(0U); }
#if CHIP_CAN_BUSES > 1
void CAN2_TX_IRQHandler(void) { tx_irq(1U); }
void CAN2_RX0_IRQHandler(void) { rx0_irq(1U); }
void CAN2_SCE_IRQHandler(void) { sce_irq(1U); }
#endif

#if defined(BXCAN_SIM)
/* Host simulation only (tests/hal/stm32f4/bxcan_sim.c): a fresh driver per test. */
void bxcan_sim_driver_reset(void);
void bxcan_sim_driver_reset(void)
{
	uint32_t bus;

	for (bus = 0; bus < CHIP_CAN_BUSES; bus++) {
		can_bus[bus] = (bus_state_t){ 0 };
		can_track[bus] = (hal_can_status_t)TRACK_STOPPED;
	}
}
#endif
