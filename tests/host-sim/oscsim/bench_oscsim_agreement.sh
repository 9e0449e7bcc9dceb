#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Agreement of the firmware model with simulation of the oscillator on the
# full 100 x 100 (a, v0) grid for the default brake and the paper's six
# variations, float and fixed builds, with timings. Figures, not pass/fail
# (the exit code only reports a run that could not complete).
set -euo pipefail
cd "$(dirname "$0")/../../.."
grid=${OSCSIM_BENCH_GRID:-100}
for build in host host-fixed; do
	start=$(date +%s.%N)
	build/$build/oscsim map --grid "$grid" --brake all --basin 20 --check || true
	end=$(date +%s.%N)
	printf 'oscsim map (%s, %s x %s, 7 brakes): %.1f s wall\n\n' "$build" "$grid" "$grid" \
		"$(echo "$end - $start" | bc)"
done
