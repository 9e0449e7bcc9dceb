#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""tools/fit_friction.py's refusals, each on data or a fit result written
here (fit() and check() called directly, no subprocess):

  - six points at two distinct speeds: "2 distinct speeds: three parameters
    need at least 3" (three are the least that identify mu_inf, delta_mu, a);
  - one speed of -0.5 m/s among positive ones: "sliding speeds must not be
    negative";
  - a identified when its 95 % interval a +- q se_a is narrower than a
    (2 q se_a = 0.9 a: taken) and refused when wider (2 q se_a = 1.1 a), with
    q = 1.959964 (normal, an absolute covariance);
  - values beyond the calibration's upper bounds (mu_inf 1.6 > 1.5, slope
    25 > 20 s/m, delta_mu 1.6 > 1.5) refused, the bounds themselves taken.

prints "RESULT: N passed, M failed"
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks  # noqa: E402
import fit_friction as ff  # noqa: E402

Q95 = 1.959964  # two-sided 95 % normal quantile (tables)
V = np.array([0.0, 1.0, 2.0, 3.0, 4.0, 5.0])


def refusal(f, *a):
    try:
        f(*a)
    except ff.cf.Refusal as e:
        return str(e)
    return None


def result(mu_inf, dmu, a, se_a, se=0.001):
    """A fit result with an absolute covariance: diagonal, the standard errors given."""
    return {"value": np.array([mu_inf, dmu, a]), "cov": np.diag([se * se, se * se, se_a * se_a]),
            "dof": None, "rms": 0.0}


def data(c, tmp):
    v = np.array([0.5, 0.5, 0.5, 2.0, 2.0, 2.0])
    mu = 0.4 + 0.2 * np.exp(-v)
    why = refusal(ff.fit, v, mu)
    c.check(why == "2 distinct speeds: three parameters need at least 3", "two speeds: refused (%s)" % why)
    v = np.array([-0.5, 0.5, 1.0, 2.0, 3.0, 4.0])
    why = refusal(ff.fit, v, 0.4 + 0.2 * np.exp(-np.abs(v)))
    c.check(why == "sliding speeds must not be negative", "a speed of -0.5 m/s: refused (%s)" % why)


def identified(c, tmp):
    a = 1.0
    why = refusal(ff.check, result(0.4, 0.2, a, 0.9 * a / (2 * Q95)), V)
    c.check(why is None, "2 q se_a = 0.9 a: a identified, taken (%s)" % why)
    why = refusal(ff.check, result(0.4, 0.2, a, 1.1 * a / (2 * Q95)), V)
    c.check(why is not None and why.startswith("the speeds cannot identify a: its 95 % interval"),
            "2 q se_a = 1.1 a: refused (%s)" % why)


def ranges(c, tmp):
    for val, ok in (((1.5, 0.2, 1.0), True), ((1.6, 0.2, 1.0), "fitted mu_inf = 1.6 is outside the calibration's "
                                                               "range 0 .. 1.5"),
                    ((0.4, 0.2, 20.0), True), ((0.4, 0.2, 25.0), "fitted slope_spm = 25 is outside the "
                                                                 "calibration's range 0 .. 20"),
                    ((0.4, 1.5, 1.0), True), ((0.4, 1.6, 1.0), "fitted delta_mu = 1.6 is outside the "
                                                               "calibration's range -1.5 .. 1.5")):
        why = refusal(ff.check, result(*val, se_a=0.01), V)
        c.check(why is None if ok is True else why == ok,
                "mu_inf %g, delta_mu %g, slope %g: %s (%s)" % (val + ("taken" if ok is True else "refused", why)))


if __name__ == "__main__":
    sys.exit(Checks.run(data, identified, ranges))
