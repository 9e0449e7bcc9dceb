/* SPDX-License-Identifier: MIT */
/*
 * squeal-sim replay LOG|- : the unchanged firmware (squeal_app_init/poll)
 * fed from a candump -L log in virtual time (hal_vbus), offline and
 * deterministic.
 *
 * Time: the first frame's timestamp (microseconds; a 9-digit log is
 * truncated to us, the firmware's resolution) starts the firmware. Before
 * each frame, every 1 ms tick up to the frame's time is run (set the virtual
 * clock, poll, take what the ECU sent); then the clock is set to the frame's
 * time, the frame is offered to the CAN controller and the firmware polls
 * once more. After the last frame the ticks go on for --tail-ms (default
 * 100 ms: ten SquealStatus periods, enough for the status after the last
 * input and for the staleness timeout of 30 ms to show). Nothing depends on
 * the wall clock, so the same log gives the same bytes.
 *
 * A timestamp earlier than the current virtual time is reported and the
 * frame is given at the current time (time never goes back). A jump back of
 * more than SEGMENT_BACK_US (1 s: a logger that restarted) starts a new
 * segment instead: the log's time from there on is re-based onto the
 * current virtual time, so the frames that follow keep their spacing;
 * segments are counted and reported. A gap longer
 * than --max-gap seconds (default 3600) is reported and skipped: the clock
 * jumps, without the ticks in between (a mix of relative and absolute
 * timestamps would otherwise tick for decades).
 *
 * Buses: without --bus every frame of the log is on the firmware's bus 0 (as
 * on a single-bus ECU); with --bus NAME the frames of interface NAME are
 * bus 0 and those of every other interface bus 1, so a two-bus log replays
 * with the calibration's input_bus/output_bus. Frames of a bus the firmware
 * uses neither for input nor output are counted (other_bus), not offered.
 *
 * Output: every frame the ECU sends, as candump -L lines on stdout, named
 * after the bus it was sent on: bus 0 is --bus NAME (or the log's first
 * interface), bus 1 the first other interface of the log ("bus1" until one
 * is seen); --iface-out NAME names every output line instead. The summary
 * goes to stderr.
 * Memory is constant: the log is streamed line by line.
 */
#include <errno.h>
#include <getopt.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "calib.h"
#include "calib_text.h"
#include "candump_log.h"
#include "hal_vbus.h"
#include "json_writer.h"
#include "monitor.h"
#include "replay_summary.h"
#include "sim_commands.h"
#include "squeal_app.h"
#include "squeal_msgs.h"

#define TICK_US 1000U
#define SEGMENT_BACK_US 1000000U /* a jump back beyond this starts a segment */
#define SEGMENT_POINTS_MAX 64U /* rebase points kept for the JSON (memory stays constant) */
#define N_STATES MSG_SQUEAL_STATE_SLOTS /* stable, bistable, unstable, not sliding, fault */
#define N_LEVELS 4U

static const char *const level_names[N_LEVELS] = {
	"none", "advisory", "warning", "critical"
};

typedef struct {
	const char *log_name;
	const char *calib_path;
	const char *iface_out;
	const char *bus_name; /* the log interface that is bus 0; NULL: all */
	uint64_t tail_us;
	uint64_t max_gap_us;
	bool rss;
	const char *summary_json; /* --summary-json FILE|- (replay_summary.h) */
	bool no_output;           /* --no-output: no frame lines, only counts */
} replay_args_t;

/* Where a new segment began: the log line, how far the log's time went
 * back and the virtual time the rest of the log was re-based onto. */
typedef struct {
	uint64_t line_no;
	uint64_t back_us;
	uint64_t at_us;
} segment_point_t;

