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
#include "calib_map.h"
#include "hal.h"
#include "monitor.h"
#include "sq_status.h"

#define TICK_US 1000U

_Static_assert(CALIB_BLOCK_LEN <= HAL_CALIB_MAX_LEN, "the calibration block fits the storage");
/* frames taken from the HAL per poll: bounds the time of one poll; the
 * kernel/FIFO keeps the rest for the next one */
#define RX_BUDGET 64U

/* One monitor per corner; the 1 ms step classifies at most one of them
 * (round robin over the corners that have a new input pair). */
static calib_t app_cal; /* the one calibration all corners read */
static monitor_t app_monitor[CALIB_MAX_CORNERS];
static uint32_t app_corners = 1U;
static uint32_t app_next_corner;
static uint64_t app_next_tick_us;
static int app_init_rc;

/* A receive filter entry: identifier and frame format. */
typedef struct {
	uint32_t id;
	bool ext;
} app_rx_id_t;

/*
 * The identifiers the corners listen to, each once, from the input map
 * (the legacy form: DiscSpeed and PadForce). The one place that knows what
 * the receive filter holds.
 */
static uint32_t rx_filter_ids(app_rx_id_t ids[2U * CALIB_MAX_CORNERS])
{
	uint32_t n = 0U;
	uint32_t k;

	for (k = 0U; k < app_corners; k++) {
		const calib_input_t *in[2];
		uint32_t j;

		in[0] = &app_monitor[k].speed_rx.desc;
		in[1] = &app_monitor[k].force_rx.desc;

		for (j = 0U; j < 2U; j++) {
			const bool ext = (in[j]->flags & CALIB_IN_EXTENDED) != 0U;
			bool seen = false;
			uint32_t i;

			for (i = 0U; i < n; i++) {
				seen = seen || ((ids[i].id == in[j]->id) && (ids[i].ext == ext));
			}
			if (!seen) {
				ids[n] = (app_rx_id_t){ in[j]->id, ext };
				n++;
			}
		}
	}
	return n;
}

/* The HAL filters standard identifiers only (until the bus-index HAL):
 * with a 29-bit input the filter stays open and the monitors sort. */
static int set_rx_filter(void)
{
	app_rx_id_t list[2U * CALIB_MAX_CORNERS];
	uint32_t ids[2U * CALIB_MAX_CORNERS];
	const uint32_t n = rx_filter_ids(list);
	uint32_t i;

	if (n > HAL_CAN_MAX_FILTERS) {
		return SQ_OK;
	}
	for (i = 0U; i < n; i++) {
		if (list[i].ext) {
			return SQ_OK;
		}
		ids[i] = list[i].id;
	}
	return hal_can_set_rx_filter(ids, n);
}

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
	bool calib_invalid;
	int rc;
	int first_error = SQ_OK;
	uint32_t k;

	calib_invalid = load_calibration(&app_cal);
	rc = monitor_init(&app_monitor[0], &app_cal, calib_invalid, hal_platform_faults(),
			  hal_time_us());
	if (rc != SQ_OK) {
		first_error = rc;
	}
	/* corners 1.. only with a valid calibration (monitor 0 fell back to
	 * the defaults' single corner otherwise) */
	app_corners = calib_corner_count(app_monitor[0].cal);
	for (k = 1U; k < app_corners; k++) {
		(void)monitor_init_corner(&app_monitor[k], app_monitor[0].cal, k, calib_invalid,
					  hal_platform_faults(), hal_time_us());
	}
	app_next_corner = 0U;
	if (calib_invalid && (first_error == SQ_OK)) {
		first_error = SQ_EBADMSG;
	}
	/* bit rate first: a restart of the controller resets its filters */
	rc = hal_can_set_bitrate(app_monitor[0].cal->bitrate_kbps);
	if ((rc != SQ_OK) && (rc != SQ_ENOTSUP) && (first_error == SQ_OK)) {
		first_error = rc;
	}
	rc = set_rx_filter();
	if ((rc != SQ_OK) && (rc != SQ_ENOTSUP) && (first_error == SQ_OK)) {
		first_error = rc;
	}
	rc = hal_watchdog_start(app_monitor[0].cal->watchdog_ms);
	if ((rc != SQ_OK) && (rc != SQ_ENOTSUP) && (first_error == SQ_OK)) {
		first_error = rc;
	}
	app_next_tick_us = hal_time_us();
	app_init_rc = first_error;
	return first_error;
}

/* false when the HAL's queue is full (the rest waits for the next tick) */
static bool transmit(monitor_t *mon)
{
	hal_can_frame_t f;
	uint32_t i;

	for (i = 0U; i < MONITOR_TX_QUEUE_LEN; i++) {
		int rc;

		if (monitor_peek_tx(mon, &f) != SQ_OK) {
			break;
		}
		rc = hal_can_send(&f);
		if (rc == SQ_ENOBUFS) {
			return false; /* stays queued: retried next tick */
		}
		monitor_tx_done(mon, rc);
	}
	return true;
}

/* The corner that may classify in this step: the next one, in turn, that
 * has a new input pair; UINT32_MAX when none has. */
static uint32_t classify_slot(void)
{
	uint32_t i;

	for (i = 0U; i < app_corners; i++) {
		const uint32_t k = (app_next_corner + i) % app_corners;

		if (monitor_wants_classify(&app_monitor[k])) {
			app_next_corner = (k + 1U) % app_corners;
			return k;
		}
	}
	return UINT32_MAX;
}

uint64_t squeal_app_poll(void)
{
	hal_can_frame_t f;
	hal_can_status_t st;
	uint64_t now = hal_time_us();
	uint32_t i;

	uint32_t k;

	for (i = 0U; i < RX_BUDGET; i++) {
		if (hal_can_receive(&f) != SQ_OK) {
			break;
		}
		for (k = 0U; k < app_corners; k++) {
			monitor_on_frame(&app_monitor[k], &f);
		}
	}
	if (now >= app_next_tick_us) {
		const uint32_t t0 = hal_cycles();
		uint32_t cpu = hal_cycles_per_us();
		const uint32_t slot = classify_slot();
		bool tx_room = true;
		uint32_t task_us;

		if (hal_can_get_status(&st) == SQ_OK) {
			for (k = 0U; k < app_corners; k++) {
				monitor_on_can_status(&app_monitor[k], &st);
			}
		}
		for (k = 0U; k < app_corners; k++) {
			monitor_step_slot(&app_monitor[k], now, (app_corners == 1U) || (k == slot));
			if (tx_room) {
				tx_room = transmit(&app_monitor[k]);
			}
		}
		hal_watchdog_kick();
		if (cpu == 0U) {
			cpu = 1U;
		}
		task_us = (hal_cycles() - t0) / cpu;
		for (k = 0U; k < app_corners; k++) {
			monitor_report_task_time(&app_monitor[k], task_us);
		}
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
	return &app_monitor[0];
}

uint32_t squeal_app_corner_count(void)
{
	return app_corners;
}

const monitor_t *squeal_app_corner(uint32_t k)
{
	return (k < app_corners) ? &app_monitor[k] : NULL;
}

int squeal_app_init_status(void)
{
	return app_init_rc;
}
