/* SPDX-License-Identifier: MIT */
/*
 * Simulated bxCAN pair (see bxcan_sim.h), from RM0090 section 32:
 *   - reset values: MCR 0x00010002 (SLEEP), MSR 0x00000C02 (SLAK),
 *     FMR 0x2A1C0E01 (FINIT, CAN2SB = 14), TSR with all mailboxes empty;
 *   - INRQ -> INAK at once (unless the controller is "dead"), leaving
 *     initialisation mode joins the bus at once;
 *   - BTR, FM1R, FS1R, FFA1R only writable in initialisation mode / FINIT;
 *     a bank's FR1/FR2 only while FINIT or the bank is inactive;
 *   - write-1-to-clear: TSR RQCPx (with TXOK/ALST/TERR), RF0R FOVR0, MSR
 *     ERRI; RF0R RFOM0 releases the FIFO's oldest frame; ABRQx aborts a
 *     pending mailbox (RQCP set, TXOK clear);
 *   - receive: only a running controller (clocked, not initialising, not
 *     asleep) with the filters out of FINIT and CAN1 clocked; the bank
 *     range is 0..CAN2SB-1 for CAN1 and CAN2SB..27 for CAN2; 32/16-bit,
 *     mask/list exactly as figure 342; FIFO 0 three deep, a fourth frame
 *     overwrites the last one and sets FOVR0 (RFLM = 0);
 *   - transmit: oldest request first; SILM alone cannot start a frame;
 *     LBKM feeds the frame back into the receive path (and, without SILM,
 *     onto the wire); an ACK and an error flag are dominant bits a node in
 *     silent mode never drives.
 */
#include "bxcan_sim.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bxcan.h"
#include "bxcan_regs.h"
#include "chip.h"
#include "can_sim.h"
#include "cortex_sim.h"
#include "wire_sim.h"
#include "sq_status.h"

uint32_t bxcan_sim_rcc[64];
uint32_t bxcan_sim_gpiob[16];

#define BANKS 28U

typedef struct {
	uint32_t rir, rdtr, rdlr, rdhr;
} sim_msg_t;

typedef struct {
	uint32_t mcr, msr, ier, esr, btr;
	uint32_t tir[3], tdtr[3], tdlr[3], tdhr[3];
	bool pending[3];
	uint32_t seq[3];
	uint32_t tsr_flags; /* RQCP/TXOK/ALST/TERR of the three mailboxes */
	sim_msg_t fifo[3];
	uint32_t fifo_n;
	bool fovr;
	bool dead;
	bool blocked;
	uint32_t aborts;
	uint32_t rx_irq_runs;
} ctl_t;

static ctl_t ctl[SIM_BUSES];
static struct {
	uint32_t fmr, fm1r, fs1r, ffa1r, fa1r;
	uint32_t fr1[BANKS], fr2[BANKS];
} flt;
static uint32_t seq_counter;

static const uint32_t irq_tx[SIM_BUSES] = { CHIP_IRQ_CAN1_TX, CHIP_IRQ_CAN2_TX };
static const uint32_t irq_rx0[SIM_BUSES] = { CHIP_IRQ_CAN1_RX0, CHIP_IRQ_CAN2_RX0 };
static const uint32_t irq_sce[SIM_BUSES] = { CHIP_IRQ_CAN1_SCE, CHIP_IRQ_CAN2_SCE };
static void (*const h_tx[SIM_BUSES])(void) = { CAN1_TX_IRQHandler, CAN2_TX_IRQHandler };
static void (*const h_rx0[SIM_BUSES])(void) = { CAN1_RX0_IRQHandler, CAN2_RX0_IRQHandler };
static void (*const h_sce[SIM_BUSES])(void) = { CAN1_SCE_IRQHandler, CAN2_SCE_IRQHandler };


/* ---- clocks and state ----------------------------------------------------- */

static uint32_t apb1enr(void)
{
	return bxcan_sim_rcc[SIM_RCC_APB1ENR_IDX];
}

