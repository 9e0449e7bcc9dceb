#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""The drive tools on a vehicle calibration with [corner] sections
(tests/tools/fixtures/two_corner.cal: FL on the flat brake and the default outputs,
RR with its own brake and outputs that are not 0x300.. + 0x10 k):

    squeal-sim plant --calib two_corner.cal --scenario stop --log in.log
    squeal-sim replay --calib two_corner.cal in.log > out.log

  - fleet.py --calib: time in each state and the episodes per corner equal
    what this test works out from each corner's SquealStatus frames in
    out.log (its identifiers read here from the calibration text, the frames
    decoded with canmatrix from squeal.dbc);
  - the heat map: each corner's panel draws the Hopf border of that corner's
    brake (checked against tests/support/reference/squeal_reference.py's hopf_force
    for the brake keys read here: the corner's over the flat ones), and the
    two corners' borders differ;
  - live_view.py --calib: a map per corner with its own Hopf border, each
    point at that corner's last decoded V0_mps / Force_N, and the snapshot
    from the command line.
Prints "RESULT: N passed, M failed, K skipped".
"""
import csv
import json
import logging
import os
import re
import subprocess
import sys
import tempfile
# tests/ of this checkout, and the folders its helper modules live in
_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, d) for d in ("support", os.path.join("support", "reference"), "host-sim", "tools")]

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(_TESTS), "tools"))
import squeal_reference as REF  # noqa: E402
from test_fleet import PY, ROOT, SIM, Results  # noqa: E402

CAL = os.path.join(HERE, "fixtures", "two_corner.cal")
DBC = os.path.join(ROOT, "firmware", "protocol", "squeal.dbc")
STATES = ("stable", "bistable", "unstable", "not_sliding", "fault")
HOPF_COLOUR = "#b2182b"
R = Results()

# what this test expects of two_corner.cal, written out by hand: the brake
# of each corner (FL: flat keys; RR: its own over them) and its outputs
BRAKE = {"FL": dict(REF.DEFAULTS, damping=0.03, slope=2.5),
         "RR": dict(REF.DEFAULTS, damping=0.09, slope=3.5, delta_mu=0.2)}
IDS = {"FL": (0x300, 0x301, 0x303), "RR": (0x4A0, 0x4B1, 0x4C3)}


def load_db():
    logging.disable(logging.WARNING)
    import canmatrix.formats
    return list(canmatrix.formats.loadp(DBC).values())[0]


def decoded_frames(db, log):
    """{corner: [(t, message name, {signal: phys or None})]} of out.log."""
    by_id = {}
    for corner, ids in IDS.items():
        for cid, name in zip(ids, ("SquealStatus", "SquealDetail", "SquealDetail2")):
            by_id[cid] = (corner, db.frame_by_name(name))
    out = {c: [] for c in IDS}
    with open(log) as f:
        for line in f:
            m = re.match(r"^\((\d+\.\d+)\) \S+ ([0-9A-F]{3})#([0-9A-F]*)$", line.strip())
            if not m or int(m.group(2), 16) not in by_id:
                continue
            corner, msg = by_id[int(m.group(2), 16)]
            sig = {}
            for name, d in msg.decode(bytes.fromhex(m.group(3))).items():
                na = msg.signal_by_name(name).values.get(d.raw_value) == "not_available"
                sig[name] = None if na else float(d.phys_value)
            out[corner].append((float(m.group(1)), msg.name, sig))
    return out


def state_times(frames, end_s):
    """Time per state and episode count of one corner: from its first
    SquealStatus, each span between two of them counts for the earlier
    state, the last one up to end_s."""
    st = [(t, STATES[int(s["SquealState"])] if int(s["SquealState"]) < 4 else "fault")
          for t, name, s in frames if name == "SquealStatus"]
    times = dict.fromkeys(STATES, 0.0)
    for (t0, s0), (t1, _) in zip(st, st[1:] + [(end_s, None)]):
        times[s0] += t1 - t0
    episodes = 1 + sum(a[1] != b[1] for a, b in zip(st, st[1:]))
    return times, episodes


def hopf_lines(ax):
    return [ln for ln in ax.get_lines() if ln.get_color() == HOPF_COLOUR]


def check_hopf(ax, corner, what):
    """The drawn Hopf border of ax is corner's: N_H(v0) of the reference."""
    lines = hopf_lines(ax)
    if not R.check(len(lines) == 1, "%s %s: one Hopf border line" % (what, corner)):
        return
    xs, ys = lines[0].get_data()
    worst = 0.0
    for v0, y in zip(xs, ys):
        if not (y == y) or v0 <= 0:
            continue
        ref = REF.classify(dict(BRAKE[corner], v0=float(v0), force=1000.0))["hopf_force"]
        worst = max(worst, abs(y * 1000.0 - ref) / ref)
    R.check(worst < 1e-9, "%s %s: Hopf border = reference N_H(v0) of its brake (rel. err %.1e)"
            % (what, corner, worst))


def make_drive(tmp):
    inp, out, js = (os.path.join(tmp, n) for n in ("in.log", "out.log", "s.json"))
    subprocess.run([SIM, "plant", "--calib", CAL, "--scenario", "stop", "--log", inp, "--quiet"],
                   check=True, timeout=120)
    with open(out, "w") as f:
        subprocess.run([SIM, "replay", "--calib", CAL, inp], stdout=f, stderr=subprocess.DEVNULL,
                       check=True, timeout=120)
    subprocess.run([SIM, "replay", "--calib", CAL, inp, "--no-output", "--summary-json", js],
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True, timeout=120)
    with open(js) as f:
        doc = json.load(f)
    return inp, out, doc


def check_fleet(tmp, inp, frames, end_s):
    import fleet
    rep = os.path.join(tmp, "report")
    p = subprocess.run([PY, os.path.join(ROOT, "tools", "fleet.py"), inp, "--calib", CAL,
                        "--workers", "1", "-o", rep], stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, timeout=300)
    print(p.stdout.decode()[-1500:])
    if not R.check(p.returncode == 0, "fleet --calib two_corner.cal: exit 0"):
        return
    with open(os.path.join(rep, "state_time.csv"), newline="") as f:
        st = {r["corner"]: r for r in csv.DictReader(f) if r["log"] != "ALL"}
    with open(os.path.join(rep, "episodes.csv"), newline="") as f:
        eps = list(csv.DictReader(f))
    R.check(sorted(st) == ["FL", "RR"], "fleet: state times for corners %s" % sorted(st))
    differ = False
    for corner in IDS:
        want, n_ep = state_times(frames[corner], end_s)
        got = {s: float(st[corner][s + "_s"]) for s in STATES} if corner in st else {}
        ok = got and all(abs(got[s] - want[s]) < 1e-6 for s in STATES)
        R.check(ok, "fleet %s: time per state %s = from its SquealStatus frames %s" %
                (corner, got, {s: round(x, 6) for s, x in want.items()}))
        mine = sum(e["corner"] == corner for e in eps)
        R.check(mine == n_ep, "fleet %s: %d episodes = its state changes + 1 (%d)" % (corner, mine, n_ep))
        differ = differ or want != state_times(frames["FL"], end_s)[0]
    R.check(differ, "the two corners' brakes give different state times")
    # the heat map's panels, drawn the way fleet.py draws them
    summary = json.load(open(os.path.join(tmp, "s.json")))
    cells = {}
    grid = fleet.add_cells(cells, summary)
    fig, panels = fleet.heat_figure(cells, grid, fleet.corner_setups(CAL), "test")
    R.check(sorted(panels) == ["FL", "RR"], "heat map: panels %s" % sorted(panels))
    for corner, ax in panels.items():
        check_hopf(ax, corner, "heat map")
    a, b = (hopf_lines(panels[c])[0].get_ydata() for c in ("FL", "RR"))
    R.check(max(abs(x - y) for x, y in zip(a, b)) > 0.1, "heat map: FL and RR borders differ")
    fleet.P.plt.close(fig)
    page = open(os.path.join(rep, "index.html")).read()
    R.check("RR: exact limit, a = 3.5 s/m, D = 0.09" in page,
            "report names RR's own brake under the borders")


def check_live(tmp, out, frames):
    import drive_common as DC
    import live_view
    t = 3.5
    view = live_view.LiveView(DC.read_calib(CAL), window_s=10.0)
    live_view.run_log(view, out, 0.0, t)
    fig = view.draw()
    R.check(sorted(view.axes) == ["FL", "RR"], "live view: maps for %s" % sorted(view.axes))
    for corner in IDS:
        if corner not in view.axes:
            continue
        check_hopf(view.axes[corner]["map"], corner, "live view")
        t0 = min(fr[0][0] for fr in frames.values() if fr)
        last = {}
        for tf, name, sig in frames[corner]:
            if tf - t0 > t + 1e-9:  # the view's time starts at the log's first frame (FL's)
                break
            last[name] = sig
        (v, n), = view.axes[corner]["point"].get_offsets()
        want_v, want_n = last["SquealDetail"]["V0_mps"], last["SquealDetail2"]["Force_N"]
        R.check(abs(v - want_v) < 1e-9 and abs(n - want_n / 1000.0) < 1e-9,
                "live view %s: point (%.2f m/s, %.3f kN) = its decoded (%.2f, %.3f)" %
                (corner, v, n, want_v, want_n / 1000.0))
    va = view.axes["FL"]["point"].get_offsets()[0][0]
    vb = view.axes["RR"]["point"].get_offsets()[0][0]
    R.check(abs(va - vb) > 0.01, "live view: FL and RR points differ (pad radii 0.12, 0.1 m)")
    live_view.P.plt.close(fig)
    png = os.path.join(tmp, "snap.png")
    p = subprocess.run([PY, os.path.join(ROOT, "tools", "live_view.py"), "--log", out, "--calib",
                        CAL, "--snapshot", png, "--after", str(t)], stdout=subprocess.PIPE,
                       stderr=subprocess.PIPE, timeout=120)
    R.check(p.returncode == 0 and os.path.isfile(png) and b"FL" in p.stdout and b"RR" in p.stdout,
            "live_view --calib --snapshot: exit 0, both corners: %s" % p.stdout.decode().strip())


def main():
    try:
        import dask.distributed  # noqa: F401
    except ImportError as e:
        R.skip("fleet with a two-corner calibration", "python3-distributed missing: %s" % e)
        R.finish()
    db = load_db()
    with tempfile.TemporaryDirectory() as tmp:
        inp, out, doc = make_drive(tmp)
        frames = decoded_frames(db, out)
        R.check(all(len(frames[c]) > 100 for c in IDS),
                "out.log has frames of both corners: %s" % {c: len(v) for c, v in frames.items()})
        end_s = float(doc["t0_s"]) + float(doc["virtual_time_s"])
        check_fleet(tmp, inp, frames, end_s)
        check_live(tmp, out, frames)
    R.finish()


if __name__ == "__main__":
    main()
