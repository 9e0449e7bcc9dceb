/* SPDX-License-Identifier: MIT */
/*
 * monitor: the brake-squeal monitor application, without any I/O.
 *
 *   frames in  -> monitor_on_frame()  (the input stage's verdict on the
 *                                      frame, input_rx_judge(), recorded:
 *                                      counters, faults, times; a used value
 *                                      converted and filtered)
 *   every 1 ms -> monitor_step()      condition (staleness) -> classify (each
 *                                      new input pair, with its uncertainty
 *                                      in the same pass) -> debounce and
 *                                      warning level -> encode (transmit
 *                                      scheduling)
 *   frames out <- monitor_pop_tx()    (E2E-protected, ready for hal_can_send)
 *
 * Time is passed in (microseconds, monotonic); nothing here reads a clock or
 * touches hardware, so the host-sim, the ECU and the tests run the same code
 * in real or virtual time. All state lives in monitor_t (no globals, no heap).
 *
 * States (SquealStatus.SquealState): the model's stable / bistable /
 * unstable / not sliding after debounce, or FAULT (15) at once when an input
 * is stale, implausible or its last frame failed E2E. A change between model
 * states needs `debounce_count` agreeing classifications in a row, or one
 * classification beyond the hysteresis band (|ln 2Q| > hyst_lnq for the Hopf
 * border, |rho - 1| > hyst_rho for the stable border, or any change into or
 * out of "not sliding" / FAULT).
 *
 * WarningLevel: 0 none (stable, not sliding, fault), 1 advisory (bistable,
 * basin ratio rho >= rho_warn: the basin reaches most of the way to the stick
 * line), 2 warning (bistable with a small basin, rho < rho_warn: a small
 * disturbance starts stick-slip), 3 critical (unstable).
 */
#ifndef MONITOR_H
#define MONITOR_H

#include <stdbool.h>
#include <stdint.h>

#include "calib.h"
#include "e2e_p01.h"
#include "hal.h"
#include "input_rx.h"
#include "model_adapter.h"
#include "squeal_msgs.h"

/* SquealState on the bus: the model's states and FAULT, the model's INVALID
 * (squeal_state.h defines the values once) */
#define MONITOR_STATE_FAULT MSG_SQUEAL_STATE_FAULT

/* Why an input is not usable right now (bits of input_t.faults). */
#define INPUT_FAULT_STALE       (1U << 0) /* no usable frame for stale_cycles periods */
#define INPUT_FAULT_E2E         (1U << 1) /* its last frame failed the E2E check      */
#define INPUT_FAULT_IMPLAUSIBLE (1U << 2) /* its last value was out of range / rate   */
#define INPUT_FAULT_NEVER_SEEN  (1U << 3) /* nothing usable since start               */

/* Counters of one input (cumulative, saturating at UINT32_MAX). */
typedef struct {
	uint32_t frames;          /* frames with this input's identifier          */
	uint32_t used;            /* accepted and used                            */
	uint32_t bad_dlc;         /* wrong length                                 */
	uint32_t e2e_wrong_crc;
	uint32_t e2e_wrong_sequence;
	uint32_t e2e_repeated;
	uint32_t e2e_lost;        /* frames reported lost by OKSOMELOST (sum)     */
	uint32_t implausible;     /* not available / qualifier / range / rate     */
	uint32_t stale_events;    /* transitions into stale                       */
	/* frames per verdict of the input stage, by input_rx_reason_t
	 * (verdict[INPUT_RX_OK] == used): what replay and decode report */
	uint32_t verdict[INPUT_RX_REASON_COUNT];
} input_counters_t;

/* One conditioned input (speed or force). */
typedef struct {
	input_rx_state_t rx;       /* the input stage's E2E and previous value    */
	uint32_t faults;           /* INPUT_FAULT_*                               */
	int32_t value;             /* conditioned: v0 [um/s] or force [mN]        */
	int64_t filtered_q8;       /* low-pass state, value x 256 (needs 64 bit) */
	uint64_t last_used_us;     /* time of the last used frame                 */
	uint64_t last_seen_us;     /* last frame with a good CRC, even repeated   */
	bool fresh;                /* a new value since the last classification   */
	input_counters_t count;
} input_t;

typedef struct {
	uint32_t unknown_id;       /* frames with an identifier we do not use     */
	uint32_t error_frames;     /* bus error frames delivered by the HAL       */
	uint32_t rtr_or_ext;       /* remote frames, or the other frame format, on our IDs */
	uint32_t classifications;
	uint32_t state_changes;
	uint32_t tx_frames;
	uint32_t tx_overflow;      /* frames dropped: TX queue full               */
	uint32_t tx_errors;        /* hal_can_send other errors (bus-off, down)   */
	uint32_t bus_off_events;
	uint32_t rx_overruns;      /* from the HAL                                */
	uint32_t model_invalid;    /* classifications the model refused           */
} monitor_counters_t;

#define MONITOR_TX_QUEUE_LEN 8U

/*
 * The platform's bring-up self-test of this start, reported on SquealDiag
 * page 4 in the DBC's raw units (HseFreq_MHz in 0.1 MHz, 255 not measured;
 * ResetCause 0..6; BorLevel 0..3, 7 none; LoopbackCan1/2 0 pass, 1 fail,
 * 2 unavailable, 3 no such bus; StackHighWater_B, 16383 unknown). failed
 * sets Fault_SelfTest.
 */
typedef struct {
	uint8_t hse_freq_100khz;
	uint8_t reset_cause;
	uint8_t bor_level;
	uint8_t loopback[2];
	uint16_t stack_high_water_b;
	bool failed;
} monitor_selftest_t;

