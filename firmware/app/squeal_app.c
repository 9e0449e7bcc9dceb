/* SPDX-License-Identifier: MIT */
/*
 * The scheduler: init and a 1 ms cooperative loop, identical on every
 * platform (the ECU, the host-sim in real time, replay in virtual time).
 * It moves frames between the HAL and the monitor and measures each 1 ms
 * task through the HAL's cycle counter.
 */
#include "squeal_app.h"

#include <stddef.h>

#include "calib.h"
#include "hal.h"
#include "monitor.h"
#include "sq_status.h"

#define TICK_US 1000U
/* frames taken from the HAL per poll: bounds the time of one poll; the
 * kernel/FIFO keeps the rest for the next one */
#define RX_BUDGET 64U

static monitor_t app_monitor;
static uint64_t app_next_tick_us;
static int app_init_rc;

/* Calibration from storage: none stored -> defaults (factory state, not a
 * fault); unreadable or corrupt -> defaults and the CalibInvalid fault. */
static bool load_calibration(calib_t *cal)
{
	uint8_t buf[CALIB_BLOCK_LEN];
	calib_error_t why = CALIB_OK;
	int rc;

	rc = hal_calib_read(buf, CALIB_BLOCK_LEN);
	if (rc == SQ_OK) {
		if (calib_decode(buf, CALIB_BLOCK_LEN, cal, &why) == SQ_OK) {
			return false;
		}
	}
	calib_default(cal);
	return rc != SQ_ENOENT;
}

int squeal_app_init(void)
{
	calib_t cal;
	bool calib_invalid;
	hal_can_filter_t filters[2];
	int rc;
	int first_error = SQ_OK;

	calib_invalid = load_calibration(&cal);
	rc = monitor_init(&app_monitor, &cal, calib_invalid, hal_platform_faults(),
			  hal_time_us());
	if (rc != SQ_OK) {
		first_error = rc;
	}
	if (calib_invalid && (first_error == SQ_OK)) {
		first_error = SQ_EBADMSG;
	}
	/* bit rate first: a restart of the controller resets its filters */
	rc = hal_can_set_bitrate(0U, app_monitor.cal.bitrate_kbps);
	if ((rc != SQ_OK) && (rc != SQ_ENOTSUP) && (first_error == SQ_OK)) {
		first_error = rc;
	}
	filters[0] = (hal_can_filter_t){ app_monitor.cal.disc_speed_id, HAL_CAN_STD_ID_MAX, 0U };
	filters[1] = (hal_can_filter_t){ app_monitor.cal.pad_force_id, HAL_CAN_STD_ID_MAX, 0U };
	rc = hal_can_set_rx_filter(0U, filters, 2U);
	if ((rc != SQ_OK) && (rc != SQ_ENOTSUP) && (first_error == SQ_OK)) {
		first_error = rc;
	}
	rc = hal_watchdog_start(app_monitor.cal.watchdog_ms);
	if ((rc != SQ_OK) && (rc != SQ_ENOTSUP) && (first_error == SQ_OK)) {
		first_error = rc;
	}
	app_next_tick_us = hal_time_us();
	app_init_rc = first_error;
	return first_error;
}

static void transmit(void)
{
	hal_can_frame_t f;
	uint32_t i;

	for (i = 0U; i < MONITOR_TX_QUEUE_LEN; i++) {
		int rc;

		if (monitor_peek_tx(&app_monitor, &f) != SQ_OK) {
			break;
		}
		rc = hal_can_send(0U, &f);
		if (rc == SQ_ENOBUFS) {
			break; /* stays queued: retried next tick */
		}
		monitor_tx_done(&app_monitor, rc);
	}
}

uint64_t squeal_app_poll(void)
{
	hal_can_frame_t f;
	hal_can_status_t st;
	uint64_t now = hal_time_us();
	uint32_t i;

	for (i = 0U; i < RX_BUDGET; i++) {
		if (hal_can_receive(0U, &f) != SQ_OK) {
			break;
		}
		monitor_on_frame(&app_monitor, &f);
	}
	if (now >= app_next_tick_us) {
		const uint32_t t0 = hal_cycles();
		uint32_t cpu = hal_cycles_per_us();

		if (hal_can_get_status(0U, &st) == SQ_OK) {
			monitor_on_can_status(&app_monitor, &st);
		}
		monitor_step(&app_monitor, now);
		transmit();
		hal_watchdog_kick();
		if (cpu == 0U) {
			cpu = 1U;
		}
		monitor_report_task_time(&app_monitor, (hal_cycles() - t0) / cpu);
		app_next_tick_us += TICK_US;
		if (app_next_tick_us <= now) {
			app_next_tick_us = now + TICK_US; /* late: skip, don't burst */
		}
	}
	return app_next_tick_us;
}

int squeal_main(volatile const bool *stop)
{
	const int rc = squeal_app_init();

	while ((stop == NULL) || !*stop) {
		hal_idle_until(squeal_app_poll());
	}
	return rc;
}

const monitor_t *squeal_app_monitor(void)
{
	return &app_monitor;
}

int squeal_app_init_status(void)
{
	return app_init_rc;
}
