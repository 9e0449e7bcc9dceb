#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""tools/drive_common.py: a calibration text's corners, against identifiers
worked out by hand from the rule of docs/calib-input-map.md (corner k sends
on the flat identifiers + 0x10 k): the four default corners, [corner POS]
sections (lower case taken, their own keys kept), '#' comments, and the
errors (an unknown position, a line without '=', a missing file).

prints "RESULT: N passed, M failed"
"""
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
import drive_common as DC  # noqa: E402

results = []


def check(what, ok):
    results.append(ok)
    print(("PASS: " if ok else "FAIL: ") + what)


def calib(text):
    fd, path = tempfile.mkstemp(suffix=".cal")
    with os.fdopen(fd, "w") as f:
        f.write(text)
    try:
        return DC.read_calib(path)
    finally:
        os.unlink(path)


def refused(text):
    try:
        calib(text)
    except DC.CalibError:
        return True
    return False


# no calibration: FL FR RL RR on 0x300/0x301/0x303 + 0x10 k
cs = DC.corners({})
check("four default corners in the order FL FR RL RR", [c.name for c in cs] == ["FL", "FR", "RL", "RR"])
check("corner RR sends on 0x330, 0x331, 0x333", cs[3].ids == (0x330, 0x331, 0x333))
check("corner FL sends on 0x300, 0x301, 0x303", cs[0].ids == (0x300, 0x301, 0x303))

# flat keys with a comment; the flat identifiers move every corner
cal = calib("status_id = 0x200  # moved\ndetail_id = 0x201\ndetail2_id = 0x202\nmass_kg = 2.5\n")
check("a comment after a value is dropped", cal["flat"]["status_id"] == "0x200")
cs = DC.corners(cal)
check("corner FR on the flat identifiers + 0x10", cs[1].ids == (0x210, 0x211, 0x212))
check("the flat brake key reaches every corner", all(c.brake["mass"] == 2.5 for c in cs))

# sections: only those corners; a lower-case position; own keys win
cal = calib("mass_kg = 2.0\n[corner rl]\nmass_kg = 3.0\n[corner FL]\nstatus_id = 0x400\n")
cs = DC.corners(cal)
check("only the corners of the sections, sorted", [c.name for c in cs] == ["FL", "RL"])
check("a corner's own key wins", cs[1].brake["mass"] == 3.0 and cs[0].brake["mass"] == 2.0)
check("its own status_id, the others + 0x10 x position",
      cs[0].ids == (0x400, 0x301, 0x303) and cs[1].ids == (0x320, 0x321, 0x323))

check("an unknown corner position is refused", refused("[corner XX]\n"))
check("a line without '=' is refused", refused("mass_kg 2.0\n"))
try:
    DC.read_calib("/nonexistent/calibration.cal")
    check("a missing file is refused", False)
except DC.CalibError:
    check("a missing file is refused", True)

print("RESULT: %d passed, %d failed" % (sum(results), len(results) - sum(results)))
sys.exit(0 if all(results) else 1)
