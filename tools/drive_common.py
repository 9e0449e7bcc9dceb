# SPDX-License-Identifier: MIT
"""Shared pieces of the drive tools (fleet.py, live_view.py): the brake and
the identifiers of a calibration text file, the corners, and the stability
map drawn under a drive.

The map's regions and borders come from tools/plots/plotlib.py: the closed
forms of shared/model.md (Hopf border Q = 1/2; the exact criterion's limit
ln 2Q = ln(2 I1(s)/s), or the paper's cubic one), in double precision with
scipy, independent of the firmware.
"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(HERE, "plots"))
import plotlib as P  # noqa: E402  (selects matplotlib's Agg backend)

SIM = os.path.join(ROOT, "build", "host", "squeal-sim")
DBC = os.path.join(ROOT, "firmware", "protocol", "squeal.dbc")
CORNERS = ("FL", "FR", "RL", "RR")
CORNER_ID_STEP = 0x10  # corner k sends on today's identifiers + 0x10 k (issue 11)
STATES = ("stable", "bistable", "unstable", "not_sliding", "fault")

# calibration key -> (plotlib brake key); see docs/calib-example.txt
_BRAKE_KEYS = {"mass_kg": "mass", "omega0_radps": "omega0", "damping": "damping",
               "mu_inf": "mu_inf", "delta_mu": "delta_mu", "slope_spm": "slope"}
_ID_KEYS = ("status_id", "detail_id", "detail2_id")
_ID_DEFAULTS = {"status_id": 0x300, "detail_id": 0x301, "detail2_id": 0x303}


class CalibError(ValueError):
    pass


def read_calib(path):
    """{key: value text} of a calibration text file ('key = value', '#'
    comments). Only the syntax is checked here: squeal-sim checks ranges."""
    out = {}
    if path is None:
        return out
    try:
        with open(path, encoding="utf-8") as f:
            for n, line in enumerate(f, 1):
                line = line.split("#", 1)[0].strip()
                if not line:
                    continue
                if "=" not in line:
                    raise CalibError("%s:%d: expected 'key = value'" % (path, n))
                k, v = (x.strip() for x in line.split("=", 1))
                out[k] = v
    except OSError as e:
        raise CalibError("%s: %s" % (path, e.strerror))
    return out


def brake(calib):
    """The brake's parameters (plotlib's keys) and criterion."""
    p = dict(P.DEFAULT)
    for key, pk in _BRAKE_KEYS.items():
        if key in calib:
            try:
                p[pk] = float(calib[key])
            except ValueError:
                raise CalibError("calibration: %s = %r is not a number" % (key, calib[key]))
    return p, calib.get("criterion", "exact")


def corner_ids(calib):
    """[(status_id, detail_id, detail2_id)] of corners FL, FR, RL, RR."""
    base = []
    for key in _ID_KEYS:
        try:
            base.append(int(calib.get(key, str(_ID_DEFAULTS[key])), 0))
        except ValueError:
            raise CalibError("calibration: %s = %r is not an identifier" % (key, calib[key]))
    return [tuple(b + CORNER_ID_STEP * k for b in base) for k in range(len(CORNERS))]


def draw_map(ax, p, v_max, n_max_n, criterion="exact", legend=True, alpha=0.55):
    """The stability map of brake p over v0 in (0, v_max] m/s and N in
    (0, n_max_n] N (axes in m/s and kN): regions by the closed forms and the
    Hopf border and stability limit as lines."""
    from matplotlib.colors import ListedColormap
    np = P.np
    vv = np.linspace(v_max / 400.0, v_max, 200)
    nn = np.linspace(n_max_n / 300.0, n_max_n, 150)
    code = np.array([[P.STATE_CODE[P.classify(p, x, y, criterion)] for x in vv] for y in nn])
    cmap = ListedColormap([P.STATE_COLORS["stable"], P.STATE_COLORS["bistable"],
                           P.STATE_COLORS["unstable"]])
    ax.pcolormesh(vv, nn / 1000.0, code, cmap=cmap, vmin=-0.5, vmax=2.5, shading="auto",
                  rasterized=True, alpha=alpha)
    lim = "exact" if criterion != "cubic" else "cubic"
    for kind, style, lab in (("hopf", P.LINE_HOPF, "Hopf border (unstable above)"),
                             (lim, P.LINE_EXACT, "%s stability limit (bistable above)" % lim)):
        ys = [P.force_border(p, x, kind) / 1000.0 for x in vv]
        ax.plot(vv, [y if math.isfinite(y) else float("nan") for y in ys], label=lab, **style)
    ax.set_xlim(0, v_max)
    ax.set_ylim(0, n_max_n / 1000.0)
    ax.set_xlabel("disc surface speed v0 [m/s]")
    ax.set_ylabel("pad force N [kN]")
    if legend:
        ax.legend(fontsize=7, loc="upper right", framealpha=0.9)
