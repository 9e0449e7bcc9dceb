#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""tools/live_view.py, headless (Agg), on logs and on a python-can bus:

  - a braking run (plant -> replay) snapshotted at 3 moments: the plotted
    operating point and its colour equal what `squeal-sim decode --csv` (the
    C decoder, independent of canmatrix) says the monitor reported last
    (V0_mps, Force_N, SquealState); in the PNG written by the command line,
    the pixel under the point has the state's colour and the map's regions
    are where the closed forms put them; the Hopf margin curve holds the
    decoded margins of the last window;
  - two corners (FL, RR on 0x330..): a map and a point each;
  - the same view fed live from a python-can virtual bus (the --iface path);
  - bad input: a missing log, a log python-can cannot parse, bad usage:
    one clear message, no traceback;
  - on vcan0 in the QEMU guest: SKIP (the guest cannot run Python).
Prints "RESULT: N passed, M failed, K skipped".
"""
import csv
import io
import os
import subprocess
import sys
import tempfile
import threading
import time
# tests/ of this checkout, and the folders its helper modules live in
_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, d) for d in ("support", os.path.join("support", "reference"), "host-sim", "tools")]

sys.path.insert(0, os.path.join(os.path.dirname(_TESTS), "tools"))
import live_view  # noqa: E402
from test_fleet import PY, ROOT, SIM, Results  # noqa: E402

TOOL = os.path.join(ROOT, "tools", "live_view.py")
R = Results()
STATE_NAMES = {"0": "stable", "1": "bistable", "2": "unstable", "3": "not_sliding"}
# reported state and map region colours (tools/plots/plotlib.py)
PATH = {"stable": "#1a9850", "bistable": "#d98e04", "unstable": "#b2182b",
        "not_sliding": "#737373", "fault": "#542788"}
REGION = {"stable": "#cfe8cf", "unstable": "#f4a6a0"}


def rgb(hexcol, alpha=1.0):
    c = [int(hexcol[i:i + 2], 16) / 255.0 for i in (1, 3, 5)]
    return [alpha * x + (1 - alpha) for x in c]  # over white


def near(px, col, tol=0.05):
    return max(abs(a - b) for a, b in zip(px[:3], col)) < tol


def expected(decoded, t):
    """The monitor's last report at time t, from decode --csv rows."""
    out = {"margins": []}
    for r in decoded:
        tr = float(r["time_s"])
        if tr > t + 1e-9:
            break
        if r["message"] == "SquealStatus":
            out["state"] = STATE_NAMES.get(r["SquealState"], "fault")
            if r["HopfMargin_mps"] != "NA":
                out["margins"].append((tr, float(r["HopfMargin_mps"])))
        elif r["message"] == "SquealDetail" and r["V0_mps"] != "NA":
            out["v0"] = float(r["V0_mps"])
        elif r["message"] == "SquealDetail2" and r["Force_N"] != "NA":
            out["force"] = float(r["Force_N"])
    return out


PNG_DPI = 150  # the snapshot's resolution (tools/plots/plotlib.py)


def pixel_of(fig, ax, x, y):
    """(row, column) of data point (x, y) in the snapshot PNG (the figure's
    own size, drawn at PNG_DPI)."""
    k = PNG_DPI / fig.dpi
    dx, dy = ax.transData.transform((x, y))
    h = fig.get_size_inches()[1] * PNG_DPI
    return int(round(h - k * dy)), int(round(k * dx))


