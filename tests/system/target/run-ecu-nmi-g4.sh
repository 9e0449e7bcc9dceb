#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The STM32G474 image's NMI handler under qemu-system-arm -M netduinoplus2:
# the G4 asks its flash ECC check first (hal/stm32f4/startup.c NMI_Handler,
# chip_g4.c chip_nmi_flash_ecc); an NMI that is no ECC double error in the
# calibration pages (here the clock security system's, which the test
# image pends itself once its main loop runs; FLASH_ECCR reads 0 in QEMU)
# must still take the fault path: recorded as vector 2, reset, the next
# start reports HAL_RESET_FAULT and runs to its end. The ECC case itself
# (claimed, counted, no reset) runs on the register simulation
# (tests/hal/stm32g4/test_chip_g4.c).
# Prints "RESULT: N passed, M failed".
set -u
cd "$(dirname "$0")/../../.."
. tests/system/target/lib-target.sh
mkdir -p build/test-logs
log=build/test-logs/target-ecu-nmi-g4.txt
run_qemu build/stm32g474-nmitest/squeal-monitor.elf "$log"
rc=$?
grep '^EVT fault\|^EVT reset_reason\|^EVT summary' "$log" | sed 's/^/  | /'
check "NMI image ends by itself after the reset (exit 0)" [ "$rc" = 0 ]
check "NMI (vector 2) recorded through the G4's NMI handler" grep -q '^EVT fault vector=2 ' "$log"
check "next start reports HAL_RESET_FAULT from the NMI" grep -q '^EVT reset_reason value=4 fault_vector=2 ' "$log"
check "next start runs its main loop to the end" grep -q '^EVT summary.* reset_reason=4 ' "$log"
finish
