#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Static RAM and stack of the monitor on the ECU (arm-none-eabi, Cortex-M4F,
# -Os): .bss/.data of firmware/app + firmware/monitor objects, the size of
# monitor_t, and the per-function stack (-fstack-usage) of the 1 ms path.
set -eu
ARM_CC=${ARM_CC:-arm-none-eabi-gcc}
if ! command -v "$ARM_CC" >/dev/null; then
	echo "$ARM_CC not installed: skipped"
	exit 0
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
flags="-std=c11 -ffreestanding -Os -mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16 -fstack-usage
	-Ifirmware/model -Ifirmware/protocol -Ifirmware/monitor -Ifirmware/app -Ihal"
for f in firmware/app/squeal_app.c firmware/monitor/*.c; do
	# shellcheck disable=SC2086
	(cd "$tmp" && $ARM_CC $flags -I"$OLDPWD"/firmware/model \
		-I"$OLDPWD"/firmware/protocol -I"$OLDPWD"/firmware/monitor -I"$OLDPWD"/firmware/app \
		-I"$OLDPWD"/hal -c "$OLDPWD/$f" -o "$(basename "$f" .c).o")
done
printf '#include "monitor.h"\nchar monitor_t_size[sizeof(monitor_t)];\n' >"$tmp/s.c"
# shellcheck disable=SC2086
(cd "$tmp" && $ARM_CC $flags -I"$OLDPWD"/firmware/model \
	-I"$OLDPWD"/firmware/protocol -I"$OLDPWD"/firmware/monitor -I"$OLDPWD"/hal -c s.c -o s.o)
arm-none-eabi-size "$tmp"/*.o | sed "s|$tmp/||" | grep -vP '\ts\.o$'
hex=$(arm-none-eabi-nm -S "$tmp/s.o" | awk '/monitor_t_size/ {print $2}')
echo "sizeof(monitor_t) on Cortex-M4: $((16#$hex)) bytes"
echo "stack per function (bytes):"
cat "$tmp"/*.su | awk -F'\t' '{split($1, a, ":"); printf "  %-28s %5s %s\n", a[4], $2, $3}' | sort -k2 -n -r | head -12
