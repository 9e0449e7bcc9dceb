#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Instructions per 1 ms task, measured with callgrind on the host builds
# (-O2, no sanitizers) of tests/monitor/monitor_step_cost.c: one callgrind
# dump per poll, so every dump is the cost of exactly one call.
#   squeal_app_poll: RX drain + E2E + conditioning + monitor_step + TX
#   monitor_step:    staleness, classification, debounce, TX scheduling
# x86-64 instruction counts: a figure for comparison, not Cortex-M cycles.
# Usage: tests/monitor/monitor-cost.sh   (make builds the drivers first)
set -eu
if ! command -v valgrind >/dev/null; then
	echo "valgrind not installed: skipped"
	exit 0
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for v in host host-fixed; do
	prog=build/$v/monitor_step_cost
	for fn in squeal_app_poll monitor_step; do
		rm -f "$tmp"/cg.*
		valgrind --tool=callgrind --collect-atstart=no --toggle-collect="$fn" \
			--callgrind-out-file="$tmp/cg.out" "$prog" >"$tmp/stdout" 2>"$tmp/stderr"
		# each dump file's total: the "totals:" (or "summary:") line
		# (dump number d is poll d, at T0 + (d - 1) ms)
		for f in "$tmp"/cg.out.*; do
			awk -v d="${f##*.}" '/^(totals|summary):/ {print $2, d; exit}' "$f"
		done | awk -v v="$v" -v fn="$fn" '
			$1 > 0 { n++; s += $1; if ($1 > max) { max = $1; at = $2 }
				 if (min == 0 || $1 < min) min = $1 }
			END { printf "%-10s %-16s calls %5d  mean %7.0f  min %6d  max %7d instructions (poll %d)\n",
			      v, fn, n, s / n, min, max, at }'
	done
	sed 's/^/           /' "$tmp/stdout"
done