/*
 * One corner (FL, FR, RL, RR) is one monitor_t: its brake, its speed and
 * force inputs, its classification and its own output messages. The app
 * owns 1..4 of them (calib_corner_count()) and staggers their
 * classifications over the 1 ms steps (monitor_step_slot()).
 */
typedef struct {
	/* the calibration in use, read-only: the caller's (it must outlive the
	 * monitor; the app keeps one for all corners), or the factory
	 * defaults when it was refused */
	const calib_t *cal;
	uint8_t corner_index;        /* k in cal.corners (0 for the legacy form) */
	calib_corner_t corner;       /* this corner's brake and output IDs       */
	input_rx_cfg_t speed_rx;     /* the inputs as configured for this corner */
	input_rx_cfg_t force_rx;
	squeal_params_t params;
	squeal_param_sd_t sd;        /* the corner's deviations, model formats */
	bool calib_invalid;          /* defaults in use because the stored block was bad */
	uint32_t platform_faults;    /* HAL_FAULT_* from the HAL                 */
	bool bus_off_seen;           /* latched until reset                      */

	input_t speed;
	input_t force;

	/* classification */
	model_eval_t eval;           /* last classification                     */
	bool have_eval;
	uint8_t state;               /* reported SquealState (0..3, 15)         */
	uint8_t warning;             /* reported WarningLevel                   */
	uint8_t candidate;           /* state the debounce is counting towards  */
	uint8_t candidate_count;
	/* uncertainty: off when the corner's deviations are all 0 */
	bool sigma_on;
	bool uncertain;              /* within k sigma of the border to the more
				      * severe neighbouring class              */
	int32_t margin_q16;          /* BorderMargin of `state` [sigma x 2^16],
				      * MODEL_MARGIN_NONE: none to report      */

	/* transmit */
	e2e_p01_tx_t tx_status;
	e2e_p01_tx_t tx_detail;
	e2e_p01_tx_t tx_detail2;
	e2e_p01_tx_t tx_diag;
	uint64_t next_status_us;
	uint64_t next_detail_us;
	uint64_t next_diag_us;
	bool status_now;             /* state or level changed: send at once   */
	uint8_t diag_page;
	monitor_selftest_t selftest;  /* page 4; "not measured" until set     */
	hal_can_frame_t txq[MONITOR_TX_QUEUE_LEN];
	uint8_t txq_head;
	uint8_t txq_count;

	/* time */
	bool started;
	uint64_t start_us;
	uint64_t now_us;
	uint32_t worst_task_us;      /* reported by the scheduler              */

	monitor_counters_t count;
} monitor_t;

/*
 * Start with a calibration (must validate; otherwise the defaults are used
 * and calib_invalid is set). The monitor keeps a pointer to cal: it must
 * stay valid and unchanged while the monitor runs. calib_invalid also forces the CalibInvalid fault
 * bit, for a caller that fell back to defaults itself.
 * Returns SQ_OK, or SQ_EINVAL when cal was rejected (defaults in use).
 */
int monitor_init(monitor_t *me, const calib_t *cal, bool calib_invalid,
		 uint32_t platform_faults, uint64_t now_us);

/* The same for corner k of cal (0 .. calib_corner_count(cal) - 1). A
 * calibration that does not validate, or a k beyond its corners, gives the
 * defaults' corner 0 and calib_invalid, as above. */
int monitor_init_corner(monitor_t *me, const calib_t *cal, uint32_t k,
			bool calib_invalid, uint32_t platform_faults, uint64_t now_us);

/* One received frame (any identifier; error frames too). */
void monitor_on_frame(monitor_t *me, const hal_can_frame_t *frame);

/* The 1 ms task: run everything due at now_us. */
void monitor_step(monitor_t *me, uint64_t now_us);

/* The same, but a new input pair is classified only when may_classify is
 * true (the app gives one corner per step that slot); otherwise it waits,
 * still fresh, for the corner's next slot. */
void monitor_step_slot(monitor_t *me, uint64_t now_us, bool may_classify);

/* True when a new input pair waits for classification (the app's choice
 * of the corner that gets the step's classification slot). */
bool monitor_wants_classify(const monitor_t *me);

/* Controller status from the HAL (bus-off, overruns), read every step. */
void monitor_on_can_status(monitor_t *me, const hal_can_status_t *status);

/* The scheduler's measured task time (us); the worst is reported. */
void monitor_report_task_time(monitor_t *me, uint32_t task_us);

/*
 * Transmit queue, drained by the scheduler:
 *   while (monitor_peek_tx(me, &f) == SQ_OK) {
 *           rc = hal_can_send(&f);
 *           if (rc == SQ_ENOBUFS) break;          (stays queued, retried)
 *           monitor_tx_done(me, rc);              (sent, or counted + dropped)
 *   }
 * A frame that cannot even be queued (our queue full) is counted as a TX
 * overflow and dropped: every message is periodic, the next one follows.
 */
int monitor_peek_tx(const monitor_t *me, hal_can_frame_t *frame);
void monitor_tx_done(monitor_t *me, int hal_rc);

/* The platform's self-test figures (after monitor_init). SQ_OK, or
 * SQ_ERANGE (a value outside its DBC range: nothing changed). */
int monitor_set_selftest(monitor_t *me, const monitor_selftest_t *st);

/* SquealDiag's fault bits (MSG_FAULT_*) as they are now. */
uint16_t monitor_fault_bits(const monitor_t *me);

#endif /* MONITOR_H */
