/* SPDX-License-Identifier: MIT */
/*
 * The CAN controller as the board (board.c) and the bring-up self-test
 * (selftest.c) see it, whichever controller the chip has: bxCAN
 * (hal/stm32f4/bxcan.c, STM32F4/F103) or FDCAN (hal/stm32g4/fdcan.c,
 * STM32G474). Each driver implements these three; the firmware uses hal.h.
 */
#ifndef CAN_CTRL_H
#define CAN_CTRL_H

#include <stdbool.h>
#include <stdint.h>

/* The bit rate every bus starts with (hal_can_open() may change it). */
#define CAN_CTRL_DEFAULT_BITRATE 500000UL

/* Start `bus` at bitrate_bps, accepting every frame until
 * hal_can_set_rx_filter(). SQ_OK; SQ_EINVAL (rate not exact: nothing
 * touched); SQ_EAGAIN (controller did not acknowledge: HAL_FAULT_CAN_INIT
 * raised, the bus stays stopped); SQ_ENODEV (no such bus). */
int can_ctrl_start(uint8_t bus, uint32_t bitrate_bps);

/* Bring-up self-test of one controller before it joins the bus: one frame
 * sent to itself in a loopback that reaches no wire. SQ_OK (came back
 * unchanged); SQ_EIO (no frame or a different one); SQ_EAGAIN (controller
 * absent or without clock); SQ_ENODEV. can_ctrl_start() follows. */
int can_ctrl_selftest_loopback(uint8_t bus);

/* A received frame waits in some bus's queue (hal_idle_until does not sleep). */
bool can_ctrl_rx_pending(void);

#endif /* CAN_CTRL_H */
