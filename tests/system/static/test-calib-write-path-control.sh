#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Negative control of tests/system/static/check-calib-write-path.sh: an ECU image
# that does not exist must be a counted skip (named, "1 skipped") and, with
# CI=true, a failure; never a silent line. Prints "RESULT: N passed, M failed".
set -u
cd "$(dirname "$0")/../../.."
# shellcheck source=tests/support/checks.sh
. tests/support/checks.sh
missing=build/no-such-dir/squeal-monitor.elf
out=$(CI= CALIB_ELFS=$missing tests/system/static/check-calib-write-path.sh 2>&1)
rc=$?
echo "$out" | sed 's/^/  local | /'
check "missing image: named skip" grep -q "^SKIP: $missing .*not built" <<<"$out"
check "missing image: counted (RESULT ... 1 skipped)" grep -qE '^RESULT: [0-9]+ passed, 0 failed, 1 skipped$' <<<"$out"
check "missing image outside CI: exit 0 (exit $rc)" [ "$rc" = 0 ]
out=$(CI=true CALIB_ELFS=$missing tests/system/static/check-calib-write-path.sh 2>&1)
rc=$?
echo "$out" | sed 's/^/  CI    | /'
check "missing image in CI: a failure naming it" grep -q "^FAIL $missing built" <<<"$out"
check "missing image in CI: RESULT 1 failed, 0 skipped" grep -qE '^RESULT: [0-9]+ passed, 1 failed, 0 skipped$' <<<"$out"
check "missing image in CI: exit non-zero (exit $rc)" [ "$rc" != 0 ]
checks_done
