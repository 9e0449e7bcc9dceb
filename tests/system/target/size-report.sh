#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Flash and RAM of an ECU image, from the linker's own accounting
# (__flash_used, __ram_used, __stack_reserve in linker/*.ld).
# Usage: tests/system/target/size-report.sh IMAGE.elf
set -euo pipefail
elf=$1
sym() {
	local hex
	hex=$(arm-none-eabi-nm "$elf" | awk -v s="$1" '$3 == s { print $1 }')
	[ -n "$hex" ] || { echo "$elf: no symbol $1" >&2; exit 1; }
	echo $((16#$hex))
}
flash=$(sym __flash_used)
ram=$(sym __ram_used)
stack=$(sym __stack_reserve)
printf '%s: flash %d bytes (%.1f KiB), RAM %d bytes (%.1f KiB) incl. stack reserve %d\n' \
	"$elf" "$flash" "$(echo "$flash / 1024" | bc -l)" "$ram" "$(echo "$ram / 1024" | bc -l)" "$stack"
