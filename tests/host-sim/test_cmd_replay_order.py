#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""`squeal-sim replay` on logs whose time is not simple, on logs of several
interfaces, and its summary in the vehicle's words. Every log is generated
here (our own drives, E2E computed here from squeal.dbc's data IDs; for the
input map our own DBC text, encoded with canmatrix), in the layouts real
loggers write:

  - a block of 2.8 s written 3 s late, and many small blocks written 2.8 s
    late (the pattern of a logger that flushes its buffers out of order):
    put back in order, counted, never turned into silence; the replay equals
    the replay of the same frames in time order, byte for byte, and its
    virtual time is the drive's;
  - two logger restarts in one log (one beyond the reorder window, one
    within it): three segments, re-based so that every frame keeps its
    spacing; the virtual times of the rebase points and of the end are
    derived by hand;
  - a gap just below --max-gap is simulated (the ECU sends on, the inputs go
    stale), one just above is skipped (nothing sent inside it);
  - the input identifiers on two interfaces: without a choice the first is
    taken, said once, the other's frames counted; --bus and the
    calibration's input_iface choose;
  - the summary names each input by corner, quantity and DBC signal, and
    counts the rejected frames by the input stage's reasons as the log was
    made (bad DLC, not available, out of range), text and JSON;
  - decode --calib names every corner's output messages.
Prints "RESULT: N passed, M failed".
"""
import io
import json
import os
import re
import subprocess
import sys
import tempfile
from decimal import Decimal
# tests/ of this checkout, and the folders its helper modules live in
_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, d) for d in ("support", os.path.join("support", "reference"), "host-sim", "tools")]

ROOT = os.path.dirname(_TESTS)

import gen_inputs  # noqa: E402
from dbc_common import Results  # noqa: E402
from sim_cli import SAN_SIMS  # noqa: E402

SIM, SIM_FIXED = SAN_SIMS["float"], SAN_SIMS["fixed"]
LINE = re.compile(r"^\((\d+)\.(\d{6})\) (\S+) ([0-9A-F]{3})#([0-9A-F]*)$")


R = Results()


def run(args, sim=SIM, stdin=None):
    p = subprocess.run([sim] + args, input=stdin, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    return p.returncode, p.stdout.decode(), p.stderr.decode()


def value(err, key):
    m = re.search(r"^\s+" + re.escape(key) + r"\s+(\d+(?:\.\d+)?)", err, re.M)
    return None if m is None else m.group(1)


def out_frames(text):
    res = []
    for ln in text.splitlines():
        m = LINE.match(ln)
        assert m is not None, ln
        res.append((int(m.group(1)) * 1000000 + int(m.group(2)), m.group(3), int(m.group(4), 16),
                    bytes.fromhex(m.group(5))))
    return res


def stamp(t_us, iface, cid, data):
    return "(%010d.%06d) %s %03X#%s" % (t_us // 1000000, t_us % 1000000, iface, cid, data.hex().upper())


def drive(enc, t0_us, seconds, iface="can0", v0=6.0, force=3000.0):
    """DiscSpeed at t, PadForce at t + 5 ms, every 10 ms: [(t_us, line)]."""
    out = []
    for k in range(int(round(seconds * 100))):
        t = t0_us + k * 10000
        out.append((t, stamp(t, iface, enc.speed_id, enc.frame(enc.speed_id, enc.speed_raw(v0)))))
        out.append((t + 5000, stamp(t + 5000, iface, enc.force_id,
                                    enc.frame(enc.force_id, enc.force_raw(force)))))
    return out


def write(path, lines):
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def summary_json(args, sim=SIM):
    rc, so, err = run(args + ["--no-output", "--summary-json", "-"], sim=sim)
    return rc, json.loads(so, parse_float=Decimal), err


# ---------------------------------------------------------------------------

def test_late_block(tmp, db):
    """20 s of drive; the frames of [8.0, 10.8) s written after those up to
    11.0 s: a jump back of 3.0 s, the block's 560 frames, a return."""
    enc = gen_inputs.InputEncoder(db)
    t0 = 1000 * 1000000
    fr = drive(enc, t0, 20.0)
    block = [x for x in fr if t0 + 8000000 <= x[0] < t0 + 10800000]
    rest = [x for x in fr if not (t0 + 8000000 <= x[0] < t0 + 10800000)]
    at = max(i for i, x in enumerate(rest) if x[0] < t0 + 11000000) + 1
    late = rest[:at] + block + rest[at:]
    pl = os.path.join(tmp, "late.log")
    ps = os.path.join(tmp, "late-sorted.log")
    write(pl, [x[1] for x in late])
    write(ps, [x[1] for x in fr])
    for sim in (SIM, SIM_FIXED):
        rc, so, err = run(["replay", pl], sim=sim)
        rc2, so2, err2 = run(["replay", ps], sim=sim)
        R.check(rc == 0 and rc2 == 0 and so == so2 and so != "",
                "late block: the same output as the log in time order (%s)" % os.path.basename(os.path.dirname(sim)))
    R.check(value(err, "reordered") == str(len(block)) and
            re.search(r"blocks written out of order: 1;", err) is not None,
            "late block: its %d frames counted as reordered, one block (%s)" % (len(block), value(err, "reordered")))
    line = at + 1
    R.check(re.search(r"^%s:%d: timestamp goes back by 2\.995000 s and returns at line %d: a block of %d frames"
                      % (re.escape(pl), line, line + len(block), len(block)), err, re.M) is not None,
            "late block: reported once with its lines")
    # back from the last frame before it (10.995 s) to 8.000 s
    # the drive's frames span 19.995 s; the replay ends with the tick after the last
    R.check(value(err, "virtual_time_s") == "19.996000" and value(err, "segments") == "1" and
            value(err, "time_backwards") == "0" and value(err, "gaps_skipped") == "0",
            "late block: virtual time 19.996 s, one segment, nothing late (%s)" % value(err, "virtual_time_s"))
    st = dict(re.findall(r"(\w+)=([\d.]+)", re.search(r"state_time_s(.*)", err).group(1)))
    R.check(Decimal(st["fault"]) < Decimal("0.02"),
            "late block: no FAULT made from invented silence (fault %s s)" % st["fault"])
    rc, doc, _ = summary_json(["replay", pl])
    R.check(doc["reordered"] == {"frames": len(block), "blocks": 1, "window_s": Decimal("5"),
                                 "window_frames": 32768},
            "late block: JSON reordered %s" % doc["reordered"])


