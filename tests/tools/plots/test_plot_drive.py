#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""tools/plots/plot_drive.py on drives written here: five operating points
(the state as a number and as its name, one fault), and three
SquealStatus frames in the `squeal-sim decode --csv` form. Checked as the
reader of the picture relies on it: the files, the axes and their units,
the legend, the path's segments in the reported state's colour through the
given points, the time plots' series, the borders where the closed forms
put them (docs/model.md, by hand):
  N_H(v0) = 2 D w0 m / (a dmu) e^(a v0)       at v0 = 1 m/s, a = 2 s/m:
          = 2 0.023 5000 / 0.3 e^2 N = 5664.9 N; at a = 3: 10266.4 N
  N_S(v0) = N_H(v0) / (2 I1(s)/s), s = a v0    at s = 2: 5664.9 / I1(2) N
the decode form's forward fill (v0 from DiscSpeed x pad radius until the
monitor's V0_mps arrives), and one clear error for a file it cannot draw.

prints "RESULT: N passed, M failed"
"""
import csv
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from figures import Checks, draw, files_ok, legend_texts, line_at, lines_of_colour, plotlib  # noqa: E402
from scipy.special import iv  # noqa: E402

T_S = [0.0, 1.0, 2.0, 3.0, 4.0]
V0_MPS = [3.0, 2.5, 1.5, 1.0, 0.5]
FORCE_N = [2000.0, 6000.0, 9000.0, 12000.0, 12000.0]
STATES = ["0", "1", "2", "unstable", "15"]
WARN = [0, 2, 3, 3, 0]
DECODE_COLS = ["time_s", "id", "message", "DiscSpeed_radps", "PadForce_N", "SquealState", "WarningLevel",
               "V0_mps", "Force_N"]


def n_hopf(v0, a=2.0, d=0.023, w0=5000.0, m=1.0, dmu=0.15):
    return 2.0 * d * w0 * m / (a * dmu) * math.exp(a * v0)


def write(path, header, rows):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        w.writerows(rows)
    return path


def segments(ax):
    return [ln for ln in ax.get_lines() if len(ln.get_xdata()) == 2 and ln.get_linewidth() == 2.4]


def drive(c, tmp):
    path = write(os.path.join(tmp, "drive.csv"), ["time_s", "v0_mps", "force_n", "state", "warning", "extra"],
                 [[t, v, n, s, w, "x"] for t, v, n, s, w in zip(T_S, V0_MPS, FORCE_N, STATES, WARN)])
    rc, out, saved = draw("plot_drive", [path, "--out", tmp, "--name", "drive_test"])
    c.check(rc in (None, 0) and len(saved) == 1 and saved[0][0] == "drive_test" and files_ok(saved[0][2]),
            "drive_test.png and .svg written, not empty (exit %r)" % (rc,))
    fig = saved[0][1]
    ax, axs = fig.axes[0], fig.axes[1:]
    c.check(ax.get_xlabel() == "disc surface speed v0 [m/s]" and ax.get_ylabel() == "pad force N [kN]",
            "the map: speed v0 [m/s] across, pad force N [kN] up")
    # v0 up to 1.1 x 3.0 m/s, N up to 1.15 x 12 kN
    c.check(ax.get_xlim()[0] == 0.0 and abs(ax.get_xlim()[1] - 3.3) < 1e-12,
            "speed axis to 1.1 x the fastest point: 3.3 m/s (%s)" % (ax.get_xlim(),))
    c.check(abs(ax.get_ylim()[1] - 13.8) < 1e-12, "force axis to 1.15 x 12 kN = 13.8 kN (%s)" % (ax.get_ylim(),))
    want = ["Hopf border (unstable above)", "exact stability limit (bistable above)", "cubic limit (paper)",
            "region: unstable (squeal)", "region: bistable (squeal possible after a kick)", "region: stable",
            "path: stable", "path: bistable (squeal possible after a kick)", "path: unstable (squeal)",
            "path: fault (inputs stale or implausible)"]
    c.check(legend_texts(ax.get_legend()) == want,
            "legend: the three borders, the three regions, then one entry per state the path has, "
            "in words (%s)" % legend_texts(ax.get_legend()))
    hopf = lines_of_colour(ax, plotlib.LINE_HOPF["color"])
    exact = lines_of_colour(ax, plotlib.LINE_EXACT["color"])
    want_h, want_s = n_hopf(1.0) / 1000.0, n_hopf(1.0) / iv(1, 2.0) / 1000.0
    c.check(len(hopf) == 1 and abs(line_at(hopf[0], 1.0) - want_h) < 2e-3 * want_h,
            "Hopf border at v0 = 1 m/s: %.4f kN (by hand %.4f)" % (line_at(hopf[0], 1.0) if hopf else -1, want_h))
    c.check(len(exact) == 1 and abs(line_at(exact[0], 1.0) - want_s) < 2e-3 * want_s,
            "stable border at v0 = 1 m/s: %.4f kN (by hand %.4f)" % (line_at(exact[0], 1.0) if exact else -1, want_s))
    seg = segments(ax)
    names = ["stable", "bistable", "unstable", "unstable"]
    ok = len(seg) == 4
    for i, ln in enumerate(seg[:4]):
        ok = ok and list(ln.get_xdata()) == V0_MPS[i:i + 2]
        ok = ok and [round(x, 9) for x in ln.get_ydata()] == [FORCE_N[i] / 1000.0, FORCE_N[i + 1] / 1000.0]
        ok = ok and ln.get_color() == plotlib.PATH_COLORS[names[i]]
    c.check(ok, "the path: 4 segments through the points, each in its starting point's reported state")
    c.check([a.get_ylabel() for a in axs] == ["v0 [m/s]", "N [kN]", "reported state", "warning level"]
            and axs[-1].get_xlabel() == "time [s]",
            "time plots: v0 [m/s], N [kN], reported state, warning level over time [s]")
    c.check([t.get_text() for t in axs[2].get_yticklabels()] ==
            ["stable", "bistable", "unstable", "not sliding", "fault"]
            and [t.get_text() for t in axs[3].get_yticklabels()] ==
            ["0 none", "1 advisory", "2 warning", "3 critical"],
            "states and warning levels named on their axes (no code names)")
    series = [list(a.get_lines()[0].get_ydata()) for a in axs]
    c.check(series[0] == V0_MPS and series[1] == [n / 1000.0 for n in FORCE_N]
            and series[2] == [0, 1, 2, 2, 4] and series[3] == WARN,
            "the series as given; the state as 0 stable .. 2 unstable, 4 fault (%s)" % series[2])
    c.check(all(a.get_xlim() == (0.0, 4.0) for a in axs), "time axes over the drive, 0..4 s")
    rc, _, saved = draw("plot_drive", [path, "--out", tmp, "--name", "drive_a3", "--slope", "3"])
    ax = saved[0][1].axes[0]
    hopf = lines_of_colour(ax, plotlib.LINE_HOPF["color"])
    c.check("a = 3 s/m" in ax.get_title() and len(hopf) == 1
            and abs(line_at(hopf[0], 1.0) - n_hopf(1.0, a=3.0) / 1000.0) < 2e-2,
            "--slope 3: the title says so and N_H(1 m/s) is %.3f kN" % (n_hopf(1.0, a=3.0) / 1000.0))


def decoded(c, tmp):
    rows = [[0.000, "110", "DiscSpeed", 10.0, "", "", "", "", ""],
            [0.001, "111", "PadForce", "", 3000.0, "", "", "", ""],
            [0.002, "300", "SquealStatus", "", "", 0, 0, "", ""],
            [0.010, "400", "SquealDetail", "", "", "", "", 2.0, ""],
            [0.011, "401", "SquealDetail2", "", "", "", "", "", 4000.0],
            [0.012, "300", "SquealStatus", "", "", 1, 2, "", ""],
            [0.020, "110", "DiscSpeed", 50.0, "", "", "", "", ""],
            [0.022, "300", "SquealStatus", "", "", 2, 3, "", ""]]
    path = write(os.path.join(tmp, "decode.csv"), DECODE_COLS, rows)
    rc, _, saved = draw("plot_drive", [path, "--out", tmp, "--name", "dec"])
    axs = saved[0][1].axes[1:] if saved else []
    got = [list(a.get_lines()[0].get_ydata()) for a in axs]
    c.check(len(got) == 4 and [round(x, 9) for x in got[0]] == [1.2, 2.0, 2.0] and got[1] == [3.0, 4.0, 4.0]
            and got[2] == [0, 1, 2] and got[3] == [0, 2, 3]
            and list(axs[0].get_lines()[0].get_xdata()) == [0.002, 0.012, 0.022],
            "decode form: one point per SquealStatus, v0 = 10 rad/s x 0.12 m = 1.2 m/s "
            "until V0_mps = 2 arrives and stays (%s)" % got[:1])
    import plot_drive
    t, v, n, st, w = plot_drive.read_drive(path, 0.1)
    c.check([round(x, 9) for x in v] == [1.0, 2.0, 2.0] and list(n) == [3000.0, 4000.0, 4000.0]
            and st == ["stable", "bistable", "unstable"],
            "--pad-radius 0.1: the first v0 is 10 rad/s x 0.1 m = 1 m/s (%s)" % list(v))


def refusals(c, tmp):
    cases = (("a CSV without its columns", ["time_s", "speed"], [[0, 1]], "needs columns"),
             ("a header without rows", ["time_s", "v0_mps", "force_n", "state", "warning"], [], "has no rows"),
             ("a decode CSV without a SquealStatus frame", DECODE_COLS,
              [[0.0, "110", "DiscSpeed", 10.0, "", "", "", "", ""]], "has no SquealStatus frames"))
    for k, (what, header, rows, text) in enumerate(cases):
        path = write(os.path.join(tmp, "bad%d.csv" % k), header, rows)
        rc, _, saved = draw("plot_drive", [path, "--out", tmp, "--name", "bad%d" % k])
        c.check(not saved and isinstance(rc, str) and rc.startswith("plot_drive: " + path) and text in rc
                and not os.path.exists(os.path.join(tmp, "bad%d.png" % k)),
                "%s: one line, nothing drawn (%r)" % (what, rc))


def main():
    return Checks.run(drive, decoded, refusals)


if __name__ == "__main__":
    sys.exit(main())
