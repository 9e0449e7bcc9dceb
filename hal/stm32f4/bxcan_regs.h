/* SPDX-License-Identifier: MIT */
/*
 * bxCAN registers (RM0090 section 32.9; identical on the STM32F1, RM0008
 * section 24.9). Only what the driver uses; names as in the manual.
 * The simulation and the driver share these numbers; the simulation
 * interprets them independently of the driver's logic.
 */
#ifndef BXCAN_REGS_H
#define BXCAN_REGS_H

#include "cortex_m.h"

/* Register offsets; the driver reads and writes them through can_rd() and
 * can_wr(), which the host simulation (tests/hal/stm32f4/bxcan_sim.c, BXCAN_SIM)
 * replaces, so that write-1-to-clear bits and mailboxes behave as on the
 * chip. */
#define CAN_MCR   0x000U
#define CAN_MSR   0x004U
#define CAN_TSR   0x008U
#define CAN_RF0R  0x00CU
#define CAN_RF1R  0x010U
#define CAN_IER   0x014U
#define CAN_ESR   0x018U
#define CAN_BTR   0x01CU
#define CAN_TIR(n)  (0x180U + 0x10U * (n))
#define CAN_TDTR(n) (0x184U + 0x10U * (n))
#define CAN_TDLR(n) (0x188U + 0x10U * (n))
#define CAN_TDHR(n) (0x18CU + 0x10U * (n))
#define CAN_RIR(n)  (0x1B0U + 0x10U * (n))
#define CAN_RDTR(n) (0x1B4U + 0x10U * (n))
#define CAN_RDLR(n) (0x1B8U + 0x10U * (n))
#define CAN_RDHR(n) (0x1BCU + 0x10U * (n))
/* Filter registers exist in CAN1 only; CAN2 uses the banks from CAN2SB. */
#define CAN_FMR   0x200U
#define CAN_FM1R  0x204U
#define CAN_FS1R  0x20CU
#define CAN_FFA1R 0x214U
#define CAN_FA1R  0x21CU
#define CAN_FR1(i) (0x240U + 8U * (i))
#define CAN_FR2(i) (0x244U + 8U * (i))

#if defined(BXCAN_SIM)
uint32_t bxcan_sim_read(uintptr_t base, uint32_t off);
void bxcan_sim_write(uintptr_t base, uint32_t off, uint32_t value);
static inline uint32_t can_rd(uintptr_t base, uint32_t off)
{
	return bxcan_sim_read(base, off);
}
static inline void can_wr(uintptr_t base, uint32_t off, uint32_t value)
{
	bxcan_sim_write(base, off, value);
}
#else
static inline uint32_t can_rd(uintptr_t base, uint32_t off)
{
	return REG32(base + off);
}
static inline void can_wr(uintptr_t base, uint32_t off, uint32_t value)
{
	REG32(base + off) = value;
}
#endif

#define CAN_MCR_INRQ  (1U << 0)
#define CAN_MCR_SLEEP (1U << 1)
#define CAN_MCR_TXFP  (1U << 2)
#define CAN_MCR_RFLM  (1U << 3)
#define CAN_MCR_NART  (1U << 4)
#define CAN_MCR_AWUM  (1U << 5)
#define CAN_MCR_ABOM  (1U << 6)
#define CAN_MCR_TTCM  (1U << 7)
#define CAN_MCR_RESET (1U << 15)
#define CAN_MCR_DBF   (1U << 16)

#define CAN_MSR_INAK  (1U << 0)
#define CAN_MSR_SLAK  (1U << 1)
#define CAN_MSR_ERRI  (1U << 2)

#define CAN_TSR_RQCP0 (1U << 0)
#define CAN_TSR_TXOK0 (1U << 1)
#define CAN_TSR_ALST0 (1U << 2)
#define CAN_TSR_TERR0 (1U << 3)
#define CAN_TSR_RQCP(n) (1U << (8U * (n)))
#define CAN_TSR_TERR(n) (1U << (8U * (n) + 3U))
#define CAN_TSR_ALST(n) (1U << (8U * (n) + 2U))
#define CAN_TSR_CODE_SHIFT 24U
#define CAN_TSR_CODE_MSK (3U << 24)
#define CAN_TSR_TME0  (1U << 26)
#define CAN_TSR_TME(n) (1U << (26U + (n)))
#define CAN_TSR_TME_ALL (7U << 26)
#define CAN_TSR_ABRQ(n) (1U << (8U * (n) + 7U))

#define CAN_RF0R_FMP0_MSK 3U
#define CAN_RF0R_FULL0 (1U << 3)
#define CAN_RF0R_FOVR0 (1U << 4)
#define CAN_RF0R_RFOM0 (1U << 5)

#define CAN_IER_TMEIE  (1U << 0)
#define CAN_IER_FMPIE0 (1U << 1)
#define CAN_IER_FFIE0  (1U << 2)
#define CAN_IER_FOVIE0 (1U << 3)
#define CAN_IER_EWGIE  (1U << 8)
#define CAN_IER_EPVIE  (1U << 9)
#define CAN_IER_BOFIE  (1U << 10)
#define CAN_IER_LECIE  (1U << 11)
#define CAN_IER_ERRIE  (1U << 15)

#define CAN_ESR_EWGF (1U << 0)
#define CAN_ESR_EPVF (1U << 1)
#define CAN_ESR_BOFF (1U << 2)
#define CAN_ESR_LEC_SHIFT 4U
#define CAN_ESR_LEC_MSK (7U << 4)
#define CAN_ESR_LEC_USER 7U /* "set by software": marks "no new code" */
#define CAN_ESR_TEC_SHIFT 16U
#define CAN_ESR_REC_SHIFT 24U

#define CAN_BTR_BRP_SHIFT 0U
#define CAN_BTR_TS1_SHIFT 16U
#define CAN_BTR_TS2_SHIFT 20U
#define CAN_BTR_SJW_SHIFT 24U
#define CAN_BTR_LBKM (1U << 30)
#define CAN_BTR_SILM (1U << 31)

#define CAN_TIR_TXRQ (1U << 0)
#define CAN_TIR_RTR  (1U << 1)
#define CAN_TIR_IDE  (1U << 2)
#define CAN_TIR_EXID_SHIFT 3U
#define CAN_TIR_STID_SHIFT 21U
#define CAN_RIR_RTR  (1U << 1)
#define CAN_RIR_IDE  (1U << 2)
#define CAN_RDTR_DLC_MSK 0xFU

#define CAN_FMR_FINIT (1U << 0)
#define CAN_FMR_CAN2SB_SHIFT 8U
#define CAN_FMR_CAN2SB_MSK (0x3FU << 8)
#define CAN_RIR_EXID_SHIFT 3U
#define CAN_RIR_STID_SHIFT 21U
#define CAN_FR_IDE (1U << 2)

#endif /* BXCAN_REGS_H */
