#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# firmware/ compiles unchanged, warning-free, freestanding, for the ECU's
# Cortex-M4F (float build) and a Cortex-M3 without FPU (fixed build), and the
# fixed build's object code contains no floating point: no soft-float helper
# (__aeabi_f*, __aeabi_d*, __*sf*, __*df*) is referenced and no float
# instruction (VFP) appears. Prints "RESULT: N passed, M failed".
set -u
cd "$(dirname "$0")/../../.."
out=build/portable
rm -rf "$out"; mkdir -p "$out"
WARN="-std=c11 -Wall -Wextra -Wconversion -Wsign-conversion -Wshadow -Wstrict-prototypes -Wmissing-prototypes -Wundef -Wcast-align -Wdouble-promotion -Werror"
INC="-Ifirmware/model -Ifirmware/protocol -Ifirmware/monitor -Ifirmware/app -Ihal"
srcs=$(ls firmware/*/*.c firmware/*.c 2>/dev/null)
pass=0; fail=0
check() { if "$@"; then pass=$((pass+1)); else fail=$((fail+1)); echo "FAILED: $*"; fi; }

build() { # name cflags...
	local name=$1; shift
	mkdir -p "$out/$name"
	local ok=0
	for s in $srcs; do
		o="$out/$name/$(echo "$s" | tr / _).o"
		arm-none-eabi-gcc $WARN -ffreestanding -Os "$@" $INC -c "$s" -o "$o" || ok=1
	done
	return $ok
}
echo "== Cortex-M4F, float build"
check build m4f -mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16 -fsingle-precision-constant
echo "== Cortex-M3, fixed build"
check build m3fixed -mcpu=cortex-m3 -mthumb -mfloat-abi=soft -DSQUEAL_NUMERIC_FIXED

no_float_symbols() {
	local hits
	hits=$(arm-none-eabi-nm -u "$out"/m3fixed/*.o | grep -E '__aeabi_[fd]|__(add|sub|mul|div|neg|cmp|eq|ne|lt|le|gt|ge|unord|fix|float|extend|trunc)[a-z]*[sd]f' || true)
	[ -z "$hits" ] || { echo "float helpers referenced: $hits"; return 1; }
}
no_vfp_instructions() {
	local hits
	hits=$(arm-none-eabi-objdump -d "$out"/m3fixed/*.o | grep -E '\bv(add|sub|mul|div|mov|ldr|str|cvt|cmp|sqrt|neg|abs|fma|push|pop)' || true)
	[ -z "$hits" ] || { echo "VFP instructions: $(echo "$hits" | head -3)"; return 1; }
}
# the float build really uses the FPU (so the check above can tell)
float_build_uses_vfp() {
	arm-none-eabi-objdump -d "$out"/m4f/*.o | grep -qE '\bv(add|mul|div)\.f32'
}
# no libc I/O, heap or OS call is referenced by firmware/
no_os_calls() {
	local hits
	hits=$(arm-none-eabi-nm -u "$out"/m4f/*.o "$out"/m3fixed/*.o | grep -E ' (malloc|calloc|realloc|free|printf|fprintf|sprintf|snprintf|puts|fopen|exit|abort|_sbrk|_write|_read|time|clock)$' || true)
	[ -z "$hits" ] || { echo "OS/libc calls: $hits"; return 1; }
}
check no_float_symbols
check no_vfp_instructions
check float_build_uses_vfp
check no_os_calls
echo "RESULT: $pass passed, $fail failed"
[ "$fail" = 0 ]
