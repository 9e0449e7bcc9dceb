/* SPDX-License-Identifier: MIT */
/*
 * squeal-sim plant: the sensors of a brake on a test rig. Sends DiscSpeed and
 * PadForce with real E2E counters and CRCs at the DBC's periods, from a
 * built-in scenario or a scenario file, on a SocketCAN interface in real time
 * or (--log) as a candump -L log in virtual time. Faults can be injected on
 * the way (drop, delay, corrupt CRC, frozen counter), reproducibly (--seed).
 */
#include <errno.h>
#include <inttypes.h>
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "calib.h"
#include "calib_text.h"
#include "candump_hal.h"
#include "candump_log.h"
#include "cli_args.h"
#include "e2e_p01.h"
#include "hal.h"
#include "hal_linux.h"
#include "plant_scenario.h"
#include "plant_vehicle.h"
#include "sim_commands.h"
#include "sq_status.h"
#include "squeal_msgs.h"

#define NS_PER_S 1000000000ULL

typedef struct {
	const char *iface;
	const char *scenario;
	const char *log_path;
	const char *calib_path;
	double v0_mps;
	double force_n;
	bool have_v0;
	bool have_force;
	double duration_s;     /* < 0: the scenario's own length */
	double drop_p;
	double delay_ms;
	double corrupt_p;
	double freeze_after_s; /* < 0: never */
	uint64_t seed;
	double rate_hz;
	bool quiet;
} plant_args_t;

/* One sender (DiscSpeed or PadForce, or one frame of an input map). */
typedef struct {
	const char *name;
	uint32_t id;
	int vframe;             /* index into plant_t.vframes, -1: legacy    */
	uint64_t period_ns;
	e2e_p01_config_t e2e;
	e2e_p01_tx_t tx;
	uint64_t next_ns;       /* nominal time of the next frame            */
	uint64_t offset_ns;
	uint64_t last_emit_ns;  /* emission times of one sender stay in order */
	bool has_pending;
	uint64_t pending_ns;
	hal_can_frame_t pending;
	/* counts */
	uint64_t made;
	uint64_t sent;
	uint64_t dropped;
	uint64_t corrupted;
	uint64_t frozen;
	uint64_t send_errors;
	uint64_t saturated;
} sender_t;

typedef struct {
	plant_args_t a;
	plant_scenario_t sc;
	calib_t cal;
	uint64_t rng;
	uint64_t period_ns;
	uint64_t end_ns;
	uint32_t n_senders;
	sender_t s[CALIB_MAX_INPUTS];
	plant_vframe_t vframes[CALIB_MAX_INPUTS];
	char vnames[CALIB_MAX_INPUTS][16];
} plant_t;

static plant_t plant; /* large (scenario table): static, not on the stack */

static uint64_t rng_next(uint64_t *x)
{
	/* xorshift64*: small, fast, reproducible from --seed */
	*x ^= *x >> 12;
	*x ^= *x << 25;
	*x ^= *x >> 27;
	return *x * 2685821657736338717ULL;
}

static double rng_uniform(uint64_t *x)
{
	return (double)(rng_next(x) >> 11) * (1.0 / 9007199254740992.0);
}

