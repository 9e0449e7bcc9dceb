/* SPDX-License-Identifier: MIT */
/*
 * squeal-sim replay LOG|- : the unchanged firmware (squeal_app_init/poll)
 * fed from a candump -L log in virtual time (hal_vbus), offline and
 * deterministic.
 *
 * Time: the earliest frame's timestamp (microseconds; a 9-digit log is
 * truncated to us, the firmware's resolution) starts the firmware. Before
 * each frame, the 1 ms ticks up to the frame's time are run (set the virtual
 * clock, poll, take what the ECU sent); then the frame is offered to the CAN
 * controller and, when its filters take it, the clock is set to the frame's
 * time and the firmware polls once more. A tick that cannot change anything
 * is skipped: the firmware says when its next work is due
 * (squeal_app_next_event_us(): a periodic message, a staleness timeout, the
 * next tick after a frame), and the clock goes straight to that tick. Before
 * a frame the controller takes, the firmware's clock and tick are put where
 * running the last skipped tick leaves them (squeal_app_skip_to_us), so
 * they are where 1 ms stepping leaves them: the output
 * is the same bytes as with every tick run (--step-every-ms, for
 * comparison). The replay ends with the first tick after the last frame (the
 * one that takes that frame in), so the final state is the one the last
 * inputs gave; --tail-ms MS runs on for MS more (default 0). Nothing depends
 * on the wall clock, so the same log gives the same bytes.
 *
 * Order: frames are held in a reorder window of REORDER_WINDOW_US (5 s of
 * log time) and at most REORDER_FRAMES (32768) frames, and given in time
 * order (file order among equal times). So
 *   - a frame up to 1 s earlier than the latest one (interleaved
 *     interfaces, a logger's jitter) is put in its place;
 *   - a block written out of order (time jumps back by more than 1 s and
 *     returns to where it was: a forward jump of more than
 *     DETOUR_RETURN_STEP_US, 100 ms, that lands no more than 1 s before the
 *     time it left) is put back in its place;
 *   - a logger that restarted (time jumps back by more than 1 s and goes on
 *     from there: beyond the window, past the time it left without such a
 *     jump, or still running when the log or the window ends) starts a new
 *     segment: the log's time from there on is re-based onto the latest
 *     time seen, so the frames that follow keep their spacing.
 * Frames put back in order and out-of-order blocks are counted
 * (`reordered`), segments are counted and reported with their line. A frame
 * the window could not place (the window was full) is reported, counted
 * (time_backwards) and given at the current time: time never goes back.
 * A gap up to --max-gap seconds (default 3600) is simulated: time passes,
 * inputs go stale, the ECU goes on sending. A longer gap is reported and
 * skipped: the clock jumps, without the ticks in between (a mix of relative
 * and absolute timestamps would otherwise tick for decades).
 *
 * Buses: the inputs come from one interface of the log: --bus NAME, else
 * the calibration's input_iface. Its frames are the firmware's input_bus,
 * every other interface's the other bus (so a two-bus log replays with the
 * calibration's input_bus/output_bus); frames of a bus the firmware uses
 * neither for input nor output are counted (other_bus), not offered. With
 * neither, every frame is on bus 0 (a single-bus ECU), but when the input
 * map's identifiers arrive on more than one interface, the first interface
 * on which one arrived is the input interface: the replay says so once and
 * counts the input-identifier frames of the other interfaces it ignores
 * (other_iface_inputs).
 *
 * Output: every frame the ECU sends, as candump -L lines on stdout, named
 * after the bus it was sent on: the input interface (or the log's first
 * interface) for the input bus, the first other interface of the log for
 * the other ("bus1" until one is seen); --iface-out NAME names every output
 * line instead. The summary goes to stderr: per corner, each input by its
 * position, quantity and DBC signal (`FL speed WHEEL_SPEEDS.WHEEL_SPEED_FL`;
 * the [input] section's name without a signal; DiscSpeed and PadForce for
 * the legacy calibration), frames used and rejected by the input stage's
 * reasons, the share of time in each state and the time in FAULT by reason.
 * Memory is constant: the log is streamed line by line through the window.
 */
#include <errno.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "calib.h"
#include "calib_text.h"
#include "cli_args.h"
#include "input_rx.h"
#include "candump_hal.h"
#include "candump_log.h"
#include "hal_vbus.h"
#include "json_writer.h"
#include "monitor.h"
#include "replay_summary.h"
#include "sim_commands.h"
#include "squeal_app.h"
#include "squeal_msgs.h"

#define TICK_US 1000U
#define SEGMENT_BACK_US 1000000U /* a jump back beyond this: a block or a restart */
#define REORDER_WINDOW_US 5000000U /* log time a frame may arrive late by */
#define REORDER_FRAMES 32768U      /* frames held at most (5 s at 6500 frames/s) */
#define DETOUR_RETURN_STEP_US 100000U /* a forward jump that ends a late block */
#define IFACES_MAX 16U             /* interfaces told apart (more share the last) */
/* Frames given before one poll takes them in (skipping): well below the
 * firmware's RX_BUDGET, so one poll takes them all, as a poll per frame does */
#define RX_DEFER_MAX 16U
/* Re-based times saturate here (2^62 us, 146,000 years): a hostile log of
 * endless restarts cannot overflow them; frames beyond are late. */
#define TIME_MAX_US (1ULL << 62)
#define SEGMENT_POINTS_MAX 64U /* rebase points kept for the JSON (memory stays constant) */
#define N_STATES MSG_SQUEAL_STATE_SLOTS /* stable, bistable, unstable, not sliding, fault */
#define N_LEVELS 4U
#define REPLAY_LOGS_MAX 4096U /* LOG words of one --each run */
#define REPLAY_ERROR_MAX 4352U /* a log's failure: a path (4096) and its message */

static const char *const level_names[N_LEVELS] = {
	"none", "advisory", "warning", "critical"
};

typedef struct {
	const char *log_name;
	const char *calib_path;
	const char *iface_out;
	uint64_t tail_us;
	uint64_t max_gap_us;
	const char *input_iface;  /* --bus NAME, else the calibration's, else NULL */
	bool input_iface_from_bus; /* chosen by --bus */
	bool rss;
	const char *summary_json; /* --summary-json FILE|- (replay_summary.h) */
	bool no_output;           /* --no-output: no frame lines, only counts */
	bool quiet;               /* --quiet: no line per message, the summary only */
	bool step_every_ms;       /* --step-every-ms: run every tick, skip none */
	bool each;                /* --each: every LOG on its own, one document each */
	const char *logs[REPLAY_LOGS_MAX]; /* the LOG words */
	size_t n_logs;
} replay_args_t;

/* Where a new segment began: the log line, how far the log's time went
 * back and the virtual time the rest of the log was re-based onto. */
typedef struct {
	uint64_t line_no;
	uint64_t back_us;
	uint64_t at_us;
} segment_point_t;

/* A frame waiting in the reorder window, as the HAL frame it will be
 * (classic, RTR, error, FD); a frame this build's HAL cannot hold (XL, FD
 * beyond HAL_CAN_MAX_DLEN) keeps only its kind: it is counted, not given. */
typedef struct {
	uint64_t t_us;       /* log time, re-based                            */
	uint64_t seq;        /* read order: ties keep the file's order        */
	uint64_t line_no;
	uint8_t iface;       /* index in replay_t.ifaces                      */
	uint8_t kind;        /* candump_kind_t                                */
	bool unsupported;    /* not a HAL frame here (candump_to_hal)         */
	bool detour;         /* read after a jump back not yet decided        */
	hal_can_frame_t frame;
} held_t;

/* Per corner: reasons by the input stage's own names, time per state and
 * the time in FAULT with each input fault (INPUT_FAULT_* bit b). */
#define N_FAULT_BITS 4U
static const char *const fault_bit_names[N_FAULT_BITS] = {
	"stale", "e2e", "implausible", "never_seen"
};
typedef struct {
	uint64_t state_us[N_STATES];
	uint64_t fault_us[2][N_FAULT_BITS];
	uint64_t fault_other_us;   /* FAULT without an input fault (calibration, platform) */
} corner_stats_t;

