#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Runs every test program given on the command line, keeps each one's output
# in build/test-logs/, and ends with one summary line "N passed, N failed".
# A program counts its own tests if it prints cmocka's "[  PASSED  ] N test(s)."
# and "[  FAILED  ] N test(s)" lines or a line "RESULT: N passed, M failed";
# otherwise it counts as one test decided by its exit code.
set -u
logdir=build/test-logs
mkdir -p "$logdir"
passed=0
failed=0
failed_progs=()
for prog in "$@"; do
	name=$(echo "$prog" | tr '/ ' '__')
	log="$logdir/$name.log"
	start=$(date +%s)
	"$prog" >"$log" 2>&1
	rc=$?
	secs=$(( $(date +%s) - start ))
	p=0; f=0; counted=0
	if grep -qE '^RESULT: [0-9]+ passed, [0-9]+ failed' "$log"; then
		line=$(grep -E '^RESULT: [0-9]+ passed, [0-9]+ failed' "$log" | tail -1)
		p=$(echo "$line" | sed -E 's/^RESULT: ([0-9]+) passed.*/\1/')
		f=$(echo "$line" | sed -E 's/.* ([0-9]+) failed.*/\1/')
		counted=1
	elif grep -qE '^\[  PASSED  \] [0-9]+ test' "$log"; then
		p=$(awk '/^\[  PASSED  \] [0-9]+ test/ {n += $4} END {print n + 0}' "$log")
		f=$(awk '/^\[  FAILED  \] [0-9]+ test/ {n += $4} END {print n + 0}' "$log")
		counted=1
	fi
	if [ "$counted" = 0 ]; then
		if [ "$rc" = 0 ]; then p=1; else f=1; fi
	elif [ "$rc" != 0 ] && [ "$f" = 0 ]; then
		f=1 # crashed or failed after its own count: never hide it
	fi
	passed=$((passed + p))
	failed=$((failed + f))
	if [ "$rc" = 0 ] && [ "$f" = 0 ]; then
		printf 'PASS  %-50s %4d passed  (%ds)\n' "$prog" "$p" "$secs"
	else
		printf 'FAIL  %-50s %4d passed, %d failed (exit %d, %ds); last lines of %s:\n' \
			"$prog" "$p" "$f" "$rc" "$secs" "$log"
		tail -n 30 "$log" | sed 's/^/    | /'
		failed_progs+=("$prog")
	fi
done
echo
if [ "${#failed_progs[@]}" -gt 0 ]; then
	echo "failed programs: ${failed_progs[*]}"
fi
echo "$passed passed, $failed failed"
[ "$failed" = 0 ] && [ "${#failed_progs[@]}" = 0 ]
