/* SPDX-License-Identifier: MIT */
/*
 * text_errf: one line of error text into a caller's buffer, for the readers
 * of text files (calibration, scenario) that return their message instead of
 * printing it. Nothing is written when err is NULL or errlen is 0. Header-
 * only (static inline), like num_text.h, so each reader links nothing more.
 */
#ifndef TEXT_ERRF_H
#define TEXT_ERRF_H

#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>

static inline void text_errf(char *err, size_t errlen, const char *fmt, ...)
	__attribute__((format(printf, 3, 4)));

static inline void text_errf(char *err, size_t errlen, const char *fmt, ...)
{
	va_list ap;

	if ((err == NULL) || (errlen == 0U)) {
		return;
	}
	va_start(ap, fmt);
	(void)vsnprintf(err, errlen, fmt, ap);
	va_end(ap);
}

#endif /* TEXT_ERRF_H */
