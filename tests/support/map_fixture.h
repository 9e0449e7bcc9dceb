/* SPDX-License-Identifier: MIT */
/*
 * Input-map fixtures (.cal text) for the cmocka tests of input_rx: load one
 * through host-sim's parser and find an input by its name. Either failing is
 * the test's failure (fail_msg), so the tests read as their expectations.
 */
#ifndef MAP_FIXTURE_H
#define MAP_FIXTURE_H

#include <stdint.h>

#include "calib_text.h"

void map_fixture_load(const char *dir, const char *file, calib_t *cal, calib_names_t *names);
uint32_t map_fixture_input(const calib_t *cal, const calib_names_t *names, const char *name);

#endif
