/* SPDX-License-Identifier: MIT */
/*
 * The scheduler: init and a 1 ms cooperative loop, identical on every
 * platform (the ECU, the host-sim in real time, replay in virtual time).
 * It moves frames between the HAL and the corners' monitors and measures
 * each 1 ms task through the HAL's cycle counter.
 *
 * Buses: the inputs come from cal.input_bus (listen-only when
 * cal.input_listen_only: the node puts nothing on the vehicle's bus), the
 * outputs go out on cal.output_bus; the defaults (0, 0, normal) are the
 * single-bus ECU.
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
/* frames taken from the HAL per poll and bus: bounds the time of one poll;
 * the kernel/FIFO keeps the rest for the next one */
#define RX_BUDGET 64U

/* One monitor per corner; the 1 ms step classifies at most one of them
 * (round robin over the corners that have a new input pair). */
static calib_t app_cal; /* the one calibration all corners read */
/*
 * The monitors' memory doubles as the buffer the stored calibration block
 * is read into: the block is decoded into app_cal before any monitor starts,
 * and monitor_init() then clears each monitor it sets up. This keeps the
 * block (CALIB_BLOCK_LEN bytes) off the start-up path's stack, the deepest
 * one (make stack-usage), so the ECU's stack reserve can be that much
 * smaller.
 */
static union {
	monitor_t monitor[CALIB_MAX_CORNERS];
	uint8_t block[CALIB_BLOCK_LEN];
} app_mem;
_Static_assert(sizeof(app_mem.monitor) >= CALIB_BLOCK_LEN, "the block fits the monitors' memory");
static uint32_t app_corners = 1U;
static uint32_t app_next_corner;
static uint64_t app_next_tick_us;
static bool app_rx_since_tick; /* a frame reached the monitors after the last tick */
static int app_init_rc;

/* The calibration in use (the stored one, or the factory defaults). */
static const calib_t *cal_in_use(void)
{
	return app_mem.monitor[0].cal;
}

/*
 * The receive filter of the input bus, from the input map: one exact
 * (id, format) entry per identifier the corners listen to (the legacy
 * form: DiscSpeed and PadForce). The one place that knows what the filter
 * holds. More identifiers than the controller has filters: the filter
 * stays open and the monitors sort the frames (counted as unknown ids).
 */
static uint32_t rx_filters(hal_can_filter_t f[HAL_CAN_MAX_FILTERS])
{
	uint32_t n = 0U;
	uint32_t k;

	for (k = 0U; k < app_corners; k++) {
		const calib_input_t *in[2];
		uint32_t j;

		in[0] = &app_mem.monitor[k].speed_rx.desc;
		in[1] = &app_mem.monitor[k].force_rx.desc;
		for (j = 0U; j < 2U; j++) {
			const bool ext = (in[j]->flags & CALIB_IN_EXTENDED) != 0U;
			const hal_can_filter_t want = {
				in[j]->id, ext ? HAL_CAN_EXT_ID_MAX : HAL_CAN_STD_ID_MAX,
				ext ? (uint8_t)HAL_CAN_FLAG_EXT : 0U
			};
			bool seen = false;
			uint32_t i;

			for (i = 0U; i < n; i++) {
				seen = seen || ((f[i].id == want.id) && (f[i].flags == want.flags));
			}
			if (!seen) {
				if (n >= HAL_CAN_MAX_FILTERS) {
					return UINT32_MAX;
				}
				f[n] = want;
				n++;
			}
		}
	}
	return n;
}

/* Keep the first error of init; SQ_ENOTSUP is fine where the platform owns
 * the setting (Linux: the bit rate belongs to `ip link`). */
static void note_init(int *first_error, int rc, bool enotsup_ok)
{
	if ((rc != SQ_OK) && !(enotsup_ok && (rc == SQ_ENOTSUP)) && (*first_error == SQ_OK)) {
		*first_error = rc;
	}
}

static int start_buses(const calib_t *cal)
{
	const uint8_t in = cal->input_bus;
	const uint8_t out = cal->output_bus;
	const hal_can_filter_t all[2] = {
		{ 0U, 0U, 0U }, { 0U, 0U, (uint8_t)HAL_CAN_FLAG_EXT }
	};
	hal_can_filter_t filters[HAL_CAN_MAX_FILTERS];
	uint32_t n;
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
	n = rx_filters(filters);
	if (n == UINT32_MAX) {
		note_init(&first_error, hal_can_set_rx_filter(in, all, 2U), true);
	} else {
		note_init(&first_error, hal_can_set_rx_filter(in, filters, n), true);
	}
	if (out != in) {
		/* nothing to receive on the output bus but its error frames */
		note_init(&first_error, hal_can_set_rx_filter(out, NULL, 0U), true);
	}
	return first_error;
}