static bool clocked(uint32_t c)
{
	return (apb1enr() & (c == 0U ? RCC_APB1ENR_CAN1EN : RCC_APB1ENR_CAN2EN)) != 0U;
}

/* The filter banks are CAN1's registers: CAN1's clock runs them. */
static bool filters_clocked(void)
{
	return (apb1enr() & RCC_APB1ENR_CAN1EN) != 0U;
}

static bool running(uint32_t c)
{
	return clocked(c) && (ctl[c].msr & (CAN_MSR_INAK | CAN_MSR_SLAK)) == 0U;
}

static void update_mode(ctl_t *k)
{
	if (k->dead) {
		return;
	}
	if ((k->mcr & CAN_MCR_INRQ) != 0U) {
		k->msr = (k->msr | CAN_MSR_INAK) & ~CAN_MSR_SLAK;
	} else if ((k->mcr & CAN_MCR_SLEEP) != 0U) {
		k->msr = (k->msr | CAN_MSR_SLAK) & ~CAN_MSR_INAK;
	} else {
		k->msr &= ~(CAN_MSR_INAK | CAN_MSR_SLAK);
	}
}

void sim_reset(void)
{
	uint32_t c;

	memset(ctl, 0, sizeof(ctl));
	memset(&flt, 0, sizeof(flt));
	wire_sim_reset();
	memset(bxcan_sim_rcc, 0, sizeof(bxcan_sim_rcc));
	memset(bxcan_sim_gpiob, 0, sizeof(bxcan_sim_gpiob));
	for (c = 0; c < SIM_BUSES; c++) {
		ctl[c].mcr = 0x00010002U;
		ctl[c].msr = 0x00000C02U;
		ctl[c].esr = 0U;
	}
	flt.fmr = 0x2A1C0E01U;
	cortex_sim_reset();
	seq_counter = 0U;
	bxcan_sim_driver_reset();
}

/* ---- frames <-> register images ------------------------------------------ */

static sim_msg_t msg_of(const hal_can_frame_t *f)
{
	sim_msg_t m;

	if ((f->flags & HAL_CAN_FLAG_EXT) != 0U) {
		m.rir = (f->id << 3) | (1U << 2);
	} else {
		m.rir = f->id << 21;
	}
	if ((f->flags & HAL_CAN_FLAG_RTR) != 0U) {
		m.rir |= 1U << 1;
	}
	m.rdtr = f->dlc;
	m.rdlr = (uint32_t)f->data[0] | ((uint32_t)f->data[1] << 8) | ((uint32_t)f->data[2] << 16) |
		 ((uint32_t)f->data[3] << 24);
	m.rdhr = (uint32_t)f->data[4] | ((uint32_t)f->data[5] << 8) | ((uint32_t)f->data[6] << 16) |
		 ((uint32_t)f->data[7] << 24);
	return m;
}

static hal_can_frame_t frame_of(uint32_t tir, uint32_t tdtr, uint32_t tdlr, uint32_t tdhr)
{
	hal_can_frame_t f;
	uint32_t i;

	memset(&f, 0, sizeof(f));
	if ((tir & (1U << 2)) != 0U) {
		f.id = tir >> 3;
		f.flags = HAL_CAN_FLAG_EXT;
	} else {
		f.id = tir >> 21;
	}
	if ((tir & (1U << 1)) != 0U) {
		f.flags |= HAL_CAN_FLAG_RTR;
	}
	f.dlc = (uint8_t)(tdtr & 0xFU);
	for (i = 0; i < 4U; i++) {
		f.data[i] = (uint8_t)(tdlr >> (8U * i));
		f.data[4U + i] = (uint8_t)(tdhr >> (8U * i));
	}
	return f;
}

/* ---- filters (figure 342) ------------------------------------------------- */

