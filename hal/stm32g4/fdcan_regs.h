/* SPDX-License-Identifier: MIT */
/*
 * FDCAN registers and message RAM of the STM32G474 (RM0440 chapter "FD
 * controller area network (FDCAN)": section 44.4 "FDCAN registers",
 * section 44.3.3, "Message RAM"). Only what the driver uses; names as in the
 * manual. The host simulation (tests/hal/stm32g4/fdcan_sim.c) and the
 * driver share these numbers; the simulation interprets them on its own.
 */
#ifndef FDCAN_REGS_H
#define FDCAN_REGS_H

#include <stdint.h>

#include "chip.h"
#include "cortex_m.h"

/* Addresses (RM0440 section 2.2, memory map), unless chip.h has them. */
#ifndef FDCAN1_BASE
#define FDCAN1_BASE 0x40006400UL
#endif
#ifndef FDCAN2_BASE
#define FDCAN2_BASE 0x40006800UL
#endif
#ifndef SRAMCAN_BASE
#define SRAMCAN_BASE 0x4000A400UL
#endif
/* Interrupt line 0 of each instance (RM0440 table 97, vector table). */
#ifndef CHIP_IRQ_FDCAN1_IT0
#define CHIP_IRQ_FDCAN1_IT0 21U
#endif
#ifndef CHIP_IRQ_FDCAN2_IT0
#define CHIP_IRQ_FDCAN2_IT0 86U
#endif

/* Register offsets from an instance's base (RM0440 section 44.4,
 * "FDCAN register map"). */
#define FDCAN_CREL   0x000U
#define FDCAN_DBTP   0x00CU
#define FDCAN_TEST   0x010U
#define FDCAN_CCCR   0x018U
#define FDCAN_NBTP   0x01CU
#define FDCAN_TSCC   0x020U
#define FDCAN_ECR    0x040U
#define FDCAN_PSR    0x044U
#define FDCAN_TDCR   0x048U
#define FDCAN_IR     0x050U
#define FDCAN_IE     0x054U
#define FDCAN_ILS    0x058U
#define FDCAN_ILE    0x05CU
#define FDCAN_RXGFC  0x080U
#define FDCAN_XIDAM  0x084U
#define FDCAN_RXF0S  0x090U
#define FDCAN_RXF0A  0x094U
#define FDCAN_TXBC   0x0C0U
#define FDCAN_TXFQS  0x0C4U
#define FDCAN_TXBRP  0x0C8U
#define FDCAN_TXBAR  0x0CCU
#define FDCAN_TXBCR  0x0D0U
#define FDCAN_TXBTO  0x0D4U
#define FDCAN_TXBCF  0x0D8U
#define FDCAN_TXBTIE 0x0DCU
#define FDCAN_REG_END 0x100U /* CKDIV (FDCAN1 only) is left at reset: /1 */

/* FDCAN_CCCR (RM0440 section 44.4) */
#define FDCAN_CCCR_INIT (1U << 0)
#define FDCAN_CCCR_CCE  (1U << 1)
#define FDCAN_CCCR_ASM  (1U << 2)
#define FDCAN_CCCR_CSA  (1U << 3)
#define FDCAN_CCCR_CSR  (1U << 4)
#define FDCAN_CCCR_MON  (1U << 5)
#define FDCAN_CCCR_DAR  (1U << 6)
#define FDCAN_CCCR_TEST (1U << 7)
#define FDCAN_CCCR_FDOE (1U << 8)
#define FDCAN_CCCR_BRSE (1U << 9)
#define FDCAN_CCCR_PXHD (1U << 12)
#define FDCAN_CCCR_EFBI (1U << 13)
#define FDCAN_CCCR_TXP  (1U << 14)
#define FDCAN_CCCR_NISO (1U << 15)

/* FDCAN_TEST (RM0440 section 44.4): writable with CCCR.TEST only */
#define FDCAN_TEST_LBCK (1U << 4)

/* NBTP and DBTP (RM0440 section 44.4): each field holds the
 * value minus one. */
