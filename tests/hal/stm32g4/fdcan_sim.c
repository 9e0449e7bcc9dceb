/* SPDX-License-Identifier: MIT */
/*
 * Simulated FDCAN pair with message RAM (see fdcan_sim.h), from RM0440
 * chapter 44:
 *   - reset: CCCR 0x00000001 (INIT), PSR 0x00000707 (LEC/DLEC "no change",
 *     ACT synchronizing), NBTP 0x06000A03, DBTP 0x00000A33, XIDAM
 *     0x1FFFFFFF, everything else 0;
 *   - CCCR: CCE only with INIT; the other configuration bits and NBTP,
 *     DBTP, TDCR, RXGFC, XIDAM, TXBC only while INIT and CCE are set
 *     (otherwise the write is ignored, counted); clearing INIT clears CCE;
 *     setting CCE resets RXF0S, TXFQS, TXBRP, TXBTO, TXBCF; clearing
 *     CCCR.TEST resets TEST, which is writable only with CCCR.TEST;
 *   - IR write 1 to clear; PSR read sets LEC and DLEC to 7, clears PXE;
 *   - RX FIFO 0: 3 elements, put/get index, fill level; RXF0A acknowledges
 *     up to the index written; full + blocking mode (F0OM 0): the new
 *     frame is lost (IR.RF0L); words the frame does not fill are garbage;
 *   - TX FIFO: TXBAR of the put index queues that buffer (other bits:
 *     counted misuse); sent oldest first, TXBTO and IR.TC (with TXBTIE),
 *     IR.TFE once empty;
 *   - filters exactly as the element descriptions of section 44.3.3: range,
 *     dual, classic, disabled; store FIFO 0/1, reject, priority; the first
 *     matching enabled element decides, else RXGFC.ANFS/ANFE; RRFS/RRFE
 *     reject remote frames; XIDAM ANDed into extended ids first;
 *   - running = INIT clear, joined, not bus-off; bus monitoring (MON): no
 *     ACK, no error flag, no transmission start; TEST.LBCK: own frames back
 *     into the receive path (with MON: nothing on the wire);
 *   - ECR: warning at 96, passive at 128 (PSR.EW/EP, IR.EW/EP on change);
 *     bus-off sets INIT; recovery needs INIT cleared and the recessive
 *     bits (sim_bus_off(off)).
 */
#include "fdcan_sim.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "chip.h"
#include "can_sim.h"
#include "cortex_sim.h"
#include "wire_sim.h"
#include "fdcan.h"
#include "fdcan_regs.h"
#include "sq_status.h"

#define RAM_WORDS (SRAMCAN_SIZE / 4U)
#define ACT_IDLE (1UL << FDCAN_PSR_ACT_SHIFT)
#define PROTECTED_CCCR 0x0000F3E4U /* ASM, MON, DAR, TEST, FDOE, BRSE, PXHD, EFBI, TXP, NISO */

typedef struct {
	uint32_t cccr, test, nbtp, dbtp, tdcr, ecr_tec, ecr_rec, psr, ir, ie, ils, ile;
	uint32_t rxgfc, xidam, txbc, txbtie, txbto, txbcf;
	uint32_t rx_get, rx_fill, rx_lost_flag;
	uint32_t tx_get, tx_fill;
	bool dead, blocked;
	uint32_t irq_runs, rx_lost, ignored, txbar_misuse;
} ctl_t;

static ctl_t ctl[SIM_BUSES];
static uint32_t ram[SIM_BUSES][RAM_WORDS];
static bool connected;
static uint32_t kernel_clock_hz;

static const uint32_t irq_of[SIM_BUSES] = { CHIP_IRQ_FDCAN1_IT0, CHIP_IRQ_FDCAN2_IT0 };
static void (*const handler_of[SIM_BUSES])(void) = { FDCAN1_IT0_IRQHandler, FDCAN2_IT0_IRQHandler };


/* ---- state ------------------------------------------------------------------ */

