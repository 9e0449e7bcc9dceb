/* SPDX-License-Identifier: MIT */
/*
 * num_text: the one reading of a number written by a person, on the command
 * line (cli_args.c) and in a calibration file (calib_text.c,
 * calib_sections.c):
 *   a real     decimal, optional sign and exponent ("1.5", "-2e-3"); no hex
 *              floats, no inf/nan, no blanks, nothing after it, finite
 *   an integer decimal with an optional sign, or 0x hex ("0x110")
 * Header-only (static inline): every program that reads numbers, including
 * the test programs that link calib_text.o alone, gets the same rules
 * without one more object to link.
 */
#ifndef NUM_TEXT_H
#define NUM_TEXT_H

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static inline bool num_text_real(const char *text, double *out)
{
	const char *p;
	char *end = NULL;
	double v;

	for (p = text; *p != '\0'; p++) {
		if (!isdigit((unsigned char)*p) && (strchr("+-.eE", *p) == NULL)) {
			return false;
		}
	}
	errno = 0;
	v = strtod(text, &end);
	if ((end == text) || (*end != '\0') || (errno == ERANGE) || !isfinite(v)) {
		return false;
	}
	*out = v;
	return true;
}

static inline bool num_text_int(const char *text, int64_t *out)
{
	char *end = NULL;
	long long v;

	errno = 0;
	if ((text[0] == '0') && ((text[1] == 'x') || (text[1] == 'X'))) {
		if (!isxdigit((unsigned char)text[2])) {
			return false;
		}
		v = strtoll(text + 2, &end, 16);
	} else {
		if (!isdigit((unsigned char)text[0]) &&
		    !(((text[0] == '-') || (text[0] == '+')) &&
		      isdigit((unsigned char)text[1]))) {
			return false;
		}
		v = strtoll(text, &end, 10);
	}
	if ((errno != 0) || (end == NULL) || (*end != '\0')) {
		return false;
	}
	*out = v;
	return true;
}

#endif /* NUM_TEXT_H */