def check_logs(tmp):
    import matplotlib.image as mpimg
    inp, out = os.path.join(tmp, "in.log"), os.path.join(tmp, "out.log")
    subprocess.run([SIM, "plant", "--scenario", "stop", "--log", inp, "--quiet"], check=True)
    with open(out, "w") as f:
        subprocess.run([SIM, "replay", inp], stdout=f, stderr=subprocess.DEVNULL, check=True)
    dec = subprocess.run([SIM, "decode", "--csv", out], stdout=subprocess.PIPE, check=True)
    decoded = list(csv.DictReader(io.StringIO(dec.stdout.decode())))
    for t in (3.0, 4.85, 5.3):
        exp = expected(decoded, t)
        view = live_view.LiveView({}, window_s=10.0)
        live_view.run_log(view, out, 0.0, t)
        fig = view.draw()
        a = view.axes["FL"]
        (v, n), = a["point"].get_offsets()
        R.check(abs(v - exp["v0"]) < 1e-9 and abs(n - exp["force"] / 1000.0) < 1e-9,
                "t=%.2f: point at (%.2f m/s, %.3f kN) = decoded (%.2f, %.3f)" %
                (t, v, n, exp["v0"], exp["force"] / 1000.0))
        face = [round(x, 3) for x in a["point"].get_facecolors()[0][:3]]
        R.check(face == [round(x, 3) for x in rgb(PATH[exp["state"]])],
                "t=%.2f: point coloured as the reported state %s" % (t, exp["state"]))
        xs, ys = a["mline"].get_data()
        ys = [y for y in ys if y == y]  # not available: a gap (NaN) in the curve
        want = [(tr - t, m) for tr, m in exp["margins"] if tr >= t - 10.0]
        R.check(len(ys) == len(want) and all(abs(m - w[1]) < 1e-9 for m, w in zip(ys, want)),
                "t=%.2f: margin curve = %d decoded margins of the last 10 s" % (t, len(want)))
        # the command line's picture: same figure geometry
        png = os.path.join(tmp, "snap-%.2f.png" % t)
        p = subprocess.run([PY, TOOL, "--log", out, "--snapshot", png, "--after", str(t)],
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=120)
        R.check(p.returncode == 0 and os.path.getsize(png) > 10000 and p.stderr == b""
                and os.path.getsize(png[:-4] + ".svg") > 10000,
                "t=%.2f: live_view --snapshot: exit 0, a PNG and the SVG beside it, nothing on stderr" % t)
        from PIL import Image
        with Image.open(png) as im:
            R.check(tuple(round(x) for x in im.info.get("dpi", (0, 0))) == (PNG_DPI, PNG_DPI)
                    and im.size == (int(round(fig.get_size_inches()[0] * PNG_DPI)),
                                    int(round(fig.get_size_inches()[1] * PNG_DPI))),
                    "t=%.2f: the PNG at 150 dpi, %s px" % (t, im.size))
        img = mpimg.imread(png)
        r, c = pixel_of(fig, a["map"], v, n)
        R.check(near(img[r, c], rgb(PATH[exp["state"]])),
                "t=%.2f: PNG pixel under the point has the %s colour (%s)" %
                (t, exp["state"], [round(float(x), 2) for x in img[r, c][:3]]))
        r, c = pixel_of(fig, a["map"], 12.5, 2.0)   # fast, light: stable region
        R.check(near(img[r, c], rgb(REGION["stable"], 0.55)), "t=%.2f: map, stable region" % t)
        r, c = pixel_of(fig, a["map"], 0.3, 18.0)   # slow, hard: unstable region
        R.check(near(img[r, c], rgb(REGION["unstable"], 0.55)), "t=%.2f: map, unstable region" % t)
        live_view.P.plt.close(fig)
    check_labels(fig, view)
    check_no_monitor(tmp, inp)
    return out, decoded


def check_labels(fig, view):
    """What the reader sees, from the Figure: every fill and line in the
    legend in words, axes with units, warning levels named."""
    a = view.axes["FL"]
    texts = [t.get_text() for leg in fig.legends for t in leg.get_texts()]
    want = ["Hopf border (unstable above)", "exact stability limit (bistable above)",
            "region: unstable (squeal)", "region: bistable (squeal possible after a kick)",
            "region: stable", "point, trail: reported stable", "point, trail: reported bistable",
            "point, trail: reported unstable"]
    R.check(texts == want, "legend: borders, regions, reported states in words (%s)" % texts)
    R.check([t.get_text() for t in a["margin"].get_legend().get_texts()] ==
            ["Hopf margin (reported)", "0: on the Hopf border"], "margin panel: both lines in its legend")
    R.check(a["map"].get_xlabel().startswith("disc surface speed v0 [m/s]")
            and a["map"].get_ylabel() == "pad force N [kN]"
            and a["margin"].get_ylabel() == "Hopf margin [m/s]"
            and a["warn"].get_xlabel() == "time [s] (0 = now)"
            and a["warn"].get_ylabel() == "warning level", "axes: labels with units")
    R.check([t.get_text() for t in a["warn"].get_yticklabels()] ==
            ["0 none", "1 advisory", "2 warning", "3 critical"], "warning levels named")
    # the map stretched where the borders are: 0..4.5 m/s (the limit reaches 20 kN at 3.65 m/s)
    x0, x1 = (a["map"].transData.transform((v, 0.0))[0] for v in (0.0, 4.5))
    xe = a["map"].transData.transform((14.0, 0.0))[0]
    R.check(abs((x1 - x0) / (xe - x0) - 0.6) < 1e-6,
            "map: 0..4.5 m/s take 60 %% of the 0..14 m/s axis (%.3f)" % ((x1 - x0) / (xe - x0)))
    title = a["title"].get_text()
    R.check("_" not in title and any(s in title for s in ("stable", "unstable (squeal)",
                                                          "bistable (squeal possible after a kick)")),
            "title: the state in words (%r)" % title)


