#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The fault handler on a broken stack: an ECU test image
# (-DSQ_TARGET_TEST_STACK_OVERFLOW) pushes its main stack below the bottom
# of SRAM once its main loop runs. The exception entry itself then fails
# (stacking error) and the handler starts with MSP outside any memory; it
# must move MSP to its own stack before any C, write the fault record and
# reset. The second boot must report HAL_RESET_FAULT with that record, the
# self-test must report the previous run's stack use as the whole reserve,
# and the image must run normally. (Without the MSP switch QEMU reports a
# lockup and the image never ends.) Prints "RESULT: N passed, M failed".
set -u
cd "$(dirname "$0")/../../.."
elf=build/stm32f4-stacktest/squeal-monitor.elf
log=build/test-logs/target-ecu-stack-overflow.txt
mkdir -p "$(dirname "$log")"
. tests/system/target/lib-target.sh
run_qemu "$elf" "$log"
rc=$?
grep -v 'EVT wdg_kick' "$log" | sed 's/^/  | /' | head -40
check "image ends by itself after the reset (exit 0, no lockup)" [ "$rc" = 0 ]
check "no CPU lockup" bash -c "! grep -q -i lockup '$log'"
fline=$(grep -m1 '^EVT fault vector=' "$log" || true)
vec=$(echo "$fline" | sed -nE 's/.*vector=([0-9]+) .*/\1/p')
msp=$(echo "$fline" | sed -nE 's/.*msp=0x([0-9a-f]+).*/\1/p')
check "fault handler ran (BusFault 5 or HardFault 3, got ${vec:-none})" \
	any_of '[ "${vec:-0}" = 5 ]' '[ "${vec:-0}" = 3 ]'
check "it ran although MSP was below SRAM (msp=0x${msp:-?})" \
	all_of '[ -n "$msp" ]' '[ $((16#$msp)) -lt $((16#20000000)) ]'
cfsr=$(echo "$fline" | sed -nE 's/.*cfsr=0x([0-9a-f]+).*/\1/p')
check "CFSR says stacking error (STKERR, bit 12; cfsr=0x${cfsr:-?})" \
	all_of '[ -n "$cfsr" ]' '[ $(( (16#$cfsr >> 12) & 1 )) = 1 ]'
boot2=$(grep '^EVT reset_reason value=4' "$log" || true)
check "second boot reports HAL_RESET_FAULT with the recorded vector" \
	all_of '[ -n "$boot2" ]' 'echo "$boot2" | grep -qE "fault_vector=${vec:-x} "'
st2=$(grep '^EVT selftest .*reset=4 ' "$log" || true)
prev=$(echo "$st2" | sed -nE 's/.* stack_prev=([0-9]+).*/\1/p')
res=$(echo "$st2" | sed -nE 's/.* stack_reserve=([0-9]+).*/\1/p')
check "self-test: previous run used the whole stack reserve (${prev:-?} of ${res:-?} bytes)" \
	all_of '[ -n "$prev" ]' '[ "$prev" = "$res" ]'
sf=$(echo "$st2" | sed -nE 's/.* faults=0x([0-9a-f]+).*/\1/p')
check "self-test: stack fault bit (0x8) set (faults=0x${sf:-?})" \
	all_of '[ -n "$sf" ]' '[ $(( 16#$sf & 8 )) = 8 ]'
check "second boot runs its main loop to the end" grep -q '^EVT summary.* reset_reason=4 ' "$log"

finish
