# SPDX-License-Identifier: MIT
"""End-to-end harness of the vehicle layouts, shared by
test_vehicle_e2e.py and test_vehicle_unseen.py:

  drive (gen_drive.py, canmatrix) -> calibration (tools/vehicle_calib.py from
  the DBC only) -> `squeal-sim replay LOG --calib car.cal` -> each corner's
  SquealStatus / SquealDetail / SquealDetail2 decoded with canmatrix from
  firmware/protocol/squeal.dbc (identifiers 0x300.. + 0x10 k) ->
    - V0_mps and Force_N follow the vehicle's signals, decoded from the log
      with canmatrix and converted here with the conversions of docs/vehicle.md;
    - SquealState equals the scipy reference (tests/reference) at the
      converted operating points, away from borders (debounce, hysteresis)
      and after start-up;
    - no FAULT after start-up: the inputs are used.
A second run of the same drive with a 2.8 s backward timestamp jump must be
replayed as a new segment (reported in the summary) without squeezing: the
corner's status frames cover the whole drive.
A layout whose calibration checks E2E P05 (p05_checked: CAN FD): the summary's crc verdict of every
input of a P05 message is 0 on the clean drive, and above 0 (the others'
still 0) on the drive with one frame's CRC corrupted.

fake_replay() is a pure-Python stand-in for squeal-sim replay (the harness's
self-test): it applies the calibration text (vehref.reference_rows and the
conversions) and the reference model, and writes the output frames with
canmatrix.
"""
import os
import re
import sys
# tests/ of this checkout, and the folders its helper modules live in
_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, d) for d in ("support", os.path.join("support", "reference"), "host-sim", "tools")]

ROOT = os.path.dirname(_TESTS)
import vehref  # noqa: E402
import gen_drive  # noqa: E402
import squeal_reference as ref  # noqa: E402
from test_cmd_replay import parse_out  # noqa: E402  (t_us, iface, id, data) of candump -L text

V0_MIN_MPS = 0.01      # calibration defaults: below these, not sliding
FORCE_MIN_N = 100.0
STATUS_PERIOD_US = 10000
FAULT = 15
LINE = re.compile(r"^\((\d+)\.(\d{6})\) (\S+) ([0-9A-F]{3}|[0-9A-F]{8})#(#[0-9A-F])?((?:[0-9A-F]{2})*)$")
# a corner's input line of the replay summary: position, quantity, signal, frames, used, verdicts
INPUT_LINE = re.compile(r"^\s+(FL|FR|RL|RR) (\w+) (\S+): frames (\d+), used (\d+), rejected((?: \w+ \d+)*), "
                        r"stale events")


def ref_state(v0, force):
    if v0 < V0_MIN_MPS or force < FORCE_MIN_N:
        return 3
    return ref.STATE_CODE[ref.classify(ref.default_point(v0, force))["state"]]


def corner_index(pos):
    return vehref.POSITIONS.index(pos)


def expected_points(layout, db, frames):
    """{pos: [(t_us, v0, force)]} after every input frame of the corner,
    from canmatrix's decoding of the log and the conversions of docs/vehicle.md."""
    out = {}
    for pos, spd, frc, opts in layout["corners"]:
        area, eta, k = gen_drive.corner_params(opts)
        smsg, ssig = spd.split(".")
        fmsg, fsig = frc.split(".")
        sframe, fframe = db.frame_by_name(smsg), db.frame_by_name(fmsg)
        sunit = sframe.signal_by_name(ssig).unit
        funit = fframe.signal_by_name(fsig).unit
        v0 = force_v = None
        pts = []
        for t, cid, ext, data in frames:
            for frame, sig, role in ((sframe, ssig, "s"), (fframe, fsig, "f")):
                if cid != frame.arbitration_id.id or ext != bool(frame.arbitration_id.extended) \
                        or not gen_drive.is_message(frame, data):
                    continue
                dec = frame.decode(bytearray(data))
                if sig not in dec:
                    continue   # another multiplexer page
                phys = float(dec[sig].raw_value * dec[sig].signal.factor + dec[sig].signal.offset)
                if role == "s":
                    v0 = vehref.v0_of(phys, sunit)
                else:
                    force_v = (phys, funit)
            if v0 is not None and force_v is not None:
                n = vehref.force_of(force_v[0], force_v[1], v0, area, eta, k)
                pts.append((int(round(t * 1e6)), v0, n))
        out[pos] = pts
    return out


