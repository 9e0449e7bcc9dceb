#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""tools/vcalib_rules.py's number rules, against values derived by hand:
the calibration text of a decimal (17 significant digits at most), a
range's bounds rounded outward, a signal's raw limits and its all-ones code.

prints "RESULT: N passed, M failed"
"""
import decimal
import os
import sys
from types import SimpleNamespace

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
import vcalib_rules as R  # noqa: E402

D = decimal.Decimal
results = []


def check(what, ok):
    results.append(ok)
    print(("PASS: " if ok else "FAIL: ") + what)


def refuses(fn, *args):
    try:
        fn(*args)
    except R.RuleRefusal:
        return True
    return False


# text(): an integer as itself; the shortest double repr where it is the
# same number; 17 digits are taken, 18 are refused
check("text(5) is '5'", R.text(D(5)) == "5")
check("text(0.1) is '0.1'", R.text(D("0.1")) == "0.1")
check("17 significant digits are taken", R.text(D("1.2345678901234567")) == "1.2345678901234567")
check("18 significant digits are refused", refuses(R.text, D("1.23456789012345678")))
check("infinity is refused", refuses(R.text, D("Infinity")))

# outward(): 1.234567890123456789 has 19 digits: to 17, up 1.2345678901234568,
# down 1.2345678901234567; a 17-digit number stays as it is
x = D("1.234567890123456789")
check("outward up rounds toward +inf", R.outward(x, True) == D("1.2345678901234568"))
check("outward down rounds toward -inf", R.outward(x, False) == D("1.2345678901234567"))
check("outward keeps 17 digits", R.outward(D("1.2345678901234567"), True) == D("1.2345678901234567"))
check("outward of a negative rounds up toward +inf",
      R.outward(-x, True) == D("-1.2345678901234567"))

# raw limits: 8 bits unsigned 0..255, signed -128..127; all ones: 255 / -1
u8 = SimpleNamespace(size=8, is_signed=False)
s8 = SimpleNamespace(size=8, is_signed=True)
s12 = SimpleNamespace(size=12, is_signed=True)
check("unsigned 8-bit limits 0..255", R.raw_limits(u8) == (0, 255))
check("signed 8-bit limits -128..127", R.raw_limits(s8) == (-128, 127))
check("signed 12-bit limits -2048..2047", R.raw_limits(s12) == (-2048, 2047))
check("all ones: unsigned 255, signed -1", R.all_ones(u8) == 255 and R.all_ones(s8) == -1)

# "not available" words, and a negation that means a good value
check("'Signal not available' means no value", R.means_no_value("Signal not available"))
check("'SNA' means no value", R.means_no_value("SNA"))
check("'no error' is a value", not R.means_no_value("no error"))

# "not available" codes: the calibration takes two inside the plausible
# range; three named ones inside it are refused, two are taken
def na(values, lo, hi):
    sig = SimpleNamespace(size=8, is_signed=False, values=values, name="S")
    return R.na_codes(sig, lambda c: c, lo, hi, None, False, (0, 255))


check("three 'not available' codes inside the range are refused",
      refuses(na, {253: "SNA", 254: "init", 255: "error"}, 0, 255))
check("two 'not available' codes inside the range are taken",
      not refuses(na, {254: "init", 255: "error"}, 0, 255))

# frame_kind_on_bus(): an 8-byte message the DBC calls FD but the log shows
# only in classic frames is classic (a DBC that marks every message FD on a
# classic bus); longer messages, mixed or absent frames: the DBC decides
fd, why = R.frame_kind_on_bus("WheelSpeed", True, 8, "VFrameFormat StandardCAN_FD", 0, 3283)
check("8-byte 'FD' message in 3283 classic frames only is classic",
      fd is False and "3283 classic frames" in why)
fd, why = R.frame_kind_on_bus("Esc", False, 8, "classic", 40, 0)
check("8-byte classic message seen only in FD frames is FD", fd is True and "40 FD frames" in why)
check("a 24-byte message stays FD whatever the log says",
      R.frame_kind_on_bus("Whl", True, 24, "DLC 24", 0, 10) == (True, "DLC 24"))
check("no frames of the message in the log: the DBC decides",
      R.frame_kind_on_bus("Brk", True, 8, "VFrameFormat StandardCAN_FD", 0, 0) ==
      (True, "VFrameFormat StandardCAN_FD"))
check("frames of both kinds: the DBC decides",
      R.frame_kind_on_bus("Brk", True, 8, "VFrameFormat StandardCAN_FD", 5, 5) ==
      (True, "VFrameFormat StandardCAN_FD"))
check("the log agrees with the DBC: unchanged",
      R.frame_kind_on_bus("Brk", True, 8, "VFrameFormat StandardCAN_FD", 7, 0) ==
      (True, "VFrameFormat StandardCAN_FD"))

print("RESULT: %d passed, %d failed" % (sum(results), len(results) - sum(results)))
sys.exit(0 if all(results) else 1)
