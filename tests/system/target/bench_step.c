/* SPDX-License-Identifier: MIT */
/*
 * Cost of the 1 ms task on the target, for `make bench` under
 * "qemu-system-arm -icount shift=0": the monitor (firmware/monitor) with the
 * default calibration, fed E2E-protected DiscSpeed/PadForce frames every
 * 10 ms through a braking manoeuvre (disc 100 -> 0 rad/s at 9000 N, the
 * same ramp as tests/firmware/monitor/bench_monitor_step.c), then 1 s dwells at three
 * speeds. One step = the frames of that millisecond (monitor_on_frame) +
 * monitor_step() + draining its TX queue, as squeal_app_poll does, without
 * the HAL calls. Timing as tv_target.c: bench_ticks() and a calibration loop.
 * Then the same with four corners on the same frames ("BENCH4"): every
 * step feeds, ticks and drains all four, and classifies at most one.
 * On an FD controller (no HAL_CAN_CLASSIC_ONLY: the G4) also four corners
 * on an input map whose two signals sit deep in 64-byte CAN FD frames with
 * E2E Profile 5 ("BENCHFD4", with deviations "BENCHFDS4"): the input stage
 * then checks a CRC-16 over 64 bytes per frame and corner.
 */
#include "calib.h"
#include "calib_map.h"
#include "e2e_p01.h"
#include "e2e_p05.h"
#include "hal.h"
#include "bench_ticks.h"
#include "stm32_board.h"
#include "monitor.h"
#include "squeal_app.h"
#include "squeal_msgs.h"

#define CAL_LOOPS 100000UL
#define FORCE_RAW 18000U /* 9000 N */

int squeal_app_init(void)
{
	return SQ_OK;
}

uint64_t squeal_app_poll(void)
{
	return hal_time_us();
}

/* The layout comes from the protocol's own pack functions (the DBC's). */
static hal_can_frame_t make_frame(uint32_t id, uint16_t data_id, e2e_p01_tx_t *tx, uint16_t raw)
{
	hal_can_frame_t f = { 0 };
	int rc;

	f.id = id;
	if (id == MSG_DISC_SPEED_ID) {
		const msg_disc_speed_t m = { 0U, 0U, raw };

		rc = msg_disc_speed_pack(&m, f.data, &f.dlc);
	} else {
		const msg_pad_force_t m = { 0U, 0U, raw };

		rc = msg_pad_force_pack(&m, f.data, &f.dlc);
	}
	if (rc == SQ_OK) {
		const e2e_p01_config_t cfg = { data_id, f.dlc, 1U };

		rc = e2e_p01_protect(&cfg, tx, f.data, f.dlc);
	}
	if (rc != SQ_OK) {
		f.dlc = 0U;
	}
	return f;
}

#ifndef HAL_CAN_CLASSIC_ONLY
/* The FD map's frame of input in: 64 bytes of filler (other signals of the
 * message), the value at its place, P05 at in->e2e_offset_byte. */
static hal_can_frame_t make_fd_frame(const calib_input_t *in, e2e_p01_tx_t *tx, uint16_t raw)
{
	hal_can_frame_t f = { 0 };
	const e2e_p05_config_t cfg = { in->data_id, in->min_dlc, in->e2e_offset_byte,
				       in->max_delta_counter };
	uint32_t i;

	f.id = in->id;
	f.flags = (uint8_t)(HAL_CAN_FLAG_FDF | HAL_CAN_FLAG_BRS);
	f.dlc = in->min_dlc;
	for (i = 0U; i < f.dlc; i++) {
		f.data[i] = (uint8_t)(0xA5U ^ i);
	}
	can_signal_put(&in->sig, f.data, raw);
	if (e2e_p05_protect(&cfg, tx, f.data, f.dlc) != SQ_OK) {
		f.dlc = 0U;
	}
	return f;
}
#endif

static uint32_t speed_raw_at(uint32_t frame_no)
{
	static const uint16_t dwell[3] = { 2500U, 1250U, 900U };

	if (frame_no <= 400U) {
		return 10000U - 25U * frame_no; /* 100 rad/s down to 0 */
	}
	frame_no -= 401U;
	return dwell[(frame_no / 100U) % 3U];
}

typedef struct {
	uint64_t total;
	uint64_t total_frames;
	uint32_t steps_frames;
	uint32_t worst;
	uint32_t n;
	uint32_t classifications;
} bench_t;

/* n monitors (corners) on cal, all fed the same frames; the step
 * classifies at most one of them, in turn (as squeal_app_poll). */