static bool bus_off(const ctl_t *k)
{
	return (k->psr & FDCAN_PSR_BO) != 0U;
}

static bool running(const ctl_t *k)
{
	return ((k->cccr & FDCAN_CCCR_INIT) == 0U) && ((k->psr & FDCAN_PSR_ACT_MSK) != 0U) && !bus_off(k);
}

static bool monitoring(const ctl_t *k)
{
	return (k->cccr & FDCAN_CCCR_MON) != 0U;
}

static bool loopback(const ctl_t *k)
{
	return ((k->cccr & FDCAN_CCCR_TEST) != 0U) && ((k->test & FDCAN_TEST_LBCK) != 0U);
}

static void reset_ctl(ctl_t *k)
{
	memset(k, 0, sizeof(*k));
	k->cccr = FDCAN_CCCR_INIT;
	k->psr = 0x00000707U;
	k->nbtp = 0x06000A03U;
	k->dbtp = 0x00000A33U;
	k->xidam = FDCAN_E0_EXTID_MSK;
}

void sim_reset(void)
{
	uint32_t c;

	for (c = 0U; c < SIM_BUSES; c++) {
		reset_ctl(&ctl[c]);
	}
	/* message RAM is not initialised by a reset: garbage */
	memset(ram, 0xA5, sizeof(ram));
	wire_sim_reset();
	connected = false;
	cortex_sim_reset();
	kernel_clock_hz = 170000000U;
	fdcan_sim_driver_reset();
}

void sim_set_kernel_hz(uint32_t hz)
{
	kernel_clock_hz = hz;
}

void sim_connect(bool on)
{
	connected = on;
}

/* Error counters -> PSR.EW/EP, IR on a change (ISO 11898-1 limits). */
static void counters_set(ctl_t *k, uint32_t tec, uint32_t rec)
{
	const uint32_t old = k->psr & (FDCAN_PSR_EW | FDCAN_PSR_EP);
	uint32_t now = 0U;

	k->ecr_tec = tec > 255U ? 255U : tec;
	k->ecr_rec = rec > 127U ? 127U : rec;
	if ((tec >= 96U) || (rec >= 96U)) {
		now |= FDCAN_PSR_EW;
	}
	if ((tec >= 128U) || (rec >= 128U)) {
		now |= FDCAN_PSR_EP;
	}
	k->psr = (k->psr & ~(FDCAN_PSR_EW | FDCAN_PSR_EP)) | now;
	if (((old ^ now) & FDCAN_PSR_EW) != 0U) {
		k->ir |= FDCAN_IR_EW;
	}
	if (((old ^ now) & FDCAN_PSR_EP) != 0U) {
		k->ir |= FDCAN_IR_EP;
	}
}

/* ---- frames <-> message RAM elements -------------------------------------------- */

static uint32_t *ram_at(uint32_t c, uint32_t byte_off)
{
	if ((byte_off % 4U) != 0U || byte_off >= SRAMCAN_SIZE) {
		fprintf(stderr, "fdcan_sim: message RAM offset 0x%x\n", (unsigned int)byte_off);
		abort();
	}
	return &ram[c][byte_off / 4U];
}

static uint8_t len_of_code(uint32_t code, bool fd)
{
	static const uint8_t fd_len[16] = { 0, 1, 2, 3, 4, 5, 6, 7, 8, 12, 16, 20, 24, 32, 48, 64 };

	return fd ? fd_len[code & 0xFU] : (uint8_t)((code & 0xFU) > 8U ? 8U : (code & 0xFU));
}

static uint32_t code_of_len(uint8_t len)
{
	static const uint8_t fd_len[16] = { 0, 1, 2, 3, 4, 5, 6, 7, 8, 12, 16, 20, 24, 32, 48, 64 };
	uint32_t code;

	for (code = 0U; code < 16U; code++) {
		if (fd_len[code] == len) {
			return code;
		}
	}
	fprintf(stderr, "fdcan_sim: no DLC code for %u bytes\n", (unsigned int)len);
	abort();
}

