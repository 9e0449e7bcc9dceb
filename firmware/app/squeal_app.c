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

/* Keep the first error of init; SQ_ENOTSUP is fine where the platform owns
 * the setting (Linux: the bit rate belongs to `ip link`). */
static void note_init(int *first_error, int rc, bool enotsup_ok)
{
	if ((rc != SQ_OK) && !(enotsup_ok && (rc == SQ_ENOTSUP)) && (*first_error == SQ_OK)) {
		*first_error = rc;
	}
}

/* Inputs from cal.input_bus (listen-only if cal.input_listen_only), outputs
 * on cal.output_bus; the defaults (0, 0, normal) are the single-bus ECU. */
static int start_buses(const calib_t *cal)
{
	const uint8_t in = cal->input_bus;
	const uint8_t out = cal->output_bus;
	hal_can_filter_t filters[2];
	int first_error = SQ_OK;

	/* bit rate first: a restart of the controller resets its filters */
	note_init(&first_error, hal_can_set_bitrate(in, cal->bitrate_kbps), true);
	if (out != in) {
		note_init(&first_error, hal_can_set_bitrate(out, cal->bitrate_kbps), true);
	}
	if (cal->input_listen_only != 0U) {
		/* not supported means the node would ACK on the input bus: an
		 * error, never ignored */
		note_init(&first_error, hal_can_set_mode(in, HAL_CAN_MODE_LISTEN_ONLY), false);
	}
	filters[0] = (hal_can_filter_t){ cal->disc_speed_id, HAL_CAN_STD_ID_MAX, 0U };
	filters[1] = (hal_can_filter_t){ cal->pad_force_id, HAL_CAN_STD_ID_MAX, 0U };
	note_init(&first_error, hal_can_set_rx_filter(in, filters, 2U), true);
	if (out != in) {
		/* nothing to receive on the output bus but its error frames */
		note_init(&first_error, hal_can_set_rx_filter(out, NULL, 0U), true);
	}
	return first_error;
}

/* The platform's bring-up self-test in SquealDiag's raw units (page 4;
 * firmware/protocol/squeal.dbc). A platform without one leaves the page
 * "not measured". */
static uint8_t hse_100khz(uint32_t hz)
{
	uint32_t v;

	if (hz == HAL_SELFTEST_NOT_MEASURED) {
		return (uint8_t)MSG_HSE_FREQ_NA;
	}
	v = (hz / 1000U + 50U) / 100U;
	return (v > MSG_HSE_FREQ_MAX) ? (uint8_t)MSG_HSE_FREQ_MAX : (uint8_t)v;
}

static void report_selftest(void)
{
	hal_selftest_t st;
	monitor_selftest_t m;
	const hal_reset_reason_t why = hal_reset_reason();
	uint32_t bus;

	if (hal_selftest(&st) != SQ_OK) {
		return;
	}
	m.hse_freq_100khz = hse_100khz(st.hse_hz);
	m.reset_cause = (uint8_t)why;
	m.bor_level = (st.bor_level == HAL_SELFTEST_NO_BOR) ? (uint8_t)MSG_BOR_LEVEL_NA :
		st.bor_level;
	for (bus = 0U; bus < 2U; bus++) { /* LoopbackCan1, LoopbackCan2 */
		m.loopback[bus] = (bus < HAL_CAN_BUSES) ? st.loopback[bus] :
			(uint8_t)HAL_LOOPBACK_NO_BUS;
	}
	m.stack_high_water_b = (st.stack_high_water_prev_b == HAL_SELFTEST_NOT_MEASURED) ?
		(uint16_t)MSG_STACK_HWM_UNKNOWN :
		((st.stack_high_water_prev_b >= MSG_STACK_HWM_UNKNOWN) ?
		 (uint16_t)(MSG_STACK_HWM_UNKNOWN - 1U) : (uint16_t)st.stack_high_water_prev_b);
	m.failed = st.failed;
	(void)monitor_set_selftest(&app_monitor, &m);
}

int squeal_app_init(void)
{
	calib_t cal;
	bool calib_invalid;
	int rc;
	int first_error = SQ_OK;

	calib_invalid = load_calibration(&cal);
	rc = monitor_init(&app_monitor, &cal, calib_invalid, hal_platform_faults(),
			  hal_time_us());
	note_init(&first_error, rc, false);
	report_selftest();
	if (calib_invalid && (first_error == SQ_OK)) {
		first_error = SQ_EBADMSG;
	}
	note_init(&first_error, start_buses(&app_monitor.cal), false);
	note_init(&first_error, hal_watchdog_start(app_monitor.cal.watchdog_ms), true);
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
		rc = hal_can_send(app_monitor.cal.output_bus, &f);
		if (rc == SQ_ENOBUFS) {
			break; /* stays queued: retried next tick */
		}
		monitor_tx_done(&app_monitor, rc);
	}
}

/* The CAN status the monitor sees: the input bus's, and with a separate
 * output bus both together (counters added, bus-off if either is). */
static int bus_status(hal_can_status_t *st)
{
	const uint8_t in = app_monitor.cal.input_bus;
	const uint8_t out = app_monitor.cal.output_bus;
	hal_can_status_t o;
	int rc = hal_can_get_status(in, st);

	if ((rc == SQ_OK) && (out != in) && (hal_can_get_status(out, &o) == SQ_OK)) {
		st->bus_off_count += o.bus_off_count;
		st->rx_overruns += o.rx_overruns;
		if (o.state == HAL_CAN_STATE_BUS_OFF) {
			st->state = HAL_CAN_STATE_BUS_OFF;
		}
	}
	return rc;
}

uint64_t squeal_app_poll(void)
{
	hal_can_frame_t f;
	hal_can_status_t st;
	uint64_t now = hal_time_us();
	uint32_t i;

	for (i = 0U; i < RX_BUDGET; i++) {
		if (hal_can_receive(app_monitor.cal.input_bus, &f) != SQ_OK) {
			break;
		}
		monitor_on_frame(&app_monitor, &f);
	}
	/* a separate output bus: only its error frames count (its filter
	 * passes no data frame; one that arrives anyway is not an input) */
	for (i = 0U; (i < RX_BUDGET) && (app_monitor.cal.output_bus != app_monitor.cal.input_bus); i++) {
		if (hal_can_receive(app_monitor.cal.output_bus, &f) != SQ_OK) {
			break;
		}
		if ((f.flags & HAL_CAN_FLAG_ERR) != 0U) {
			monitor_on_frame(&app_monitor, &f);
		}
	}
	if (now >= app_next_tick_us) {
		const uint32_t t0 = hal_cycles();
		uint32_t cpu = hal_cycles_per_us();

		if (bus_status(&st) == SQ_OK) {
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