def test_small_blocks(tmp, db):
    """30 s of drive; every 1.05 s the 0.1 s block from T written after the
    frames up to T + 2.8 s (what a logger flushing out of order writes)."""
    enc = gen_inputs.InputEncoder(db)
    t0 = 50 * 1000000
    fr = drive(enc, t0, 30.0)
    starts = [t0 + 1000000 + k * 1050000 for k in range(24)]
    blocks = {s: [x for x in fr if s <= x[0] < s + 100000] for s in starts}
    moved = {x[0] for b in blocks.values() for x in b}
    lines = []
    pending = sorted(starts)
    for x in fr:
        while pending and x[0] >= pending[0] + 2800000:
            lines += [y[1] for y in blocks[pending.pop(0)]]
        if x[0] not in moved:
            lines.append(x[1])
    p = os.path.join(tmp, "small.log")
    ps = os.path.join(tmp, "small-sorted.log")
    write(p, lines)
    write(ps, [x[1] for x in fr])
    rc, so, err = run(["replay", p])
    rc2, so2, _ = run(["replay", ps])
    n = sum(len(b) for b in blocks.values())
    R.check(rc == 0 and so == so2, "small blocks: the same output as the log in time order")
    R.check(value(err, "reordered") == str(n) and
            re.search(r"blocks written out of order: %d;" % len(starts), err) is not None,
            "small blocks: %d frames in %d blocks reordered (%s)" % (n, len(starts), value(err, "reordered")))
    R.check(value(err, "virtual_time_s") == "29.996000" and value(err, "segments") == "1",
            "small blocks: virtual time 29.996 s (the drive's), one segment (%s, %s)"
            % (value(err, "virtual_time_s"), value(err, "segments")))


