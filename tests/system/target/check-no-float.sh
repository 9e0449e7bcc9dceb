#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Proves a linked image contains no floating point: no soft-float helper
# (__aeabi_f*, __aeabi_d*, libgcc's __*sf*/__*df*) is defined or referenced,
# and no VFP instruction (v<op>.f32/.f64, vmov/vldr/vstr/vpush/vpop of s/d
# registers, vmrs/vmsr) is in its code. Exit 0 when clean.
# Usage: tests/system/target/check-no-float.sh IMAGE.elf
set -euo pipefail
elf=$1
bad=0
syms=$(arm-none-eabi-nm "$elf" | awk '{ print $NF }' |
	grep -E '^__aeabi_([fd](add|sub|rsub|mul|div|cmp|cmpeq|cmplt|cmple|cmpge|cmpgt|cmpun|2|neg)|[iul]*2[fd]|[fd]2)|^__(add|sub|mul|div|neg|cmp|eq|ne|lt|le|gt|ge|unord|fix|fixuns|float|floatun|extend|trunc)[a-z]*[sdt]f[0-9]?$' || true)
if [ -n "$syms" ]; then
	echo "floating-point routines in $elf:"; echo "$syms" | sed 's/^/  /'
	bad=1
fi
insns=$(arm-none-eabi-objdump -d "$elf" |
	grep -E $'\t''v[a-z0-9]+(\.f32|\.f64|\.f16)?'$'\t''|'$'\t''(vmov|vldr|vstr|vpush|vpop|vldm|vstm|vmrs|vmsr)' || true)
if [ -n "$insns" ]; then
	echo "VFP instructions in $elf:"; echo "$insns" | head -20 | sed 's/^/  /'
	bad=1
fi
if [ "$bad" = 0 ]; then
	echo "no floating point in $elf: no __aeabi_f*/__aeabi_d* or libgcc float routine, no VFP instruction"
fi
exit "$bad"
