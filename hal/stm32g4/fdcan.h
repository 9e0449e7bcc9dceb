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

/* The board's controller-neutral calls (the same three as the bxCAN
 * driver's), implemented here for FDCAN. */

/* Start `bus` at bitrate_bps (nominal; the data phase at
 * FDCAN_DEFAULT_DATA_BITRATE) in its current mode (NORMAL after reset),
 * accepting every frame until hal_can_set_rx_filter(). SQ_OK; SQ_EINVAL
 * (rate not exact: nothing touched); SQ_EAGAIN (the controller did not
 * acknowledge INIT or did not join the bus: HAL_FAULT_CAN_INIT raised);
 * SQ_ENODEV. */
int can_ctrl_start(uint8_t bus, uint32_t bitrate_bps);

/* Bring-up self-test, before the bus is joined: internal loopback
 * (CCCR.TEST, TEST.LBCK with CCCR.MON: nothing reaches the pin, not even
 * an ACK), one FD frame with BRS sent to itself. Leaves the controller in
 * initialisation mode; can_ctrl_start() follows. SQ_OK (the frame came back
 * unchanged); SQ_EIO (no frame or a different one); SQ_EAGAIN (controller
 * absent or without clock); SQ_ENODEV. */
int can_ctrl_selftest_loopback(uint8_t bus);

/* A received frame waits in some bus's ring (hal_idle_until does not sleep). */
bool can_ctrl_rx_pending(void);

void FDCAN1_IT0_IRQHandler(void);
void FDCAN2_IT0_IRQHandler(void);

#endif /* FDCAN_H */