static int plant_parse(int argc, char **argv, plant_args_t *a)
{
	const cli_opt_t opts[] = {
		CLI_OPT_TEXT("iface", &a->iface, NULL, "IF",
			     "the SocketCAN interface to send on (with --log: only\n"
			     "the name of the log's interface column)"),
		CLI_OPT_TEXT("log", &a->log_path, NULL, "FILE|-",
			     "write a candump -L log in virtual time instead"),
		CLI_OPT_TEXT("scenario", &a->scenario, NULL, "NAME|FILE",
			     "stop, creep, sweep, point or a file (above; required)"),
		CLI_OPT_REAL("v0", &a->v0_mps, &a->have_v0, 0.0, 1000.0, 0U, "MPS",
			     "--scenario point: pad surface speed [m/s]"),
		CLI_OPT_REAL("force", &a->force_n, &a->have_force, 0.0, 1e6, 0U, "N",
			     "--scenario point: pad force [N]"),
		CLI_OPT_REAL("duration", &a->duration_s, NULL, 0.0, 1e7, 0U, "S",
			     "run S seconds (default: the scenario's length;\n"
			     "past its last row the last values hold)"),
		CLI_OPT_REAL("rate-hz", &a->rate_hz, NULL, 0.1, 1e6, 0U, "N",
			     "frames per second of EACH message (default 100:\n"
			     "the DBC period); higher for flood tests"),
		CLI_OPT_TEXT("calib", &a->calib_path, NULL, "FILE",
			     "take identifiers and radii from a calibration\n"
			     "text file (as the ECU's --calib); with an input\n"
			     "map ([input]/[corner] sections) send that vehicle's\n"
			     "frames instead, in its layout and protection, each\n"
			     "at its period (--rate-hz 100 = that period)"),
		CLI_OPT_REAL("drop", &a->drop_p, NULL, 0.0, 1.0, 0U, "P",
			     "lose each frame with probability P (the sender's\n"
			     "counter still advances, as for a frame lost on\n"
			     "the bus)"),
		CLI_OPT_REAL("delay", &a->delay_ms, NULL, 0.0, 60000.0, 0U, "MS",
			     "each frame leaves up to MS ms late (uniform,\n"
			     "order within a message kept): jitter, staleness"),
		CLI_OPT_REAL("corrupt-crc", &a->corrupt_p, NULL, 0.0, 1.0, 0U, "P",
			     "flip CRC bits of a frame with probability P"),
		CLI_OPT_REAL("freeze-counter", &a->freeze_after_s, NULL, 0.0, 1e7, 0U, "S",
			     "from S seconds on the alive counter stops"),
		CLI_OPT_U64("seed", &a->seed, NULL, 0.0, 1e15, 1U, "N",
			    "random seed of the faults (default 1)"),
		CLI_OPT_FLAG("quiet", 0, &a->quiet, "no summary on stderr"),
	};
	const cli_spec_t spec = {
		.cmd = "plant",
		CLI_SPEC_OPTS(opts),
		.synopsis = "squeal-sim plant (--iface IF | --log FILE|-) --scenario NAME|FILE\n"
			    "         [--v0 MPS --force N] [--duration S] [--rate-hz N] [--calib FILE]\n"
			    "         [--drop P] [--delay MS] [--corrupt-crc P] [--freeze-counter AFTER_S]\n"
			    "         [--seed N] [--quiet]",
		.description = "Sends DiscSpeed and PadForce (E2E counter + CRC) every 10 ms each, the\n"
			       "two senders 5 ms apart, following a scenario: in real time on a SocketCAN\n"
			       "interface, or with --log as a candump -L log in virtual time starting at\n"
			       "(0.000000) (no interface needed; --iface then only names the log's\n"
			       "interface column, default vcan0).\n\n"
			       "Scenarios (speeds are vehicle speeds; the disc turns at v / r_w and its\n"
			       "surface at the pad moves at v0 = v r_p / r_w):\n"
			       "  stop    30 m/s -> standstill at 6 m/s^2, 9000 N (6 s)\n"
			       "  creep   slow rolling 1.0 -> 0.4 -> 1.0 m/s at 1500 N (12 s)\n"
			       "  sweep   3, 6, 9, 12 kN, each 10 -> 0.5 -> 10 m/s (32 s)\n"
			       "  point   constant --v0 MPS (pad surface speed, as in classify) and\n"
			       "          --force N (10 s)\n"
			       "  FILE    rows 'time_s speed_mps force_n', linear interpolation, '#'\n"
			       "          comments (see scenarios/)",
		.closing = "Exit status: 0 done (or stopped by SIGINT/SIGTERM), 1 interface or\n"
			   "file error, 2 bad usage.",
	};
	cli_result_t r;
	bool point;

	memset(a, 0, sizeof(*a));
	a->duration_s = -1.0;
	a->freeze_after_s = -1.0;
	a->rate_hz = 100.0;
	a->seed = 1U;
	r = cli_parse(&spec, argc, argv, NULL, NULL);
	if (r != CLI_OK) {
		return (int)r;
	}
	if (a->scenario == NULL) {
		return (int)cli_usage_error(&spec, "--scenario NAME|FILE is required");
	}
	if ((a->iface == NULL) && (a->log_path == NULL)) {
		return (int)cli_usage_error(&spec, "give --iface IF (send) or --log FILE|- (write a log)");
	}
	point = strcmp(a->scenario, "point") == 0;
	if (point && (!a->have_v0 || !a->have_force)) {
		return (int)cli_usage_error(&spec, "--scenario point needs --v0 MPS and --force N");
	}
	if (!point && (a->have_v0 || a->have_force)) {
		return (int)cli_usage_error(&spec, "--v0/--force belong to --scenario point");
	}
	return CLI_OK;
}

/* Saturating raw conversion, counted when the sender had to clamp. */
static uint16_t to_raw(double phys, double per_raw, uint16_t max, uint64_t *sat)
{
	const double r = floor(phys / per_raw + 0.5);

	if (!(r >= 0.0)) {
		(*sat)++;
		return 0U;
	}
	if (r > (double)max) {
		(*sat)++;
		return max;
	}
	return (uint16_t)r;
}

