#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The shared check helpers (tests/support/checks.sh) can fail: all_of is
# false when any part is false or cannot be evaluated (an empty field in
# arithmetic), any_of only when every part is; and a compound condition
# given to check through them is decided inside check, unlike
# `check "d" [ A ] && [ B ]`, whose [ B ] runs outside it (a defect this
# library was written against). Prints "RESULT: N passed, M failed".
set -u
cd "$(dirname "$0")/../.."
# shellcheck source=tests/support/checks.sh
. tests/support/checks.sh
inner() { # counts of a check run on its own: "pass fail"
	(pass=0; fail=0; "$@" >/dev/null; echo "$pass $fail")
}
cfsr=0; empty=""
check "all_of: every part true is true" all_of '[ 1 = 1 ]' '[ 2 -gt 1 ]'
check "all_of: a false part is false" bash -c '! { . tests/support/checks.sh; all_of "[ 1 = 1 ]" "[ 1 = 2 ]"; }'
check "all_of: an unevaluable part is false" \
	bash -c '! { . tests/support/checks.sh; x=""; all_of "[ \$(( 16#\$x & 1 )) = 1 ]"; }'
check "any_of: one true part is true" any_of '[ 1 = 2 ]' '[ 3 = 3 ]'
check "any_of: no true part is false" bash -c '! { . tests/support/checks.sh; any_of "[ 1 = 2 ]" "[ 3 = 4 ]"; }'
check "a compound condition through all_of fails inside check (STKERR clear)" \
	[ "$(inner check "d" all_of '[ -n "$cfsr" ]' '[ $(( (16#$cfsr >> 12) & 1 )) = 1 ]')" = "0 1" ]
check "the same written with && outside check would have passed (the defect)" \
	[ "$(inner eval 'check "d" [ -n "$cfsr" ] && [ $(( (16#$cfsr >> 12) & 1 )) = 1 ]')" = "1 0" ]
check "an empty field fails the check, never passes it" \
	[ "$(inner check "d" all_of '[ -n "$empty" ]' '[ "$empty" -le 3 ]')" = "0 1" ]
checks_done
