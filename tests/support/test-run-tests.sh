#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Self-test of tests/run-tests.sh: fake test programs that pass, fail and
# skip (SKIP: lines, "RESULT: ... K skipped", cmocka's [  SKIPPED ]) must
# give the right "N passed, N failed, N skipped" line, name every skip, and
# with CI=true fail on a skip not listed in the expected-skips file.
# Prints "RESULT: N passed, M failed".
set -u
cd "$(dirname "$0")/../.."
tmp=$(mktemp -d build/run-tests-selftest.XXXXXX 2>/dev/null || { mkdir -p build; mktemp -d build/run-tests-selftest.XXXXXX; })
trap 'rm -rf "$tmp"' EXIT
# shellcheck source=tests/support/checks.sh
. tests/support/checks.sh
fake() { # name, body
	printf '#!/bin/sh\n%s\n' "$2" >"$tmp/$1"; chmod +x "$tmp/$1"
}
fake skips 'echo "ok 1"; echo "SKIP: gadget check (no gadget here)"; echo "SKIP: widget check (no widget)"
echo "RESULT: 3 passed, 0 failed, 2 skipped"'
fake skiplines 'echo "SKIP: lone check (reason)"; exit 0'
fake unnamed 'echo "RESULT: 1 passed, 0 failed, 1 skipped"'
fake cmocka 'printf "%s\n" "[ RUN      ] t_a" "[       OK ] t_a" "[ RUN      ] t_b" "[  SKIPPED ] t_b" \
"[==========] 2 test(s) run." "[  PASSED  ] 1 test(s)." "[  SKIPPED ] 1 test(s), listed below:" "[  SKIPPED ] t_b"'
fake fails 'echo "RESULT: 1 passed, 1 failed"; exit 1'
printf '%s\n' "# program | what (glob) | reason" \
	"*/skips | gadget check * | no gadget on this host" \
	"*/skiplines | lone check* | the lone one" \
	"*/cmocka | t_b | cmocka skip" \
	"*/skips | widget check * |" >"$tmp/expected"

run() { # out-file, env..., programs...
	local o=$1; shift
	env TEST_LOGDIR="$tmp/logs" EXPECTED_SKIPS="$tmp/expected" "$@" >"$o" 2>&1
}
last() { tail -n 1 "$1"; }

run "$tmp/all" CI= tests/run-tests.sh "$tmp/skips" "$tmp/skiplines" "$tmp/unnamed" "$tmp/cmocka" "$tmp/fails"
echo "--- all (not CI):"; sed 's/^/  | /' "$tmp/all"
check "summary counts passed, failed and skipped (got: $(last "$tmp/all"))" \
	[ "$(last "$tmp/all")" = "7 passed, 1 failed, 5 skipped" ]
check "every skip named in the output" grep -q 'SKIP .*/skips: widget check (no widget)' "$tmp/all"
check "cmocka skip named once" [ "$(grep -c 'SKIP .*/cmocka: t_b' "$tmp/all")" = 1 ]
check "counted but unnamed skip listed" grep -q 'SKIP .*/unnamed: (unnamed skip)' "$tmp/all"
check "skips listed in the log" [ "$(wc -l <"$tmp/logs/skips.txt")" = 5 ]

run "$tmp/ci-ok" CI=true tests/run-tests.sh "$tmp/skiplines" "$tmp/cmocka"
echo "--- CI, expected skips only:"; sed 's/^/  | /' "$tmp/ci-ok"
check "CI: expected skips pass (got: $(last "$tmp/ci-ok"))" \
	[ "$(last "$tmp/ci-ok")" = "2 passed, 0 failed, 2 skipped" ]

run "$tmp/ci-bad" CI=true tests/run-tests.sh "$tmp/skips" "$tmp/unnamed"
rc=$?
echo "--- CI, unexpected skips:"; sed 's/^/  | /' "$tmp/ci-bad"
check "CI: an unexpected skip fails the run (exit $rc)" [ "$rc" != 0 ]
check "CI: a row without a reason covers nothing; unnamed skip unexpected (got: $(last "$tmp/ci-bad"))" \
	[ "$(last "$tmp/ci-bad")" = "4 passed, 2 failed, 1 skipped" ]
check "CI: the unexpected skip is named" grep -q '^  .*/skips: widget check (no widget)' "$tmp/ci-bad"
checks_done
