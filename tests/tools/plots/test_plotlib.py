#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""The pictures: make each one (small grids, into a temporary directory)
and open it: PNG signature and header, size in pixels and bytes, content
that is not blank (pixel spread, distinct colours, share of non-background
pixels); SVG parsed as XML with a real drawing inside. The drive picture is
drawn from a synthetic braking manoeuvre generated here. The committed
docs/img/*.png are checked the same way (and for the 300 KB limit).

usage: test_plots.py [path/to/oscsim]   prints "RESULT: N passed, M failed"
"""
import csv
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


def check_svg(path):
    name = os.path.basename(path)
    try:
        root = ET.parse(path).getroot()
        n = sum(1 for _ in root.iter())
        paths = sum(1 for e in root.iter() if e.tag.endswith("path"))
        ok = root.tag.endswith("svg") and paths >= 20
        detail = f"{n} elements, {paths} paths"
    except (ET.ParseError, OSError) as exc:
        ok, detail = False, repr(exc)
    check(f"{name} is an SVG drawing", ok, detail)


def synthetic_drive(path):
    """A braking manoeuvre: 3 m/s to standstill in 12 s, pad force up to
    9 kN then 14 kN; state and warning from the closed forms."""
    p = dict(plotlib.DEFAULT)
    with open(path, "w", newline="") as f:
        wr = csv.writer(f)
        wr.writerow(["time_s", "v0_mps", "force_n", "state", "warning"])
        for i in range(0, 131):
            t = 0.1 * i
            v0 = max(0.0, 3.0 * (1.0 - t / 12.0))
            n = min(9000.0, 4500.0 * t) + (5000.0 * (t - 8.0) / 4.0 if t > 8.0 else 0.0)
            st = plotlib.classify(p, v0, n)
            code = {"stable": 0, "bistable": 1, "unstable": 2, "not_sliding": 3}[st]
            warn = {0: 0, 1: 2, 2: 3, 3: 0}[code]
            wr.writerow([f"{t:.2f}", f"{v0:.4f}", f"{n:.1f}", code, warn])
    return p


def decode_style(drive_csv, path):
    """The drive as decode --csv writes it: one row per frame, a signal's
    cell empty in frames that do not carry it."""
    cols = ["time_s", "id", "message", "counter", "e2e", "DiscSpeed_radps", "PadForce_N",
            "SquealState", "WarningLevel", "V0_mps", "Force_N", "raw"]
    with open(drive_csv, newline="") as f, open(path, "w", newline="") as g:
        wr = csv.DictWriter(g, fieldnames=cols)
        wr.writeheader()
        for i, row in enumerate(csv.DictReader(f)):
            t = float(row["time_s"])
            wr.writerow({"time_s": f"{t:.6f}", "id": "110", "message": "DiscSpeed",
                         "DiscSpeed_radps": f"{float(row['v0_mps']) / 0.12:.3f}"})
            if i % 3 == 0:
                wr.writerow({"time_s": f"{t + 0.001:.6f}", "id": "400", "message": "SquealDetail",
                             "V0_mps": row["v0_mps"]})
                wr.writerow({"time_s": f"{t + 0.002:.6f}", "id": "401",
                             "message": "SquealDetail2", "Force_N": row["force_n"]})
            wr.writerow({"time_s": f"{t + 0.003:.6f}", "id": "300", "message": "SquealStatus",
                         "SquealState": row["state"], "WarningLevel": row["warning"]})


def main():
    with tempfile.TemporaryDirectory() as tmp:
        try:
            csv_path = os.path.join(tmp, "map.csv")
            run([TOOL, "map", "--grid", "30", "--brake", "all", "--no-linear", "--csv", csv_path])
            out = run([PY, os.path.join(PLOTS, "plot_map.py"), csv_path, "--out", tmp])
            check("plot_map.py writes both maps", len(out.split()) == 4, out.replace("\n", " "))
            check_png(os.path.join(tmp, "stability_map.png"))
            check_png(os.path.join(tmp, "stability_map_variations.png"))
            check_svg(os.path.join(tmp, "stability_map.svg"))
            check_svg(os.path.join(tmp, "stability_map_variations.svg"))
        except Exception as exc:
            check("stability maps", False, repr(exc))
        try:
            run([PY, os.path.join(PLOTS, "plot_phase.py"), "--sim", TOOL, "--out", tmp])
            check_png(os.path.join(tmp, "phase_portraits.png"), min_w=1000)
            check_svg(os.path.join(tmp, "phase_portraits.svg"))
        except Exception as exc:
            check("phase portraits", False, repr(exc))
        try:
            drive = os.path.join(tmp, "drive.csv")
            synthetic_drive(drive)
            run([PY, os.path.join(PLOTS, "plot_drive.py"), drive, "--out", tmp,
                 "--name", "drive_synthetic"])
            check_png(os.path.join(tmp, "drive_synthetic.png"), min_w=1000)
            check_svg(os.path.join(tmp, "drive_synthetic.svg"))
            # the same drive as `squeal-sim decode --csv` rows (frames)
            dec = os.path.join(tmp, "decode.csv")
            decode_style(drive, dec)
            run([PY, os.path.join(PLOTS, "plot_drive.py"), dec, "--out", tmp,
                 "--name", "drive_decoded"])
            check_png(os.path.join(tmp, "drive_decoded.png"), min_w=1000)
            # a wrong input is refused, not drawn
            bad = os.path.join(tmp, "bad.csv")
            with open(bad, "w") as f:
                f.write("time_s,speed\n0,1\n")
            rc = subprocess.run([PY, os.path.join(PLOTS, "plot_drive.py"), bad, "--out", tmp],
                                capture_output=True, cwd=ROOT).returncode
            check("plot_drive.py refuses a CSV without its columns", rc != 0, f"exit {rc}")
        except Exception as exc:
            check("drive picture", False, repr(exc))
    # the borders the maps draw: v_H of the default brake (model.md section 8)
    v_h = plotlib.border_v0(plotlib.DEFAULT, 2.0, "hopf")
    check("map's Hopf border at a = 2 s/m is 1.2315 m/s", abs(v_h - 1.2315) < 5e-5, f"{v_h:.6f}")
    committed = sorted(glob.glob(os.path.join(ROOT, "docs", "img", "*.png")))
    for path in committed:
        check_png(path, min_w=600, min_h=400, max_bytes=300_000)
    return check.finish()


if __name__ == "__main__":
    sys.exit(main())
