#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Phase portraits (x, x') of the full stick-slip oscillator at three
operating points of the paper's brake (a = 2 s/m, N = 9 kN), simulated by
`simulate` (oscsim or squeal-sim):
  unstable  v0 = 1.0 m/s: a tiny disturbance grows into stick-slip;
  bistable  v0 = 1.5 m/s: the unstable sliding cycle separates decay (start
            at 0.8 x the cycle) from capture by the stick-slip cycle (1.2 x);
  stable    v0 = 2.5 m/s: even a push beyond the stick line dies out.

usage: plot_phase.py [--sim PATH] [--out DIR]   writes DIR/phase_portraits.{png,svg}
"""
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plotlib as P  # noqa: E402
import helptext  # noqa: E402  (tools/, put on the path by plotlib)
from plotlib import plt, np  # noqa: E402

BRAKE = ["--slope", "2", "--force", "9000"]


def sim(tool, args):
    out = subprocess.run([tool, "simulate"] + BRAKE + args, capture_output=True,
                         text=True, timeout=120)
    if out.returncode != 0:
        sys.exit(f"plot_phase: {tool} simulate {' '.join(args)} failed: {out.stderr}")
    return out.stdout


def trajectory(tool, args):
    t, x, v, stick = [], [], [], []
    for line in sim(tool, args).splitlines()[1:]:
        kind, tt, xx, vv, mode = line.split(",")
        if kind == "switch":
            continue
        t.append(float(tt))
        x.append(float(xx))
        v.append(float(vv))
        stick.append(mode == "stick")
    return np.array(t), np.array(x), np.array(v), np.array(stick)


def keyvals(text):
    return dict(tok.split("=", 1) for tok in text.split() if "=" in tok)


def steady_x(v0):
    p = P.DEFAULT
    mu = p["mu_inf"] + p["delta_mu"] * np.exp(-p["slope"] * v0)
    return p["force"] * mu / (p["mass"] * p["omega0"] ** 2)


def draw_path(ax, x, v, xs, **kw):
    ax.plot((x - xs) * 1e6, v, **kw)


def stick_line(ax, v0):
    ax.axhline(v0, color="#8c2d04", lw=1.0, ls="-.")
    ax.text(0.02, v0, " stick line x' = v0", color="#8c2d04", fontsize=8,
            va="bottom", transform=ax.get_yaxis_transform())


def main():
    ap = helptext.parser(__doc__, "tools/plots/plot_phase.py")
    ap.add_argument("--sim", default="build/host/oscsim",
                    help="program with a 'simulate' subcommand")
    ap.add_argument("--out", default="build/plots", metavar="DIR", help="folder for phase_portraits.png and .svg (default build/plots)")
    args = ap.parse_args()
    tool = args.sim
    fig, axes = plt.subplots(1, 3, figsize=(15.0, 5.4))

    # unstable: growth from 1 µm into the stick-slip cycle
    ax = axes[0]
    v0 = 1.0
    xs = steady_x(v0)
    t, x, v, st = trajectory(tool, ["--v0", str(v0), "--dx", "1e-6", "--t-end", "0.085",
                                    "--dt", "1e-5"])
    late = t > 0.08
    draw_path(ax, x[~late], v[~late], xs, color="#6baed6", lw=0.6,
              label="from 1 µm off steady sliding")
    draw_path(ax, x[late], v[late], xs, color="#b2182b", lw=1.8,
              label="stick-slip cycle (t > 80 ms)")
    ax.plot([0], [0], "o", color="k", ms=4, label="steady sliding (unstable)")
    stick_line(ax, v0)
    ax.set_title("UNSTABLE  v0 = 1.0 m/s (below v_H = 1.23 m/s)\n"
                 "disturbances grow into stick-slip", fontsize=10)

    # bistable: the unstable cycle separates decay and capture
    ax = axes[1]
    v0 = 1.5
    xs = steady_x(v0)
    tr = keyvals(sim(tool, ["--v0", str(v0), "--truth"]))
    cyc = [line.split(",") for line in sim(tool, ["--v0", str(v0), "--cycle"]).splitlines()[1:]]
    cx = np.array([float(r[2]) for r in cyc])
    cv = np.array([float(r[3]) for r in cyc])
    r_cyc = float(tr["r"])
    a_m = r_cyc / (2.0 * 5000.0)
    t, x, v, st = trajectory(tool, ["--v0", str(v0), "--dx", repr(0.8 * a_m),
                                    "--t-end", "0.02", "--dt", "1e-5"])
    draw_path(ax, x, v, xs, color="#1a9850", lw=0.6, label="start 0.8 x cycle: decays")
    t, x, v, st = trajectory(tool, ["--v0", str(v0), "--dx", repr(1.2 * a_m),
                                    "--t-end", "0.025", "--dt", "1e-5"])
    late = t > 0.02
    draw_path(ax, x[~late], v[~late], xs, color="#fdae61", lw=0.8,
              label="start 1.2 x cycle: captured")
    draw_path(ax, x[late], v[late], xs, color="#b2182b", lw=1.8, label="stick-slip cycle")
    draw_path(ax, cx, cv, xs, color="k", lw=2.0, ls="--",
              label=f"unstable sliding cycle (max x' = {float(tr['cycle_x']) / 2.0:.2f} m/s)")
    ax.plot([0], [0], "o", color="k", ms=4, label="steady sliding (stable)")
    stick_line(ax, v0)
    ax.set_title("BISTABLE  v0 = 1.5 m/s\nthe unstable cycle is the border of safety",
                 fontsize=10)

    # stable: a push past the stick line still dies out
    ax = axes[2]
    v0 = 2.5
    xs = steady_x(v0)
    stick_lab = "sticking (x' = v0)"
    for dx, col, lab in ((4.5e-4, "#1a9850", "push to 0.9 v0: decays"),
                         (6e-4, "#4575b4", "push to the stick line: sticks once, decays")):
        t, x, v, st = trajectory(tool, ["--v0", str(v0), "--dx", repr(dx), "--t-end", "0.015",
                                        "--dt", "1e-5"])
        draw_path(ax, x, v, xs, color=col, lw=0.6, label=lab)
        if st.any():
            draw_path(ax, x[st], v[st], xs, color="#b2182b", lw=2.5, label=stick_lab)
            stick_lab = None
    ax.plot([0], [0], "o", color="k", ms=4, label="steady sliding (stable)")
    stick_line(ax, v0)
    ax.set_title("STABLE  v0 = 2.5 m/s\nno sliding cycle below the stick line", fontsize=10)

    for ax in axes:
        ax.set_xlabel("x - x_s [µm]")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7.5, loc="lower left", framealpha=0.9)
    axes[0].set_ylabel("pad velocity x' [m/s]")
    fig.suptitle("Phase portraits of the stick-slip oscillator (paper's brake, a = 2 s/m, "
                 "N = 9 kN), simulated with sticking", fontsize=11)
    fig.tight_layout(rect=(0, 0, 1, 0.95))
    for path in P.save(fig, args.out, "phase_portraits"):
        print(path)


if __name__ == "__main__":
    main()
