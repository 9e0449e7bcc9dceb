/* SPDX-License-Identifier: MIT */
/*
 * squeal-sim ecu: the unchanged firmware (squeal_app) on a SocketCAN
 * interface in real time, through hal/linux.
 *
 * --calib FILE (text, calib_text.h) is checked here, encoded into the
 * firmware's binary block (calib_encode: magic, version, CRC-32) and written
 * to a private temporary file that becomes the HAL's calibration storage, so
 * the firmware loads it exactly as it would load its flash block on the ECU
 * (and a bad block would take the same fallback path). The file is removed
 * at exit.
 *
 * The loop is squeal_main()'s (init, then poll + hal_idle_until until
 * stopped), written out here so the state can be followed after every poll
 * for --verbose and the exit summary.
 */
#include <errno.h>
#include <inttypes.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "calib.h"
#include "calib_text.h"
#include "cli_args.h"
#include "hal.h"
#include "hal_linux.h"
#include "monitor.h"
#include "sim_commands.h"
#include "sq_status.h"
#include "squeal_app.h"
#include "squeal_model.h"

typedef struct {
	const char *iface;
	const char *out_iface; /* bus 1: the outputs go there (output_bus 1) */
	bool listen_only;      /* the input bus is listen-only              */
	const char *calib_path;
	bool verbose;
	double duration_s; /* < 0: until SIGINT/SIGTERM */
	int rcvbuf_bytes;  /* 0: the kernel's default */
} ecu_args_t;

static volatile bool ecu_stop;
static char ecu_calib_tmp[64];

static int ecu_parse(int argc, char **argv, ecu_args_t *a)
{
	uint32_t rcvbuf = 0U;
	const cli_opt_t opts[] = {
		CLI_OPT_TEXT("iface", &a->iface, NULL, "IF",
			     "the CAN interface (required): bus 0, the inputs"),
		CLI_OPT_TEXT("out-iface", &a->out_iface, NULL, "IF2",
			     "a second interface, bus 1: the outputs go there\n"
			     "(calibration output_bus = 1)"),
		CLI_OPT_FLAG("listen-only", 0, &a->listen_only,
			     "never send on the input bus (input_listen_only = yes);\n"
			     "set the interface itself listen-only too: ip link set\n"
			     "can0 type can listen-only on (no ACK, no error frames)"),
		CLI_OPT_TEXT("calib", &a->calib_path, NULL, "FILE",
			     "calibration text file (docs/calib-example.txt lists\n"
			     "every key); a bad file is refused with its line number"),
		CLI_OPT_REAL("duration", &a->duration_s, NULL, 0.0, 1e7, 0U, "S",
			     "stop by itself after S seconds"),
		CLI_OPT_U32("rcvbuf", &rcvbuf, NULL, 0.0, 268435456.0, "BYTES",
			    "socket receive buffer (SO_RCVBUF; the kernel caps it\n"
			    "at net.core.rmem_max): depth for input floods"),
		CLI_OPT_FLAG("verbose", 'v', &a->verbose,
			     "print every state / warning level change on stderr"),
	};
	const cli_spec_t spec = {
		.cmd = "ecu",
		CLI_SPEC_OPTS(opts),
		.synopsis = "squeal-sim ecu --iface IF [--out-iface IF2] [--listen-only]\n"
			    "         [--calib FILE] [--duration S] [--rcvbuf BYTES] [--verbose]",
		.description = "Runs the monitor firmware on a SocketCAN interface (vcan0, can0, ...) in\n"
			       "real time: reads DiscSpeed/PadForce, sends SquealStatus, SquealDetail,\n"
			       "SquealDetail2 and SquealDiag, until SIGINT or SIGTERM. The interface must\n"
			       "exist and be up (no root needed). On exit a summary goes to stderr.",
		.closing = "Exit status: 0 stopped by a signal or --duration, 1 interface or\n"
			   "calibration error, 2 bad usage. Watchdog expiries (a stalled loop) are\n"
			   "reported on stderr and counted in the summary.",
	};
	cli_result_t r;

	memset(a, 0, sizeof(*a));
	a->duration_s = -1.0;
	r = cli_parse(&spec, argc, argv, NULL, NULL);
	if (r != CLI_OK) {
		return (int)r;
	}
	a->rcvbuf_bytes = (int)rcvbuf; /* <= 2^28 */
	if (a->iface == NULL) {
		return (int)cli_usage_error(&spec, "--iface IF is required (e.g. --iface vcan0)");
	}
	return CLI_OK;
}

/*
 * Text file (or the defaults) with the command line's bus settings -> binary
 * block in a private temporary file -> HAL storage. --out-iface puts the
 * outputs on bus 1, --listen-only makes the input bus listen-only; a file
 * that names bus 1 without --out-iface is refused (that bus has no
 * interface).
 */