static uint32_t image16(uint32_t rir)
{
	uint32_t ide = (rir >> 2) & 1U;
	uint32_t rtr = (rir >> 1) & 1U;
	uint32_t stid = ide != 0U ? (rir >> 21) & 0x7FFU : (rir >> 21) & 0x7FFU;
	uint32_t exid_hi = ide != 0U ? (rir >> 18) & 7U : 0U; /* EXID[17:15] */

	return (stid << 5) | (rtr << 4) | (ide << 3) | exid_hi;
}

static bool bank_match(uint32_t b, uint32_t rir)
{
	bool list = (flt.fm1r & (1U << b)) != 0U;
	bool wide = (flt.fs1r & (1U << b)) != 0U;
	uint32_t r1 = flt.fr1[b];
	uint32_t r2 = flt.fr2[b];

	if (wide) {
		uint32_t img = rir & ~1U;

		if (list) {
			return img == (r1 & ~1U) || img == (r2 & ~1U);
		}
		return ((img ^ r1) & r2 & ~1U) == 0U;
	} else {
		uint32_t img = image16(rir);

		if (list) {
			return img == (r1 & 0xFFFFU) || img == (r1 >> 16) || img == (r2 & 0xFFFFU) ||
			       img == (r2 >> 16);
		}
		return ((img ^ (r1 & 0xFFFFU)) & (r1 >> 16)) == 0U ||
		       ((img ^ (r2 & 0xFFFFU)) & (r2 >> 16)) == 0U;
	}
}

static void rx_deliver(uint32_t c, const sim_msg_t *m)
{
	ctl_t *k = &ctl[c];
	uint32_t sb = (flt.fmr >> 8) & 0x3FU;
	uint32_t first = c == 0U ? 0U : sb;
	uint32_t end = c == 0U ? sb : BANKS;
	uint32_t b;

	if (!running(c) || !filters_clocked() || (flt.fmr & 1U) != 0U) {
		return;
	}
	for (b = first; b < end && b < BANKS; b++) {
		if ((flt.fa1r & (1U << b)) == 0U || !bank_match(b, m->rir)) {
			continue;
		}
		if ((flt.ffa1r & (1U << b)) != 0U) {
			return; /* FIFO 1: the driver never assigns it */
		}
		if (k->fifo_n < 3U) {
			k->fifo[k->fifo_n] = *m;
			k->fifo_n++;
		} else {
			k->fifo[2] = *m;
			k->fovr = true;
		}
		return;
	}
}

/* ---- register access (bxcan_regs.h, BXCAN_SIM) --------------------------- */

static uint32_t ctl_of(uintptr_t base)
{
	if (base == CAN1_BASE) {
		return 0U;
	}
	if (base == CAN2_BASE) {
		return 1U;
	}
	fprintf(stderr, "bxcan_sim: access to base 0x%lx\n", (unsigned long)base);
	abort();
}

static uint32_t tsr_value(const ctl_t *k)
{
	uint32_t v = k->tsr_flags;
	uint32_t code = 3U;
	uint32_t mb;

	for (mb = 3U; mb-- > 0U;) {
		if (!k->pending[mb]) {
			v |= CAN_TSR_TME(mb);
			code = mb;
		}
	}
	return v | ((code & 3U) << CAN_TSR_CODE_SHIFT);
}

static bool filter_reg(uint32_t off, uint32_t **reg, uint32_t *bank)
{
	*bank = BANKS;
	switch (off) {
	case CAN_FMR: *reg = &flt.fmr; return true;
	case CAN_FM1R: *reg = &flt.fm1r; return true;
	case CAN_FS1R: *reg = &flt.fs1r; return true;
	case CAN_FFA1R: *reg = &flt.ffa1r; return true;
	case CAN_FA1R: *reg = &flt.fa1r; return true;
	default: break;
	}
	if (off >= CAN_FR1(0U) && off < CAN_FR1(BANKS)) {
		*bank = (off - CAN_FR1(0U)) / 8U;
		*reg = ((off - CAN_FR1(0U)) % 8U) == 0U ? &flt.fr1[*bank] : &flt.fr2[*bank];
		return true;
	}
	return false;
}

