# SPDX-License-Identifier: MIT
"""Shared helpers of the protocol cross-checks: load the DBC with canmatrix,
run the C emitter, an independent bitwise CRC-8 (P01), a tiny test counter."""
import os
import re
import subprocess
import sys
import warnings
# tests/ of this checkout, and the folders its helper modules live in
_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, d) for d in ("support", os.path.join("support", "reference"), "host-sim", "tools")]

ROOT = os.path.dirname(_TESTS)
DBC = os.path.join(ROOT, "firmware", "protocol", "squeal.dbc")
EMIT = os.environ.get("EMIT_FRAMES",
                      os.path.join(ROOT, "build", "test", "tests", "firmware", "protocol", "emit_frames"))


def load_dbc(path=DBC):
    """The single database in the DBC file (canmatrix)."""
    import canmatrix.formats
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        dbs = canmatrix.formats.loadp(path)
    if len(dbs) != 1:
        raise RuntimeError("expected one database in %s, got %d" % (path, len(dbs)))
    return list(dbs.values())[0]


def run_emitter(*args):
    out = subprocess.run([EMIT] + list(args), check=True, stdout=subprocess.PIPE,
                         universal_newlines=True)
    return out.stdout


def crc8_p01(data, init=0x00, xorout=0x00):
    """CRC-8 poly 0x1D, MSB first, bit by bit (the definition)."""
    c = init
    for b in data:
        c ^= b
        for _ in range(8):
            c = ((c << 1) ^ 0x1D) & 0xFF if c & 0x80 else (c << 1) & 0xFF
    return c ^ xorout


def e2e_p01_crc(data_id, frame):
    """P01 variant 1A: data ID low, data ID high, then bytes 1..n-1."""
    return crc8_p01([data_id & 0xFF, data_id >> 8] + list(frame[1:]))


def snake(name):
    """DiscSpeed -> DISC_SPEED, E2eSpeed -> E2E_SPEED, V0_mps -> V0_MPS."""
    return re.sub(r"(?<=[a-z0-9])(?=[A-Z])", "_", name).upper()


class Results:
    """Counts checks; prints a failed one (and a passed one where OK is set)."""
    OK = None
    FAIL = "FAIL: "

    def __init__(self):
        self.passed = 0
        self.failed = 0

    def check(self, cond, what):
        if cond:
            self.passed += 1
            if self.OK is not None:
                print(self.OK + str(what))
        else:
            self.failed += 1
            print(self.FAIL + str(what))
        return cond

    def finish(self):
        print("RESULT: %d passed, %d failed" % (self.passed, self.failed))
        sys.exit(0 if self.failed == 0 else 1)
