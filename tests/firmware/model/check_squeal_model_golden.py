#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Checks the reference against docs/model.md (--self-check) and that the
committed golden vectors are exactly what the reference generates now.
Prints "RESULT: N passed, M failed". Run from the repository root."""

import os
import subprocess
import sys
import tempfile
# tests/ of this checkout, and the folders its helper modules live in
_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, d) for d in ("support", os.path.join("support", "reference"), "host-sim", "tools")]

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(_TESTS)
GOLDEN = os.path.join(ROOT, "tests", "support", "golden", "model_vectors.csv")


def main():
    passed = failed = 0
    r = subprocess.run([sys.executable, os.path.join(_TESTS, "support", "reference", "squeal_reference.py"),
                        "--self-check"], capture_output=True, text=True)
    sys.stdout.write(r.stdout)
    if r.returncode == 0:
        passed += 1
    else:
        failed += 1
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "v.csv")
        r = subprocess.run([sys.executable, os.path.join(_TESTS, "support", "reference", "gen_model_vectors.py"),
                            "-o", out], capture_output=True, text=True)
        with open(out, encoding="ascii") as a, open(GOLDEN, encoding="ascii") as b:
            same = r.returncode == 0 and a.read() == b.read()
    if same:
        passed += 1
        print("golden vectors up to date")
    else:
        failed += 1
        print("FAIL: tests/support/golden/model_vectors.csv differs from the reference's output; "
              "run 'make golden' and review the diff")
    print("RESULT: %d passed, %d failed" % (passed, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
