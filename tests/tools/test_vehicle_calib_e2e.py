#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""End to end on every fixture vehicle layout: a braking drive in
the vehicle's layout (10/20/24 ms, dropped frames, other traffic, the
layout's protection) -> calibration from the DBC by tools/vehicle_calib.py ->
`squeal-sim replay LOG --calib car.cal` -> each corner's outputs decoded with
canmatrix: V0_mps and Force_N follow the vehicle's signals (docs/vehicle.md's
formulas, computed here), SquealState equals the scipy reference at the
converted operating points away from borders, no FAULT; and the drive with a
2.8 s backward timestamp jump is a new segment, nothing squeezed
(e2e_harness.py).

    test_vehicle_e2e.py [--self-test]   (--self-test: the pure-Python stand-in
                                         for replay, no C needed)
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
    e2e_harness.main(sys.argv[1:], [(n, l, 7) for n, l in vehref.LAYOUTS.items()])
