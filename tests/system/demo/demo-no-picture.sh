#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Stand-in demo for tests/system/demo/test-demo-control.sh: the real demo's run and
# timeline, but its picture is drawn elsewhere, never in DEMO_OUT (as if
# plotting had silently written nothing there).
set -u
cd "$(dirname "$0")/../../.."
out=${DEMO_OUT:-build/demo}
DEMO_OUT=$out.elsewhere tools/demo.sh "$@"
