/* SPDX-License-Identifier: MIT */
/* json_writer: see json_writer.h. */
#include "json_writer.h"

#include <inttypes.h>
#include <math.h>
#include <string.h>

void json_writer_init(json_writer_t *w, FILE *out)
{
	memset(w, 0, sizeof(*w));
	w->out = out;
	w->error = (out == NULL);
}

static void put(json_writer_t *w, const char *s, size_t n)
{
	if (!w->error && (n > 0U) && (fwrite(s, 1U, n, w->out) != n)) {
		w->error = true;
	}
}

static void puts_(json_writer_t *w, const char *s)
{
	put(w, s, strlen(s));
}

/* Before any value: the comma, and the check that a value is allowed here. */
static bool value_start(json_writer_t *w)
{
	if (w->error) {
		return false;
	}
	if (w->depth == 0U) {
		if (w->started) {
			w->error = true; /* a second top-level value */
			return false;
		}
		w->started = true;
		return true;
	}
	if (w->is_object[w->depth - 1U]) {
		if (!w->key_done) {
			w->error = true; /* a value where a key is due */
			return false;
		}
		w->key_done = false;
		return true;
	}
	if (w->has_items[w->depth - 1U]) {
		puts_(w, ",");
	}
	w->has_items[w->depth - 1U] = true;
	return !w->error;
}

static void begin(json_writer_t *w, bool object)
{
	if (!value_start(w)) {
		return;
	}
	if (w->depth >= JSON_MAX_DEPTH) {
		w->error = true;
		return;
	}
	w->is_object[w->depth] = object;
	w->has_items[w->depth] = false;
	w->depth++;
	puts_(w, object ? "{" : "[");
}

static void end(json_writer_t *w, bool object)
{
	if (w->error) {
		return;
	}
	if ((w->depth == 0U) || (w->is_object[w->depth - 1U] != object) || w->key_done) {
		w->error = true;
		return;
	}
	w->depth--;
	puts_(w, object ? "}" : "]");
	if (w->depth == 0U) {
		puts_(w, "\n");
	}
}

void json_begin_object(json_writer_t *w) { begin(w, true); }
void json_end_object(json_writer_t *w) { end(w, true); }
void json_begin_array(json_writer_t *w) { begin(w, false); }
void json_end_array(json_writer_t *w) { end(w, false); }

/* Length of the valid UTF-8 sequence at s (1..4), or 0 if it is not one. */
static size_t utf8_len(const unsigned char *s)
{
	const unsigned char c = s[0];
	unsigned char lo = 0x80U;
	unsigned char hi = 0xBFU;
	size_t n;
	size_t i;

	if (c < 0x80U) {
		return 1U;
	}
	if ((c >= 0xC2U) && (c <= 0xDFU)) {
		n = 2U;
	} else if ((c >= 0xE0U) && (c <= 0xEFU)) {
		n = 3U;
		lo = (c == 0xE0U) ? 0xA0U : 0x80U;   /* no overlong forms */
		hi = (c == 0xEDU) ? 0x9FU : 0xBFU;   /* no surrogates     */
	} else if ((c >= 0xF0U) && (c <= 0xF4U)) {
		n = 4U;
		lo = (c == 0xF0U) ? 0x90U : 0x80U;
		hi = (c == 0xF4U) ? 0x8FU : 0xBFU;   /* <= U+10FFFF        */
	} else {
		return 0U;
	}
	for (i = 1U; i < n; i++) {
		const unsigned char lim_lo = (i == 1U) ? lo : 0x80U;
		const unsigned char lim_hi = (i == 1U) ? hi : 0xBFU;

		if ((s[i] < lim_lo) || (s[i] > lim_hi)) { /* also stops at the NUL */
			return 0U;
		}
	}
	return n;
}

/* The two-character escape of a byte, or NULL: RFC 8259's " \\ and the
 * control characters that have one written out. */
static const char *short_escape(unsigned char c)
{
	static const struct {
		unsigned char c;
		const char *esc;
	} table[] = { { '"', "\\\"" }, { '\\', "\\\\" }, { '\n', "\\n" }, { '\t', "\\t" },
		      { '\r', "\\r" } };
	size_t i;

	for (i = 0U; i < sizeof(table) / sizeof(table[0]); i++) {
		if (table[i].c == c) {
			return table[i].esc;
		}
	}
	return NULL;
}