def at(pts, t_us, j):
    """Index of the last point at or before t_us (monotonic search from j)."""
    while j + 1 < len(pts) and pts[j + 1][0] <= t_us:
        j += 1
    return j


def check_corner(r, label, pos, pts, outf, sq, torque):
    k = corner_index(pos)
    status = sq.frame_by_name("SquealStatus")
    detail = sq.frame_by_name("SquealDetail")
    detail2 = sq.frame_by_name("SquealDetail2")
    sid, did, d2id = 0x300 + 0x10 * k, 0x301 + 0x10 * k, 0x303 + 0x10 * k
    if not r.check(len(pts) > 100, "%s %s: the drive has operating points (%d)" % (label, pos, len(pts))):
        return set()
    t0, t_end = pts[0][0], pts[-1][0]
    ref_at, changes, last = [], [], None
    for t_us, v, f in pts:
        s = ref_state(v, f)
        ref_at.append(s)
        if s != last:
            changes.append(t_us)
            last = s
    n_status = compared = faults = 0
    mismatched, seen = [], set()
    v0_bad, f_bad, n_detail, n_detail2 = [], [], 0, 0
    j = 0
    for t_us, _, cid, data in outf:
        if t_us < t0 + 300000 or t_us > t_end:
            continue   # start-up; the tail after the last input
        j = at(pts, t_us, j)
        if cid == sid:
            n_status += 1
            st = int(status.decode(bytearray(data))["SquealState"].raw_value)
            if st == FAULT:
                faults += 1
            if any(t_us - 300000 <= c <= t_us + 60000 for c in changes):
                continue
            compared += 1
            seen.add(ref_at[j])
            if st != ref_at[j]:
                mismatched.append(((t_us - t0) / 1e6, st, ref_at[j]))
        elif cid == did:
            n_detail += 1
            got = float(detail.decode(bytearray(data))["V0_mps"].phys_value)
            cands = [pts[i][1] for i in (j, max(0, j - 1), max(0, j - 2))]
            if not any(abs(got - v) <= 0.011 + 0.002 * v for v in cands):
                v0_bad.append(((t_us - t0) / 1e6, got, cands[0]))
        elif cid == d2id:
            n_detail2 += 1
            got = float(detail2.decode(bytearray(data))["Force_N"].phys_value)
            cands = [pts[i][2] for i in (j, max(0, j - 1), max(0, j - 2))]
            rel = 0.01 if torque else 0.002
            if not any(abs(got - f) <= 0.6 + rel * f for f in cands):
                f_bad.append(((t_us - t0) / 1e6, got, cands[0]))
    expect_status = (t_end - t0 - 300000) // STATUS_PERIOD_US
    r.check(n_status >= 0.9 * expect_status, "%s %s: status frames at 0x%X every 10 ms (%d of about %d)"
            % (label, pos, sid, n_status, expect_status))
    r.check(faults == 0, "%s %s: inputs used, no FAULT after start-up (%d of %d status frames)"
            % (label, pos, faults, n_status))
    r.check(compared > 0.5 * n_status and len(seen) >= 2,
            "%s %s: states compared away from borders (%d of %d, reference states %s)"
            % (label, pos, compared, n_status, sorted(seen)))
    r.check(not mismatched, "%s %s: SquealState equals the reference at the converted points "
            "(%d mismatches, first (t, got, ref) %s)" % (label, pos, len(mismatched), mismatched[:4]))
    r.check(n_detail > 50 and not v0_bad, "%s %s: V0_mps follows the wheel speed (%d frames, %d off, first "
            "(t, got, expected) %s)" % (label, pos, n_detail, len(v0_bad), v0_bad[:3]))
    r.check(n_detail2 > 50 and not f_bad, "%s %s: Force_N follows the vehicle's force signal (%d frames, %d off, "
            "first (t, got, expected) %s)" % (label, pos, n_detail2, len(f_bad), f_bad[:3]))
    return seen


