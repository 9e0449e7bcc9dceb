/* SPDX-License-Identifier: MIT */
/*
 * squeal-sim decode [LOG|-|--iface IF] [--bus NAME] [--csv]: the frames of
 * squeal.dbc as physical values, from a candump -L log, stdin, or a CAN
 * interface. --bus NAME takes only the log's frames of interface NAME (the
 * interface the inputs come from in a multi-bus log); default: the
 * calibration's input_iface with --calib, else every interface.
 *
 * Values come from the firmware's descriptor tables (msg_table,
 * msg_sig_table, checked against the DBC by tests/firmware/protocol/): physical =
 * (raw * factor_num + offset_num) / factor_den, printed exactly in decimal
 * with as many digits as the factor needs (0.01 -> 2, 0.5 -> 1), "NA" for
 * the DBC's "not available" raw value.
 *
 * E2E (every message of the DBC is protected, AUTOSAR P01 1A): the CRC is
 * recomputed with the DBC's E2E_DataID and the alive counter of each
 * message is followed:
 *   ok             CRC right, counter = previous + 1 (mod 15)
 *   initial        first frame of that message
 *   lost:N         N frames missing before this one
 *   repeated       same counter as the previous frame
 *   wrong_crc      CRC wrong (values printed anyway, as received)
 *   bad_counter    counter 15 (never sent by a P01 sender)
 *   bad_dlc        length is not the message's DLC (no values)
 *
 * With --calib, each [corner POS] of the calibration's input map sends its
 * own identifiers: its frames are named NAME[POS] ("SquealStatus[FR]"), in
 * text and CSV, and each corner's E2E counters are followed on their own.
 *
 * Text: one line per frame, "TIME NAME signal=value ... ctr=N e2e=STATUS";
 * SquealState, WarningLevel and SquealDiag_Page print as state=NAME,
 * warning=NAME, page=NAME, the Fault_* bits as faults=A|B (or none).
 * Other frames: "TIME ID unknown [LEN] DATA", remote/FD/XL/error frames
 * likewise raw.
 *
 * CSV (--csv): a header, then one row per frame:
 *   time_s,id,message,counter,e2e,<every non-E2E signal of squeal.dbc in
 *   DBC order, named as in the DBC>,raw
 * A signal's cell is empty when the frame does not carry it (other message
 * or other SquealDiag page), "NA" when not available; enumerations
 * (SquealState, WarningLevel, SquealDiag_Page) are their numbers; raw is the
 * payload in hex. The column set depends only on the DBC, so scripts can
 * rely on it; forward-fill a column to get its value at every time.
 */
#include <errno.h>
#include <inttypes.h>
#include <signal.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "candump_hal.h"
#include "candump_log.h"
#include "cli_args.h"
#include "crc8_p01.h"
#include "decode_inputs.h"
#include "hal.h"
#include "hal_linux.h"
#include "sim_commands.h"
#include "squeal_msgs.h"

typedef struct {
	bool seen;
	uint8_t last_counter;
} e2e_track_t;

/* With --calib: each corner's output messages, by their identifiers. */
typedef struct {
	uint16_t id;
	uint8_t mi;                /* index in msg_table */
	uint8_t corner;            /* index in the calibration's corners */
	const char *pos;
} corner_msg_t;

#define CORNER_MSGS_MAX (CALIB_MAX_CORNERS * 4U)

typedef struct {
	bool csv;
	decode_inputs_t *inputs;   /* --calib: the input map's inputs          */
	bool inputs_csv;           /* --inputs-csv: only those, as CSV         */
	e2e_track_t e2e[CALIB_MAX_CORNERS][MSG_COUNT]; /* per corner (0 without --calib) */
	corner_msg_t cmsg[CORNER_MSGS_MAX];
	uint32_t n_cmsg;
	uint8_t decimals[MSG_SIG_COUNT];
	char *out;      /* line being built */
	size_t out_len;
	size_t out_size;
	bool overflow;
} decoder_t;

static const char *const level_names[4] = { "none", "advisory", "warning", "critical" };
static const char *const page_names[5] = {
	"uptime_and_bus_off", "task_time_and_overruns", "e2e_errors", "tx_and_frame_errors",
	"self_test"
};

