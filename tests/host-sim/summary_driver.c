/* SPDX-License-Identifier: MIT */
/*
 * Test driver of host-sim/replay_summary.c alone: reads candump -L lines of
 * monitor OUTPUT frames (any of the four corners) from stdin, feeds them to
 * the summary as if the ECU had sent them, and writes the JSON document
 * ({"episodes": ..., "cells_grid": ..., "corners": ...}) on stdout. The
 * end time is the last frame's time plus END_MS (argv[1], default 0).
 * test_summary_json.py builds four-corner streams that today's firmware
 * (one corner) cannot send, and checks the result independently.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "candump_log.h"
#include "replay_summary.h"

int main(int argc, char **argv)
{
	static candump_reader_t reader;
	static replay_summary_t rs;
	json_writer_t w;
	candump_frame_t f;
	const char *line;
	size_t len;
	bool too_long;
	uint64_t last_us = 0U;
	const uint64_t end_ms = (argc > 1) ? strtoull(argv[1], NULL, 10) : 0U;

	json_writer_init(&w, stdout);
	json_begin_object(&w);
	replay_summary_init(&rs, &w);
	candump_reader_init(&reader, stdin);
	while (candump_reader_next(&reader, &line, &len, &too_long) > 0) {
		candump_err_t err = CANDUMP_OK;
		size_t col = 0U;
		hal_can_frame_t hf;

		if (too_long || (candump_parse_line(line, len, &f, &err, &col) != CANDUMP_LINE_FRAME)) {
			continue;
		}
		memset(&hf, 0, sizeof(hf));
		hf.id = f.id;
		hf.dlc = (f.len > 8U) ? 8U : (uint8_t)f.len;
		hf.timestamp_us = f.t_ns / 1000U;
		hf.flags = f.ext ? HAL_CAN_FLAG_EXT : 0U;
		memcpy(hf.data, f.data, sizeof(hf.data));
		last_us = hf.timestamp_us;
		replay_summary_on_frame(&rs, &hf);
	}
	replay_summary_finish(&rs, last_us + end_ms * 1000U);
	json_end_object(&w);
	return json_writer_done(&w) ? 0 : 1;
}