uint32_t bxcan_sim_read(uintptr_t base, uint32_t off)
{
	uint32_t c = ctl_of(base);
	ctl_t *k = &ctl[c];
	uint32_t *reg;
	uint32_t bank;

	if (off >= CAN_FMR) {
		if (c != 0U || !filters_clocked() || !filter_reg(off, &reg, &bank)) {
			return 0U; /* CAN2 has no filter registers of its own */
		}
		return *reg;
	}
	if (!clocked(c)) {
		return 0U;
	}
	switch (off) {
	case CAN_MCR: return k->mcr;
	case CAN_MSR: return k->msr;
	case CAN_TSR: return tsr_value(k);
	case CAN_RF0R:
		return k->fifo_n | (k->fifo_n == 3U ? CAN_RF0R_FULL0 : 0U) | (k->fovr ? CAN_RF0R_FOVR0 : 0U);
	case CAN_IER: return k->ier;
	case CAN_ESR: return k->esr;
	case CAN_BTR: return k->btr;
	case CAN_RIR(0U): return k->fifo_n > 0U ? k->fifo[0].rir : 0U;
	case CAN_RDTR(0U): return k->fifo_n > 0U ? k->fifo[0].rdtr : 0U;
	case CAN_RDLR(0U): return k->fifo_n > 0U ? k->fifo[0].rdlr : 0U;
	case CAN_RDHR(0U): return k->fifo_n > 0U ? k->fifo[0].rdhr : 0U;
	default: break;
	}
	if (off >= CAN_TIR(0U) && off < CAN_TIR(3U)) {
		uint32_t mb = (off - CAN_TIR(0U)) / 0x10U;

		switch ((off - CAN_TIR(0U)) % 0x10U) {
		case 0x0U: return k->tir[mb] | (k->pending[mb] ? CAN_TIR_TXRQ : 0U);
		case 0x4U: return k->tdtr[mb];
		case 0x8U: return k->tdlr[mb];
		default: return k->tdhr[mb];
		}
	}
	return 0U;
}

static void filter_write(uint32_t off, uint32_t v)
{
	uint32_t *reg;
	uint32_t bank;
	bool finit = (flt.fmr & 1U) != 0U;

	if (!filter_reg(off, &reg, &bank)) {
		return;
	}
	if (off == CAN_FMR) {
		flt.fmr = (flt.fmr & ~0x3F01U) | (v & 0x3F01U);
	} else if (off == CAN_FA1R) {
		flt.fa1r = v & 0x0FFFFFFFU;
	} else if (bank < BANKS) {
		if (finit || (flt.fa1r & (1U << bank)) == 0U) {
			*reg = v;
		}
	} else if (finit) {
		*reg = v & 0x0FFFFFFFU;
	}
}