/* A TX buffer element of controller c as the frame on the wire. */
static hal_can_frame_t frame_of_txb(uint32_t c, uint32_t b)
{
	const ctl_t *k = &ctl[c];
	const uint32_t at = (uint32_t)SRAMCAN_TXB + (uint32_t)SRAMCAN_ELEM_BYTES * b;
	const uint32_t t0 = *ram_at(c, at);
	const uint32_t t1 = *ram_at(c, at + 4U);
	/* FDF is honoured only with CCCR.FDOE, BRS only with BRSE too */
	const bool fd = ((t1 & FDCAN_E1_FDF) != 0U) && ((k->cccr & FDCAN_CCCR_FDOE) != 0U);
	hal_can_frame_t f;
	uint32_t i;

	memset(&f, 0, sizeof(f));
	if ((t0 & FDCAN_E0_XTD) != 0U) {
		f.flags |= HAL_CAN_FLAG_EXT;
		f.id = t0 & 0x1FFFFFFFU;
	} else {
		f.id = (t0 >> 18) & 0x7FFU;
	}
	if (fd) {
		f.flags |= HAL_CAN_FLAG_FDF;
		if (((t1 & FDCAN_E1_BRS) != 0U) && ((k->cccr & FDCAN_CCCR_BRSE) != 0U)) {
			f.flags |= HAL_CAN_FLAG_BRS;
		}
		if ((t0 & FDCAN_E0_ESI) != 0U) {
			f.flags |= HAL_CAN_FLAG_ESI;
		}
	} else if ((t0 & FDCAN_E0_RTR) != 0U) {
		f.flags |= HAL_CAN_FLAG_RTR; /* an FD frame has no remote form */
	}
	f.dlc = ((f.flags & HAL_CAN_FLAG_RTR) != 0U) ? (uint8_t)((t1 >> 16) & 0xFU)
						   : len_of_code((t1 >> 16) & 0xFU, fd);
	for (i = 0U; ((f.flags & HAL_CAN_FLAG_RTR) == 0U) && (i < f.dlc); i++) {
		f.data[i] = (uint8_t)(*ram_at(c, at + 8U + 4U * (i / 4U)) >> (8U * (i % 4U)));
	}
	return f;
}

/* ---- filters (RM0440 section 44.3.3, filter element descriptions) ---------------------------- */

/* 0: FIFO 0, 1: FIFO 1, 2: reject */
static uint32_t std_filter(uint32_t c, uint32_t id)
{
	const ctl_t *k = &ctl[c];
	const uint32_t lss = (k->rxgfc >> FDCAN_RXGFC_LSS_SHIFT) & 0x1FU;
	uint32_t i;

	for (i = 0U; i < lss && i < SRAMCAN_FLS_NBR; i++) {
		const uint32_t w = *ram_at(c, (uint32_t)SRAMCAN_FLS + 4U * i);
		const uint32_t sft = w >> 30;
		const uint32_t sfec = (w >> 27) & 7U;
		const uint32_t id1 = (w >> 16) & 0x7FFU;
		const uint32_t id2 = w & 0x7FFU;
		bool match;

		if (sfec == 0U || sft == 3U) {
			continue; /* disabled */
		}
		switch (sft) {
		case 0U: match = (id >= id1) && (id <= id2); break;
		case 1U: match = (id == id1) || (id == id2); break;
		default: match = (id & id2) == (id1 & id2); break;
		}
		if (match) {
			return (sfec == 1U || sfec == 5U) ? 0U : (sfec == 2U || sfec == 6U) ? 1U : 2U;
		}
	}
	return ((k->rxgfc >> FDCAN_RXGFC_ANFS_SHIFT) & 3U) >= 2U ? 2U : ((k->rxgfc >> FDCAN_RXGFC_ANFS_SHIFT) & 3U);
}

