#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# firmware/ under clang-14 with every warning, as errors, for both numeric
# builds, on the host and (syntax and semantic analysis only: clang ships
# the freestanding headers firmware/ uses) on the two ECU targets:
#   host-float    x86-64, float build
#   host-fixed    x86-64, -DSQUEAL_NUMERIC_FIXED
#   m4f-float     thumbv7em Cortex-M4F hard float (STM32F405/407)
#   m3-fixed      thumbv7m Cortex-M3 soft float, fixed build (STM32F103)
#
# Flags: the project's WARN set (-Wall -Wextra -Wconversion -Wshadow ... see
# the Makefile) plus -Weverything, minus these, each for a reason:
#   -Wno-padded                 structs are not packed on purpose (nothing
#                               is serialised by memcpy; layouts are explicit
#                               in pack/encode), so padding is expected
#   -Wno-covered-switch-default every switch keeps a default (MISRA 16.4):
#                               an enum object may hold any int value after
#                               memory corruption, and default handles it
#   -Wno-switch-enum            the same switches list the cases they act on
#                               and let default take the rest on purpose
#   -Wno-empty-translation-unit squeal_model_float.c / _fixed.c are empty in
#                               the other numeric build by design
# Prints "RESULT: N passed, M failed" (one test per configuration).
set -u
cd "$(dirname "$0")/../../.."

CLANG=${CLANG:-clang-14}
warn=(-std=c11 -ffreestanding -Wall -Wextra -Wconversion -Wsign-conversion
      -Wshadow -Wstrict-prototypes -Wmissing-prototypes -Wundef -Wcast-align
      -Wdouble-promotion -Wformat=2 -Weverything -Werror
      -Wno-padded -Wno-covered-switch-default -Wno-switch-enum
      -Wno-empty-translation-unit)
incs=(-Ifirmware/model -Ifirmware/protocol -Ifirmware/monitor
      -Ifirmware/app -Ihal)
mapfile -t srcs < <(find firmware -name '*.c' | sort)

passed=0
failed=0
check() { # name, flags...
	local name=$1; shift
	local log
	local bad=0
	local f

	log=$(mktemp)
	for f in "${srcs[@]}"; do
		if ! "$CLANG" "${warn[@]}" "$@" "${incs[@]}" -fsyntax-only "$f" >>"$log" 2>&1; then
			bad=1
		fi
	done
	if [ "$bad" = 0 ] && ! grep -q 'warning:' "$log"; then
		echo "PASS $name (${#srcs[@]} files)"
		passed=$((passed + 1))
	else
		echo "FAIL $name:"
		grep -E 'warning:|error:' "$log" | sed 's/^/    /' | head -40
		failed=$((failed + 1))
	fi
	rm -f "$log"
}

if ! command -v "$CLANG" >/dev/null; then
	echo "$CLANG not installed"; echo "RESULT: 0 passed, 1 failed"; exit 1
fi
check host-float
check host-fixed -DSQUEAL_NUMERIC_FIXED
check m4f-float --target=thumbv7em-none-eabihf -mcpu=cortex-m4 -mfloat-abi=hard -mfpu=fpv4-sp-d16
check m3-fixed --target=thumbv7m-none-eabi -mcpu=cortex-m3 -mfloat-abi=soft -DSQUEAL_NUMERIC_FIXED
echo "RESULT: $passed passed, $failed failed"
[ "$failed" = 0 ]
