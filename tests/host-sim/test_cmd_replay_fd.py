#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""squeal-sim replay and decode --inputs-csv of CAN FD logs (both builds).

The log is written here, independently of the firmware: the FD layout of
tests/host-sim/fd_p05.cal (24-byte wheel speeds at 0x0A0, 32-byte pressures
at 0x0B0, AUTOSAR E2E P05 with a CRC-16/CCITT-FALSE of our own below,
checked against its check value and the published P05 example), a drive of
5 s at v0 = 3 m/s then 5 s at v0 = 1 m/s at 9 kN; the expected states come
from the reference model (tests/support/reference/squeal_reference.py). Then:
  - every FD frame is read as FD (fd_frames), used, none unsupported;
  - the state time follows the reference's states;
  - both flag conventions (##1 and ##5) are the same frame;
  - a classic frame on an FD input's identifier is a wrong-format frame
    (bad_dlc), a wrong CRC is e2e_wrong_crc, a length that is no DLC code
    is a malformed line, an XL frame is still unsupported;
  - decode --inputs-csv gives one row per input of every FD frame with the
    physical value written, and says nothing is left out.
Prints one line per check and "RESULT: N passed, M failed".
"""
import csv
import io
import json
import os
import re
import subprocess
import sys
import tempfile
# tests/ of this checkout, and the folders its helper modules live in
_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, d) for d in ("support", os.path.join("support", "reference"), "host-sim", "tools")]

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(_TESTS)
import squeal_reference as ref  # noqa: E402
from dbc_common import Results  # noqa: E402
from vehref import crc16_ccitt_false  # noqa: E402

SIMS = [os.path.join(ROOT, "build", v, "squeal-sim") for v in ("test", "test-fixed")]
CAL = os.path.join(HERE, "fd_p05.cal")
ID_WS, ID_P = 0x0A0, 0x0B0
DATA_ID_WS, DATA_ID_P = 0x10A0, 0x10B0
R_PAD_M, R_WHEEL_M = 0.12, 0.30      # the calibration's defaults
AREA_M2 = 2290e-6
FORCE_N = 9000.0


def p05_protect(buf, data_id, counter):
    """CRC little-endian in bytes 0-1, counter in byte 2; the CRC over
    bytes 2.. then the Data ID low byte, high byte."""
    buf[2] = counter & 0xFF
    crc = crc16_ccitt_false(bytes(buf[2:]) + bytes([data_id & 0xFF, data_id >> 8]))
    buf[0], buf[1] = crc & 0xFF, crc >> 8
    return buf


def put_intel(buf, start, length, value):
    for i in range(length):
        bit = start + i
        if (value >> i) & 1:
            buf[bit // 8] |= 1 << (bit % 8)


def ws_frame(kmh, counter, bad_crc=False):
    raw = round(kmh * 32)
    buf = bytearray(24)
    for k in range(4):
        put_intel(buf, 64 + 14 * k, 14, raw)
    p05_protect(buf, DATA_ID_WS, counter)
    if bad_crc:
        buf[0] ^= 0x01
    return bytes(buf)


def p_frame(kpa, counter):
    raw = round(kpa)
    buf = bytearray(32)
    for k in range(4):
        put_intel(buf, 64 + 16 * k, 16, raw)
    return bytes(p05_protect(buf, DATA_ID_P, counter))


def line(t_us, ident, data, flags=1):
    return "(%010d.%06d) can0 %03X##%X%s\n" % (t_us // 1000000, t_us % 1000000, ident, flags,
                                              data.hex().upper())


def drive():
    """(lines, expected: list of (v0, state), counts)"""
    kpa = FORCE_N / AREA_M2 / 1e3
    out = []
    t = 100 * 1000000
    ctr = 0
    for v0 in (3.0, 1.0):
        kmh = v0 * R_WHEEL_M / R_PAD_M * 3.6
        for _ in range(500):
            # the wheel speeds with BRS (##1, older can-utils), the
            # pressures with FDF|BRS (##5, newer ones)
            out.append(line(t, ID_WS, ws_frame(kmh, ctr), 1))
            out.append(line(t + 2000, ID_P, p_frame(kpa, ctr), 5))
            ctr = (ctr + 1) & 0xFF
            t += 10000
    return out, t, ctr, kpa


def run(sim, args, stdin=None):
    p = subprocess.run([sim] + args, input=stdin, capture_output=True, text=True, timeout=300)
    return p.returncode, p.stdout, p.stderr


def value(err, key):
    m = re.search(r"^\s+" + re.escape(key) + r"\s+(\d+(?:\.\d+)?)", err, re.M)
    return None if m is None else m.group(1)


def main():
    R = Results()
    R.check(crc16_ccitt_false(b"123456789") == 0x29B1, "reference CRC-16/CCITT-FALSE check value 0x29B1")
    ex = p05_protect(bytearray(8), 0x1234, 0)
    R.check(bytes(ex[:2]) == bytes([0x1C, 0xCA]), "reference P05: 8 zero bytes, Data ID 0x1234 -> 1c ca")
    ex = bytearray(8)
    ex[2] = 1
    crc = crc16_ccitt_false(bytes(ex[2:]) + bytes([0x34, 0x12]))
    R.check(bytes([crc & 0xFF, crc >> 8]) == bytes([0xCF, 0x8D]), "reference P05: counter 1 -> cf 8d")

    lines, t_end, ctr, kpa = drive()
    n_fd = len(lines)
    force_n = round(kpa) * 1e3 * AREA_M2
    want = [ref.classify(ref.default_point(v0, force_n))["state"] for v0 in (3.0, 1.0)]
    names = {ref.STABLE: "stable", ref.BISTABLE: "bistable", ref.UNSTABLE: "unstable"}
    with tempfile.TemporaryDirectory() as tmp:
        log = os.path.join(tmp, "fd.log")
        with open(log, "w") as f:
            f.writelines(lines)
        faults = list(lines)
        faults += [
            "(%010d.%06d) can0 0A0#0011223344556677\n" % (t_end // 1000000, t_end % 1000000),
            line(t_end + 1000, ID_WS, ws_frame(3.6, ctr, bad_crc=True)),
            "(%010d.%06d) can0 0A0##1%s\n" % (t_end // 1000000, t_end % 1000000 + 2000, "00" * 13),
            "(%010d.%06d) can0 45110#81:00:12345678#00112233\n" % (t_end // 1000000,
                                                                   t_end % 1000000 + 3000),
        ]
        flog = os.path.join(tmp, "faults.log")
        with open(flog, "w") as f:
            f.writelines(faults)
        for sim in SIMS:
            b = os.path.basename(os.path.dirname(sim))
            if not os.access(sim, os.X_OK):
                R.check(False, "%s missing" % sim)
                continue
            rc, so, err = run(sim, ["replay", "--calib", CAL, "--no-output", log])
            R.check(rc == 0, "%s: replay of the FD log exits 0 (%d)" % (b, rc))
            m = re.search(r"frames_read\s+(\d+) \(classic_frames (\d+), fd_frames (\d+), xl_frames (\d+)\)", err)
            R.check(m is not None and m.groups() == (str(n_fd), "0", str(n_fd), "0"),
                    "%s: every frame read as FD (%s)" % (b, m.groups() if m else None))
            # frames_used: the first corner's speed and force (every frame)
            R.check(value(err, "frames_used") == str(n_fd),
                    "%s: every FD frame used by corner FL (%s of %d)" % (b, value(err, "frames_used"), n_fd))
            R.check(re.search(r"unsupported_fd_xl\s+0 ", err) is not None, "%s: no FD frame unsupported" % b)
            for key in ("e2e_wrong_crc", "e2e_wrong_sequence", "bad_dlc", "malformed_lines"):
                R.check(value(err, key) == "0", "%s: %s 0 (%s)" % (b, key, value(err, key)))
            m = re.search(r"state_time_s(.*)", err)
            st = dict(re.findall(r"(\w+)=([\d.]+)", m.group(1))) if m else {}
            # 5 s in each state, less the start-up and the change-over
            for w in want:
                R.check(float(st.get(names[w], 0)) > 4.5,
                        "%s: about 5 s %s as the reference says (%s s)" % (b, names[w], st.get(names[w])))
            rc, so, err = run(sim, ["replay", "--calib", CAL, "--no-output", "--summary-json", "-", log])
            doc = json.loads(so) if rc == 0 else {}
            R.check(doc.get("frames_by_format") == {"classic": 0, "fd": n_fd, "xl": 0},
                    "%s: JSON frames_by_format %s" % (b, doc.get("frames_by_format")))

            rc, so, err = run(sim, ["replay", "--calib", CAL, "--no-output", flog])
            R.check(rc == 0, "%s: faults log exits 0" % b)
            R.check(re.search(r"bad_dlc\s+1 \(FL speed WS_FL 1,", err) is not None,
                    "%s: a classic frame on the FD identifier is a wrong-format frame (bad_dlc 1)" % b)
            R.check(re.search(r"e2e_wrong_crc\s+1 \(FL speed WS_FL 1,", err) is not None,
                    "%s: a wrong P05 CRC is e2e_wrong_crc (%s)" % (b, value(err, "e2e_wrong_crc")))
            R.check(value(err, "malformed_lines") == "1" and
                    re.search(r"faults\.log:%d: not a valid CAN FD length" % (n_fd + 3), err) is not None,
                    "%s: 13 bytes (no DLC code) is one malformed line, said with its line" % b)
            R.check(re.search(r"unsupported_fd_xl\s+1 \(FD 0, XL 1\)", err) is not None,
                    "%s: the XL frame is still unsupported" % b)

            rc, so, err = run(sim, ["decode", "--calib", CAL, "--inputs-csv", log])
            rows = list(csv.DictReader(io.StringIO(so))) if rc == 0 else []
            R.check(rc == 0 and len(rows) == 2 * n_fd,
                    "%s: decode --inputs-csv: one row per input of every FD frame (%d of %d)" % (b, len(rows), 2 * n_fd))
            ok = [r for r in rows if r["valid"] == "1" and r["reason"] == "ok"]
            R.check(len(ok) == len(rows), "%s: every row valid (%d of %d)" % (b, len(ok), len(rows)))
            ws = sorted({round(float(r["physical"]), 6) for r in rows if r["input"] == "WS_FL"})
            R.check(ws == [9.0, 27.0], "%s: WS_FL physical 27 and 9 km/h as written (%s)" % (b, ws))
            p = sorted({float(r["physical"]) for r in rows if r["input"] == "P_FR"})
            R.check(p == [float(round(kpa))], "%s: P_FR physical %d kPa as written (%s)" % (b, round(kpa), p))
            R.check(rc == 0 and "not decoded" not in err, "%s: decode says no frame left out (%s)" % (b, err.strip()[:80]))
            rc, so, err = run(sim, ["decode", "--calib", CAL, "--inputs-csv", flog])
            R.check(re.search(r"1 frames not decoded as inputs \(CAN XL 1,", err) is not None,
                    "%s: decode counts and says the XL frame it cannot use (%s)" % (b, err.strip()[-120:]))
    print("RESULT: %d passed, %d failed" % (R.passed, R.failed))
    return 0 if R.failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
