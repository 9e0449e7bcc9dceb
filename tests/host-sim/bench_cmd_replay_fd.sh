#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# make bench: replay throughput of CAN FD traffic beside classic traffic, one
# run each on logs of the same size and rate (tests/host-sim/gen_vehicle_traffic.py):
#   classic  the input map of tests/firmware/monitor/fixtures/moto15_p02.cal (8-byte frames,
#            P02) among 40 other ECUs' 8-byte frames;
#   FD       the FD layout of tests/host-sim/fd_p05.cal (24- and 32-byte FD
#            frames, P05) among the same 40 ECUs sending 64-byte FD frames.
# squeal-sim replay --calib, release build, with and without frame output;
# frames/s on CPU time (user + sys). Builds nothing (make bench builds
# build/host/squeal-sim first). BENCH_FD_FRAMES sets the log size (500000).
set -euo pipefail
cd "$(dirname "$0")/../.."
SIM=build/host/squeal-sim
PY=${PYTHON:-/usr/bin/python3}
N=${BENCH_FD_FRAMES:-500000}
DIR=build/replay-bench-fd
mkdir -p "$DIR"

gen() { # calib out [--fd-bytes N]
	local cal=$1 out=$2
	shift 2
	if [ ! -s "$out" ] || [ tests/host-sim/gen_vehicle_traffic.py -nt "$out" ] || [ "$cal" -nt "$out" ]; then
		"$PY" tests/host-sim/gen_vehicle_traffic.py --calib "$cal" --frames "$N" --out "$out" \
			--sim "$SIM" "$@" >"$out.gen.txt"
	fi
}

cpu_s() { # command... -> CPU seconds of one run
	/usr/bin/time -f '%U %S' -o "$DIR/t.txt" "$@" >/dev/null 2>&1
	awk '{printf "%.2f", $1 + $2}' "$DIR/t.txt"
}

CCAL=tests/firmware/monitor/fixtures/moto15_p02.cal
FCAL=tests/host-sim/fd_p05.cal
gen "$CCAL" "$DIR/classic.log"
gen "$FCAL" "$DIR/fd.log" --fd-bytes 64
echo "                         CPU s    frames/s (CPU)   input"
for case in classic fd; do
	cal=$CCAL
	[ "$case" = fd ] && cal=$FCAL
	log=$DIR/$case.log
	n=$(wc -l <"$log")
	sum=$("$SIM" replay --calib "$cal" --no-output "$log" 2>&1 >/dev/null)
	read_fd=$(awk '$1 == "frames_read" {print $0}' <<<"$sum" | sed 's/^ *//')
	used=$(awk '$1 == "frames_used" {print $2}' <<<"$sum")
	for out in output no-output; do
		if [ "$out" = output ]; then
			t=$(cpu_s "$SIM" replay --calib "$cal" "$log")
		else
			t=$(cpu_s "$SIM" replay --calib "$cal" --no-output "$log")
		fi
		printf '%-8s replay %-10s %7s %14s   %s frames, %s MB; %s; used %s\n' "$case" "$out" "$t" \
			"$(awk -v n="$n" -v t="$t" 'BEGIN {printf "%.0f", n / t}')" "$n" \
			"$(du -m "$log" | cut -f1)" "$read_fd" "$used"
	done
done
