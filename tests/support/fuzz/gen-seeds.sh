#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Regenerates the committed seed corpora tests/support/fuzz/corpus/<target>/ with
# build/host/tests/support/fuzz/gen_seeds (make fuzz-seeds builds it and runs this).
# Only the seed-NNN files are replaced; a corpus directory may also hold
# hand-made seeds (other names), which are kept.
set -euo pipefail
cd "$(dirname "$0")/../../.."
gen=${1:-build/host/tests/support/fuzz/gen_seeds}
for t in fuzz_model_float fuzz_model_fixed fuzz_msgs fuzz_calib_block fuzz_monitor \
	fuzz_monitor_fixed fuzz_candump fuzz_calib_text fuzz_calib_text_fixed; do
	mkdir -p "tests/support/fuzz/corpus/$t"
	rm -f "tests/support/fuzz/corpus/$t"/seed-*
done
"$gen" tests/support/fuzz/corpus
# the monitor's seeds mean the same in both numeric builds
cp tests/support/fuzz/corpus/fuzz_monitor/seed-* tests/support/fuzz/corpus/fuzz_monitor_fixed/
# the documented example calibration file as it is
[ -f docs/calib-example.txt ] && cp docs/calib-example.txt tests/support/fuzz/corpus/fuzz_calib_text/seed-example
# and the fixture vehicle layouts (input map sections)
for f in tests/firmware/monitor/fixtures/*.cal; do
	[ -f "$f" ] && cp "$f" "tests/support/fuzz/corpus/fuzz_calib_text/seed-$(basename "$f" .cal)"
done
# the calibration text means the same in both numeric builds
cp tests/support/fuzz/corpus/fuzz_calib_text/seed-* tests/support/fuzz/corpus/fuzz_calib_text_fixed/
for d in tests/support/fuzz/corpus/*/; do
	echo "$(basename "$d"): $(ls "$d" | wc -l) files"
done
