# shellcheck shell=bash
# SPDX-License-Identifier: MIT
# Shared by the suite's shell self-tests and negative controls (sourced):
#   check "description" command...   runs the command INSIDE the check (a
#                                    compound condition: check "d" all_of ...)
#   checks_done                      prints "RESULT: N passed, M failed" and
#                                    returns non-zero on a failure
pass=0
fail=0
check() { # description, condition...
	local d=$1; shift
	if "$@"; then pass=$((pass + 1)); echo "PASS: $d"; else fail=$((fail + 1)); echo "FAIL: $d"; fi
}
checks_done() {
	echo "RESULT: $pass passed, $fail failed"
	[ "$fail" = 0 ]
}
