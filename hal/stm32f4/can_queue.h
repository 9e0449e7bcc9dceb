/* SPDX-License-Identifier: MIT */
/*
 * The software queues behind hal_can_send()/hal_can_receive() that every
 * STM32 CAN driver (bxCAN, FDCAN) keeps per bus, whatever its controller:
 *   - the RX ring: written only by the driver's receive interrupt (one
 *     producer), read only by hal_can_receive() (one consumer);
 *     free-running indices, count = head - tail, so no lock;
 *   - the TX queue: the frames waiting for a hardware mailbox / TX FIFO
 *     slot, touched with interrupts masked only.
 */
#ifndef CAN_QUEUE_H
#define CAN_QUEUE_H

#include <stdbool.h>
#include <stdint.h>

#include "hal.h"

#define CAN_QUEUE_RX_LEN 32U /* power of two; 32 frames = 3 ms of a full bus */
#define CAN_QUEUE_TX_LEN 8U  /* + the controller's 3; a corner queues at most 4 a ms */

typedef struct {
	volatile uint32_t rx_head;
	volatile uint32_t rx_tail;
	hal_can_frame_t rx_ring[CAN_QUEUE_RX_LEN];
	hal_can_frame_t tx_queue[CAN_QUEUE_TX_LEN];
	uint32_t tx_first;
	uint32_t tx_count;
} can_queue_t;

/* Both empty (the controller is in init: no interrupt touches q). */
void can_queue_reset(can_queue_t *q);

/* A received frame waits. */
bool can_queue_rx_pending(const can_queue_t *q);

/* Receive interrupt: the slot the next frame goes into, or NULL when the
 * ring is full (the caller counts the overrun and drops the frame). The
 * frame is published by can_queue_rx_commit() once complete. */
hal_can_frame_t *can_queue_rx_slot(can_queue_t *q);
void can_queue_rx_commit(can_queue_t *q);

/* hal_can_receive(): the oldest frame; SQ_OK or SQ_EAGAIN (none). */
int can_queue_rx_pop(can_queue_t *q, hal_can_frame_t *frame);

/* Interrupts masked: append a frame; SQ_OK or SQ_ENOBUFS (full). */
int can_queue_tx_push(can_queue_t *q, const hal_can_frame_t *frame);

/* Interrupts masked: the oldest waiting frame (NULL: none), and taking it
 * off once the controller holds it. */
const hal_can_frame_t *can_queue_tx_peek(const can_queue_t *q);
void can_queue_tx_pop(can_queue_t *q);

#endif /* CAN_QUEUE_H */
