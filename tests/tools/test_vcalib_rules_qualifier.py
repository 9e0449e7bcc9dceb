#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""tools/vcalib_rules.py's choice of a value's qualifier bit
(choose_qualifier), on a DBC message written here and read by canmatrix:

  Speed 0|16 (Intel), Speed_Q 16|1, Speed_Disp 24|16, Speed_Disp_Stat 40|1
  with VAL_ 1 "Invalid" 0 "Ok", Other_Flag 48|1, Speed_Valid 56|1.

By the naming rules (a 1-bit sibling named the value plus a qualifier
word): Speed has two equally good candidates (Speed_Q, invalid when 1;
Speed_Valid, invalid when 0), so none is chosen and the note says which
two and how to choose (--qualifier); with one of them beyond the DLC the
other is chosen; Speed_Disp's _Stat sibling decides by its VAL_ table
(invalid when 1). Other_Flag is named after neither and never a candidate.

prints "RESULT: N passed, M failed"
"""
import contextlib
import io
import logging
import os
import sys
import tempfile
import warnings

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
import vcalib_rules as R  # noqa: E402

DBC = """VERSION ""

NS_ :

BS_:

BU_: ESC

BO_ 400 WheelSpeed: 8 ESC
 SG_ Speed : 0|16@1+ (0.01,0) [0|655.35] "kph" Vector__XXX
 SG_ Speed_Q : 16|1@1+ (1,0) [0|1] "" Vector__XXX
 SG_ Speed_Valid : 56|1@1+ (1,0) [0|1] "" Vector__XXX
 SG_ Speed_Disp : 24|16@1+ (0.01,0) [0|655.35] "kph" Vector__XXX
 SG_ Speed_Disp_Stat : 40|1@1+ (1,0) [0|1] "" Vector__XXX
 SG_ Other_Flag : 48|1@1+ (1,0) [0|1] "" Vector__XXX

VAL_ 400 Speed_Disp_Stat 1 "Invalid" 0 "Ok" ;
"""

results = []


def check(what, ok):
    results.append(ok)
    print(("PASS: " if ok else "FAIL: ") + what)


def load_frame():
    logging.disable(logging.CRITICAL)
    with contextlib.redirect_stderr(io.StringIO()):  # its optional formats' notes
        import canmatrix.formats
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "wheel.dbc")
        with open(path, "w") as f:
            f.write(DBC)
        with warnings.catch_warnings(), contextlib.redirect_stdout(io.StringIO()):
            warnings.simplefilter("ignore")
            db = list(canmatrix.formats.loadp(path, import_type="dbc").values())[0]
    return db.frame_by_name("WheelSpeed")


def bit_of(sig):
    return int(sig.start_bit)  # Intel: the start bit is the value's bit


def main():
    frame = load_frame()
    speed = frame.signal_by_name("Speed")
    disp = frame.signal_by_name("Speed_Disp")

    q, bad, note = R.choose_qualifier(frame, speed, bit_of, 8)
    check("two equally good siblings (Speed_Q, Speed_Valid): none chosen (%s)" % (q and q.name,), q is None)
    check("and no invalid value (%s)" % (bad,), bad is None)
    check("the note names both and says --qualifier: %s" % note,
          "Speed_Q and Speed_Valid are equally good" in note and "--qualifier WheelSpeed.Speed=" in note)

    # DLC 7: Speed_Valid (byte 7) lies beyond it, Speed_Q is the one left
    q, bad, note = R.choose_qualifier(frame, speed, bit_of, 7)
    check("DLC 7: Speed_Valid beyond it, Speed_Q chosen, bit 16, invalid when 1 (%s)" % note,
          q is not None and q.name == "Speed_Q" and bit_of(q) == 16 and bad == 1)

    # DLC 2: both lie beyond it: none, and the note says so
    q, bad, note = R.choose_qualifier(frame, speed, bit_of, 2)
    check("DLC 2: both siblings beyond it, none chosen (%s)" % note,
          q is None and "beyond the DLC 2" in note and "Speed_Q" in note and "Speed_Valid" in note)

    # the candidates, each with its invalid value by its word
    cands = {c[1].name: (c[0], c[2]) for c in R.qualifier_candidates(frame, speed, bit_of)}
    check("candidates of Speed: Speed_Q (invalid when 1), Speed_Valid (invalid when 0) and only they (%s)" % cands,
          set(cands) == {"Speed_Q", "Speed_Valid"} and cands["Speed_Q"][1] == 1 and cands["Speed_Valid"][1] == 0
          and cands["Speed_Q"][0] == cands["Speed_Valid"][0])

    q, bad, note = R.choose_qualifier(frame, disp, bit_of, 8)
    check("Speed_Disp: its _Stat sibling with VAL_ 1 'Invalid' is chosen, bit 40, invalid when 1 (%s)" % note,
          q is not None and q.name == "Speed_Disp_Stat" and bit_of(q) == 40 and bad == 1)

    print("RESULT: %d passed, %d failed" % (sum(results), len(results) - sum(results)))
    return 0 if all(results) else 1


if __name__ == "__main__":
    sys.exit(main())
