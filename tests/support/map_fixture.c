/* SPDX-License-Identifier: MIT */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "map_fixture.h"
#include "sq_status.h"

void map_fixture_load(const char *dir, const char *file, calib_t *cal, calib_names_t *names)
{
	char path[256];
	char err[300] = "";

	if (snprintf(path, sizeof(path), "%s/%s", dir, file) >= (int)sizeof(path)) {
		fail_msg("fixture path too long: %s/%s", dir, file);
	}
	if (calib_text_load_map(path, cal, names, err, sizeof(err)) != SQ_OK) {
		fail_msg("%s", err);
	}
}

uint32_t map_fixture_input(const calib_t *cal, const calib_names_t *names, const char *name)
{
	for (uint32_t i = 0U; i < cal->n_inputs; i++) {
		if (strcmp(names->input[i], name) == 0) {
			return i;
		}
	}
	fail_msg("no input %s", name);
	return 0U;
}