def stem(label):
    return re.sub(r"\W+", "_", label).strip("_")


def build_calib(r, label, layout, tmp, drive_log):
    cal = os.path.join(tmp, stem(label) + ".cal")
    log = drive_log if layout["period_from"] == "log" else None
    rc, _, err = vehref.run_tool(vehref.calib_command(layout, log=log, out=cal))
    if not r.check(rc == 0, "%s: vehicle_calib.py builds the calibration from the DBC: %s" % (label, err.strip())):
        return None
    return cal


def run_layout(r, label, layout, tmp, replay, seed=7):
    db = vehref.load_dbc(vehref.layout_dbc(layout))
    sq = vehref.load_dbc(vehref.SQUEAL_DBC)
    frames = gen_drive.Drive(layout, seed=seed).frames()
    log = os.path.join(tmp, stem(label) + ".log")
    gen_drive.write_log(log, frames)
    cal = build_calib(r, label, layout, tmp, log)
    if cal is None:
        return
    rc, out, err = replay(log, cal)
    if rc != 0:
        vehref.sim_missing(r, "%s: replay %s --calib %s" % (label, os.path.basename(log), os.path.basename(cal)),
                           rc, err)
        return
    if layout.get("p05_checked"):
        check_p05(r, label, layout, db, tmp, replay, frames, cal, err)
    outf = parse_out(out.decode())
    pts = expected_points(layout, db, frames)
    seen = set()
    for pos, spd, frc, opts in layout["corners"]:
        unit = db.frame_by_name(frc.split(".")[0]).signal_by_name(frc.split(".")[1]).unit
        seen |= check_corner(r, label, pos, pts[pos], outf, sq, unit.lower() == "nm")
    r.check(seen == {0, 1, 2, 3}, "%s: the states compared cover stable, bistable, unstable and not "
            "sliding (%s)" % (label, sorted(seen)))

    # the same drive with the logger's 2.8 s jump back
    jframes = gen_drive.Drive(layout, seed=seed, jump=True).frames()
    jlog = os.path.join(tmp, stem(label) + "-jump.log")
    gen_drive.write_log(jlog, jframes)
    rc, out, err = replay(jlog, cal)
    if rc != 0:
        vehref.sim_missing(r, "%s: replay of the drive with a backward jump" % label, rc, err)
        return
    seg = re.search(r"^.*(?:segment|backward|time.?jump).*?(\d+).*$", err, re.I | re.M)
    r.check(seg is not None and int(seg.group(1)) >= 1,
            "%s: the 2.8 s jump back is reported as a new segment in the summary (%s)"
            % (label, seg.group(0).strip() if seg else "no 'segment' line"))
    outj = parse_out(out.decode())
    drive_us = int(round((frames[-1][0] - frames[0][0]) * 1e6))
    for pos, _, _, _ in layout["corners"]:
        sid = 0x300 + 0x10 * corner_index(pos)
        st = [int(sq.frame_by_name("SquealStatus").decode(bytearray(d))["SquealState"].raw_value)
              for _, _, c, d in outj if c == sid]
        r.check(len(st) >= 0.9 * drive_us // STATUS_PERIOD_US,
                "%s %s, jump: status frames cover the whole drive, nothing squeezed (%d of about %d)"
                % (label, pos, len(st), drive_us // STATUS_PERIOD_US))
        r.check(st and st.count(FAULT) <= 0.05 * len(st),
                "%s %s, jump: inputs used across the jump (%d FAULT of %d)" % (label, pos, st.count(FAULT), len(st)))


def input_verdicts(err):
    """{(pos, quantity): (signal, frames, used, {verdict: count})} of a replay summary."""
    out = {}
    for line in err.splitlines():
        m = INPUT_LINE.match(line)
        if m:
            v = m.group(6).split()
            out[(m.group(1), m.group(2))] = (m.group(3), int(m.group(4)), int(m.group(5)),
                                             {a: int(b) for a, b in zip(v[::2], v[1::2])})
    return out


def p05_inputs(layout):
    """[(pos, quantity, message)] of the corners' inputs in P05 messages."""
    out = []
    for pos, spd, frc, _ in layout["corners"]:
        for q, ref in (("speed", spd), ("force", frc)):
            if ref.split(".")[0] in layout["p05_checked"]:
                out.append((pos, q, ref.split(".")[0]))
    return out


def check_p05(r, label, layout, db, tmp, replay, frames, cal, err):
    """crc verdicts: 0 on the clean drive, > 0 with one CRC corrupted."""
    got = input_verdicts(err)
    mine = p05_inputs(layout)
    for pos, q, msg in mine:
        v = got.get((pos, q))
        r.check(v is not None and v[2] > 0 and v[3].get("crc") == 0,
                "%s %s %s: P05 checked, no crc verdict on the clean drive (%s)" % (label, pos, q, v))
    msg = mine[0][2]
    f = db.frame_by_name(msg)
    hit = next(k for k, (t, cid, ext, d) in enumerate(frames) if cid == f.arbitration_id.id
               and ext == bool(f.arbitration_id.extended) and t > frames[0][0] + 1.0
               and gen_drive.is_message(f, d))
    t, cid, ext, d = frames[hit]
    bad = bytearray(d)
    off = layout["p05"][msg][0][1]
    bad[off] ^= 0x01
    bad = gen_drive.fd_data(bad, d.flags) if isinstance(d, gen_drive.FdData) else bytes(bad)
    blog = os.path.join(tmp, stem(label) + "-badcrc.log")
    gen_drive.write_log(blog, frames[:hit] + [(t, cid, ext, bad)] + frames[hit + 1:])
    rc, _, berr = replay(blog, cal)
    if rc != 0:
        vehref.sim_missing(r, "%s: replay of the drive with one corrupted CRC" % label, rc, berr)
        return
    got = input_verdicts(berr)
    for pos, q, m in mine:
        v = got.get((pos, q))
        want = (lambda n: n > 0) if m == msg else (lambda n: n == 0)
        r.check(v is not None and want(v[3].get("crc", -1)),
                "%s %s %s: one corrupted CRC of %s %s (%s)" % (label, pos, q, msg,
                                                               "is a crc verdict" if m == msg else "not counted here", v))


def sim_replay(log, cal):
    return vehref.run_sim(["replay", log, "--calib", cal])


# ------------------------------------------------------------ self-test stand-in

def p05_ok(inp, data):
    """The frame's P05 CRC (little-endian at e2e_offset_byte) is right for the input's Data ID."""
    off = vehref.ival(inp, "e2e_offset_byte", 0)
    return vehref.p05_crc(data, vehref.ival(inp, "data_id"), off) == data[off] | data[off + 1] << 8


def fake_replay(log, cal):
    """squeal-sim replay as the harness expects it, from the calibration text,
    vehref's extraction and conversions and the reference model: status every
    10 ms, details every 100 ms, no debounce; a jump back > 1 s re-bases."""
    import can  # noqa: F401  (same environment as the real test)
    with open(cal) as f:
        flat, inputs, corners = vehref.parse_calib(f.read())
    sq = vehref.load_dbc(vehref.SQUEAL_DBC)
    frames, base, last_t, segments = [], 0, None, 0
    with open(log) as f:
        for line in f:
            m = LINE.match(line.strip())
            t = int(m.group(1)) * 1000000 + int(m.group(2)) + base
            if last_t is not None and t < last_t - 1000000:
                base += last_t - t + 1000
                t = last_t + 1000
                segments += 1
            last_t = t
            data = bytes.fromhex(m.group(6))
            if m.group(5):
                data = gen_drive.fd_data(data, int(m.group(5)[1], 16))
            frames.append((t, int(m.group(4), 16), len(m.group(4)) == 8, data))
    values = {}
    out = []
    next_status = frames[0][0] + STATUS_PERIOD_US
    tick = 0

    def emit(t):
        nonlocal tick
        for pos, c in corners.items():
            k = corner_index(pos)
            sv, fv = values.get(c["speed"]), values.get(c["force"])
            if sv is None or fv is None:
                state, v0, n = FAULT, 0.0, 0.0
            else:
                v0 = vehref.v0_of(sv, inputs[c["speed"]]["unit"], float(flat.get("wheel_radius_m", 0.3)))
                n = vehref.force_of(fv, inputs[c["force"]]["unit"], v0, float(c.get("piston_area_mm2", 0)),
                                    float(c.get("efficiency", 1)), float(c.get("axle_factor", 1)))
                state = ref_state(v0, n)
            data = sq.frame_by_name("SquealStatus").encode({"SquealState": state})
            out.append((t, 0x300 + 0x10 * k, bytes(data)))
            if tick % 10 == 0:
                out.append((t, 0x301 + 0x10 * k, bytes(sq.frame_by_name("SquealDetail").encode(
                    {"V0_mps": int(round(v0 / 0.01))}))))
                out.append((t, 0x303 + 0x10 * k, bytes(sq.frame_by_name("SquealDetail2").encode(
                    {"Force_N": int(round(n / 0.5))}))))
        tick += 1

    verdicts = {}   # input -> [frames, used, dlc, crc]
    for t, cid, ext, data in frames:
        while next_status <= t:
            emit(next_status)
            next_status += STATUS_PERIOD_US
        for _, _, name, raw, phys, reason in vehref.reference_rows(inputs, [("", cid, ext, data)]):
            inp = inputs[name]
            if reason == "ok" and inp.get("protection") == "p05" and not p05_ok(inp, data):
                reason = "crc"
            v = verdicts.setdefault(name, [0, 0, 0, 0])
            v[0] += 1
            v[1] += reason == "ok"
            v[2] += reason == "dlc"
            v[3] += reason == "crc"
            if reason == "ok":
                values[name] = phys
    text = "".join("(%010d.%06d) can0 %03X#%s\n" % (t // 1000000, t % 1000000, c, d.hex().upper())
                   for t, c, d in out)
    summary = "replay summary\n  segments %d\n" % (segments + 1)
    for pos, c in corners.items():
        for q in ("speed", "force"):
            v = verdicts.get(c[q], [0, 0, 0, 0])
            summary += "    %s %s %s: frames %d, used %d, rejected dlc %d crc %d, stale events 0\n" % (
                pos, q, inputs[c[q]].get("signal", c[q]), v[0], v[1], v[2], v[3])
    return 0, text.encode(), summary


def main(argv, layouts):
    """Run layouts [(label, layout, seed)] on every squeal-sim build (or on
    fake_replay with --self-test); print RESULT and exit."""
    import tempfile
    self_test = "--self-test" in argv
    replay = fake_replay if self_test else sim_replay
    r = vehref.Results()
    with tempfile.TemporaryDirectory() as tmp:
        for sim in [None] if self_test else vehref.SIMS:
            vehref.SIM = sim
            if sim is not None:
                vehref.use_checker(sim)
            for name, layout, seed in layouts:
                label = name if sim is None else "%s (%s)" % (name, os.path.basename(os.path.dirname(sim)))
                run_layout(r, label, layout, tmp, replay, seed)
    r.finish()
