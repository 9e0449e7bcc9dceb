#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Target-in-the-loop, model: the golden vectors (tests/support/golden/model_vectors.csv)
# through squeal_model_classify on
#   - a Cortex-M4F (float build) under qemu-system-arm -M netduinoplus2,
#   - a Cortex-M3 (fixed build, no FPU) under qemu-system-arm -M netduino2,
#   - the STM32G474 image's HAL (float and fixed, Cortex-M4F) under
#     -M netduinoplus2 (the G4's flash and SRAM addresses; its RCC, PWR and
#     FDCAN are absent there: the HAL must report them unavailable and go on),
# each against the host build of the same numeric mode (build/host*/tv-digest,
# the same tv_run.c on the host's libfirmware.a): the FNV-1a digests over all
# output bits (return code, state, flags, eight result fields) must be equal,
# per chunk of 512 classifications and in total. The number of classifications
# is checked against the CSV itself.
# Prints "RESULT: N passed, M failed".
set -u
cd "$(dirname "$0")/../../.."
out=build/test-logs/target-golden
mkdir -p "$out"
pass=0; fail=0
ok() { pass=$((pass + 1)); echo "PASS: $*"; }
ko() { fail=$((fail + 1)); echo "FAIL: $*"; }

csv_count() { # rows of the CSV the given numeric build runs
	/usr/bin/python3 - "$1" <<'PY'
import csv, sys
rows = csv.DictReader(l for l in open("tests/support/golden/model_vectors.csv") if not l.startswith("#"))
print(sum(1 for r in rows if r["variant"] in ("both", sys.argv[1])))
PY
}

run_mode() { # numeric machine image host_prog [name]
	local num=$1 machine=$2 elf=$3 host=$4 name=${5:-$1}
	local t="$out/$name-target.txt" h="$out/$name-host.txt"
	# -icount shift=0: deterministic virtual time (1 ns per instruction)
	timeout 300 qemu-system-arm -M "$machine" -icount shift=0 -nographic -monitor none -serial none \
		-semihosting-config enable=on,target=native -kernel "$elf" >"$t" 2>&1
	local rc=$?
	"$host" >"$h" 2>&1 || ko "$name: host digest program failed"
	if [ "$rc" != 0 ]; then
		ko "$name: $machine run exited $rc (see $t)"
		tail -5 "$t"
		return
	fi
	local td hd
	td=$(grep '^DIGEST' "$t"); hd=$(grep '^DIGEST' "$h")
	echo "  target ($machine): $td"
	echo "  host:              $hd"
	if [ -n "$td" ] && [ "$td" = "$hd" ]; then
		ok "$name: $machine digest equals the host build's, bit for bit"
	else
		local nd
		nd=$(diff <(grep '^CHUNK' "$t") <(grep '^CHUNK' "$h") | grep -c '^<')
		ko "$name: digests differ ($nd of $(grep -c '^CHUNK' "$h") chunks of 512 differ)"
	fi
	# Each classification is timed (bench_ticks.h); a backwards step of the
	# timer would show up as a delta near 2^32.
	local tmax
	tmax=$(grep '^TIMING' "$t" | sed -nE 's/.* ticks_max=([0-9]+) .*/\1/p')
	if [ -n "$tmax" ] && [ "$tmax" -lt 2147483648 ]; then
		ok "$name: timer never went backwards over $(grep -c '^CHUNK' "$t") chunks (largest delta $tmax)"
	else
		ko "$name: timer went backwards (largest delta ${tmax:-?})"
	fi
	local want n
	want=$(csv_count "$num")
	n=$(echo "$td" | sed -nE 's/.* n=([0-9]+) .*/\1/p')
	if [ "$n" = "$want" ]; then
		ok "$name: $n classifications = rows of the CSV for this build"
	else
		ko "$name: ran ${n:-?} classifications, CSV has $want"
	fi
}

run_mode float netduinoplus2 build/tv-m4f/model-vectors.elf build/host/tv-digest
run_mode fixed netduino2 build/tv-m3/model-vectors.elf build/host-fixed/tv-digest
run_mode float netduinoplus2 build/tv-g4/model-vectors.elf build/host/tv-digest g4-float
run_mode fixed netduinoplus2 build/tv-g4-fixed/model-vectors.elf build/host-fixed/tv-digest g4-fixed
# the G4 HAL on a machine without its peripherals: they are reported, the
# run goes on (the semihosting events of the test image)
for v in g4-float g4-fixed; do
	f=$out/$v-target.txt
	if grep -q '^EVT can_init_timeout' "$f" && grep -q '^EVT boot value=16000000' "$f" &&
		grep -q '^DIGEST' "$f"; then
		ok "$v: missing FDCAN (init timeout) and crystal (HSI 16 MHz) reported, vectors ran"
	else
		ko "$v: no unavailable-peripheral events in $out/$v-target.txt"
	fi
done
for elf in build/tv-m3/model-vectors.elf build/tv-g4-fixed/model-vectors.elf; do
	if tests/system/target/check-no-float.sh "$elf"; then
		ok "fixed test image $elf has no floating point"
	else
		ko "fixed test image $elf contains floating point"
	fi
done

echo "RESULT: $pass passed, $fail failed"
[ "$fail" = 0 ]