static uint32_t ext_filter(uint32_t c, uint32_t id_raw)
{
	const ctl_t *k = &ctl[c];
	const uint32_t lse = (k->rxgfc >> FDCAN_RXGFC_LSE_SHIFT) & 0xFU;
	const uint32_t id = id_raw & k->xidam;
	uint32_t i;

	for (i = 0U; i < lse && i < SRAMCAN_FLE_NBR; i++) {
		const uint32_t f0 = *ram_at(c, (uint32_t)SRAMCAN_FLE + 8U * i);
		const uint32_t f1 = *ram_at(c, (uint32_t)SRAMCAN_FLE + 8U * i + 4U);
		const uint32_t efec = f0 >> 29;
		const uint32_t eft = f1 >> 30;
		const uint32_t id1 = f0 & 0x1FFFFFFFU;
		const uint32_t id2 = f1 & 0x1FFFFFFFU;
		bool match;

		if (efec == 0U) {
			continue;
		}
		switch (eft) {
		case 0U: match = (id >= id1) && (id <= id2); break;
		case 1U: match = (id_raw == id1) || (id_raw == id2); break;
		case 2U: match = (id_raw & id2) == (id1 & id2); break;
		default: match = (id_raw >= id1) && (id_raw <= id2); break;
		}
		if (match) {
			return (efec == 1U || efec == 5U) ? 0U : (efec == 2U || efec == 6U) ? 1U : 2U;
		}
	}
	return ((k->rxgfc >> FDCAN_RXGFC_ANFE_SHIFT) & 3U) >= 2U ? 2U : ((k->rxgfc >> FDCAN_RXGFC_ANFE_SHIFT) & 3U);
}

/* A valid frame on controller c's input: filtered, into RX FIFO 0. */
static void rx_deliver(uint32_t c, const hal_can_frame_t *f)
{
	ctl_t *k = &ctl[c];
	const bool ext = (f->flags & HAL_CAN_FLAG_EXT) != 0U;
	const bool rtr = (f->flags & HAL_CAN_FLAG_RTR) != 0U;
	const bool fd = (f->flags & HAL_CAN_FLAG_FDF) != 0U;
	uint32_t dest;
	uint32_t at;
	uint32_t i;

	if (!running(k)) {
		return;
	}
	if (fd && ((k->cccr & FDCAN_CCCR_FDOE) == 0U)) {
		/* an FD frame to a classic node: a form error */
		k->psr = (k->psr & ~FDCAN_PSR_LEC_MSK) | 2U;
		k->ir |= FDCAN_IR_PEA;
		return;
	}
	if (rtr && ((k->rxgfc & (ext ? FDCAN_RXGFC_RRFE : FDCAN_RXGFC_RRFS)) != 0U)) {
		return;
	}
	dest = ext ? ext_filter(c, f->id) : std_filter(c, f->id);
	if (dest != 0U) {
		return; /* rejected, or FIFO 1 (the driver never uses it) */
	}
	if (k->rx_fill >= SRAMCAN_RF0_NBR) {
		k->rx_lost++;
		k->rx_lost_flag = 1U;
		k->ir |= FDCAN_IR_RF0L;
		return;
	}
	at = (uint32_t)SRAMCAN_RF0 + (uint32_t)SRAMCAN_ELEM_BYTES * ((k->rx_get + k->rx_fill) % SRAMCAN_RF0_NBR);
	*ram_at(c, at) = (ext ? (f->id | FDCAN_E0_XTD) : (f->id << 18)) | (rtr ? FDCAN_E0_RTR : 0U) |
			 (((f->flags & HAL_CAN_FLAG_ESI) != 0U) ? FDCAN_E0_ESI : 0U);
	*ram_at(c, at + 4U) = ((rtr ? f->dlc : code_of_len(f->dlc)) << 16) | (fd ? FDCAN_E1_FDF : 0U) |
			      (((f->flags & HAL_CAN_FLAG_BRS) != 0U) ? FDCAN_E1_BRS : 0U) |
			      ((uint32_t)(sim_now_us() & 0xFFFFU));
	for (i = 0U; i < 16U; i++) {
		*ram_at(c, at + 8U + 4U * i) = 0xDEADBEEFU; /* beyond the frame: garbage */
	}
	for (i = 0U; !rtr && i < f->dlc; i++) {
		uint32_t *w = ram_at(c, at + 8U + 4U * (i / 4U));

		if ((i % 4U) == 0U) {
			*w = 0U;
		}
		*w |= (uint32_t)f->data[i] << (8U * (i % 4U));
	}
	k->rx_fill++;
	k->ir |= FDCAN_IR_RF0N | ((k->rx_fill == SRAMCAN_RF0_NBR) ? FDCAN_IR_RF0F : 0U);
}

