#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""tools/plots/plotlib.py, the pictures' shared style (each picture itself is
drawn and read by its own test_plot_*.py): save() writes a 150 dpi PNG and
the SVG beside it; state and warning names in words; the map's fills in
the legend; the stretched speed axis (invertible, 60 % for the zoom, ending
past the speed where the stability limit reaches the top force, found here
by bisection on N_S with scipy's I1); the Hopf border by hand. Then the
committed docs/img/*.png opened: PNG signature and header, 150 dpi, size in
pixels and under 300 KB, content not blank (pixel spread, distinct colours,
share of white); each SVG there under 300 KB and a real drawing.

usage: test_plotlib.py   prints "RESULT: N passed, M failed"
"""
import glob
import math
import os
import struct
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET
# tests/ of this checkout, and the folders its helper modules live in
_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, d) for d in ("support", os.path.join("support", "reference"), "host-sim", "tools")]

ROOT = os.path.dirname(_TESTS)
TOOL = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build/host/oscsim"))
PLOTS = os.path.join(ROOT, "tools", "plots")
PY = sys.executable
sys.path.insert(0, PLOTS)

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import numpy as np  # noqa: E402
import plotlib  # noqa: E402
from named_checks import NamedChecks  # noqa: E402

check = NamedChecks()


def run(cmd):
    out = subprocess.run(cmd, capture_output=True, text=True, timeout=300, cwd=ROOT)
    if out.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)}: rc {out.returncode}: {out.stderr[-2000:]}")
    return out.stdout


def check_png(path, min_w=600, min_h=400, max_bytes=None):
    name = os.path.relpath(path, ROOT) if path.startswith(ROOT) else os.path.basename(path)
    if not os.path.isfile(path):
        check(f"{name} exists", False)
        return
    size = os.path.getsize(path)
    with open(path, "rb") as f:
        head = f.read(33)
    sig_ok = head[:8] == b"\x89PNG\r\n\x1a\n" and head[12:16] == b"IHDR"
    w, h = struct.unpack(">II", head[16:24]) if sig_ok else (0, 0)
    check(f"{name} is a PNG of at least {min_w}x{min_h}", sig_ok and w >= min_w and h >= min_h,
          f"{w}x{h}, {size} bytes")
    from PIL import Image
    with Image.open(path) as im:
        dpi = tuple(round(x) for x in im.info.get("dpi", (0, 0)))
    check(f"{name} is at 150 dpi", dpi == (150, 150), str(dpi))
    if max_bytes is not None:
        check(f"{name} is under {max_bytes // 1000} KB", size < max_bytes, f"{size} bytes")
    img = mpimg.imread(path)
    if img.ndim == 2:
        img = np.stack([img] * 3, axis=-1)
    rgb = img[..., :3].reshape(-1, 3)
    spread = float(rgb.std())
    colours = len(np.unique((rgb * 255).astype(np.uint8), axis=0))
    background = np.all(rgb > 0.97, axis=1).mean()
    check(f"{name} is not blank",
          spread > 0.05 and colours >= 16 and background < 0.95,
          f"pixel std {spread:.3f}, {colours} colours, {100 * background:.0f} % white")


def check_svg(path, min_paths=20):
    name = os.path.basename(path)
    try:
        root = ET.parse(path).getroot()
        n = sum(1 for _ in root.iter())
        paths = sum(1 for e in root.iter() if e.tag.endswith("path"))
        ok = root.tag.endswith("svg") and paths >= min_paths
        detail = f"{n} elements, {paths} paths"
    except (ET.ParseError, OSError) as exc:
        ok, detail = False, repr(exc)
    check(f"{name} is an SVG drawing", ok, detail)


def check_save(tmp):
    """plotlib.save: the PNG at 150 dpi (its pHYs chunk), the SVG beside."""
    from PIL import Image
    fig, ax = plotlib.plt.subplots(figsize=(6.0, 4.0))
    ax.plot([0, 1, 2], [0, 1, 0], label="a line")
    ax.legend()
    paths = plotlib.save(fig, tmp, "probe")
    check("save writes NAME.png and NAME.svg", paths == [os.path.join(tmp, "probe.png"),
                                                        os.path.join(tmp, "probe.svg")])
    with Image.open(paths[0]) as im:
        dpi = tuple(round(x) for x in im.info.get("dpi", (0, 0)))
    check("the PNG declares 150 dpi", dpi == (150, 150), str(dpi))
    check_svg(paths[1], min_paths=3)


def check_names():
    """What a reader sees: human state names, named warning levels."""
    labels = list(plotlib.STATE_LABELS.values()) + list(plotlib.STATE_SHORT.values())
    check("no state label is a code name", all("_" not in t for t in labels), str(labels))
    check("bistable and unstable say what they mean",
          plotlib.STATE_LABELS["bistable"] == "bistable (squeal possible after a kick)"
          and plotlib.STATE_LABELS["unstable"] == "unstable (squeal)"
          and plotlib.STATE_LABELS["not_sliding"] == "not sliding")
    check("warning levels as the DBC names them",
          plotlib.WARNING_TICKS == ("0 none", "1 advisory", "2 warning", "3 critical"))
    hs = [h.get_label() for h in plotlib.region_handles()]
    check("the map's fills have legend entries", hs == [
        "region: unstable (squeal)", "region: bistable (squeal possible after a kick)",
        "region: stable"], str(hs))


def check_zoom():
    """The stretched speed axis: continuous, invertible, 60 % for the zoom;
    the zoom ends past the speed where the stability limit reaches N."""
    z = plotlib.SpeedZoom(3.0, 15.0)
    v = np.linspace(0.0, 15.0, 301)
    back = z.inverse(z.forward(v))
    check("zoom: inverse(forward(v)) = v", float(np.max(np.abs(back - v))) < 1e-12)
    frac = float(z.forward(3.0) / z.forward(15.0))
    check("zoom: 0..3 m/s take 60 % of a 0..15 m/s axis", abs(frac - 0.6) < 1e-12, "%.6f" % frac)
    p = plotlib.DEFAULT
    # N_S(v) = 2 D w0 m / (a dmu) e^(a v) / (2 I1(a v) / (a v)), solved here by bisection
    from scipy.special import iv
    n_s = lambda x: 2 * 0.023 * 5000 / (2 * 0.15) * math.exp(2 * x) / (2 * iv(1, 2 * x) / (2 * x))
    lo, hi = 0.1, 10.0
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if n_s(mid) < 20000.0 else (lo, mid)
    got = plotlib.stable_speed(p, 20000.0)
    check("stability limit reaches 20 kN at %.4f m/s (bisection %.4f)" % (got, lo), abs(got - lo) < 1e-6)
    zz = plotlib.speed_zoom(p, 14.0, 20000.0)
    check("map to 14 m/s, 20 kN: zoomed to 4.5 m/s", zz is not None and zz.v_zoom == 4.5,
          str(zz and zz.v_zoom))
    check("map to 3.3 m/s: no zoom (the borders fill it)", plotlib.speed_zoom(p, 3.3, 13800.0) is None)


def main():
    with tempfile.TemporaryDirectory() as tmp:
        check_save(tmp)
    check_names()
    check_zoom()
    # the borders the maps draw: v_H of the default brake (docs/model.md section 8)
    v_h = plotlib.border_v0(plotlib.DEFAULT, 2.0, "hopf")
    check("map's Hopf border at a = 2 s/m is 1.2315 m/s", abs(v_h - 1.2315) < 5e-5, f"{v_h:.6f}")
    # the committed pictures (make docs-img): PNG 150 dpi under 300 KB, SVGs
    # beside them only when small
    committed = sorted(glob.glob(os.path.join(ROOT, "docs", "img", "*.png")))
    check("docs/img holds the pictures", len(committed) >= 9, str(len(committed)))
    for path in committed:
        check_png(path, min_w=600, min_h=400, max_bytes=300_000)
    for path in sorted(glob.glob(os.path.join(ROOT, "docs", "img", "*.svg"))):
        check(f"{os.path.basename(path)} is under 300 KB", os.path.getsize(path) < 300_000)
        check_svg(path)
    return check.finish()


if __name__ == "__main__":
    sys.exit(main())
