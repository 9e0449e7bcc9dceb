#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Negative controls of tests/system/static/cppcheck-misra.sh, on a small part of the
# tree (firmware/protocol, float build) so that they stay quick:
#   - as is, it passes (so each failure below is the injected fault's);
#   - the addon missing, or raising an exception: the run fails, naming it;
#   - no file to check: the run fails;
#   - a deviation row whose Count is lower than its findings: the run fails,
#     naming the row, its findings and its budget.
# Prints "RESULT: N passed, M failed".
set -u
cd "$(dirname "$0")/../../.."
tmp=$(mktemp -d build/misra-control.XXXXXX)
trap 'rm -rf "$tmp"' EXIT
# shellcheck source=tests/support/checks.sh
. tests/support/checks.sh
misra() { # case, env...: runs the check on firmware/protocol -> $tmp/case.txt, returns its exit
	local c=$1; shift
	env MISRA_OUT="$tmp/$c" MISRA_BUILDS=float MISRA_GROUPS=core MISRA_CORE_DIRS=firmware/protocol \
		"$@" tests/system/static/cppcheck-misra.sh >"$tmp/$c.txt" 2>&1
	local rc=$?
	grep -E '^(FAIL|RESULT)|^    [^ ].*(addon|error|exited|files|no files)' "$tmp/$c.txt" | head -8 | sed "s/^/  $c | /"
	return "$rc"
}
has() { grep -qE "$2" "$tmp/$1.txt"; }

misra good
check "unchanged: passes (exit $?)" has good '^RESULT: [1-9][0-9]* passed, 0 failed$'

echo '{"script": "no_such_misra_addon.py", "args": []}' >"$tmp/missing.json"
misra missing MISRA_ADDON="$tmp/missing.json"; rc=$?
check "addon missing: fails (exit $rc)" [ "$rc" != 0 ]
check "addon missing: named" has missing '^FAIL cppcheck and the MISRA addon ran cleanly'
check "addon missing: cppcheck's message shown" has missing 'Did not find addon no_such_misra_addon.py'
check "addon missing: canary not flagged" has missing '^FAIL canary: .*missed: .*misra-c2012'

echo "{\"script\": \"$PWD/tests/system/static/canary/broken_addon.py\", \"args\": []}" >"$tmp/broken.json"
misra broken MISRA_ADDON="$tmp/broken.json"; rc=$?
check "addon exception: fails (exit $rc)" [ "$rc" != 0 ]
check "addon exception: cppcheck's bail-out named" has broken 'Bailing out from checking .* internal error'

mkdir -p "$tmp/empty"
misra nofiles MISRA_CORE_DIRS="$tmp/empty"; rc=$?
check "no files: fails (exit $rc)" [ "$rc" != 0 ]
check "no files: named" has nofiles 'no files checked'

# the 15.5 row (early return, accepted in all of firmware/) with budget 1
sed -E 's/^(\| 15\.5 \|[^|]*\| )[0-9]+/\11/' docs/misra-deviations.md >"$tmp/dev.md"
misra budget MISRA_DEVIATIONS="$tmp/dev.md"; rc=$?
check "deviation over budget: fails (exit $rc)" [ "$rc" != 0 ]
check "deviation over budget: row, findings and budget named" \
	has budget '^FAIL deviation 15\.5 in firmware/\* .*: [0-9]+ findings, budget 1 '
check "deviation over budget: the only failure" has budget '^RESULT: [0-9]+ passed, 1 failed$'
checks_done
