#!/bin/sh
# SPDX-License-Identifier: MIT
# make bench: the live path on vcan0 in the QEMU guest (emulated time):
# input-frame-to-status-frame latency (median, p99), idle and beside a
# flood, and the highest input rate the ECU takes with zero loss against
# plain candump on the same flood (ratio). About 60-70 s.
set -eu
cd "$(dirname "$0")/../../.."
make -s build/host/squeal-sim
out=$(mktemp -d "${TMPDIR:-/tmp}/sq-bench.XXXXXX")
trap 'rm -rf "$out"' EXIT
tests/system/vcan/guest.sh --timeout 170 --run tests/system/integration/guest-bench.sh \
	--add build/host/squeal-sim --add tests/system/integration --out "$out" -- 5
exec /usr/bin/python3 tests/system/integration/bench_live.py "$out"
