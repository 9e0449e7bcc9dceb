/* SPDX-License-Identifier: MIT */
/*
 * Cost driver for the 1 ms task: squeal_app_poll() on the test HAL through
 * a braking manoeuvre (30 m/s -> stop at 9000 N, Omega -0.25 rad/s per
 * 10 ms frame) followed by 1.2 s dwells at a stable, a bistable and an
 * unstable point. Inputs arrive in the same millisecond as the periodic
 * transmissions, so the steps that receive two frames, classify, and send
 * SquealStatus + Detail + Detail2 + Diag are all in the run.
 *
 * A second argument "sigma" calibrates standard deviations (the Monte Carlo
 * file's first set: m 2 %, w0 1.5 %, D 10 %, dmu 4 %, a 5 %, corr 0.85):
 * every classification also propagates them (squeal_sigma).
 *
 * With an argument N (2..4) the calibration has N corners, all on the same
 * DiscSpeed/PadForce frames (each corner its own outputs): every frame feeds
 * every corner, and the app staggers their classifications, one per step.
 *
 * Under callgrind (tests/firmware/monitor/bench_monitor_cost.sh) every poll is followed
 * by CALLGRIND_DUMP_STATS, so each dump holds exactly one poll's cost (with
 * --toggle-collect limiting collection to the function measured). Without
 * valgrind the requests are no-ops and it just runs.
 */
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <valgrind/callgrind.h>

#include "calib.h"
#include "calib_map.h"
#include "sq_status.h"
#include "squeal_app.h"
#include "test_hal.h"

#define T0_US 1000000ULL
#define FORCE_RAW 18000U

static test_sender_t snd;
static uint32_t n_frames;

static int queue(uint16_t speed_raw, uint32_t k)
{
	return test_send_pair(&snd, speed_raw, FORCE_RAW, T0_US + 10000ULL * k);
}

/* n corners on the legacy inputs (1: the legacy form), with or without
 * deviations, stored as the app's calibration */
static int store_corners(uint32_t n, bool sigma)
{
	static calib_t cal;
	static uint8_t block[CALIB_BLOCK_LEN];
	calib_corner_t c0;

	calib_default(&cal);
	if (sigma) {
		cal.sd.mass_sd_q16 = 1311;
		cal.sd.omega0_sd_q12 = 75 * 4096;
		cal.sd.damping_sd_q30 = 2469606;
		cal.sd.delta_mu_sd_q30 = 6442451;
		cal.sd.slope_sd_q24 = 1677722;
		cal.sd.slope_delta_mu_corr_q30 = 912680550;
	}
	if (n == 1U) {
		if (calib_encode(&cal, block, sizeof(block)) != SQ_OK) {
			return SQ_EINVAL;
		}
		test_hal_calib_store(block, sizeof(block));
		return SQ_OK;
	}
	if (calib_corner_view(&cal, 0U, &c0, &cal.inputs[0], &cal.inputs[1]) != SQ_OK) {
		return SQ_EINVAL;
	}
	cal.n_inputs = 2U;
	cal.n_corners = (uint8_t)n;
	for (uint32_t k = 0U; k < n; k++) {
		calib_corner_defaults(&cal, (uint8_t)k, &cal.corners[k]);
		cal.corners[k].speed_input = 0U;
		cal.corners[k].force_input = 1U;
	}
	if (calib_encode(&cal, block, sizeof(block)) != SQ_OK) {
		return SQ_EINVAL;
	}
	test_hal_calib_store(block, sizeof(block));
	return SQ_OK;
}

int main(int argc, char **argv)
{
	const uint32_t corners = (argc > 1) ? (uint32_t)strtoul(argv[1], NULL, 10) : 1U;
	const bool sigma = (argc > 2) && (strcmp(argv[2], "sigma") == 0);
	static const uint16_t dwell[3] = { 2500U, 1250U, 900U }; /* 3, 1.5, 1.08 m/s */
	uint32_t k = 0U;
	uint32_t polls = 0U;
	uint64_t end;

	test_hal_reset();
	test_hal_set_time_us(T0_US);
	test_sender_init(&snd);
	if ((corners < 1U) || (corners > CALIB_MAX_CORNERS) ||
	    (((corners > 1U) || sigma) && (store_corners(corners, sigma) != SQ_OK))) {
		fprintf(stderr, "corners 1..4\n");
		return 1;
	}
	if ((squeal_app_init() != SQ_OK) || (squeal_app_corner_count() != corners)) {
		fprintf(stderr, "init failed\n");
		return 1;
	}
	for (uint32_t raw = 10000U;; raw -= 25U) {
		if (queue((uint16_t)raw, k++) != SQ_OK) {
			return 1;
		}
		if (raw == 0U) {
			break;
		}
	}
	for (uint32_t d = 0U; d < 3U; d++) {
		/* jump to the dwell point (a step beyond the rate limit costs
		 * one implausible frame: that path is measured too), hold */
		for (uint32_t i = 0U; i < 120U; i++) {
			if (queue(dwell[d], k++) != SQ_OK) {
				return 1;
			}
		}
	}
	n_frames = k;
	end = T0_US + 10000ULL * k;
	while (hal_time_us() <= end) {
		(void)squeal_app_poll();
		CALLGRIND_DUMP_STATS;
		polls++;
		test_hal_advance_us(1000U);
	}
	printf("%scorners %u, polls %u, input pairs %u, classifications %u, state changes %u, "
	       "frames sent %u, final state %u\n", sigma ? "sigma on, " : "", corners, polls, n_frames,
	       squeal_app_monitor()->count.classifications,
	       squeal_app_monitor()->count.state_changes, test_hal_tx_count(),
	       squeal_app_monitor()->state);
	for (uint32_t c = 1U; c < corners; c++) {
		printf("  corner %u: classifications %u, final state %u\n", c,
		       squeal_app_corner(c)->count.classifications, squeal_app_corner(c)->state);
	}
	return 0;
}
