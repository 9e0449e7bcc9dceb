#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Contracts on the ECU: a test image calls hal_can_send() with a
# bus index hal.h does not have once its main loop runs. The STM32
# hal_contract_failed() must record the file and line in the no-init fault
# record and reset; the next start reports HAL_RESET_FAULT with that line
# (the one in bxcan.c that checks the bus index) and runs normally.
# Prints "RESULT: N passed, M failed".
set -u
cd "$(dirname "$0")/../../.."
elf=build/stm32f4-contracttest/squeal-monitor.elf
log=build/test-logs/target-ecu-contract.txt
mkdir -p "$(dirname "$log")"
. tests/system/target/lib-target.sh
run_qemu "$elf" "$log"
rc=$?
grep '^EVT contract\|^EVT reset_reason\|^EVT summary' "$log" | sed 's/^/  | /'
want=$(grep -n 'HAL_REQUIRE(bus < HAL_CAN_BUSES);' hal/stm32f4/bxcan.c | cut -d: -f1)
check "image ends by itself after the reset (exit 0)" [ "$rc" = 0 ]
check "contract handler names bxcan.c line ${want:-?}" \
	grep -qE "^EVT contract file=hal/stm32f4/bxcan.c line=${want:-x}\$" "$log"
check "next start reports HAL_RESET_FAULT with the contract record and line" \
	grep -qE "^EVT reset_reason value=4 fault_vector=1024 .* contract_line=${want:-x}" "$log"
check "and runs its main loop to the end" grep -q '^EVT summary.* reset_reason=4 ' "$log"
finish
