#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""`squeal-sim decode` (host-sim/cmd_decode.c) on frames made here: the
monitor's messages encoded by canmatrix from firmware/protocol/squeal.dbc
with values chosen here, the E2E CRC computed here (P01: CRC-8 0x1D over the
DBC's E2E_DataID, then bytes 1..), the counters set by hand to walk through
every E2E status:

  - text: each message's line with the values and names written out by
    hand, and the E2E status of each frame (initial, ok, lost:N, repeated,
    wrong_crc, bad_counter, bad_dlc); an unknown identifier printed raw;
  - --csv: the header, every signal's cell equal to the value encoded, the
    counter and E2E columns (no counter and no values for a bad_dlc frame),
    the raw payload;
  - the counter wraps from 14 to 0 as P01's does (mod 15: 14 -> 0 is ok,
    not a lost frame); WarningLevel 3 is "critical"; a DiscSpeed frame
    longer than its 4 bytes is bad_dlc like a shorter one (no values);
  - --bus NAME takes one interface's frames; bad usage and a missing log
    are one line each with their exit codes.
Both sanitizer builds. Prints "RESULT: N passed, M failed".
"""
import csv
import io
import os
import subprocess
import sys
import tempfile
from decimal import Decimal

_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, "support")]
ROOT = os.path.dirname(_TESTS)

import dbc_common  # noqa: E402  (load_dbc, e2e_p01_crc, Results)

SIMS = [os.path.join(ROOT, "build", b, "squeal-sim") for b in ("test", "test-fixed")]
R = dbc_common.Results()
check = R.check


def run(sim, args, stdin=None):
    p = subprocess.run([sim] + args, input=stdin, capture_output=True, text=True, timeout=60)
    return p.returncode, p.stdout, p.stderr


def protect(fr, data, counter, crc_ok=True):
    """P01 1A: counter in the low nibble of byte 1, CRC-8 in byte 0."""
    data = bytearray(data)
    data[1] = (data[1] & 0xF0) | (counter & 0x0F)
    crc = dbc_common.e2e_p01_crc(int(fr.attributes["E2E_DataID"]), data)
    data[0] = crc if crc_ok else crc ^ 0xFF
    return bytes(data)


STATUS = {"SquealState": 1, "WarningLevel": 2, "BasinRatio": Decimal("0.4321"),
          "HopfMargin_mps": Decimal("-1.25"), "BorderMargin_sigma": Decimal("3.4")}
DETAIL = {"V0_mps": Decimal("12.34"), "HopfSpeed_mps": Decimal("2.5"),
          "TriggerVelocity_mps": Decimal("0.75"), "VehicleSpeedBorder_kph": Decimal("88.8")}
# SquealStatus's counters and what decode must call each frame
STEPS = [(0, True, 8, "initial"), (1, True, 8, "ok"), (4, True, 8, "lost:2"),
         (4, True, 8, "repeated"), (5, False, 8, "wrong_crc"), (15, True, 8, "bad_counter"),
         (6, True, 7, "bad_dlc")]
STATUS_TEXT = ("SquealStatus state=bistable warning=warning BasinRatio=0.4321 "
               "HopfMargin_mps=-1.25 BorderMargin_sigma=3.4")
DETAIL_TEXT = ("SquealDetail V0_mps=12.34 HopfSpeed_mps=2.50 TriggerVelocity_mps=0.75 "
               "VehicleSpeedBorder_kph=88.8")


def encode(fr, values):
    """canmatrix packs raw values: the DBC's scaling applied by canmatrix first."""
    return bytes(fr.encode({k: fr.signal_by_name(k).phys2raw(Decimal(v)) for k, v in values.items()}))


def make_log(db):
    st = db.frame_by_name("SquealStatus")
    de = db.frame_by_name("SquealDetail")
    st_data = encode(st, STATUS)
    de_data = encode(de, DETAIL)
    lines = []
    for k, (ctr, crc_ok, dlc, _) in enumerate(STEPS):
        data = protect(st, st_data, ctr, crc_ok)[:dlc]
        lines.append("(%010d.%06d) can0 300#%s" % (1, 10000 * k, data.hex().upper()))
    lines.append("(0000000002.000000) can0 301#%s" % protect(de, de_data, 0).hex().upper())
    lines.append("(0000000002.010000) can0 123#0102")
    return "\n".join(lines) + "\n"


def test_text(sim, tag, log):
    rc, out, err = run(sim, ["decode", "-"], stdin=log)
    lines = out.splitlines()
    check(rc == 0 and err == "" and len(lines) == len(STEPS) + 2,
          "%s: decode: one line per frame, exit 0 (%d, %d lines, %r)" % (tag, rc, len(lines), err[:80]))
    for k, (ctr, _, dlc, e2e) in enumerate(STEPS[:-1]):
        want = "1.%06d %s ctr=%d e2e=%s" % (10000 * k, STATUS_TEXT, ctr, e2e)
        check(lines[k:k + 1] == [want], "%s: frame %d: %r (got %r)" % (tag, k, want, lines[k:k + 1]))
    last = lines[len(STEPS) - 1] if len(lines) >= len(STEPS) else ""
    short = log.splitlines()[len(STEPS) - 1].split("#")[1]
    check(last == "1.060000 SquealStatus bad_dlc [7] " + short,
          "%s: a 7-byte SquealStatus: bad_dlc, its bytes, no values (%r)" % (tag, last))
    check(lines[len(STEPS):] == ["2.000000 %s ctr=0 e2e=initial" % DETAIL_TEXT, "2.010000 123 unknown [2] 0102"],
          "%s: SquealDetail's values and an unknown id raw (%r)" % (tag, lines[len(STEPS):]))