/* Build the frame of sender i at its nominal time; applies the faults. */
static void make_frame(plant_t *p, unsigned int i)
{
	sender_t *s = &p->s[i];
	const double t_s = (double)s->next_ns / (double)NS_PER_S;
	double speed_mps;
	double force_n;
	hal_can_frame_t f;
	uint8_t counter_before;
	int rc;

	plant_scenario_eval(&p->sc, t_s, &speed_mps, &force_n);
	memset(&f, 0, sizeof(f));
	f.id = s->id;
	counter_before = s->tx.counter;
	rc = SQ_OK;
	if (s->vframe >= 0) {
		plant_vehicle_pack(&p->cal, &p->vframes[s->vframe], &s->tx, speed_mps, force_n, &f,
				   &s->saturated);
	} else if (i == 0U) {
		msg_disc_speed_t m = { 0U, 0U, 0U };
		const double r_w_m = (double)p->cal.wheel_radius_um * 1e-6;

		m.disc_speed_radps = to_raw(speed_mps / r_w_m, 0.01,
					    MSG_DISC_SPEED_RADPS_MAX, &s->saturated);
		rc = msg_disc_speed_pack(&m, f.data, &f.dlc);
	} else {
		msg_pad_force_t m = { 0U, 0U, 0U };

		m.pad_force_n = to_raw(force_n, 0.5, MSG_PAD_FORCE_N_MAX, &s->saturated);
		rc = msg_pad_force_pack(&m, f.data, &f.dlc);
	}
	if ((rc != SQ_OK) ||
	    ((s->vframe < 0) && (e2e_p01_protect(&s->e2e, &s->tx, f.data, f.dlc) != SQ_OK))) {
		/* cannot happen with saturated raw values; never send garbage */
		fprintf(stderr, "squeal-sim plant: internal error packing %s\n", s->name);
		exit(1);
	}
	if ((p->a.freeze_after_s >= 0.0) && (t_s >= p->a.freeze_after_s)) {
		/* the sender's counter is stuck: every frame repeats it (the CRC
		 * is right for the stuck counter: a software fault, not noise) */
		s->tx.counter = counter_before;
		s->frozen++;
	}
	s->made++;
	if ((p->a.corrupt_p > 0.0) && (rng_uniform(&p->rng) < p->a.corrupt_p)) {
		f.data[0] ^= (uint8_t)(1U + (rng_next(&p->rng) % 255U));
		s->corrupted++;
	}
	s->pending = f;
	s->pending_ns = s->next_ns;
	if (p->a.delay_ms > 0.0) {
		s->pending_ns += (uint64_t)(rng_uniform(&p->rng) * p->a.delay_ms * 1e6);
	}
	if (s->pending_ns < s->last_emit_ns) {
		s->pending_ns = s->last_emit_ns;
	}
	s->has_pending = true;
	if ((p->a.drop_p > 0.0) && (rng_uniform(&p->rng) < p->a.drop_p)) {
		s->dropped++;
		s->has_pending = false;
	}
	s->next_ns = s->offset_ns + (s->made * s->period_ns);
}

/* Fill both senders' pending frames (while there is scenario time left). */
static void refill(plant_t *p)
{
	unsigned int i;

	for (i = 0U; i < p->n_senders; i++) {
		/* a dropped frame leaves nothing pending: go on to the next */
		while (!p->s[i].has_pending && (p->s[i].next_ns < p->end_ns)) {
			make_frame(p, i);
		}
	}
}

/* The next frame to emit (the earliest; the first sender on a tie), or -1
 * when every sender is done. */
static int next_sender(const plant_t *p)
{
	int best = -1;
	uint32_t i;

	for (i = 0U; i < p->n_senders; i++) {
		if (p->s[i].has_pending &&
		    ((best < 0) || (p->s[i].pending_ns < p->s[best].pending_ns))) {
			best = (int)i;
		}
	}
	return best;
}

static void write_log_line(FILE *out, const char *iface, uint64_t t_ns,
			   const hal_can_frame_t *f)
{
	const uint64_t us = (t_ns + 500U) / 1000U; /* to the nearest microsecond */
	candump_frame_t c;
	char line[CANDUMP_FORMAT_MAX + 2U];
	int n;

	candump_from_hal(f, us * 1000U, iface, &c);
	n = candump_format_frame(&c, true, line, sizeof(line));
	if (n > 0) {
		(void)fwrite(line, 1U, (size_t)n, out);
	}
}