#define FDCAN_NBTP_NTSEG2_SHIFT 0U
#define FDCAN_NBTP_NTSEG1_SHIFT 8U
#define FDCAN_NBTP_NBRP_SHIFT 16U
#define FDCAN_NBTP_NSJW_SHIFT 25U
#define FDCAN_DBTP_DSJW_SHIFT 0U
#define FDCAN_DBTP_DTSEG2_SHIFT 4U
#define FDCAN_DBTP_DTSEG1_SHIFT 8U
#define FDCAN_DBTP_DBRP_SHIFT 16U
#define FDCAN_DBTP_TDC (1U << 23)
/* FDCAN_TDCR (RM0440 section 44.4), in minimum time quanta (kernel clocks) */
#define FDCAN_TDCR_TDCF_SHIFT 0U
#define FDCAN_TDCR_TDCO_SHIFT 8U
#define FDCAN_TDCR_MAX 127U

/* FDCAN_ECR (RM0440 section 44.4) */
#define FDCAN_ECR_TEC_MSK 0xFFU
#define FDCAN_ECR_REC_SHIFT 8U
#define FDCAN_ECR_REC_MSK (0x7FU << 8)
#define FDCAN_ECR_RP (1U << 15)

/* FDCAN_PSR (RM0440 section 44.4): reading it sets LEC and DLEC to 7 ("no change")
 * and clears PXE. */
#define FDCAN_PSR_LEC_MSK 7U
#define FDCAN_PSR_LEC_NONE 0U
#define FDCAN_PSR_LEC_ACK 3U
#define FDCAN_PSR_LEC_NO_CHANGE 7U
#define FDCAN_PSR_ACT_SHIFT 3U
#define FDCAN_PSR_ACT_MSK (3U << 3)
#define FDCAN_PSR_ACT_SYNC 0U /* integrating: waiting for 11 recessive bits */
#define FDCAN_PSR_EP (1U << 5)
#define FDCAN_PSR_EW (1U << 6)
#define FDCAN_PSR_BO (1U << 7)
#define FDCAN_PSR_DLEC_SHIFT 8U
#define FDCAN_PSR_PXE (1U << 14)

/* IR / IE (RM0440 section 44.4): write 1 to clear */
#define FDCAN_IR_RF0N (1U << 0)
#define FDCAN_IR_RF0F (1U << 1)
#define FDCAN_IR_RF0L (1U << 2)
#define FDCAN_IR_TC   (1U << 7)  /* per buffer, with TXBTIE */
#define FDCAN_IR_TCF  (1U << 8)
#define FDCAN_IR_TFE  (1U << 9)
#define FDCAN_IR_EP   (1U << 17)
#define FDCAN_IR_EW   (1U << 18)
#define FDCAN_IR_BO   (1U << 19)
#define FDCAN_IR_PEA  (1U << 21)
#define FDCAN_IR_PED  (1U << 22)
#define FDCAN_IR_ALL  0x00FFFFFFU
/* FDCAN_ILE (RM0440 section 44.4) */
#define FDCAN_ILE_EINT0 (1U << 0)

/* FDCAN_RXGFC (RM0440 section 44.4) */
#define FDCAN_RXGFC_RRFE (1U << 0)
#define FDCAN_RXGFC_RRFS (1U << 1)
#define FDCAN_RXGFC_ANFE_SHIFT 2U
#define FDCAN_RXGFC_ANFS_SHIFT 4U
#define FDCAN_RXGFC_ANF_REJECT 2U /* non-matching frames: reject */
#define FDCAN_RXGFC_F0OM (1U << 9) /* 0: FIFO 0 blocking (a full FIFO loses the new frame) */
#define FDCAN_RXGFC_LSS_SHIFT 16U
#define FDCAN_RXGFC_LSE_SHIFT 24U

/* RXF0S / RXF0A (RM0440 section 44.4) */
#define FDCAN_RXF0S_F0FL_MSK 0xFU
#define FDCAN_RXF0S_F0GI_SHIFT 8U
#define FDCAN_RXF0S_F0GI_MSK (3U << 8)
#define FDCAN_RXF0S_F0PI_SHIFT 16U
#define FDCAN_RXF0S_F0F (1U << 24)
#define FDCAN_RXF0S_RF0L (1U << 25)

/* FDCAN_TXBC (RM0440 section 44.4): TFQM 0 = Tx FIFO (sent in the order put) */
#define FDCAN_TXBC_TFQM (1U << 24)
/* FDCAN_TXFQS (RM0440 section 44.4) */
#define FDCAN_TXFQS_TFFL_MSK 7U
#define FDCAN_TXFQS_TFQPI_SHIFT 16U
#define FDCAN_TXFQS_TFQPI_MSK (3U << 16)
#define FDCAN_TXFQS_TFQF (1U << 21)
#define FDCAN_TXB_ALL 7U

