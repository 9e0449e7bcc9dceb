# SPDX-License-Identifier: MIT
"""Shared parts of the calibration fitters (tools/fit_friction.py,
tools/fit_modal.py): reading a measurement CSV, refusing bad data with one
line, the JSON form of a fitted parameter, and writing calibration text
(the format of docs/calib-example.txt).

A refusal is a `Refusal` exception carrying one line; `run_tool` turns it
(and any other failure) into that line on stderr and a non-zero exit, never
a traceback.
"""

import json
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import deps  # noqa: E402  (names the Debian package of a missing module)

deps.need("numpy", "scipy")
import numpy as np  # noqa: E402
from scipy import stats  # noqa: E402

EXIT_REFUSED = 1
EXIT_INTERNAL = 3


class Refusal(Exception):
    """Bad data or a fit that cannot be trusted: one line for the user."""


def run_tool(main, argv):
    """Run main(argv); a Refusal or any other error becomes one line."""
    prog = os.path.basename(sys.argv[0]) if sys.argv and sys.argv[0] else "fit"
    try:
        return main(argv)
    except Refusal as e:
        print(f"{prog}: {e}", file=sys.stderr)
        return EXIT_REFUSED
    except OSError as e:
        print(f"{prog}: {e.filename or ''}: {e.strerror or e}", file=sys.stderr)
        return EXIT_REFUSED
    except KeyboardInterrupt:
        return 130
    except Exception as e:  # noqa: BLE001  (the promise: never a traceback)
        print(f"{prog}: internal error ({type(e).__name__}: {e}); please report it",
              file=sys.stderr)
        return EXIT_INTERNAL


def read_csv(path, layouts):
    """Read a numeric CSV with a header line.

    layouts: {name: (required columns tuple, optional columns tuple)}. The
    first layout whose required columns are all present is used.
    Returns (layout name, {column: numpy array}). '#' lines and blank lines
    are skipped. Refuses: an empty file, no matching layout, a row with a
    wrong number of fields, a field that is not a finite number.
    """
    with open(path, encoding="utf-8", errors="replace") as f:
        lines = [(i + 1, ln.strip()) for i, ln in enumerate(f)]
    lines = [(n, ln) for n, ln in lines if ln and not ln.startswith("#")]
    if not lines:
        raise Refusal(f"{path}: empty file (no header, no data)")
    hdr_no, hdr = lines[0]
    cols = [c.strip() for c in hdr.split(",")]
    chosen = None
    for name, (req, _opt) in layouts.items():
        if all(c in cols for c in req):
            chosen = name
            break
    if chosen is None:
        want = " or ".join(",".join(req) for req, _ in layouts.values())
        raise Refusal(f"{path}:{hdr_no}: columns '{hdr}': expected {want}")
    req, opt = layouts[chosen]
    use = [c for c in req + opt if c in cols]
    idx = {c: cols.index(c) for c in use}
    data = {c: [] for c in use}
    for n, ln in lines[1:]:
        fields = [x.strip() for x in ln.split(",")]
        if len(fields) != len(cols):
            raise Refusal(f"{path}:{n}: {len(fields)} fields, the header has {len(cols)}")
        for c in use:
            try:
                v = float(fields[idx[c]])
            except ValueError:
                raise Refusal(f"{path}:{n}: {c} '{fields[idx[c]]}' is not a number") from None
            if not math.isfinite(v):
                raise Refusal(f"{path}:{n}: {c} is {fields[idx[c]]}, not a finite number")
            data[c].append(v)
    if not data[use[0]]:
        raise Refusal(f"{path}: header only, no data rows")
    return chosen, {c: np.asarray(v, dtype=float) for c, v in data.items()}


def add_output_args(ap, plot_help):
    """The options both fitters share: where the result goes."""
    ap.add_argument("--base", metavar="FILE.cal", help="calibration file whose other keys are kept")
    ap.add_argument("-o", "--output", metavar="FILE.cal", help="calibration file to write ('-' = stdout)")
    ap.add_argument("--no-sd", action="store_true",
                    help="leave the standard deviations out of the calibration file")
    ap.add_argument("--plot", metavar="FILE.png", help=plot_help)
    ap.add_argument("--json", action="store_true", help="print the result as one JSON object (below)")


def _plotlib():
    """tools/plots/plotlib.py: the pictures' one style (imported only to plot)."""
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "plots"))
    import plotlib
    return plotlib


def pyplot():
    """matplotlib's pyplot without a display, in the pictures' style."""
    import deps
    deps.need("matplotlib")
    return _plotlib().plt


def finish_plot(fig, ax, title, path):
    """Title, grid and legend; PATH (150 dpi PNG) and the SVG beside it."""
    ax.set_title(title)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    _plotlib().save_as(fig, path)


def t_quantile(dof):
    """Two-sided 95 % quantile: Student t with dof degrees of freedom
    (covariance scaled by the residuals), normal when dof is None."""
    return float(stats.norm.ppf(0.975) if dof is None else stats.t.ppf(0.975, dof))


def param_json(value, stderr, q):
    return {"value": float(value), "stderr": float(stderr),
            "ci95": [float(value - q * stderr), float(value + q * stderr)]}


def print_json(obj):
    print(json.dumps(obj, indent=2))


def fmt(v):
    """A calibration value: 9 significant digits, no exponent for the
    usual magnitudes (the calibration parser takes both)."""
    return f"{v:.9g}"


KEY_RE = re.compile(r"^\s*([A-Za-z0-9_]+)\s*=")


def write_calib(path, values, comments, base=None, header=()):
    """Write calibration text: the keys of `values` (dict, in order) with
    their `comments`; with `base`, every other line of the base file is kept
    as it is and a base line setting one of our keys is replaced in place."""
    out = []
    done = set()
    if base is not None:
        with open(base, encoding="utf-8") as f:
            for ln in f.read().splitlines():
                m = KEY_RE.match(ln)
                if m and m.group(1) in values:
                    k = m.group(1)
                    if k in done:
                        continue  # the parser refuses a key given twice
                    out.append(f"{k} = {fmt(values[k])}".ljust(35) + f"# {comments[k]}")
                    done.add(k)
                else:
                    out.append(ln)
    else:
        out.extend(f"# {h}" for h in header)
    rest = [k for k in values if k not in done]
    if rest:
        if base is not None:
            out.append("")
            out.extend(f"# {h}" for h in header)
        for k in rest:
            out.append(f"{k} = {fmt(values[k])}".ljust(35) + f"# {comments[k]}")
    text = "\n".join(out) + "\n"
    if path == "-":
        sys.stdout.write(text)
    else:
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)


def read_calib(path):
    """The key = value pairs of a calibration text file (values as text;
    comments and blank lines skipped). Refuses a line without '='."""
    out = {}
    with open(path, encoding="utf-8") as f:
        for n, ln in enumerate(f, 1):
            body = ln.split("#", 1)[0].strip()
            if not body:
                continue
            if "=" not in body:
                raise Refusal(f"{path}:{n}: expected 'key = value'")
            k, v = (x.strip() for x in body.split("=", 1))
            out[k] = v
    return out


if __name__ == "__main__":
    import helptext
    helptext.module_main(__doc__, "tools/calibfit.py")
