/* SPDX-License-Identifier: MIT */
/*
 * The bxCAN driver's interface to the board (bxcan.c, bxcan_timing.c); the
 * firmware uses hal.h only.
 */
#ifndef BXCAN_H
#define BXCAN_H

#include <stdbool.h>
#include <stdint.h>

/* Bit timing for the bxCAN on an APB clock: SQ_OK with *btr, or SQ_EINVAL
 * if the bit rate cannot be made exactly (see bxcan_timing.c). */
int bxcan_bit_timing(uint32_t apb_hz, uint32_t bitrate_bps, uint32_t *btr);

#define BXCAN_DEFAULT_BITRATE 500000UL

/* Start `bus` at bitrate_bps in its current mode (NORMAL after reset),
 * accepting every frame until hal_can_set_rx_filter(). SQ_OK; SQ_EINVAL
 * (rate not exact: nothing touched); SQ_EAGAIN (controller did not
 * acknowledge: HAL_FAULT_CAN_INIT raised, the bus stays stopped); SQ_ENODEV. */
int bxcan_start(uint8_t bus, uint32_t bitrate_bps);

/*
 * Bring-up self-test of one controller, before it joins the bus: silent
 * loopback (BTR.SILM | LBKM: nothing reaches the wire, not even an ACK),
 * one frame sent to itself through the accept-all filter of its own banks.
 * Leaves the controller in initialisation mode; bxcan_start() follows.
 * SQ_OK (frame came back unchanged); SQ_EIO (no frame, or a different one:
 * controller, clock or filter broken); SQ_EAGAIN (controller absent or
 * without clock: it never acknowledged initialisation); SQ_ENODEV.
 */
int bxcan_selftest_loopback(uint8_t bus);

/* A received frame waits in some bus's ring (hal_idle_until does not sleep). */
bool bxcan_rx_pending(void);

/* Its interrupt handlers: chip.h (CHIP_CAN_VECTORS). */

#endif /* BXCAN_H */
