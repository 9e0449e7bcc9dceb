#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Static checks of the ECU images (no QEMU):
#   - the fixed STM32F103 image contains no floating point, and the checker
#     does catch float code (the M4F image's VFP instructions, the soft-float
#     routines of an M3 float build): the check is tested too;
#   - the worst-case stack depth (tools/stack_usage.py) of each image is
#     bounded and fits the linker's stack reserve;
#   - vectors, calibration sectors and RAM layout as linker/*.ld promise;
#   - `make flash DRY_RUN=1` prints the exact OpenOCD command line.
# Prints "RESULT: N passed, M failed".
set -u
cd "$(dirname "$0")/../../.."
pass=0; fail=0
check() {
	local d=$1; shift
	if "$@"; then pass=$((pass + 1)); echo "PASS: $d"; else fail=$((fail + 1)); echo "FAIL: $d"; fi
}
not() { ! "$@"; }
quiet() { "$@" >/dev/null 2>&1; }

f4=build/stm32f4/squeal-monitor.elf
f1=build/stm32f103/squeal-monitor.elf
check "STM32F103 fixed image: no floating point" tests/system/target/check-no-float.sh "$f1"
check "checker flags the M4F float image (VFP instructions)" not quiet tests/system/target/check-no-float.sh "$f4"
check "checker flags soft-float routines (M3 float build)" \
	not quiet tests/system/target/check-no-float.sh build/stm32f103-float/squeal-monitor.elf

for img in "$f4:build/stm32f4/fw" "$f1:build/stm32f103/fw"; do
	elf=${img%%:*}; dir=${img#*:}
	log="build/test-logs/stack-$(echo "$elf" | cut -d/ -f2).txt"
	mkdir -p build/test-logs
	/usr/bin/python3 tools/stack_usage.py "$elf" "$dir" >"$log" 2>&1
	rc=$?
	sed 's/^/  | /' "$log"
	check "$elf: stack depth bounded and within the reserve" [ "$rc" = 0 ]
done

sym() { arm-none-eabi-nm "$1" | awk -v s="$2" '$3 == s { print $1 }'; }
check "F4 vectors at 0x08000000" [ "$(sym "$f4" stm32_vectors)" = 08000000 ]
check "F4 calibration slots at sectors 1-2 (0x08004000)" [ "$(sym "$f4" __calib_start)" = 08004000 ]
overlap=$(
	arm-none-eabi-objdump -h "$f4" | awk '$2 ~ /^\./ && $5 ~ /^080/ { print $5, $3 }' |
	while read -r lma size; do
		s=$((16#$lma)); e=$((s + 16#$size))
		if [ "$s" -lt $((0x0800C000)) ] && [ "$e" -gt $((0x08004000)) ]; then echo "$lma"; fi
	done)
check "F4 image leaves the calibration sectors free" [ -z "$overlap" ]
check "F4 stack at the bottom of SRAM" [ "$(sym "$f4" _sstack)" = 20000000 ]
check "F103 calibration pages at 0x0801F000" [ "$(sym "$f1" __calib_start)" = 0801f000 ]

want='openocd -f interface/stlink.cfg -f target/stm32f4x.cfg -c "program build/stm32f4/squeal-monitor.elf verify reset exit"'
got=$(env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make -s --no-print-directory flash DRY_RUN=1 TARGET=stm32f4 NUMERIC=float 2>/dev/null | tail -1)
check "make flash DRY_RUN=1 prints the OpenOCD command" [ "$got" = "$want" ]
got=$(tools/flash.sh --dry-run --target stm32f103 "$f1")
check "tools/flash.sh --dry-run for the F103" \
	[ "$got" = "openocd -f interface/stlink.cfg -f target/stm32f1x.cfg -c \"program $f1 verify reset exit\"" ]
check "tools/flash.sh refuses a missing image" not quiet tools/flash.sh --dry-run build/nonexistent.elf
echo "RESULT: $pass passed, $fail failed"
[ "$fail" = 0 ]