/* ---- register access (fdcan_regs.h, FDCAN_SIM) ------------------------------------- */

static bool decode(uintptr_t addr, uint32_t *c, uint32_t *off, bool *is_ram)
{
	if (addr >= SRAMCAN_BASE && addr < SRAMCAN_BASE + SIM_BUSES * SRAMCAN_SIZE) {
		*c = (uint32_t)((addr - SRAMCAN_BASE) / SRAMCAN_SIZE);
		*off = (uint32_t)((addr - SRAMCAN_BASE) % SRAMCAN_SIZE);
		*is_ram = true;
		return true;
	}
	*is_ram = false;
	if (addr >= FDCAN1_BASE && addr < FDCAN1_BASE + FDCAN_REG_END) {
		*c = 0U;
		*off = (uint32_t)(addr - FDCAN1_BASE);
		return true;
	}
	if (addr >= FDCAN2_BASE && addr < FDCAN2_BASE + FDCAN_REG_END) {
		*c = 1U;
		*off = (uint32_t)(addr - FDCAN2_BASE);
		return true;
	}
	return false;
}

static uint32_t reg_value(uint32_t c, uint32_t off)
{
	const ctl_t *k = &ctl[c];

	switch (off) {
	case FDCAN_CREL: return 0x32141218U;
	case FDCAN_DBTP: return k->dbtp;
	case FDCAN_TEST: return k->test;
	case FDCAN_CCCR: return k->cccr;
	case FDCAN_NBTP: return k->nbtp;
	case FDCAN_ECR: return k->ecr_tec | (k->ecr_rec << FDCAN_ECR_REC_SHIFT) |
			       ((k->ecr_rec >= 127U) ? FDCAN_ECR_RP : 0U);
	case FDCAN_PSR: return k->psr;
	case FDCAN_TDCR: return k->tdcr;
	case FDCAN_IR: return k->ir;
	case FDCAN_IE: return k->ie;
	case FDCAN_ILS: return k->ils;
	case FDCAN_ILE: return k->ile;
	case FDCAN_RXGFC: return k->rxgfc;
	case FDCAN_XIDAM: return k->xidam;
	case FDCAN_RXF0S:
		return k->rx_fill | (k->rx_get << FDCAN_RXF0S_F0GI_SHIFT) |
		       (((k->rx_get + k->rx_fill) % SRAMCAN_RF0_NBR) << FDCAN_RXF0S_F0PI_SHIFT) |
		       ((k->rx_fill == SRAMCAN_RF0_NBR) ? FDCAN_RXF0S_F0F : 0U) |
		       ((k->rx_lost_flag != 0U) ? FDCAN_RXF0S_RF0L : 0U);
	case FDCAN_TXBC: return k->txbc;
	case FDCAN_TXFQS: {
		const uint32_t put = (k->tx_get + k->tx_fill) % SRAMCAN_TXB_NBR;

		return (SRAMCAN_TXB_NBR - k->tx_fill) | (k->tx_get << 8) | (put << FDCAN_TXFQS_TFQPI_SHIFT) |
		       ((k->tx_fill == SRAMCAN_TXB_NBR) ? FDCAN_TXFQS_TFQF : 0U);
	}
	case FDCAN_TXBRP: {
		uint32_t v = 0U;
		uint32_t i;

		for (i = 0U; i < k->tx_fill; i++) {
			v |= 1U << ((k->tx_get + i) % SRAMCAN_TXB_NBR);
		}
		return v;
	}
	case FDCAN_TXBTO: return k->txbto;
	case FDCAN_TXBCF: return k->txbcf;
	case FDCAN_TXBTIE: return k->txbtie;
	default: return 0U;
	}
}