void bxcan_sim_write(uintptr_t base, uint32_t off, uint32_t v)
{
	uint32_t c = ctl_of(base);
	ctl_t *k = &ctl[c];
	uint32_t mb;

	if (off >= CAN_FMR) {
		if (c == 0U && filters_clocked()) {
			filter_write(off, v);
		}
		return;
	}
	if (!clocked(c)) {
		return;
	}
	switch (off) {
	case CAN_MCR:
		k->mcr = v & 0x000100FFU;
		update_mode(k);
		return;
	case CAN_MSR:
		k->msr &= ~(v & (CAN_MSR_ERRI | (1U << 3) | (1U << 4)));
		return;
	case CAN_TSR:
		for (mb = 0; mb < 3U; mb++) {
			if ((v & CAN_TSR_RQCP(mb)) != 0U) {
				k->tsr_flags &= ~(0xFU << (8U * mb));
			}
			if ((v & CAN_TSR_ABRQ(mb)) != 0U && k->pending[mb]) {
				k->pending[mb] = false;
				k->tsr_flags = (k->tsr_flags & ~(0xFU << (8U * mb))) | CAN_TSR_RQCP(mb);
				k->aborts++;
			}
		}
		return;
	case CAN_RF0R:
		if ((v & CAN_RF0R_RFOM0) != 0U && k->fifo_n > 0U) {
			k->fifo[0] = k->fifo[1];
			k->fifo[1] = k->fifo[2];
			k->fifo_n--;
		}
		if ((v & CAN_RF0R_FOVR0) != 0U) {
			k->fovr = false;
		}
		return;
	case CAN_IER:
		k->ier = v;
		return;
	case CAN_ESR:
		k->esr = (k->esr & ~CAN_ESR_LEC_MSK) | (v & CAN_ESR_LEC_MSK);
		return;
	case CAN_BTR:
		if ((k->msr & CAN_MSR_INAK) != 0U) {
			k->btr = v & 0xC37F03FFU;
		}
		return;
	default:
		break;
	}
	if (off >= CAN_TIR(0U) && off < CAN_TIR(3U)) {
		mb = (off - CAN_TIR(0U)) / 0x10U;
		if (k->pending[mb]) {
			return; /* write-protected while the request is pending */
		}
		switch ((off - CAN_TIR(0U)) % 0x10U) {
		case 0x0U:
			k->tir[mb] = v & ~CAN_TIR_TXRQ;
			if ((v & CAN_TIR_TXRQ) != 0U) {
				k->pending[mb] = true;
				k->seq[mb] = ++seq_counter;
				k->tsr_flags &= ~(0xFU << (8U * mb));
			}
			break;
		case 0x4U: k->tdtr[mb] = v; break;
		case 0x8U: k->tdlr[mb] = v; break;
		default: k->tdhr[mb] = v; break;
		}
	}
}

/* ---- the wire and time ---------------------------------------------------- */

static void transmit(uint32_t c)
{
	ctl_t *k = &ctl[c];
	bool silm = (k->btr & CAN_BTR_SILM) != 0U;
	bool lbkm = (k->btr & CAN_BTR_LBKM) != 0U;
	uint32_t round;

	for (round = 0; round < 3U; round++) {
		uint32_t mb;
		uint32_t best = 3U;

		for (mb = 0; mb < 3U; mb++) {
			if (k->pending[mb] && (best == 3U || k->seq[mb] < k->seq[best])) {
				best = mb;
			}
		}
		if (best == 3U || (silm && !lbkm) || (k->esr & CAN_ESR_BOFF) != 0U ||
		    (k->blocked && !lbkm)) {
			return;
		}
		{
			hal_can_frame_t f = frame_of(k->tir[best], k->tdtr[best], k->tdlr[best], k->tdhr[best]);

			if (lbkm) {
				sim_msg_t m = msg_of(&f);

				rx_deliver(c, &m);
			}
			if (!silm) {
				wire_sim_push(c, &f);
			}
		}
		k->pending[best] = false;
		k->tsr_flags |= CAN_TSR_RQCP(best) | (CAN_TSR_RQCP(best) << 1); /* RQCP, TXOK */
	}
}

void cortex_sim_step(void)
{
	uint32_t c;

	for (c = 0; c < SIM_BUSES; c++) {
		if (running(c)) {
			transmit(c);
		}
	}
}

bool cortex_sim_irq_round(void)
{
	bool any = false;
	uint32_t c;

	for (c = 0; c < SIM_BUSES; c++) {
		ctl_t *k = &ctl[c];

		if (!clocked(c)) {
			continue;
		}
		if (cortex_sim_irq_enabled(irq_rx0[c]) && (((k->ier & CAN_IER_FMPIE0) != 0U && k->fifo_n > 0U) ||
					    ((k->ier & CAN_IER_FOVIE0) != 0U && k->fovr))) {
			k->rx_irq_runs++;
			h_rx0[c]();
			any = true;
		}
		if (cortex_sim_irq_enabled(irq_tx[c]) && (k->ier & CAN_IER_TMEIE) != 0U &&
		    (k->tsr_flags & (CAN_TSR_RQCP(0U) | CAN_TSR_RQCP(1U) | CAN_TSR_RQCP(2U))) != 0U) {
			h_tx[c]();
			any = true;
		}
		if (cortex_sim_irq_enabled(irq_sce[c]) && (k->ier & CAN_IER_ERRIE) != 0U &&
		    (k->msr & CAN_MSR_ERRI) != 0U) {
			h_sce[c]();
			any = true;
		}
	}
	return any;
}

