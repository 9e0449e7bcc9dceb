#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""A replayed drive over the stability map: the path of the operating
point (v0, N) over the brake's map in the (v0, N) plane, coloured by the
state the monitor reported, and a time plot of speed, force, state and
warning level.

input CSV columns: time_s,v0_mps,force_n,state,warning
  state: a number (0 stable, 1 bistable, 2 unstable, 3 not sliding,
  15 fault) or its name; warning: 0..3. Extra columns are ignored.
or the output of `squeal-sim decode --csv` (one row per frame, recognised
  by its message and SquealState columns): the monitor's V0_mps, Force_N,
  SquealState and WarningLevel are forward-filled and one point is taken
  per SquealStatus frame (before the first SquealDetail frames: the inputs
  DiscSpeed_radps x --pad-radius and PadForce_N). E.g.
    squeal-sim plant --log in.log --scenario sweep
    squeal-sim replay in.log > out.log
    sort -s -k1,1 in.log out.log | squeal-sim decode --csv > drive.csv
The map background and borders come from the closed forms (docs/model.md,
exact criterion) for the brake given by the options (default: the
paper's brake at a = 2 s/m).

usage: plot_drive.py DRIVE.csv [--out DIR] [--name NAME] [--slope A]
         [--damping D] [--omega0 W] [--mass M] [--delta-mu Y]
writes DIR/NAME.{png,svg} (NAME default: drive)
"""
import csv
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plotlib as P  # noqa: E402
import helptext  # noqa: E402  (tools/, put on the path by plotlib)
from plotlib import plt, np  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402

NAMES = {0: "stable", 1: "bistable", 2: "unstable", 3: "not_sliding", 15: "fault"}
PATH_COLORS = P.PATH_COLORS


def state_name(text):
    text = text.strip()
    try:
        return NAMES.get(int(float(text)), "fault")
    except ValueError:
        return text if text in PATH_COLORS else "fault"


def _num(text):
    try:
        x = float(text)
    except (TypeError, ValueError):
        return None
    return x if math.isfinite(x) else None


def read_decode(rd, pad_radius):
    """Rows of `squeal-sim decode --csv` to the drive's series."""
    t, v, n, st, w = [], [], [], [], []
    last = {}
    for row in rd:
        for key in ("V0_mps", "Force_N", "DiscSpeed_radps", "PadForce_N", "SquealState",
                    "WarningLevel"):
            x = _num(row.get(key))
            if x is not None:
                last[key] = x
        if row.get("message") != "SquealStatus" or "SquealState" not in last:
            continue
        v0 = last.get("V0_mps")
        if v0 is None and "DiscSpeed_radps" in last:
            v0 = last["DiscSpeed_radps"] * pad_radius
        force = last.get("Force_N", last.get("PadForce_N"))
        if v0 is None or force is None:
            continue
        t.append(float(row["time_s"]))
        v.append(v0)
        n.append(force)
        st.append(state_name(str(int(last["SquealState"]))))
        w.append(last.get("WarningLevel", 0.0))
    return t, v, n, st, w


def read_drive(path, pad_radius=0.12):
    t, v, n, st, w = [], [], [], [], []
    with open(path, newline="") as f:
        rd = csv.DictReader(f)
        if {"message", "SquealState"}.issubset(rd.fieldnames or []):
            t, v, n, st, w = read_decode(rd, pad_radius)
            if not t:
                sys.exit(f"plot_drive: {path} has no SquealStatus frames with a known operating point")
            return np.array(t), np.array(v), np.array(n), st, np.array(w)
        need = {"time_s", "v0_mps", "force_n", "state", "warning"}
        if not need.issubset(rd.fieldnames or []):
            sys.exit(f"plot_drive: {path} needs columns {sorted(need)}")
        for row in rd:
            t.append(float(row["time_s"]))
            v.append(float(row["v0_mps"]))
            n.append(float(row["force_n"]))
            st.append(state_name(row["state"]))
            w.append(float(row["warning"]))
    if not t:
        sys.exit(f"plot_drive: {path} has no rows")
    return np.array(t), np.array(v), np.array(n), st, np.array(w)


def main():
    ap = helptext.parser(__doc__, "tools/plots/plot_drive.py")
    ap.add_argument("csv", metavar="DRIVE.csv", help="drive CSV (columns above) or squeal-sim decode --csv output")
    ap.add_argument("--out", default="build/plots", metavar="DIR", help="folder for NAME.png and NAME.svg (default build/plots)")
    ap.add_argument("--name", default="drive", help="file name without extension (default drive)")
    ap.add_argument("--pad-radius", type=float, default=0.12,
                    help="r_p [m] for v0 from DiscSpeed_radps (decode CSV only)")
    for opt, key in (("--slope", "slope"), ("--damping", "damping"), ("--omega0", "omega0"),
                     ("--mass", "mass"), ("--delta-mu", "delta_mu")):
        ap.add_argument(opt, type=float, default=P.DEFAULT[key], dest=key,
                        help="brake parameter %s of the map (default %g)" % (key, P.DEFAULT[key]))
    args = ap.parse_args()
    p = dict(P.DEFAULT)
    for key in ("slope", "damping", "omega0", "mass", "delta_mu"):
        p[key] = getattr(args, key)
    t, v, n, st, w = read_drive(args.csv, args.pad_radius)

    fig = plt.figure(figsize=(14.0, 7.0))
    gs = fig.add_gridspec(4, 2, width_ratios=(1.15, 1.0), hspace=0.15, wspace=0.22)
    ax = fig.add_subplot(gs[:, 0])
    v_max = max(1.1 * float(v.max()), 0.5)
    n_max = max(1.15 * float(n.max()), 1000.0)
    P.draw_map(ax, p, v_max, n_max, cubic=True)
    # the path, segment by segment in the reported state's colour
    for i in range(len(t) - 1):
        ax.plot(v[i:i + 2], n[i:i + 2] / 1000.0, color=PATH_COLORS[st[i]], lw=2.4,
                solid_capstyle="round")
    ax.plot(v[0], n[0] / 1000.0, "o", color="k", ms=6)
    ax.annotate("start", (v[0], n[0] / 1000.0), textcoords="offset points", xytext=(6, 6),
                fontsize=8)
    ax.plot(v[-1], n[-1] / 1000.0, "s", color="k", ms=6)
    ax.annotate("end", (v[-1], n[-1] / 1000.0), textcoords="offset points", xytext=(6, -12),
                fontsize=8)
    ax.set_title(f"Operating point over the map (a = {p['slope']:g} s/m, D = {p['damping']:g})",
                 fontsize=10)
    seen = [s for s in P.PATH_COLORS if s in st]
    paths = [Line2D([], [], color=PATH_COLORS[s], lw=2.4, label="path: " + P.state_label(s))
             for s in seen]
    # below the map: the legend must not hide the path
    P.map_legend(ax, paths, loc="upper center", bbox_to_anchor=(0.5, -0.09), ncol=2,
                 fontsize=7.5, frameon=False)

    axs = [fig.add_subplot(gs[i, 1]) for i in range(4)]
    axs[0].plot(t, v, color="#2166ac")
    axs[0].set_ylabel("v0 [m/s]")
    axs[1].plot(t, n / 1000.0, color="#4d4d4d")
    axs[1].set_ylabel("N [kN]")
    order = ("stable", "bistable", "unstable", "not_sliding", "fault")
    codes = [order.index(s) for s in st]
    axs[2].step(t, codes, where="post", color="k", lw=1.0)
    for i in range(len(t) - 1):
        axs[2].axvspan(t[i], t[i + 1], color=PATH_COLORS[st[i]], alpha=0.35, lw=0)
    axs[2].set_yticks([0, 1, 2, 3, 4])
    axs[2].set_yticklabels([P.STATE_SHORT[s] for s in order], fontsize=7)
    axs[2].set_ylabel("reported state")
    axs[3].step(t, w, where="post", color="#b2182b")
    axs[3].set_yticks([0, 1, 2, 3])
    axs[3].set_yticklabels(P.WARNING_TICKS, fontsize=7)
    axs[3].set_ylim(-0.3, 3.3)
    axs[3].set_ylabel("warning level")
    axs[3].set_xlabel("time [s]")
    for a in axs:
        a.grid(alpha=0.3)
        a.set_xlim(t[0], t[-1] if t[-1] > t[0] else t[0] + 1.0)
    for a in axs[:-1]:
        a.tick_params(labelbottom=False)
    fig.suptitle("Replayed drive: where the brake operated, and what the monitor said",
                 fontsize=11)
    for path in P.save(fig, args.out, args.name):
        print(path)


if __name__ == "__main__":
    main()