static void run(monitor_t *mons, uint32_t n_corners, const calib_t *cal, uint32_t overhead,
		bench_t *b)
{
#ifndef HAL_CAN_CLASSIC_ONLY
	/* P05-protected inputs: the map's FD frames (input 0 speed, 1 force) */
	const bool fd_map = (cal->n_corners != 0U) && (cal->inputs[0].protection == (uint8_t)CALIB_PROT_P05);
#endif
	e2e_p01_tx_t tx_speed = { 0U };
	e2e_p01_tx_t tx_force = { 0U };
	uint64_t now_us = 1000000U;
	uint32_t frames_sent = 0U;
	uint32_t next = 0U;
	uint32_t ms;
	uint32_t c;

	(void)overhead;
	*b = (bench_t){ 0 };
	for (c = 0U; c < n_corners; c++) {
		if (monitor_init_corner(&mons[c], cal, c, false, 0U, now_us) != SQ_OK) {
			semihost_write0("BENCH monitor_init failed\n");
			semihost_exit(1U);
		}
	}
	for (ms = 0; ms < 7000U; ms++) {
		hal_can_frame_t f;
		hal_can_frame_t g;
		uint32_t dt;
		uint32_t k;
		uint32_t slot = UINT32_MAX;
		const bool frames = (ms % 10U) == 0U;
		uint32_t t0;

		now_us += 1000U;
		t0 = bench_ticks();
		if (frames) {
			const uint32_t raw = speed_raw_at(frames_sent++);

#ifndef HAL_CAN_CLASSIC_ONLY
			if (fd_map) {
				f = make_fd_frame(&cal->inputs[0], &tx_speed, (uint16_t)raw);
				g = make_fd_frame(&cal->inputs[1], &tx_force, FORCE_RAW);
			} else
#endif
			{
				f = make_frame(MSG_DISC_SPEED_ID, MSG_DISC_SPEED_DATA_ID, &tx_speed,
					       (uint16_t)raw);
				g = make_frame(MSG_PAD_FORCE_ID, MSG_PAD_FORCE_DATA_ID, &tx_force, FORCE_RAW);
			}
			f.timestamp_us = now_us;
			g.timestamp_us = now_us;
			for (c = 0U; c < n_corners; c++) {
				monitor_on_frame(&mons[c], &f);
				monitor_on_frame(&mons[c], &g);
			}
		}
		for (c = 0U; (c < n_corners) && (slot == UINT32_MAX); c++) {
			if (monitor_wants_classify(&mons[(next + c) % n_corners])) {
				slot = (next + c) % n_corners;
				next = (slot + 1U) % n_corners;
			}
		}
		for (c = 0U; c < n_corners; c++) {
			monitor_step_slot(&mons[c], now_us, (n_corners == 1U) || (c == slot));
			for (k = 0; k < 16U && monitor_peek_tx(&mons[c], &f) == SQ_OK; k++) {
				monitor_tx_done(&mons[c], SQ_OK);
			}
		}
		dt = bench_ticks() - t0;
		b->total += dt;
		if (frames) {
			b->total_frames += dt;
			b->steps_frames++;
		}
		if (dt > b->worst) {
			b->worst = dt;
		}
		b->n++;
	}
	for (c = 0U; c < n_corners; c++) {
		b->classifications += mons[c].count.classifications;
	}
}

static void report(const char *tag, const bench_t *b, uint32_t overhead, uint32_t cal_ticks)
{
	semihost_write0(tag);
	semihost_print_u32(" steps=", b->n, NULL);
	semihost_print_u32(" ticks_total=", (uint32_t)b->total, NULL);
	semihost_print_u32(" steps_with_frames=", b->steps_frames, NULL);
	semihost_print_u32(" ticks_frames=", (uint32_t)b->total_frames, NULL);
	semihost_print_u32(" ticks_max=", b->worst, NULL);
	semihost_print_u32(" overhead_ticks=", overhead, NULL);
	semihost_print_u32(" cal_ticks=", cal_ticks, NULL);
	semihost_print_u32(" cal_insns=", 2U * CAL_LOOPS, NULL);
	semihost_print_u32(" classifications=", b->classifications, "\n");
}

/* the Monte Carlo file's first set: m 2 %, w0 1.5 %, D 10 %, dmu 4 %, a 5 %,
 * corr(a, dmu) 0.85 (tests/support/golden/sigma_vectors.csv) */
