#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Instructions per 1 ms task, measured with callgrind on the host builds
# (-O2, no sanitizers) of tests/firmware/monitor/bench_monitor_step.c: one callgrind
# dump per poll, so every dump is the cost of exactly one call.
#   squeal_app_poll: RX drain + E2E + conditioning + monitor_step + TX
#   monitor_step_slot: staleness, classification, debounce, TX scheduling (all
#                    corners of one step together)
# x86-64 instruction counts: a figure for comparison, not Cortex-M cycles.
# Usage: tests/firmware/monitor/bench_monitor_cost.sh   (make builds the drivers first)
set -eu
if ! command -v valgrind >/dev/null; then
	echo "valgrind not installed: skipped"
	exit 0
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# "corners 4": the same drive with four corners on the same frames (the
# worst step: one corner classifies, all four receive, tick and send).
# "sigma": the calibration carries standard deviations: every
# classification also propagates them.
for run in "host 1" "host-fixed 1" "host 4" "host-fixed 4" \
	   "host 1 sigma" "host-fixed 1 sigma" "host 4 sigma" "host-fixed 4 sigma"; do
	set -- $run
	v=$1
	corners=$2
	extra=${3:-}
	prog=build/$v/tests/firmware/monitor/bench_monitor_step
	for fn in squeal_app_poll monitor_step_slot; do
		rm -f "$tmp"/cg.*
		valgrind --tool=callgrind --collect-atstart=no --toggle-collect="$fn" \
			--callgrind-out-file="$tmp/cg.out" "$prog" "$corners" $extra >"$tmp/stdout" 2>"$tmp/stderr"
		# each dump file's total: the "totals:" (or "summary:") line
		# (dump number d is poll d, at T0 + (d - 1) ms); one grep over
		# all files (one awk per file took minutes for 7611 dumps)
		find "$tmp" -name 'cg.out.*' -print0 |
			xargs -0 grep -H -m1 -E '^(totals|summary):' |
			sed -E 's/^.*cg\.out\.([0-9]+):[a-z]+: *([0-9]+).*$/\2 \1/' | sort -n -k2 | awk -v v="$v" -v fn="$fn" -v c="$corners" -v x="$extra" '
			$1 > 0 { n++; s += $1; if ($1 > max) { max = $1; at = $2 }
				 if (min == 0 || $1 < min) min = $1 }
			END { printf "%-10s %u corner%s %-5s %-16s calls %5d  mean %7.0f  min %6d  max %7d instructions (poll %d)\n",
			      v, c, (c == 1) ? " " : "s", x, fn, n, s / n, min, max, at }'
	done
	sed 's/^/           /' "$tmp/stdout"
done
