#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Calibration write protection, proved on the build products: no firmware
# object calls hal_calib_write(), in either numeric build, and no firmware
# source names it. So no CAN frame (or anything else the firmware reacts to)
# can change the stored calibration: the only writers are outside firmware/
# (SWD flash programming on the ECU, the --calib file on Linux). See
# docs/reliability.md. Prints "RESULT: N passed, M failed, K skipped".
# An ECU image that was not built is a counted skip ("SKIP: ..."), and a
# failure when CI=true (CI builds everything). CALIB_ELFS="a.elf b.elf"
# checks other images (the negative control gives a missing one).
set -u
cd "$(dirname "$0")/../../.."
passed=0
failed=0
skipped=0
result() { # ok?, text
	if [ "$1" = 0 ]; then
		echo "PASS $2"; passed=$((passed + 1))
	else
		echo "FAIL $2"; failed=$((failed + 1))
	fi
}

for lib in build/host/libfirmware.a build/host-fixed/libfirmware.a; do
	if [ ! -f "$lib" ]; then
		result 1 "$lib missing (make all first)"
		continue
	fi
	calls=$(nm -A "$lib" 2>/dev/null | grep -E ' [UTtW] hal_calib_write$' || true)
	result "$([ -z "$calls" ] && echo 0 || echo 1)" "$lib references no hal_calib_write ${calls:+($calls)}"
	# what the firmware does take from the HAL (for the record)
	echo "    HAL functions used: $(nm -u "$lib" 2>/dev/null | awk '/ U hal_/ {print $2}' | sort -u | tr '\n' ' ')"
done
# The ECU images (mk/target.mk, built by make all) are linked with
# --gc-sections: if nothing can reach the calibration writer, the writer and
# the flash erase/program routines are not even in the image.
for elf in ${CALIB_ELFS:-build/stm32f4/squeal-monitor.elf build/stm32f103/squeal-monitor.elf}; do
	if [ ! -f "$elf" ]; then
		if [ "${CI:-}" = true ]; then
			result 1 "$elf built (CI builds every image: make all)"
		else
			echo "SKIP: $elf contains no calibration writer ($elf not built: make all)"
			skipped=$((skipped + 1))
		fi
		continue
	fi
	w=$(arm-none-eabi-nm "$elf" 2>/dev/null | grep -E ' (hal_calib_write|chip_flash_program|chip_flash_erase_slot)$' || true)
	result "$([ -z "$w" ] && echo 0 || echo 1)" "$elf contains no calibration writer or flash program/erase code ${w:+($w)}"
done
src=$(grep -rn 'hal_calib_write' firmware/ || true)
result "$([ -z "$src" ] && echo 0 || echo 1)" "no firmware/ source names hal_calib_write ${src:+($src)}"
echo "RESULT: $passed passed, $failed failed, $skipped skipped"
[ "$failed" = 0 ]
