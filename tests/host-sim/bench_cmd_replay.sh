#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# make bench: offline replay throughput against the script an engineer would
# otherwise write (python-can + canmatrix, tests/support/pydecode.py), in one
# run on the same 1,000,000-frame log:
#   - input log: DiscSpeed + PadForce, each every 10 ms (5,000 s virtual),
#     E2E-protected, generated into build/replay-bench/ (not committed);
#   - squeal-sim replay (release build): the firmware runs every 1 ms tick
#     (5,000,000 ticks) and writes ~3M output frames to /dev/null;
#   - replay --no-output: the same run without formatting and
#     writing the frames, and with --summary-json (the fleet's job);
#   - squeal-sim decode: the same log to physical values (like for like with
#     the Python script);
#   - times: median of RUNS (default 3) wall-clock runs each;
#   - peak RSS of replay for 10^5 and 10^6 frames (/usr/bin/time, else the
#     summary's VmHWM): constant memory means both are the same.
#   - a vehicle-layout log (most frames on other identifiers) replayed with
#     --calib, with and without frame output (at the end).
# Builds nothing: make bench builds build/host/squeal-sim first.
set -euo pipefail
cd "$(dirname "$0")/../.."
SIM=build/host/squeal-sim
PY=${PYTHON:-/usr/bin/python3}
RUNS=${BENCH_REPLAY_RUNS:-3}
PY_RUNS=${BENCH_REPLAY_PY_RUNS:-3}
DIR=build/replay-bench
mkdir -p "$DIR"

gen() { # frames file
	if [ ! -s "$2" ] || [ tests/host-sim/gen_inputs.py -nt "$2" ]; then
		"$PY" tests/host-sim/gen_inputs.py --frames "$1" --out "$2" 2>/dev/null
	fi
}
gen 100000 "$DIR/in-1e5.log"
gen 1000000 "$DIR/in-1e6.log"
LOG=$DIR/in-1e6.log
N=$(wc -l <"$LOG")