static uint64_t mono_ns(void)
{
	struct timespec ts;

	(void)clock_gettime(CLOCK_MONOTONIC, &ts);
	return (uint64_t)ts.tv_sec * NS_PER_S + (uint64_t)ts.tv_nsec;
}

static void sleep_until_ns(uint64_t t_ns)
{
	struct timespec ts;

	ts.tv_sec = (time_t)(t_ns / NS_PER_S);
	ts.tv_nsec = (long)(t_ns % NS_PER_S);
	/* EINTR (a signal): the caller checks the stop flag */
	(void)clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, NULL);
}

static int plant_setup(plant_t *p, int argc, char **argv)
{
	char err[300];
	int rc = plant_parse(argc, argv, &p->a);
	double v_vehicle = 0.0;
	unsigned int i;

	if (rc != CLI_OK) {
		return cli_exit_status((cli_result_t)rc);
	}
	calib_default(&p->cal);
	if ((p->a.calib_path != NULL) &&
	    (calib_text_load(p->a.calib_path, &p->cal, err, sizeof(err)) != SQ_OK)) {
		fprintf(stderr, "squeal-sim plant: %s\n", err);
		return 1;
	}
	if (p->a.have_v0) {
		v_vehicle = p->a.v0_mps * (double)p->cal.wheel_radius_um /
			    (double)p->cal.pad_radius_um;
	}
	if (plant_scenario_builtin(p->a.scenario, v_vehicle, p->a.force_n, &p->sc) != 0) {
		if (plant_scenario_load(p->a.scenario, &p->sc, err, sizeof(err)) != 0) {
			if (strchr(p->a.scenario, '/') == NULL &&
			    strchr(p->a.scenario, '.') == NULL) {
				fprintf(stderr, "squeal-sim plant: unknown scenario '%s' (stop, creep, sweep, point, or a file)\n",
					p->a.scenario);
			} else {
				fprintf(stderr, "squeal-sim plant: %s\n", err);
			}
			return 1;
		}
	}
	p->period_ns = (uint64_t)llround(1e9 / p->a.rate_hz);
	if (p->period_ns < 2U) {
		p->period_ns = 2U;
	}
	p->end_ns = (uint64_t)llround(((p->a.duration_s >= 0.0) ? p->a.duration_s :
				       plant_scenario_end_s(&p->sc)) * 1e9);
	/* a zero seed would stall xorshift */
	p->rng = (p->a.seed * 0x9E3779B97F4A7C15ULL) ^ 0xD1B54A32D192ED03ULL;
	if (p->rng == 0U) {
		p->rng = 1U;
	}
	memset(p->s, 0, sizeof(p->s));
	p->n_senders = plant_vehicle_frames(&p->cal, p->vframes);
	for (i = 0U; i < p->n_senders; i++) {
		if (p->vframes[i].dlc > HAL_CAN_MAX_DLEN) {
			fprintf(stderr, "squeal-sim plant: message 0x%" PRIX32 " has %u bytes, this build's CAN frames hold %u\n",
				p->vframes[i].id, p->vframes[i].dlc, (unsigned)HAL_CAN_MAX_DLEN);
			return 1;
		}
	}
	if (p->n_senders > 0U) {
		/* a vehicle layout: one sender per frame, at its inputs' period
		 * (--rate-hz scales it: 100 Hz is each frame's own period) */
		for (i = 0U; i < p->n_senders; i++) {
			sender_t *s = &p->s[i];

			snprintf(p->vnames[i], sizeof(p->vnames[i]), "frame%u", i);
			s->name = p->vnames[i];
			s->id = p->vframes[i].id;
			s->vframe = (int)i;
			s->period_ns = (uint64_t)llround((double)p->vframes[i].period_ms * 1e6 *
							 100.0 / p->a.rate_hz);
			if (s->period_ns < 2U) {
				s->period_ns = 2U;
			}
			s->offset_ns = (s->period_ns * i) / p->n_senders;
			e2e_p01_tx_init(&s->tx);
			s->next_ns = s->offset_ns;
		}
		return -1;
	}
	p->n_senders = 2U;
	p->s[0].name = "DiscSpeed";
	p->s[0].id = p->cal.disc_speed_id;
	p->s[0].e2e.data_id = MSG_DISC_SPEED_DATA_ID;
	p->s[0].e2e.data_len = MSG_DISC_SPEED_DLC;
	p->s[1].name = "PadForce";
	p->s[1].id = p->cal.pad_force_id;
	p->s[1].e2e.data_id = MSG_PAD_FORCE_DATA_ID;
	p->s[1].e2e.data_len = MSG_PAD_FORCE_DLC;
	p->s[1].offset_ns = p->period_ns / 2U; /* two senders, half a period apart */
	for (i = 0U; i < 2U; i++) {
		p->s[i].vframe = -1;
		p->s[i].period_ns = p->period_ns;
		p->s[i].e2e.max_delta_counter = p->cal.e2e_max_delta_counter;
		e2e_p01_tx_init(&p->s[i].tx);
		p->s[i].next_ns = p->s[i].offset_ns;
	}
	return -1; /* go on */
}

