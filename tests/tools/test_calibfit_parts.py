#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""tools/calibfit.py's shared parts, called directly:

  - read_csv refuses a row with more fields than the header (and one with
    fewer), naming the line;
  - t_quantile is the two-sided 95 % quantile: 1.959964 (normal, dof None),
    2.570582 (Student t, 5 degrees of freedom), 2.228139 (10), from tables;
  - write_calib writes to a file given by its path (nothing on stdout) and
    to stdout for "-".

prints "RESULT: N passed, M failed"
"""
import contextlib
import io
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks  # noqa: E402
import calibfit as cf  # noqa: E402

LAYOUT = {"mu": (("v_mps", "mu"), ())}


def csv(c, tmp):
    for rows, want in ((["1.0,0.5", "2.0,0.4,9"], ":3: 3 fields, the header has 2"),
                       (["1.0,0.5", "2.0"], ":3: 1 fields, the header has 2")):
        path = os.path.join(tmp, "d.csv")
        with open(path, "w") as f:
            f.write("\n".join(["v_mps,mu"] + rows) + "\n")
        try:
            cf.read_csv(path, LAYOUT)
            why = None
        except cf.Refusal as e:
            why = str(e)
        c.check(why == path + want, "row %r: refused (%s)" % (rows[1], why))
    with open(path, "w") as f:
        f.write("v_mps,mu\n1.0,0.5\n2.0,0.4\n")
    name, cols = cf.read_csv(path, LAYOUT)
    c.check(name == "mu" and list(cols["mu"]) == [0.5, 0.4], "two good rows: read")


def quantile(c, tmp):
    for dof, want in ((None, 1.959964), (5, 2.570582), (10, 2.228139)):
        got = cf.t_quantile(dof)
        c.check(abs(got - want) < 1e-6, "t_quantile(%s) = %.6f, table %.6f" % (dof, got, want))


def write(c, tmp):
    path = os.path.join(tmp, "out.cal")
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        cf.write_calib(path, {"mu_inf": 0.25}, {"mu_inf": "fitted"}, header=("h",))
    text = open(path).read() if os.path.exists(path) else None
    c.check(text == "# h\n" + "mu_inf = 0.25".ljust(35) + "# fitted\n" and out.getvalue() == "",
            "a path: written there, nothing on stdout (%r, %r)" % (text, out.getvalue()))
    out = io.StringIO()
    cwd = os.getcwd()
    os.chdir(tmp)
    try:
        with contextlib.redirect_stdout(out):
            cf.write_calib("-", {"mu_inf": 0.25}, {"mu_inf": "fitted"})
    finally:
        os.chdir(cwd)
    c.check(out.getvalue() == "mu_inf = 0.25".ljust(35) + "# fitted\n" and not os.path.exists(os.path.join(tmp, "-")),
            "'-': on stdout, no file '-' (%r)" % out.getvalue())


if __name__ == "__main__":
    sys.exit(Checks.run(csv, quantile, write))