typedef struct {
	/* lines */
	uint64_t lines;
	uint64_t frames;
	uint64_t comments;
	uint64_t blanks;
	uint64_t dropcount_lines;
	uint64_t dropped;
	uint64_t malformed;
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
	uint64_t now_us;
	uint64_t next_tick_us;
	uint64_t backwards;
	uint64_t segments;         /* new segments after a jump back > 1 s  */
	int64_t rebase_us;         /* added to the log's time (segments)    */
	segment_point_t segment_at[SEGMENT_POINTS_MAX]; /* the first ones */
	uint64_t gaps;
	uint64_t state_us[N_STATES];
	uint8_t state;
	uint8_t warning;
	uint64_t into_level[N_LEVELS];
	uint64_t transitions[N_STATES][N_STATES];
	/* output: the name of each bus in the output log */
	char iface[HAL_CAN_BUSES][CANDUMP_IFACE_MAX + 1U];
	bool bus1_named;
	uint64_t out_frames;
	uint64_t out_by_msg[MSG_COUNT + 1U];
	bool out_error;
	bool no_output;
	replay_summary_t *summary; /* NULL without --summary-json */
} replay_t;

static void replay_usage(FILE *f)
{
	fprintf(f,
		"usage: squeal-sim replay LOG|- [--calib FILE] [--bus NAME]\n"
		"         [--iface-out NAME] [--tail-ms MS] [--max-gap S] [--rss]\n"
		"         [--summary-json FILE|-] [--no-output]\n\n"
		"Feeds a candump -L log (a file, or - for stdin) through the firmware in\n"
		"virtual time taken from the log's timestamps, offline. Writes every frame\n"
		"the ECU sends as a candump -L log on stdout, and a summary on stderr:\n"
		"frames read, used, rejected by reason, time in each state, warnings\n"
		"raised, state changes. Malformed lines are reported as LOG:LINE: message\n"
		"and skipped. The same log gives the same output, byte for byte.\n\n"
		"  --calib FILE     calibration text file (docs/calib-example.txt)\n"
		"  --bus NAME       the log's interface NAME is the firmware's bus 0, every\n"
		"                   other interface bus 1 (calibration input_bus and\n"
		"                   output_bus pick); default: all frames on bus 0\n"
		"  --iface-out NAME interface name of the output lines (default: the\n"
		"                   output bus's: --bus NAME or the log's first\n"
		"                   interface for bus 0, another of its interfaces for 1)\n"
		"  --tail-ms MS     run on after the last frame (default 100)\n"
		"  --max-gap S      a gap between frames longer than S seconds is\n"
		"                   skipped instead of simulated (default 3600)\n"
		"  --rss            add the peak resident memory (VmHWM) to the summary\n"
		"  --summary-json FILE  also write the summary as one JSON document, with\n"
		"                   the episodes (time spans in one state per corner) and\n"
		"                   the time per (v0, force) cell; - for stdout (needs\n"
		"                   --no-output)\n"
		"  --no-output      do not write the ECU's frames (only count them)\n\n"
		"CAN FD and XL frames are counted as unsupported (classic controller).\n"
		"Exit status: 0 done (also with malformed lines), 1 input/calibration\n"
		"error, 2 bad usage.\n");
}

static int parse_u64(const char *flag, const char *text, uint64_t max, uint64_t *out)
{
	char *end = NULL;
	unsigned long long v;

	errno = 0;
	v = strtoull(text, &end, 10);
	if ((end == text) || (*end != '\0') || (errno != 0) || (text[0] == '-') || (v > max)) {
		fprintf(stderr, "squeal-sim replay: %s needs a whole number 0..%llu, got '%s'\n",
			flag, (unsigned long long)max, text);
		return -1;
	}
	*out = v;
	return 0;
}

