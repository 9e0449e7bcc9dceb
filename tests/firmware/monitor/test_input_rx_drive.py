#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""A braking drive in each fixture vehicle layout (tests/firmware/monitor/fixtures/*.cal),
end to end through the host programs:

    squeal-sim plant --calib CAR --scenario DRIVE --log in.log
    squeal-sim replay --calib CAR in.log > out.log

At the end of every hold of the drive, for every corner of the layout:
  - the monitor's operating point (SquealDetail.V0_mps, SquealDetail2.Force_N
    of that corner's identifiers, decoded with canmatrix from squeal.dbc)
    equals the one derived HERE from the drive, the calibration file and the
    conversions of docs/vehicle.md (the vehicle's raw quantization
    included; v0 = v_w r_p / r_w, N = p A eta k, N = T / (n_f mu(v0) r_p)),
    written without any of the C code;
  - its SquealState equals `squeal-sim classify` at that derived point
    ("not sliding" below the calibration's v0_min_mps / force_min_n)
    (skipped where a 1 % change of v0 or N would change the state: the
    debounce/hysteresis band).
And a log of the same drive twice, the logger's clock restarting in
between, replays as two segments (nothing squeezed into one instant).
Prints "RESULT: N passed, M failed, K skipped".
"""
import json
import math
import os
import re
import subprocess
import sys
import tempfile

import logging

logging.disable(logging.WARNING)  # canmatrix's notes on formats it lacks
import canmatrix.formats  # noqa: E402
# tests/ of this checkout, and the folders its helper modules live in
_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, d) for d in ("support", os.path.join("support", "reference"), "host-sim", "tools")]

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(_TESTS)
import dbc_common  # noqa: E402
import vehref  # noqa: E402
SIM = os.environ.get("SQUEAL_SIM", os.path.join(ROOT, "build", "host", "squeal-sim"))
DBC = os.path.join(ROOT, "firmware", "protocol", "squeal.dbc")
LAYOUTS = ["moto15_p02.cal", "intel14_counter.cal", "mux_psi.cal", "ext29_kn.cal",
           "torque_rpm.cal"]
POS = {"FL": 0, "FR": 1, "RL": 2, "RR": 3}
STATES = {0: "stable", 1: "bistable", 2: "unstable", 3: "not_sliding", 15: "fault"}

# (time_s, vehicle speed m/s, pad force N); holds of 1 s joined by 0.3 s ramps
DRIVE = [(0.0, 30, 9000), (1.0, 30, 9000), (1.3, 8, 9000), (2.3, 8, 9000),
         (2.6, 3, 9000), (3.6, 3, 9000), (3.9, 1, 9000), (4.9, 1, 9000),
         (5.2, 8, 3000), (6.2, 8, 3000), (6.5, 20, 12000), (7.5, 20, 12000),
         (7.8, 0.01, 5000), (8.8, 0.01, 5000)]
HOLD_ENDS = [1.0, 2.3, 3.6, 4.9, 6.2, 7.5, 8.8]

# model defaults (docs/calib-example.txt) for torque: mu(v0) = mu_inf + dmu e^-a v0
MU_INF, DMU, SLOPE = 0.25, 0.15, 2.0


class Results(dbc_common.Results):
    """The shared counter, with the skips of this test."""
    skipped = 0


def read_cal(path):
    """The calibration text as {'flat': {...}, 'inputs': {name: {...}},
    'corners': [(pos, {...})]} (keys and values as written)."""
    with open(path) as f:
        flat, inputs, corners = vehref.parse_calib(f.read())
    return {"flat": flat, "inputs": inputs, "corners": list(corners.items())}


def num(d, key, default):
    return float(d[key]) if key in d else default


def geometry(cal, corner):
    flat = cal["flat"]
    return {
        "r_p": num(corner, "pad_radius_m", num(flat, "pad_radius_m", 0.12)),
        "r_w": num(corner, "wheel_radius_m", num(flat, "wheel_radius_m", 0.3)),
        "area_m2": num(corner, "piston_area_mm2", 0.0) * 1e-6,
        "eta": num(corner, "efficiency", 1.0),
        "k": num(corner, "axle_factor", 1.0),
        "n_f": num(corner, "friction_faces", 2.0),
    }


PA = {"bar": 1e5, "kpa": 1e3, "mpa": 1e6, "psi": 6894.757}


def mu(v0):
    return MU_INF + DMU * math.exp(-SLOPE * v0)


def quantize(inp, phys):
    """What the vehicle sends: raw = round((phys - offset) / factor)."""
    factor = float(inp["factor"])
    offset = float(inp.get("offset", "0"))
    raw = math.floor((phys - offset) / factor + 0.5)
    return raw * factor + offset


def speed_phys(unit, v, g):
    u = unit.lower()
    return {"km/h": v * 3.6, "kph": v * 3.6, "m/s": v, "mph": v / 0.44704,
            "rad/s": v / g["r_w"], "rpm": v / g["r_w"] * 60 / (2 * math.pi),
            "1/min": v / g["r_w"] * 60 / (2 * math.pi)}[u]


def v0_of(unit, phys, g):
    u = unit.lower()
    if u in ("rad/s",):
        return phys * g["r_p"]
    if u in ("rpm", "1/min"):
        return phys * 2 * math.pi / 60 * g["r_p"]
    v_w = {"km/h": phys / 3.6, "kph": phys / 3.6, "m/s": phys, "mph": phys * 0.44704}[u]
    return v_w * g["r_p"] / g["r_w"]


def expected_point(cal, k, v, force):
    """The operating point corner k's monitor should see (v0 m/s, N)."""
    pos, corner = cal["corners"][k]
    g = geometry(cal, corner)
    sp = cal["inputs"][corner["speed"]]
    v0 = v0_of(sp["unit"], quantize(sp, speed_phys(sp["unit"], v, g)), g)
    fname = corner["force"]
    fo = cal["inputs"][fname]
    # the sender converts with the first corner that uses the input
    first = next(c for _, c in cal["corners"] if c["speed"] == fname or c["force"] == fname)
    g0 = geometry(cal, first)
    u = fo["unit"].lower()
    if u in PA:
        p = force / (g0["area_m2"] * g0["eta"] * g0["k"]) / PA[u]
        n = quantize(fo, p) * PA[u] * g["area_m2"] * g["eta"] * g["k"]
    elif u == "nm":
        v0_first = v * g0["r_p"] / g0["r_w"]
        t = quantize(fo, force * g0["n_f"] * mu(v0_first) * g0["r_p"])
        n = t / (g["n_f"] * mu(v0) * g["r_p"])
    else:
        scale = {"n": 1.0, "kn": 1000.0}[u]
        n = quantize(fo, force / scale) * scale
    return pos, v0, n


# the monitor's "not sliding" thresholds (calibration defaults v0_min_mps,
# force_min_n): below them it does not ask the model
V0_MIN_MPS = 0.01
FORCE_MIN_N = 100.0


def classify(v0, n):
    if v0 < V0_MIN_MPS or n < FORCE_MIN_N:
        return "not_sliding"
    out = subprocess.run([SIM, "classify", "--v0", "%.9g" % v0, "--force", "%.9g" % n, "--json"],
                         stdout=subprocess.PIPE, check=True).stdout
    return json.loads(out)["state"]


def scenario_at(t):
    for (t0, v0, f0), (t1, v1, f1) in zip(DRIVE, DRIVE[1:]):
        if t0 <= t <= t1:
            a = (t - t0) / (t1 - t0)
            return v0 + a * (v1 - v0), f0 + a * (f1 - f0)
    return DRIVE[-1][1], DRIVE[-1][2]


def corner_outputs(db, out_log, k):
    """[(t, name, signals)] of corner k's frames (0x300.. + 0x10 k)."""
    msgs = {m.arbitration_id.id + 0x10 * k: m for m in db.frames
            if m.name in ("SquealStatus", "SquealDetail", "SquealDetail2")}
    rows = []
    for line in out_log.splitlines():
        m = re.match(r"^\((\d+\.\d+)\) \S+ ([0-9A-F]{3})#([0-9A-F]*)$", line)
        if not m:
            continue
        fid = int(m.group(2), 16)
        if fid in msgs:
            sig = msgs[fid].decode(bytes.fromhex(m.group(3)))
            rows.append((float(m.group(1)), msgs[fid].name,
                         {s: float(v.raw_value) for s, v in sig.items()}))
    return rows


def last_before(rows, name, t, key):
    val = None
    for tt, nm, sig in rows:
        if tt > t:
            break
        if nm == name:
            val = sig[key]
    return val


def run_layout(r, db, tmp, layout):
    path = os.path.join(HERE, "fixtures", layout)
    cal = read_cal(path)
    drive = os.path.join(tmp, "drive.txt")
    with open(drive, "w") as f:
        for t, v, n in DRIVE:
            f.write("%g %g %g\n" % (t, v, n))
    log = os.path.join(tmp, "in.log")
    subprocess.run([SIM, "plant", "--calib", path, "--scenario", drive, "--log", log, "--quiet"],
                   check=True)
    p = subprocess.run([SIM, "replay", "--calib", path, log], stdout=subprocess.PIPE,
                       stderr=subprocess.PIPE, check=True)
    out = p.stdout.decode()
    err = p.stderr.decode()
    r.check(re.search(r"implausible\s+0 ", err) is not None and
            re.search(r"bad_dlc\s+0 ", err) is not None,
            "%s: no input refused on a clean drive" % layout)
    for k in range(len(cal["corners"])):
        rows = corner_outputs(db, out, k)
        r.check(len(rows) > 100, "%s corner %d: outputs present" % (layout, k))
        for t_end in HOLD_ENDS:
            t = t_end - 0.02
            v, n_in = scenario_at(t)
            pos, v0, n = expected_point(cal, k, v, n_in)
            got_v0 = last_before(rows, "SquealDetail", t, "V0_mps")
            got_n = last_before(rows, "SquealDetail2", t, "Force_N")
            got_state = last_before(rows, "SquealStatus", t, "SquealState")
            what = "%s %s t=%.2f (v=%g N=%g)" % (layout, pos, t, v, n_in)
            r.check(got_v0 is not None and abs(got_v0 * 0.01 - v0) <= 0.011,
                    "%s: V0 %.4f m/s, derived %.4f" % (what, (got_v0 or 0) * 0.01, v0))
            r.check(got_n is not None and abs(got_n * 0.5 - n) <= 0.6 + 2e-4 * n,
                    "%s: Force %.1f N, derived %.1f" % (what, (got_n or 0) * 0.5, n))
            want = classify(v0, n)
            near = {classify(v0 * a, n * b) for a in (0.99, 1.01) for b in (0.99, 1.01)}
            if len(near | {want}) > 1:
                print("SKIP: %s state (within 1 %% of a border: %s)" % (what, sorted(near)))
                r.skipped += 1
                continue
            r.check(STATES.get(int(got_state)) == want,
                    "%s: state %s, classify %s" % (what, STATES.get(int(got_state)), want))


def summary_number(err, key):
    m = re.search(r"^\s+" + re.escape(key) + r"\s+(\d+(?:\.\d+)?)", err, re.M)
    return None if m is None else float(m.group(1))


def test_restarted_logger(r, tmp):
    """The same drive logged twice, the logger's clock restarting in
    between (a jump back of 8.8 s): two segments, every frame used, the
    virtual time the sum of both."""
    path = os.path.join(HERE, "fixtures", LAYOUTS[0])
    log = os.path.join(tmp, "in.log")
    subprocess.run([SIM, "plant", "--calib", path, "--scenario", os.path.join(tmp, "drive.txt"),
                    "--log", log, "--quiet"], check=True)
    with open(log) as f:
        once = f.read()
    twice = os.path.join(tmp, "twice.log")
    with open(twice, "w") as f:
        f.write(once + once)
    p = subprocess.run([SIM, "replay", "--calib", path, twice], stdout=subprocess.PIPE,
                       stderr=subprocess.PIPE, check=True)
    err = p.stderr.decode()
    n = len(once.splitlines())
    r.check(summary_number(err, "segments") == 2, "restarted log: 2 segments")
    r.check(summary_number(err, "time_backwards") == 0, "restarted log: no frame squeezed")
    r.check(re.search(r"new segment 2, log time re-based", err) is not None,
            "restarted log: the new segment is reported with its line")
    vt = summary_number(err, "virtual_time_s")
    # replay ends with the tick after the last frame (no tail)
    r.check(vt is not None and abs(vt - (2 * DRIVE[-1][0] + 0.01 + 0.001)) < 0.05,
            "restarted log: virtual time %.3f s = both segments" % (vt or 0))
    r.check(summary_number(err, "frames_read") == 2 * n, "restarted log: every frame read")


def main():
    r = Results()
    db = canmatrix.formats.loadp_flat(DBC)
    with tempfile.TemporaryDirectory() as tmp:
        for layout in LAYOUTS:
            run_layout(r, db, tmp, layout)
        test_restarted_logger(r, tmp)
    print("RESULT: %d passed, %d failed, %d skipped" % (r.passed, r.failed, r.skipped))
    return 0 if r.failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
