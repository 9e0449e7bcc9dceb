#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Target-in-the-loop, ECU image: the real firmware (firmware/app + monitor on
# hal/stm32f4), built with -DSQ_TARGET_TEST so the HAL reports its events
# through semihosting, boots on qemu-system-arm -M netduinoplus2 (STM32F405).
# QEMU models neither the RCC nor bxCAN (they read 0), so a correct image
#   - does not hang: it ends by itself after 2 s of main loop (exit 0),
#   - reaches the main loop,
#   - reports HAL_FAULT_CLOCK_FALLBACK (bit 0) and HAL_FAULT_CAN_INIT (bit 1),
#   - runs on the 16 MHz HSI, CAN state STOPPED (4),
#   - starts the watchdog and keeps kicking it until the end;
# and a fault (divide by zero) is recorded, resets the core, and the next
# boot reports it as the reset reason.
# Prints "RESULT: N passed, M failed".
# QEMU_ARM=path runs another emulator (tests/system/target/stub-qemu-arm.sh, the
# negative control), logging to ECU_BOOT_LOGDIR (default build/test-logs).
set -u
cd "$(dirname "$0")/../../.."
qemu=${QEMU_ARM:-qemu-system-arm}
logdir=${ECU_BOOT_LOGDIR:-build/test-logs}
# ECU_BOOT_TARGET=stm32g474: the G4 image on the same machine (QEMU has no
# G4 either: its RCC, PWR and FDCAN read 0 there, the same checks hold)
target=${ECU_BOOT_TARGET:-stm32f4}
elf=build/$target-ecutest/squeal-monitor.elf
log=$logdir/target-ecu-boot-$target.txt
mkdir -p "$(dirname "$log")"
# shellcheck source=tests/support/checks.sh
. tests/support/checks.sh
timeout 60 "$qemu" -M netduinoplus2 -nographic -monitor none -serial none \
	-semihosting-config enable=on,target=native -kernel "$elf" >"$log" 2>&1
rc=$?
sed 's/^/  | /' "$log"
check "image ends by itself (no hang, exit 0)" [ "$rc" = 0 ]
sum=$(grep '^EVT summary' "$log" || true)
field() { echo "$sum" | sed -nE "s/.* $1=([0-9a-fx]+).*/\1/p"; }
check "reaches the main loop" grep -q '^EVT main_loop' "$log"
check "summary line after the run" [ -n "$sum" ]
faults=$(( $(field faults || echo 0) + 0 ))
check "clock fallback reported (HAL_FAULT_CLOCK_FALLBACK)" [ $((faults & 1)) = 1 ]
check "missing CAN controller reported (HAL_FAULT_CAN_INIT)" [ $((faults & 2)) = 2 ]
check "CAN init wait timed out instead of hanging" grep -q '^EVT can_init_timeout' "$log"
check "runs on the HSI (16 MHz)" [ "$(field core_mhz)" = 16 ]
check "CAN state STOPPED" [ "$(field can_state)" = 4 ]
check "watchdog started" grep -qE '^EVT wdg_start value=[1-9]' "$log"
check "hal_time_us() never went backwards over $(field idle_calls) idle calls" [ "$(field time_back)" = 0 ]
check "hal_time_us() agrees with the millisecond tick ($(field time_ms) vs $(field uptime_ms) ms)" \
	all_of '[ -n "$(field time_ms)" ]' '[ $(( $(field time_ms) - $(field uptime_ms) )) -ge 0 ]' \
	'[ $(( $(field time_ms) - $(field uptime_ms) )) -le 1 ]'
up=$(field uptime_ms); kicks=$(field kicks); last=$(field last_kick_ms)
loop_start=$(sed -nE 's/^EVT main_loop uptime_ms=([0-9]+).*/\1/p' "$log")
check "watchdog kicked at least every other ms of the loop (${kicks:-?} kicks in $(( ${up:-0} - ${loop_start:-0} )) ms)" \
	all_of '[ -n "$kicks" ]' '[ "$kicks" -ge $(( (${up:-0} - ${loop_start:-0}) / 2 )) ]'
check "still kicking at the end (last kick ${last:-?} ms, end ${up:-?} ms)" \
	all_of '[ -n "$last" ]' '[ $(( up - last )) -le 10 ]'

# The fault path (the generic fault handler every image shares; its test
# image is built for the F4):
if [ "$target" != stm32f4 ]; then
	checks_done
	exit $?
fi
# An image that divides by zero once its main loop runs
# (trapped: the start-up code sets CCR.DIV_0_TRP). The handler must record
# the cause in no-init RAM and reset; the second boot must find the record,
# report HAL_RESET_FAULT (4) and run normally.
felf=build/stm32f4-faulttest/squeal-monitor.elf
flog=$logdir/target-ecu-fault.txt
timeout 60 "$qemu" -M netduinoplus2 -nographic -monitor none -serial none \
	-semihosting-config enable=on,target=native -kernel "$felf" >"$flog" 2>&1
rc=$?
sed 's/^/  | /' "$flog"
check "fault image: ends by itself after the reset (exit 0)" [ "$rc" = 0 ]
fline=$(grep -m1 '^EVT fault vector=' "$flog" || true)
check "UsageFault (vector 6) taken" all_of '[ -n "$fline" ]' 'echo "$fline" | grep -q "vector=6 "'
cfsr=$(echo "$fline" | sed -nE 's/.*cfsr=0x([0-9a-f]+).*/\1/p')
check "CFSR says DIVBYZERO (bit 25)" all_of '[ -n "$cfsr" ]' '[ $(( (16#${cfsr:-0} >> 25) & 1 )) = 1 ]'
boot2=$(grep '^EVT reset_reason value=4' "$flog" || true)
check "second boot reports HAL_RESET_FAULT with the recorded vector" \
	all_of '[ -n "$boot2" ]' 'echo "$boot2" | grep -q "fault_vector=6 "'
pc=$(echo "$boot2" | sed -nE 's/.*fault_pc=0x([0-9a-f]+).*/\1/p')
func=$(arm-none-eabi-addr2line -f -e "$felf" "0x${pc:-0}" | head -1)
check "recorded PC is the faulting instruction's function (stm32_test_event, got ${func:-?})" \
	[ "$func" = stm32_test_event ]
check "second boot runs its main loop to the end" grep -q '^EVT summary.* reset_reason=4 ' "$flog"

checks_done