uint32_t fdcan_sim_read(uintptr_t addr)
{
	uint32_t c;
	uint32_t off;
	bool is_ram;
	uint32_t v;

	if (!decode(addr, &c, &off, &is_ram)) {
		fprintf(stderr, "fdcan_sim: read of 0x%lx\n", (unsigned long)addr);
		abort();
	}
	if (is_ram) {
		return *ram_at(c, off);
	}
	if (ctl[c].dead) {
		return 0U;
	}
	v = reg_value(c, off);
	if (off == FDCAN_PSR) {
		ctl[c].psr = (ctl[c].psr & ~(FDCAN_PSR_PXE | 0x700U | FDCAN_PSR_LEC_MSK)) | 0x707U;
	}
	return v;
}

static bool config_open(const ctl_t *k)
{
	return (k->cccr & (FDCAN_CCCR_INIT | FDCAN_CCCR_CCE)) == (FDCAN_CCCR_INIT | FDCAN_CCCR_CCE);
}

static void cccr_write(ctl_t *k, uint32_t v)
{
	const uint32_t old = k->cccr;
	uint32_t next = old;

	if (config_open(k)) {
		next = (next & ~PROTECTED_CCCR) | (v & PROTECTED_CCCR);
	} else if (((v ^ old) & PROTECTED_CCCR) != 0U) {
		k->ignored++;
	}
	next = (next & ~FDCAN_CCCR_INIT) | (v & FDCAN_CCCR_INIT);
	if ((next & FDCAN_CCCR_INIT) == 0U) {
		next &= ~FDCAN_CCCR_CCE; /* leaving INIT clears CCE */
	} else if ((old & FDCAN_CCCR_INIT) != 0U) {
		next = (next & ~FDCAN_CCCR_CCE) | (v & FDCAN_CCCR_CCE);
	}
	if (((next & FDCAN_CCCR_CCE) != 0U) && ((old & FDCAN_CCCR_CCE) == 0U)) {
		/* CCE holds these in reset */
		k->rx_get = 0U;
		k->rx_fill = 0U;
		k->rx_lost_flag = 0U;
		k->tx_get = 0U;
		k->tx_fill = 0U;
		k->txbto = 0U;
		k->txbcf = 0U;
	}
	if ((next & FDCAN_CCCR_TEST) == 0U) {
		k->test = 0U;
	}
	if ((next & FDCAN_CCCR_INIT) != 0U) {
		k->psr &= ~FDCAN_PSR_ACT_MSK; /* integrating again once INIT clears */
	} else if (((old & FDCAN_CCCR_INIT) != 0U) && !bus_off(k)) {
		k->psr = (k->psr & ~FDCAN_PSR_ACT_MSK) | ACT_IDLE; /* 11 recessive bits at once */
	}
	k->cccr = next;
}

static void protected_write(ctl_t *k, uint32_t *reg, uint32_t v)
{
	if (config_open(k)) {
		*reg = v;
	} else {
		k->ignored++;
	}
}

