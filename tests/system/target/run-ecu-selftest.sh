#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The bring-up self-test at every start, under qemu-system-arm
# -M netduinoplus2 (STM32F405 without RCC, TIM11 or bxCAN models: the
# registers read 0). Each boot prints
#   EVT selftest hse_hz=.. reset=.. bor=.. lb0=.. lb1=.. stack_prev=.. stack_reserve=.. faults=0x..
# before the main loop. Checked here: the crystal is measured (none starts
# in QEMU: 0 Hz and the crystal fault bit), the reset cause, the BOR level
# read from the option bytes, both CAN controllers' loopback reported as
# unavailable (2: they never acknowledge initialisation), the previous
# run's stack high-water mark (unknown after a cold start, measured after
# the fault test's reset), that the ECU still runs its main loop, and the
# clock security system's NMI path (record, reset, HSI fallback reported).
# Prints "RESULT: N passed, M failed".
set -u
cd "$(dirname "$0")/../../.."
. tests/system/target/lib-target.sh
f() { echo "$1" | sed -nE "s/.* $2=(0x)?([0-9a-f]+).*/\2/p"; }
mkdir -p build/test-logs
log=build/test-logs/target-ecu-selftest.txt
run_qemu build/stm32f4-ecutest/squeal-monitor.elf "$log"
rc=$?
grep '^EVT selftest\|^EVT main_loop\|^EVT summary' "$log" | sed 's/^/  | /'
st=$(grep -m1 '^EVT selftest ' "$log" || true)
check "image ends by itself (exit 0)" [ "$rc" = 0 ]
check "self-test line printed" [ -n "$st" ]
check "self-test before the main loop" \
	[ "$(grep -n '^EVT selftest' "$log" | head -1 | cut -d: -f1)" -lt "$(grep -n '^EVT main_loop' "$log" | head -1 | cut -d: -f1)" ]
check "crystal measured: none started in QEMU (hse_hz=$(f "$st" hse_hz))" [ "$(f "$st" hse_hz)" = 0 ]
check "crystal fault bit (0x1) set" [ $(( 16#$(f "$st" faults) & 1 )) = 1 ]
check "reset cause reported (cold start, RCC_CSR reads 0: unknown = 6)" [ "$(f "$st" reset)" = 6 ]
check "BOR level reported, 0..3 (got $(f "$st" bor))" \
	all_of '[ -n "$(f "$st" bor)" ]' '[ "$(f "$st" bor)" -le 3 ]'
check "CAN1 loopback: unavailable (2) in QEMU" [ "$(f "$st" lb0)" = 2 ]
check "CAN2 loopback: unavailable (2) in QEMU" [ "$(f "$st" lb1)" = 2 ]
check "loopback unavailable is not a loopback failure (fault bit 0x4 clear)" [ $(( 16#$(f "$st" faults) & 4 )) = 0 ]
check "stack high-water mark unknown after a cold start" [ "$(f "$st" stack_prev)" = 4294967295 ]
check "the ECU still runs what it can (main loop to the end)" grep -q '^EVT summary' "$log"

# After a reset the previous run's stack use is measured.
log2=build/test-logs/target-ecu-selftest-reset.txt
run_qemu build/stm32f4-faulttest/squeal-monitor.elf "$log2"
st2=$(grep '^EVT selftest .*reset=4 ' "$log2" || true)
echo "  | $st2"
prev=$(f "$st2" stack_prev); res=$(f "$st2" stack_reserve)
check "after a reset: reset cause HAL_RESET_FAULT (4)" [ -n "$st2" ]
check "after a reset: previous run's stack use measured (${prev:-?} of ${res:-?} bytes, 64..reserve/2)" \
	all_of '[ -n "$prev" ]' '[ "$prev" -ge 64 ]' '[ "$prev" -le $(( ${res:-0} / 2 )) ]'

# Clock security system: a crystal that stops at run time gives the NMI
# (QEMU has no CSS: the test image pends the NMI itself once its main loop
# runs). The handler records vector 2 and resets; the next start reports
# the fault as the reset cause and runs on the HSI with the clock fault.
log3=build/test-logs/target-ecu-selftest-nmi.txt
run_qemu build/stm32f4-nmitest/squeal-monitor.elf "$log3"
rc=$?
grep '^EVT fault\|^EVT reset_reason\|^EVT summary' "$log3" | sed 's/^/  | /'
check "NMI image ends by itself after the reset (exit 0)" [ "$rc" = 0 ]
check "NMI (vector 2) recorded" grep -q '^EVT fault vector=2 ' "$log3"
check "next start reports HAL_RESET_FAULT from the NMI" grep -q '^EVT reset_reason value=4 fault_vector=2 ' "$log3"
sum3=$(grep '^EVT summary' "$log3" || true)
check "and runs on the HSI (16 MHz) with the clock fallback reported" \
	all_of '[ -n "$sum3" ]' 'echo "$sum3" | grep -q " core_mhz=16"' \
	'[ $(( $(echo "$sum3" | sed -nE "s/.* faults=0x([0-9a-f]+).*/0x\1/p") & 1 )) = 1 ]'

finish