def test_two_restarts(tmp, db):
    """A: 100.000..109.995 s; B restarts at 0 (back 109.995 s, beyond the
    window: re-based onto 109.995); C restarts at 2.000 (109.995 + 2.000 =
    111.995, back 2.995 s from 114.990, within the window, and goes on past
    it: re-based onto 114.990). The last frame, C's 7.995, is at
    7.995 + 109.995 + 2.995 = 120.985 s; the end is its tick, 120.986 s."""
    enc = gen_inputs.InputEncoder(db)
    a = drive(enc, 100 * 1000000, 10.0)
    b = drive(enc, 0, 5.0)
    c = drive(enc, 2 * 1000000, 6.0)
    p = os.path.join(tmp, "restarts.log")
    write(p, [x[1] for x in a + b + c])
    rc, so, err = run(["replay", p])
    R.check(rc == 0 and value(err, "segments") == "3", "two restarts: three segments (%s)" % value(err, "segments"))
    R.check(value(err, "virtual_time_s") == "20.986000",
            "two restarts: virtual time 20.986 s (%s)" % value(err, "virtual_time_s"))
    msgs = re.findall(r":(\d+): timestamp goes back by ([\d.]+) s: new segment (\d+)", err)
    R.check(msgs == [(str(len(a) + 1), "109.995000", "2"), (str(len(a) + len(b) + 1), "2.995000", "3")],
            "two restarts: reported at their lines with their jumps %s" % msgs)
    rc, doc, _ = summary_json(["replay", p])
    R.check(doc["segments"]["rebase_points"] ==
            [{"segment": 2, "line": len(a) + 1, "back_s": Decimal("109.995"), "at_s": Decimal("109.995")},
             {"segment": 3, "line": len(a) + len(b) + 1, "back_s": Decimal("2.995"),
              "at_s": Decimal("114.99")}],
            "two restarts: rebase points %s" % doc["segments"]["rebase_points"])
    # every frame keeps its spacing: the ECU's status every 10 ms throughout,
    # the inputs never stale
    st = [f[0] for f in out_frames(so) if f[2] == 0x300]
    gaps = [y - x for x, y in zip(st, st[1:])]
    R.check(st[0] < 100020000 and st[-1] >= 120970000 and max(gaps) <= 10000,
            "two restarts: SquealStatus every 10 ms from 100.0 to 120.98 s (largest gap %d us)" % max(gaps))
    R.check(value(err, "stale_events") == "0" and doc["reordered"]["frames"] == 0,
            "two restarts: no input stale, nothing reordered")


def test_gaps(tmp, db):
    """3 s of drive, a gap, 3 s of drive, with --max-gap 2: a gap of 1.99 s
    (just below) is simulated, one of 2.01 s (just above) skipped."""
    for gap_us, simulated in ((1990000, True), (2010000, False)):
        enc = gen_inputs.InputEncoder(db)
        one = drive(enc, 10 * 1000000, 3.0)
        last = one[-1][0]
        two = drive(enc, last + gap_us, 3.0)  # the first DiscSpeed gap_us after the last PadForce
        p = os.path.join(tmp, "gap.log")
        write(p, [x[1] for x in one + two])
        rc, so, err = run(["replay", "--max-gap", "2", p])
        inside = [f for f in out_frames(so) if last + 10000 < f[0] < two[0][0]]
        states = {db.frame_by_name("SquealStatus").decode(bytearray(f[3]))["SquealState"].raw_value
                  for f in inside if f[2] == 0x300}
        what = "gap %.2f s with --max-gap 2" % (gap_us / 1e6)
        if simulated:
            R.check(rc == 0 and value(err, "gaps_skipped") == "0", what + ": simulated, not skipped")
            R.check(len([f for f in inside if f[2] == 0x300]) >= 190 and 15 in states,
                    what + ": the ECU sends on through it and goes FAULT (%d status frames, states %s)"
                    % (len(inside), sorted(states)))
            R.check(value(err, "stale_events") == "2", what + ": both inputs went stale")
        else:
            R.check(rc == 0 and value(err, "gaps_skipped") == "1" and
                    re.search(r"gap of 2\.010000 s > --max-gap: skipped", err) is not None,
                    what + ": skipped and reported")
            R.check(inside == [], what + ": nothing sent inside it (%d frames)" % len(inside))
        # the time of the gap passes either way
        R.check(value(err, "virtual_time_s") == "%d.%06d" % divmod(two[-1][0] - one[0][0] + 1000, 1000000),
                what + ": virtual time first to last frame (%s)" % value(err, "virtual_time_s"))