static void put(decoder_t *d, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

static void put(decoder_t *d, const char *fmt, ...)
{
	va_list ap;
	int n;

	if (d->out_len >= d->out_size) {
		d->overflow = true;
		return;
	}
	va_start(ap, fmt);
	n = vsnprintf(d->out + d->out_len, d->out_size - d->out_len, fmt, ap);
	va_end(ap);
	if ((n < 0) || ((size_t)n >= d->out_size - d->out_len)) {
		d->overflow = true;
		d->out_len = d->out_size;
		return;
	}
	d->out_len += (size_t)n;
}

/* Digits after the point that (raw * num + off) / den needs, 0..9. */
static uint8_t sig_decimals(const msg_sig_desc_t *s)
{
	int64_t p = 1;
	uint8_t k;

	for (k = 0U; k < 9U; k++) {
		if ((((int64_t)s->factor_num * p) % s->factor_den == 0) &&
		    (((int64_t)s->offset_num * p) % s->factor_den == 0)) {
			return k;
		}
		p *= 10;
	}
	return 9U;
}

/* Exact decimal text of a raw value ("NA" for not available). */
static void put_phys(decoder_t *d, const msg_sig_desc_t *s, uint8_t decimals, int32_t raw)
{
	int64_t p = 1;
	int64_t v;
	uint64_t a;
	uint8_t k;

	if (((s->flags & MSG_SIG_HAS_NA) != 0U) && (raw == s->na_raw)) {
		put(d, "NA");
		return;
	}
	for (k = 0U; k < decimals; k++) {
		p *= 10;
	}
	/* |raw| < 2^31, |num| small, p <= 10^9: fits in int64 for the table's
	 * factors (checked: num * p < 2^32) */
	v = ((int64_t)raw * s->factor_num + s->offset_num) * p / s->factor_den;
	a = (v < 0) ? (uint64_t)(-v) : (uint64_t)v;
	if (decimals == 0U) {
		put(d, "%s%" PRIu64, (v < 0) ? "-" : "", a);
	} else {
		put(d, "%s%" PRIu64 ".%0*" PRIu64, (v < 0) ? "-" : "", a / (uint64_t)p,
		    (int)decimals, a % (uint64_t)p);
	}
}

static bool is_fault_bit(const msg_sig_desc_t *s)
{
	return (s->length == 1U) && (strncmp(s->name, "Fault_", 6) == 0);
}

/* E2E state of one frame of a known message (dlc already checked). */
static const char *e2e_status(decoder_t *d, size_t corner, size_t mi, const uint8_t *data,
			      uint8_t dlc, uint8_t *lost)
{
	const msg_desc_t *m = &msg_table[mi];
	e2e_track_t *t = &d->e2e[corner][mi];
	const uint8_t id[2] = { (uint8_t)(m->data_id & 0xFFU), (uint8_t)(m->data_id >> 8) };
	const uint8_t counter = data[1] & 0x0FU;
	uint8_t crc;
	uint8_t delta;

	*lost = 0U;
	crc = crc8_p01_update(crc8_p01_update(0U, id, 2U), data + 1, (size_t)dlc - 1U);
	if (crc != data[0]) {
		return "wrong_crc";
	}
	if (counter > 14U) {
		return "bad_counter";
	}
	if (!t->seen) {
		t->seen = true;
		t->last_counter = counter;
		return "initial";
	}
	delta = (uint8_t)((counter + 15U - t->last_counter) % 15U);
	t->last_counter = counter;
	if (delta == 0U) {
		return "repeated";
	}
	if (delta == 1U) {
		return "ok";
	}
	*lost = (uint8_t)(delta - 1U);
	return "lost";
}

static void put_time(decoder_t *d, uint64_t t_ns)
{
	put(d, "%" PRIu64 ".%06" PRIu64, t_ns / 1000000000U, (t_ns % 1000000000U) / 1000U);
}

static void put_hex(decoder_t *d, const uint8_t *data, size_t len)
{
	size_t i;

	for (i = 0U; i < len; i++) {
		put(d, "%02X", data[i]);
	}
}

static void put_id(decoder_t *d, const candump_frame_t *f)
{
	if (f->kind == CANDUMP_KIND_ERROR) {
		put(d, "%08" PRIX32, f->id | CANDUMP_ERR_FLAG);
	} else if (f->ext) {
		put(d, "%08" PRIX32, f->id);
	} else {
		put(d, "%03" PRIX32, f->id);
	}
}

static const char *kind_name(const candump_frame_t *f)
{
	switch (f->kind) {
	case CANDUMP_KIND_RTR:
		return "remote";
	case CANDUMP_KIND_FD:
		return "fd";
	case CANDUMP_KIND_ERROR:
		return "error";
	case CANDUMP_KIND_XL:
		return "xl";
	default:
		return "unknown";
	}
}

static void csv_header(decoder_t *d)
{
	size_t i;

	put(d, "time_s,id,message,counter,e2e");
	for (i = 0U; i < MSG_SIG_COUNT; i++) {
		if ((msg_sig_table[i].flags & MSG_SIG_E2E) == 0U) {
			put(d, ",%s", msg_sig_table[i].name);
		}
	}
	put(d, ",raw\n");
}

static void decode_frame(decoder_t *d, const candump_frame_t *f)
{
	const msg_desc_t *m = NULL;
	const corner_msg_t *cm = NULL;
	char name[48];
	size_t mi = 0U;
	const char *e2e = "";
	uint8_t lost = 0U;
	bool dlc_ok = false;
	size_t i;

	if ((f->kind == CANDUMP_KIND_CLASSIC) && !f->ext) {
		for (i = 0U; (i < d->n_cmsg) && (cm == NULL); i++) {
			if (d->cmsg[i].id == f->id) {
				cm = &d->cmsg[i];
				m = &msg_table[cm->mi];
			}
		}
		if (cm == NULL) {
			m = msg_desc_find((uint16_t)f->id);
		}
	}
	if (m != NULL) {
		mi = (size_t)(m - msg_table);
		dlc_ok = (f->len == m->dlc);
		e2e = dlc_ok ? e2e_status(d, (cm != NULL) ? cm->corner : 0U, mi, f->data, f->len, &lost) :
			       "bad_dlc";
		if (cm != NULL) {
			(void)snprintf(name, sizeof(name), "%s[%s]", m->name, cm->pos);
		} else {
			(void)snprintf(name, sizeof(name), "%s", m->name);
		}
	}
	put_time(d, f->t_ns);
	if (d->csv) {
		put(d, ",");
		put_id(d, f);
		put(d, ",%s,", (m != NULL) ? name : kind_name(f));
		if (dlc_ok) {
			put(d, "%u", f->data[1] & 0x0FU);
		}
		put(d, ",%s", e2e);
		if (lost != 0U) {
			put(d, ":%u", lost);
		}
		for (i = 0U; i < MSG_SIG_COUNT; i++) {
			const msg_sig_desc_t *s = &msg_sig_table[i];
			int32_t raw;

			if ((s->flags & MSG_SIG_E2E) != 0U) {
				continue;
			}
			put(d, ",");
			if (dlc_ok && (s->msg_id == m->id) &&
			    (msg_sig_get_raw(s, f->data, f->len, &raw) == SQ_OK)) {
				put_phys(d, s, d->decimals[i], raw);
			}
		}
		put(d, ",");
		if ((f->kind != CANDUMP_KIND_RTR) && (f->kind != CANDUMP_KIND_XL)) {
			put_hex(d, f->data, f->len);
		}
		put(d, "\n");
		return;
	}
	put(d, " ");
	if ((m == NULL) || !dlc_ok) {
		if (m != NULL) {
			put(d, "%s bad_dlc ", name);
		} else {
			put_id(d, f);
			put(d, " %s ", kind_name(f));
		}
		if (f->kind == CANDUMP_KIND_XL) {
			put(d, "[%u]\n", f->xl_len);
			return;
		}
		if (f->kind == CANDUMP_KIND_FD) {
			put(d, "flags=%X ", f->fd_flags);
		}
		put(d, "[%u]", f->len);
		if (f->kind != CANDUMP_KIND_RTR) {
			put(d, " ");
			put_hex(d, f->data, f->len);
		}
		put(d, "\n");
		return;
	}
	put(d, "%s", name);
	{
		bool any_fault_sig = false;
		bool any_fault = false;

		for (i = m->sig_first; i < (size_t)m->sig_first + m->sig_count; i++) {
			const msg_sig_desc_t *s = &msg_sig_table[i];
			int32_t raw;

			if (((s->flags & MSG_SIG_E2E) != 0U) ||
			    (msg_sig_get_raw(s, f->data, f->len, &raw) != SQ_OK)) {
				continue;
			}
			if (strcmp(s->name, "SquealState") == 0) {
				const char *n = msg_squeal_state_name((uint8_t)(raw & 0xF));

				if (n != NULL) {
					put(d, " state=%s", n);
				} else {
					put(d, " state=%d", (int)(raw & 0xF)); /* a value the DBC does not name */
				}
			} else if (strcmp(s->name, "WarningLevel") == 0) {
				if ((raw >= 0) && (raw < 4)) {
					put(d, " warning=%s", level_names[raw]);
				} else {
					put(d, " warning=%" PRId32, raw);
				}
			} else if (strcmp(s->name, "SquealDiag_Page") == 0) {
				if ((raw >= 0) && (raw < 5)) {
					put(d, " page=%s", page_names[raw]);
				} else {
					put(d, " page=%" PRId32, raw);
				}
			} else if (is_fault_bit(s)) {
				if (!any_fault_sig) {
					put(d, " faults=");
					any_fault_sig = true;
				}
				if (raw != 0) {
					put(d, "%s%s", any_fault ? "|" : "", s->name + 6);
					any_fault = true;
				}
			} else {
				if (any_fault_sig && !any_fault) {
					put(d, "none");
					any_fault = true;
				}
				put(d, " %s=", s->name);
				put_phys(d, s, d->decimals[i], raw);
			}
		}
		if (any_fault_sig && !any_fault) {
			put(d, "none");
		}
	}
	put(d, " ctr=%u e2e=%s", f->data[1] & 0x0FU, e2e);
	if (lost != 0U) {
		put(d, ":%u", lost);
	}
	put(d, "\n");
}

static int flush_line(decoder_t *d);

/* One frame: the DBC view (unless --inputs-csv), then the input map's. */
static int decode_one(decoder_t *d, const candump_frame_t *f)
{
	int rc = 0;

	if (!d->inputs_csv) {
		decode_frame(d, f);
		rc = flush_line(d);
	}
	if (d->inputs != NULL) {
		decode_inputs_frame(d->inputs, f, d->inputs_csv, stdout);
	}
	return rc;
}

static int flush_line(decoder_t *d)
{
	int rc = 0;

	if (d->overflow) {
		rc = -1; /* cannot happen with the table's signals; never print half */
	} else if (fwrite(d->out, 1U, d->out_len, stdout) != d->out_len) {
		rc = -1;
	}
	d->out_len = 0U;
	d->overflow = false;
	return rc;
}

/* The output messages of every [corner] of the calibration (none for the
 * legacy form, whose one corner sends the DBC's identifiers). */
static void corner_msgs(decoder_t *d, const decode_inputs_t *in)
{
	static const char *const pos[4] = { "FL", "FR", "RL", "RR" };
	uint32_t k;

	d->n_cmsg = 0U;
	if (in->cal.n_corners == 0U) {
		return;
	}
	for (k = 0U; (k < in->n_corners) && (k < CALIB_MAX_CORNERS); k++) {
		const calib_corner_t *c = &in->corner[k];
		const uint16_t ids[4][2] = {
			{ c->status_id, MSG_SQUEAL_STATUS_ID }, { c->detail_id, MSG_SQUEAL_DETAIL_ID },
			{ c->detail2_id, MSG_SQUEAL_DETAIL2_ID }, { c->diag_id, MSG_SQUEAL_DIAG_ID },
		};
		unsigned j;

		for (j = 0U; j < 4U; j++) {
			const msg_desc_t *m = msg_desc_find(ids[j][1]);

			if ((m != NULL) && (d->n_cmsg < CORNER_MSGS_MAX)) {
				d->cmsg[d->n_cmsg] = (corner_msg_t){ ids[j][0], (uint8_t)(m - msg_table),
								     (uint8_t)k, pos[c->pos & 3U] };
				d->n_cmsg++;
			}
		}
	}
}

static volatile bool stop_flag;

static int decode_iface(decoder_t *d, const char *iface)
{
	hal_can_frame_t hf;
	candump_frame_t f;
	int rc;

	if (hal_linux_install_signal_handlers(&stop_flag) != SQ_OK) {
		fprintf(stderr, "squeal-sim decode: %s\n", hal_linux_strerror());
		return 1;
	}
	rc = hal_linux_open(0U, iface, NULL);
	if (rc != SQ_OK) {
		fprintf(stderr, "squeal-sim decode: %s\n", hal_linux_strerror());
		return 1;
	}
	while (!stop_flag) {
		hal_idle_until(hal_time_us() + 200000U);
		while (!stop_flag && (hal_can_receive(0U, &hf) == SQ_OK)) {
			candump_from_hal(&hf, hf.timestamp_us * 1000U, iface, &f);
			if (decode_one(d, &f) != 0) {
				hal_linux_close();
				return 1;
			}
		}
	}
	hal_linux_close();
	if (d->inputs != NULL) {
		decode_inputs_summary(d->inputs, stderr);
	}
	return 0;
}

static int decode_log(decoder_t *d, const char *path, const char *bus_name)
{
	static candump_reader_t reader;
	static candump_pending_t pending;
	const char *name = path;
	candump_frame_t f;
	const char *line;
	size_t len;
	bool too_long;
	FILE *in = stdin;
	int rc;
	int status = 0;

	if ((path == NULL) || (strcmp(path, "-") == 0)) {
		name = "<stdin>";
	} else {
		in = fopen(path, "rb");
		if (in == NULL) {
			fprintf(stderr, "squeal-sim decode: cannot open %s: %s\n", path, strerror(errno));
			return 1;
		}
	}
	candump_reader_init(&reader, in);
	candump_pending_init(&pending, stderr, name);
	while ((rc = candump_reader_next(&reader, &line, &len, &too_long)) > 0) {
		candump_err_t err = CANDUMP_OK;
		size_t col = 0U;

		if (too_long) {
			candump_pending_report(&pending, "%s:%" PRIu64 ": %s", name, reader.line_no,
					       candump_strerror(CANDUMP_ERR_TOO_LONG));
			continue;
		}
		switch (candump_parse_line(line, len, &f, &err, &col)) {
		case CANDUMP_LINE_FRAME:
			candump_pending_frame(&pending);
			if ((bus_name != NULL) && (strcmp(f.iface, bus_name) != 0)) {
				break; /* another bus of the log */
			}
			if (decode_one(d, &f) != 0) {
				status = 1;
			}
			break;
		case CANDUMP_LINE_MALFORMED:
			candump_pending_report(&pending, "%s:%" PRIu64 ": %s (column %zu)", name,
					       reader.line_no, candump_strerror(err), col + 1U);
			break;
		default:
			break;
		}
	}
	if (d->inputs != NULL) {
		decode_inputs_summary(d->inputs, stderr);
	}
	if (rc < 0) {
		fprintf(stderr, "squeal-sim decode: %s: read error\n", name);
		status = 1;
	} else if (candump_pending_no_frames(&pending, reader.line_no)) {
		status = 1;
	}
	if (in != stdin) {
		(void)fclose(in);
	}
	if (fflush(stdout) != 0) {
		status = 1;
	}
	return status;
}

int cmd_decode(int argc, char **argv)
{
	static char linebuf[4096];
	static char outbuf[1U << 16];
	static decoder_t d;
	static decode_inputs_t inputs;
	const char *calib_path = NULL;
	const char *iface = NULL;
	const char *bus_name = NULL;
	const char *path = NULL;
	const cli_opt_t opts[] = {
		CLI_OPT_FLAG("csv", 0, &d.csv,
			     "one CSV row per frame: time_s,id,message,counter,e2e,\n"
			     "every signal of the DBC (empty if not in the frame,\n"
			     "NA if not available),raw"),
		CLI_OPT_TEXT("iface", &iface, NULL, "IF", "read from a CAN interface (vcan0, can0, ...)"),
		CLI_OPT_TEXT("bus", &bus_name, NULL, "NAME",
			     "of a log, only the frames of interface NAME (one bus of a\n"
			     "multi-bus log; default: the calibration's input_iface, else\n"
			     "every interface)"),
		CLI_OPT_TEXT("calib", &calib_path, NULL, "FILE",
			     "calibration text with an input map (docs/calib-input-map.md):\n"
			     "after each frame, every input it carries as the monitor sees\n"
			     "it: raw, physical, valid/reason, and per corner v0 [m/s] or\n"
			     "the clamp force [N]; each corner's messages by their\n"
			     "identifiers, named NAME[POS] (SquealStatus[FR])"),
		CLI_OPT_FLAG("inputs-csv", 0, &d.inputs_csv,
			     "with --calib: only the inputs, one CSV row each:\n"
			     "t_s,iface,id,input,raw,physical,unit,valid,reason"),
	};
	const cli_spec_t spec = {
		.cmd = "decode",
		CLI_SPEC_OPTS(opts),
		.synopsis = "squeal-sim decode [LOG|-] [--bus NAME] [--csv] [--calib FILE [--inputs-csv]]\n"
			    "       squeal-sim decode --iface IF [--csv] [--calib FILE [--inputs-csv]]",
		.description = "Prints every frame of the monitor's messages and inputs (squeal.dbc) as\n"
			       "physical values with names and state names, checking E2E (CRC with the\n"
			       "DBC's data ID, alive counter sequence per message); other frames raw.\n"
			       "Reads a candump -L log (default: stdin), or a SocketCAN interface until\n"
			       "SIGINT/SIGTERM.",
		.closing = "Malformed log lines are reported on stderr as LOG:LINE: message.\n"
			   "Exit status: 0 done, 1 input error, 2 bad usage.",
		.min_pos = 0U,
		.max_pos = 1U,
	};
	size_t n_pos = 0U;
	cli_result_t r;
	size_t i;

	memset(&d, 0, sizeof(d));
	d.out = linebuf;
	d.out_size = sizeof(linebuf);
	r = cli_parse(&spec, argc, argv, &path, &n_pos);
	if (r != CLI_OK) {
		return cli_exit_status(r);
	}
	if ((iface != NULL) && (bus_name != NULL)) {
		return cli_exit_status(cli_usage_error(&spec, "--bus picks an interface of a log, not with --iface"));
	}
	if ((iface != NULL) && (path != NULL)) {
		return cli_exit_status(cli_usage_error(&spec, "give one LOG, -, or --iface IF"));
	}
	if (d.inputs_csv && (calib_path == NULL)) {
		return cli_exit_status(cli_usage_error(&spec, "--inputs-csv needs --calib FILE"));
	}
	if (calib_path != NULL) {
		if (decode_inputs_load(&inputs, calib_path) != 0) {
			return 1;
		}
		d.inputs = &inputs;
		corner_msgs(&d, &inputs);
		if ((bus_name == NULL) && (iface == NULL) && (inputs.names.input_iface[0] != '\0')) {
			bus_name = inputs.names.input_iface; /* the calibration's input interface */
		}
	}
	for (i = 0U; i < MSG_SIG_COUNT; i++) {
		d.decimals[i] = sig_decimals(&msg_sig_table[i]);
	}
	/* before any output: line buffered live, block buffered from a log */
	if (iface != NULL) {
		(void)setvbuf(stdout, NULL, _IOLBF, 0);
	} else {
		(void)setvbuf(stdout, outbuf, _IOFBF, sizeof(outbuf));
	}
	if (d.inputs_csv) {
		decode_inputs_csv_header(stdout);
	} else if (d.csv) {
		csv_header(&d);
		if (flush_line(&d) != 0) {
			return 1;
		}
	}
	if (iface != NULL) {
		return decode_iface(&d, iface);
	}
	return decode_log(&d, path, bus_name);
}