static int install_calibration(const ecu_args_t *a)
{
	calib_t cal;
	uint8_t block[CALIB_BLOCK_LEN];
	char err[300];
	const char *dir = getenv("TMPDIR");
	const char *what = (a->calib_path != NULL) ? a->calib_path : "calibration";
	ssize_t n;
	int fd;

	if (a->calib_path == NULL) {
		calib_default(&cal);
	} else if (calib_text_load(a->calib_path, &cal, err, sizeof(err)) != SQ_OK) {
		fprintf(stderr, "squeal-sim ecu: %s\n", err);
		return -1;
	}
	if (a->out_iface != NULL) {
		cal.output_bus = 1U;
	}
	if (a->listen_only) {
		cal.input_listen_only = 1U;
	}
	if ((a->out_iface == NULL) && ((cal.input_bus != 0U) || (cal.output_bus != 0U))) {
		fprintf(stderr, "squeal-sim ecu: %s: bus 1 (input_bus/output_bus) needs --out-iface\n",
			what);
		return -1;
	}
	if (calib_encode(&cal, block, sizeof(block)) != SQ_OK) {
		fprintf(stderr, "squeal-sim ecu: %s: calibration does not encode\n", what);
		return -1;
	}
	if ((dir == NULL) || (dir[0] == '\0') || (strlen(dir) > 40U)) {
		dir = "/tmp";
	}
	snprintf(ecu_calib_tmp, sizeof(ecu_calib_tmp), "%s/squeal-cal.XXXXXX", dir);
	fd = mkstemp(ecu_calib_tmp);
	if (fd < 0) {
		fprintf(stderr, "squeal-sim ecu: cannot create %s: %s\n", ecu_calib_tmp,
			strerror(errno));
		ecu_calib_tmp[0] = '\0';
		return -1;
	}
	n = write(fd, block, sizeof(block));
	if ((close(fd) != 0) || (n != (ssize_t)sizeof(block))) {
		fprintf(stderr, "squeal-sim ecu: cannot write %s\n", ecu_calib_tmp);
		return -1;
	}
	if (hal_linux_set_calib_path(ecu_calib_tmp) != SQ_OK) {
		fprintf(stderr, "squeal-sim ecu: %s\n", hal_linux_strerror());
		return -1;
	}
	return 0;
}

static void remove_calibration(void)
{
	if (ecu_calib_tmp[0] != '\0') {
		(void)unlink(ecu_calib_tmp);
		ecu_calib_tmp[0] = '\0';
	}
}

static const char *state_name(uint8_t state)
{
	const char *n = msg_squeal_state_name(state);

	return (n != NULL) ? n : "?";
}

static void print_input(const char *name, const input_t *in)
{
	const input_counters_t *c = &in->count;

	fprintf(stderr, "%s_frames=%" PRIu32 " %s_used=%" PRIu32 " %s_bad_dlc=%" PRIu32
		" %s_e2e_wrong_crc=%" PRIu32 " %s_e2e_wrong_sequence=%" PRIu32
		" %s_e2e_repeated=%" PRIu32 " %s_e2e_lost=%" PRIu32
		" %s_implausible=%" PRIu32 " %s_stale_events=%" PRIu32 "\n",
		name, c->frames, name, c->used, name, c->bad_dlc, name, c->e2e_wrong_crc,
		name, c->e2e_wrong_sequence, name, c->e2e_repeated, name, c->e2e_lost,
		name, c->implausible, name, c->stale_events);
}