void fdcan_sim_write(uintptr_t addr, uint32_t v)
{
	uint32_t c;
	uint32_t off;
	bool is_ram;
	ctl_t *k;

	if (!decode(addr, &c, &off, &is_ram)) {
		fprintf(stderr, "fdcan_sim: write of 0x%lx\n", (unsigned long)addr);
		abort();
	}
	if (is_ram) {
		*ram_at(c, off) = v;
		return;
	}
	k = &ctl[c];
	if (k->dead) {
		return;
	}
	switch (off) {
	case FDCAN_CCCR: cccr_write(k, v); break;
	case FDCAN_TEST:
		if ((k->cccr & FDCAN_CCCR_TEST) != 0U) {
			k->test = v & (FDCAN_TEST_LBCK | (3U << 5));
		} else {
			k->ignored++;
		}
		break;
	case FDCAN_NBTP: protected_write(k, &k->nbtp, v); break;
	case FDCAN_DBTP: protected_write(k, &k->dbtp, v & 0x009F1FFFU); break;
	case FDCAN_TDCR: protected_write(k, &k->tdcr, v & 0x7F7FU); break;
	case FDCAN_RXGFC: protected_write(k, &k->rxgfc, v & 0x0F1F033FU); break;
	case FDCAN_XIDAM: protected_write(k, &k->xidam, v & 0x1FFFFFFFU); break;
	case FDCAN_TXBC: protected_write(k, &k->txbc, v & FDCAN_TXBC_TFQM); break;
	case FDCAN_IR: k->ir &= ~v; if ((v & FDCAN_IR_RF0L) != 0U) { k->rx_lost_flag = 0U; } break;
	case FDCAN_IE: k->ie = v & FDCAN_IR_ALL; break;
	case FDCAN_ILS: k->ils = v & 0x7FU; break;
	case FDCAN_ILE: k->ile = v & 3U; break;
	case FDCAN_TXBTIE: k->txbtie = v & FDCAN_TXB_ALL; break;
	case FDCAN_RXF0A: {
		const uint32_t ai = v & 7U;
		const uint32_t n = ((ai + SRAMCAN_RF0_NBR - k->rx_get) % SRAMCAN_RF0_NBR) + 1U;

		if (ai < SRAMCAN_RF0_NBR && n <= k->rx_fill) {
			k->rx_get = (k->rx_get + n) % SRAMCAN_RF0_NBR;
			k->rx_fill -= n;
		}
		break;
	}
	case FDCAN_TXBAR: {
		const uint32_t put = (k->tx_get + k->tx_fill) % SRAMCAN_TXB_NBR;

		if ((k->cccr & FDCAN_CCCR_CCE) != 0U) {
			break; /* held in reset */
		}
		if (v == 0U) {
			break;
		}
		if (v != (1U << put) || k->tx_fill >= SRAMCAN_TXB_NBR) {
			k->txbar_misuse++;
			fprintf(stderr, "fdcan_sim: TXBAR 0x%x, put index %u, fill %u\n", (unsigned int)v,
				(unsigned int)put, (unsigned int)k->tx_fill);
			abort();
		}
		k->tx_fill++;
		k->txbto &= ~v;
		break;
	}
	default: break;
	}
}

/* ---- the wires and time ---------------------------------------------------------- */

/* Someone on c's wire ACKs a frame of c: the harness's node (unless
 * blocked), or, with the instances connected, the other one if it runs
 * and is not monitoring. */
static bool acked(uint32_t c)
{
	if (connected) {
		const ctl_t *o = &ctl[1U - c];

		return running(o) && !monitoring(o);
	}
	return !ctl[c].blocked;
}

static void transmit(uint32_t c)
{
	ctl_t *k = &ctl[c];
	uint32_t round;

	for (round = 0U; round < SRAMCAN_TXB_NBR && k->tx_fill > 0U; round++) {
		const uint32_t b = k->tx_get;
		const hal_can_frame_t f = frame_of_txb(c, b);
		const bool lbck = loopback(k);

		if (!running(k) || (monitoring(k) && !lbck)) {
			return; /* bus monitoring starts no transmission */
		}
		if (lbck) {
			rx_deliver(c, &f);
		}
		if (!(lbck && monitoring(k))) {
			if (!lbck && !acked(c)) {
				return; /* no ACK: retransmitted later */
			}
			wire_sim_push(c, &f);
			if (connected) {
				rx_deliver(1U - c, &f);
				wire_sim_dominant(1U - c); /* its ACK */
			}
		}
		k->tx_get = (k->tx_get + 1U) % SRAMCAN_TXB_NBR;
		k->tx_fill--;
		k->txbto |= 1U << b;
		if ((k->txbtie & (1U << b)) != 0U) {
			k->ir |= FDCAN_IR_TC;
		}
		if (k->tx_fill == 0U) {
			k->ir |= FDCAN_IR_TFE;
		}
	}
}

