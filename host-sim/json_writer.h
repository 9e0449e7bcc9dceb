/* SPDX-License-Identifier: MIT */
/*
 * json_writer: a small bounded JSON writer onto a stdio stream, for the
 * documents the C side defines (replay --summary-json). No allocation:
 * nesting is limited to JSON_MAX_DEPTH levels, numbers are formatted into
 * fixed buffers, strings are escaped byte by byte as they are written.
 *
 * Strings: '"', '\\' and control characters are escaped (\n, \t, ...,
 * \u00XX); valid UTF-8 passes unchanged; a byte that is not part of valid
 * UTF-8 (a log name is any byte string) becomes U+FFFD, so the output is
 * always valid JSON. Non-finite doubles are written as null.
 *
 * Errors are sticky: a failed write, nesting deeper than JSON_MAX_DEPTH, a
 * close without an open, a value where a key is due or a key outside an
 * object sets the error flag and every later call does nothing.
 * json_writer_done() tells whether the document is complete and whole.
 */
#ifndef JSON_WRITER_H
#define JSON_WRITER_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#define JSON_MAX_DEPTH 16U

typedef struct {
	FILE *out;
	unsigned depth;                     /* open containers               */
	bool is_object[JSON_MAX_DEPTH];     /* per level: object or array    */
	bool has_items[JSON_MAX_DEPTH];     /* per level: a comma is due     */
	bool key_done;                      /* in an object: the value is due */
	bool started;                       /* the top-level value began     */
	bool error;
} json_writer_t;

void json_writer_init(json_writer_t *w, FILE *out);

void json_begin_object(json_writer_t *w);
void json_end_object(json_writer_t *w);
void json_begin_array(json_writer_t *w);
void json_end_array(json_writer_t *w);
void json_key(json_writer_t *w, const char *key);

void json_string(json_writer_t *w, const char *s);
void json_u64(json_writer_t *w, uint64_t v);
void json_i64(json_writer_t *w, int64_t v);
void json_double(json_writer_t *w, double v);   /* %.17g; null if not finite */
void json_fixed(json_writer_t *w, int64_t v, unsigned decimals); /* v / 10^decimals exactly */
void json_bool(json_writer_t *w, bool v);
void json_null(json_writer_t *w);

/* Key and value in one call (inside an object). */
void json_kv_u64(json_writer_t *w, const char *key, uint64_t v);
void json_kv_string(json_writer_t *w, const char *key, const char *s);
void json_kv_seconds(json_writer_t *w, const char *key, uint64_t us); /* us -> s, 6 decimals */

/* True when one complete top-level value was written without an error. */
bool json_writer_done(const json_writer_t *w);

#endif /* JSON_WRITER_H */