static void string_body(json_writer_t *w, const char *s)
{
	const unsigned char *p = (const unsigned char *)s;

	puts_(w, "\"");
	while (*p != 0U) {
		const size_t n = utf8_len(p);
		const char *short_esc = (n == 1U) ? short_escape(*p) : NULL;
		char esc[8];

		if (n == 0U) {
			puts_(w, "\\ufffd");
			p++;
		} else if (short_esc != NULL) {
			puts_(w, short_esc);
			p++;
		} else if ((*p < 0x20U) || (*p == 0x7FU)) {
			(void)snprintf(esc, sizeof(esc), "\\u%04x", (unsigned)*p);
			puts_(w, esc);
			p++;
		} else {
			put(w, (const char *)p, n);
			p += n;
		}
	}
	puts_(w, "\"");
}

void json_key(json_writer_t *w, const char *key)
{
	if (w->error) {
		return;
	}
	if ((w->depth == 0U) || !w->is_object[w->depth - 1U] || w->key_done || (key == NULL)) {
		w->error = true;
		return;
	}
	if (w->has_items[w->depth - 1U]) {
		puts_(w, ",");
	}
	w->has_items[w->depth - 1U] = true;
	string_body(w, key);
	puts_(w, ":");
	w->key_done = true;
}

void json_string(json_writer_t *w, const char *s)
{
	if (s == NULL) {
		json_null(w);
		return;
	}
	if (value_start(w)) {
		string_body(w, s);
	}
}

void json_u64(json_writer_t *w, uint64_t v)
{
	char buf[24];

	if (value_start(w)) {
		(void)snprintf(buf, sizeof(buf), "%" PRIu64, v);
		puts_(w, buf);
	}
}

void json_i64(json_writer_t *w, int64_t v)
{
	char buf[24];

	if (value_start(w)) {
		(void)snprintf(buf, sizeof(buf), "%" PRId64, v);
		puts_(w, buf);
	}
}

void json_double(json_writer_t *w, double v)
{
	char buf[32];

	if (!isfinite(v)) {
		json_null(w);
		return;
	}
	if (value_start(w)) {
		(void)snprintf(buf, sizeof(buf), "%.17g", v);
		puts_(w, buf);
	}
}

void json_fixed(json_writer_t *w, int64_t v, unsigned decimals)
{
	static const uint64_t pow10[10] = {
		1U, 10U, 100U, 1000U, 10000U, 100000U, 1000000U, 10000000U, 100000000U,
		1000000000U
	};
	char buf[40];
	uint64_t mag;

	if (decimals > 9U) {
		w->error = true;
		return;
	}
	if (!value_start(w)) {
		return;
	}
	/* magnitude without overflow, also for INT64_MIN */
	mag = (v < 0) ? (uint64_t)(-(v + 1)) + 1U : (uint64_t)v;
	(void)snprintf(buf, sizeof(buf), "%s%" PRIu64, (v < 0) ? "-" : "", mag / pow10[decimals]);
	puts_(w, buf);
	if (decimals > 0U) {
		uint64_t frac = mag % pow10[decimals];
		char digits[10];
		unsigned i;

		digits[0] = '.';
		for (i = decimals; i > 0U; i--) { /* fixed width: leading zeros kept */
			digits[i] = (char)('0' + (int)(frac % 10U));
			frac /= 10U;
		}
		put(w, digits, decimals + 1U);
	}
}

void json_bool(json_writer_t *w, bool v)
{
	if (value_start(w)) {
		puts_(w, v ? "true" : "false");
	}
}

void json_null(json_writer_t *w)
{
	if (value_start(w)) {
		puts_(w, "null");
	}
}

void json_kv_u64(json_writer_t *w, const char *key, uint64_t v)
{
	json_key(w, key);
	json_u64(w, v);
}

void json_kv_string(json_writer_t *w, const char *key, const char *s)
{
	json_key(w, key);
	json_string(w, s);
}

void json_kv_seconds(json_writer_t *w, const char *key, uint64_t us)
{
	json_key(w, key);
	if (us > (uint64_t)INT64_MAX) {
		w->error = true;
		return;
	}
	json_fixed(w, (int64_t)us, 6U);
}

bool json_writer_done(const json_writer_t *w)
{
	return !w->error && w->started && (w->depth == 0U);
}