/* The platform's bring-up self-test in SquealDiag's raw units (page 4;
 * firmware/protocol/squeal.dbc), the same for every corner. A platform
 * without one leaves the page "not measured". */
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
	uint32_t k;

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
	if (st.stack_high_water_prev_b == HAL_SELFTEST_NOT_MEASURED) {
		m.stack_high_water_b = (uint16_t)MSG_STACK_HWM_UNKNOWN;
	} else if (st.stack_high_water_prev_b >= MSG_STACK_HWM_UNKNOWN) {
		m.stack_high_water_b = (uint16_t)(MSG_STACK_HWM_UNKNOWN - 1U); /* saturated */
	} else {
		m.stack_high_water_b = (uint16_t)st.stack_high_water_prev_b;
	}
	m.failed = st.failed;
	for (k = 0U; k < app_corners; k++) {
		(void)monitor_set_selftest(&app_mem.monitor[k], &m);
	}
}

/* Calibration from storage: none stored -> defaults (factory state, not a
 * fault); unreadable or corrupt -> defaults and the CalibInvalid fault. */
static bool load_calibration(calib_t *cal)
{
	calib_error_t why = CALIB_OK;
	bool invalid = false;
	uint32_t i;
	int rc;

	rc = hal_calib_read(app_mem.block, CALIB_BLOCK_LEN);
	if ((rc != SQ_OK) ||
	    (calib_decode(app_mem.block, CALIB_BLOCK_LEN, cal, &why) != SQ_OK)) {
		calib_default(cal);
		invalid = rc != SQ_ENOENT;
	}
	for (i = 0U; i < CALIB_BLOCK_LEN; i++) {
		app_mem.block[i] = 0U; /* no stale bytes in the monitors' memory */
	}
	return invalid;
}

int squeal_app_init(void)
{
	bool calib_invalid;
	int first_error = SQ_OK;
	uint32_t k;

	calib_invalid = load_calibration(&app_cal);
	note_init(&first_error, monitor_init(&app_mem.monitor[0], &app_cal, calib_invalid,
					     hal_platform_faults(), hal_time_us()), false);
	/* corners 1.. only with a valid calibration (monitor 0 fell back to
	 * the defaults' single corner otherwise) */
	app_corners = calib_corner_count(cal_in_use());
	for (k = 1U; k < app_corners; k++) {
		(void)monitor_init_corner(&app_mem.monitor[k], cal_in_use(), k, calib_invalid,
					  hal_platform_faults(), hal_time_us());
	}
	app_next_corner = 0U;
	report_selftest();
	if (calib_invalid && (first_error == SQ_OK)) {
		first_error = SQ_EBADMSG;
	}
	note_init(&first_error, start_buses(cal_in_use()), false);
	note_init(&first_error, hal_watchdog_start(cal_in_use()->watchdog_ms), true);
	app_next_tick_us = hal_time_us();
	app_rx_since_tick = false;
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
		rc = hal_can_send(cal_in_use()->output_bus, &f);
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

		if (monitor_wants_classify(&app_mem.monitor[k])) {
			app_next_corner = (k + 1U) % app_corners;
			return k;
		}
	}
	return UINT32_MAX;
}

/* The CAN status the monitors see: the input bus's, and with a separate
 * output bus both together (counters added, bus-off if either is). */