# "WALL CPU": medians over $1 runs of wall-clock and CPU (user + sys)
# seconds. The machine may be shared: CPU time is the steadier figure.
median_s() {
	local runs=$1
	shift
	local out="$DIR/times.txt"
	: >"$out"
	for _ in $(seq "$runs"); do
		if [ -x /usr/bin/time ]; then
			/usr/bin/time -f '%e %U %S' -o "$DIR/t.txt" "$@" >/dev/null 2>&1
			awk '{printf "%s %.2f\n", $1, $2 + $3}' "$DIR/t.txt" >>"$out"
		else
			local t0 t1
			t0=$(date +%s.%N)
			"$@" >/dev/null 2>&1
			t1=$(date +%s.%N)
			awk -v a="$t0" -v b="$t1" 'BEGIN {printf "%.3f %.3f\n", b - a, b - a}' >>"$out"
		fi
	done
	w=$(sort -g -k1 "$out" | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
	c=$(sort -g -k2 "$out" | awk '{a[NR]=$2} END {print a[int((NR+1)/2)]}')
	echo "$w $c"
}

echo "input: $LOG ($N frames, $(du -h "$LOG" | cut -f1))"
read -r rep_w rep <<<"$(median_s "$RUNS" "$SIM" replay "$LOG")"
# Without the frame output (only the summary is wanted)
read -r nout_w nout <<<"$(median_s "$RUNS" "$SIM" replay --no-output "$LOG")"
read -r njs_w njs <<<"$(median_s "$RUNS" "$SIM" replay --no-output --summary-json "$DIR/summary.json" "$LOG")"
read -r dec_w dec <<<"$(median_s "$RUNS" "$SIM" decode "$LOG")"
read -r py_w py <<<"$(median_s "$PY_RUNS" "$PY" tests/support/pydecode.py "$LOG")"
outn=$("$SIM" replay "$LOG" 2>/dev/null | wc -l)

fps() { awk -v n="$N" -v t="$1" 'BEGIN {printf "%.0f", n / t}'; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN {printf "%.1f", a / b}'; }
echo "                          CPU s   frames/s (CPU)   wall s  (medians)"
printf 'squeal-sim replay      %8.2f %14s %10.2f  (%s runs; %s output frames)\n' \
	"$rep" "$(fps "$rep")" "$rep_w" "$RUNS" "$outn"
printf 'replay --no-output     %8.2f %14s %10.2f  (%s runs; frames counted, not written)\n' \
	"$nout" "$(fps "$nout")" "$nout_w" "$RUNS"
printf 'replay --no-output +JSON %7.2f %14s %10.2f  (%s runs; --summary-json FILE)\n' \
	"$njs" "$(fps "$njs")" "$njs_w" "$RUNS"
printf 'speedup without output %8s x (CPU), %s x (wall)\n' "$(ratio "$rep" "$nout")" "$(ratio "$rep_w" "$nout_w")"
printf 'squeal-sim decode      %8.2f %14s %10.2f  (%s runs)\n' "$dec" "$(fps "$dec")" "$dec_w" "$RUNS"
printf 'python-can+canmatrix   %8.2f %14s %10.2f  (%s runs, pydecode.py)\n' \
	"$py" "$(fps "$py")" "$py_w" "$PY_RUNS"
printf 'ratio replay / python  %8s x (CPU), %s x (wall)\n' "$(ratio "$py" "$rep")" "$(ratio "$py_w" "$rep_w")"
printf 'ratio decode / python  %8s x (CPU), %s x (wall)\n' "$(ratio "$py" "$dec")" "$(ratio "$py_w" "$dec_w")"

for f in "$DIR/in-1e5.log" "$DIR/in-1e6.log"; do
	n=$(wc -l <"$f")
	if [ -x /usr/bin/time ]; then
		/usr/bin/time -f '%M' -o "$DIR/rss.txt" "$SIM" replay "$f" >/dev/null 2>&1
		kb=$(tail -1 "$DIR/rss.txt")
		how="/usr/bin/time %M"
	else
		kb=$("$SIM" replay --rss "$f" 2>&1 >/dev/null | awk '/peak_rss_kb/ {print $2}')
		how="VmHWM"
	fi
	printf 'replay peak RSS %8s frames: %6s kB (%s)\n' "$n" "$kb" "$how"
done

# Real vehicle traffic (the replay's target "about 4 M frames/s where most frames have
# other identifiers"): a vehicle-layout log, 1,000,000 frames, the input map
# of tests/firmware/monitor/fixtures/moto15_p02.cal (four corners, wheel speeds every 10 ms,
# P02 pressure every 20 ms) among 40 other ECUs' identifiers
# (tests/host-sim/gen_vehicle_traffic.py); replayed with --calib: the other
# identifiers stop at the controller's filters (filtered_ids).
VCAL=tests/firmware/monitor/fixtures/moto15_p02.cal
VLOG=$DIR/vehicle-1e6.log
if [ ! -s "$VLOG" ] || [ tests/host-sim/gen_vehicle_traffic.py -nt "$VLOG" ] || [ "$VCAL" -nt "$VLOG" ]; then
	"$PY" tests/host-sim/gen_vehicle_traffic.py --calib "$VCAL" --frames 1000000 --out "$VLOG" --sim "$SIM" \
		>"$DIR/vehicle-gen.txt"
fi
VN=$(wc -l <"$VLOG")
VOWN=$("$SIM" replay --calib "$VCAL" --no-output "$VLOG" 2>&1 | awk '/frames_used/ {print $2}')
echo "vehicle input: $VLOG ($VN frames, $VOWN on the input map's identifiers, $VCAL)"
read -r vrep_w vrep <<<"$(median_s "$RUNS" "$SIM" replay --calib "$VCAL" "$VLOG")"
read -r vnout_w vnout <<<"$(median_s "$RUNS" "$SIM" replay --calib "$VCAL" --no-output "$VLOG")"
vfps() { awk -v n="$VN" -v t="$1" 'BEGIN {printf "%.0f", n / t}'; }
printf 'vehicle replay         %8.2f %14s %10.2f  (%s runs; replay --calib, 4 corners)\n' \
	"$vrep" "$(vfps "$vrep")" "$vrep_w" "$RUNS"
printf 'vehicle --no-output    %8.2f %14s %10.2f  (%s runs)\n' "$vnout" "$(vfps "$vnout")" "$vnout_w" "$RUNS"