static void sd_on(calib_sd_t *sd)
{
	sd->mass_sd_q16 = 1311;
	sd->omega0_sd_q12 = 75 * 4096;
	sd->damping_sd_q30 = 2469606;
	sd->delta_mu_sd_q30 = 6442451;
	sd->slope_sd_q24 = 1677722;
	sd->slope_delta_mu_corr_q30 = 912680550;
}

#ifndef HAL_CAN_CLASSIC_ONLY
/* cal4's inputs moved into 64-byte FD messages with E2E P05: the speed at
 * bytes 40..41, the force at 56..57 (Intel), the P05 header at bytes 0..2;
 * the same raw scaling, identifiers and corners. */
static void fd_map_of(const calib_t *cal4, calib_t *fd)
{
	static const uint16_t start_bit[2] = { 320U, 448U };
	static const uint16_t data_id[2] = { 0x0A10U, 0x0A11U };
	uint32_t i;

	*fd = *cal4;
	for (i = 0U; i < 2U; i++) {
		calib_input_t *in = &fd->inputs[i];

		in->fd = 1U;
		in->min_dlc = 64U;
		in->sig = (can_signal_t){ start_bit[i], 16U, (uint8_t)CAN_SIGNAL_INTEL, 0U };
		in->protection = (uint8_t)CALIB_PROT_P05;
		in->data_id = data_id[i];
		in->e2e_offset_byte = 0U;
		in->max_delta_counter = 1U;
	}
	if (calib_validate(fd) != SQ_OK) {
		semihost_write0("BENCHFD map refused by calib_validate\n");
		semihost_exit(1U);
	}
}
#endif

int squeal_main(volatile const bool *stop)
{
	static calib_t cal;
	static calib_t cal4;
#ifndef HAL_CAN_CLASSIC_ONLY
	static calib_t calfd;
#endif
	static monitor_t mons[CALIB_MAX_CORNERS];
	calib_corner_t c0;
	bench_t b;
	uint32_t t0;
	uint32_t cal_ticks;
	uint32_t overhead;
	uint32_t c;

	(void)stop;
	calib_default(&cal);
	/* four corners on the same DiscSpeed/PadForce frames, each its own
	 * outputs: every frame feeds every corner */
	calib_default(&cal4);
	(void)calib_corner_view(&cal4, 0U, &c0, &cal4.inputs[0], &cal4.inputs[1]);
	cal4.n_inputs = 2U;
	cal4.n_corners = (uint8_t)CALIB_MAX_CORNERS;
	for (c = 0U; c < CALIB_MAX_CORNERS; c++) {
		calib_corner_defaults(&cal4, (uint8_t)c, &cal4.corners[c]);
		cal4.corners[c].speed_input = 0U;
		cal4.corners[c].force_input = 1U;
	}
	bench_ticks_start();
	t0 = bench_ticks();
	overhead = bench_ticks() - t0;
	t0 = bench_ticks();
	{
		uint32_t k = CAL_LOOPS;

		__asm__ volatile("1: subs %0, %0, #1\n\t"
				 "bne 1b\n\t"
				 : "+r"(k)::"cc");
	}
	cal_ticks = bench_ticks() - t0;
	run(mons, 1U, &cal, overhead, &b);
	report("BENCH", &b, overhead, cal_ticks);
	run(mons, CALIB_MAX_CORNERS, &cal4, overhead, &b);
	report("BENCH4", &b, overhead, cal_ticks);
#ifndef HAL_CAN_CLASSIC_ONLY
	fd_map_of(&cal4, &calfd);
	run(mons, CALIB_MAX_CORNERS, &calfd, overhead, &b);
	report("BENCHFD4", &b, overhead, cal_ticks);
#endif
	/* the same with standard deviations calibrated: every
	 * classification also propagates them (the corners inherit the flat
	 * deviations: set them on each) */
	sd_on(&cal.sd);
	sd_on(&cal4.sd);
	for (c = 0U; c < CALIB_MAX_CORNERS; c++) {
		sd_on(&cal4.corners[c].sd);
	}
	run(mons, 1U, &cal, overhead, &b);
	report("BENCHS", &b, overhead, cal_ticks);
	run(mons, CALIB_MAX_CORNERS, &cal4, overhead, &b);
	report("BENCHS4", &b, overhead, cal_ticks);
#ifndef HAL_CAN_CLASSIC_ONLY
	fd_map_of(&cal4, &calfd);
	run(mons, CALIB_MAX_CORNERS, &calfd, overhead, &b);
	report("BENCHFDS4", &b, overhead, cal_ticks);
#endif
	semihost_exit(0U);
}