static int replay_parse(int argc, char **argv, replay_args_t *a)
{
	enum { OPT_CALIB = 256, OPT_IFACE_OUT, OPT_BUS, OPT_TAIL, OPT_GAP, OPT_RSS, OPT_HELP,
	       OPT_SUMMARY_JSON, OPT_NO_OUTPUT };
	static const struct option options[] = {
		{ "calib", required_argument, NULL, OPT_CALIB },
		{ "bus", required_argument, NULL, OPT_BUS },
		{ "iface-out", required_argument, NULL, OPT_IFACE_OUT },
		{ "tail-ms", required_argument, NULL, OPT_TAIL },
		{ "max-gap", required_argument, NULL, OPT_GAP },
		{ "rss", no_argument, NULL, OPT_RSS },
		{ "summary-json", required_argument, NULL, OPT_SUMMARY_JSON },
		{ "no-output", no_argument, NULL, OPT_NO_OUTPUT },
		{ "help", no_argument, NULL, OPT_HELP },
		{ NULL, 0, NULL, 0 },
	};
	uint64_t v;
	int c;

	a->tail_us = 100000U;
	a->max_gap_us = 3600ULL * 1000000ULL;
	optind = 1;
	while ((c = getopt_long(argc, argv, "h", options, NULL)) != -1) {
		switch (c) {
		case OPT_CALIB:
			a->calib_path = optarg;
			break;
		case OPT_IFACE_OUT:
		case OPT_BUS:
			if ((strlen(optarg) == 0U) || (strlen(optarg) > CANDUMP_IFACE_MAX) ||
			    (strpbrk(optarg, " \t\n") != NULL)) {
				fprintf(stderr, "squeal-sim replay: %s needs 1..%u characters without blanks\n",
					(c == OPT_BUS) ? "--bus" : "--iface-out", CANDUMP_IFACE_MAX);
				return 2;
			}
			if (c == OPT_BUS) {
				a->bus_name = optarg;
			} else {
				a->iface_out = optarg;
			}
			break;
		case OPT_TAIL:
			if (parse_u64("--tail-ms", optarg, 86400000ULL, &v) != 0) {
				return 2;
			}
			a->tail_us = v * 1000U;
			break;
		case OPT_GAP:
			if (parse_u64("--max-gap", optarg, 31536000ULL, &v) != 0) {
				return 2;
			}
			a->max_gap_us = v * 1000000U;
			break;
		case OPT_RSS:
			a->rss = true;
			break;
		case OPT_SUMMARY_JSON:
			a->summary_json = optarg;
			break;
		case OPT_NO_OUTPUT:
			a->no_output = true;
			break;
		case OPT_HELP:
		case 'h':
			replay_usage(stdout);
			return 1;
		default:
			replay_usage(stderr);
			return 2;
		}
	}
	if (optind + 1 != argc) {
		fprintf(stderr, "squeal-sim replay: give exactly one LOG (or - for stdin)\n");
		replay_usage(stderr);
		return 2;
	}
	a->log_name = argv[optind];
	if ((a->summary_json != NULL) && (strcmp(a->summary_json, "-") == 0) && !a->no_output) {
		fprintf(stderr, "squeal-sim replay: --summary-json - shares stdout with the frames: add --no-output\n");
		return 2;
	}
	return 0;
}

/* ---- output ------------------------------------------------------------------ */

