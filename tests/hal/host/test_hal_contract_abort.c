/* SPDX-License-Identifier: MIT */
/*
 * The host's contract handler (hal/host/hal_contract_abort.c): a
 * programming error prints "FILE:LINE: contract violated (programming
 * error)" on stderr and aborts (SIGABRT), for a direct call, a NULL file
 * name ("?") and HAL_REQUIRE() itself. Each case runs in a child process;
 * the parent reads its stderr through a pipe and its end from waitpid().
 */
#include <setjmp.h>
#include <signal.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "sq_contract.h"

typedef void (*violation_fn)(void);

/* Runs fn in a child with stderr on a pipe: *text gets what it printed,
 * the result is its wait status. */
static int run_child(violation_fn fn, char *text, size_t cap)
{
	int fds[2];
	pid_t child;
	int status = 0;
	size_t len = 0;
	ssize_t n;

	assert_int_equal(pipe(fds), 0);
	child = fork();
	assert_true(child >= 0);
	if (child == 0) {
		(void)close(fds[0]);
		(void)dup2(fds[1], STDERR_FILENO);
		fn();
		_exit(0); /* not reached: the handler never returns */
	}
	(void)close(fds[1]);
	while (len + 1U < cap && (n = read(fds[0], text + len, cap - 1U - len)) > 0) {
		len += (size_t)n;
	}
	text[len] = '\0';
	(void)close(fds[0]);
	assert_int_equal(waitpid(child, &status, 0), child);
	return status;
}

static void direct_call(void)
{
	hal_contract_failed("firmware/monitor/example.c", 42U);
}

static void null_file(void)
{
	hal_contract_failed(NULL, 7U);
}

static void require_false(void)
{
	volatile int zero = 0;

	HAL_REQUIRE(zero != 0);
}
enum { REQUIRE_LINE = __LINE__ - 2 }; /* the HAL_REQUIRE's line, two above */

static void assert_aborted(int status)
{
	assert_true(WIFSIGNALED(status));
	assert_int_equal(WTERMSIG(status), SIGABRT);
}

static void test_prints_file_and_line_then_aborts(void **state)
{
	char text[256];

	(void)state;
	assert_aborted(run_child(direct_call, text, sizeof(text)));
	assert_string_equal(text, "firmware/monitor/example.c:42: contract violated (programming error)\n");
}

static void test_null_file_prints_a_question_mark(void **state)
{
	char text[256];

	(void)state;
	assert_aborted(run_child(null_file, text, sizeof(text)));
	assert_string_equal(text, "?:7: contract violated (programming error)\n");
}

static void test_hal_require_names_its_own_line(void **state)
{
	char text[256];
	char want[256];

	(void)state;
	assert_aborted(run_child(require_false, text, sizeof(text)));
	(void)snprintf(want, sizeof(want), "%s:%d: contract violated (programming error)\n",
		       __FILE__, REQUIRE_LINE);
	assert_string_equal(text, want);
}

SQ_CMOCKA_MAIN(
	cmocka_unit_test(test_prints_file_and_line_then_aborts),
	cmocka_unit_test(test_null_file_prints_a_question_mark),
	cmocka_unit_test(test_hal_require_names_its_own_line))
