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
#   - starts the watchdog and keeps kicking it until the end.
# Prints "RESULT: N passed, M failed".
set -u
cd "$(dirname "$0")/../.."
elf=build/stm32f4-ecutest/squeal-monitor.elf
log=build/test-logs/target-ecu-boot.txt
mkdir -p "$(dirname "$log")"
pass=0; fail=0
check() { # description, condition...
	local d=$1; shift
	if "$@"; then pass=$((pass + 1)); echo "PASS: $d"; else fail=$((fail + 1)); echo "FAIL: $d"; fi
}
timeout 60 qemu-system-arm -M netduinoplus2 -nographic -monitor none -serial none \
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
up=$(field uptime_ms); kicks=$(field kicks); last=$(field last_kick_ms)
loop_start=$(sed -nE 's/^EVT main_loop uptime_ms=([0-9]+).*/\1/p' "$log")
check "watchdog kicked at least every other ms of the loop (${kicks:-?} kicks in $(( ${up:-0} - ${loop_start:-0} )) ms)" \
	[ -n "$kicks" ] && [ "$kicks" -ge $(( (${up:-0} - ${loop_start:-0}) / 2 )) ]
check "still kicking at the end (last kick ${last:-?} ms, end ${up:-?} ms)" \
	[ -n "$last" ] && [ $(( up - last )) -le 10 ]
echo "RESULT: $pass passed, $fail failed"
[ "$fail" = 0 ]
