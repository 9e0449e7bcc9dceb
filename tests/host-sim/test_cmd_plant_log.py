#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""squeal-sim plant --log (virtual time, no CAN needed) and squeal-sim ecu's
error paths, checked from outside: frames decoded with canmatrix from the
DBC, E2E with the bitwise CRC-8 of tests/support/dbc_common.py, expected
values from the scenario definitions (hand-derived: v = 30 - 6 (t - 0.5) m/s,
DiscSpeed = v / r_w, 0.01 rad/s per bit; PadForce 0.5 N per bit, at most
raw 65534, the DBC's 32767 N: a force there is sent as it is, one beyond it
is clamped and counted as saturated).

usage: test_plant_log.py [SQUEAL_SIM]   prints "RESULT: N passed, M failed"
"""
import os
import subprocess
import sys
import tempfile
# tests/ of this checkout, and the folders its helper modules live in
_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, d) for d in ("support", os.path.join("support", "reference"), "host-sim", "tools")]

ROOT = os.path.dirname(_TESTS)
from check_vcan import Checks, Decoder, read_log  # noqa: E402

SIM = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build", "test", "squeal-sim")
ID_SPEED, ID_FORCE = 0x110, 0x111


def run(*args, check=True):
    p = subprocess.run([SIM] + list(args), stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                       universal_newlines=True, timeout=60)
    if check and p.returncode != 0:
        raise RuntimeError("%s: exit %d: %s" % (args, p.returncode, p.stderr))
    return p


def frames_of(*args):
    with tempfile.NamedTemporaryFile("w", suffix=".log", delete=False) as f:
        path = f.name
    try:
        run("plant", "--log", path, "--quiet", *args)
        return read_log(path), open(path).read()
    finally:
        os.unlink(path)


def counters(frames, ident):
    return [f.data[1] & 0x0F for f in frames if f.id == ident]


def main():
    c = Checks()
    dec = Decoder()

    # --- stop scenario, no faults ---------------------------------------
    fr, text = frames_of("--scenario", "stop")
    sp = [f for f in fr if f.id == ID_SPEED]
    fo = [f for f in fr if f.id == ID_FORCE]
    c.check(len(sp) == 600 and len(fo) == 600, "stop: 600 + 600 frames in 6 s")
    c.check(all(abs(f.t - 0.010 * i) < 1e-9 for i, f in enumerate(sp)) and
            all(abs(f.t - (0.005 + 0.010 * i)) < 1e-9 for i, f in enumerate(fo)),
            "stop: DiscSpeed every 10 ms from 0, PadForce every 10 ms from 5 ms")
    c.check(all(a.t <= b.t for a, b in zip(fr, fr[1:])), "stop: log in time order")
    c.check(all(dec.e2e_ok(f) for f in fr), "stop: E2E CRC of every frame right")
    c.check(counters(fr, ID_SPEED) == [i % 15 for i in range(600)] and
            counters(fr, ID_FORCE) == [i % 15 for i in range(600)],
            "stop: alive counters 0..14 repeating")
    worst = 0.0
    for f in sp:
        v = 30.0 if f.t <= 0.5 else max(0.0, 30.0 - 6.0 * (f.t - 0.5))
        want_raw = round(v / 0.30 / 0.01)
        worst = max(worst, abs(dec.decode(f)["DiscSpeed_radps"] - want_raw))
    c.check(worst <= 1, "stop: DiscSpeed = v(t) / r_w within one bit (worst %d)" % worst)
    c.check(all(dec.decode(f)["PadForce_N"] == 18000 for f in fo), "stop: PadForce 9000 N")
    c.check(text.splitlines()[0] == "(0000000000.000000) vcan0 110#E3001027",
            "stop: first line, candump -L format (%s)" % text.splitlines()[0])
    _, text2 = frames_of("--scenario", "stop")
    c.check(text == text2, "stop: same output twice")

    # --- point: --v0 is the pad surface speed ----------------------------
    fr, _ = frames_of("--scenario", "point", "--v0", "1.2", "--force", "4000.5",
                      "--duration", "0.1", "--iface", "can7")
    sp = [dec.decode(f)["DiscSpeed_radps"] for f in fr if f.id == ID_SPEED]
    fo = [dec.decode(f)["PadForce_N"] for f in fr if f.id == ID_FORCE]
    c.check(sp == [1000] * 10 and fo == [8001] * 10,
            "point: v0 1.2 m/s -> 10.00 rad/s at r_p 0.12; 4000.5 N -> raw 8001")
    c.check(all(" can7 " in line for line in _.splitlines()), "point: --iface names the log column")

    # --- the force's top: 32767 N is raw 65534 (0.5 N per bit), the DBC's
    # largest value, sent as it is; 32767.25 N rounds to 65535 (the "not
    # available" code) and is clamped to 65534 and counted as saturated ----
    for force, sat in (("32767", 0), ("32767.25", 10)):
        p = run("plant", "--log", os.devnull, "--scenario", "point", "--v0", "1.2",
                "--force", force, "--duration", "0.1")
        line = [x for x in p.stderr.splitlines() if x.lstrip().startswith("PadForce ")]
        c.check(len(line) == 1 and line[0].endswith("made 10, sent 10, dropped 0, corrupted 0, "
                                                     "frozen 0, send errors 0, saturated %d" % sat),
                "point --force %s: PadForce saturated %d times of 10 (%s)" % (force, sat, line))
        fr, _ = frames_of("--scenario", "point", "--v0", "1.2", "--force", force, "--duration", "0.1")
        fo = [dec.decode(f)["PadForce_N"] for f in fr if f.id == ID_FORCE]
        c.check(fo == [65534] * 10, "point --force %s: PadForce raw 65534 (%s)" % (force, fo[:2]))

    # --- faults ------------------------------------------------------------
    args = ["--scenario", "point", "--v0", "3", "--force", "9000", "--duration", "20"]
    fr, t1 = frames_of(*args, "--drop", "0.1", "--seed", "5")
    _, t2 = frames_of(*args, "--drop", "0.1", "--seed", "5")
    _, t3 = frames_of(*args, "--drop", "0.1", "--seed", "6")
    c.check(t1 == t2 and t1 != t3, "faults: same --seed same log, other seed other log")
    n = len(fr)
    c.check(3600 - 180 < n < 3600 + 180, "drop 0.1: %d of 4000 frames left (expected ~3600)" % n)
    c.check(all((f.data[1] & 0x0F) == round(f.t / 0.01) % 15 for f in fr if f.id == ID_SPEED),
            "drop: the counter still advances over dropped frames (frame i carries i mod 15)")
    fr, _ = frames_of(*args, "--corrupt-crc", "0.1", "--seed", "7")
    bad = sum(1 for f in fr if not dec.e2e_ok(f))
    c.check(len(fr) == 4000 and 400 - 80 < bad < 400 + 80,
            "corrupt-crc 0.1: %d of 4000 frames with a wrong CRC" % bad)
    fr, _ = frames_of(*args, "--freeze-counter", "1")
    cs = [(f.t, f.data[1] & 0x0F) for f in fr if f.id == ID_SPEED]
    before = [x for t, x in cs if t < 1.0]
    after = set(x for t, x in cs if t >= 1.0)
    c.check(before == [i % 15 for i in range(100)] and len(after) == 1 and
            all(dec.e2e_ok(f) for f in fr),
            "freeze-counter 1: counter counts to 1 s, then one value (%s), CRC still right" % after)
    fr, _ = frames_of(*args, "--delay", "20", "--seed", "3")
    late = []
    for ident, off in ((ID_SPEED, 0.0), (ID_FORCE, 0.005)):
        ts = [f.t for f in fr if f.id == ident]
        late += [t - (off + 0.01 * i) for i, t in enumerate(ts)]
        c.check(all(a <= b for a, b in zip(ts, ts[1:])), "delay: order kept for 0x%03X" % ident)
    c.check(len(fr) == 4000 and min(late) >= -1e-9 and max(late) <= 0.020 + 1e-6 and
            max(late) > 0.015, "delay 20: frames 0..20 ms late (max %.1f ms)" % (1e3 * max(late)))
    fr, _ = frames_of(*args, "--rate-hz", "1000", "--duration", "0.01")
    c.check(len(fr) == 20 and abs(fr[1].t - 0.0005) < 1e-9,
            "rate-hz 1000: 10 + 10 frames in 10 ms, senders 0.5 ms apart")

    # --- scenario files ------------------------------------------------------
    with tempfile.TemporaryDirectory() as d:
        good = os.path.join(d, "s.txt")
        with open(good, "w") as f:
            f.write("# ramp\n0 10 1000\n\n1.0 20 3000  # end\n")
        fr, _ = frames_of("--scenario", good)
        sp = [f for f in fr if f.id == ID_SPEED]
        mid = [f for f in sp if abs(f.t - 0.5) < 1e-9][0]
        c.check(len(sp) == 100 and dec.decode(mid)["DiscSpeed_radps"] == round(15.0 / 0.3 / 0.01),
                "file: linear interpolation (15 m/s at 0.5 s)")
        for content, want in (("0 1 2\n0.5 x 3\n", ":2: speed_mps is not a number: 'x'"),
                              ("0 1 2\n0 1 3\n", ":2: time_s 0 is not after"),
                              ("0 1\n", ":1: expected 3 columns"),
                              ("0 1 2 3\n", ":1: more than 3 columns"),
                              ("0 -1 2\n", ":1: speed_mps must be >= 0"),
                              ("# nothing\n", ": no rows")):
            bad = os.path.join(d, "bad.txt")
            with open(bad, "w") as f:
                f.write(content)
            p = run("plant", "--log", "-", "--scenario", bad, check=False)
            c.check(p.returncode == 1 and (bad + want) in p.stderr,
                    "file error reported: %r -> %s" % (content, p.stderr.strip()))
        # ecu: calibration errors come before any CAN access
        cal = os.path.join(d, "bad.cal")
        with open(cal, "w") as f:
            f.write("damping = 0.05\nslope_spm = fast\n")
        p = run("ecu", "--iface", "vcan0", "--calib", cal, check=False)
        c.check(p.returncode == 1 and (cal + ":2: slope_spm needs a number") in p.stderr,
                "ecu --calib: bad file refused with its line number")
    p = run("ecu", "--iface", "nosuchcan0", "--calib", os.path.join(ROOT, "docs", "calib-example.txt"),
            check=False)
    c.check(p.returncode == 1 and p.stderr.strip() != "" and "squeal-sim ecu:" in p.stderr,
            "ecu: a clear message and exit 1 without CAN / interface (%s)" % p.stderr.strip())
    p = run("plant", "--iface", "nosuchcan0", "--scenario", "stop", check=False)
    c.check(p.returncode == 1 and "squeal-sim plant:" in p.stderr,
            "plant: a clear message and exit 1 without CAN / interface")
    p = run("plant", "--scenario", "point", "--log", "-", check=False)
    c.check(p.returncode == 2 and "--v0" in p.stderr, "plant: point without --v0/--force is a usage error")
    c.check(run("ecu", "--help").returncode == 0 and run("plant", "--help").returncode == 0,
            "ecu/plant --help exit 0")
    print("RESULT: %d passed, %d failed" % (c.passed, c.failed))
    return 0 if c.failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
