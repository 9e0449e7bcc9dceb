# shellcheck shell=bash
# SPDX-License-Identifier: MIT
# Shared by the suite's shell self-tests and negative controls (sourced):
#   check "description" command...   runs the command INSIDE the check (a
#                                    compound condition: check "d" all_of ...)
#   all_of 'cond' 'cond'...          true when every condition is; one
#                                    argument of check, so that every part
#                                    runs inside it (check "d" [ A ] && [ B ]
#                                    would run [ B ] outside and drop it)
#   any_of 'cond' 'cond'...          true when one of them is
#   checks_done                      prints "RESULT: N passed, M failed" and
#                                    returns non-zero on a failure
pass=0
fail=0
check() { # description, condition...
	local d=$1; shift
	if "$@"; then pass=$((pass + 1)); echo "PASS: $d"; else fail=$((fail + 1)); echo "FAIL: $d"; fi
}
# A part that cannot be evaluated (an empty field in arithmetic) is false.
all_of() {
	local c
	for c in "$@"; do
		(eval "$c") 2>/dev/null || return 1
	done
}
any_of() {
	local c
	for c in "$@"; do
		(eval "$c") 2>/dev/null && return 0
	done
	return 1
}
checks_done() {
	echo "RESULT: $pass passed, $fail failed"
	[ "$fail" = 0 ]
}
