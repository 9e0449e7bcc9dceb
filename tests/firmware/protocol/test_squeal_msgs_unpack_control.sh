#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Negative control of tests/firmware/protocol/test_squeal_msgs_unpack.py: an unpacker
# that returns one wrong bit, or accepts a frame it must refuse, fails it.
# Prints "RESULT: N passed, M failed".
set -u
cd "$(dirname "$0")/../../.."
# shellcheck source=tests/support/checks.sh
. tests/support/checks.sh
for defect in bit accept; do
	out=$(UNPACK_RANDOM=tests/firmware/protocol/unpack-random-wrong.sh UNPACK_DEFECT=$defect \
		tests/firmware/protocol/test_squeal_msgs_unpack.py 2>/dev/null)
	rc=$?
	echo "$out" | grep -E '^(FAIL|RESULT)' | head -3 | sed "s/^/  $defect | /"
	check "$defect: the cross-check fails (exit $rc)" [ "$rc" != 0 ]
	check "$defect: it names the frame" grep -qE '^FAIL: (DiscSpeed|PadForce) [0-9A-F]+' <<<"$out"
done
checks_done
