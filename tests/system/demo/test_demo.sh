#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The README's main job works: the demo runs, its timeline shows the braking
# run passing stable -> bistable -> unstable -> not sliding with the warning
# levels rising, and it draws a non-blank picture.
# Everything checked is deleted first, so a stale picture cannot pass.
# DEMO_TEST_OUT and DEMO_SCRIPT: another output place and demo (the negative
# control tests/system/demo/test-demo-control.sh uses a demo that draws nothing).
set -u
cd "$(dirname "$0")/../../.."
out=${DEMO_TEST_OUT:-build/demo-test}
rm -f "$out.txt" "$out/drive_map.png"
pass=0; fail=0
check() { if eval "$2"; then pass=$((pass+1)); else fail=$((fail+1)); echo "FAILED: $1"; fi; }
DEMO_OUT=$out "${DEMO_SCRIPT:-tools/demo.sh}" >"$out.txt" 2>&1
rc=$?
cat "$out.txt"
check "demo exits 0" '[ $rc = 0 ]'
order=$(grep -E '^ *[0-9]+\.[0-9]+ s ' "$out.txt" | grep -oE ' (stable|bistable|unstable|not sliding|FAULT) ' | tr -s ' \n' ' ')
check "states in order (got: $order)" '[[ "$order" == *"stable bistable bistable unstable not"* ]]'
check "critical warning at the Hopf border" 'grep -q "unstable *CRITICAL" "$out.txt"'
check "picture written" '[ -s "$out/drive_map.png" ]'
check "picture not blank" '/usr/bin/python3 -c "
import sys, matplotlib.image as im
a = im.imread(\"$out/drive_map.png\")
sys.exit(0 if a.shape[0] > 300 and a.shape[1] > 500 and float(a.std()) > 0.05 else 1)"'
echo "RESULT: $pass passed, $fail failed"
[ "$fail" = 0 ]