void cortex_sim_step(void)
{
	uint32_t c;

	for (c = 0U; c < SIM_BUSES; c++) {
		transmit(c);
	}
}

bool cortex_sim_irq_round(void)
{
	bool any = false;
	uint32_t c;

	for (c = 0U; c < SIM_BUSES; c++) {
		ctl_t *k = &ctl[c];

		if (k->ils != 0U) {
			fprintf(stderr, "fdcan_sim: ILS 0x%x (the model has line 0 only)\n", (unsigned int)k->ils);
			abort();
		}
		if (!k->dead && cortex_sim_irq_enabled(irq_of[c]) && ((k->ile & FDCAN_ILE_EINT0) != 0U) &&
		    ((k->ir & k->ie) != 0U)) {
			k->irq_runs++;
			handler_of[c]();
			any = true;
		}
	}
	return any;
}

bool sim_inject(uint8_t bus, const hal_can_frame_t *f)
{
	ctl_t *k;
	bool ack = false;

	if (bus >= SIM_BUSES) {
		abort();
	}
	k = &ctl[bus];
	if (running(k) && !monitoring(k)) {
		wire_sim_dominant(bus); /* its ACK bit */
		ack = true;
	}
	rx_deliver(bus, f);
	if (connected) {
		rx_deliver(1U - bus, f);
	}
	cortex_sim_irqs();
	return ack;
}

void sim_error_frame(uint8_t bus)
{
	ctl_t *k = &ctl[bus];

	if (!running(k)) {
		return;
	}
	k->psr = (k->psr & ~FDCAN_PSR_LEC_MSK) | 1U; /* stuff error */
	counters_set(k, k->ecr_tec, k->ecr_rec + 1U);
	k->ir |= FDCAN_IR_PEA;
	if (!monitoring(k)) {
		wire_sim_dominant(bus); /* its error flag */
	}
	cortex_sim_irqs();
}

void sim_set_counters(uint8_t bus, uint32_t tec, uint32_t rec)
{
	counters_set(&ctl[bus], tec, rec);
	cortex_sim_irqs();
}

void sim_protocol_exception(uint8_t bus)
{
	ctl[bus].psr |= FDCAN_PSR_PXE;
}

bool sim_bus_off(uint8_t bus, bool on)
{
	ctl_t *k = &ctl[bus];

	if (on) {
		counters_set(k, 255U, k->ecr_rec);
		k->psr |= FDCAN_PSR_BO;
		k->cccr |= FDCAN_CCCR_INIT; /* the controller stops itself */
		k->ir |= FDCAN_IR_BO;
	} else if (bus_off(k) && ((k->cccr & FDCAN_CCCR_INIT) == 0U)) {
		/* software cleared INIT; the 129 x 11 recessive bits passed */
		k->psr = (k->psr & ~(FDCAN_PSR_BO | FDCAN_PSR_ACT_MSK)) | ACT_IDLE;
		counters_set(k, 0U, 0U);
		k->ir |= FDCAN_IR_BO;
	}
	cortex_sim_run();
	return !bus_off(k);
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

uint32_t sim_reg(uint8_t bus, uint32_t off) { return reg_value(bus, off); }
uint32_t sim_ram(uint8_t bus, uint32_t byte_off) { return *ram_at(bus, byte_off); }
uint32_t sim_irq_runs(uint8_t bus) { return ctl[bus].irq_runs; }
uint32_t sim_rx_lost(uint8_t bus) { return ctl[bus].rx_lost; }
uint32_t sim_protected_writes_ignored(uint8_t bus) { return ctl[bus].ignored; }

/* ---- what the driver needs from the board (the core: cortex_sim.c) ------ */

uint32_t chip_fdcan_kernel_hz(void)
{
	return kernel_clock_hz;
}

void chip_can_pins_init(uint8_t bus)
{
	(void)bus;
}
