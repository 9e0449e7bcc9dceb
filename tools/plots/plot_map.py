#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Stability maps in the (a, v0) plane from `squeal-sim map --csv` (or
`oscsim map --csv`): the simulated truth shaded, the Hopf border, the
exact limit and the paper's cubic limit drawn from their closed forms, and
the simulated bistable/stable border as a dotted line.

usage: plot_map.py MAP.csv [--out DIR] [--brake NAME]
  writes DIR/stability_map.{png,svg} (the default brake, large) and, when
  the CSV holds the variations, DIR/stability_map_variations.{png,svg}.
"""
import csv
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plotlib as P  # noqa: E402
import helptext  # noqa: E402  (tools/, put on the path by plotlib)
from plotlib import plt, np  # noqa: E402
from matplotlib.colors import ListedColormap  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402


def read_map(path):
    by_brake = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            by_brake.setdefault(row["brake"], []).append(row)
    return by_brake


def grid_of(rows):
    a = sorted({float(r["a_spm"]) for r in rows})
    v = sorted({float(r["v0_mps"]) for r in rows})
    ia = {x: i for i, x in enumerate(a)}
    iv = {x: j for j, x in enumerate(v)}
    truth = np.full((len(v), len(a)), np.nan)
    dist = np.full((len(v), len(a)), np.nan)
    exact_bad = []
    cubic_bad = []
    for r in rows:
        i, j = ia[float(r["a_spm"])], iv[float(r["v0_mps"])]
        truth[j, i] = P.STATE_CODE[r["truth"]]
        lq, lb = float(r["ln_q"]), float(r["ln_q_border"])
        # signed distance to the simulated bistable/stable border in ln Q
        # (smooth, so its zero contour is the border without grid steps)
        dist[j, i] = lq - lb if math.isfinite(lb) else np.nan
        pt = (float(r["a_spm"]), float(r["v0_mps"]))
        if r["exact"] != r["truth"]:
            exact_bad.append(pt)
        if r["cubic"] != r["truth"]:
            cubic_bad.append(pt)
    return np.array(a), np.array(v), truth, dist, exact_bad, cubic_bad


def draw(ax, p, rows, big):
    a, v, truth, dist, exact_bad, cubic_bad = grid_of(rows)
    cmap = ListedColormap([P.STATE_COLORS["stable"], P.STATE_COLORS["bistable"],
                           P.STATE_COLORS["unstable"]])
    da, dv = a[1] - a[0], v[1] - v[0]
    ax.pcolormesh(np.append(a - da / 2, a[-1] + da / 2),
                  np.append(v - dv / 2, v[-1] + dv / 2),
                  np.ma.masked_invalid(truth), cmap=cmap, vmin=-0.5, vmax=2.5,
                  shading="flat", rasterized=True)
    # the simulated border between bistable and stable (where Q > 1/2)
    lnq_hopf = np.full_like(dist, np.nan)
    for j, vv in enumerate(v):
        for i, aa in enumerate(a):
            lnq_hopf[j, i] = P.ln_c(p, aa) + aa * vv - math.log(0.5)
    sim = np.where(lnq_hopf > 0, dist, np.nan)
    if np.nanmin(sim) < 0 < np.nanmax(sim):
        # on top of the exact limit, which it follows closely
        ax.contour(a, v, sim, levels=[0.0], colors=LINE_SIM["color"],
                   linewidths=LINE_SIM["lw"] * 2.2, linestyles="dotted",
                   zorder=5)
    a_fine = np.linspace(a[0] * 0.5, a[-1], 600)
    for kind, style in (("hopf", P.LINE_HOPF), ("exact", P.LINE_EXACT),
                        ("cubic", P.LINE_CUBIC)):
        vs = [P.border_v0(p, x, kind) for x in a_fine]
        xs = [x for x, y in zip(a_fine, vs) if y is not None]
        ys = [y for y in vs if y is not None]
        ax.plot(xs, ys, **style)
    if exact_bad:
        ax.plot(*zip(*exact_bad), "x", color=P.LINE_EXACT["color"], ms=4 if big else 3,
                mew=1.0)
    ax.set_xlim(0, a[-1] + da / 2)
    ax.set_ylim(0, v[-1] + dv / 2)
    return len(exact_bad), len(cubic_bad), len(rows)


LINE_SIM = P.LINE_SIM


def legend_handles(with_bad):
    h = [Patch(color=P.STATE_COLORS[s], label="simulated: " + P.state_label(s))
         for s in ("unstable", "bistable", "stable")]
    h += [Line2D([], [], label="Hopf border  Q = 1/2", **P.LINE_HOPF),
          Line2D([], [], label="exact limit  Q = I1(s)/s  (firmware default)", **P.LINE_EXACT),
          Line2D([], [], label="cubic limit  Q = 1/2 + s²/16  (paper)", **P.LINE_CUBIC),
          Line2D([], [], color="k", lw=2.2, ls=":", label="simulated bistable/stable border")]
    if with_bad:
        h.append(Line2D([], [], color=P.LINE_EXACT["color"], marker="x", ls="",
                        label="exact criterion disagrees with simulation"))
    return h


def main():
    ap = helptext.parser(__doc__, "tools/plots/plot_map.py")
    ap.add_argument("csv", metavar="MAP.csv", help="output of squeal-sim map --csv or oscsim map --csv")
    ap.add_argument("--out", default="build/plots", metavar="DIR", help="folder for the pictures (default build/plots)")
    ap.add_argument("--brake", default="default", metavar="NAME", help="brake of the large map: default, d0.05, d0.1, k2, k0.5, n5000 or n20000")
    args = ap.parse_args()
    maps = read_map(args.csv)
    if args.brake not in maps:
        sys.exit(f"plot_map: brake {args.brake!r} not in {args.csv}")

    p = P.BRAKES[args.brake]
    fig, ax = plt.subplots(figsize=(9.0, 7.4))
    ne, nc, n = draw(ax, p, maps[args.brake], True)
    ax.set_xlabel("friction slope a [s/m]")
    ax.set_ylabel("disc surface speed v0 [m/s]")
    ax.set_title(f"Stability of steady sliding: {P.BRAKE_TITLES.get(args.brake, args.brake)}\n"
                 f"simulation of {n} points; exact criterion agrees at {100.0 * (n - ne) / n:.2f} %, "
                 f"cubic at {100.0 * (n - nc) / n:.2f} %", fontsize=10)
    ax.text(0.6, 0.25, "UNSTABLE", fontsize=13, weight="bold", color="#8c2d04")
    a_lab = 4.2
    vb = 0.5 * (P.border_v0(p, a_lab, "hopf") + P.border_v0(p, a_lab, "exact"))
    ax.text(a_lab, vb, "BISTABLE", fontsize=11, weight="bold", color="#7f5f00",
            ha="center", va="center")
    ax.text(0.75, 0.93, "STABLE", fontsize=13, weight="bold", color="#1b5e20",
            transform=ax.transAxes)
    ax.annotate("cubic limit calls these\nbistable points stable\n(it under-warns)",
                xy=(3.0, 0.5 * (P.border_v0(p, 3.0, "cubic") + P.border_v0(p, 3.0, "exact"))),
                xytext=(4.3, 2.55), fontsize=8.5,
                arrowprops=dict(arrowstyle="->", color="#4d4d4d"))
    fig.legend(handles=legend_handles(ne > 0), loc="lower center", ncol=2,
               fontsize=8.5, frameon=False)
    fig.tight_layout(rect=(0, 0.15, 1, 1))
    out = P.save(fig, args.out, "stability_map")

    others = [b for b in ("d0.05", "d0.1", "k2", "k0.5", "n5000", "n20000") if b in maps]
    if others:
        fig, axes = plt.subplots(2, 3, figsize=(12.0, 7.4), sharex=True, sharey=True)
        any_bad = False
        for ax, b in zip(axes.flat, others):
            ne, nc, n = draw(ax, P.BRAKES[b], maps[b], False)
            any_bad = any_bad or ne > 0
            ax.set_title(f"{P.BRAKE_TITLES[b]}\nexact {100.0 * (n - ne) / n:.2f} %, "
                         f"cubic {100.0 * (n - nc) / n:.2f} % agree", fontsize=9)
        for ax in axes[1, :]:
            ax.set_xlabel("a [s/m]")
        for ax in axes[:, 0]:
            ax.set_ylabel("v0 [m/s]")
        fig.legend(handles=legend_handles(any_bad), loc="lower center", ncol=4, fontsize=8)
        fig.suptitle("The paper's variations: simulated classes and the three borders", fontsize=11)
        fig.tight_layout(rect=(0, 0.08, 1, 0.96))
        out += P.save(fig, args.out, "stability_map_variations")
    for path in out:
        print(path)


if __name__ == "__main__":
    main()
