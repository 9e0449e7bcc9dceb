#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Flash an ECU image through an ST-LINK with OpenOCD: program, verify, reset.
#   usage: tools/flash.sh [--dry-run] [--target stm32f4|stm32f103|stm32g474] IMAGE.elf
# --dry-run prints the exact command line instead of running it.
# The ELF (or HEX) is flashed, never the .bin: only the sectors the image
# covers are erased, so the calibration sectors keep their contents.
# Needs Debian's openocd; without it, or without a probe, one line says what
# is missing (exit 1).
set -euo pipefail
dry=0
target=stm32f4
while [ $# -gt 0 ]; do
	case "$1" in
	--dry-run) dry=1; shift ;;
	--target) target=$2; shift 2 ;;
	-h|--help) sed -n '3,9p' "$0"; exit 0 ;;
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
command -v openocd >/dev/null 2>&1 ||
	{ echo "flash.sh: openocd not found: install Debian's package openocd (sudo apt-get install openocd)" >&2; exit 1; }
# OpenOCD's own lines stay visible; a missing probe gets one line saying what to check.
log=$(mktemp)
trap 'rm -f "$log"' EXIT
set +e
"${cmd[@]}" 2>&1 | tee "$log"
rc=${PIPESTATUS[0]}
set -e
if [ "$rc" != 0 ]; then
	if grep -qiE 'no device found|open failed|unable to open|LIBUSB_ERROR_ACCESS' "$log"; then
		echo "flash.sh: no ST-LINK probe reached: plug it in by USB (lsusb lists 0483:3748 or 0483:374b), use a data cable, and let this user open it (Debian's openocd package installs the udev rules; re-plug after installing, or run as root)" >&2
	elif grep -qiE 'target voltage|init mode failed|unable to connect|Error connecting DP' "$log"; then
		echo "flash.sh: the ST-LINK answers but the MCU does not: check the board's power (3.3 V sense), SWDIO/SWCLK/GND and NRST wiring" >&2
	fi
	exit 1
fi
