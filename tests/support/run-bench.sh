#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Runs the benchmark programs given (make bench: BENCH_PROGS; make bench-full:
# BENCH_PROGS and BENCH_FULL_PROGS), each under "== PROG", and ends with
# the wall and CPU seconds of each: the figures never pass or fail, only a
# program that cannot run stops the run (its exit status).
# On a terminal (stderr a tty) a line before each program says done/total,
# the time so far and about how long is left (from the last run's times in
# build/bench-times.txt); in a log (not a tty) there is no progress line.
set -u
times_file=${BENCH_TIMES:-build/bench-times.txt}
mkdir -p "$(dirname "$times_file")"
declare -A last=()
if [ -f "$times_file" ]; then
	while read -r prog wall _; do last[$prog]=$wall; done <"$times_file"
fi
tty=0
[ -t 2 ] && tty=1
total=$#
done_n=0
start=$SECONDS
rows=()
# the programs write to fds 3 and 4 (this stdout and stderr); the time report to the pipe
exec 3>&1 4>&2
fmt() { printf '%d:%02d' $(($1 / 60)) $(($1 % 60)); }
for prog in "$@"; do
	if [ "$tty" = 1 ]; then
		left=0 known=1
		for p in "${@:done_n+1}"; do
			if [ -n "${last[$p]:-}" ]; then left=$((left + ${last[$p]%.*})); else known=0; fi
		done
		msg="bench $((done_n + 1))/$total, $(fmt $((SECONDS - start))) so far"
		if [ "$known" = 1 ]; then msg="$msg, about $(fmt "$left") left"; fi
		echo "-- $msg: $prog" >&2
	fi
	echo "== $prog"
	TIMEFORMAT='%R %U %S'
	t=$( { time "$prog" >&3 2>&4; } 2>&1 )
	rc=$?
	read -r wall user sys <<<"$t"
	[ "$rc" = 0 ] || { echo "run-bench.sh: $prog failed (exit $rc)" >&2; exit "$rc"; }
	rows+=("$prog $wall $(awk -v u="$user" -v s="$sys" 'BEGIN { printf "%.2f", u + s }')")
	done_n=$((done_n + 1))
done
echo "== times (wall s, CPU s of the program and its children; load $(cut -d' ' -f1-3 /proc/loadavg))"
for r in "${rows[@]}"; do
	read -r p w c <<<"$r"
	printf '  %-60s %8.1f %8.1f\n' "$p" "$w" "$c"
done
echo "  total $(fmt $((SECONDS - start)))"
# this run's times become the estimate of the next one
{
	for r in "${rows[@]}"; do echo "$r"; done
	for p in "${!last[@]}"; do
		printf '%s\n' "${rows[@]}" | grep -q "^$p " || echo "$p ${last[$p]} -"
	done
} >"$times_file.new" && mv "$times_file.new" "$times_file"