static void emit(replay_t *r, uint8_t bus, const hal_can_frame_t *hf)
{
	candump_frame_t f;
	char line[CANDUMP_FORMAT_MAX + 2U];
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
	memset(&f, 0, sizeof(f));
	f.t_ns = hf->timestamp_us * 1000U;
	memcpy(f.iface, r->iface[bus], sizeof(f.iface));
	f.kind = ((hf->flags & HAL_CAN_FLAG_RTR) != 0U) ? CANDUMP_KIND_RTR : CANDUMP_KIND_CLASSIC;
	f.ext = (hf->flags & HAL_CAN_FLAG_EXT) != 0U;
	f.id = hf->id;
	f.len = hf->dlc;
	memcpy(f.data, hf->data, HAL_CAN_MAX_DLEN);
	n = candump_format_frame(&f, true, line, sizeof(line));
	if (n < 0) {
		r->out_error = true;
		return;
	}
	if (fwrite(line, 1U, (size_t)n, stdout) != (size_t)n) {
		r->out_error = true;
	}
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

/* Move the virtual clock to t_us (never back); the time in between counts
 * for the state that held during it. */
static void set_time(replay_t *r, uint64_t t_us)
{
	if (t_us > r->now_us) {
		r->state_us[msg_squeal_state_slot(r->state)] += t_us - r->now_us;
		r->now_us = t_us;
		hal_vbus_set_time_us(t_us);
	}
}

/* Every 1 ms tick up to and including t_us. */
static void run_until(replay_t *r, uint64_t t_us)
{
	while (r->next_tick_us <= t_us) {
		set_time(r, r->next_tick_us);
		(void)squeal_app_poll();
		after_poll(r);
		r->next_tick_us += TICK_US;
	}
	set_time(r, t_us);
}

static void start(replay_t *r, const candump_frame_t *f, const replay_args_t *a)
{
	const monitor_t *m;

	r->started = true;
	r->t0_us = f->t_ns / 1000U;
	r->now_us = r->t0_us;
	r->next_tick_us = r->t0_us;
	hal_vbus_set_time_us(r->t0_us);
	if (a->iface_out != NULL) {
		(void)snprintf(r->iface[0], sizeof(r->iface[0]), "%s", a->iface_out);
		(void)snprintf(r->iface[1], sizeof(r->iface[1]), "%s", a->iface_out);
		r->bus1_named = true;
	} else {
		(void)snprintf(r->iface[0], sizeof(r->iface[0]), "%s",
			       (a->bus_name != NULL) ? a->bus_name : f->iface);
		(void)snprintf(r->iface[1], sizeof(r->iface[1]), "%s", "bus1");
	}
	(void)squeal_app_init();
	m = squeal_app_monitor();
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

/* The firmware bus of a log frame (see the top of this file). */
static uint8_t bus_of_frame(replay_t *r, const candump_frame_t *f, const replay_args_t *a)
{
	if ((a->bus_name == NULL) || (strcmp(f->iface, a->bus_name) == 0)) {
		return 0U;
	}
	if (!r->bus1_named) {
		(void)snprintf(r->iface[1], sizeof(r->iface[1]), "%s", f->iface);
		r->bus1_named = true;
	}
	return 1U;
}

static void give_frame(replay_t *r, const candump_frame_t *f, const replay_args_t *a)
{
	const calib_t *cal = squeal_app_monitor()->cal;
	const uint8_t bus = bus_of_frame(r, f, a);
	hal_can_frame_t hf;
	int rc;

	if ((bus != cal->input_bus) && (bus != cal->output_bus)) {
		r->other_bus++; /* a bus the firmware does not use */
		return;
	}

	switch (f->kind) {
	case CANDUMP_KIND_FD:
		r->unsupported_fd++;
		return;
	case CANDUMP_KIND_XL:
		r->unsupported_xl++;
		return;
	default:
		break;
	}
	memset(&hf, 0, sizeof(hf));
	hf.id = f->id;
	hf.dlc = (f->len > HAL_CAN_MAX_DLEN) ? (uint8_t)HAL_CAN_MAX_DLEN : f->len;
	if (f->kind == CANDUMP_KIND_RTR) {
		hf.flags |= HAL_CAN_FLAG_RTR;
	} else {
		memcpy(hf.data, f->data, hf.dlc);
	}
	if (f->kind == CANDUMP_KIND_ERROR) {
		hf.flags |= HAL_CAN_FLAG_ERR;
	} else if (f->ext) {
		hf.flags |= HAL_CAN_FLAG_EXT;
	}
	hf.timestamp_us = r->now_us; /* arrives now */
	rc = hal_vbus_rx_push(bus, &hf);
	if (rc == SQ_ENOENT) {
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
	(void)squeal_app_poll();
	after_poll(r);
}

static void on_frame(replay_t *r, const candump_frame_t *f, const replay_args_t *a,
		     uint64_t line_no)
{
	uint64_t t_us;

	if (!r->started) {
		start(r, f, a);
	}
	t_us = (uint64_t)((int64_t)(f->t_ns / 1000U) + r->rebase_us);
	if ((t_us < r->now_us) && (r->now_us - t_us > SEGMENT_BACK_US)) {
		const uint64_t back = r->now_us - t_us;

		if (r->segments < SEGMENT_POINTS_MAX) {
			r->segment_at[r->segments] = (segment_point_t){ line_no, back, r->now_us };
		}
		r->segments++;
		r->rebase_us += (int64_t)back;
		fprintf(stderr, "%s:%llu: timestamp goes back by %llu.%06llu s: new segment %llu, log time re-based\n",
			a->log_name, (unsigned long long)line_no,
			(unsigned long long)(back / 1000000U), (unsigned long long)(back % 1000000U),
			(unsigned long long)(r->segments + 1U));
		t_us = r->now_us;
	} else if (t_us < r->now_us) {
		const uint64_t back = r->now_us - t_us;

		r->backwards++;
		fprintf(stderr, "%s:%llu: timestamp goes back by %llu.%06llu s: frame given at the current time\n",
			a->log_name, (unsigned long long)line_no,
			(unsigned long long)(back / 1000000U), (unsigned long long)(back % 1000000U));
		t_us = r->now_us;
	} else if (t_us - r->now_us > a->max_gap_us) {
		const uint64_t gap = t_us - r->now_us;

		r->gaps++;
		fprintf(stderr, "%s:%llu: gap of %llu.%06llu s > --max-gap: skipped, not simulated\n",
			a->log_name, (unsigned long long)line_no,
			(unsigned long long)(gap / 1000000U), (unsigned long long)(gap % 1000000U));
		/* keep the tick grid's phase */
		r->next_tick_us += ((t_us - r->next_tick_us) / TICK_US) * TICK_US;
		set_time(r, t_us);
	}
	run_until(r, t_us);
	give_frame(r, f, a);
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

static void summary(const replay_t *r, const replay_args_t *a)
{
	FILE *o = stderr;
	const monitor_t *m = squeal_app_monitor();
	const input_counters_t *sp = &m->speed.count;
	const input_counters_t *fo = &m->force.count;
	unsigned i;
	unsigned j;
	uint64_t changes = 0U;

	fprintf(o, "replay summary: %s\n", a->log_name);
	fprintf(o, "  lines                 %llu (frames %llu, comments %llu, blank %llu, dropcount %llu, malformed %llu)\n",
		(unsigned long long)r->lines, (unsigned long long)r->frames,
		(unsigned long long)r->comments, (unsigned long long)r->blanks,
		(unsigned long long)r->dropcount_lines, (unsigned long long)r->malformed);
	if (!r->started) {
		fprintf(o, "  no frames: the firmware was not started\n");
		return;
	}
	fprintf(o, "  virtual_time_s        ");
	print_us(o, r->now_us - r->t0_us);
	fprintf(o, " (from ");
	print_us(o, r->t0_us);
	fprintf(o, ", tail %llu ms)\n", (unsigned long long)(a->tail_us / 1000U));
	fprintf(o, "  frames_read           %llu\n", (unsigned long long)r->frames);
	fprintf(o, "  frames_used           %llu (DiscSpeed %u, PadForce %u)\n",
		(unsigned long long)sp->used + fo->used, sp->used, fo->used);
	for (i = 0U; i < squeal_app_corner_count(); i++) {
		const monitor_t *c = squeal_app_corner(i);
		static const char *const pos[4] = { "FL", "FR", "RL", "RR" };

		fprintf(o, "  corner %s              inputs used speed %u force %u, implausible %u/%u, final %s\n",
			pos[c->corner.pos & 3U], c->speed.count.used, c->force.count.used,
			c->speed.count.implausible, c->force.count.implausible,
			rs_state_name(msg_squeal_state_slot(c->state)));
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
	fprintf(o, "    e2e_wrong_crc       %llu (DiscSpeed %u, PadForce %u)\n",
		(unsigned long long)sp->e2e_wrong_crc + fo->e2e_wrong_crc, sp->e2e_wrong_crc,
		fo->e2e_wrong_crc);
	fprintf(o, "    e2e_wrong_sequence  %llu (DiscSpeed %u, PadForce %u)\n",
		(unsigned long long)sp->e2e_wrong_sequence + fo->e2e_wrong_sequence,
		sp->e2e_wrong_sequence, fo->e2e_wrong_sequence);
	fprintf(o, "    repeated            %llu (DiscSpeed %u, PadForce %u)\n",
		(unsigned long long)sp->e2e_repeated + fo->e2e_repeated, sp->e2e_repeated,
		fo->e2e_repeated);
	fprintf(o, "    implausible         %llu (DiscSpeed %u, PadForce %u)\n",
		(unsigned long long)sp->implausible + fo->implausible, sp->implausible,
		fo->implausible);
	fprintf(o, "    bad_dlc             %llu (DiscSpeed %u, PadForce %u)\n",
		(unsigned long long)sp->bad_dlc + fo->bad_dlc, sp->bad_dlc, fo->bad_dlc);
	fprintf(o, "    error_frames        %u\n", m->count.error_frames);
	fprintf(o, "    remote_or_extended  %u\n", m->count.rtr_or_ext);
	fprintf(o, "    rx_overflow         %llu\n", (unsigned long long)r->rx_overflow);
	if (a->bus_name != NULL) {
		fprintf(o, "    other_bus           %llu\n", (unsigned long long)r->other_bus);
	}
	fprintf(o, "  e2e_frames_lost       %llu (counter gaps: DiscSpeed %u, PadForce %u)\n",
		(unsigned long long)sp->e2e_lost + fo->e2e_lost, sp->e2e_lost, fo->e2e_lost);
	fprintf(o, "  stale_events          %llu (DiscSpeed %u, PadForce %u)\n",
		(unsigned long long)sp->stale_events + fo->stale_events, sp->stale_events,
		fo->stale_events);
	fprintf(o, "  candump_dropped       %llu\n", (unsigned long long)r->dropped);
	fprintf(o, "  time_backwards        %llu\n", (unsigned long long)r->backwards);
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
	if (squeal_app_init_status() != SQ_OK) {
		fprintf(o, "  firmware_init         error %d (running with defaults)\n",
			squeal_app_init_status());
	}
	if (a->rss) {
		fprintf(o, "  peak_rss_kb           %ld\n", vm_hwm_kb());
	}
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

/* Everything after the episodes: the caller began the object with "log"
 * and the episodes (replay_summary_init); this closes it. */
static void summary_json(json_writer_t *w, const replay_t *r, const replay_args_t *a)
{
	const monitor_t *m = squeal_app_monitor();
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
	json_kv_u64(w, "gaps_skipped", r->gaps);
	json_key(w, "state_time_s");
	json_begin_object(w);
	for (i = 0U; i < N_STATES; i++) {
		json_kv_seconds(w, rs_state_name(i), r->state_us[i]);
	}
	json_end_object(w);
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
	json_key(w, "output_written");
	json_bool(w, !a->no_output);
	json_key(w, "firmware_init_status");
	json_i64(w, r->started ? squeal_app_init_status() : 0);
	if (a->rss) {
		json_key(w, "peak_rss_kb");
		json_i64(w, vm_hwm_kb());
	}
	json_end_object(w);
}

/* Opens --summary-json's file and starts the document; NULL on error. */
static FILE *summary_json_open(json_writer_t *w, replay_summary_t *rs, const replay_args_t *a)
{
	FILE *f = (strcmp(a->summary_json, "-") == 0) ? stdout : fopen(a->summary_json, "w");

	if (f == NULL) {
		fprintf(stderr, "squeal-sim replay: cannot write %s: %s\n", a->summary_json,
			strerror(errno));
		return NULL;
	}
	json_writer_init(w, f);
	json_begin_object(w);
	json_kv_string(w, "format", "squeal-replay-summary");
	json_kv_u64(w, "version", 1U);
	json_kv_string(w, "log", a->log_name);
	replay_summary_init(rs, w);
	return f;
}

/* Ends the document; 0, or -1 when it could not be written whole. */
static int summary_json_close(json_writer_t *w, FILE *f, const replay_t *r, const replay_args_t *a)
{
	int rc = 0;

	summary_json(w, r, a);
	if (!json_writer_done(w) || (fflush(f) != 0)) {
		rc = -1;
	}
	if ((f != stdout) && (fclose(f) != 0)) {
		rc = -1;
	}
	if (rc != 0) {
		fprintf(stderr, "squeal-sim replay: error writing %s\n", a->summary_json);
	}
	return rc;
}

/* ---- main ------------------------------------------------------------------------ */

static int load_calib(const char *path)
{
	calib_t cal;
	uint8_t block[CALIB_BLOCK_LEN];
	char err[256];

	if (calib_text_load(path, &cal, err, sizeof(err)) != SQ_OK) {
		fprintf(stderr, "squeal-sim replay: %s\n", err);
		return -1;
	}
	if ((calib_encode(&cal, block, sizeof(block)) != SQ_OK) ||
	    (hal_vbus_calib_store(block, sizeof(block)) != SQ_OK)) {
		fprintf(stderr, "squeal-sim replay: %s: cannot store the calibration\n", path);
		return -1;
	}
	return 0;
}

int cmd_replay(int argc, char **argv)
{
	static candump_reader_t reader; /* 70 kB: not on the stack */
	static char outbuf[1U << 16];
	static replay_t r;
	static replay_summary_t rs; /* 820 kB of occupancy cells: not on the stack */
	json_writer_t jw;
	FILE *json_f = NULL;
	int json_rc = 0;
	replay_args_t a;
	candump_frame_t f;
	const char *line;
	size_t len;
	bool too_long;
	FILE *in;
	int rc;

	memset(&a, 0, sizeof(a));
	memset(&r, 0, sizeof(r));
	rc = replay_parse(argc, argv, &a);
	if (rc != 0) {
		return (rc == 1) ? 0 : rc;
	}
	if (strcmp(a.log_name, "-") == 0) {
		in = stdin;
		a.log_name = "<stdin>";
	} else {
		in = fopen(a.log_name, "rb");
		if (in == NULL) {
			fprintf(stderr, "squeal-sim replay: cannot open %s: %s\n", a.log_name,
				strerror(errno));
			return 1;
		}
	}
	(void)setvbuf(stdout, outbuf, _IOFBF, sizeof(outbuf));
	hal_vbus_reset();
	if ((a.calib_path != NULL) && (load_calib(a.calib_path) != 0)) {
		if (in != stdin) {
			(void)fclose(in);
		}
		return 1;
	}
	r.no_output = a.no_output;
	if (a.summary_json != NULL) {
		json_f = summary_json_open(&jw, &rs, &a);
		if (json_f == NULL) {
			if (in != stdin) {
				(void)fclose(in);
			}
			return 1;
		}
		r.summary = &rs;
	}
	candump_reader_init(&reader, in);
	for (;;) {
		candump_err_t err = CANDUMP_OK;
		size_t col = 0U;

		rc = candump_reader_next(&reader, &line, &len, &too_long);
		if (rc <= 0) {
			break;
		}
		r.lines++;
		if (too_long) {
			r.malformed++;
			fprintf(stderr, "%s:%llu: %s\n", a.log_name,
				(unsigned long long)reader.line_no,
				candump_strerror(CANDUMP_ERR_TOO_LONG));
			continue;
		}
		switch (candump_parse_line(line, len, &f, &err, &col)) {
		case CANDUMP_LINE_FRAME:
			r.frames++;
			on_frame(&r, &f, &a, reader.line_no);
			break;
		case CANDUMP_LINE_BLANK:
			r.blanks++;
			break;
		case CANDUMP_LINE_COMMENT:
			r.comments++;
			break;
		case CANDUMP_LINE_DROPCOUNT:
			r.dropcount_lines++;
			r.dropped += f.dropped;
			break;
		default:
			r.malformed++;
			fprintf(stderr, "%s:%llu: %s (column %zu)\n", a.log_name,
				(unsigned long long)reader.line_no, candump_strerror(err), col + 1U);
			break;
		}
	}
	if (rc < 0) {
		fprintf(stderr, "squeal-sim replay: %s: read error\n", a.log_name);
	}
	if (in != stdin) {
		(void)fclose(in);
	}
	if (r.started) {
		run_until(&r, r.now_us + a.tail_us);
	}
	if (json_f != NULL) {
		json_rc = summary_json_close(&jw, json_f, &r, &a);
	}
	if ((fflush(stdout) != 0) || r.out_error) {
		fprintf(stderr, "squeal-sim replay: error writing the output\n");
		summary(&r, &a);
		return 1;
	}
	summary(&r, &a);
	return ((rc < 0) || (json_rc != 0)) ? 1 : 0;
}