typedef struct {
	/* lines */
	uint64_t lines;
	uint64_t frames;
	uint64_t comments;
	uint64_t blanks;
	uint64_t dropcount_lines;
	uint64_t dropped;
	uint64_t malformed;
	/* frames by format: classic data, remote and error frames; CAN FD */
	uint64_t classic_frames;
	uint64_t fd_frames;
	/* frames not given to the firmware or refused by its controller */
	uint64_t unsupported_fd;
	uint64_t unsupported_xl;
	uint64_t filtered_id;
	uint64_t filtered_rtr;
	uint64_t filtered_ext;
	uint64_t rx_overflow;
	uint64_t other_bus;
	uint64_t pushed;
	/* time */
	bool started;
	uint64_t t0_us;
	uint64_t now_us;           /* the virtual clock, counted up to (set_time) */
	uint64_t frame_us;         /* time of the latest frame given             */
	uint64_t next_tick_us;     /* the next tick not yet run or skipped       */
	bool skip;                 /* skip the ticks that change nothing         */
	bool idle_pending;         /* idle_tick_us was skipped, nothing run since */
	uint32_t rx_deferred;      /* frames given, not yet polled (skipping)    */
	uint64_t idle_tick_us;     /* the last tick skipped                      */
	/* standard identifiers the controller's filters refused, per bus (the
	 * firmware sets its filters once, at init) */
	bool std_filtered[HAL_CAN_BUSES][CANDUMP_SFF_MAX + 1U];
	uint64_t backwards;
	uint64_t segments;         /* new segments after a jump back > 1 s  */
	uint64_t rebase_us;        /* added to the log's time (segments)    */
	segment_point_t segment_at[SEGMENT_POINTS_MAX]; /* the first ones */
	uint64_t gaps;
	uint64_t state_us[N_STATES];
	uint8_t state;
	uint8_t warning;
	uint64_t into_level[N_LEVELS];
	uint64_t transitions[N_STATES][N_STATES];
	/* the reorder window: frames read in time order wait in a FIFO, the
	 * others in a binary min-heap on (t_us, seq); the two are merged */
	held_t *fifo;              /* REORDER_FRAMES each (window_fifo, window_heap) */
	uint32_t fifo_head;
	uint32_t fifo_n;
	held_t *held;
	uint32_t n_held;
	uint64_t seq;
	bool have_max;
	uint64_t max_seen_us;      /* latest time read (not counting a detour)  */
	uint64_t prev_t_us;        /* time of the frame read before             */
	bool detour;               /* a jump back > 1 s, not yet decided        */
	uint64_t jump_from_us;     /* the time it left                          */
	uint64_t detour_first_us;  /* the first frame after the jump            */
	uint64_t detour_line;
	uint64_t detour_frames;
	uint64_t reordered;        /* frames given earlier than read            */
	uint64_t reordered_blocks; /* blocks written out of order, put back     */
	bool init_failed;          /* firmware_init refused the given calibration */
	/* interfaces of the log, by first appearance */
	char ifaces[IFACES_MAX][CANDUMP_IFACE_MAX + 1U];
	uint32_t n_ifaces;
	bool iface_has_inputs[IFACES_MAX];
	bool auto_input;           /* an input interface was taken (no choice given) */
	uint8_t auto_iface;
	bool multi_reported;
	uint64_t other_iface_inputs; /* input-identifier frames of other interfaces */
	/* names of the inputs (calib_names_t), per corner statistics */
	calib_names_t names;
	bool map_form;             /* [input]/[corner] sections: names apply */
	corner_stats_t cs[CALIB_MAX_CORNERS];
	/* the firmware's corners, taken at start (their number is fixed by
	 * init): read on every frame and tick */
	uint32_t n_corners;
	const monitor_t *corner[CALIB_MAX_CORNERS];
	/* output: the name of each bus in the output log */
	char iface[HAL_CAN_BUSES][CANDUMP_IFACE_MAX + 1U];
	bool bus1_named;
	uint64_t out_frames;
	uint64_t out_by_msg[MSG_COUNT + 1U];
	bool out_error;
	/* the output lines, written to stdout a block at a time (not a stdio
	 * call per frame) */
	char out_buf[1U << 16];
	size_t out_len;
	bool no_output;
	replay_summary_t *summary; /* NULL without --summary-json */
	/* what the document says of a failure and of the first bad line */
	char error[REPLAY_ERROR_MAX];
	uint64_t first_bad_line;   /* 0: none */
	size_t first_bad_column;   /* 0: the whole line */
	candump_err_t first_bad_err;
} replay_t;

static int replay_parse(int argc, char **argv, replay_args_t *a)
{
	const cli_opt_t opts[] = {
		CLI_OPT_TEXT("calib", &a->calib_path, NULL, "FILE",
			     "calibration text file (docs/calib-example.txt)"),
		CLI_OPT_NAME("bus", &a->input_iface, &a->input_iface_from_bus, CANDUMP_IFACE_MAX, "NAME",
			     "the inputs come from the log's interface NAME (the\n"
			     "calibration's input_bus), every other interface is\n"
			     "the other bus; default: the calibration's input_iface,\n"
			     "else all frames on bus 0 with the inputs from the first\n"
			     "interface that carries one (said so when several do)"),
		CLI_OPT_NAME("iface-out", &a->iface_out, NULL, CANDUMP_IFACE_MAX, "NAME",
			     "interface name of the output lines (default: the\n"
			     "output bus's: the input interface or the log's first\n"
			     "for the input bus, another of its interfaces for the other)"),
		CLI_OPT_U64("tail-ms", &a->tail_us, NULL, 0.0, 86400000.0, 1000U, "MS",
			    "run on after the last frame (default 0: the replay\n"
			    "ends with the tick that takes the last frame in)"),
		CLI_OPT_U64("max-gap", &a->max_gap_us, NULL, 0.0, 31536000.0, 1000000U, "S",
			    "a gap between frames up to S seconds is simulated\n"
			    "(time passes, inputs go stale); a longer one is\n"
			    "skipped (default 3600)"),
		CLI_OPT_FLAG("rss", 0, &a->rss, "add the peak resident memory (VmHWM) to the summary"),
		CLI_OPT_TEXT("summary-json", &a->summary_json, NULL, "FILE|-",
			     "also write the summary as one JSON document, with\n"
			     "the episodes (time spans in one state per corner) and\n"
			     "the time per (v0, force) cell; - for stdout (needs\n"
			     "--no-output or --quiet)"),
		CLI_OPT_FLAG("no-output", 0, &a->no_output,
			     "do not write the ECU's frames (only count them)"),
		CLI_OPT_FLAG("quiet", 0, &a->quiet,
			     "no line per message: neither the ECU's frames nor the\n"
			     "notes on single log lines (each still counted); only\n"
			     "the summary"),
		CLI_OPT_FLAG("step-every-ms", 0, &a->step_every_ms,
			     "run every 1 ms tick, also those that change nothing\n"
			     "(the same output, slower: for comparison)"),
		CLI_OPT_FLAG("each", 0, &a->each,
			     "replay every LOG on its own, from a reset ECU, as one\n"
			     "run per log would (many short logs in one process);\n"
			     "the summaries go to --summary-json one document per\n"
			     "line, each with the log's exit_status and error;\n"
			     "needs --summary-json and --no-output"),
	};
	const cli_spec_t spec = {
		.cmd = "replay",
		CLI_SPEC_OPTS(opts),
		.synopsis = "squeal-sim replay LOG|- [--calib FILE] [--bus NAME]\n"
			    "         [--iface-out NAME] [--tail-ms MS] [--max-gap S] [--rss]\n"
			    "         [--summary-json FILE|-] [--no-output] [--quiet]\n"
			    "         [--step-every-ms]\n"
			    "       squeal-sim replay --each LOG... --summary-json FILE|- --no-output\n"
			    "         [the options above]",
		.description = "Feeds a candump -L log (a file, or - for stdin) through the firmware in\n"
			       "virtual time taken from the log's timestamps, offline. Writes every frame\n"
			       "the ECU sends as a candump -L log on stdout, and a summary on stderr:\n"
			       "frames read, used, rejected by reason, time in each state, warnings\n"
			       "raised, state changes. Malformed lines are reported as LOG:LINE: message\n"
			       "and skipped. The same log gives the same output, byte for byte.\n\n"
			       "Frames out of time order are put back in order within a window of 5 s of\n"
			       "log time (32768 frames); a jump back of more than 1 s that does not return\n"
			       "to where it left is a logger restart: a new segment, re-based.",
		.closing = "CAN FD frames (##) reach the firmware as FD frames; CAN XL frames are\ncounted as unsupported.\n"
			   "Exit status: 0 done (also with malformed lines), 1 input/calibration\n"
			   "error or no CAN frame in the log (with --each: in any of the logs),\n"
			   "2 bad usage.",
		.min_pos = 1U,
		.max_pos = REPLAY_LOGS_MAX,
	};
	cli_result_t r;

	a->tail_us = 0U;
	a->max_gap_us = 3600ULL * 1000000ULL;
	r = cli_parse(&spec, argc, argv, a->logs, &a->n_logs);
	if (r != CLI_OK) {
		return (int)r;
	}
	a->log_name = a->logs[0];
	if ((a->n_logs > 1U) && !a->each) {
		return (int)cli_usage_error(&spec, "one LOG (several with --each, each replayed on its own)");
	}
	a->no_output = a->no_output || a->quiet;
	if (a->each && ((a->summary_json == NULL) || !a->no_output)) {
		return (int)cli_usage_error(&spec, "--each needs --summary-json FILE|- and --no-output");
	}
	if ((a->summary_json != NULL) && (strcmp(a->summary_json, "-") == 0) && !a->no_output) {
		return (int)cli_usage_error(&spec, "--summary-json - shares stdout with the frames: add --no-output");
	}
	return CLI_OK;
}

/* A note about one log line on stderr (a restart, a gap, a late frame),
 * unless --quiet: the summary counts each. */
