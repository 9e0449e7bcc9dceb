# SPDX-License-Identifier: MIT
"""Counting checks for the calibration tests: one line per check, and the
runner's "RESULT: N passed, M failed" at the end."""

import os
import sys
import tempfile
# tests/ of this checkout, and the folders its helper modules live in
_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, d) for d in ("support", os.path.join("support", "reference"), "host-sim", "tools")]

ROOT = os.path.dirname(_TESTS)
TOOLS = os.path.join(ROOT, "tools")
sys.path.insert(0, TOOLS)


class Checks:
    def __init__(self):
        self.passed = 0
        self.failed = 0

    def check(self, ok, what):
        print(("PASS  " if ok else "FAIL  ") + what)
        if ok:
            self.passed += 1
        else:
            self.failed += 1

    def coverage(self, hits, reps, what, lo=0.90, hi=0.99):
        frac = hits / reps
        self.check(lo <= frac <= hi,
                   f"{what}: 95 % interval covers the truth in {hits}/{reps} = "
                   f"{100 * frac:.1f} % (bound {100 * lo:.0f}-{100 * hi:.0f} %)")

    def finish(self):
        print(f"RESULT: {self.passed} passed, {self.failed} failed")
        return 0 if self.failed == 0 else 1

    @classmethod
    def run(cls, *groups):
        """A test file's main(): each group(c, tmp) in order, sharing one
        counter and one temporary folder; the exit status of finish()."""
        c = cls()
        with tempfile.TemporaryDirectory() as tmp:
            for group in groups:
                group(c, tmp)
        return c.finish()
