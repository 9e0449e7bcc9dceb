#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""The check on a layout no other test uses: a drive in a layout no other test uses
(tests/tools/fixtures/unseen/), configured only with tools/vehicle_calib.py from its
DBC, replays with the inputs used (no FAULT after start-up); V0_mps and
Force_N follow the vehicle's signals and the states equal the reference at
the converted operating points (e2e_harness.py, same checks as the other
layouts, including the 2.8 s timestamp jump).
Prints "RESULT: N passed, M failed".
"""
import os
import sys
# tests/ of this checkout, and the folders its helper modules live in
_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, d) for d in ("support", os.path.join("support", "reference"), "host-sim", "tools")]

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import e2e_harness  # noqa: E402
import vehref  # noqa: E402

if __name__ == "__main__":
    e2e_harness.main(sys.argv[1:], [("unseen", vehref.UNSEEN, 11)])
