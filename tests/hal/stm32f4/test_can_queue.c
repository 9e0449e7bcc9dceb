/* SPDX-License-Identifier: MIT */
/*
 * The STM32 CAN drivers' per-bus queues (hal/stm32f4/can_queue.c): the RX
 * ring hands frames out in arrival order, refuses a slot when 32 wait and
 * keeps working across the wrap of its free-running indices; the TX queue
 * holds 8 frames in order and refuses the ninth. Frames are told apart by
 * their identifiers, written by this test.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "can_queue.h"
#include "cortex_m.h"
#include "sq_status.h"

void cm_dmb(void) {} /* one thread here: no barrier needed */

/* Host contract handler: cmocka's expect_assert_failure() catches it. */
_Noreturn void hal_contract_failed(const char *file, uint32_t line)
{
	mock_assert(0, "hal_contract_failed", file, (int)line);
	abort();
}

static void put_rx(can_queue_t *q, uint32_t id)
{
	hal_can_frame_t *f = can_queue_rx_slot(q);

	assert_non_null(f);
	memset(f, 0, sizeof(*f));
	f->id = id;
	can_queue_rx_commit(q);
}

static void test_rx_order_full_and_empty(void **state)
{
	can_queue_t q;
	hal_can_frame_t f;
	uint32_t i;

	(void)state;
	can_queue_reset(&q);
	assert_false(can_queue_rx_pending(&q));
	assert_int_equal(can_queue_rx_pop(&q, &f), SQ_EAGAIN);
	for (i = 0U; i < 32U; i++) {
		put_rx(&q, 0x100U + i);
	}
	assert_null(can_queue_rx_slot(&q)); /* the 33rd has no room */
	assert_true(can_queue_rx_pending(&q));
	for (i = 0U; i < 32U; i++) {
		assert_int_equal(can_queue_rx_pop(&q, &f), SQ_OK);
		assert_int_equal(f.id, 0x100U + i);
	}
	assert_int_equal(can_queue_rx_pop(&q, &f), SQ_EAGAIN);
	assert_false(can_queue_rx_pending(&q));
}

/* head and tail just below 2^32: head - tail stays the count across the wrap */
static void test_rx_index_wrap(void **state)
{
	can_queue_t q;
	hal_can_frame_t f;
	uint32_t i;

	(void)state;
	can_queue_reset(&q);
	q.rx_head = 0xFFFFFFF0U;
	q.rx_tail = 0xFFFFFFF0U;
	for (i = 0U; i < 32U; i++) {
		put_rx(&q, i);
	}
	assert_int_equal(q.rx_head, 0x10U);
	assert_null(can_queue_rx_slot(&q));
	for (i = 0U; i < 32U; i++) {
		assert_int_equal(can_queue_rx_pop(&q, &f), SQ_OK);
		assert_int_equal(f.id, i);
	}
	assert_int_equal(can_queue_rx_pop(&q, &f), SQ_EAGAIN);
}

static void test_tx_fifo(void **state)
{
	can_queue_t q;
	hal_can_frame_t f = { 0 };
	uint32_t i;
	uint32_t round;

	(void)state;
	can_queue_reset(&q);
	assert_null(can_queue_tx_peek(&q));
	/* three rounds: the ring's start moves past the end */
	for (round = 0U; round < 3U; round++) {
		for (i = 0U; i < 8U; i++) {
			f.id = round * 16U + i;
			assert_int_equal(can_queue_tx_push(&q, &f), SQ_OK);
		}
		f.id = 0x7FFU;
		assert_int_equal(can_queue_tx_push(&q, &f), SQ_ENOBUFS);
		for (i = 0U; i < 5U; i++) {
			assert_int_equal(can_queue_tx_peek(&q)->id, round * 16U + i);
			can_queue_tx_pop(&q);
		}
		for (i = 5U; i < 8U; i++) {
			assert_int_equal(can_queue_tx_peek(&q)->id, round * 16U + i);
			can_queue_tx_pop(&q);
		}
		assert_null(can_queue_tx_peek(&q));
	}
	f.id = 1U;
	assert_int_equal(can_queue_tx_push(&q, &f), SQ_OK);
	can_queue_reset(&q);
	assert_null(can_queue_tx_peek(&q));
}

static void test_contracts(void **state)
{
	can_queue_t q;
	hal_can_frame_t f = { 0 };

	(void)state;
	can_queue_reset(&q);
	expect_assert_failure(can_queue_tx_pop(&q)); /* nothing to take off */
	expect_assert_failure(can_queue_rx_pop(&q, NULL));
	expect_assert_failure(can_queue_tx_push(NULL, &f));
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_rx_order_full_and_empty),
		cmocka_unit_test(test_rx_index_wrap),
		cmocka_unit_test(test_tx_fifo),
		cmocka_unit_test(test_contracts),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
