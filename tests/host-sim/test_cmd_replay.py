#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""End-to-end tests of `squeal-sim replay` and `squeal-sim decode`, against
tools and models that share no code with them:

  - the input log is written by python-can's candump writer, with E2E CRCs
    and counters computed here (gen_inputs.py) from the DBC's data IDs;
  - the SquealStatus states of the replay match the independent scipy
    reference (tests/support/reference/squeal_reference.py) at the operating points
    of the log, away from the borders (debounce and hysteresis);
  - the output is the same bytes on every run, and for the release and the
    sanitizer build;
  - malformed lines, comments, blank and DROPCOUNT lines are reported with
    their line numbers and change nothing else (same bytes as the clean log);
    timestamps going back are reported and do not move time back;
  - frames the firmware must refuse are counted by reason in the summary;
  - python-can reads the replay's output back exactly (candump writer);
  - canmatrix decodes the replay's output to the same values as
    `decode --csv`, and the E2E CRC/counter of every output frame is right.
Prints "RESULT: N passed, M failed".
"""
import csv
import io
import os
import re
import subprocess
import sys
import tempfile
from decimal import Decimal
# tests/ of this checkout, and the folders its helper modules live in
_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, d) for d in ("support", os.path.join("support", "reference"), "host-sim", "tools")]

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(_TESTS)

import gen_inputs  # noqa: E402
import squeal_reference as ref  # noqa: E402
from dbc_common import Results  # noqa: E402
from sim_cli import SAN_SIMS, SIMS  # noqa: E402

SIM_TEST, SIM_HOST, SIM_FIXED = SAN_SIMS["float"], SIMS["float"], SAN_SIMS["fixed"]

# Monitor calibration defaults (calib.h): below these it is "not sliding".
V0_MIN_MPS = 0.01
FORCE_MIN_N = 100.0

LINE = re.compile(r"^\((\d{10})\.(\d{6})\) (\S+) ([0-9A-F]{3})#((?:[0-9A-F]{2})*)$")


def run(sim, args, stdin=None):
    p = subprocess.run([sim] + args, input=stdin, stdout=subprocess.PIPE,
                       stderr=subprocess.PIPE)
    return p.returncode, p.stdout, p.stderr.decode("utf-8", "replace")


def summary_value(err, key):
    """First number after `key` in the replay summary (or None)."""
    m = re.search(r"^\s+" + re.escape(key) + r"\s+(\d+(?:\.\d+)?)", err, re.M)
    return None if m is None else m.group(1)


def summary_detail(err, key, name):
    m = re.search(r"^\s+" + re.escape(key) + r"\s.*\b" + re.escape(name) + r" (\d+)", err, re.M)
    return None if m is None else int(m.group(1))


def parse_out(text):
    frames = []
    for line in text.splitlines():
        m = LINE.match(line)
        if m is None:
            raise ValueError("not a candump -L line: %r" % line)
        t_us = int(m.group(1)) * 1000000 + int(m.group(2))
        frames.append((t_us, m.group(3), int(m.group(4), 16), bytes.fromhex(m.group(5))))
    return frames


def ref_state(v0, force):
    if v0 < V0_MIN_MPS or force < FORCE_MIN_N:
        return 3
    return ref.STATE_CODE[ref.classify(ref.default_point(v0, force))["state"]]


# ---------------------------------------------------------------------------

def test_model_agreement(r, tmp, db, sim=None):
    enc = gen_inputs.InputEncoder(db)
    frames = gen_inputs.braking_frames(enc)
    log = os.path.join(tmp, "brake.log")
    gen_inputs.write_python_can(log, frames)
    rc, out, err = run(sim or SIM_TEST, ["replay", log])
    r.check(rc == 0, "replay exits 0 (%d): %s" % (rc, err[-500:]))
    r.check(summary_value(err, "frames_read") == str(len(frames)), "all frames read")
    r.check(summary_value(err, "frames_used") == str(len(frames)), "all frames used")
    outf = parse_out(out.decode())
    status_id = db.frame_by_name("SquealStatus").arbitration_id.id
    status = db.frame_by_name("SquealStatus")
    t0_us = int(round(frames[0][0] * 1e6))

    # operating point of the inputs as the firmware last received them:
    # the values the frames carry, converted with the DBC scaling and r_p
    pts = []  # (t_us, v0, force) after each input frame
    v0, force = None, None
    for fr in frames:
        raw = fr[2][2] | (fr[2][3] << 8)
        if fr[1] == enc.speed_id:
            v0 = raw * enc.speed_factor * gen_inputs.PAD_RADIUS_M
        else:
            force = raw * enc.force_factor
        pts.append((int(round(fr[0] * 1e6)), v0, force))

    # reference state over time, and where it changes
    ref_at = []
    changes = []
    last = None
    for t_us, v, f in pts:
        if v is None or f is None:
            continue
        s = ref_state(v, f)
        ref_at.append((t_us, s))
        if s != last:
            changes.append(t_us)
            last = s
    seen = set(s for _, s in ref_at)
    r.check(seen == {0, 1, 2, 3}, "the braking run visits all four model states (%s)" % sorted(seen))

    compared = 0
    mismatched = []
    states_compared = set()
    j = 0
    n_status = 0
    for t_us, _, cid, data in outf:
        if cid != status_id:
            continue
        n_status += 1
        while j + 1 < len(ref_at) and ref_at[j + 1][0] <= t_us:
            j += 1
        if t_us < t0_us + 150000 or ref_at[j][0] > t_us or t_us > pts[-1][0]:
            continue  # start-up, and the tail after the last input (stale)
        # away from the borders: no reference change 150 ms before or
        # 50 ms after (debounce of 3 classifications, hysteresis bands)
        if any(t_us - 150000 <= c <= t_us + 50000 for c in changes):
            continue
        dec = status.decode(bytearray(data))
        fw = int(dec["SquealState"].raw_value)
        compared += 1
        states_compared.add(ref_at[j][1])
        if fw != ref_at[j][1]:
            mismatched.append((t_us - t0_us, fw, ref_at[j][1]))
    r.check(compared > 0.8 * n_status - 200,
            "most status frames compared (%d of %d)" % (compared, n_status))
    r.check(states_compared == {0, 1, 2, 3}, "compared frames in every state")
    r.check(not mismatched, "SquealState equals the reference away from borders "
            "(%d mismatches, first %s)" % (len(mismatched), mismatched[:5]))
    return log, out


def test_determinism(r, tmp, log, out_test):
    rc1, out1, err1 = run(SIM_HOST, ["replay", log])
    rc2, out2, err2 = run(SIM_HOST, ["replay", log])
    r.check(rc1 == 0 and rc2 == 0, "release replay exits 0")
    r.check(out1 == out2 and len(out1) > 0, "two runs: identical output bytes")
    r.check(err1 == err2, "two runs: identical summary")
    r.check(out1 == out_test, "release and sanitizer builds: identical output bytes")
    with open(log, "rb") as f:
        rc3, out3, err3 = run(SIM_HOST, ["replay", "-"], stdin=f.read())
    r.check(rc3 == 0 and out3 == out1, "stdin gives the same bytes as the file")
    rc4, out4, _ = run(SIM_HOST, ["replay", "--iface-out", "vcan7", log])
    r.check(rc4 == 0 and out4 == out1.replace(b") can0 ", b") vcan7 "),
            "--iface-out renames the interface only")


def test_malformed_lines(r, tmp, log, out_clean):
    with open(log) as f:
        lines = f.read().splitlines()
    bad = {}
    dirty = []
    inserts = {
        0: "# comment at the top",
        3: "",
        10: "(1700000000.050000) can0 110#1",                        # odd digits
        50: "(1700000000.250000) can0 1100#00112233",               # 4-digit id
        51: "DROPCOUNT: dropped 2 CAN frames on 'can0' socket (total drops 2)",
        100: "garbage \x01\x02",
        400: "(1700000002.000000) can0 110#GG001122",               # bad hex
        401: "(1700000002.000000) can0 110",                        # no '#'
        900: "(1700000004.500000) can0 800#00",                     # id too large
        1500: "(17000000.123) can0 110#00",                         # 3-digit fraction
    }
    malformed = {10, 50, 100, 400, 401, 900, 1500}
    for i, line in enumerate(lines):
        if i in inserts:
            dirty.append(inserts[i])
            if i in malformed:
                bad[len(dirty)] = inserts[i]
        dirty.append(line)
    path = os.path.join(tmp, "dirty.log")
    with open(path, "w") as f:
        f.write("\n".join(dirty) + "\n")
    rc, out, err = run(SIM_TEST, ["replay", path])
    r.check(rc == 0, "replay with malformed lines exits 0")
    r.check(out == out_clean, "malformed lines, comments, DROPCOUNT change nothing in the output")
    reported = sorted(int(m.group(1)) for m in re.finditer(r"^" + re.escape(path) + r":(\d+): ", err, re.M))
    r.check(reported == sorted(bad), "each malformed line reported as LOG:LINE (%s vs %s)"
            % (reported, sorted(bad)))
    r.check(summary_value(err, "malformed_lines") == str(len(bad)), "malformed count in the summary")
    r.check(summary_value(err, "candump_dropped") == "2", "DROPCOUNT summed")


def frames_log(lines):
    return "\n".join(lines) + "\n"


def test_rejections_and_time(r, tmp, db):
    enc = gen_inputs.InputEncoder(db)
    sid, fid = enc.speed_id, enc.force_id
    out = []
    t = 0
    expect = {"crc": 0, "seq": 0, "rep": 0, "dlc": 0, "impl": 0}
    for k in range(400):  # 4 s, faults one per second at k = 50, 150, ...
        ts = "(%010d.%06d)" % (100 + t // 1000000, t % 1000000)
        sd = enc.frame(sid, enc.speed_raw(5.0))
        if k == 50:
            sd = bytes([sd[0] ^ 0x5A]) + sd[1:]
            expect["crc"] += 1
        if k == 150:
            enc.counters[sid] = (enc.counters[sid] + 5) % 15  # sender jumps
            sd = enc.frame(sid, enc.speed_raw(5.0))
            expect["seq"] += 1
        out.append("%s can0 %03X#%s" % (ts, sid, sd.hex().upper()))
        if k == 250:
            out.append("%s can0 %03X#%s" % (ts, sid, sd.hex().upper()))  # repeated
            expect["rep"] += 1
        fd = enc.frame(fid, enc.force_raw(4000.0))
        if k == 300:
            fd = fd[:3]  # DLC 3
            expect["dlc"] += 1
        if k == 350:
            fd = enc.frame(fid, 0xFFFF)  # not available
            expect["impl"] += 1
        out.append("%s can0 %03X#%s" % (ts, fid, fd.hex().upper()))
        t += 10000
    out += [
        "(0000000104.000000) can0 110##4%s" % enc.frame(sid, 500).hex().upper(),    # FD: wrong format
        "(0000000104.000000) can0 45110#81:00:12345678#00112233",                 # XL
        "(0000000104.001000) can0 110#R4",                                         # remote
        "(0000000104.002000) can0 00000110#%s" % enc.frame(sid, 500).hex().upper(),  # ext
        "(0000000104.003000) can0 123#00",                                         # other id
        "(0000000104.004000) can0 20000004#0004000000000000",                      # error
        "(0000000103.500000) can0 123#00",                                         # back
        "(0000000104.005000) can0 123#00",
    ]
    path = os.path.join(tmp, "faults.log")
    with open(path, "w") as f:
        f.write(frames_log(out))
    rc, so, err = run(SIM_TEST, ["replay", path])
    r.check(rc == 0, "faults log: exit 0")
    checks = [
        ("e2e_wrong_crc", expect["crc"], "DiscSpeed"),
        ("e2e_wrong_sequence", expect["seq"], "DiscSpeed"),
        ("repeated", expect["rep"], "DiscSpeed"),
        ("implausible", expect["impl"], "PadForce"),
    ]
    for key, n, who in checks:
        r.check(summary_value(err, key) == str(n), "%s = %d (%s)" % (key, n, summary_value(err, key)))
        r.check(summary_detail(err, key, who) == n, "%s counted for %s" % (key, who))
    # the FD frame on DiscSpeed's (classic) identifier: a wrong-format frame,
    # the input stage's dlc verdict; only the XL frame is unsupported
    r.check(summary_value(err, "bad_dlc") == str(expect["dlc"] + 1) and
            summary_detail(err, "bad_dlc", "PadForce") == expect["dlc"] and
            summary_detail(err, "bad_dlc", "DiscSpeed") == 1,
            "bad_dlc = %d (PadForce %d, DiscSpeed 1: the FD frame) (%s)" %
            (expect["dlc"] + 1, expect["dlc"], summary_value(err, "bad_dlc")))
    r.check(summary_value(err, "unsupported_fd_xl") == "1", "XL frame unsupported, FD frame given")
    # hal.h's filters match the identifier and its kind (standard or
    # extended), data and remote frames alike: the remote frame on
    # DiscSpeed's id passes the controller and the firmware rejects it
    r.check(summary_value(err, "filtered_ids") == "4", "extended and other ids filtered")
    r.check(summary_detail(err, "filtered_ids", "remote") == 0, "remote frame passes the filter")
    r.check(summary_value(err, "remote_or_extended") == "1", "remote frame counted by the firmware")
    r.check(summary_detail(err, "filtered_ids", "extended") == 1, "extended counted")
    r.check(summary_value(err, "error_frames") == "1", "error frame given to the firmware and counted")
    # the frame 0.504 s late is put in its place by the reorder window
    r.check(summary_value(err, "time_backwards") == "0", "a frame 0.5 s late is not given late")
    r.check(summary_value(err, "reordered") == "1", "a frame 0.5 s late is put back in order (counted)")
    frames = parse_out(so.decode())
    ts = [f[0] for f in frames]
    r.check(ts == sorted(ts), "output time never goes back")
    # the replay stops at the last frame (104.005 s) and its tick
    r.check(104000000 <= ts[-1] <= 104006000, "output ends at the last frame (%d)" % ts[-1])
    r.check(summary_value(err, "virtual_time_s") == "4.006000",
            "virtual time: first frame to the tick after the last (%s)" % summary_value(err, "virtual_time_s"))
    rc, so, err = run(SIM_TEST, ["replay", "--tail-ms", "100", path])
    ts = [f[0] for f in parse_out(so.decode())]
    r.check(rc == 0 and 104095000 <= ts[-1] <= 104106000, "--tail-ms 100 runs on 100 ms (%d)" % ts[-1])
    used = int(summary_value(err, "frames_used"))
    # 800 inputs + 1 repeated; rejected: CRC, sequence, repeated, DLC, NA
    r.check(used == 801 - 5, "frames used = inputs minus the rejected ones (%d)" % used)

    # a log without a single CAN frame: one line, exit 1 (replay and decode)
    for text in ("", "# nothing\n\n", "not a log\nat all\n"):
        for cmd in ("replay", "decode"):
            rc, so, err = run(SIM_TEST, [cmd, "-"], stdin=text.encode())
            n = len(text.splitlines())
            want = "<stdin>: no CAN frame in %d line%s\n" % (n, "" if n == 1 else "s")
            r.check(rc == 1 and so == b"" and err == want,
                    "%s of %r: 'no CAN frame', exit 1 (%d %r)" % (cmd, text, rc, err))
    readme = os.path.join(HERE, "README.md")
    with open(readme, "rb") as f:
        readme_lines = len(f.read().splitlines())
    for cmd in ("replay", "decode"):
        rc, so, err = run(SIM_TEST, [cmd, readme])
        r.check(rc == 1 and so == b"" and err == "%s: no CAN frame in %d lines\n" % (readme, readme_lines),
                "%s of a text file: one line, exit 1 (%d, %d lines)" % (cmd, rc, len(err.splitlines())))
    rc, _, err = run(SIM_TEST, ["replay", os.path.join(tmp, "missing.log")])
    r.check(rc == 1 and "cannot open" in err, "missing log: exit 1 with a message")
    rc, _, _ = run(SIM_TEST, ["replay"])
    r.check(rc == 2, "no LOG: usage error")
    # a gap larger than --max-gap is skipped and reported
    gap = "(0000000001.000000) can0 123#\n(0000100000.000000) can0 123#\n"
    rc, so, err = run(SIM_TEST, ["replay", "--max-gap", "10", "-"], stdin=gap.encode())
    r.check(rc == 0 and summary_value(err, "gaps_skipped") == "1" and "<stdin>:2: gap of" in err,
            "gap beyond --max-gap skipped and reported")


def test_calib(r, tmp):
    cal = os.path.join(tmp, "ids.cal")
    with open(cal, "w") as f:
        f.write("status_id = 0x280\n")
    log = "(0000000001.000000) can0 123#\n"
    rc, so, err = run(SIM_TEST, ["replay", "--calib", cal, "-"], stdin=log.encode())
    r.check(rc == 0 and b" 280#" in so and b" 300#" not in so,
            "--calib: the calibration's identifiers are used")
    with open(cal, "w") as f:
        f.write("no_such_key = 1\n")
    rc, so, err = run(SIM_TEST, ["replay", "--calib", cal, "-"], stdin=log.encode())
    r.check(rc == 1 and (cal + ":1:") in err, "--calib: a bad file is refused with its line")


def test_python_can_reads_output(r, out):
    import can
    text = out.decode()
    ours = parse_out(text)
    with tempfile.NamedTemporaryFile("w", suffix=".log", delete=False) as f:
        f.write(text)
        path = f.name
    try:
        msgs = list(can.io.CanutilsLogReader(path))
    finally:
        os.unlink(path)
    ok = len(msgs) == len(ours)
    for m, o in zip(msgs, ours):
        if (int(round(m.timestamp * 1e6)) != o[0] or m.arbitration_id != o[2] or
                bytes(m.data) != o[3] or m.is_extended_id or m.channel != o[1]):
            ok = False
            break
    r.check(ok, "python-can reads the replay output back exactly (%d frames)" % len(ours))
    # the writer's other forms, exactly as the C unit test pins them
    forms = [
        ("(0000000012.340000) vcan0 300#01AB00FF10203040", dict(arbitration_id=0x300, is_extended_id=False, dlc=8)),
        ("(0000000012.340000) vcan0 00000123#", dict(arbitration_id=0x123, is_extended_id=True, dlc=0)),
        ("(0000000012.340000) vcan0 123#R3", dict(arbitration_id=0x123, is_remote_frame=True, dlc=3)),
        ("(0000000012.340000) vcan0 123##501AB", dict(arbitration_id=0x123, is_fd=True, bitrate_switch=True, dlc=2)),
    ]
    for line, want in forms:
        with tempfile.NamedTemporaryFile("w", suffix=".log", delete=False) as f:
            f.write(line + "\n")
            path = f.name
        try:
            m = list(can.io.CanutilsLogReader(path))[0]
        finally:
            os.unlink(path)
        good = abs(m.timestamp - 12.34) < 1e-9 and all(getattr(m, k) == v for k, v in want.items())
        r.check(good, "python-can reads %r" % line)


def test_decode_vs_canmatrix(r, db, out):
    rc, csv_text, err = run(SIM_TEST, ["decode", "--csv", "-"], stdin=out)
    r.check(rc == 0 and err == "", "decode --csv exits 0 without messages")
    rows = list(csv.DictReader(io.StringIO(csv_text.decode())))
    frames = parse_out(out.decode())
    r.check(len(rows) == len(frames), "one CSV row per frame")
    by_id = {f.arbitration_id.id: f for f in db.frames}
    bad = []
    e2e_bad = []
    counters = {}
    for row, (t_us, _, cid, data) in zip(rows, frames):
        fr = by_id.get(cid)
        if fr is None or row["message"] != fr.name:
            bad.append((row["time_s"], "message"))
            continue
        if row["time_s"] != "%d.%06d" % divmod(t_us, 1000000):
            bad.append((row["time_s"], "time"))
        dec = fr.decode(bytearray(data))
        for name, d in dec.items():
            sig = d.signal
            if name.endswith("_CRC") or name.endswith("_Counter"):
                continue
            cell = row.get(name)
            if cell is None:
                bad.append((row["time_s"], name, "no column"))
                continue
            na = [k for k, v in sig.values.items() if v == "not_available"]
            if na and int(na[0]) == d.raw_value:
                if cell != "NA":
                    bad.append((row["time_s"], name, cell, "want NA"))
            elif cell == "" or abs(Decimal(cell) - Decimal(str(d.phys_value))) > Decimal("1e-9"):
                bad.append((row["time_s"], name, cell, d.phys_value))
        # every other signal column empty
        names = set(dec.keys())
        for col, cell in row.items():
            if col in ("time_s", "id", "message", "counter", "e2e", "raw") or col in names:
                continue
            if cell != "":
                bad.append((row["time_s"], col, "should be empty"))
        # E2E, computed here
        did = int(fr.attributes["E2E_DataID"])
        crc = gen_inputs.crc8_p01(bytes([did & 0xFF, did >> 8]) + data[1:])
        ctr = data[1] & 0x0F
        prev = counters.get(cid)
        want = "initial" if prev is None else ("ok" if ctr == (prev + 1) % 15 else "?")
        counters[cid] = ctr
        if crc != data[0] or row["e2e"] != want or row["counter"] != str(ctr):
            e2e_bad.append((row["time_s"], cid, row["e2e"], want))
    r.check(not bad, "canmatrix and decode --csv agree on every signal (%d differences, first %s)"
            % (len(bad), bad[:5]))
    r.check(not e2e_bad, "E2E of every output frame right and reported ok (%s)" % e2e_bad[:5])

    # text mode: the example line's form, and E2E faults named
    rc, txt, _ = run(SIM_TEST, ["decode", "-"], stdin=out)
    first = txt.decode().splitlines()[0]
    r.check(re.match(r"^\d+\.\d{6} SquealStatus state=fault warning=none BasinRatio=NA "
                     r"HopfMargin_mps=NA BorderMargin_sigma=NA ctr=0 e2e=initial$", first) is not None,
            "decode text line: %r" % first)
    bad_crc = b"(0000000001.000000) can0 300#00000000FFFF0080\n(0000000001.010000) can0 123#11\n"
    rc, txt, _ = run(SIM_TEST, ["decode", "-"], stdin=bad_crc)
    lines = txt.decode().splitlines()
    r.check(len(lines) == 2 and lines[0].endswith("e2e=wrong_crc") and
            lines[1] == "1.010000 123 unknown [1] 11", "decode names a wrong CRC and prints unknown ids raw")
    rc, _, err = run(SIM_TEST, ["decode", "--iface", "vcan_nonexistent0"])
    r.check(rc == 1 and "squeal-sim decode: " in err and len(err.strip().splitlines()) == 1,
            "decode --iface without CAN: one-line error, exit 1 (%r)" % err.strip())


def test_two_buses(r, tmp, log, out):
    """--bus: a two-bus log (the inputs on can1, other traffic on can0) with
    the calibration's input_bus 1 (listen-only) and output_bus 0, the inputs
    taken from can1, gives the single-bus replay's output, sent on can0;
    decode --bus can1 picks the input frames only."""
    with open(log) as f:
        lines = [ln for ln in f.read().splitlines() if ln.strip()]
    moved = [re.sub(r" \S+ ", " can1 ", ln, count=1) for ln in lines]
    noise = [ln.split(" ")[0] + " can0 123#00" for ln in lines]
    two = os.path.join(tmp, "two-bus.log")
    with open(two, "w") as f:
        f.write("\n".join(sorted(moved + noise, key=lambda ln: ln.split(" ")[0])) + "\n")
    cal = os.path.join(tmp, "two-bus.cal")
    with open(cal, "w") as f:
        f.write("input_bus = 1\noutput_bus = 0\ninput_listen_only = yes\n")
    rc, so, err = run(SIM_TEST, ["replay", two, "--bus", "can1", "--calib", cal])
    r.check(rc == 0, "two-bus replay: exit 0")
    got = so.decode().splitlines()
    want = out.splitlines() if isinstance(out, str) else out.decode().splitlines()
    r.check(len(got) == len(want) and all(" can0 " in ln for ln in got),
            "two-bus replay: every output line on the output bus can0 (%d lines)" % len(got))
    r.check([ln.split(" ", 2)[::2] for ln in got] == [ln.split(" ", 2)[::2] for ln in want],
            "two-bus replay: same frames at the same times as the single-bus replay")
    r.check(summary_value(err, "other_bus") == "0", "two-bus replay: no frame on an unused bus")
    rc, txt, _ = run(SIM_TEST, ["decode", two, "--bus", "can1"])
    r.check(rc == 0 and len(txt.decode().splitlines()) == len(lines),
            "decode --bus can1: the %d input frames only" % len(lines))


def main():
    r = Results()
    db = gen_inputs.load_dbc()
    with tempfile.TemporaryDirectory() as tmp:
        log, out = test_model_agreement(r, tmp, db)
        test_model_agreement(r, tmp, db, SIM_FIXED)  # fixed-point build
        test_determinism(r, tmp, log, out)
        test_malformed_lines(r, tmp, log, out)
        test_rejections_and_time(r, tmp, db)
        test_calib(r, tmp)
        test_two_buses(r, tmp, log, out)
        test_python_can_reads_output(r, out)
        test_decode_vs_canmatrix(r, db, out)
    print("RESULT: %d passed, %d failed" % (r.passed, r.failed))
    return 0 if r.failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
