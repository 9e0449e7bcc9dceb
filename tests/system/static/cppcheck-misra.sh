#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# cppcheck (2.10) with its MISRA C:2012 addon plus cppcheck's own
# warning/style/portability checks, on firmware/ and hal/, for both numeric
# builds (float, and -DSQUEAL_NUMERIC_FIXED).
#
#   tests/system/static/cppcheck-misra.sh           check: fails on any finding that
#                                            is not a documented deviation, on
#                                            a deviation over its Count budget,
#                                            on any cppcheck/addon failure, and
#                                            when the canary is not flagged
#   tests/system/static/cppcheck-misra.sh --count   no deviations applied: counts by
#                                            rule and area (the "before" view)
#                                            and per deviation row, paste-ready
#                                            (make misra-count)
#
# The MISRA rule texts are not shipped with cppcheck (they are licensed), so
# the addon runs without --rule-texts and reports rule numbers only
# ("misra-c2012-15.5"). tests/system/static/misra.json is the addon configuration.
#
# Deviations live in docs/misra-deviations.md, in the table under the heading
# "## Deviations", whose rows read
#   | 15.5 | `firmware/*` `hal/linux/*` | count | reason |
# (a MISRA rule number or a cppcheck check id, then file globs in backticks).
# This script turns every row into cppcheck suppressions "id:glob", so a new
# finding of a rule in a place that is not documented fails the check.
# The "Count" cell of each row is its budget: the row's findings with no
# deviation applied (both builds, each file:line:id once) must not exceed it
# (tests/system/static/misra_budget.py).
# cppcheck's exit status, anything it prints that is not a finding or its
# progress ("Did not find addon", "Bailing out ... internal error", an addon
# traceback), an internalError/syntaxError finding, and a run that did not
# check every file it was given are failures: never "0 findings, PASS".
# Positive control: tests/system/static/canary/misra_canary.c, whose marked lines
# ("canary: <id>...") must be exactly the findings cppcheck + addon report.
# Negative controls: tests/system/static/test-cppcheck-misra-control.sh, through
# MISRA_ADDON (addon configuration), MISRA_DEVIATIONS (the table),
# MISRA_CORE_DIRS (what the core group checks), MISRA_GROUPS, MISRA_BUILDS,
# MISRA_OUT.
# Prints "RESULT: N passed, M failed".
set -u
cd "$(dirname "$0")/../../.."

mode=check
[ "${1:-}" = --count ] && mode=count
out=${MISRA_OUT:-build/static}
dev=${MISRA_DEVIATIONS:-docs/misra-deviations.md}
addon=${MISRA_ADDON:-tests/system/static/misra.json}
builds=${MISRA_BUILDS:-float fixed}
canary=tests/system/static/canary/misra_canary.c
mkdir -p "$out"

if ! command -v cppcheck >/dev/null; then
	echo "cppcheck not installed"; echo "RESULT: 0 passed, 1 failed"; exit 1
fi

# What is checked: all of firmware/ and hal/ (the Linux OS layer and the ECU
# layers included; their deviations are listed separately), in groups that
# share include paths: the ECU HALs take chip.h from their chip directory
# exactly as mk/target.mk compiles them.
incs=(-Ifirmware/model -Ifirmware/protocol -Ifirmware/monitor
      -Ifirmware/app -Ihal)
# shellcheck disable=SC2206 # MISRA_GROUPS is a list of names
groups=(${MISRA_GROUPS:-core vbus stm32f4 stm32f103})
# shellcheck disable=SC2086 # MISRA_CORE_DIRS is a list of directories
files_core() { find ${MISRA_CORE_DIRS:-firmware hal/linux hal/host hal/common} -name '*.c' | sort; }
incs_core=()
own_core='^(firmware/|hal/linux/|hal/host/|hal/common/|hal/hal\.h:|hal/sq_status\.h:|hal/sq_contract\.h:|hal/hal_can_common\.h:)'
# the in-memory backend defines the same hal.h functions as hal/linux: its
# own group (a program links one backend)
files_vbus() { find hal/vbus -name '*.c' | sort; }
incs_vbus=(-Ihal/vbus)
own_vbus='^hal/vbus/'
files_stm32f4() { [ -d hal/stm32f4 ] && find hal/stm32f4 -name '*.c' | sort; }
incs_stm32f4=(-Ihal/stm32f4/stm32f405 -Ihal/stm32f4)
own_stm32f4='^hal/stm32f4/'
files_stm32f103() { [ -d hal/stm32f103 ] && find hal/stm32f103 -name '*.c' | sort; }
incs_stm32f103=(-Ihal/stm32f103/stm32f103xb -Ihal/stm32f4)
own_stm32f103='^hal/stm32f103/'

