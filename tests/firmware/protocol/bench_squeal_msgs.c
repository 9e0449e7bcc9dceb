/* SPDX-License-Identifier: MIT */
/*
 * Figures for the protocol layer on the host (release build): time per
 * CRC over a classic frame, per pack+protect of SquealStatus and per
 * receive (E2E check + unpack) of DiscSpeed. Figures only, never pass/fail;
 * for target numbers use instruction counts (valgrind --tool=callgrind).
 */
#include <stdio.h>
#include <time.h>

#include "crc8_p01.h"
#include "e2e_p01.h"
#include "sq_status.h"
#include "squeal_msgs.h"

#define N 2000000UL

static double now_s(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

int main(void)
{
	static const e2e_p01_config_t st_cfg = { MSG_SQUEAL_STATUS_DATA_ID, MSG_SQUEAL_STATUS_DLC, 1 };
	static const e2e_p01_config_t ds_cfg = { MSG_DISC_SPEED_DATA_ID, MSG_DISC_SPEED_DLC, 1 };
	volatile uint8_t sink = 0;
	uint8_t frame[8] = { 1, 2, 3, 4, 5, 6, 7, 8 };
	uint8_t frames[15][8];
	e2e_p01_tx_t tx;
	e2e_p01_rx_t rx;
	uint8_t dlc = 0;
	double t0, t1;

	t0 = now_s();
	for (unsigned long i = 0; i < N; i++) {
		frame[1] = (uint8_t)i;
		sink = (uint8_t)(sink ^ crc8_p01(frame, 8));
	}
	t1 = now_s();
	printf("crc8_p01 over 8 bytes:               %6.1f ns\n", (t1 - t0) * 1e9 / (double)N);

	e2e_p01_tx_init(&tx);
	t0 = now_s();
	for (unsigned long i = 0; i < N; i++) {
		msg_squeal_status_t m = { 0, 0, (uint8_t)(i & 3U), 2, (uint16_t)(i % 10000U),
					  (int16_t)(i & 0x7FFFU), (uint8_t)(i & 0xFFU) };

		if (msg_squeal_status_pack(&m, frame, &dlc) != SQ_OK ||
		    e2e_p01_protect(&st_cfg, &tx, frame, dlc) != SQ_OK) {
			return 1;
		}
		sink = (uint8_t)(sink ^ frame[0]);
	}
	t1 = now_s();
	printf("SquealStatus pack + protect:         %6.1f ns\n", (t1 - t0) * 1e9 / (double)N);

	e2e_p01_tx_init(&tx);
	for (unsigned int c = 0; c < 15U; c++) {
		msg_disc_speed_t m = { 0, 0, (uint16_t)(1000U + c) };

		if (msg_disc_speed_pack(&m, frames[c], &dlc) != SQ_OK ||
		    e2e_p01_protect(&ds_cfg, &tx, frames[c], dlc) != SQ_OK) {
			return 1;
		}
	}
	e2e_p01_rx_init(&rx);
	t0 = now_s();
	for (unsigned long i = 0; i < N; i++) {
		msg_disc_speed_t m;

		if (msg_disc_speed_receive(&ds_cfg, &rx, frames[i % 15U], 4, &m) != SQ_OK) {
			return 1;
		}
		sink = (uint8_t)(sink ^ m.disc_speed_radps);
	}
	t1 = now_s();
	printf("DiscSpeed receive (check + unpack):  %6.1f ns\n", (t1 - t0) * 1e9 / (double)N);
	(void)sink;
	return 0;
}