def check_no_monitor(tmp, inp):
    """The plant's input log has CAN frames but not one monitor frame:
    refused in one line, exit 1, nothing written."""
    png = os.path.join(tmp, "nomon.png")
    p = subprocess.run([PY, TOOL, "--log", inp, "--snapshot", png, "--after", "3"],
                       stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=120)
    err = p.stderr.decode().strip().splitlines()
    R.check(p.returncode == 1 and len(err) == 1 and "no monitor frames" in err[0]
            and not os.path.exists(png) and not os.path.exists(png[:-4] + ".svg"),
            "a log without monitor frames: exit %d, one line %s, no picture" % (p.returncode, err))
    before = sorted(os.listdir(tmp))
    p = subprocess.run([PY, TOOL, "--help"], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                       timeout=60, cwd=tmp)
    helptext = p.stdout.decode()
    opts = ("--iface", "--log", "--rate", "--calib", "--snapshot", "--after", "--window",
            "--v-max", "--force-max", "--interface")
    R.check(p.returncode == 0 and all(("  %s " % o) in helptext for o in opts)
            and sorted(os.listdir(tmp)) == before and "Exit status" in helptext,
            "--help: exit 0, a line per option and the exit status, no file written")


def check_corners(tmp, out, decoded):
    """Two corners (FL and RR, RR's frames on 0x330.. = FL's copied): one
    map per corner, each with its own point."""
    two = os.path.join(tmp, "two.log")
    with open(out) as f, open(two, "w") as g:
        for line in f:
            g.write(line)
            head, _, rest = line.partition(" vcan0 ")
            if rest[:3] in ("300", "301", "303"):
                g.write("%s vcan0 %03X%s" % (head, int(rest[:3], 16) + 0x30, rest[3:]))
    view = live_view.LiveView({}, window_s=10.0)
    live_view.run_log(view, two, 0.0, 5.3)
    fig = view.draw()
    exp = expected(decoded, 5.3)
    R.check(sorted(view.axes) == ["FL", "RR"], "two corners: maps for %s" % sorted(view.axes))
    for name in ("FL", "RR"):
        (v, n), = view.axes[name]["point"].get_offsets()
        R.check(abs(v - exp["v0"]) < 1e-9 and view.corners[name].state == exp["state"],
                "two corners: %s point at %.2f m/s, %s" % (name, v, view.corners[name].state))
    live_view.P.plt.close(fig)


def check_bus(out, decoded):
    """The --iface path (run_bus) on python-can's virtual bus."""
    import can
    frames = [m for m in can.LogReader(out)]
    t0 = frames[0].timestamp
    send = [m for m in frames if m.timestamp - t0 <= 1.0]
    ours = sum(1 for m in send if m.arbitration_id in (0x300, 0x301, 0x303))
    view = live_view.LiveView({}, window_s=10.0)
    with can.Bus(interface="virtual", channel="h7-live") as rx, \
            can.Bus(interface="virtual", channel="h7-live") as tx:
        def sender():
            time.sleep(0.2)
            for m in send:
                tx.send(can.Message(arbitration_id=m.arbitration_id, data=m.data,
                                    is_extended_id=False))
        th = threading.Thread(target=sender)
        th.start()
        live_view.run_bus(view, rx, after_s=1.5)
        th.join()
    exp = expected(decoded, 1.0)
    c = view.corners.get("FL")
    R.check(view.frames == ours, "bus: %d of %d monitor frames taken" % (view.frames, ours))
    R.check(c is not None and c.state == exp["state"] and abs(c.v0 - exp["v0"]) < 1e-9,
            "bus: state %s, v0 %s as decoded" % (c and c.state, c and c.v0))


def check_bad(tmp):
    bad = os.path.join(tmp, "bad.log")
    with open(bad, "w") as f:
        f.write("(0.100000) vcan0 300#ZZ\n")
    for args, code, what in (
            (["--log", os.path.join(tmp, "none.log"), "--snapshot", "x.png", "--after", "1"], 1,
             "missing log"),
            (["--log", bad, "--snapshot", os.path.join(tmp, "x.png"), "--after", "1"], 1,
             "unparsable log"),
            (["--log", bad, "--snapshot", "x.png"], 2, "--snapshot without --after"),
            (["--iface", "vcan0", "--rate", "2"], 2, "--rate with --iface")):
        p = subprocess.run([PY, TOOL] + args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=60)
        err = p.stderr.decode()
        R.check(p.returncode == code and "Traceback" not in err and err.strip(),
                "%s: exit %d, one message: %s" % (what, p.returncode, err.strip().splitlines()[-1:]))


def main():
    with tempfile.TemporaryDirectory() as tmp:
        out, decoded = check_logs(tmp)
        check_corners(tmp, out, decoded)
        check_bus(out, decoded)
        check_bad(tmp)
    R.skip("live view on vcan0 in the QEMU guest",
           "the guest is a busybox initramfs without python3, numpy, matplotlib, canmatrix "
           "and python-can; the --iface path is tested on python-can's virtual bus")
    R.finish()


if __name__ == "__main__":
    main()
