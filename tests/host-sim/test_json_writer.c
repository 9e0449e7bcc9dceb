/* SPDX-License-Identifier: MIT */
/*
 * host-sim/json_writer.c: exact output for hand-derived cases (escapes,
 * UTF-8 kept or replaced, fixed-point numbers, commas), and every misuse
 * sets the sticky error instead of writing broken JSON. (Whole documents are
 * parsed by Python's json module in tests/host-sim/test_replay_summary.py.)
 */
#include <setjmp.h>
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "json_writer.h"

typedef struct {
	char *buf;
	size_t len;
	FILE *f;
	json_writer_t w;
} sink_t;

static void open_sink(sink_t *s)
{
	memset(s, 0, sizeof(*s));
	s->f = open_memstream(&s->buf, &s->len);
	assert_non_null(s->f);
	json_writer_init(&s->w, s->f);
}

static void close_sink(sink_t *s, const char *want)
{
	assert_int_equal(fclose(s->f), 0);
	if (want != NULL) {
		assert_string_equal(s->buf, want);
	}
	free(s->buf);
}

static void test_document(void **state)
{
	sink_t s;

	(void)state;
	open_sink(&s);
	json_begin_object(&s.w);
	json_kv_u64(&s.w, "n", UINT64_MAX);
	json_key(&s.w, "a");
	json_begin_array(&s.w);
	json_i64(&s.w, INT64_MIN);
	json_null(&s.w);
	json_bool(&s.w, true);
	json_double(&s.w, 0.5);
	json_double(&s.w, (double)NAN);
	json_begin_object(&s.w);
	json_end_object(&s.w);
	json_end_array(&s.w);
	json_kv_seconds(&s.w, "t", 1234567U);
	json_end_object(&s.w);
	assert_true(json_writer_done(&s.w));
	close_sink(&s, "{\"n\":18446744073709551615,\"a\":[-9223372036854775808,null,true,0.5,null,{}],"
		       "\"t\":1.234567}\n");
}

static void test_fixed(void **state)
{
	sink_t s;

	(void)state;
	open_sink(&s);
	json_begin_array(&s.w);
	json_fixed(&s.w, -5, 2);        /* -0.05 */
	json_fixed(&s.w, 90000, 1);     /* 9000.0 */
	json_fixed(&s.w, 7, 0);
	json_fixed(&s.w, INT64_MIN, 9);
	json_fixed(&s.w, 0, 6);
	json_end_array(&s.w);
	assert_true(json_writer_done(&s.w));
	close_sink(&s, "[-0.05,9000.0,7,-9223372036.854775808,0.000000]\n");
}

static void test_strings(void **state)
{
	sink_t s;

	(void)state;
	open_sink(&s);
	json_begin_array(&s.w);
	json_string(&s.w, "q\"b\\s/n\nt\tr\rc\x01\x1f" "d\x7f");
	json_string(&s.w, "\xc3\xa4\xe2\x82\xac\xf0\x9f\x98\x80");   /* ä € 😀 kept */
	json_string(&s.w, "\xff|\xc0\xaf|\xed\xa0\x80|\xf4\x90\x80\x80|\xe2\x82"); /* invalid */
	json_string(&s.w, NULL);
	json_end_array(&s.w);
	assert_true(json_writer_done(&s.w));
	close_sink(&s, "[\"q\\\"b\\\\s/n\\nt\\tr\\rc\\u0001\\u001fd\\u007f\","
		       "\"\xc3\xa4\xe2\x82\xac\xf0\x9f\x98\x80\","
		       "\"\\ufffd|\\ufffd\\ufffd|\\ufffd\\ufffd\\ufffd|\\ufffd\\ufffd\\ufffd\\ufffd|"
		       "\\ufffd\\ufffd\","
		       "null]\n");
}

typedef void (*misuse_fn)(json_writer_t *w);

static void m_value_for_key(json_writer_t *w) { json_begin_object(w); json_u64(w, 1U); }
static void m_key_in_array(json_writer_t *w) { json_begin_array(w); json_key(w, "k"); }
static void m_key_twice(json_writer_t *w) { json_begin_object(w); json_key(w, "a"); json_key(w, "b"); }
static void m_close_wrong(json_writer_t *w) { json_begin_object(w); json_end_array(w); }
static void m_close_none(json_writer_t *w) { json_end_object(w); }
static void m_close_after_key(json_writer_t *w) { json_begin_object(w); json_key(w, "a"); json_end_object(w); }
static void m_two_tops(json_writer_t *w) { json_null(w); json_null(w); }
static void m_decimals(json_writer_t *w) { json_fixed(w, 1, 10U); }
static void m_null_key(json_writer_t *w) { json_begin_object(w); json_key(w, NULL); }
static void m_too_deep(json_writer_t *w)
{
	unsigned i;

	for (i = 0U; i <= JSON_MAX_DEPTH; i++) {
		json_begin_array(w);
	}
}

static void test_misuse(void **state)
{
	static const misuse_fn cases[] = {
		m_value_for_key, m_key_in_array, m_key_twice, m_close_wrong, m_close_none,
		m_close_after_key, m_two_tops, m_decimals, m_null_key, m_too_deep
	};
	size_t i;

	(void)state;
	for (i = 0U; i < sizeof(cases) / sizeof(cases[0]); i++) {
		sink_t s;
		size_t before;

		open_sink(&s);
		cases[i](&s.w);
		assert_true(s.w.error);
		assert_false(json_writer_done(&s.w));
		(void)fflush(s.f);
		before = s.len;
		json_u64(&s.w, 42U); /* sticky: nothing more is written */
		(void)fflush(s.f);
		assert_int_equal(s.len, before);
		close_sink(&s, NULL);
	}
}

static void test_depth_limit_exact(void **state)
{
	sink_t s;
	unsigned i;

	(void)state;
	open_sink(&s);
	for (i = 0U; i < JSON_MAX_DEPTH; i++) {
		json_begin_array(&s.w);
	}
	for (i = 0U; i < JSON_MAX_DEPTH; i++) {
		json_end_array(&s.w);
	}
	assert_true(json_writer_done(&s.w));
	close_sink(&s, "[[[[[[[[[[[[[[[[]]]]]]]]]]]]]]]]\n");
}

static void test_write_error(void **state)
{
	json_writer_t w;
	FILE *f = fopen("/dev/full", "w");

	(void)state;
	if (f == NULL) {
		skip();
	}
	(void)setvbuf(f, NULL, _IONBF, 0);
	json_writer_init(&w, f);
	json_begin_object(&w);
	json_end_object(&w);
	assert_true(w.error);
	assert_false(json_writer_done(&w));
	(void)fclose(f);
	json_writer_init(&w, NULL);
	assert_true(w.error);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_document),
		cmocka_unit_test(test_fixed),
		cmocka_unit_test(test_strings),
		cmocka_unit_test(test_misuse),
		cmocka_unit_test(test_depth_limit_exact),
		cmocka_unit_test(test_write_error),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