static void ecu_summary(const uint64_t state_us[MSG_SQUEAL_STATE_SLOTS], uint64_t run_us)
{
	const monitor_t *m = squeal_app_monitor();
	hal_linux_can_stats_t st;
	unsigned int i;

	hal_linux_can_get_stats(0U, &st);
	fprintf(stderr, "squeal-sim ecu: summary after %.3f s (key=value)\n",
		(double)run_us / 1e6);
	fprintf(stderr, "state=%s warning=%u state_changes=%" PRIu32
		" classifications=%" PRIu32 " model_invalid=%" PRIu32
		" fault_bits=0x%04X calib_invalid=%d init_rc=%d\n",
		state_name(m->state), m->warning, m->count.state_changes,
		m->count.classifications, m->count.model_invalid,
		monitor_fault_bits(m), m->calib_invalid ? 1 : 0,
		squeal_app_init_status());
	fprintf(stderr, "time_s:");
	for (i = 0U; i < MSG_SQUEAL_STATE_SLOTS; i++) {
		fprintf(stderr, " %s=%.3f",
			state_name((uint8_t)((i < MSG_SQUEAL_STATE_SLOT_FAULT) ? i : MSG_SQUEAL_STATE_FAULT)),
			(double)state_us[i] / 1e6);
	}
	fprintf(stderr, "\n");
	print_input("speed", &m->speed);
	print_input("force", &m->force);
	fprintf(stderr, "unknown_id=%" PRIu32 " error_frames=%" PRIu32
		" rtr_or_ext=%" PRIu32 " bus_off_events=%" PRIu32
		" rx_overruns=%" PRIu32 "\n",
		m->count.unknown_id, m->count.error_frames, m->count.rtr_or_ext,
		m->count.bus_off_events, m->count.rx_overruns);
	fprintf(stderr, "tx_frames=%" PRIu32 " tx_overflow=%" PRIu32 " tx_errors=%" PRIu32
		" worst_task_us=%" PRIu32 "\n",
		m->count.tx_frames, m->count.tx_overflow, m->count.tx_errors,
		m->worst_task_us);
	fprintf(stderr, "hal_rx_frames=%" PRIu64 " hal_rx_err_frames=%" PRIu64
		" hal_rx_kernel_drops=%" PRIu64 " hal_tx_frames=%" PRIu64
		" hal_tx_retries=%" PRIu64 " hal_tx_dropped=%" PRIu64
		" hal_tx_worst_us=%" PRIu32 " watchdog_expiries=%" PRIu32 "\n",
		st.rx_frames, st.rx_err_frames, st.rx_kernel_drops, st.tx_frames,
		st.tx_retries, st.tx_dropped, st.tx_worst_us,
		hal_linux_watchdog_expiries());
	if (hal_linux_can_fd(1U) >= 0) {
		hal_linux_can_get_stats(1U, &st);
		fprintf(stderr, "out_hal_rx_err_frames=%" PRIu64 " out_hal_tx_frames=%" PRIu64
			" out_hal_tx_retries=%" PRIu64 " out_hal_tx_dropped=%" PRIu64 "\n",
			st.rx_err_frames, st.tx_frames, st.tx_retries, st.tx_dropped);
	}
	{
		hal_can_status_t in;

		if (hal_can_get_status(m->cal->input_bus, &in) == SQ_OK) {
			fprintf(stderr, "in_listen_only=%d in_tx_refused_listen_only=%" PRIu32 "\n",
				(in.mode == HAL_CAN_MODE_LISTEN_ONLY) ? 1 : 0, in.tx_refused_listen_only);
		}
	}
}

int cmd_ecu(int argc, char **argv)
{
	ecu_args_t a;
	hal_linux_can_opts_t opts;
	uint64_t state_us[MSG_SQUEAL_STATE_SLOTS] = { 0U, 0U, 0U, 0U, 0U };
	uint64_t t_start;
	uint64_t t_prev;
	uint64_t t_end = UINT64_MAX;
	uint8_t state;
	uint8_t warning;
	int rc = ecu_parse(argc, argv, &a);

	if (rc != CLI_OK) {
		return cli_exit_status((cli_result_t)rc);
	}
	if (hal_linux_install_signal_handlers(&ecu_stop) != SQ_OK) {
		fprintf(stderr, "squeal-sim ecu: %s\n", hal_linux_strerror());
		return 1;
	}
	if ((a.calib_path != NULL) || (a.out_iface != NULL) || a.listen_only) {
		if (install_calibration(&a) != 0) {
			remove_calibration();
			return 1;
		}
	} else {
		/* no storage: the firmware's defaults, not a fault */
		(void)hal_linux_set_calib_path(NULL);
	}
	memset(&opts, 0, sizeof(opts));
	opts.rcvbuf_bytes = a.rcvbuf_bytes;
	if ((hal_linux_open(0U, a.iface, &opts) != SQ_OK) ||
	    ((a.out_iface != NULL) && (hal_linux_open(1U, a.out_iface, &opts) != SQ_OK))) {
		fprintf(stderr, "squeal-sim ecu: %s\n", hal_linux_strerror());
		hal_linux_close();
		remove_calibration();
		return 1;
	}
	rc = squeal_app_init();
	remove_calibration(); /* read once at init, as from flash */
	if (rc != SQ_OK) {
		fprintf(stderr, "squeal-sim ecu: firmware init reported %d (running on; see fault_bits)\n",
			rc);
	}
	state = squeal_app_monitor()->state;
	warning = squeal_app_monitor()->warning;
	t_start = hal_time_us();
	t_prev = t_start;
	if (a.duration_s >= 0.0) {
		t_end = t_start + (uint64_t)(a.duration_s * 1e6);
	}
	if (a.verbose) {
		fprintf(stderr, "squeal-sim ecu: running on %s (%s build), state %s\n",
			a.iface, SQUEAL_NUMERIC_NAME, state_name(state));
	}
	while (!ecu_stop) {
		const uint64_t next = squeal_app_poll();
		const monitor_t *m = squeal_app_monitor();
		const uint64_t now = hal_time_us();

		state_us[msg_squeal_state_slot(state)] += now - t_prev;
		t_prev = now;
		if ((m->state != state) || (m->warning != warning)) {
			if (a.verbose) {
				fprintf(stderr, "%.6f state %s -> %s, warning %u -> %u\n",
					(double)(now - t_start) / 1e6, state_name(state),
					state_name(m->state), warning, m->warning);
			}
			state = m->state;
			warning = m->warning;
		}
		if (now >= t_end) {
			break;
		}
		hal_idle_until(next < t_end ? next : t_end);
	}
	ecu_summary(state_us, hal_time_us() - t_start);
	hal_linux_close();
	return 0;
}
