#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# make mutate's mutant list still fits the code: every mutant's original text
# occurs exactly once in its file and every mutated file has tests mapped
# (tools/mutate.py --list checks both and runs nothing). Without this a
# refactor silently turns the mutation score into "cannot apply".
# Prints "RESULT: N passed, M failed".
set -u
cd "$(dirname "$0")/../.."
out=$(/usr/bin/python3 tools/mutate.py --list 2>&1)
rc=$?
n=$(echo "$out" | grep -c '^[a-z0-9-]\+ \+[a-z]')
if [ "$rc" = 0 ] && [ "$n" -gt 0 ]; then
	echo "PASS: $n mutants apply to today's sources (tools/mutants.txt)"
	echo "RESULT: 1 passed, 0 failed"
else
	echo "FAIL: tools/mutants.txt no longer fits the sources (exit $rc):"
	echo "$out" | grep -v '^ ' | head -20 | sed 's/^/    /'
	echo "RESULT: 0 passed, 1 failed"
	exit 1
fi
