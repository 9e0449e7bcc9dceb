#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Decode the firmware's own frames with canmatrix from the DBC and compare
with the intended physical values.

emit_frames packs and E2E-protects frames of every message through the
firmware's msg_*_pack() and e2e_p01_protect() and prints them as a candump -L
log, each followed by "# <id> Signal=raw:physical ..." with the physical
values written by hand. Here:
  - python-can's candump reader must accept the log (format check);
  - canmatrix decodes every frame from squeal.dbc: each listed signal has the
    intended raw and physical value ("NA": the DBC's not_available entry),
    every other signal of the frame (and of its multiplexer page) is 0;
  - the CRC in byte 0 is recomputed independently (bitwise CRC-8, poly 0x1D,
    over the DBC's E2E_DataID low/high byte and bytes 1..n-1), and the alive
    counter of each message counts 0, 1, 2, ... modulo 15.
"""
import os
import re
import sys
import tempfile
from decimal import Decimal
# tests/ of this checkout, and the folders its helper modules live in
_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, d) for d in ("support", os.path.join("support", "reference"), "host-sim", "tools")]

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from dbc_common import Results, crc8_p01, e2e_p01_crc, load_dbc, run_emitter  # noqa: E402

LINE = re.compile(r"^\((\d+)\.(\d{6})\) (\w+) ([0-9A-F]{3})#([0-9A-F]*)$")


def parse(text):
    frames = []
    pending = None
    for line in text.splitlines():
        if line.startswith("("):
            m = LINE.match(line)
            if m is None:
                raise ValueError("bad candump line: " + line)
            pending = (int(m.group(4), 16), bytes.fromhex(m.group(5)), line)
        elif line.startswith("# "):
            f = line[2:].split()
            fid = int(f[0], 16)
            if pending is None or pending[0] != fid:
                raise ValueError("expectation without frame: " + line)
            exp = {}
            for item in f[1:]:
                name, rest = item.split("=", 1)
                raw, phys = rest.split(":", 1)
                exp[name] = (int(raw), phys)
            frames.append((fid, pending[1], pending[2], exp))
            pending = None
    return frames


def check_with_python_can(lines, r):
    try:
        import can
    except ImportError:
        r.check(False, "python-can importable")
        return
    with tempfile.NamedTemporaryFile("w", suffix=".log", delete=False) as tmp:
        tmp.write("\n".join(lines) + "\n")
        path = tmp.name
    try:
        msgs = list(can.CanutilsLogReader(path))
    finally:
        os.unlink(path)
    r.check(len(msgs) == len(lines), "python-can read %d of %d frames" % (len(msgs), len(lines)))
    for msg, line in zip(msgs, lines):
        m = LINE.match(line)
        r.check(not msg.is_extended_id and msg.arbitration_id == int(m.group(4), 16)
                and bytes(msg.data) == bytes.fromhex(m.group(5)),
                "python-can reads %s" % line)


def main():
    r = Results()
    r.check(crc8_p01(b"123456789") == 0x37, "reference CRC check value 0x37")
    r.check(crc8_p01(b"123456789", 0xFF, 0xFF) == 0x4B, "reference SAE-J1850 check value 0x4B")
    db = load_dbc()
    frames = parse(run_emitter())
    r.check(len(frames) >= 20, "emitter printed %d frames" % len(frames))
    check_with_python_can([f[2] for f in frames], r)

    by_id = {f.arbitration_id.id: f for f in db.frames if not f.arbitration_id.extended}
    next_counter = {}
    seen_msgs = set()
    seen_sigs = set()
    for fid, data, line, exp in frames:
        frame = by_id.get(fid)
        if not r.check(frame is not None, "DBC knows 0x%X" % fid):
            continue
        name = frame.name
        seen_msgs.add(name)
        r.check(len(data) == frame.size, "%s: DLC %d, DBC %d" % (line, len(data), frame.size))
        decoded = frame.decode(bytearray(data))
        # E2E, recomputed from the DBC alone
        did = int(frame.attributes["E2E_DataID"])
        r.check(data[0] == e2e_p01_crc(did, data), "%s: CRC 0x%02X, expected 0x%02X" %
                (line, data[0], e2e_p01_crc(did, data)))
        r.check(decoded[name + "_CRC"].raw_value == data[0], "%s: %s_CRC signal" % (line, name))
        cnt = decoded[name + "_Counter"].raw_value
        want = next_counter.get(fid, 0)
        r.check(cnt == want, "%s: counter %d, expected %d" % (line, cnt, want))
        next_counter[fid] = (want + 1) % 15
        for sname, (raw, phys) in exp.items():
            d = decoded.get(sname)
            if not r.check(d is not None, "%s: canmatrix decodes %s" % (line, sname)):
                continue
            seen_sigs.add((fid, sname))
            r.check(d.raw_value == raw, "%s: %s raw %s, intended %d" % (line, sname, d.raw_value, raw))
            if phys == "NA":
                r.check(d.signal.values.get(raw) == "not_available",
                        "%s: %s raw %d is the DBC's not_available" % (line, sname, raw))
            else:
                pv = d.phys_value
                r.check(Decimal(str(pv)) == Decimal(phys),
                        "%s: %s physical %s, intended %s" % (line, sname, pv, phys))
        for sname, d in decoded.items():
            if sname in exp or sname in (name + "_CRC", name + "_Counter"):
                continue
            r.check(d.raw_value == 0, "%s: unlisted %s is 0 (got %s)" % (line, sname, d.raw_value))
    # coverage: every message, every non-E2E signal at least once
    r.check(seen_msgs == {f.name for f in db.frames}, "every message emitted: %s" % sorted(seen_msgs))
    for f in db.frames:
        for s in f.signals:
            if s.name.endswith("_CRC") or s.name.endswith("_Counter"):
                continue
            r.check((f.arbitration_id.id, s.name) in seen_sigs, "signal %s exercised" % s.name)
    r.finish()


if __name__ == "__main__":
    main()