static void plant_summary(const plant_t *p, double wall_s, bool stopped)
{
	unsigned int i;

	if (p->a.quiet) {
		return;
	}
	fprintf(stderr, "squeal-sim plant: scenario %s, %.3f s of scenario time%s",
		p->sc.name, (double)p->end_ns / 1e9, stopped ? " (stopped early)" : "");
	if (wall_s > 0.0) {
		fprintf(stderr, ", %.3f s wall time", wall_s);
	}
	fprintf(stderr, "\n");
	for (i = 0U; i < p->n_senders; i++) {
		const sender_t *s = &p->s[i];

		fprintf(stderr, "  %-9s id 0x%03" PRIX32 ": made %" PRIu64 ", sent %" PRIu64
			", dropped %" PRIu64 ", corrupted %" PRIu64 ", frozen %" PRIu64
			", send errors %" PRIu64 ", saturated %" PRIu64 "\n",
			s->name, s->id, s->made, s->sent, s->dropped, s->corrupted,
			s->frozen, s->send_errors, s->saturated);
	}
	if (wall_s > 0.0) {
		uint64_t sent = 0U;

		for (i = 0U; i < p->n_senders; i++) {
			sent += p->s[i].sent;
		}
		fprintf(stderr, "  rate: %.0f frames/s in all\n", (double)sent / wall_s);
	}
}

static int run_log(plant_t *p)
{
	FILE *out = stdout;
	const char *iface = (p->a.iface != NULL) ? p->a.iface : "vcan0";
	int n;

	if (strcmp(p->a.log_path, "-") != 0) {
		out = fopen(p->a.log_path, "w");
		if (out == NULL) {
			fprintf(stderr, "squeal-sim plant: %s: %s\n", p->a.log_path, strerror(errno));
			return 1;
		}
	}
	for (;;) {
		refill(p);
		n = next_sender(p);
		if (n < 0) {
			break;
		}
		write_log_line(out, iface, p->s[n].pending_ns, &p->s[n].pending);
		p->s[n].last_emit_ns = p->s[n].pending_ns;
		p->s[n].has_pending = false;
		p->s[n].sent++;
	}
	if ((fflush(out) != 0) || ferror(out) || ((out != stdout) && (fclose(out) != 0))) {
		fprintf(stderr, "squeal-sim plant: writing %s failed\n", p->a.log_path);
		return 1;
	}
	plant_summary(p, 0.0, false);
	return 0;
}

static volatile bool plant_stop;

static int run_live(plant_t *p)
{
	uint64_t start_ns;
	int n;

	if (hal_linux_install_signal_handlers(&plant_stop) != SQ_OK) {
		fprintf(stderr, "squeal-sim plant: %s\n", hal_linux_strerror());
		return 1;
	}
	if (hal_linux_open(0U, p->a.iface, NULL) != SQ_OK) {
		fprintf(stderr, "squeal-sim plant: %s\n", hal_linux_strerror());
		return 1;
	}
	/* a sender: receive nothing (the socket queue would only fill up) */
	(void)hal_can_set_rx_filter(0U, NULL, 0U);
	start_ns = mono_ns();
	while (!plant_stop) {
		int rc;

		refill(p);
		n = next_sender(p);
		if (n < 0) {
			break;
		}
		if (mono_ns() < start_ns + p->s[n].pending_ns) {
			/* behind schedule (a flood): no sleep call at all */
			sleep_until_ns(start_ns + p->s[n].pending_ns);
		}
		if (plant_stop) {
			break;
		}
		rc = hal_can_send(0U, &p->s[n].pending);
		if (rc == SQ_OK) {
			p->s[n].sent++;
		} else {
			p->s[n].send_errors++;
		}
		p->s[n].last_emit_ns = p->s[n].pending_ns;
		p->s[n].has_pending = false;
	}
	plant_summary(p, (double)(mono_ns() - start_ns) / 1e9, plant_stop);
	hal_linux_close();
	return 0;
}

int cmd_plant(int argc, char **argv)
{
	const int rc = plant_setup(&plant, argc, argv);

	if (rc >= 0) {
		return rc;
	}
	if (plant.a.log_path != NULL) {
		return run_log(&plant);
	}
	return run_live(&plant);
}
