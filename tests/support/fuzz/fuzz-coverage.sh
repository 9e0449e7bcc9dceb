#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Line and branch coverage that the fuzz corpora reach in the code each
# target is for: replays tests/support/fuzz/corpus/<target>/ and, if present,
# build/fuzz-corpus/<target>/ (grown by make fuzz) once through the
# coverage build build/fuzzcov/bin/<target> (make fuzz-coverage builds them)
# and prints llvm-cov's summary for the target's own sources.
#   tests/support/fuzz/fuzz-coverage.sh build/fuzzcov/bin/fuzz_msgs ...
set -u
cd "$(dirname "$0")/../../.."
PROFDATA=${PROFDATA:-llvm-profdata-14}
COV=${COV:-llvm-cov-14}
out=build/fuzzcov/profiles
mkdir -p "$out"

sources_of() { # target -> the files it is meant to exercise
	case "$1" in
	fuzz_model_float) echo firmware/model/squeal_model_float.c firmware/model/sq_mathf.c firmware/model/squeal_model_common.c ;;
	fuzz_model_fixed) echo firmware/model/squeal_model_fixed.c firmware/model/fixmath.c firmware/model/bessel_table.c firmware/model/squeal_model_common.c ;;
	fuzz_msgs) echo firmware/protocol/squeal_msgs.c firmware/protocol/e2e_p01.c firmware/protocol/crc8_p01.c ;;
	fuzz_calib_block) echo firmware/monitor/calib.c ;;
	fuzz_monitor|fuzz_monitor_fixed) echo firmware/monitor/monitor.c firmware/monitor/model_adapter.c ;;
	fuzz_candump) echo host-sim/candump_log.c ;;
	fuzz_calib_text) echo host-sim/calib_text.c ;;
	*) echo "" ;;
	esac
}

for bin in "$@"; do
	name=$(basename "$bin")
	dirs=()
	[ -d "tests/support/fuzz/corpus/$name" ] && dirs+=("tests/support/fuzz/corpus/$name")
	[ -d "build/fuzz-corpus/$name" ] && dirs+=("build/fuzz-corpus/$name")
	rm -f "$out/$name".*.profraw
	LLVM_PROFILE_FILE="$out/$name.%p.profraw" "$bin" -runs=0 "${dirs[@]}" >/dev/null 2>&1
	"$PROFDATA" merge -sparse "$out/$name".*.profraw -o "$out/$name.profdata" || continue
	inputs=$(find "${dirs[@]}" -type f | wc -l)
	echo "== $name ($inputs inputs from ${dirs[*]})"
	# shellcheck disable=SC2046
	"$COV" report "$bin" -instr-profile="$out/$name.profdata" $(sources_of "$name") |
		awk '/\.c / || /^TOTAL/ { n = split($1, p, "/"); printf "  %-24s lines %7s  branches %7s  functions %7s  regions %7s\n", p[n], $10, $13, $7, $4 }'
done
