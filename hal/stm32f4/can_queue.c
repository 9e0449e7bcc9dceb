/* SPDX-License-Identifier: MIT */
/* The per-bus RX ring and TX queue of the STM32 CAN drivers (can_queue.h). */
#include "can_queue.h"

#include <stddef.h>

#include "cortex_m.h"
#include "sq_status.h"

_Static_assert((CAN_QUEUE_RX_LEN & (CAN_QUEUE_RX_LEN - 1U)) == 0U,
	       "ring length must be a power of two (free-running indices wrap at 2^32)");

void can_queue_reset(can_queue_t *q)
{
	HAL_REQUIRE(q != NULL);
	q->rx_head = 0U;
	q->rx_tail = 0U;
	q->tx_first = 0U;
	q->tx_count = 0U;
}

bool can_queue_rx_pending(const can_queue_t *q)
{
	HAL_REQUIRE(q != NULL);
	return q->rx_head != q->rx_tail;
}

hal_can_frame_t *can_queue_rx_slot(can_queue_t *q)
{
	uint32_t head;

	HAL_REQUIRE(q != NULL);
	head = q->rx_head;
	if ((head - q->rx_tail) >= CAN_QUEUE_RX_LEN) {
		return NULL;
	}
	return &q->rx_ring[head % CAN_QUEUE_RX_LEN];
}

void can_queue_rx_commit(can_queue_t *q)
{
	HAL_REQUIRE((q != NULL) && ((q->rx_head - q->rx_tail) < CAN_QUEUE_RX_LEN));
	cm_dmb(); /* the frame is complete before the head moves */
	q->rx_head = q->rx_head + 1U;
}

int can_queue_rx_pop(can_queue_t *q, hal_can_frame_t *frame)
{
	uint32_t tail;

	HAL_REQUIRE((q != NULL) && (frame != NULL));
	tail = q->rx_tail;
	if (tail == q->rx_head) {
		return SQ_EAGAIN;
	}
	cm_dmb(); /* read the slot only after seeing the head that covers it */
	*frame = q->rx_ring[tail % CAN_QUEUE_RX_LEN];
	cm_dmb(); /* finish reading before handing the slot back */
	q->rx_tail = tail + 1U;
	return SQ_OK;
}

int can_queue_tx_push(can_queue_t *q, const hal_can_frame_t *frame)
{
	HAL_REQUIRE((q != NULL) && (frame != NULL));
	if (q->tx_count >= CAN_QUEUE_TX_LEN) {
		return SQ_ENOBUFS;
	}
	q->tx_queue[(q->tx_first + q->tx_count) % CAN_QUEUE_TX_LEN] = *frame;
	q->tx_count++;
	return SQ_OK;
}

const hal_can_frame_t *can_queue_tx_peek(const can_queue_t *q)
{
	HAL_REQUIRE(q != NULL);
	return (q->tx_count > 0U) ? &q->tx_queue[q->tx_first] : NULL;
}

void can_queue_tx_pop(can_queue_t *q)
{
	HAL_REQUIRE((q != NULL) && (q->tx_count > 0U));
	q->tx_first = (q->tx_first + 1U) % CAN_QUEUE_TX_LEN;
	q->tx_count--;
}
