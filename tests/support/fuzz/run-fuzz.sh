#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Runs libFuzzer targets (tests/support/fuzz/, built by mk/fuzz.mk), $FUZZ_JOBS
# at a time (one per CPU), and prints one line per target with executions, execs/s and
# libFuzzer's final coverage (cov: edges, ft: features), then
#   RESULT: N passed, M failed
#
#   run-fuzz.sh [--mode test|fuzz] [--seconds S] [TARGET...]
#
# --mode test (default, what `make test` runs): S = $FUZZ_TEST_SECONDS (10)
#     per target, on a scratch copy of the committed seeds (nothing in the
#     tree changes), with a fixed random seed ($FUZZ_TEST_SEED, default 1)
#     so that CI explores the same inputs on every run: a failure there is
#     reproducible, not luck. `make fuzz` explores with fresh seeds.
# --mode fuzz (`make fuzz`): S = $FUZZ_SECONDS (300) per target; new inputs
#     accumulate in build/fuzz-corpus/<target>/ across runs.
# Targets default to $FUZZ_TARGETS (exported by make) or build/fuzz/bin/*.
# A target fails on a crash, a property failure (abort), a timeout (one input
# > 5 s), a leak, any sanitizer report or an out-of-memory; the input is kept
# in build/fuzz-artifacts/ and the log in build/fuzz-logs/.
set -u
cd "$(dirname "$0")/../../.."

mode=test
secs=""
targets=()
while [ $# -gt 0 ]; do
	case "$1" in
	--mode) mode=$2; shift 2 ;;
	--seconds) secs=$2; shift 2 ;;
	-h|--help) sed -n '3,18p' "$0"; exit 0 ;;
	*) targets+=("$1"); shift ;;
	esac
done
if [ -z "$secs" ]; then
	if [ "$mode" = fuzz ]; then secs=${FUZZ_SECONDS:-300}; else secs=${FUZZ_TEST_SECONDS:-10}; fi
fi
if [ ${#targets[@]} -eq 0 ]; then
	if [ -n "${FUZZ_TARGETS:-}" ]; then
		read -r -a targets <<<"$FUZZ_TARGETS"
	else
		targets=(build/fuzz/bin/fuzz_*)
	fi
fi

logs=build/fuzz-logs
artifacts=build/fuzz-artifacts
mkdir -p "$logs" "$artifacts"
# One target: its log in $logs, its report (one PASS/FAIL line, and on a
# failure the log's telling lines) in $logs/<name>.<mode>.result.
run_one() {
	local bin=$1 name seeds log res work rc execs rate last cov ft corp bad
	name=$(basename "$bin")
	seeds=tests/support/fuzz/corpus/$name
	log=$logs/$name.$mode.log
	res=$logs/$name.$mode.result
	if [ ! -x "$bin" ]; then
		echo "FAIL  $name: $bin not built" >"$res"
		return
	fi
	if [ "$mode" = fuzz ]; then
		work=build/fuzz-corpus/$name
		mkdir -p "$work"
	else
		work=$(mktemp -d "${TMPDIR:-/tmp}/fuzz-$name.XXXXXX")
	fi
	local dirs=("$work")
	[ -d "$seeds" ] && dirs+=("$seeds")
	# -timeout: one input may take 5 s at most (a hang is a failure);
	# -rss_limit_mb: an unbounded allocation is a failure too.
	local seedopt=()
	[ "$mode" = fuzz ] || seedopt=(-seed="${FUZZ_TEST_SEED:-1}")
	"$bin" "${seedopt[@]}" -max_total_time="$secs" -timeout=5 -rss_limit_mb=2048 \
		-print_final_stats=1 -detect_leaks=1 \
		-artifact_prefix="$artifacts/$name-" "${dirs[@]}" >"$log" 2>&1
	rc=$?
	[ "$mode" = fuzz ] || rm -rf "$work"
	execs=$(sed -nE 's/^stat::number_of_executed_units: *([0-9]+).*/\1/p' "$log" | tail -1)
	rate=$(sed -nE 's/^stat::average_exec_per_sec: *([0-9]+).*/\1/p' "$log" | tail -1)
	last=$(grep -E '^#[0-9]+' "$log" | grep -E 'cov: [0-9]+' | tail -1)
	cov=$(echo "$last" | sed -nE 's/.*cov: ([0-9]+).*/\1/p')
	ft=$(echo "$last" | sed -nE 's/.*ft: ([0-9]+).*/\1/p')
	corp=$(echo "$last" | sed -nE 's/.*corp: ([0-9]+\/[0-9]+[a-zA-Z]*).*/\1/p')
	bad=0
	[ "$rc" = 0 ] || bad=1
	if grep -qE 'ERROR: (AddressSanitizer|LeakSanitizer|UndefinedBehaviorSanitizer|libFuzzer)|runtime error:|property failed|==[0-9]+==ERROR' "$log"; then
		bad=1
	fi
	{
		printf '%-5s %-18s %4ss  execs %-10s execs/s %-8s cov %-6s ft %-7s corpus %s\n' \
			"$([ $bad = 0 ] && echo PASS || echo FAIL)" "$name" "$secs" \
			"${execs:-?}" "${rate:-?}" "${cov:-?}" "${ft:-?}" "${corp:-?}"
		if [ $bad != 0 ]; then
			grep -E 'ERROR|runtime error|property failed|SUMMARY|Test unit written|^    #[0-9]' "$log" | head -40 | sed 's/^/    | /'
			echo "    (full log: $log)"
		fi
	} >"$res"
}

# Targets run $FUZZ_JOBS at a time (default: one per CPU); each is
# single-threaded and bound by its own time, so on N CPUs N at once take the
# time of one. Reports print in the targets' order.
jobs_max=${FUZZ_JOBS:-$(nproc 2>/dev/null || echo 1)}
for bin in "${targets[@]}"; do
	rm -f "$logs/$(basename "$bin").$mode.result"
	while [ "$(jobs -rp | wc -l)" -ge "$jobs_max" ]; do
		wait -n
	done
	run_one "$bin" &
done
wait
passed=0
failed=0
for bin in "${targets[@]}"; do
	res=$logs/$(basename "$bin").$mode.result
	if [ -s "$res" ] && head -1 "$res" | grep -q '^PASS'; then
		passed=$((passed + 1))
	else
		failed=$((failed + 1))
	fi
	cat "$res" 2>/dev/null || echo "FAIL  $(basename "$bin"): no report"
done
echo "RESULT: $passed passed, $failed failed"
[ "$failed" = 0 ]