void sim_error_code(uint8_t bus, uint32_t lec)
{
	ctl_t *k = &ctl[bus];

	if (!running(bus)) {
		return;
	}
	k->esr = (k->esr & ~CAN_ESR_LEC_MSK) | ((lec & 7U) << CAN_ESR_LEC_SHIFT);
	k->esr += 1U << CAN_ESR_REC_SHIFT;
	k->msr |= CAN_MSR_ERRI;
	if ((k->btr & CAN_BTR_SILM) == 0U) {
		wire_sim_dominant(bus); /* its error flag */
	}
	cortex_sim_irqs();
}

void sim_error_frame(uint8_t bus)
{
	sim_error_code(bus, 3U); /* acknowledgment error */
}

void sim_error_counters(uint8_t bus, uint8_t tec, uint8_t rec)
{
	ctl_t *k = &ctl[bus];
	uint32_t flags = 0U;

	if (tec >= 96U || rec >= 96U) {
		flags |= CAN_ESR_EWGF;
	}
	if (tec > 127U || rec > 127U) {
		flags |= CAN_ESR_EPVF;
	}
	k->esr = (k->esr & CAN_ESR_LEC_MSK) | flags | ((uint32_t)tec << CAN_ESR_TEC_SHIFT) |
		 ((uint32_t)rec << CAN_ESR_REC_SHIFT);
	k->msr |= CAN_MSR_ERRI;
	cortex_sim_run();
}

bool sim_inject(uint8_t bus, const hal_can_frame_t *f)
{
	sim_msg_t m = msg_of(f);
	bool ack = false;

	if (bus >= SIM_BUSES) {
		abort();
	}
	if (running(bus) && (ctl[bus].btr & CAN_BTR_SILM) == 0U) {
		wire_sim_dominant(bus); /* its ACK bit */
		ack = true;
	}
	rx_deliver(bus, &m);
	cortex_sim_irqs();
	return ack;
}

bool sim_bus_off(uint8_t bus, bool on)
{
	ctl_t *k = &ctl[bus];

	if (on) {
		k->esr = (k->esr & 0xFFU) | CAN_ESR_BOFF | CAN_ESR_EPVF | CAN_ESR_EWGF | (255U << CAN_ESR_TEC_SHIFT);
	} else {
		k->esr &= ~(CAN_ESR_BOFF | CAN_ESR_EPVF | CAN_ESR_EWGF | (0xFFU << CAN_ESR_TEC_SHIFT) |
			    (0xFFU << CAN_ESR_REC_SHIFT));
	}
	k->msr |= CAN_MSR_ERRI;
	cortex_sim_run();
	return (k->esr & CAN_ESR_BOFF) == 0U;
}

void sim_block_tx(uint8_t bus, bool blocked)
{
	ctl[bus].blocked = blocked;
	cortex_sim_run();
}

void sim_controller_dead(uint8_t bus, bool dead)
{
	ctl[bus].dead = dead;
}

void sim_poke_can2sb(uint32_t sb)
{
	flt.fmr = (flt.fmr & ~0x3F00U) | ((sb & 0x3FU) << 8);
}

uint32_t sim_btr(uint8_t bus) { return ctl[bus].btr; }
uint32_t sim_mcr(uint8_t bus) { return ctl[bus].mcr; }
uint32_t sim_fmr(void) { return flt.fmr; }
uint32_t sim_aborts(uint8_t bus) { return ctl[bus].aborts; }
uint32_t sim_rx_irq_runs(uint8_t bus) { return ctl[bus].rx_irq_runs; }

/* ---- what the driver needs from the board (the core: cortex_sim.c) ------ */

uint32_t chip_apb1_hz(void)
{
	return CHIP_APB1_HZ;
}
