#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Negative control of tests/protocol/test_unpack_crosscheck.py: an unpacker
# that returns one wrong bit, or accepts a frame it must refuse, fails it.
# Prints "RESULT: N passed, M failed".
set -u
cd "$(dirname "$0")/../.."
pass=0; fail=0
check() { # description, condition...
	local d=$1; shift
	if "$@"; then pass=$((pass + 1)); echo "PASS: $d"; else fail=$((fail + 1)); echo "FAIL: $d"; fi
}
for defect in bit accept; do
	out=$(UNPACK_RANDOM=tests/protocol/unpack-random-wrong.sh UNPACK_DEFECT=$defect \
		tests/protocol/test_unpack_crosscheck.py 2>/dev/null)
	rc=$?
	echo "$out" | grep -E '^(FAIL|RESULT)' | head -3 | sed "s/^/  $defect | /"
	check "$defect: the cross-check fails (exit $rc)" [ "$rc" != 0 ]
	check "$defect: it names the frame" grep -qE '^FAIL: (DiscSpeed|PadForce) [0-9A-F]+' <<<"$out"
done
echo "RESULT: $pass passed, $fail failed"
[ "$fail" = 0 ]
