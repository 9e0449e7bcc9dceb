#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# cppcheck (2.10) with its MISRA C:2012 addon plus cppcheck's own
# warning/style/portability checks, on firmware/ and hal/, for both numeric
# builds (float, and -DSQUEAL_NUMERIC_FIXED).
#
#   tests/static/cppcheck-misra.sh           check: fails on any finding that
#                                            is not a documented deviation
#   tests/static/cppcheck-misra.sh --count   no deviations applied: counts by
#                                            rule and area (the "before" view)
#
# The MISRA rule texts are not shipped with cppcheck (they are licensed), so
# the addon runs without --rule-texts and reports rule numbers only
# ("misra-c2012-15.5"). tests/static/misra.json is the addon configuration.
#
# Deviations live in docs/misra-deviations.md, in the table under the heading
# "## Deviations", whose rows read
#   | 15.5 | `firmware/*` `hal/linux/*` | count | reason |
# (a MISRA rule number or a cppcheck check id, then file globs in backticks).
# This script turns every row into cppcheck suppressions "id:glob", so a new
# finding of a rule in a place that is not documented fails the check.
# Prints "RESULT: N passed, M failed" (one test per numeric build).
set -u
cd "$(dirname "$0")/../.."

mode=check
[ "${1:-}" = --count ] && mode=count
out=build/static
dev=docs/misra-deviations.md
mkdir -p "$out"

if ! command -v cppcheck >/dev/null; then
	echo "cppcheck not installed"; echo "RESULT: 0 passed, 1 failed"; exit 1
fi

# What is checked: all of firmware/ and hal/ (the Linux OS layer and the ECU
# layers included; their deviations are listed separately), in groups that
# share include paths: the ECU HALs take chip.h from their chip directory
# exactly as mk/target.mk compiles them.
incs=(-Ifirmware/common -Ifirmware/model -Ifirmware/protocol -Ifirmware/monitor
      -Ifirmware/app -Ihal)
groups=(core stm32f4 stm32f103)
files_core() { find firmware hal/linux -name '*.c' | sort; }
incs_core=()
own_core='^(firmware/|hal/linux/|hal/hal\.h:)'
files_stm32f4() { [ -d hal/stm32f4 ] && find hal/stm32f4 -name '*.c' | sort; }
incs_stm32f4=(-Ihal/stm32f4/stm32f405 -Ihal/stm32f4)
own_stm32f4='^hal/stm32f4/'
files_stm32f103() { [ -d hal/stm32f103 ] && find hal/stm32f103 -name '*.c' | sort; }
incs_stm32f103=(-Ihal/stm32f103/stm32f103xb -Ihal/stm32f4)
own_stm32f103='^hal/stm32f103/'

# Deviation table -> suppressions list
supp=$out/misra-suppressions.txt
: >"$supp"
if [ "$mode" = check ]; then
	awk -F'|' '
	/^## / { in_dev = ($0 ~ /^## Deviations/) }
	in_dev && /^\|/ {
		rule = $2; gsub(/^[ \t]+|[ \t]+$/, "", rule)
		if (rule ~ /^[0-9]+\.[0-9]+$/) id = "misra-c2012-" rule
		else if (rule ~ /^[A-Za-z][A-Za-z0-9_]*$/ && rule != "Rule") id = rule
		else next
		globs = $3
		while (match(globs, /`[^`]+`/)) {
			print id ":" substr(globs, RSTART + 1, RLENGTH - 2)
			globs = substr(globs, RSTART + RLENGTH)
		}
	}' "$dev" >"$supp"
fi

run_build() { # name, extra defines...
	local name=$1; shift
	local raw=$out/findings-$name.txt
	local args=()
	local g

	[ "$mode" = check ] && args+=(--suppressions-list="$supp")
	: >"$raw.all"
	for g in "${groups[@]}"; do
		local bdir=$out/cppcheck-$name-$g
		local -n gincs=incs_$g
		local -n gown=own_$g
		local gfiles

		mapfile -t gfiles < <("files_$g")
		[ ${#gfiles[@]} -gt 0 ] || continue
		mkdir -p "$bdir"
		cppcheck --std=c11 --platform=unix64 --enable=warning,style,portability \
			--addon=tests/static/misra.json \
			--template='{file}:{line}:{id}:{severity}:{message}' \
			--suppress=missingIncludeSystem --suppress=missingInclude \
			--suppress=unmatchedSuppression \
			--cppcheck-build-dir="$bdir" -q -j2 \
			"${incs[@]}" "${gincs[@]}" "$@" "${args[@]}" "${gfiles[@]}" \
			2>"$raw.g" >/dev/null
		# a group reports on its own files only: the others' headers
		# are seen through a few of their users there (2.5 "unused
		# macro" would be judged on a partial program)
		grep -E "$gown" "$raw.g" >>"$raw.all"
		grep -vE '^[^:]+:[0-9]+:[A-Za-z0-9_.-]+:' "$raw.g" >>"$raw.all"
	done
	rm -f "$raw.g"
	# only finding lines (file:line:id:...) count
	grep -E '^[^:]+:[0-9]+:[A-Za-z0-9_.-]+:' "$raw.all" | sort -u >"$raw"
	rm -f "$raw.all"
}

run_build float
run_build fixed -DSQUEAL_NUMERIC_FIXED

if [ "$mode" = count ]; then
	sort -u "$out/findings-float.txt" "$out/findings-fixed.txt" >"$out/findings-all.txt"
	for n in float fixed all; do
		echo "$n: $(wc -l <"$out/findings-$n.txt") findings"
	done
	echo
	echo "by rule and area (both builds, each finding once):"
	awk -F: '
	{
		id = $3; sub(/^misra-c2012-/, "", id)
		f = $1
		if (f ~ /^firmware\//) { split(f, p, "/"); area = p[1] "/" p[2] }
		else if (f ~ /^hal\/[^\/]+\//) { split(f, p, "/"); area = p[1] "/" p[2] }
		else area = "hal/hal.h"
		n[id]++; a[id, area]++; areas[area] = 1; total++
	}
	END {
		for (r in n) {
			s = ""
			for (ar in areas) if (a[r, ar]) s = s " " ar "=" a[r, ar]
			printf "%-22s %5d %s\n", r, n[r], s
		}
		printf "%-22s %5d\n", "TOTAL", total
	}' "$out/findings-all.txt" | sort -t' ' -k1,1V
	exit 0
fi

passed=0
failed=0
for n in float fixed; do
	c=$(wc -l <"$out/findings-$n.txt")
	if [ "$c" = 0 ]; then
		echo "PASS $n: no findings outside docs/misra-deviations.md"
		passed=$((passed + 1))
	else
		echo "FAIL $n: $c findings not covered by docs/misra-deviations.md:"
		sed 's/^/    /' "$out/findings-$n.txt" | head -60
		failed=$((failed + 1))
	fi
done
echo "RESULT: $passed passed, $failed failed"
[ "$failed" = 0 ]
