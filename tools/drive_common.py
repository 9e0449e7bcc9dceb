# SPDX-License-Identifier: MIT
"""Shared pieces of the drive tools (fleet.py, live_view.py): a
calibration text file's corners (each with its brake, its output
identifiers and its position), and the stability map drawn under a drive.

A calibration without sections has the four positions FL, FR, RL, RR, all
with the flat brake keys, corner k sending on the flat identifiers + 0x10 k.
One with `[corner POS]` sections (docs/calib-input-map.md) has exactly
those corners; each takes the flat brake keys unless it sets its own, and
its own status_id/detail_id/detail2_id, by default the flat ones + 0x10 x
its position (FL 0, FR 1, RL 2, RR 3), as host-sim/calib_sections.c does.

The map's regions and borders come from tools/plots/plotlib.py: the closed
forms of docs/model.md (Hopf border Q = 1/2; the exact criterion's limit
ln 2Q = ln(2 I1(s)/s), or the paper's cubic one), in double precision with
scipy, independent of the firmware.
"""
import collections
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
import deps  # noqa: E402  (names the Debian package of a missing module)

deps.need("numpy", "scipy", "matplotlib")
sys.path.insert(0, os.path.join(HERE, "plots"))
import plotlib as P  # noqa: E402  (selects matplotlib's Agg backend)

SIM = os.path.join(ROOT, "build", "host", "squeal-sim")
DBC = os.path.join(ROOT, "firmware", "protocol", "squeal.dbc")
CORNERS = ("FL", "FR", "RL", "RR")
CORNER_ID_STEP = 0x10  # corner at position k defaults to the flat identifiers + 0x10 k
STATES = ("stable", "bistable", "unstable", "not_sliding", "fault")

# calibration key -> (plotlib brake key); see docs/calib-example.txt
_BRAKE_KEYS = {"mass_kg": "mass", "omega0_radps": "omega0", "damping": "damping",
               "mu_inf": "mu_inf", "delta_mu": "delta_mu", "slope_spm": "slope"}
_ID_KEYS = ("status_id", "detail_id", "detail2_id")
_ID_DEFAULTS = {"status_id": "0x300", "detail_id": "0x301", "detail2_id": "0x303"}
_SECTION = re.compile(r"\[\s*(input|corner)\s+([A-Za-z0-9_]+)\s*\]$", re.IGNORECASE)

# One corner of a calibration: position name (FL..RR) and index (0..3), the
# brake (plotlib's keys), the criterion and (status, detail, detail2) ids.
Corner = collections.namedtuple("Corner", "name pos brake criterion ids")


class CalibError(ValueError):
    pass


def read_calib(path):
    """A calibration text file as {"flat": {key: value}, "inputs": {NAME:
    {key: value}}, "corners": [(POS, {key: value})]} ('key = value', '#'
    comments, [input NAME] / [corner POS] sections). Only the syntax is
    checked here (and a corner's position): squeal-sim checks the rest."""
    out = {"flat": {}, "inputs": {}, "corners": []}
    if path is None:
        return out
    cur = out["flat"]
    try:
        with open(path, encoding="utf-8") as f:
            for n, line in enumerate(f, 1):
                line = line.split("#", 1)[0].strip()
                if not line:
                    continue
                m = _SECTION.match(line)
                if m:
                    cur = {}
                    name = m.group(2)
                    if m.group(1).lower() == "input":
                        out["inputs"][name] = cur
                    elif name.upper() not in CORNERS:
                        raise CalibError("%s:%d: corner position %r is not one of %s"
                                         % (path, n, name, ", ".join(CORNERS)))
                    else:
                        out["corners"].append((name.upper(), cur))
                    continue
                if "=" not in line:
                    raise CalibError("%s:%d: expected 'key = value' or a section" % (path, n))
                k, v = (x.strip() for x in line.split("=", 1))
                cur[k] = v
    except OSError as e:
        raise CalibError("%s: %s" % (path, e.strerror))
    return out


def _brake(keys, where):
    """The brake's parameters (plotlib's keys) and criterion from keys."""
    p = dict(P.DEFAULT)
    for key, pk in _BRAKE_KEYS.items():
        if key in keys:
            try:
                p[pk] = float(keys[key])
            except ValueError:
                raise CalibError("%s: %s = %r is not a number" % (where, key, keys[key]))
    return p, keys.get("criterion", "exact")


def _ids(keys, where):
    out = []
    for key in _ID_KEYS:
        try:
            out.append(int(keys[key], 0))
        except ValueError:
            raise CalibError("%s: %s = %r is not an identifier" % (where, key, keys[key]))
    return tuple(out)


def corners(cal):
    """[Corner] of a calibration read by read_calib (or {} for the
    defaults), in the order FL, FR, RL, RR."""
    flat = dict(_ID_DEFAULTS, **cal.get("flat", {}))
    base = _ids(flat, "calibration")
    sections = cal.get("corners") or [(name, {}) for name in CORNERS]
    out = []
    for name, own in sections:
        k = CORNERS.index(name)
        where = "calibration [corner %s]" % name if cal.get("corners") else "calibration"
        keys = dict(flat, **{key: str(b + CORNER_ID_STEP * k) for key, b in zip(_ID_KEYS, base)})
        keys.update(own)
        p, criterion = _brake(keys, where)
        out.append(Corner(name, k, p, criterion, _ids(keys, where)))
    return sorted(out, key=lambda c: c.pos)


def draw_map(ax, p, v_max, n_max_n, criterion="exact", legend=True, alpha=0.55, zoom=True):
    """The stability map of brake p over v0 in (0, v_max] m/s and N in
    (0, n_max_n] N (axes in m/s and kN): plotlib.draw_map (regions by the
    closed forms, the Hopf border and stability limit as lines, the speed
    axis stretched where the borders are), with its legend."""
    z = P.draw_map(ax, p, v_max, n_max_n, criterion, alpha=alpha, zoom=zoom)
    if legend:
        P.map_legend(ax, region_alpha=alpha, fontsize=7)
    return z


if __name__ == "__main__":
    import helptext
    helptext.module_main(__doc__, "tools/drive_common.py")