# Deviation table -> suppressions list
supp=$out/misra-suppressions.txt
: >"$supp"
[ "$mode" = check ] && /usr/bin/python3 tests/system/static/misra_budget.py suppressions "$dev" >"$supp"

passed=0
failed=0
result() { # ok?, text
	if [ "$1" = 0 ]; then
		echo "PASS $2"; passed=$((passed + 1))
	else
		echo "FAIL $2"; failed=$((failed + 1))
	fi
}
finding_re='^[^:]+:[0-9]+:[A-Za-z0-9_.-]+:'
# ids that mean "this file was not (fully) analysed", whatever the file
broken_ids='^[^:]+:[0-9]+:(internalError|internalAstError|syntaxError|cppcheckError|misra-config|preprocessorErrorDirective|unknownMacro):'

# cppcheck_run TAG BUILD-DIR ARGS... -- FILES...: runs cppcheck; findings in
# $out/TAG.err; tool failures appended to $out/tool-errors.txt.
cppcheck_run() {
	local tag=$1 bdir=$2; shift 2
	local args=() files=() rc nchecked
	while [ $# -gt 0 ] && [ "$1" != -- ]; do args+=("$1"); shift; done
	shift
	files=("$@")
	# a fresh build dir every run: cppcheck keeps each file's cross-file
	# (CTU) information there, and after a header changed, stale entries
	# report declarations twice (8.5) at lines that no longer hold them
	rm -rf "$bdir"
	mkdir -p "$bdir"
	cppcheck --std=c11 --platform=unix64 --enable=warning,style,portability \
		--library=tests/system/static/hal-contract.cfg \
		--addon="$addon" \
		--template='{file}:{line}:{id}:{severity}:{message}' \
		--suppress=missingIncludeSystem --suppress=missingInclude \
		--suppress=unmatchedSuppression \
		--cppcheck-build-dir="$bdir" -j2 \
		"${args[@]}" "${files[@]}" 2>"$out/$tag.err" >"$out/$tag.out"
	rc=$?
	{
		[ "$rc" = 0 ] || echo "$tag: cppcheck exited with status $rc"
		[ "${#files[@]}" -gt 0 ] || echo "$tag: no files to check"
		grep -vE '^Checking .*\.\.\.$|^[0-9]+/[0-9]+ files checked' "$out/$tag.out" | sed "s|^|$tag: |"
		grep -vE "$finding_re" "$out/$tag.err" | sed "s|^|$tag: |"
		grep -E "$broken_ids" "$out/$tag.err" | sed "s|^|$tag: |"
		nchecked=$(sed -nE 's/^Checking ([^ :]+)(:| \.\.\.).*/\1/p' "$out/$tag.out" | sort -u | wc -l)
		[ "$nchecked" -ge "${#files[@]}" ] ||
			echo "$tag: cppcheck checked $nchecked of ${#files[@]} files"
	} >>"$out/tool-errors.txt"
}

# run_build NAME SUPPRESS(yes|no) DEFINES...: findings of firmware/ and hal/
# in $out/findings-NAME.txt (with the deviations applied when SUPPRESS=yes)
run_build() {
	local name=$1 sup=$2; shift 2
	local raw=$out/findings-$name.txt
	local args=()
	local g

	[ "$sup" = yes ] && args+=(--suppressions-list="$supp")
	: >"$raw.all"
	for g in "${groups[@]}"; do
		local -n gincs=incs_$g
		local -n gown=own_$g
		local gfiles

		mapfile -t gfiles < <("files_$g")
		if [ ${#gfiles[@]} = 0 ]; then
			# the ECU groups may be absent; the core group never is
			[ "$g" = core ] && echo "$name-$g: no files checked" >>"$out/tool-errors.txt"
			continue
		fi
		cppcheck_run "cppcheck-$name-$g" "$out/cppcheck-$name-$g" \
			"${incs[@]}" "${gincs[@]}" "$@" "${args[@]}" -- "${gfiles[@]}"
		# a group reports on its own files only: the others' headers
		# are seen through a few of their users there (2.5 "unused
		# macro" would be judged on a partial program)
		grep -E "$gown" "$out/cppcheck-$name-$g.err" >>"$raw.all"
	done
	# only finding lines (file:line:id:...) count
	grep -E "$finding_re" "$raw.all" | sort -u >"$raw"
	rm -f "$raw.all"
}

: >"$out/tool-errors.txt"
defs_float=()
defs_fixed=(-DSQUEAL_NUMERIC_FIXED)
all_files=()
for n in $builds; do
	defs=defs_$n[@]
	[ "$mode" = check ] && run_build "$n" yes "${!defs}"
	run_build "$n-all" no "${!defs}"
	all_files+=("$out/findings-$n-all.txt")
done

if [ "$mode" = count ]; then
	sort -u "${all_files[@]}" >"$out/findings-all.txt"
	for n in $builds; do
		echo "$n: $(wc -l <"$out/findings-$n-all.txt") findings"
	done
	echo "all: $(wc -l <"$out/findings-all.txt") findings"
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
	echo
	/usr/bin/python3 tests/system/static/misra_budget.py counts "$dev" "${all_files[@]}"
	if [ -s "$out/tool-errors.txt" ]; then
		echo; echo "cppcheck or the addon failed: these counts are incomplete:"
		sed 's/^/    /' "$out/tool-errors.txt"
		exit 1
	fi
	exit 0
fi

for n in $builds; do
	c=$(wc -l <"$out/findings-$n.txt")
	if [ "$c" = 0 ]; then
		result 0 "$n: no findings outside $dev"
	else
		result 1 "$n: $c findings not covered by $dev:"
		sed 's/^/    /' "$out/findings-$n.txt" | head -60
	fi
done

# budgets: one test per deviation row
budget=$(/usr/bin/python3 tests/system/static/misra_budget.py check "$dev" "${all_files[@]}")
echo "$budget" | grep -vE '^(PASS|BUDGETS)'
over=$(echo "$budget" | grep -c '^FAIL')
rows=$(echo "$budget" | grep -c '^PASS')
passed=$((passed + rows)); failed=$((failed + over))
echo "deviation budgets: $rows rows within their Count, $over over (make misra-count prints today's counts)"

# the canary: exactly the marked findings, so the addon and every check
# class are known to run
cppcheck_run canary "$out/cppcheck-canary" -- "$canary"
want=$(awk '{ if (match($0, /canary: [A-Za-z0-9_. -]+\*\//)) {
		n = split(substr($0, RSTART + 8, RLENGTH - 10), ids, " ")
		for (i = 1; i <= n; i++) print NR ":" ids[i] } }' "$canary" | sort)
got=$(grep -E "$finding_re" "$out/canary.err" | cut -d: -f2,3 | sort -u)
missed=$(comm -23 <(echo "$want") <(echo "$got") | tr '\n' ' ')
extra=$(comm -13 <(echo "$want") <(echo "$got") | tr '\n' ' ')
result "$([ -n "$want" ] && [ -z "$missed" ] && [ -z "$extra" ] && echo 0 || echo 1)" \
	"canary: cppcheck + addon flag exactly the $(echo "$want" | grep -c .) marked findings of $canary${missed:+ (missed: $missed)}${extra:+ (unexpected: $extra)}"

if [ -s "$out/tool-errors.txt" ]; then
	result 1 "cppcheck and the MISRA addon ran cleanly on every file:"
	sed 's/^/    /' "$out/tool-errors.txt" | head -40
else
	result 0 "cppcheck and the MISRA addon ran cleanly on every file"
fi
echo "RESULT: $passed passed, $failed failed"
[ "$failed" = 0 ]
