#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Negative control of tests/system/demo/test_demo.sh: with a good picture left
# from an earlier run in its output place, a demo that draws no picture must
# fail the picture checks (and only those). Prints "RESULT: N passed, M failed".
set -u
cd "$(dirname "$0")/../../.."
out=build/demo-control
# shellcheck source=tests/support/checks.sh
. tests/support/checks.sh
# a stale, valid picture: the one a real run draws
DEMO_OUT=$out tools/demo.sh >/dev/null 2>&1
check "setup: a real run leaves a picture" [ -s "$out/drive_map.png" ]
res=$(DEMO_TEST_OUT=$out DEMO_SCRIPT=tests/system/demo/demo-no-picture.sh tests/system/demo/test_demo.sh 2>&1)
rc=$?
echo "$res" | grep -E '^(FAILED|RESULT)' | sed 's/^/  | /'
check "no picture: test_demo fails (exit $rc)" [ "$rc" != 0 ]
check "no picture: 'picture written' fails" grep -qx 'FAILED: picture written' <<<"$res"
check "no picture: 'picture not blank' fails" grep -qx 'FAILED: picture not blank' <<<"$res"
check "no picture: nothing else fails" grep -qx 'RESULT: 3 passed, 2 failed' <<<"$res"
checks_done
