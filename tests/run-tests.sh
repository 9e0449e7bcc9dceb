#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Runs every test program given on the command line, keeps each one's output
# in build/test-logs/ (TEST_LOGDIR), and ends with one summary line
# "N passed, N failed, N skipped".
#
# Counting, per program:
#   - a line "RESULT: N passed, M failed[, K skipped]" (the last one), or
#   - cmocka's "[  PASSED  ] N test(s)." / "[  FAILED  ] N test(s)" /
#     "[  SKIPPED ] N test(s)" lines;
#   - otherwise the program counts as one test decided by its exit code.
# Skips: a program names each skipped check on a line "SKIP: <what> (<why>)"
# (cmocka: "[  SKIPPED ] <test name>"). The skip count is K from RESULT (or
# cmocka's count), else the number of SKIP: lines; a skip the program counted
# but did not name is listed as "(unnamed skip)". Every skip is listed in the
# log (build/test-logs/skips.txt) and printed.
# CI=true: a skip that does not match a line of tests/expected-skips.txt
# (program | what glob | reason) is a failure: it is counted as failed, not
# skipped, and the run fails.
set -u
logdir=${TEST_LOGDIR:-build/test-logs}
mkdir -p "$logdir"
expected=${EXPECTED_SKIPS:-tests/expected-skips.txt}
skiplog=$logdir/skips.txt
: >"$skiplog"
passed=0
failed=0
skipped=0
failed_progs=()
skips=()       # "prog: what" of every skip
unexpected=()  # the ones not in $expected (CI only)

# expected_skip PROG WHAT: 0 when a row of $expected covers it
expected_skip() {
	local prog=$1 what=$2 p w r
	[ -f "$expected" ] || return 1
	while IFS='|' read -r p w r; do
		p=$(echo "$p" | sed -E 's/^[ \t]+|[ \t]+$//g')
		w=$(echo "$w" | sed -E 's/^[ \t]+|[ \t]+$//g')
		r=$(echo "$r" | sed -E 's/^[ \t]+|[ \t]+$//g')
		case $p in '' | '#'*) continue ;; esac
		[ -n "$w" ] && [ -n "$r" ] || continue # a row without a reason covers nothing
		# shellcheck disable=SC2053 # $p and $w are glob patterns
		[[ $prog == $p ]] && [[ $what == $w ]] && return 0
	done <"$expected"
	return 1
}

for prog in "$@"; do
	name=$(echo "$prog" | tr '/ ' '__')
	log="$logdir/$name.log"
	start=$(date +%s)
	"$prog" >"$log" 2>&1
	rc=$?
	secs=$(( $(date +%s) - start ))
	p=0; f=0; s=0; counted=0
	# names of the skips this program reports
	mapfile -t names < <( {
		sed -nE 's/^SKIP: (.*)$/\1/p' "$log"
		grep -E '^\[  SKIPPED \] ' "$log" | grep -vE '^\[  SKIPPED \] [0-9]+ test' |
			sed -E 's/^\[  SKIPPED \] //' | sort -u
	} )
	if grep -qE '^RESULT: [0-9]+ passed, [0-9]+ failed' "$log"; then
		line=$(grep -E '^RESULT: [0-9]+ passed, [0-9]+ failed' "$log" | tail -1)
		p=$(echo "$line" | sed -E 's/^RESULT: ([0-9]+) passed.*/\1/')
		f=$(echo "$line" | sed -E 's/^RESULT: [0-9]+ passed, ([0-9]+) failed.*/\1/')
		s=$(echo "$line" | sed -nE 's/.* failed, ([0-9]+) skipped.*/\1/p')
		[ -n "$s" ] || s=${#names[@]}
		counted=1
	elif grep -qE '^\[  PASSED  \] [0-9]+ test' "$log"; then
		p=$(awk '/^\[  PASSED  \] [0-9]+ test/ {n += $4} END {print n + 0}' "$log")
		f=$(awk '/^\[  FAILED  \] [0-9]+ test/ {n += $4} END {print n + 0}' "$log")
		s=$(awk '/^\[  SKIPPED \] [0-9]+ test/ {n += $4} END {print n + 0}' "$log")
		counted=1
	else
		s=${#names[@]}
	fi
	if [ "$counted" = 0 ]; then
		if [ "$rc" = 0 ]; then p=1; else f=1; fi
	elif [ "$rc" != 0 ] && [ "$f" = 0 ]; then
		f=1 # crashed or failed after its own count: never hide it
	fi
	while [ "${#names[@]}" -lt "$s" ]; do names+=("(unnamed skip)"); done
	bad=0
	for ((i = 0; i < s; i++)); do
		what=${names[$i]}
		echo "$prog: $what" >>"$skiplog"
		skips+=("$prog: $what")
		if [ "${CI:-}" = true ] && ! expected_skip "$prog" "$what"; then
			unexpected+=("$prog: $what")
			bad=$((bad + 1))
		fi
	done
	s=$((s - bad))
	f=$((f + bad))
	passed=$((passed + p))
	failed=$((failed + f))
	skipped=$((skipped + s))
	skipnote=
	[ $((s + bad)) -gt 0 ] && skipnote=", $((s + bad)) skipped"
	if [ "$rc" = 0 ] && [ "$f" = 0 ]; then
		printf 'PASS  %-50s %4d passed%s  (%ds)\n' "$prog" "$p" "$skipnote" "$secs"
	else
		printf 'FAIL  %-50s %4d passed, %d failed%s (exit %d, %ds); last lines of %s:\n' \
			"$prog" "$p" "$f" "$skipnote" "$rc" "$secs" "$log"
		tail -n 30 "$log" | sed 's/^/    | /'
		failed_progs+=("$prog")
	fi
done
echo
if [ "${#skips[@]}" -gt 0 ]; then
	echo "skipped checks (also in $skiplog):"
	printf '  SKIP %s\n' "${skips[@]}"
fi
if [ "${#unexpected[@]}" -gt 0 ]; then
	echo "unexpected skips (CI=true; not in $expected), counted as failed:"
	printf '  %s\n' "${unexpected[@]}"
fi
if [ "${#failed_progs[@]}" -gt 0 ]; then
	echo "failed programs: ${failed_progs[*]}"
fi
echo "$passed passed, $failed failed, $skipped skipped"
[ "$failed" = 0 ] && [ "${#failed_progs[@]}" = 0 ]
