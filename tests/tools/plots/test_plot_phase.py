#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""tools/plots/plot_phase.py with the simulator (oscsim): the phase
portraits at v0 = 1.0, 1.5 and 2.5 m/s of the paper's brake (a = 2 s/m,
N = 9 kN). Checked as the reader of the picture relies on it: the files,
the three panels with their axes, units, titles and legends, and what the
physics fixes by hand:
  - v_H = (ln 1/2 - ln(D w0 m / (a N dmu))) / a = 1.2315 m/s, so the
    title's "v_H = 1.23 m/s" and v0 = 1.0 m/s lies below it;
  - while the pad sticks it moves with the disc: x' = v0 exactly, so each
    stick-slip path tops out on its panel's stick line x' = v0 and a
    path that does not stick stays below it;
  - the paths start at rest, dx off steady sliding: (1 um, 0) at v0 = 1;
    at 0.8 and 1.2 x the sliding cycle (ratio 2/3) at v0 = 1.5;
  - a push dx from rest swings to about w0 dx: 5000 x 450 um = 2.25 m/s
    = 0.9 v0 (below the stick line), 5000 x 600 um = 3 m/s (past it).
A simulator that fails gives one line, no picture.

usage: test_plot_phase.py [path/to/oscsim]   prints "RESULT: N passed, M failed"
"""
import math
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from figures import ROOT, Checks, draw, files_ok, legend_texts, no_code_names, suptitle  # noqa: E402

SIM = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build", "host", "oscsim"))
V0_MPS = (1.0, 1.5, 2.5)
STICK_RED = "#b2182b"


def paths(ax):
    """The drawn paths (more than two points), in drawing order."""
    return [ln for ln in ax.get_lines() if len(ln.get_xdata()) > 2]


def top(ln):
    return float(max(ln.get_ydata()))


def main():
    c = Checks()
    v_h = (math.log(0.5) - math.log(0.023 * 5000.0 * 1.0 / (2.0 * 9000.0 * 0.15))) / 2.0
    with tempfile.TemporaryDirectory() as tmp:
        rc, out, saved = draw("plot_phase", ["--sim", SIM, "--out", tmp])
        c.check(rc in (None, 0) and len(saved) == 1 and saved[0][0] == "phase_portraits"
                and files_ok(saved[0][2]), "phase_portraits.png and .svg written, not empty (exit %r)" % (rc,))
        if not saved:
            return c.finish()
        fig = saved[0][1]
        axes = fig.axes
        c.check(len(axes) == 3 and all(a.get_xlabel() == "x - x_s [µm]" for a in axes)
                and axes[0].get_ylabel() == "pad velocity x' [m/s]",
                "three panels: x - x_s [µm] across, pad velocity x' [m/s] up")
        titles = [a.get_title().split("\n")[0] for a in axes]
        c.check(titles[0] == "UNSTABLE  v0 = 1.0 m/s (below v_H = %.2f m/s)" % v_h
                and titles[1] == "BISTABLE  v0 = 1.5 m/s" and titles[2] == "STABLE  v0 = 2.5 m/s",
                "titles: the class and v0 of each panel, v_H = %.4f m/s by hand (%s)" % (v_h, titles))
        c.check("a = 2 s/m" in suptitle(fig) and "N = 9 kN" in suptitle(fig), "the brake named in the title")
        counts = [len(legend_texts(a.get_legend())) for a in axes]
        c.check(counts == [3, 5, 4], "legends: 3, 5 and 4 entries (%s)" % counts)
        texts = [t for a in axes for t in legend_texts(a.get_legend())]
        c.check("sticking (x' = v0)" in texts and not no_code_names(texts),
                "the stable panel's sticking stretch in the legend; no code names (%s)" % no_code_names(texts))
        ok = True
        for ax, v0 in zip(axes, V0_MPS):
            stick = [ln for ln in ax.get_lines() if ln.get_linestyle() == "-."]
            steady = [ln for ln in ax.get_lines() if ln.get_marker() == "o"]
            ok = ok and len(stick) == 1 and list(stick[0].get_ydata()) == [v0, v0]
            ok = ok and len(steady) == 1 and list(steady[0].get_xdata()) == [0] and list(steady[0].get_ydata()) == [0]
        c.check(ok, "each panel: the stick line at x' = v0, steady sliding at the origin")

        grow, cycle = paths(axes[0])[:2]
        c.check(abs(grow.get_xdata()[0] - 1.0) < 1e-6 and grow.get_ydata()[0] == 0.0,
                "v0 = 1: the path starts at rest 1 um off steady sliding (%.6f um)" % grow.get_xdata()[0])
        c.check(cycle.get_color() == STICK_RED and abs(top(cycle) - 1.0) < 1e-9,
                "v0 = 1: the stick-slip cycle tops out at x' = v0 = 1 m/s (%.9f)" % top(cycle))

        decay, captured = paths(axes[1])[:2]
        ratio = decay.get_xdata()[0] / captured.get_xdata()[0]
        c.check(abs(ratio - 0.8 / 1.2) < 1e-9, "v0 = 1.5: the two starts at 0.8 and 1.2 x the cycle (%.6f)" % ratio)
        c.check(top(decay) < 1.5 and abs(top(captured) - 1.5) < 1e-9,
                "v0 = 1.5: the decaying path stays below the stick line, the captured one reaches it "
                "(%.4f, %.4f m/s)" % (top(decay), top(captured)))

        small, big = paths(axes[2])[:2]
        sticks = [ln for ln in axes[2].get_lines() if ln.get_color() == STICK_RED]
        c.check(abs(small.get_xdata()[0] - 450.0) < 1e-6 and abs(big.get_xdata()[0] - 600.0) < 1e-6,
                "v0 = 2.5: pushes of 450 and 600 um from rest")
        c.check(top(small) < 2.5 and abs(top(big) - 2.5) < 1e-9 and len(sticks) == 1
                and all(abs(y - 2.5) < 1e-9 for y in sticks[0].get_ydata()),
                "v0 = 2.5: 0.9 v0 stays below the stick line (%.3f m/s), 1.2 v0 sticks once at x' = 2.5 m/s"
                % top(small))
        rc, _, saved = draw("plot_phase", ["--sim", "/bin/false", "--out", tmp])
        c.check(not saved and isinstance(rc, str) and rc.startswith("plot_phase: /bin/false simulate --v0 1.0"),
                "a simulator that fails: one line, nothing drawn (%r)" % (rc[:60] if isinstance(rc, str) else rc))
    return c.finish()


if __name__ == "__main__":
    sys.exit(main())