def test_csv(sim, tag, db, log):
    rc, out, err = run(sim, ["decode", "--csv", "-"], stdin=log)
    rows = list(csv.DictReader(io.StringIO(out)))
    check(rc == 0 and err == "" and len(rows) == len(STEPS) + 2, "%s: decode --csv: one row per frame" % tag)
    header = out.splitlines()[0].split(",")
    sigs = [s.name for f in db.frames for s in f.signals
            if not s.name.endswith("_CRC") and not s.name.endswith("_Counter")]
    check(header[:5] == ["time_s", "id", "message", "counter", "e2e"] and header[-1] == "raw" and
          sorted(header[5:-1]) == sorted(sigs),
          "%s: the header: fixed columns, then every non-E2E signal of the DBC, then raw" % tag)
    bad = []
    for k, (ctr, _, dlc, e2e) in enumerate(STEPS):
        r = rows[k]
        if (r["time_s"], r["id"], r["message"], r["counter"], r["e2e"]) != \
                ("1.%06d" % (10000 * k), "300", "SquealStatus", str(ctr) if dlc == 8 else "", e2e):
            bad.append((k, "columns", r["time_s"], r["counter"], r["e2e"]))
        for name, v in STATUS.items():
            cell = r[name]
            if dlc != 8:
                if cell != "":
                    bad.append((k, name, cell, "empty"))
            elif cell == "" or Decimal(cell) != Decimal(v):
                bad.append((k, name, cell, v))
        others = [c for c in header[5:-1] if c not in STATUS and r[c] != ""]
        if others:
            bad.append((k, "cells of other messages", others))
    d = rows[len(STEPS)]
    for name, v in DETAIL.items():
        if d[name] == "" or Decimal(d[name]) != v:
            bad.append(("detail", name, d[name], v))
    u = rows[-1]
    if (u["id"], u["message"], u["raw"]) != ("123", "unknown", "0102"):
        bad.append(("unknown", u["id"], u["message"], u["raw"]))
    check(not bad, "%s: every cell as encoded (%s)" % (tag, bad[:4]))


def test_wrap_level_and_length(sim, tag, db):
    """Counters 13, 14, 0, 1 (mod 15: every step +1), WarningLevel 3, and a
    DiscSpeed of 4 (its DLC), 5 and 8 bytes."""
    st = db.frame_by_name("SquealStatus")
    ds = db.frame_by_name("DiscSpeed")
    st_data = encode(st, dict(STATUS, WarningLevel=3))
    ds_data = encode(ds, {"DiscSpeed_radps": Decimal("12.34")})
    lines = ["(0000000003.%06d) can0 300#%s" % (10000 * k, protect(st, st_data, ctr).hex().upper())
             for k, ctr in enumerate((13, 14, 0, 1))]
    long5 = protect(ds, ds_data, 1) + b"\x00"
    long8 = protect(ds, ds_data, 2) + bytes(4)
    lines += ["(0000000004.000000) can0 110#%s" % protect(ds, ds_data, 0).hex().upper(),
              "(0000000004.010000) can0 110#%s" % long5.hex().upper(),
              "(0000000004.020000) can0 110#%s" % long8.hex().upper()]
    rc, out, err = run(sim, ["decode", "-"], stdin="\n".join(lines) + "\n")
    status = STATUS_TEXT.replace("warning=warning", "warning=critical")
    want = ["3.%06d %s ctr=%d e2e=%s" % (10000 * k, status, ctr, e2e)
            for k, (ctr, e2e) in enumerate(((13, "initial"), (14, "ok"), (0, "ok"), (1, "ok")))]
    want += ["4.000000 DiscSpeed DiscSpeed_radps=12.34 ctr=0 e2e=initial",
             "4.010000 DiscSpeed bad_dlc [5] " + long5.hex().upper(),
             "4.020000 DiscSpeed bad_dlc [8] " + long8.hex().upper()]
    got = out.splitlines()
    check(rc == 0 and err == "" and got == want,
          "%s: 14 -> 0 ok, warning=critical, a 5- and 8-byte DiscSpeed bad_dlc (%r)" %
          (tag, [g for g, w in zip(got, want) if g != w] or got[len(want):]))


def test_bus_and_usage(sim, tag, log):
    two = log + "(0000000003.000000) can1 123#AA\n(0000000003.010000) can1 123#BB\n"
    rc, out, _ = run(sim, ["decode", "--bus", "can1", "-"], stdin=two)
    check(rc == 0 and out.splitlines() == ["3.000000 123 unknown [1] AA", "3.010000 123 unknown [1] BB"],
          "%s: --bus can1: can1's two frames only (%r)" % (tag, out.splitlines()[:3]))
    rc, out, err = run(sim, ["decode", "--no-such-option", "-"], stdin=log)
    check(rc == 2 and out == "" and err.startswith("squeal-sim decode: "),
          "%s: unknown option: exit 2 with the command's name (%d %r)" % (tag, rc, err[:80]))
    with tempfile.TemporaryDirectory() as tmp:
        missing = os.path.join(tmp, "missing.log")
        rc, out, err = run(sim, ["decode", missing])
        check(rc == 1 and out == "" and missing in err and len(err.strip().splitlines()) == 1,
              "%s: a missing log: one line, exit 1 (%d %r)" % (tag, rc, err))


def main():
    db = dbc_common.load_dbc()
    log = make_log(db)
    for sim in SIMS:
        tag = os.path.basename(os.path.dirname(sim))
        test_text(sim, tag, log)
        test_csv(sim, tag, db, log)
        test_wrap_level_and_length(sim, tag, db)
        test_bus_and_usage(sim, tag, log)
    R.finish()


if __name__ == "__main__":
    main()
