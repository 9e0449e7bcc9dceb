#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Stand-in for `squeal-sim calib-check FILE` in the Python-only tests of
tools/vehicle_calib.py: reads the sections with vehref.parse_calib and
answers as calib-check does on a file that sets up (`FILE: ok (N inputs,
M corners)`, exit 0). It checks none of the firmware's rules: the tests that
run squeal-sim use the real calib-check."""
import os
import sys
# tests/ of this checkout, and the folders its helper modules live in
_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, d) for d in ("support", os.path.join("support", "reference"), "host-sim", "tools")]

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import vehref  # noqa: E402


def main(argv):
    if len(argv) != 2 or argv[0] != "calib-check":
        sys.stderr.write("usage: stub_calib_check.py calib-check FILE\n")
        return 1
    path = argv[1]
    if path == "--help":
        print("usage: stub_calib_check.py calib-check FILE")
        return 0
    with open(path) as f:
        text = f.read()
    _, inputs, corners = vehref.parse_calib(text)
    print("%s: ok (%d inputs, %d corners)" % (path, len(inputs), len(corners)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
