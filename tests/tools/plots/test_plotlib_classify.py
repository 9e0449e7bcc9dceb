#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""tools/plots/plotlib.py's closed-form class of one point (classify), the
drive plot's background, against values worked out by hand for the paper's
brake (D 0.023, w0 5000 rad/s, m 1 kg, a 2 s/m, dmu 0.15) at N = 9 kN:
ln Q = ln(D w0 m / (a N dmu)) + a v0 = ln(115 / 2700) + 2 v0 = -3.1561 + 2 v0.

  v0 1.0: ln Q = -1.156 <= ln 1/2 = -0.693: unstable (Hopf);
  v0 1.5: ln Q = -0.156, s = 3, ln(I1(3)/3) = ln(3.9534/3) = 0.276: bistable
          (cubic: ln(1/2 + 9/16) = 0.061, bistable too);
  v0 2.5: ln Q = 1.844, s = 5, ln(I1(5)/5) = ln(24.336/5) = 1.583: stable
          (cubic: ln(1/2 + 25/16) = 0.724, stable);
  v0 0 or N 0: not sliding;
  on the Hopf border itself (Q = 1/2 exactly: D w0 m / (a N dmu) = 1/2 and
  a v0 far below one unit in the last place of ln 1/2): unstable.

prints "RESULT: N passed, M failed"
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from checks import Checks  # noqa: E402
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "tools", "plots"))
import plotlib as P  # noqa: E402

PAPER = dict(mass=1.0, omega0=5000.0, damping=0.023, mu_inf=0.25, delta_mu=0.15, slope=2.0)


def classes(c, tmp):
    for v0, force, crit, want in ((1.0, 9000.0, "exact", "unstable"), (1.5, 9000.0, "exact", "bistable"),
                                  (2.5, 9000.0, "exact", "stable"), (1.5, 9000.0, "cubic", "bistable"),
                                  (2.5, 9000.0, "cubic", "stable"), (1.0, 9000.0, "cubic", "unstable"),
                                  (0.0, 9000.0, "exact", "not_sliding"), (1.5, 0.0, "exact", "not_sliding"),
                                  (-1.0, 9000.0, "exact", "not_sliding")):
        got = P.classify(PAPER, v0, force, crit)
        c.check(got == want, "v0 %g m/s, N %g N, %s criterion: %s (%s)" % (v0, force, crit, want, got))


def hopf_border(c, tmp):
    p = dict(PAPER, damping=0.5, omega0=1.0, slope=1.0, delta_mu=1.0)
    got = P.classify(p, 1e-20, 1.0)
    c.check(got == "unstable", "Q = 1/2 exactly (on the Hopf border): unstable (%s)" % got)


if __name__ == "__main__":
    sys.exit(Checks.run(classes, hopf_border))
