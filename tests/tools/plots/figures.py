# SPDX-License-Identifier: MIT
"""What the tests of the plotting scripts share: run a script's main() in
this process with its command line, keep the matplotlib Figures it hands to
plotlib.save() (to read their axes, labels, legends and lines), and check
the files written: a PNG with its signature and header, an SVG that parses
as XML with an <svg> root."""
import contextlib
import importlib
import inspect
import io
import os
import struct
import sys
import xml.etree.ElementTree as ET

_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
ROOT = os.path.dirname(_TESTS)
PLOTS = os.path.join(ROOT, "tools", "plots")
sys.path[:0] = [PLOTS, os.path.join(ROOT, "tools"), os.path.join(_TESTS, "tools")]

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import numpy as np  # noqa: E402
import plotlib  # noqa: E402
from checks import Checks  # noqa: E402,F401  (the tests' counter)


def draw(script, argv, write=True):
    """(exit status, stdout, [(name, Figure, paths)]) of tools/plots/SCRIPT.py
    run with argv; SystemExit's message is the status when it is text.
    write=False keeps the Figures but writes no file (paths empty): for the
    tests that read only what was drawn, without the time of rendering."""
    mod = importlib.import_module(script)
    saved = []
    real = plotlib.save

    def keep(fig, out_dir, name):
        paths = real(fig, out_dir, name) if write else []
        saved.append((name, fig, list(paths)))  # the caller may extend its list
        return paths

    plotlib.save, old_argv = keep, sys.argv
    sys.argv = [script + ".py"] + list(argv)
    out = io.StringIO()
    try:
        with contextlib.redirect_stdout(out):
            rc = mod.main(list(argv)) if inspect.signature(mod.main).parameters else mod.main()
    except SystemExit as e:
        rc = e.code
    finally:
        plotlib.save, sys.argv = real, old_argv
    return rc, out.getvalue(), saved


DPI = 150


def png_dpi(path):
    """The resolution a PNG declares (its pHYs chunk), or None."""
    from PIL import Image
    with Image.open(path) as im:
        dpi = im.info.get("dpi")
    return None if dpi is None else tuple(int(round(x)) for x in dpi)


def files_ok(paths):
    """Both files of a picture written, not empty, of their format: the PNG
    at 150 dpi, the SVG beside it (same name)."""
    ok = len(paths) == 2 and paths[0].endswith(".png") and paths[1] == paths[0][:-4] + ".svg"
    for path in paths:
        if not os.path.isfile(path) or os.path.getsize(path) == 0:
            return False
        if path.endswith(".png"):
            with open(path, "rb") as f:
                head = f.read(24)
            ok = ok and head[:8] == b"\x89PNG\r\n\x1a\n" and head[12:16] == b"IHDR"
            ok = ok and min(struct.unpack(">II", head[16:24])) > 100 and png_dpi(path) == (DPI, DPI)
        else:
            try:
                ok = ok and ET.parse(path).getroot().tag.endswith("svg")
            except ET.ParseError:
                return False
    return ok


def legend_texts(legend):
    return [t.get_text() for t in legend.get_texts()] if legend is not None else []


def line_at(line, x):
    """A drawn line's y at x (linear between its points)."""
    xs, ys = np.asarray(line.get_xdata(), float), np.asarray(line.get_ydata(), float)
    return float(np.interp(x, xs, ys))


def lines_of_colour(ax, colour, min_points=3):
    return [ln for ln in ax.get_lines()
            if matplotlib.colors.same_color(ln.get_color(), colour) and len(ln.get_xdata()) >= min_points]


def all_legend_texts(fig):
    """Every legend's labels of a figure (axes' and the figure's own)."""
    out = []
    for leg in [a.get_legend() for a in fig.axes] + list(fig.legends):
        out += legend_texts(leg)
    return out


CODE_NAMES = ("not_sliding", " um", "[um]", "mu_inf", "delta_mu", "w0 =")


def no_code_names(texts):
    """None of the code names a reader should not see (state names,
    'um' for micrometres, the fit's variable names)."""
    return [t for t in texts if any(c in t for c in CODE_NAMES)]


def suptitle(fig):
    """The figure's title (Figure.get_suptitle() is matplotlib 3.8 on)."""
    texts = [t.get_text() for t in fig.texts]
    return fig._suptitle.get_text() if getattr(fig, "_suptitle", None) is not None else " ".join(texts)