def test_buses(tmp, db):
    """The inputs on can0; another ECU's copy of the PadForce identifier on
    can1 (force 0, every 20 ms), and other traffic on can1."""
    enc = gen_inputs.InputEncoder(db)
    main = drive(enc, 5 * 1000000, 6.0)
    other = gen_inputs.InputEncoder(db)
    noise = []
    for k in range(300):
        t = 5 * 1000000 + 2000 + k * 20000
        noise.append((t, stamp(t, "can1", other.force_id, other.frame(other.force_id, other.force_raw(0.0)))))
        noise.append((t + 1000, stamp(t + 1000, "can1", 0x7E0, b"\x01\x02")))
    both = sorted(main + noise, key=lambda x: x[0])
    p = os.path.join(tmp, "buses.log")
    p0 = os.path.join(tmp, "bus0.log")
    write(p, [x[1] for x in both])
    write(p0, [x[1] for x in main])
    _, want, _ = run(["replay", p0])
    rc, so, err = run(["replay", p])
    first = [x[1] for x in both].index(noise[0][1]) + 1
    R.check(rc == 0 and so == want, "two interfaces, no choice: the inputs of can0 (the first), same output")
    R.check(re.findall(r"input identifiers arrive on (\S+) and (\S+) \(0x(\w+) here\): the inputs are taken from (\S+)",
                       err) == [("can0", "can1", "%X" % enc.force_id, "can0")] and
            ("%s:%d: the input identifiers" % (p, first)) in err,
            "two interfaces: said once, at the first other interface's input frame")
    R.check(value(err, "other_iface_inputs") == "300",
            "two interfaces: the 300 input frames of can1 ignored and counted (%s)" % value(err, "other_iface_inputs"))
    rc, doc, _ = summary_json(["replay", p])
    R.check(doc["buses"] == {"input_iface": "can0", "chosen_by": "first_input_frame",
                             "interfaces": ["can0", "can1"], "interfaces_with_inputs": ["can0", "can1"],
                             "other_iface_inputs": 300, "other_bus": 0},
            "two interfaces: JSON buses %s" % doc["buses"])
    rc, so, err = run(["replay", "--bus", "can0", p])
    R.check(rc == 0 and so == want and value(err, "other_bus") == "600" and "arrive on" not in err,
            "--bus can0: the same output, can1's 600 frames on the unused bus")
    cal = os.path.join(tmp, "iface.cal")
    with open(cal, "w") as f:
        f.write("input_iface = can0\n")
    rc, so, err = run(["replay", "--calib", cal, p])
    R.check(rc == 0 and so == want and value(err, "other_bus") == "600" and
            re.search(r"input_iface\s+can0 \(calibration\)", err) is not None,
            "input_iface = can0: the same as --bus can0")
    with open(cal, "w") as f:
        f.write("input_iface = can1\n")
    rc, so, err = run(["replay", "--calib", cal, "--bus", "can0", p])
    R.check(rc == 0 and so == want and re.search(r"input_iface\s+can0 \(--bus\)", err) is not None,
            "--bus can0 overrides input_iface = can1")
    rc, so, err = run(["replay", "--calib", cal, p])
    used = re.search(r"frames_used\s+\d+ \(DiscSpeed (\d+), PadForce (\d+)\)", err)
    R.check(rc == 0 and used is not None and used.groups() == ("0", "300"),
            "input_iface = can1: only can1's 300 PadForce frames used (%s)" % (used and used.groups(),))
    # decode: the calibration's interface unless --bus says otherwise
    with open(cal, "w") as f:
        f.write("input_iface = can1\n")
    def frame_lines(text):
        return [ln for ln in text.splitlines() if not ln.startswith(" ")]
    rc, so, _ = run(["decode", "--calib", cal, p])
    R.check(rc == 0 and len(frame_lines(so)) == 600, "decode --calib (input_iface can1): can1's 600 frames")
    rc, so, _ = run(["decode", "--calib", cal, "--bus", "can0", p])
    R.check(rc == 0 and len(frame_lines(so)) == len(main), "decode --bus can0 overrides input_iface")


