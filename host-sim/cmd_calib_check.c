/* SPDX-License-Identifier: MIT */
/*
 * squeal-sim calib-check FILE: does a calibration text file load, and does
 * every corner set up exactly as written? The loader runs the firmware's
 * own validation (calib_validate: the same preparation input_rx_setup()
 * does for every corner); the check then sets every corner up as the
 * monitor does, so "ok" here means the ECU, replay and decode run this
 * calibration, not the factory defaults.
 *
 * Exit 0 with `FILE: ok (N inputs, M corners)` on stdout, or exit 1 with
 * one line `FILE:LINE: reason` on stderr (LINE of the responsible key,
 * omitted for whole-file problems); 2 for bad usage.
 */
#include <stdio.h>
#include <string.h>

#include "calib.h"
#include "calib_map.h"
#include "calib_text.h"
#include "cli_args.h"
#include "monitor.h"
#include "sim_commands.h"
#include "sq_status.h"

/* Every corner set up by the monitor itself (monitor_init_corner(), what
 * the ECU, replay and decode run): it keeps the calibration only when the
 * corner sets up, and falls back to the factory defaults otherwise. */
static int set_up_all(const calib_t *cal, uint32_t *bad_corner)
{
	static monitor_t mon;
	uint32_t k;

	for (k = 0U; k < calib_corner_count(cal); k++) {
		if ((monitor_init_corner(&mon, cal, k, false, 0U, 0U) != SQ_OK) || (mon.cal != cal)) {
			*bad_corner = k;
			return -1;
		}
	}
	return 0;
}

int cmd_calib_check(int argc, char **argv)
{
	static calib_t cal;
	static calib_names_t names;
	char err[400];
	uint32_t bad = 0U;

	static const cli_spec_t spec = {
		.cmd = "calib-check",
		.synopsis = "squeal-sim calib-check FILE",
		.description = "Load a calibration text file (docs/calib-example.txt,\n"
			       "docs/calib-input-map.md) and set up every corner as the monitor does.\n\n"
			       "  FILE: ok (N inputs, M corners)   on stdout, exit 0, when it does;\n"
			       "  FILE:LINE: reason                on stderr, exit 1, when it does not\n"
			       "                                   (LINE of the key responsible, left\n"
			       "                                   out for whole-file problems).",
		.closing = "Exit 2: bad usage.",
		.min_pos = 1U,
		.max_pos = 1U,
	};
	const char *path = NULL;
	const cli_result_t r = cli_parse(&spec, argc, argv, &path, NULL);

	if (r != CLI_OK) {
		return cli_exit_status(r);
	}
	if (calib_text_load_map(path, &cal, &names, err, sizeof(err)) != SQ_OK) {
		fprintf(stderr, "%s\n", err);
		return 1;
	}
	if (set_up_all(&cal, &bad) != 0) {
		/* calib_validate() and the set-up share one preparation: this
		 * would be a defect of the program, reported as the file's */
		fprintf(stderr, "%s: corner %u does not set up\n", path, (unsigned int)bad);
		return 1;
	}
	printf("%s: ok (%u inputs, %u corners)\n", path,
	       (unsigned int)((cal.n_corners == 0U) ? 2U : cal.n_inputs),
	       (unsigned int)calib_corner_count(&cal));
	return 0;
}
