#!/bin/sh
# SPDX-License-Identifier: MIT
# make test entry: plant -> ecu -> candump on a real vcan0 in the QEMU guest
# of tests/system/vcan/guest.sh (natively where this host has vcan0), then the
# host-side checks of tests/support/check_vcan.py on the captures:
# the stop scenario against the reference model, live (canplayer) against
# offline (squeal-sim replay) on the same log, faults on the bus, a flood.
# Prints "RESULT: N passed, M failed". About 70-90 s (boot included).
set -eu
cd "$(dirname "$0")/../../.."
make -s build/host/squeal-sim
out=$(mktemp -d "${TMPDIR:-/tmp}/sq-integ.XXXXXX")
trap 'rm -rf "$out"' EXIT
rc=0
tests/system/vcan/guest.sh --timeout 170 --run tests/system/integration/guest-vcan.sh \
	--add build/host/squeal-sim --add tests/system/integration --out "$out" \
	-- max 10 all || rc=$?
if [ "$rc" != 0 ]; then
	echo "guest run failed (exit $rc)"
	echo "RESULT: 0 passed, 1 failed"
	exit 1
fi
# keep the captures for a look after a failure
mkdir -p build/test-logs/integration
cp "$out"/* build/test-logs/integration/ 2>/dev/null || true
exec /usr/bin/python3 tests/support/check_vcan.py "$out" \
	--sim build/host/squeal-sim --calib tests/system/integration/vcan.cal
