/* SPDX-License-Identifier: MIT */
/*
 * The FDCAN driver's interface to the board (fdcan.c, fdcan_timing.c) on the
 * STM32G474: FDCAN1 = bus 0 (vehicle bus), FDCAN2 = bus 1 (output bus). The
 * firmware uses hal.h only.
 */
#ifndef FDCAN_H
#define FDCAN_H

#include <stdbool.h>
#include <stdint.h>

#define FDCAN_DEFAULT_BITRATE 500000UL       /* nominal (arbitration) phase */
#define FDCAN_DEFAULT_DATA_BITRATE 2000000UL /* data phase of BRS frames    */

/* The register values of one bit timing (RM0440 section 44.4, FDCAN_NBTP,
 * FDCAN_DBTP with TDC set, FDCAN_TDCR), and what they mean. */
typedef struct {
	uint32_t nbtp;
	uint32_t dbtp;
	uint32_t tdcr;
	uint32_t nominal_tq;     /* quanta per nominal bit                  */
	uint32_t data_tq;        /* quanta per data bit                     */
	uint32_t tdco_mtq;       /* secondary sample point offset, clocks   */
} fdcan_timing_t;

/* Bit timing for nominal_bps (<= 1 Mbit/s) and data_bps (nominal_bps ..
 * 8 Mbit/s) from the FDCAN kernel clock: SQ_OK with *t, or SQ_EINVAL if a
 * rate cannot be made exactly (see fdcan_timing.c). */
int fdcan_bit_timing(uint32_t kernel_hz, uint32_t nominal_bps, uint32_t data_bps,
		     fdcan_timing_t *t);

/* The board's controller-neutral calls (can_ctrl.h), implemented in
 * fdcan.c: the data phase of BRS frames runs at FDCAN_DEFAULT_DATA_BITRATE;
 * the self-test loopback is the internal one (CCCR.TEST, TEST.LBCK with
 * CCCR.MON: nothing reaches the pin, not even an ACK) with one FD frame with
 * BRS, and leaves the controller in initialisation mode. */
#include "can_ctrl.h"

void FDCAN1_IT0_IRQHandler(void);
void FDCAN2_IT0_IRQHandler(void);

#endif /* FDCAN_H */