# Our own vehicle layout: wheel speeds and a brake pressure, no protection.
OWN_DBC = """VERSION ""
NS_ :
BS_:
BU_: ABS ESC
BO_ 416 ABS_1: 8 ABS
 SG_ WHEEL_SPEED_FL : 7|16@0+ (0.01,0) [0|655.35] "km/h" ESC
 SG_ WHEEL_SPEED_FR : 23|16@0+ (0.01,0) [0|655.35] "km/h" ESC
BO_ 432 BRAKE_2: 8 ESC
 SG_ BRAKE_PRESSURE : 0|12@1+ (0.1,0) [0|409.5] "bar" ABS
"""

OWN_CAL = """# our own layout (ABS_1 0x1A0, BRAKE_2 0x1B0)
[input wheel_fl]
id = 0x1A0
min_dlc = 8
start_bit = 7
length = 16
byte_order = motorola
factor = 0.01
unit = km/h
na_raw = 0xFFFF
period_ms = 10
min = 0
max = 300
step_max = 300
signal = ABS_1.WHEEL_SPEED_FL
[input brake]
id = 0x1B0
start_bit = 0
length = 12
byte_order = intel
factor = 0.1
unit = bar
period_ms = 10
min = 0
max = 200
step_max = 300
[corner FL]
speed = wheel_fl
force = brake
piston_area_mm2 = 2000
"""


def test_names(tmp):
    import canmatrix.formats
    db = canmatrix.formats.loads_flat(OWN_DBC, "dbc")
    abs1 = db.frame_by_name("ABS_1")
    brk = db.frame_by_name("BRAKE_2")
    lines = []
    expect = {"dlc": 0, "na": 0, "range": 0}
    used = {"speed": 0, "force": 0}
    for k in range(400):
        t = 20 * 1000000 + k * 10000
        # canmatrix's encode takes raw values: 40 km/h is 4000
        data = bytes(abs1.encode({"WHEEL_SPEED_FL": 4000, "WHEEL_SPEED_FR": 4000}))
        if k in (100, 200, 300):
            data = data[:5]
            expect["dlc"] += 1
        elif k in (150, 250):
            data = b"\xff\xff" + data[2:]
            expect["na"] += 1
        else:
            used["speed"] += 1
        lines.append(stamp(t, "can0", 0x1A0, data))
        bar = 20.0
        if k in (120, 220):
            bar = 300.0  # beyond max = 200 bar
            expect["range"] += 1
        else:
            used["force"] += 1
        lines.append(stamp(t + 5000, "can0", 0x1B0,
                           bytes(brk.encode({"BRAKE_PRESSURE": int(round(bar * 10))}))))
    p = os.path.join(tmp, "own.log")
    write(p, lines)
    cal = os.path.join(tmp, "own.cal")
    with open(cal, "w") as f:
        f.write(OWN_CAL)
    rc, so, err = run(["replay", "--calib", cal, p])
    sp = re.search(r"^    FL speed ABS_1\.WHEEL_SPEED_FL: frames (\d+), used (\d+), rejected(.*), stale", err, re.M)
    fo = re.search(r"^    FL force brake: frames (\d+), used (\d+), rejected(.*), stale", err, re.M)
    R.check(rc == 0 and sp is not None and fo is not None,
            "names: FL speed by its DBC signal, FL force by its section's name")
    if sp is None or fo is None:
        return
    rs = dict((k, int(v)) for k, v in re.findall(r" (\w+) (\d+)", sp.group(3)))
    rf = dict((k, int(v)) for k, v in re.findall(r" (\w+) (\d+)", fo.group(3)))
    R.check(int(sp.group(1)) == 400 and int(sp.group(2)) == used["speed"] and
            rs.get("dlc") == 3 and rs.get("na") == 2 and sum(rs.values()) == 5,
            "names: the speed's 3 bad DLC and 2 not available frames by reason %s" % rs)
    R.check(int(fo.group(1)) == 400 and int(fo.group(2)) == used["force"] and
            rf.get("range") == 2 and sum(rf.values()) == 2,
            "names: the force's 2 frames beyond its range %s" % rf)
    R.check(re.search(r"frames_used\s+\d+ \(FL speed ABS_1\.WHEEL_SPEED_FL \d+, FL force brake \d+\)", err)
            is not None, "names: the totals in the vehicle's words, not DiscSpeed/PadForce")
    R.check(re.search(r"^  corner FL\s+final \w+, time stable [\d.]+ % bistable", err, re.M) is not None and
            re.search(r"^    fault time:.*FL force brake implausible 0\.0\d+ s", err, re.M) is not None,
            "names: share of time per state, and FAULT time by input and reason")
    rc, doc, _ = summary_json(["replay", "--calib", cal, p])
    c = doc["inputs_by_corner"]
    R.check(len(c) == 1 and c[0]["corner"] == "FL" and
            c[0]["speed"]["label"] == "FL speed ABS_1.WHEEL_SPEED_FL" and
            c[0]["force"]["label"] == "FL force brake" and
            c[0]["speed"]["rejected"] == {"dlc": 3, "na": 2, "qualifier": 0, "crc": 0, "counter": 0,
                                          "repeated": 0, "range": 0, "step": 0} and
            c[0]["force"]["rejected"]["range"] == 2 and
            c[0]["speed"]["used"] == used["speed"] and
            sum(c[0]["state_share"].values()) in (Decimal("0.999999"), Decimal("1"), Decimal("1.000001")),
            "names: JSON inputs_by_corner %s" % json.dumps(c, default=str)[:300])
    R.check(doc["frames_used"]["DiscSpeed"] == used["speed"],
            "names: the JSON's existing keys stay (frames_used.DiscSpeed is corner 0's speed)")


