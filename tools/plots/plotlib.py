# SPDX-License-Identifier: MIT
"""Shared pieces of the plotting scripts: the brake's closed-form borders, colours and file output.

The borders are those of docs/model.md (the Hopf border and the stability
limit), computed here independently of the firmware, in double precision
with scipy. The style (150 dpi, state and warning names in words, legend
entries for the region fills, the stretched speed axis) is the one every
picture of the project uses. A module the plotting scripts import.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
import deps  # noqa: E402  (names the Debian package of a missing module)

deps.need("numpy", "scipy", "matplotlib")

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from scipy.optimize import brentq  # noqa: E402
from scipy.special import i1e  # noqa: E402

DEFAULT = dict(mass=1.0, omega0=5000.0, damping=0.023, mu_inf=0.25,
               delta_mu=0.15, slope=2.0, force=9000.0)

# the paper's variations, as in host-sim/oscsim/oscsim_map.c
BRAKES = {
    "default": dict(DEFAULT),
    "d0.05": dict(DEFAULT, damping=0.05),
    "d0.1": dict(DEFAULT, damping=0.1),
    "k2": dict(DEFAULT, omega0=5000.0 * math.sqrt(2.0)),
    "k0.5": dict(DEFAULT, omega0=5000.0 * math.sqrt(0.5)),
    "n5000": dict(DEFAULT, force=5000.0),
    "n20000": dict(DEFAULT, force=20000.0),
}
BRAKE_TITLES = {
    "default": "paper's brake (D 0.023, w0 5000 rad/s, N 9 kN)",
    "d0.05": "damping D = 0.05", "d0.1": "damping D = 0.1",
    "k2": "stiffness x2", "k0.5": "stiffness x0.5",
    "n5000": "pad force 5 kN", "n20000": "pad force 20 kN",
}

STATE_COLORS = {"stable": "#cfe8cf", "bistable": "#ffe08a",
                "unstable": "#f4a6a0", "not_sliding": "#dddddd"}
# the state the monitor reported (paths, live view, fleet heat map)
PATH_COLORS = {"stable": "#1a9850", "bistable": "#d98e04", "unstable": "#b2182b",
               "not_sliding": "#737373", "fault": "#542788"}
STATE_CODE = {"stable": 0, "bistable": 1, "unstable": 2, "not_sliding": 3}
# what a reader sees for a state (legends, titles): never the code name
STATE_LABELS = {"stable": "stable", "bistable": "bistable (squeal possible after a kick)",
                "unstable": "unstable (squeal)", "not_sliding": "not sliding",
                "fault": "fault (inputs stale or implausible)"}
STATE_SHORT = {"stable": "stable", "bistable": "bistable", "unstable": "unstable",
               "not_sliding": "not sliding", "fault": "fault"}
# WarningLevel 0..3 (firmware/protocol/squeal.dbc)
WARNING_NAMES = ("none", "advisory", "warning", "critical")
WARNING_TICKS = tuple("%d %s" % kv for kv in enumerate(WARNING_NAMES))
LINE_HOPF = dict(color="#b2182b", lw=2.0)
LINE_EXACT = dict(color="#2166ac", lw=2.0)
LINE_CUBIC = dict(color="#4d4d4d", lw=1.6, ls="--")
LINE_SIM = dict(color="k", lw=1.0, ls=":")


def ln_i1_over_x(s):
    """ln(I1(s)/s), overflow-free (i1e(s) = I1(s) e^-s)."""
    s = np.asarray(s, dtype=float)
    small = s < 1e-6
    out = np.empty_like(s)
    out[small] = math.log(0.5)
    ss = s[~small]
    out[~small] = np.log(i1e(ss)) + ss - np.log(ss)
    return out


def ln_c(p, a):
    """ln(D w0 m / (a N dmu)): ln Q = ln_c + a v0."""
    return math.log(p["damping"] * p["omega0"] * p["mass"] /
                    (a * p["force"] * p["delta_mu"]))


def _solve_s(fn, target):
    """s > 0 with fn(s) - s = target, fn(s) - s strictly decreasing from
    ln(1/2) at s = 0; None when target >= ln(1/2)."""
    if target >= math.log(0.5):
        return None
    g = lambda s: fn(s) - s - target
    hi = 1.0
    while g(hi) > 0:
        hi *= 2.0
    return brentq(g, 0.0, hi, xtol=1e-13)


def border_v0(p, a, kind):
    """The speed of a border at slope a: 'hopf', 'exact' or 'cubic'.
    Below it the point is more critical. None if the border does not exist."""
    c = ln_c(p, a)
    if kind == "hopf":
        v = (math.log(0.5) - c) / a
        return v if v > 0 else None
    if kind == "exact":
        s = _solve_s(lambda x: float(ln_i1_over_x(np.array([x]))[0]), c)
    else:
        s = _solve_s(lambda x: math.log(0.5 + x * x / 16.0), c)
    return None if s is None else s / a


def force_border(p, v0, kind):
    """Pad force of a border at speed v0 (above it: more critical)."""
    a, s = p["slope"], p["slope"] * v0
    base = p["damping"] * p["omega0"] * p["mass"] / (a * p["delta_mu"])
    if kind == "hopf":
        lim = math.log(0.5)
    elif kind == "exact":
        lim = float(ln_i1_over_x(np.array([s]))[0])
    else:
        lim = math.log(0.5 + s * s / 16.0)
    # ln Q = ln(base / N) + s = lim
    return base * math.exp(s - lim)


def classify(p, v0, force, criterion="exact"):
    """Closed-form class of one point (for the drive plot's background)."""
    if v0 <= 0 or force <= 0:
        return "not_sliding"
    a = p["slope"]
    lnq = math.log(p["damping"] * p["omega0"] * p["mass"] /
                   (a * force * p["delta_mu"])) + a * v0
    s = a * v0
    if lnq <= math.log(0.5):
        return "unstable"
    lim = (float(ln_i1_over_x(np.array([s]))[0]) if criterion == "exact"
           else math.log(0.5 + s * s / 16.0))
    return "bistable" if lnq < lim else "stable"


# ---- the one style of every picture -----------------------------------------

DPI = 150            # PNG resolution; every PNG has an SVG beside it
STYLE = {"font.size": 9.0, "axes.titlesize": 10.0, "axes.labelsize": 9.0,
         "legend.fontsize": 8.0, "legend.framealpha": 0.92, "xtick.labelsize": 8.5,
         "ytick.labelsize": 8.5, "axes.grid": False, "grid.alpha": 0.3,
         "savefig.dpi": DPI, "figure.dpi": 100, "svg.hashsalt": "squeal",
         "svg.fonttype": "path"}
matplotlib.rcParams.update(STYLE)


def state_label(name):
    return STATE_LABELS.get(name, name)


def region_handles(states=("unstable", "bistable", "stable"), alpha=1.0, prefix="region: "):
    """Legend entries of the map's fills, in the words of the legend."""
    from matplotlib.patches import Patch
    return [Patch(facecolor=STATE_COLORS[s], alpha=alpha, edgecolor="0.6", lw=0.5,
                  label=prefix + STATE_LABELS[s]) for s in states]


def reported_handles(states, prefix="reported ", short=False):
    """Legend entries of what the monitor reported (paths, trails, cells);
    short: without the explanation (when the regions' entries give it)."""
    from matplotlib.patches import Patch
    names = STATE_SHORT if short else STATE_LABELS
    return [Patch(color=PATH_COLORS[s], label=prefix + names[s]) for s in states]


def limit_kind(criterion):
    return "cubic" if criterion == "cubic" else "exact"


def stable_speed(p, n_n, criterion="exact"):
    """The speed [m/s] at which the stability limit reaches pad force n_n:
    above it every force up to n_n is stable (where the borders end)."""
    kind = limit_kind(criterion)
    g = lambda v: force_border(p, v, kind) - n_n
    if g(1e-6) >= 0:
        return 1e-6
    hi = 1.0
    while g(hi) < 0 and hi < 1e3:
        hi *= 2.0
    return brentq(g, 1e-6, hi, xtol=1e-9)


class SpeedZoom:
    """A v0 axis stretched where the borders are: 0..v_zoom takes FRAC of
    the axis, v_zoom..v_max the rest (linear in each part)."""
    FRAC = 0.6

    def __init__(self, v_zoom, v_max):
        self.v_zoom, self.v_max = float(v_zoom), float(v_max)
        self.k = (self.v_zoom * (1.0 - self.FRAC) / self.FRAC) / (self.v_max - self.v_zoom)

    def forward(self, v):
        v = np.asarray(v, dtype=float)
        return np.where(v <= self.v_zoom, v, self.v_zoom + (v - self.v_zoom) * self.k)

    def inverse(self, u):
        u = np.asarray(u, dtype=float)
        return np.where(u <= self.v_zoom, u, self.v_zoom + (u - self.v_zoom) / self.k)

    def grid(self, n_zoom=240, n_rest=80):
        """Sample speeds, as dense on the axis in both parts."""
        return np.concatenate([np.linspace(self.v_zoom / n_zoom, self.v_zoom, n_zoom),
                               np.linspace(self.v_zoom, self.v_max, n_rest + 1)[1:]])


def speed_zoom(p, v_max, n_max_n, criterion="exact"):
    """The zoom for a map up to (v_max, n_max_n), or None when the borders
    already fill more than half of the axis."""
    v_end = stable_speed(p, n_max_n, criterion)
    v_zoom = math.ceil(1.15 * v_end * 2.0) / 2.0   # a round 0.5 m/s past the last border
    return SpeedZoom(v_zoom, v_max) if v_zoom < 0.5 * v_max else None


def _nice_step(span, n):
    raw = span / max(n, 1)
    for step in (0.25, 0.5, 1.0, 2.0, 2.5, 5.0, 10.0, 20.0, 50.0):
        if step >= raw:
            return step
    return raw


def apply_speed_zoom(ax, zoom):
    """Put the stretched scale on ax's x axis, with round ticks in each
    part, the break marked and said in the axis label."""
    ax.set_xscale("function", functions=(zoom.forward, zoom.inverse))
    s1 = _nice_step(zoom.v_zoom, 6)
    s2 = _nice_step(zoom.v_max - zoom.v_zoom, 4)
    lo = list(np.arange(0.0, zoom.v_zoom + 1e-9, s1))
    hi = [x for x in np.arange(math.ceil(zoom.v_zoom / s2) * s2, zoom.v_max + 1e-9, s2)
          if x > zoom.v_zoom + 0.3 * s2]
    ax.set_xticks(lo + hi)
    ax.set_xticklabels(["%g" % x for x in lo + hi])
    ax.axvline(zoom.v_zoom, color="0.35", lw=0.9, ls=(0, (4, 3)), zorder=6)
    ax.set_xlim(0.0, zoom.v_max)
    ax.set_xlabel("disc surface speed v0 [m/s]  (0-%g m/s stretched, %g-%g m/s compressed)"
                  % (zoom.v_zoom, zoom.v_zoom, zoom.v_max))


def draw_map(ax, p, v_max, n_max_n, criterion="exact", alpha=1.0, cubic=False, zoom=True):
    """The stability map of brake p over v0 in (0, v_max] m/s and N in
    (0, n_max_n] N (axes in m/s and kN): the regions from the closed forms,
    the Hopf border and the stability limit as labelled lines (and the
    paper's cubic limit with cubic=True). With zoom the v0 axis is stretched
    where the borders are (SpeedZoom). Returns the zoom or None."""
    from matplotlib.colors import ListedColormap
    z = speed_zoom(p, v_max, n_max_n, criterion) if zoom else None
    vv = z.grid() if z is not None else np.linspace(v_max / 400.0, v_max, 300)
    nn = np.linspace(n_max_n / 300.0, n_max_n, 240)
    code = np.array([[STATE_CODE[classify(p, x, y, criterion)] for x in vv] for y in nn])
    cmap = ListedColormap([STATE_COLORS["stable"], STATE_COLORS["bistable"],
                           STATE_COLORS["unstable"]])
    ax.pcolormesh(vv, nn / 1000.0, code, cmap=cmap, vmin=-0.5, vmax=2.5, shading="auto",
                  rasterized=True, alpha=alpha)
    lim = limit_kind(criterion)
    lines = [("hopf", LINE_HOPF, "Hopf border (unstable above)"),
             (lim, LINE_EXACT, "%s stability limit (bistable above)" % lim)]
    if cubic and lim != "cubic":
        lines.append(("cubic", LINE_CUBIC, "cubic limit (paper)"))
    for kind, style, lab in lines:
        ys = np.array([force_border(p, x, kind) / 1000.0 for x in vv])
        ax.plot(vv, np.where(np.isfinite(ys), ys, np.nan), label=lab, **style)
    ax.set_xlim(0, v_max)
    ax.set_ylim(0, n_max_n / 1000.0)
    ax.set_xlabel("disc surface speed v0 [m/s]")
    ax.set_ylabel("pad force N [kN]")
    if z is not None:
        apply_speed_zoom(ax, z)
    return z


def map_legend(ax, extra=(), region_alpha=1.0, **kw):
    """One legend for a map: its lines, its fills, then extra handles."""
    handles, _ = ax.get_legend_handles_labels()
    handles = list(handles) + region_handles(alpha=region_alpha) + list(extra)
    return ax.legend(handles=handles, **dict(dict(fontsize=7.5, loc="upper right"), **kw))


# ---- files -----------------------------------------------------------------

def _style_rgb():
    """The style's own colours (fills, reported states, lines, black, white)."""
    from matplotlib.colors import to_rgb
    cols = list(STATE_COLORS.values()) + list(PATH_COLORS.values()) + [
        LINE_HOPF["color"], LINE_EXACT["color"], LINE_CUBIC["color"], "#000000", "#ffffff"]
    out = []
    for c in cols:
        rgb = tuple(int(round(255 * x)) for x in to_rgb(c))
        if rgb not in out:
            out.append(rgb)
    return out


def _shrink_png(path):
    """A 256-colour palette: adaptive, plus the style's own colours exactly
    (a state's colour stays that colour); line art loses nothing visible and
    the committed pictures stay small (README, docs/img)."""
    from PIL import Image
    fixed = _style_rgb()
    with Image.open(path) as im:
        rgb = im.convert("RGB")
    n = 256 - len(fixed)
    adaptive = rgb.quantize(colors=n, method=Image.Quantize.MEDIANCUT
                            if hasattr(Image, "Quantize") else 0)
    pal = (adaptive.getpalette()[:3 * n] + [0] * (3 * n))[:3 * n]
    for c in fixed:
        pal += list(c)
    ref = Image.new("P", (1, 1))
    ref.putpalette(pal)
    nodither = Image.Dither.NONE if hasattr(Image, "Dither") else 0
    q = rgb.quantize(palette=ref, dither=nodither)
    # Pillow's palette look-up is approximate: entries a few steps off a
    # style colour (the white background) become that colour
    got = q.getpalette()
    for i in range(len(got) // 3):
        e = got[3 * i:3 * i + 3]
        near = [c for c in fixed if max(abs(a - b) for a, b in zip(c, e)) <= 6]
        if near:
            got[3 * i:3 * i + 3] = list(near[0])
    q.putpalette(got)
    q.save(path, optimize=True, dpi=(DPI, DPI))


def save_as(fig, png_path, tight=True):
    """fig as png_path (DPI) and the SVG beside it; closes fig; returns
    [png, svg]. tight=False keeps the figure's own size (pixel positions
    scale with DPI / fig.dpi)."""
    bbox = "tight" if tight else None
    d = os.path.dirname(png_path)
    if d:
        os.makedirs(d, exist_ok=True)
    svg_path = os.path.splitext(png_path)[0] + ".svg"
    fig.savefig(png_path, dpi=DPI, bbox_inches=bbox)
    _shrink_png(png_path)
    fig.savefig(svg_path, format="svg", bbox_inches=bbox, metadata={"Date": None})
    plt.close(fig)
    return [png_path, svg_path]


def save(fig, out_dir, name):
    """fig as OUT_DIR/NAME.png and .svg (save_as)."""
    return save_as(fig, os.path.join(out_dir, name + ".png"))


if __name__ == "__main__":
    import helptext
    helptext.module_main(__doc__, "tools/plots/plotlib.py")