static void note(const replay_args_t *a, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

static void note(const replay_args_t *a, const char *fmt, ...)
{
	va_list ap;

	if (a->quiet) {
		return;
	}
	va_start(ap, fmt);
	vfprintf(stderr, fmt, ap);
	va_end(ap);
}

/* ---- output ------------------------------------------------------------------ */

static void out_flush(replay_t *r)
{
	if ((r->out_len > 0U) && (fwrite(r->out_buf, 1U, r->out_len, stdout) != r->out_len)) {
		r->out_error = true;
	}
	r->out_len = 0U;
}

static void emit(replay_t *r, uint8_t bus, const hal_can_frame_t *hf)
{
	candump_frame_t f;
	const msg_desc_t *d;
	int n;

	if (r->summary != NULL) {
		replay_summary_on_frame(r->summary, hf);
	}
	r->out_frames++;
	d = ((hf->flags & HAL_CAN_FLAG_EXT) != 0U) ? NULL : msg_desc_find((uint16_t)hf->id);
	r->out_by_msg[(d != NULL) ? (size_t)(d - msg_table) : MSG_COUNT]++;
	if (r->no_output) {
		return;
	}
	if (sizeof(r->out_buf) - r->out_len < CANDUMP_FORMAT_MAX + 2U) {
		out_flush(r);
	}
	candump_from_hal(hf, hf->timestamp_us * 1000U, r->iface[bus], &f);
	n = candump_format_frame(&f, true, r->out_buf + r->out_len, sizeof(r->out_buf) - r->out_len);
	if (n < 0) {
		r->out_error = true;
		return;
	}
	r->out_len += (size_t)n;
}

/* After each poll: take what the ECU sent, follow state and warning. */
static void after_poll(replay_t *r)
{
	const monitor_t *m = squeal_app_monitor();
	hal_can_frame_t f;
	unsigned from;
	unsigned to;
	uint8_t bus;

	for (bus = 0U; bus < HAL_CAN_BUSES; bus++) {
		while (hal_vbus_tx_pop(bus, &f) == SQ_OK) {
			emit(r, bus, &f);
		}
	}
	from = msg_squeal_state_slot(r->state);
	to = msg_squeal_state_slot(m->state);
	if (from != to) {
		r->transitions[from][to]++;
	}
	r->state = m->state;
	if ((m->warning != r->warning) && (m->warning < N_LEVELS)) {
		r->into_level[m->warning]++;
	}
	r->warning = m->warning;
}

/* The time from now to t_us counts, per corner, for the state that held and,
 * in FAULT, for each input fault that caused it. */
static void account_corners(replay_t *r, uint64_t dt)
{
	uint32_t k;

	for (k = 0U; k < r->n_corners; k++) {
		const monitor_t *c = r->corner[k];
		corner_stats_t *cs = &r->cs[k];
		const uint32_t slot = msg_squeal_state_slot(c->state);
		const uint32_t faults[2] = { c->speed.faults, c->force.faults };
		unsigned j;
		unsigned b;

		cs->state_us[slot] += dt;
		if (slot != MSG_SQUEAL_STATE_SLOT_FAULT) {
			continue;
		}
		if ((faults[0] | faults[1]) == 0U) {
			cs->fault_other_us += dt;
		}
		for (j = 0U; j < 2U; j++) {
			for (b = 0U; b < N_FAULT_BITS; b++) {
				if ((faults[j] & (1U << b)) != 0U) {
					cs->fault_us[j][b] += dt;
				}
			}
		}
	}
}

/* Move the virtual clock to t_us (never back); the time in between counts
 * for the state that held during it. */
static void set_time(replay_t *r, uint64_t t_us)
{
	if (t_us > r->now_us) {
		r->state_us[msg_squeal_state_slot(r->state)] += t_us - r->now_us;
		account_corners(r, t_us - r->now_us);
		r->now_us = t_us;
		hal_vbus_set_time_us(t_us);
	}
}

/* One 1 ms tick at t_us. */
static void tick(replay_t *r, uint64_t t_us)
{
	set_time(r, t_us);
	(void)squeal_app_poll();
	after_poll(r);
	r->idle_pending = false;
	r->rx_deferred = 0U;
}

/* The first tick of the grid from `from` at or after ev_us; UINT64_MAX when
 * it is beyond until_us. */
static uint64_t first_tick_at(uint64_t from, uint64_t ev_us, uint64_t until_us)
{
	uint64_t steps;

	if (ev_us <= from) {
		return from;
	}
	steps = ((ev_us - from) / TICK_US) + ((((ev_us - from) % TICK_US) != 0U) ? 1U : 0U);
	return (steps > (until_us - from) / TICK_US) ? UINT64_MAX : from + (steps * TICK_US);
}

/* The 1 ms ticks up to and including t_us: each one, or (skipping) only
 * those at or after the firmware's next event; the last idle tick skipped is
 * kept for run_idle_tick(). The clock stays at the last tick run. */
static void run_until(replay_t *r, uint64_t t_us)
{
	while (r->next_tick_us <= t_us) {
		uint64_t at = r->next_tick_us;

		if (r->skip && (r->rx_deferred == 0U)) {
			at = first_tick_at(at, squeal_app_next_event_us(), t_us);
			if (at == UINT64_MAX) {
				r->idle_tick_us = r->next_tick_us +
					(((t_us - r->next_tick_us) / TICK_US) * TICK_US);
				r->idle_pending = true;
				r->next_tick_us = r->idle_tick_us + TICK_US;
				return;
			}
		}
		tick(r, at);
		r->next_tick_us = at + TICK_US;
	}
}

/* Before the firmware sees anything again (a frame, a gap, the end): its
 * clock and tick go where running the last tick skipped leaves them
 * (squeal_app_skip_to_us: that tick has nothing to do, sends nothing and
 * changes no state). */
static void run_idle_tick(replay_t *r)
{
	if (r->idle_pending) {
		set_time(r, r->idle_tick_us);
		squeal_app_skip_to_us(r->idle_tick_us);
		r->idle_pending = false;
	}
}

/*
 * Skipping, a frame the controller took waits there for the next tick's
 * poll, which takes it in before it ticks: a poll at the frame's own time
 * would only take it in (the ticks up to that time have run or are skipped,
 * the next is later), sends nothing and changes no state, and the monitors
 * stamp a frame with their own clock at the latest, which moves only when
 * they tick, so the frames get the times a poll per frame gives them. The
 * next tick is due (run_until), as after such a poll. Not while a corner is
 * in FAULT: a frame taken in changes its inputs' faults at once, and the
 * time in FAULT is counted by those (account_corners). Before a jump of the
 * clock (a gap not simulated) they are taken in at their time, as stepping
 * does.
 */
static bool fault_time_by_input(const replay_t *r)
{
	uint32_t k;

	for (k = 0U; k < r->n_corners; k++) {
		if (msg_squeal_state_slot(r->corner[k]->state) == MSG_SQUEAL_STATE_SLOT_FAULT) {
			return true;
		}
	}
	return false;
}

static void take_deferred(replay_t *r)
{
	if (r->rx_deferred > 0U) {
		(void)squeal_app_poll();
		after_poll(r);
		r->rx_deferred = 0U;
	}
}

/* The calibration's input bus, and the bus of every other interface. */
static uint8_t input_bus(void)
{
	return squeal_app_monitor()->cal->input_bus;
}

static uint8_t other_bus_of(uint8_t in_bus)
{
	return (in_bus == 0U) ? 1U : 0U;
}

static void start(replay_t *r, const held_t *h, const replay_args_t *a)
{
	const monitor_t *m;
	const char *first = r->ifaces[h->iface];

	r->started = true;
	r->t0_us = h->t_us;
	r->now_us = r->t0_us;
	r->frame_us = r->t0_us;
	r->next_tick_us = r->t0_us;
	hal_vbus_set_time_us(r->t0_us);
	if ((squeal_app_init() != SQ_OK) && (a->calib_path != NULL)) {
		/* the loader accepted the file, the firmware did not: never run
		 * a given calibration's log on the defaults */
		r->init_failed = true;
		return;
	}
	m = squeal_app_monitor();
	for (r->n_corners = 0U; (r->n_corners < squeal_app_corner_count()) &&
	     (r->n_corners < CALIB_MAX_CORNERS); r->n_corners++) {
		r->corner[r->n_corners] = squeal_app_corner(r->n_corners);
	}
	if (a->iface_out != NULL) {
		(void)snprintf(r->iface[0], sizeof(r->iface[0]), "%s", a->iface_out);
		(void)snprintf(r->iface[1], sizeof(r->iface[1]), "%s", a->iface_out);
		r->bus1_named = true;
	} else if (a->input_iface != NULL) {
		const uint8_t in = input_bus();

		uint32_t i;

		(void)snprintf(r->iface[in], sizeof(r->iface[in]), "%s", a->input_iface);
		(void)snprintf(r->iface[other_bus_of(in)], sizeof(r->iface[0]), "%s", "bus1");
		/* the window has read ahead: the first other interface of the log */
		for (i = 0U; (i < r->n_ifaces) && !r->bus1_named; i++) {
			if (strcmp(r->ifaces[i], a->input_iface) != 0) {
				memcpy(r->iface[other_bus_of(in)], r->ifaces[i], sizeof(r->iface[0]));
				r->bus1_named = true;
			}
		}
	} else {
		(void)snprintf(r->iface[0], sizeof(r->iface[0]), "%s", first);
		(void)snprintf(r->iface[1], sizeof(r->iface[1]), "%s", "bus1");
	}
	if (r->summary != NULL) {
		uint32_t k;

		/* each configured corner by its position (FL, FR, RL, RR) with
		 * its own output identifiers from the calibration */
		for (k = 0U; k < squeal_app_corner_count(); k++) {
			const monitor_t *c = squeal_app_corner(k);
			const rs_corner_ids_t ids = { c->corner.status_id, c->corner.detail_id,
						      c->corner.detail2_id };

			replay_summary_set_corner(r->summary, c->corner.pos, &ids);
		}
	}
	r->state = m->state;
	r->warning = m->warning;
}

static bool carries_id(const input_rx_cfg_t *cfg, const hal_can_frame_t *f)
{
	return (cfg->desc.id == f->id) &&
	       (((cfg->desc.flags & CALIB_IN_EXTENDED) != 0U) ==
		((f->flags & HAL_CAN_FLAG_EXT) != 0U)) &&
	       ((f->flags & (HAL_CAN_FLAG_ERR | HAL_CAN_FLAG_RTR)) == 0U);
}

/* Does the frame have the identifier of an input of any corner? */
static bool is_input_frame(const replay_t *r, const hal_can_frame_t *f)
{
	uint32_t k;

	for (k = 0U; k < r->n_corners; k++) {
		const monitor_t *c = r->corner[k];

		if (carries_id(&c->speed_rx, f) || carries_id(&c->force_rx, f)) {
			return true;
		}
	}
	return false;
}

/* The firmware bus of a log frame (see the top of this file); false: the
 * frame is ignored (an input identifier of an interface that is not the
 * input interface, counted). */
static bool bus_of_frame(replay_t *r, const held_t *h, const hal_can_frame_t *hf,
			 const replay_args_t *a, uint8_t *bus)
{
	const char *name = r->ifaces[h->iface];

	if (a->input_iface != NULL) {
		const uint8_t in = input_bus();

		if (strcmp(name, a->input_iface) == 0) {
			*bus = in;
			return true;
		}
		*bus = other_bus_of(in);
		if (!r->bus1_named) {
			memcpy(r->iface[*bus], name, sizeof(r->iface[0]));
			r->bus1_named = true;
		}
		return true;
	}
	*bus = 0U;
	if (!is_input_frame(r, hf)) {
		return true;
	}
	if (!r->iface_has_inputs[h->iface]) {
		r->iface_has_inputs[h->iface] = true;
		if (!r->auto_input) {
			r->auto_input = true;
			r->auto_iface = h->iface;
		} else if (!r->multi_reported) {
			r->multi_reported = true;
			note(a, "%s:%llu: the input identifiers arrive on %s and %s (0x%X here): the inputs are taken from %s (the first that carried one), the other's are ignored; --bus NAME or input_iface chooses\n",
				a->log_name, (unsigned long long)h->line_no, r->ifaces[r->auto_iface],
				name, (unsigned)hf->id, r->ifaces[r->auto_iface]);
		}
	}
	if (h->iface != r->auto_iface) {
		r->other_iface_inputs++;
		return false;
	}
	return true;
}

static void give_frame(replay_t *r, const held_t *h, const replay_args_t *a)
{
	const calib_t *cal = squeal_app_monitor()->cal;
	hal_can_frame_t hf = h->frame;
	uint8_t bus = 0U;
	bool std;
	int rc;

	if (h->unsupported) {
		if (h->kind == (uint8_t)CANDUMP_KIND_XL) {
			r->unsupported_xl++;
		} else {
			r->unsupported_fd++; /* longer than this build's HAL frame */
		}
		return;
	}
	if (!bus_of_frame(r, h, &hf, a, &bus)) {
		return;
	}
	if ((bus != cal->input_bus) && (bus != cal->output_bus)) {
		r->other_bus++; /* a bus the firmware does not use */
		return;
	}
	/* arrives at its time, so it is queued ahead of an earlier idle tick;
	 * an idle tick at the frame's own time comes first (as stepping runs
	 * it), unless the filters are known to refuse the frame */
	std = (hf.flags & (HAL_CAN_FLAG_EXT | HAL_CAN_FLAG_ERR)) == 0U;
	if (r->idle_pending && (r->idle_tick_us == r->frame_us) &&
	    !(std && r->std_filtered[bus][hf.id & CANDUMP_SFF_MAX])) {
		run_idle_tick(r);
	}
	hf.timestamp_us = r->frame_us;
	rc = hal_vbus_rx_push(bus, &hf);
	if (rc == SQ_ENOENT) {
		if (std) {
			r->std_filtered[bus][hf.id & CANDUMP_SFF_MAX] = true;
		}
		if ((hf.flags & HAL_CAN_FLAG_RTR) != 0U) {
			r->filtered_rtr++;
		} else if ((hf.flags & HAL_CAN_FLAG_EXT) != 0U) {
			r->filtered_ext++;
		} else {
			r->filtered_id++;
		}
		return;
	}
	if (rc == SQ_ENOBUFS) {
		r->rx_overflow++;
		return;
	}
	r->pushed++;
	run_idle_tick(r);
	set_time(r, r->frame_us);
	if (r->skip && (r->rx_deferred < RX_DEFER_MAX) && !fault_time_by_input(r)) {
		r->rx_deferred++;
	} else {
		take_deferred(r);
		(void)squeal_app_poll();
		after_poll(r);
	}
}

/* A frame leaves the window, in time order: the clock goes to its time. */
static void release(replay_t *r, const held_t *h, const replay_args_t *a)
{
	uint64_t t_us = h->t_us;

	if (r->init_failed) {
		return;
	}
	if (!r->started) {
		start(r, h, a);
		if (r->init_failed) {
			return;
		}
	}
	if (t_us < r->frame_us) {
		const uint64_t back = r->frame_us - t_us;

		r->backwards++;
		note(a, "%s:%llu: timestamp %llu.%06llu s behind, beyond the reorder window: frame given at the current time\n",
			a->log_name, (unsigned long long)h->line_no,
			(unsigned long long)(back / 1000000U), (unsigned long long)(back % 1000000U));
		t_us = r->frame_us;
	} else if (t_us - r->frame_us > a->max_gap_us) {
		const uint64_t gap = t_us - r->frame_us;

		r->gaps++;
		note(a, "%s:%llu: gap of %llu.%06llu s > --max-gap: skipped, not simulated\n",
			a->log_name, (unsigned long long)h->line_no,
			(unsigned long long)(gap / 1000000U), (unsigned long long)(gap % 1000000U));
		/* keep the tick grid's phase */
		take_deferred(r);
		run_idle_tick(r);
		r->next_tick_us += ((t_us - r->next_tick_us) / TICK_US) * TICK_US;
		set_time(r, t_us);
	}
	run_until(r, t_us);
	r->frame_us = t_us;
	give_frame(r, h, a);
}

/* ---- the reorder window ------------------------------------------------------ */

static bool held_before(const held_t *x, const held_t *y)
{
	return (x->t_us < y->t_us) || ((x->t_us == y->t_us) && (x->seq < y->seq));
}

static void heap_down(replay_t *r, uint32_t i)
{
	const held_t moving = r->held[i];

	for (;;) {
		const uint32_t left = (2U * i) + 1U;
		uint32_t best = left;

		if (left >= r->n_held) {
			break;
		}
		if ((left + 1U < r->n_held) && held_before(&r->held[left + 1U], &r->held[left])) {
			best = left + 1U;
		}
		if (!held_before(&r->held[best], &moving)) {
			break;
		}
		r->held[i] = r->held[best];
		i = best;
	}
	r->held[i] = moving;
}

static void heap_push(replay_t *r, const held_t *h)
{
	uint32_t i = r->n_held++;

	while (i > 0U) {
		const uint32_t up = (i - 1U) / 2U;

		if (!held_before(h, &r->held[up])) {
			break;
		}
		r->held[i] = r->held[up];
		i = up;
	}
	r->held[i] = *h;
}

/* Frames held in the window, FIFO and heap. */
static uint32_t held_count(const replay_t *r)
{
	return r->fifo_n + r->n_held;
}

/* The earliest frame held (the window is not empty). */
static const held_t *held_min(const replay_t *r)
{
	const held_t *f = (r->fifo_n != 0U) ? &r->fifo[r->fifo_head] : NULL;

	if ((f == NULL) || ((r->n_held != 0U) && held_before(&r->held[0], f))) {
		return &r->held[0];
	}
	return f;
}

static void held_pop(replay_t *r, held_t *out)
{
	if (held_min(r) == &r->held[0]) {
		*out = r->held[0];
		r->n_held--;
		if (r->n_held != 0U) {
			r->held[0] = r->held[r->n_held];
			heap_down(r, 0U);
		}
	} else {
		*out = r->fifo[r->fifo_head];
		r->fifo_head = (r->fifo_head + 1U) % REORDER_FRAMES;
		r->fifo_n--;
	}
}

/* A frame not earlier than every frame read before: the FIFO's end. */
static void fifo_push(replay_t *r, const held_t *h)
{
	r->fifo[(r->fifo_head + r->fifo_n) % REORDER_FRAMES] = *h;
	r->fifo_n++;
}

/* The frames read after the jump back were a restart: they move, with the
 * rest of the log, onto the time the log left (a new segment). */
static void detour_restart(replay_t *r, const replay_args_t *a)
{
	const uint64_t back = r->jump_from_us - r->detour_first_us;
	uint32_t i;

	for (i = 0U; i < r->n_held; i++) {
		if (r->held[i].detour) {
			r->held[i].t_us += back;
			r->held[i].detour = false;
		}
	}
	for (i = r->n_held / 2U; i > 0U; i--) {
		heap_down(r, i - 1U);
	}
	if (r->segments < SEGMENT_POINTS_MAX) {
		r->segment_at[r->segments] = (segment_point_t){ r->detour_line, back, r->jump_from_us };
	}
	r->segments++;
	r->rebase_us = (back > TIME_MAX_US - r->rebase_us) ? TIME_MAX_US : r->rebase_us + back;
	r->prev_t_us += back;
	if (r->prev_t_us > r->max_seen_us) {
		r->max_seen_us = r->prev_t_us;
	}
	r->detour = false;
	note(a, "%s:%llu: timestamp goes back by %llu.%06llu s: new segment %llu, log time re-based\n",
		a->log_name, (unsigned long long)r->detour_line,
		(unsigned long long)(back / 1000000U), (unsigned long long)(back % 1000000U),
		(unsigned long long)(r->segments + 1U));
}

/* The frames read after the jump back were a block written out of order:
 * they stay where their times put them. */
static void detour_reordered(replay_t *r, const replay_args_t *a, uint64_t line_no)
{
	const uint64_t back = r->jump_from_us - r->detour_first_us;
	uint32_t i;

	for (i = 0U; i < r->n_held; i++) {
		r->held[i].detour = false;
	}
	r->reordered += r->detour_frames;
	r->reordered_blocks++;
	r->detour = false;
	note(a, "%s:%llu: timestamp goes back by %llu.%06llu s and returns at line %llu: a block of %llu frames written out of order, put back in order\n",
		a->log_name, (unsigned long long)r->detour_line,
		(unsigned long long)(back / 1000000U), (unsigned long long)(back % 1000000U),
		(unsigned long long)line_no, (unsigned long long)r->detour_frames);
}

/* Give every frame the window need not hold any longer (all with force). */
static void release_due(replay_t *r, const replay_args_t *a, bool all)
{
	held_t h;

	while (held_count(r) > 0U) {
		if (!all && (held_count(r) < REORDER_FRAMES) &&
		    (held_min(r)->t_us + REORDER_WINDOW_US > r->max_seen_us)) {
			return;
		}
		if (r->detour) {
			/* full while a late block is open: take it as a restart */
			detour_restart(r, a);
		}
		held_pop(r, &h);
		release(r, &h, a);
	}
}

static uint8_t iface_index(replay_t *r, const char *name)
{
	uint32_t i;

	for (i = 0U; i < r->n_ifaces; i++) {
		if (strcmp(r->ifaces[i], name) == 0) {
			return (uint8_t)i;
		}
	}
	if (r->n_ifaces < IFACES_MAX) {
		(void)snprintf(r->ifaces[r->n_ifaces], sizeof(r->ifaces[0]), "%s", name);
		r->n_ifaces++;
	}
	return (uint8_t)(r->n_ifaces - 1U);
}

/* The frame's log time plus the segments' rebase (saturating). */
static uint64_t rebased_us(const replay_t *r, const candump_frame_t *f)
{
	const uint64_t raw = f->t_ns / 1000U;

	return (raw > TIME_MAX_US - r->rebase_us) ? TIME_MAX_US : raw + r->rebase_us;
}

/* One frame read from the log: into the window (see the top of the file). */
static void on_frame(replay_t *r, const candump_frame_t *f, const replay_args_t *a,
		     uint64_t line_no)
{
	held_t h;
	uint64_t t_us;

	memset(&h, 0, sizeof(h));
	h.seq = r->seq++;
	h.line_no = line_no;
	h.iface = iface_index(r, f->iface);
	h.kind = (uint8_t)f->kind;
	h.unsupported = candump_to_hal(f, &h.frame) != SQ_OK;
	if (f->kind == CANDUMP_KIND_FD) {
		r->fd_frames++;
	} else if (f->kind != CANDUMP_KIND_XL) {
		r->classic_frames++;
	} else {
		/* XL: counted as unsupported when given */
	}
	t_us = rebased_us(r, f);
	if (r->detour) {
		if (t_us + SEGMENT_BACK_US < r->prev_t_us) {
			detour_restart(r, a); /* back again: the first was a restart */
			t_us = rebased_us(r, f);
		} else if ((t_us + SEGMENT_BACK_US >= r->jump_from_us) &&
			   (t_us > r->prev_t_us + DETOUR_RETURN_STEP_US)) {
			detour_reordered(r, a, line_no); /* it returned */
		} else if (t_us > r->jump_from_us) {
			detour_restart(r, a); /* it went on past where it left */
			t_us = rebased_us(r, f);
		} else {
			h.t_us = t_us;
			h.detour = true;
			r->detour_frames++;
			r->prev_t_us = t_us;
			heap_push(r, &h);
			release_due(r, a, false);
			return;
		}
	}
	if (r->have_max && (t_us + SEGMENT_BACK_US < r->max_seen_us)) {
		if (t_us + REORDER_WINDOW_US < r->max_seen_us) {
			/* beyond the window: a restart at once */
			r->detour_first_us = t_us;
			r->jump_from_us = r->max_seen_us;
			r->detour_line = line_no;
			r->detour_frames = 0U;
			r->prev_t_us = t_us;
			r->detour = true;
			detour_restart(r, a);
			t_us = r->max_seen_us;
		} else {
			r->detour = true;
			r->jump_from_us = r->max_seen_us;
			r->detour_first_us = t_us;
			r->detour_line = line_no;
			r->detour_frames = 1U;
			h.t_us = t_us;
			h.detour = true;
			r->prev_t_us = t_us;
			heap_push(r, &h);
			release_due(r, a, false);
			return;
		}
	} else if (r->have_max && (t_us < r->max_seen_us)) {
		r->reordered++; /* a little late: put in its place */
	}
	h.t_us = t_us;
	r->prev_t_us = t_us;
	if (!r->have_max || (t_us >= r->max_seen_us)) {
		r->max_seen_us = t_us;
		r->have_max = true;
		fifo_push(r, &h);
	} else {
		heap_push(r, &h);
	}
	release_due(r, a, false);
}

/* After the last line: an open late block went on to the end (a restart);
 * every frame held is given. */
static void end_of_log(replay_t *r, const replay_args_t *a)
{
	if (r->detour) {
		detour_restart(r, a);
	}
	release_due(r, a, true);
}

/* ---- names ------------------------------------------------------------------- */

static const char *const pos_names[4] = { "FL", "FR", "RL", "RR" };
static const char *const qty_names[2] = { "speed", "force" };

/* Input j (0 speed, 1 force) of corner k in the vehicle's words:
 * "FL speed WHEEL_SPEEDS.WHEEL_SPEED_FL" (the input's DBC signal, else its
 * [input] section's name); DiscSpeed / PadForce for the legacy form. */
static void input_label(const replay_t *r, uint32_t k, unsigned j, char *buf, size_t len)
{
	const monitor_t *c = squeal_app_corner(k);
	const calib_t *cal = c->cal;
	uint32_t idx;
	const char *what;

	if (!r->map_form || (cal->n_corners == 0U) || (c->corner_index >= cal->n_corners)) {
		(void)snprintf(buf, len, "%s", (j == 0U) ? "DiscSpeed" : "PadForce");
		return;
	}
	idx = (j == 0U) ? cal->corners[c->corner_index].speed_input :
			  cal->corners[c->corner_index].force_input;
	what = "?";
	if (idx < CALIB_MAX_INPUTS) {
		what = (r->names.signal[idx][0] != '\0') ? r->names.signal[idx] : r->names.input[idx];
	}
	(void)snprintf(buf, len, "%s %s %s", pos_names[c->corner.pos & 3U], qty_names[j], what);
}

/* share of total in percent, one decimal */
static void print_share(FILE *o, uint64_t part, uint64_t total)
{
	const uint64_t pm = (total == 0U) ? 0U : ((part * 1000U) + (total / 2U)) / total;

	fprintf(o, "%llu.%llu %%", (unsigned long long)(pm / 10U), (unsigned long long)(pm % 10U));
}

/* ---- summary ------------------------------------------------------------------- */

static void print_us(FILE *o, uint64_t us)
{
	fprintf(o, "%llu.%06llu", (unsigned long long)(us / 1000000U),
		(unsigned long long)(us % 1000000U));
}

static long vm_hwm_kb(void)
{
	FILE *f = fopen("/proc/self/status", "r");
	char line[256];
	long kb = -1;

	if (f == NULL) {
		return -1;
	}
	while (fgets(line, sizeof(line), f) != NULL) {
		if (strncmp(line, "VmHWM:", 6) == 0) {
			kb = strtol(line + 6, NULL, 10);
			break;
		}
	}
	(void)fclose(f);
	return kb;
}

/* A corner's replayed time: the sum of its time in each state (the base of
 * the shares in the text and the JSON summary). */
static uint64_t corner_time_us(const corner_stats_t *cs)
{
	uint64_t total = 0U;
	unsigned s;

	for (s = 0U; s < N_STATES; s++) {
		total += cs->state_us[s];
	}
	return total;
}

/* What the text and the JSON summary show of corner k. */
typedef struct {
	const corner_stats_t *cs;
	const input_counters_t *cnt[2]; /* speed, force */
	uint64_t total_us;              /* corner_time_us */
} corner_view_t;

static const monitor_t *corner_view(const replay_t *r, uint32_t k, corner_view_t *v)
{
	const monitor_t *c = squeal_app_corner(k);

	v->cs = &r->cs[k];
	v->cnt[0] = &c->speed.count;
	v->cnt[1] = &c->force.count;
	v->total_us = corner_time_us(v->cs);
	return c;
}

/* One corner: final state, share of time per state, each input's frames
 * used and rejected by the input stage's reasons, the time in FAULT by
 * reason. */
static void corner_summary(FILE *o, const replay_t *r, uint32_t k)
{
	corner_view_t v;
	const monitor_t *c = corner_view(r, k, &v);
	const corner_stats_t *cs = v.cs;
	const input_counters_t *const *cnt = v.cnt;
	const uint64_t total = v.total_us;
	char label[96];
	unsigned s;
	unsigned j;
	unsigned q;

	fprintf(o, "  corner %s              final %s, time", pos_names[c->corner.pos & 3U],
		rs_state_name(msg_squeal_state_slot(c->state)));
	for (s = 0U; s < N_STATES; s++) {
		fprintf(o, " %s ", rs_state_name(s));
		print_share(o, cs->state_us[s], total);
	}
	fprintf(o, "\n");
	for (j = 0U; j < 2U; j++) {
		input_label(r, k, j, label, sizeof(label));
		fprintf(o, "    %s: frames %u, used %u, rejected", label, cnt[j]->frames, cnt[j]->used);
		for (q = 1U; q < (unsigned)INPUT_RX_REASON_COUNT; q++) {
			fprintf(o, " %s %llu", input_rx_reason_name((input_rx_reason_t)q),
				(unsigned long long)cnt[j]->verdict[q]);
		}
		fprintf(o, ", stale events %u\n", cnt[j]->stale_events);
	}
	fprintf(o, "    fault time:");
	for (j = 0U; j < 2U; j++) {
		input_label(r, k, j, label, sizeof(label));
		for (q = 0U; q < N_FAULT_BITS; q++) {
			if (cs->fault_us[j][q] != 0U) {
				fprintf(o, " %s %s ", label, fault_bit_names[q]);
				print_us(o, cs->fault_us[j][q]);
				fprintf(o, " s,");
			}
		}
	}
	fprintf(o, " without an input fault ");
	print_us(o, cs->fault_other_us);
	fprintf(o, " s\n");
}

static void summary_to(FILE *o, const replay_t *r, const replay_args_t *a)
{
	const monitor_t *m = squeal_app_monitor();
	const input_counters_t *sp = &m->speed.count;
	const input_counters_t *fo = &m->force.count;
	unsigned i;
	unsigned j;
	uint64_t changes = 0U;
	char l0[96];
	char l1[96];

	fprintf(o, "replay summary: %s\n", a->log_name);
	fprintf(o, "  lines                 %llu (frames %llu, comments %llu, blank %llu, dropcount %llu, malformed %llu)\n",
		(unsigned long long)r->lines, (unsigned long long)r->frames,
		(unsigned long long)r->comments, (unsigned long long)r->blanks,
		(unsigned long long)r->dropcount_lines, (unsigned long long)r->malformed);
	if (!r->started) {
		fprintf(o, "  no frames: the firmware was not started\n");
		return;
	}
	input_label(r, 0U, 0U, l0, sizeof(l0));
	input_label(r, 0U, 1U, l1, sizeof(l1));
	fprintf(o, "  virtual_time_s        ");
	print_us(o, r->now_us - r->t0_us);
	fprintf(o, " (from ");
	print_us(o, r->t0_us);
	fprintf(o, ", tail %llu ms)\n", (unsigned long long)(a->tail_us / 1000U));
	fprintf(o, "  frames_read           %llu (classic_frames %llu, fd_frames %llu, xl_frames %llu)\n",
		(unsigned long long)r->frames, (unsigned long long)r->classic_frames,
		(unsigned long long)r->fd_frames,
		(unsigned long long)(r->frames - r->classic_frames - r->fd_frames));
	fprintf(o, "  frames_used           %llu (%s %u, %s %u)\n",
		(unsigned long long)sp->used + fo->used, l0, sp->used, l1, fo->used);
	for (i = 0U; (i < squeal_app_corner_count()) && (i < CALIB_MAX_CORNERS); i++) {
		corner_summary(o, r, i);
	}
	fprintf(o, "  rejected:\n");
	fprintf(o, "    malformed_lines     %llu\n", (unsigned long long)r->malformed);
	fprintf(o, "    filtered_ids        %llu (other ids %llu, remote %llu, extended %llu)\n",
		(unsigned long long)(r->filtered_id + r->filtered_rtr + r->filtered_ext),
		(unsigned long long)r->filtered_id, (unsigned long long)r->filtered_rtr,
		(unsigned long long)r->filtered_ext);
	fprintf(o, "    unsupported_fd_xl   %llu (FD %llu, XL %llu)\n",
		(unsigned long long)(r->unsupported_fd + r->unsupported_xl),
		(unsigned long long)r->unsupported_fd, (unsigned long long)r->unsupported_xl);
	fprintf(o, "    e2e_wrong_crc       %llu (%s %u, %s %u)\n",
		(unsigned long long)sp->e2e_wrong_crc + fo->e2e_wrong_crc, l0, sp->e2e_wrong_crc,
		l1, fo->e2e_wrong_crc);
	fprintf(o, "    e2e_wrong_sequence  %llu (%s %u, %s %u)\n",
		(unsigned long long)sp->e2e_wrong_sequence + fo->e2e_wrong_sequence,
		l0, sp->e2e_wrong_sequence, l1, fo->e2e_wrong_sequence);
	fprintf(o, "    repeated            %llu (%s %u, %s %u)\n",
		(unsigned long long)sp->e2e_repeated + fo->e2e_repeated, l0, sp->e2e_repeated,
		l1, fo->e2e_repeated);
	fprintf(o, "    implausible         %llu (%s %u, %s %u)\n",
		(unsigned long long)sp->implausible + fo->implausible, l0, sp->implausible,
		l1, fo->implausible);
	fprintf(o, "    bad_dlc             %llu (%s %u, %s %u)\n",
		(unsigned long long)sp->bad_dlc + fo->bad_dlc, l0, sp->bad_dlc, l1, fo->bad_dlc);
	fprintf(o, "    error_frames        %u\n", m->count.error_frames);
	fprintf(o, "    remote_or_extended  %u\n", m->count.rtr_or_ext);
	fprintf(o, "    rx_overflow         %llu\n", (unsigned long long)r->rx_overflow);
	if (a->input_iface != NULL) {
		fprintf(o, "    other_bus           %llu\n", (unsigned long long)r->other_bus);
	} else if (r->multi_reported) {
		fprintf(o, "    other_iface_inputs  %llu (input identifiers not on %s)\n",
			(unsigned long long)r->other_iface_inputs, r->ifaces[r->auto_iface]);
	}
	fprintf(o, "  e2e_frames_lost       %llu (counter gaps: %s %u, %s %u)\n",
		(unsigned long long)sp->e2e_lost + fo->e2e_lost, l0, sp->e2e_lost, l1, fo->e2e_lost);
	fprintf(o, "  stale_events          %llu (%s %u, %s %u)\n",
		(unsigned long long)sp->stale_events + fo->stale_events, l0, sp->stale_events,
		l1, fo->stale_events);
	fprintf(o, "  candump_dropped       %llu\n", (unsigned long long)r->dropped);
	fprintf(o, "  time_backwards        %llu\n", (unsigned long long)r->backwards);
	fprintf(o, "  reordered             %llu (frames put back in time order; blocks written out of order: %llu; window %u s, %u frames)\n",
		(unsigned long long)r->reordered, (unsigned long long)r->reordered_blocks,
		REORDER_WINDOW_US / 1000000U, REORDER_FRAMES);
	fprintf(o, "  segments              %llu (new after a jump back of more than 1 s: %llu)\n",
		(unsigned long long)(r->segments + 1U), (unsigned long long)r->segments);
	fprintf(o, "  gaps_skipped          %llu\n", (unsigned long long)r->gaps);
	fprintf(o, "  state_time_s         ");
	for (i = 0U; i < N_STATES; i++) {
		fprintf(o, " %s=", rs_state_name(i));
		print_us(o, r->state_us[i]);
	}
	fprintf(o, "\n  warnings_raised      ");
	for (i = 1U; i < N_LEVELS; i++) {
		fprintf(o, " %s=%llu", level_names[i], (unsigned long long)r->into_level[i]);
	}
	fprintf(o, " (back to none: %llu)\n", (unsigned long long)r->into_level[0]);
	for (i = 0U; i < N_STATES; i++) {
		for (j = 0U; j < N_STATES; j++) {
			changes += r->transitions[i][j];
		}
	}
	fprintf(o, "  state_changes         %llu", (unsigned long long)changes);
	for (i = 0U; i < N_STATES; i++) {
		for (j = 0U; j < N_STATES; j++) {
			if (r->transitions[i][j] != 0U) {
				fprintf(o, " %s->%s=%llu", rs_state_name(i), rs_state_name(j),
					(unsigned long long)r->transitions[i][j]);
			}
		}
	}
	fprintf(o, "\n  final_state           %s, warning %s\n",
		rs_state_name(msg_squeal_state_slot(m->state)),
		(m->warning < N_LEVELS) ? level_names[m->warning] : "?");
	fprintf(o, "  output_frames         %llu (", (unsigned long long)r->out_frames);
	for (i = 0U; i < MSG_COUNT; i++) {
		fprintf(o, "%s%s %llu", (i == 0U) ? "" : ", ", msg_table[i].name,
			(unsigned long long)r->out_by_msg[i]);
	}
	fprintf(o, ", other %llu)\n", (unsigned long long)r->out_by_msg[MSG_COUNT]);
	if (a->input_iface != NULL) {
		fprintf(o, "  input_iface           %s (%s)\n", a->input_iface,
			a->input_iface_from_bus ? "--bus" : "calibration");
	} else if (r->auto_input) {
		fprintf(o, "  input_iface           %s (the first interface with an input identifier)\n",
			r->ifaces[r->auto_iface]);
	}
	if (squeal_app_init_status() != SQ_OK) {
		fprintf(o, "  firmware_init         error %d (running with defaults)\n",
			squeal_app_init_status());
	}
	if (a->rss) {
		fprintf(o, "  peak_rss_kb           %ld\n", vm_hwm_kb());
	}
}

/* The summary on stderr in one write: stderr is unbuffered, and a write
 * per piece (about a hundred per log) would wake a program that reads it
 * through a pipe as often (tools/fleet.py reads it for every log; with
 * two workers that traffic cost a third of the fleet's speed). Formatted
 * into a fixed buffer, so the heap a replay uses stays the same whatever
 * the log; straight onto stderr when that stream cannot be had or the
 * text would not fit. */
#define SUMMARY_TEXT_MAX 32768U
static char summary_text[SUMMARY_TEXT_MAX];

static void summary(const replay_t *r, const replay_args_t *a)
{
	FILE *mem = fmemopen(summary_text, sizeof(summary_text), "w");
	long len;

	if (mem == NULL) {
		summary_to(stderr, r, a);
		return;
	}
	summary_to(mem, r, a);
	len = (fflush(mem) == 0) ? ftell(mem) : -1L;
	if ((len >= 0L) && ((unsigned long)len < sizeof(summary_text))) {
		(void)fwrite(summary_text, 1U, (size_t)len, stderr);
	} else {
		summary_to(stderr, r, a);
	}
	(void)fclose(mem);
}

/* ---- summary as JSON (--summary-json; the same counts as summary()) ---------------- */

static void json_pair(json_writer_t *w, const char *key, uint64_t speed, uint64_t force)
{
	json_key(w, key);
	json_begin_object(w);
	json_kv_u64(w, "total", speed + force);
	json_kv_u64(w, "DiscSpeed", speed);
	json_kv_u64(w, "PadForce", force);
	json_end_object(w);
}

/* "segments": the text summary's count and new ones, and where each new
 * segment began (the line and jump of its stderr message, and the virtual
 * time the log was re-based onto); points beyond SEGMENT_POINTS_MAX are
 * counted in "points_not_listed". */
static void json_segments(json_writer_t *w, const replay_t *r)
{
	const uint64_t listed = (r->segments < SEGMENT_POINTS_MAX) ? r->segments : SEGMENT_POINTS_MAX;
	uint64_t i;

	json_key(w, "segments");
	json_begin_object(w);
	json_kv_u64(w, "total", r->started ? r->segments + 1U : 0U);
	json_kv_u64(w, "new", r->segments);
	json_key(w, "rebase_points");
	json_begin_array(w);
	for (i = 0U; i < listed; i++) {
		json_begin_object(w);
		json_kv_u64(w, "segment", i + 2U);
		json_kv_u64(w, "line", r->segment_at[i].line_no);
		json_kv_seconds(w, "back_s", r->segment_at[i].back_us);
		json_kv_seconds(w, "at_s", r->segment_at[i].at_us);
		json_end_object(w);
	}
	json_end_array(w);
	json_kv_u64(w, "points_not_listed", r->segments - listed);
	json_end_object(w);
}

/* "buses": where the inputs came from and what was ignored. */
static void json_buses(json_writer_t *w, const replay_t *r, const replay_args_t *a)
{
	uint32_t i;

	json_key(w, "buses");
	json_begin_object(w);
	json_key(w, "input_iface");
	if (a->input_iface != NULL) {
		json_string(w, a->input_iface);
	} else {
		json_string(w, r->auto_input ? r->ifaces[r->auto_iface] : NULL);
	}
	json_kv_string(w, "chosen_by", (a->input_iface == NULL) ?
		       (r->auto_input ? "first_input_frame" : "none") :
		       (a->input_iface_from_bus ? "bus_option" : "calibration"));
	json_key(w, "interfaces");
	json_begin_array(w);
	for (i = 0U; i < r->n_ifaces; i++) {
		json_string(w, r->ifaces[i]);
	}
	json_end_array(w);
	json_key(w, "interfaces_with_inputs");
	json_begin_array(w);
	for (i = 0U; i < r->n_ifaces; i++) {
		if (r->iface_has_inputs[i]) {
			json_string(w, r->ifaces[i]);
		}
	}
	json_end_array(w);
	json_kv_u64(w, "other_iface_inputs", r->other_iface_inputs);
	json_kv_u64(w, "other_bus", r->other_bus);
	json_end_object(w);
}

/* One input of a corner in "inputs_by_corner" (j: 0 speed, 1 force). */
static void json_corner_input(json_writer_t *w, const replay_t *r, uint32_t k, unsigned j,
			      const corner_view_t *v)
{
	const input_counters_t *cnt = v->cnt[j];
	char label[96];
	unsigned q;

	input_label(r, k, j, label, sizeof(label));
	json_key(w, qty_names[j]);
	json_begin_object(w);
	json_kv_string(w, "label", label);
	json_kv_u64(w, "frames", cnt->frames);
	json_kv_u64(w, "used", cnt->used);
	json_key(w, "rejected");
	json_begin_object(w);
	for (q = 1U; q < (unsigned)INPUT_RX_REASON_COUNT; q++) {
		json_kv_u64(w, input_rx_reason_name((input_rx_reason_t)q), cnt->verdict[q]);
	}
	json_end_object(w);
	json_kv_u64(w, "stale_events", cnt->stale_events);
	json_key(w, "fault_time_s");
	json_begin_object(w);
	for (q = 0U; q < N_FAULT_BITS; q++) {
		json_kv_seconds(w, fault_bit_names[q], v->cs->fault_us[j][q]);
	}
	json_end_object(w);
	json_end_object(w);
}

/* "inputs_by_corner": the text summary's corner blocks. */
static void json_inputs_by_corner(json_writer_t *w, const replay_t *r)
{
	uint32_t k;

	json_key(w, "inputs_by_corner");
	json_begin_array(w);
	for (k = 0U; r->started && (k < squeal_app_corner_count()) && (k < CALIB_MAX_CORNERS); k++) {
		corner_view_t v;
		const monitor_t *c = corner_view(r, k, &v);
		unsigned s;

		json_begin_object(w);
		json_kv_string(w, "corner", pos_names[c->corner.pos & 3U]);
		json_kv_string(w, "final_state", rs_state_name(msg_squeal_state_slot(c->state)));
		rs_json_state_times(w, "state_time_s", v.cs->state_us);
		json_key(w, "state_share");
		json_begin_object(w);
		for (s = 0U; s < N_STATES; s++) {
			json_key(w, rs_state_name(s));
			json_fixed(w, (v.total_us == 0U) ? 0 :
				   (int64_t)(((v.cs->state_us[s] * 1000000U) + (v.total_us / 2U)) /
					     v.total_us), 6U);
		}
		json_end_object(w);
		json_corner_input(w, r, k, 0U, &v);
		json_corner_input(w, r, k, 1U, &v);
		json_kv_seconds(w, "fault_without_input_fault_s", v.cs->fault_other_us);
		json_end_object(w);
	}
	json_end_array(w);
}

/* --each: the log's exit status and the message of its failure ("" for
 * none), as the run of that log alone gives them (its exit status and last
 * message on stderr). */
static void json_outcome(json_writer_t *w, const replay_t *r, int status)
{
	json_key(w, "exit_status");
	json_i64(w, status);
	json_kv_string(w, "error", r->error);
}

/* Everything after the episodes: the caller began the object with "log"
 * and the episodes (replay_summary_init); this closes it. */
static void summary_json(json_writer_t *w, const replay_t *r, const replay_args_t *a, int status)
{
	/* a log without frames never started the firmware: its counters are
	 * the zeros of an ECU that did not run (with --each, not the last log's) */
	static const monitor_t not_started;
	const monitor_t *m = r->started ? squeal_app_monitor() : &not_started;
	const input_counters_t *sp = &m->speed.count;
	const input_counters_t *fo = &m->force.count;
	uint64_t changes = 0U;
	unsigned i;
	unsigned j;

	replay_summary_finish(r->summary, r->now_us);
	json_key(w, "lines");
	json_begin_object(w);
	json_kv_u64(w, "total", r->lines);
	json_kv_u64(w, "frames", r->frames);
	json_kv_u64(w, "comments", r->comments);
	json_kv_u64(w, "blank", r->blanks);
	json_kv_u64(w, "dropcount", r->dropcount_lines);
	json_kv_u64(w, "malformed", r->malformed);
	json_end_object(w);
	json_key(w, "started");
	json_bool(w, r->started);
	json_kv_seconds(w, "t0_s", r->t0_us);
	json_kv_seconds(w, "virtual_time_s", r->now_us - r->t0_us);
	json_kv_u64(w, "tail_ms", a->tail_us / 1000U);
	json_kv_u64(w, "frames_read", r->frames);
	json_key(w, "frames_by_format");
	json_begin_object(w);
	json_kv_u64(w, "classic", r->classic_frames);
	json_kv_u64(w, "fd", r->fd_frames);
	json_kv_u64(w, "xl", r->frames - r->classic_frames - r->fd_frames);
	json_end_object(w);
	json_pair(w, "frames_used", r->started ? sp->used : 0U, r->started ? fo->used : 0U);
	json_key(w, "rejected");
	json_begin_object(w);
	json_kv_u64(w, "malformed_lines", r->malformed);
	json_key(w, "filtered_ids");
	json_begin_object(w);
	json_kv_u64(w, "total", r->filtered_id + r->filtered_rtr + r->filtered_ext);
	json_kv_u64(w, "other_ids", r->filtered_id);
	json_kv_u64(w, "remote", r->filtered_rtr);
	json_kv_u64(w, "extended", r->filtered_ext);
	json_end_object(w);
	json_key(w, "unsupported_fd_xl");
	json_begin_object(w);
	json_kv_u64(w, "total", r->unsupported_fd + r->unsupported_xl);
	json_kv_u64(w, "fd", r->unsupported_fd);
	json_kv_u64(w, "xl", r->unsupported_xl);
	json_end_object(w);
	json_pair(w, "e2e_wrong_crc", sp->e2e_wrong_crc, fo->e2e_wrong_crc);
	json_pair(w, "e2e_wrong_sequence", sp->e2e_wrong_sequence, fo->e2e_wrong_sequence);
	json_pair(w, "repeated", sp->e2e_repeated, fo->e2e_repeated);
	json_pair(w, "implausible", sp->implausible, fo->implausible);
	json_pair(w, "bad_dlc", sp->bad_dlc, fo->bad_dlc);
	json_kv_u64(w, "error_frames", m->count.error_frames);
	json_kv_u64(w, "remote_or_extended", m->count.rtr_or_ext);
	json_kv_u64(w, "rx_overflow", r->rx_overflow);
	json_end_object(w);
	json_pair(w, "e2e_frames_lost", sp->e2e_lost, fo->e2e_lost);
	json_pair(w, "stale_events", sp->stale_events, fo->stale_events);
	json_kv_u64(w, "candump_dropped", r->dropped);
	json_kv_u64(w, "time_backwards", r->backwards);
	json_segments(w, r);
	json_key(w, "reordered");
	json_begin_object(w);
	json_kv_u64(w, "frames", r->reordered);
	json_kv_u64(w, "blocks", r->reordered_blocks);
	json_kv_seconds(w, "window_s", REORDER_WINDOW_US);
	json_kv_u64(w, "window_frames", REORDER_FRAMES);
	json_end_object(w);
	json_buses(w, r, a);
	json_kv_u64(w, "gaps_skipped", r->gaps);
	rs_json_state_times(w, "state_time_s", r->state_us);
	json_key(w, "warnings_raised");
	json_begin_object(w);
	for (i = 1U; i < N_LEVELS; i++) {
		json_kv_u64(w, level_names[i], r->into_level[i]);
	}
	json_kv_u64(w, "back_to_none", r->into_level[0]);
	json_end_object(w);
	json_key(w, "state_changes");
	json_begin_object(w);
	for (i = 0U; i < N_STATES; i++) {
		for (j = 0U; j < N_STATES; j++) {
			char name[32];

			changes += r->transitions[i][j];
			if (r->transitions[i][j] != 0U) {
				(void)snprintf(name, sizeof(name), "%s->%s", rs_state_name(i), rs_state_name(j));
				json_kv_u64(w, name, r->transitions[i][j]);
			}
		}
	}
	json_kv_u64(w, "total", changes);
	json_end_object(w);
	json_key(w, "final_state");
	json_string(w, r->started ? rs_state_name(msg_squeal_state_slot(m->state)) : NULL);
	json_key(w, "final_warning");
	json_string(w, (r->started && (m->warning < N_LEVELS)) ? level_names[m->warning] : NULL);
	json_key(w, "output_frames");
	json_begin_object(w);
	json_kv_u64(w, "total", r->out_frames);
	for (i = 0U; i < MSG_COUNT; i++) {
		json_kv_u64(w, msg_table[i].name, r->out_by_msg[i]);
	}
	json_kv_u64(w, "other", r->out_by_msg[MSG_COUNT]);
	json_end_object(w);
	json_inputs_by_corner(w, r);
	json_key(w, "output_written");
	json_bool(w, !a->no_output);
	json_key(w, "firmware_init_status");
	json_i64(w, r->started ? squeal_app_init_status() : 0);
	if (a->rss) {
		json_key(w, "peak_rss_kb");
		json_i64(w, vm_hwm_kb());
	}
	json_key(w, "first_malformed");
	if (r->first_bad_line == 0U) {
		json_null(w);
	} else {
		json_begin_object(w);
		json_kv_u64(w, "line", r->first_bad_line);
		json_kv_u64(w, "column", r->first_bad_column);
		json_kv_string(w, "error", candump_strerror(r->first_bad_err));
		json_end_object(w);
	}
	if (a->each) {
		json_outcome(w, r, status);
	}
	json_end_object(w);
}

/* --summary-json's file (- : stdout), opened when the first document is
 * due (so a log that cannot be opened leaves no file behind); NULL when it
 * cannot be written, said so once. */
static FILE *json_file;
static bool json_file_failed;

static FILE *summary_json_file(const replay_args_t *a)
{
	if ((json_file == NULL) && !json_file_failed) {
		json_file = (strcmp(a->summary_json, "-") == 0) ? stdout : fopen(a->summary_json, "w");
		if (json_file == NULL) {
			json_file_failed = true;
			fprintf(stderr, "squeal-sim replay: cannot write %s: %s\n", a->summary_json,
				strerror(errno));
		}
	}
	return json_file;
}

/* The summary file could not be written whole: said once. */
static void summary_json_failed(const replay_args_t *a)
{
	if (!json_file_failed) {
		json_file_failed = true;
		fprintf(stderr, "squeal-sim replay: error writing %s\n", a->summary_json);
	}
}

/* 0, or -1 (said so) when the file could not be written whole. */
static int summary_json_close(FILE *f, const replay_args_t *a)
{
	int rc = (fflush(f) != 0) ? -1 : 0;

	if ((f != stdout) && (fclose(f) != 0)) {
		rc = -1;
	}
	if ((rc != 0) || json_file_failed) {
		summary_json_failed(a);
		rc = -1;
	}
	return rc;
}

/* The document's first members, on f. */
static void summary_doc_head(json_writer_t *w, FILE *f, const replay_args_t *a)
{
	json_writer_init(w, f);
	json_begin_object(w);
	json_kv_string(w, "format", "squeal-replay-summary");
	json_kv_u64(w, "version", 1U);
	json_kv_string(w, "log", a->log_name);
}

/* Starts a log's document on f: the episodes follow as they happen. */
static void summary_doc_begin(json_writer_t *w, FILE *f, replay_summary_t *rs, const replay_args_t *a)
{
	summary_doc_head(w, f, a);
	replay_summary_init(rs, w);
}

/* Ends a log's document with the rest of the summary (and its line: the
 * writer ends a document with a newline) and writes it out, before the
 * text summary and before the next log (a later crash keeps it); false
 * (said so) when it could not be written whole. */
static bool summary_doc_end(json_writer_t *w, const replay_t *r, const replay_args_t *a, int status)
{
	summary_json(w, r, a, status);
	if (!json_writer_done(w) || (fflush(w->out) != 0)) {
		summary_json_failed(a);
		return false;
	}
	return true;
}

/* A log --each could not open: a document of what is known. */
static bool summary_doc_unopened(FILE *f, const replay_t *r, const replay_args_t *a)
{
	json_writer_t w;

	summary_doc_head(&w, f, a);
	json_key(&w, "started");
	json_bool(&w, false);
	json_outcome(&w, r, 1);
	json_end_object(&w);
	if (!json_writer_done(&w) || (fflush(f) != 0)) {
		summary_json_failed(a);
		return false;
	}
	return true;
}

/* ---- main ------------------------------------------------------------------------ */

static int load_calib(replay_t *r, const char *path)
{
	calib_t cal;
	uint8_t block[CALIB_BLOCK_LEN];
	char err[256];

	if (calib_text_load_map(path, &cal, &r->names, err, sizeof(err)) != SQ_OK) {
		fprintf(stderr, "squeal-sim replay: %s\n", err);
		return -1;
	}
	r->map_form = cal.n_corners != 0U;
	if ((calib_encode(&cal, block, sizeof(block)) != SQ_OK) ||
	    (hal_vbus_calib_store(block, sizeof(block)) != SQ_OK)) {
		fprintf(stderr, "squeal-sim replay: %s: cannot store the calibration\n", path);
		return -1;
	}
	return 0;
}

/* A malformed log line (column 0: the whole line) on stderr unless --quiet;
 * the first is kept for the document. */
static void report_line(replay_t *r, candump_pending_t *p, const replay_args_t *a,
			uint64_t line_no, candump_err_t err, size_t column)
{
	if (r->first_bad_line == 0U) {
		r->first_bad_line = line_no;
		r->first_bad_column = column;
		r->first_bad_err = err;
	}
	if (a->quiet) {
		return;
	}
	if (column == 0U) {
		candump_pending_report(p, "%s:%llu: %s", a->log_name, (unsigned long long)line_no,
				       candump_strerror(err));
	} else {
		candump_pending_report(p, "%s:%llu: %s (column %zu)", a->log_name,
				       (unsigned long long)line_no, candump_strerror(err), column);
	}
}

/* A failure of the log: on stderr, and kept for the --each document. */
static void fail(replay_t *r, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

static void fail(replay_t *r, const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	(void)vsnprintf(r->error, sizeof(r->error), fmt, ap);
	va_end(ap);
	fprintf(stderr, "%s\n", r->error);
}

/* The reorder window's frames (7 MB): outside replay_t, which is cleared
 * at start, so that only the part a log fills is ever touched. */
static held_t window_fifo[REORDER_FRAMES];
static held_t window_heap[REORDER_FRAMES];

/* One log's state: large, so static; cleared (as far as used) per log. */
static candump_reader_t reader; /* 270 kB */
static replay_t rp;
static replay_summary_t rs;     /* 820 kB of occupancy cells */
static candump_pending_t pending;

/* Reads the log through the firmware; the exit status of the line loop's
 * errors is left in r (read_error). */
static int read_log(replay_t *r, FILE *in, const replay_args_t *a)
{
	candump_frame_t f;
	const char *line;
	size_t len;
	bool too_long;
	int rc = 0;

	candump_reader_init(&reader, in);
	while (!r->init_failed) {
		candump_err_t err = CANDUMP_OK;
		size_t col = 0U;

		rc = candump_reader_next(&reader, &line, &len, &too_long);
		if (rc <= 0) {
			break;
		}
		r->lines++;
		if (too_long) {
			r->malformed++;
			report_line(r, &pending, a, reader.line_no, CANDUMP_ERR_TOO_LONG, 0U);
			continue;
		}
		switch (candump_parse_line(line, len, &f, &err, &col)) {
		case CANDUMP_LINE_FRAME:
			r->frames++;
			candump_pending_frame(&pending);
			on_frame(r, &f, a, reader.line_no);
			break;
		case CANDUMP_LINE_BLANK:
			r->blanks++;
			break;
		case CANDUMP_LINE_COMMENT:
			r->comments++;
			break;
		case CANDUMP_LINE_DROPCOUNT:
			r->dropcount_lines++;
			r->dropped += f.dropped;
			break;
		default:
			r->malformed++;
			report_line(r, &pending, a, reader.line_no, err, col + 1U);
			break;
		}
	}
	return (rc < 0) ? -1 : 0;
}

/*
 * Replays the log name from a reset ECU, its document to --summary-json's
 * file. Returns the exit status a run of this log alone gives, or -1 when
 * no later log can be replayed either (the summary file cannot be written,
 * the calibration cannot be loaded).
 */
static int replay_log(const replay_args_t *args, const char *name)
{
	replay_t *const r = &rp;
	replay_args_t a = *args;
	FILE *json_f = NULL;
	json_writer_t jw;
	bool json_ok = true;
	bool no_frames = false;
	int status = 0;
	int read_rc;
	FILE *in;

	memset(r, 0, sizeof(*r));
	r->fifo = window_fifo;
	r->held = window_heap;
	a.log_name = name;
	if (strcmp(a.log_name, "-") == 0) {
		in = stdin;
		a.log_name = "<stdin>";
	} else {
		in = fopen(a.log_name, "rb");
		if (in == NULL) {
			fail(r, "squeal-sim replay: cannot open %s: %s", a.log_name, strerror(errno));
			if (a.each) {
				json_f = summary_json_file(&a);
				if ((json_f == NULL) || !summary_doc_unopened(json_f, r, &a)) {
					return -1;
				}
			}
			return 1;
		}
	}
	hal_vbus_reset();
	if ((a.calib_path != NULL) && (load_calib(r, a.calib_path) != 0)) {
		if (in != stdin) {
			(void)fclose(in);
		}
		return -1;
	}
	if ((a.input_iface == NULL) && (r->names.input_iface[0] != '\0')) {
		a.input_iface = r->names.input_iface;
	}
	r->no_output = a.no_output;
	r->skip = !a.step_every_ms;
	if (a.summary_json != NULL) {
		json_f = summary_json_file(&a);
		if (json_f == NULL) {
			if (in != stdin) {
				(void)fclose(in);
			}
			return -1;
		}
		summary_doc_begin(&jw, json_f, &rs, &a);
		r->summary = &rs;
	}
	candump_pending_init(&pending, stderr, a.log_name);
	read_rc = read_log(r, in, &a);
	if (read_rc < 0) {
		fail(r, "squeal-sim replay: %s: read error", a.log_name);
		status = 1;
	}
	if (in != stdin) {
		(void)fclose(in);
	}
	if (!r->init_failed) {
		end_of_log(r, &a);
	}
	if (r->init_failed) {
		fail(r, "squeal-sim replay: %s: the firmware refused the calibration (firmware_init error %d)",
		     a.calib_path, squeal_app_init_status());
		if (json_f != NULL) {
			json_ok = summary_doc_end(&jw, r, &a, 1);
		}
		return json_ok ? 1 : -1;
	}
	if (r->started) {
		/* the tick that takes the last frame in, then the tail */
		const uint64_t end_us = r->next_tick_us + a.tail_us;

		run_until(r, end_us);
		run_idle_tick(r);
		set_time(r, end_us);
	}
	out_flush(r);
	if ((fflush(stdout) != 0) || r->out_error) {
		fail(r, "squeal-sim replay: error writing the output");
		status = 1;
	} else if ((read_rc == 0) && candump_pending_no_frames(&pending, r->lines)) {
		candump_no_frames_text(r->error, sizeof(r->error), a.log_name, r->lines);
		no_frames = true;
		status = 1;
	}
	if (json_f != NULL) {
		json_ok = summary_doc_end(&jw, r, &a, status);
	}
	if (!no_frames) {
		summary(r, &a);
	}
	return json_ok ? status : -1;
}

int cmd_replay(int argc, char **argv)
{
	static char outbuf[1U << 16];
	static replay_args_t a; /* the LOG words: 32 kB */
	int worst = 0;
	size_t i;
	int rc;

	memset(&a, 0, sizeof(a));
	rc = replay_parse(argc, argv, &a);
	if (rc != CLI_OK) {
		return cli_exit_status((cli_result_t)rc);
	}
	(void)setvbuf(stdout, outbuf, _IOFBF, sizeof(outbuf));
	for (i = 0U; i < a.n_logs; i++) {
		rc = replay_log(&a, a.logs[i]);
		if (rc < 0) {
			worst = 1;
			break; /* said so: no later log can be replayed */
		}
		if (rc > worst) {
			worst = rc;
		}
	}
	if ((json_file != NULL) && (summary_json_close(json_file, &a) != 0)) {
		worst = 1;
	}
	return worst;
}