def test_decode_corners(tmp):
    """decode --calib names each corner's output messages: FL sends the DBC's
    identifiers (0x300..0x303), FR the default next block (0x310..0x313);
    each corner's E2E counters are followed on their own."""
    import canmatrix.formats
    db = canmatrix.formats.loads_flat(OWN_DBC, "dbc")
    abs1 = db.frame_by_name("ABS_1")
    brk = db.frame_by_name("BRAKE_2")
    lines = []
    for k in range(100):
        t = 30 * 1000000 + k * 10000
        lines.append(stamp(t, "can0", 0x1A0, bytes(abs1.encode({"WHEEL_SPEED_FL": 4000, "WHEEL_SPEED_FR": 4000}))))
        lines.append(stamp(t + 5000, "can0", 0x1B0, bytes(brk.encode({"BRAKE_PRESSURE": 200}))))
    p = os.path.join(tmp, "corners-in.log")
    write(p, lines)
    cal = os.path.join(tmp, "corners.cal")
    with open(cal, "w") as f:
        f.write(OWN_CAL + "[corner FR]\nspeed = wheel_fl\nforce = brake\npiston_area_mm2 = 2000\n")
    rc, so, _ = run(["replay", "--calib", cal, p])
    out = os.path.join(tmp, "corners-out.log")
    with open(out, "w") as f:
        f.write(so)
    rc2, txt, _ = run(["decode", "--calib", cal, out])
    want = {0x300: "SquealStatus[FL]", 0x301: "SquealDetail[FL]", 0x302: "SquealDiag[FL]",
            0x303: "SquealDetail2[FL]", 0x310: "SquealStatus[FR]", 0x311: "SquealDetail[FR]",
            0x312: "SquealDiag[FR]", 0x313: "SquealDetail2[FR]"}
    frames = out_frames(so)
    names = [ln.split(" ")[1] for ln in txt.splitlines() if not ln.startswith(" ")]
    R.check(rc == 0 and rc2 == 0 and len(names) == len(frames) and
            all(want.get(f[2]) == n for f, n in zip(frames, names)) and
            {f[2] for f in frames} == set(want),
            "decode --calib: every output frame named by message and corner (%s)" % sorted(set(names)))
    e2e = [ln.rsplit("e2e=", 1)[1] for ln in txt.splitlines() if "e2e=" in ln]
    R.check(len(e2e) == len(frames) and set(e2e) <= {"initial", "ok"} and e2e.count("initial") == 8,
            "decode --calib: each corner's counters followed on their own (%s)" % sorted(set(e2e)))


def main():
    db = gen_inputs.load_dbc()
    with tempfile.TemporaryDirectory() as tmp:
        test_late_block(tmp, db)
        test_small_blocks(tmp, db)
        test_two_restarts(tmp, db)
        test_gaps(tmp, db)
        test_buses(tmp, db)
        test_names(tmp)
        test_decode_corners(tmp)
    print("RESULT: %d passed, %d failed" % (R.passed, R.failed))
    return 0 if R.failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