/*
 * The fixed message RAM of one instance (RM0440 section 44.3.3, "Message
 * RAM", its figure of the message RAM configuration): 212 words from SRAMCAN_BASE + 0x350 x
 * instance, byte offsets:
 *   0x000 28 standard filter elements (1 word)
 *   0x070  8 extended filter elements (2 words)
 *   0x0B0  RX FIFO 0: 3 elements of 18 words (2 header + 64 data bytes)
 *   0x188  RX FIFO 1: 3 elements (unused)
 *   0x260  TX event FIFO: 3 elements of 2 words (unused)
 *   0x278  TX buffers (FIFO/queue): 3 elements of 18 words
 */
#define SRAMCAN_SIZE 0x350U
#define SRAMCAN_FLS 0x000U
#define SRAMCAN_FLE 0x070U
#define SRAMCAN_RF0 0x0B0U
#define SRAMCAN_RF1 0x188U
#define SRAMCAN_TEF 0x260U
#define SRAMCAN_TXB 0x278U
#define SRAMCAN_FLS_NBR 28U
#define SRAMCAN_FLE_NBR 8U
#define SRAMCAN_RF0_NBR 3U
#define SRAMCAN_TXB_NBR 3U
#define SRAMCAN_ELEM_BYTES 72U /* 18 words */
#define SRAMCAN_FLE_BYTES 8U
#define SRAMCAN_INSTANCE(n) (SRAMCAN_BASE + (uintptr_t)SRAMCAN_SIZE * (uintptr_t)(n))

/* RX/TX element header (RM0440 section 44.3.3, "Rx FIFO element", "Tx
 * buffer element"): word 0 ESI, XTD, RTR, ID (standard ids in bits 28:18); word 1
 * (RX) ANMF, FIDX, FDF, BRS, DLC, RXTS; (TX) MM, EFC, FDF, BRS, DLC. */
#define FDCAN_E0_ESI (1U << 31)
#define FDCAN_E0_XTD (1U << 30)
#define FDCAN_E0_RTR (1U << 29)
#define FDCAN_E0_STDID_SHIFT 18U
#define FDCAN_E0_EXTID_MSK 0x1FFFFFFFU
#define FDCAN_E1_FDF (1U << 21)
#define FDCAN_E1_BRS (1U << 20)
#define FDCAN_E1_DLC_SHIFT 16U
#define FDCAN_E1_DLC_MSK (0xFU << 16)

/* Standard filter element (RM0440 section 44.3.3, "Standard message ID
 * filter element"): SFT 31:30, SFEC 29:27, SFID1 26:16, SFID2 10:0. */
#define FDCAN_SFT_CLASSIC (2U << 30)  /* SFID1 = filter, SFID2 = mask */
#define FDCAN_SFEC_FIFO0 (1U << 27)   /* store in RX FIFO 0 on a match */
#define FDCAN_SFID1_SHIFT 16U
/* Extended filter element, word 0 EFEC 31:29, EFID1 28:0; word 1 EFT 31:30,
 * EFID2 28:0. */
#define FDCAN_EFEC_FIFO0 (1U << 29)
#define FDCAN_EFT_CLASSIC (2U << 30)  /* EFID1 = filter, EFID2 = mask */

/* Access: every register and message RAM word goes through fd_rd()/fd_wr()
 * (an address), which the host simulation replaces (FDCAN_SIM), so that
 * write-1-to-clear bits, protected fields and the FIFO indices behave as
 * on the chip. */
#if defined(FDCAN_SIM)
uint32_t fdcan_sim_read(uintptr_t addr);
void fdcan_sim_write(uintptr_t addr, uint32_t value);
static inline uint32_t fd_rd(uintptr_t addr)
{
	return fdcan_sim_read(addr);
}
static inline void fd_wr(uintptr_t addr, uint32_t value)
{
	fdcan_sim_write(addr, value);
}
#else
static inline uint32_t fd_rd(uintptr_t addr)
{
	return REG32(addr);
}
static inline void fd_wr(uintptr_t addr, uint32_t value)
{
	REG32(addr) = value;
}
#endif

#endif /* FDCAN_REGS_H */
