#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Benchmark of the squeal model in both numeric builds (make bench builds
# build/host/tests/firmware/model/bench_squeal_model and build/host-fixed/tests/firmware/model/bench_squeal_model; this script builds
# nothing). Prints one table:
#   build | criterion | ns/call median (min..max) | instructions/call |
#   brute-force ns/decision | brute/closed-form
# ns/call: ROUNDS rounds, each running the float then the fixed binary for
#   REPEATS repeats of CALLS calls per criterion (criteria interleaved inside
#   a run, builds interleaved across rounds), pooled per build and criterion.
# instructions/call: valgrind callgrind, (Ir(N calls) - Ir(0 calls)) / N, so
#   start-up and the set-up of the points are not counted.
# brute force: the mean time to decide one of BRUTE points with Q > 1/2 by
#   backward integration (tests/support/brute_force.c; the same for both
#   builds, it is double precision); ratio = that / the closed-form median.
# Figures only: the exit code is 0 unless a program fails to run.
set -euo pipefail
cd "$(dirname "$0")/../../.."

ROUNDS=${ROUNDS:-3}
REPEATS=${REPEATS:-5}
CALLS=${CALLS:-20000}
CG_CALLS=${CG_CALLS:-8192}
BRUTE=${BRUTE:-256}
builds=(host host-fixed)
declare -A numname=([host]=float [host-fixed]=fixed)

for b in "${builds[@]}"; do
	if [ ! -x "build/$b/tests/firmware/model/bench_squeal_model" ]; then
		echo "bench_squeal_model.sh: build/$b/tests/firmware/model/bench_squeal_model missing (run: make bench)" >&2
		exit 1
	fi
done

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

echo "CPU: $(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //'), $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
for r in $(seq 1 "$ROUNDS"); do
	for b in "${builds[@]}"; do
		"build/$b/tests/firmware/model/bench_squeal_model" --repeats "$REPEATS" --calls "$CALLS" >"$tmp/run.$b.$r"
		if [ "$r" = 1 ]; then
			grep -E '^(bench_model|classes|byclass)' "$tmp/run.$b.$r"
		fi
		awk -v b="${numname[$b]}" '$1 == "sample" { print b, $2, $3 }' "$tmp/run.$b.$r" >>"$tmp/samples"
	done
done

# callgrind: Ir of N calls minus Ir of 0 calls, per build and criterion
collected() { # binary criterion calls
	valgrind --tool=callgrind --callgrind-out-file=/dev/null \
		"$1" --callgrind "$3" --criterion "$2" 2>&1 >/dev/null |
		sed -nE 's/^==[0-9]+== Collected : ([0-9]+).*/\1/p'
}
declare -A ipc
for b in "${builds[@]}"; do
	for c in exact cubic; do
		if command -v valgrind >/dev/null; then
			i0=$(collected "build/$b/tests/firmware/model/bench_squeal_model" "$c" 0)
			i1=$(collected "build/$b/tests/firmware/model/bench_squeal_model" "$c" "$CG_CALLS")
			ipc[$b.$c]=$(awk -v a="$i0" -v b="$i1" -v n="$CG_CALLS" 'BEGIN { printf "%.0f", (b - a) / n }')
		else
			ipc[$b.$c]="n/a"
		fi
	done
done

build/host/tests/firmware/model/bench_squeal_model --brute "$BRUTE" >"$tmp/brute"
cat "$tmp/brute"
brute_mean=$(awk '$1 == "brute" && $2 == "ns/decision" { print $4 }' "$tmp/brute")

# median, min, max of the pooled samples
stats() { # build criterion
	awk -v b="$1" -v c="$2" '$1 == b && $2 == c { print $3 }' "$tmp/samples" | sort -g |
		awk '{ v[NR] = $1 } END {
			m = (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2
			printf "%s %s %s\n", m, v[1], v[NR] }'
}
declare -A med
echo
echo "squeal_model_classify, $((ROUNDS * REPEATS)) repeats x $CALLS calls per build and criterion (4096 points, 1/3 each class)"
printf '%-6s | %-9s | %-28s | %-17s | %-23s | %s\n' build criterion "ns/call median (min..max)" "instructions/call" "brute-force ns/decision" "brute/closed-form"
printf '%s\n' "-------|-----------|------------------------------|-------------------|-------------------------|------------------"
for b in "${builds[@]}"; do
	n=${numname[$b]}
	for c in exact cubic; do
		read -r m lo hi < <(stats "$n" "$c")
		med[$n.$c]=$m
		printf '%-6s | %-9s | %-28s | %-17s | %-23s | %s\n' "$n" "$c" \
			"$(printf '%.1f (%.1f..%.1f)' "$m" "$lo" "$hi")" "${ipc[$b.$c]}" \
			"$(printf '%.0f' "$brute_mean")" \
			"$(awk -v x="$brute_mean" -v y="$m" 'BEGIN { printf "%.0f", x / y }')"
	done
done
awk -v fe="${med[fixed.exact]}" -v fle="${med[float.exact]}" \
	-v fc="${med[fixed.cubic]}" -v flc="${med[float.cubic]}" 'BEGIN {
	printf "ratio fixed/float: exact %.2f, cubic %.2f\n", fe / fle, fc / flc
	printf "ratio cubic/exact: float %.2f, fixed %.2f\n", flc / fle, fc / fe }'
awk '$1 == "brute" && $2 == "ns/decision" {
	printf "brute force per decision: mean %.2f ms, median %.2f ms, min %.2f ms, max %.2f ms (the column and ratio use the mean)\n",
		$4 / 1e6, $6 / 1e6, $8 / 1e6, $10 / 1e6 }' "$tmp/brute"
