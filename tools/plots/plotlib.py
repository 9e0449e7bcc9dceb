# SPDX-License-Identifier: MIT
"""Shared pieces of the plotting scripts: the brake's closed-form borders
(shared/model.md sections 2-4, computed here independently of the
firmware, in double precision with scipy), colours and file output."""
import math
import os

import matplotlib
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


def _shrink_png(path):
    """Adaptive 256-colour palette: line art loses nothing visible and the
    committed pictures stay small (README, docs/img)."""
    from PIL import Image
    with Image.open(path) as im:
        q = im.convert("RGB").quantize(colors=256, method=Image.Quantize.MEDIANCUT
                                       if hasattr(Image, "Quantize") else 0)
    q.save(path, optimize=True)


def save(fig, out_dir, name):
    os.makedirs(out_dir, exist_ok=True)
    paths = []
    for ext in ("png", "svg"):
        path = os.path.join(out_dir, f"{name}.{ext}")
        fig.savefig(path, dpi=90 if ext == "png" else None,
                    bbox_inches="tight", metadata={"Date": None} if ext == "svg" else None)
        if ext == "png":
            _shrink_png(path)
        paths.append(path)
    plt.close(fig)
    return paths
