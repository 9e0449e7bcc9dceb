#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Flash an ECU image through an ST-LINK with OpenOCD: program, verify, reset.
#   tools/flash.sh [--dry-run] [--target stm32f4|stm32f103|stm32g474] IMAGE.elf
# --dry-run prints the exact command line instead of running it.
# The ELF (or HEX) is flashed, never the .bin: only the sectors the image
# covers are erased, so the calibration sectors keep their contents.
set -euo pipefail
dry=0
target=stm32f4
while [ $# -gt 0 ]; do
	case "$1" in
	--dry-run) dry=1; shift ;;
	--target) target=$2; shift 2 ;;
	-h|--help) sed -n '3,7p' "$0"; exit 0 ;;
	-*) echo "flash.sh: unknown option $1" >&2; exit 2 ;;
	*) break ;;
	esac
done
[ $# -eq 1 ] || { echo "usage: tools/flash.sh [--dry-run] [--target stm32f4|stm32f103|stm32g474] IMAGE.elf" >&2; exit 2; }
image=$1
case "$target" in
stm32f4) cfg=target/stm32f4x.cfg ;;
stm32f103) cfg=target/stm32f1x.cfg ;;
stm32g474) cfg=target/stm32g4x.cfg ;;
*) echo "flash.sh: unknown target $target" >&2; exit 2 ;;
esac
[ -f "$image" ] || { echo "flash.sh: $image not found (make firmware first)" >&2; exit 1; }
cmd=(openocd -f interface/stlink.cfg -f "$cfg" -c "program $image verify reset exit")
if [ "$dry" = 1 ]; then
	echo "openocd -f interface/stlink.cfg -f $cfg -c \"program $image verify reset exit\""
	exit 0
fi
exec "${cmd[@]}"