static int bus_status(hal_can_status_t *st)
{
	const uint8_t in = cal_in_use()->input_bus;
	const uint8_t out = cal_in_use()->output_bus;
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

static void to_every_corner(const hal_can_frame_t *f)
{
	uint32_t k;

	app_rx_since_tick = true;
	for (k = 0U; k < app_corners; k++) {
		monitor_on_frame(&app_mem.monitor[k], f);
	}
}

uint64_t squeal_app_poll(void)
{
	const uint8_t in = cal_in_use()->input_bus;
	const uint8_t out = cal_in_use()->output_bus;
	hal_can_frame_t f;
	hal_can_status_t st;
	uint64_t now = hal_time_us();
	uint32_t i;

	for (i = 0U; i < RX_BUDGET; i++) {
		if (hal_can_receive(in, &f) != SQ_OK) {
			break;
		}
		to_every_corner(&f);
	}
	/* a separate output bus: only its error frames count (its filter
	 * passes no data frame; one that arrives anyway is not an input) */
	for (i = 0U; (i < RX_BUDGET) && (out != in); i++) {
		if (hal_can_receive(out, &f) != SQ_OK) {
			break;
		}
		if ((f.flags & HAL_CAN_FLAG_ERR) != 0U) {
			to_every_corner(&f);
		}
	}
	if (now >= app_next_tick_us) {
		const uint32_t t0 = hal_cycles();
		uint32_t cpu = hal_cycles_per_us();
		const uint32_t slot = classify_slot();
		bool tx_room = true;
		uint32_t task_us;
		uint32_t k;

		if (bus_status(&st) == SQ_OK) {
			for (k = 0U; k < app_corners; k++) {
				monitor_on_can_status(&app_mem.monitor[k], &st);
			}
		}
		for (k = 0U; k < app_corners; k++) {
			monitor_step_slot(&app_mem.monitor[k], now, (app_corners == 1U) || (k == slot));
			if (tx_room) {
				tx_room = transmit(&app_mem.monitor[k]);
			}
		}
		hal_watchdog_kick();
		if (cpu == 0U) {
			cpu = 1U;
		}
		task_us = (hal_cycles() - t0) / cpu;
		for (k = 0U; k < app_corners; k++) {
			monitor_report_task_time(&app_mem.monitor[k], task_us);
		}
		app_rx_since_tick = false;
		app_next_tick_us += TICK_US;
		if (app_next_tick_us <= now) {
			app_next_tick_us = now + TICK_US; /* late: skip, don't burst */
		}
	}
	return app_next_tick_us;
}

/* The CAN status the monitors took at the last tick is still the HAL's (as
 * monitor_on_can_status() takes it; every corner takes the same). */
static bool can_status_taken(void)
{
	const monitor_t *m = &app_mem.monitor[0];
	hal_can_status_t st;
	bool taken = true; /* no status: a tick takes nothing either */

	if (bus_status(&st) == SQ_OK) {
		taken = (st.bus_off_count == m->count.bus_off_events) &&
			(st.rx_overruns == m->count.rx_overruns) &&
			(m->bus_off_seen ||
			 ((st.state != HAL_CAN_STATE_BUS_OFF) && (st.bus_off_count == 0U)));
	}
	return taken;
}

static uint64_t earlier(uint64_t a, uint64_t b)
{
	return (a < b) ? a : b;
}

/* The first time at which the input goes stale (the monitor's test: older
 * than stale_cycles periods); UINT64_MAX when it already is. */
static uint64_t stale_at_us(const input_t *in, const input_rx_cfg_t *cfg)
{
	const uint64_t timeout_us = (uint64_t)cfg->desc.period_ms * TICK_US *
				    (uint64_t)cfg->desc.stale_cycles;

	return (((in->faults & INPUT_FAULT_STALE) != 0U) ||
		(in->last_used_us >= UINT64_MAX - timeout_us - 1U)) ? UINT64_MAX :
		in->last_used_us + timeout_us + 1U;
}

uint64_t squeal_app_next_event_us(void)
{
	bool pending = app_rx_since_tick; /* the commonest: nothing else to look at */
	uint64_t next = UINT64_MAX;
	uint32_t k;

	if (!pending) {
		pending = !can_status_taken();
	}
	for (k = 0U; !pending && (k < app_corners); k++) {
		const monitor_t *m = &app_mem.monitor[k];
		const bool wants = monitor_wants_classify(m);

		pending = m->status_now || (m->txq_count != 0U) || wants;
		next = earlier(next, earlier(m->next_status_us,
					     earlier(m->next_detail_us, m->next_diag_us)));
		next = earlier(next, earlier(stale_at_us(&m->speed, &m->speed_rx),
					     stale_at_us(&m->force, &m->force_rx)));
	}
	return (pending || (next < app_next_tick_us)) ? app_next_tick_us : next;
}

void squeal_app_skip_to_us(uint64_t t_us)
{
	if (t_us >= app_next_tick_us) {
		uint32_t k;

		for (k = 0U; k < app_corners; k++) {
			/* the one field a tick without work changes (the
			 * monitor's clock: monitor_step_slot) */
			if (t_us > app_mem.monitor[k].now_us) {
				app_mem.monitor[k].now_us = t_us;
			}
		}
		app_next_tick_us = t_us + TICK_US;
	}
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
	return &app_mem.monitor[0];
}

uint32_t squeal_app_corner_count(void)
{
	return app_corners;
}

const monitor_t *squeal_app_corner(uint32_t k)
{
	return (k < app_corners) ? &app_mem.monitor[k] : NULL;
}

int squeal_app_init_status(void)
{
	return app_init_rc;
}
