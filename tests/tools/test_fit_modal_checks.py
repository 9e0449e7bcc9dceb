#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""tools/fit_modal.py's refusals, each on data or a fit result written here
(check(), frf() and ring_down() called directly):

  - damping ratio D = 1 (critically damped) refused "not an underdamped
    mode", D = 0.999 taken;
  - D identified when its 95 % interval D +- q sd is narrower than D
    (2 q sd = 0.9 D: taken), refused when wider (2 q sd = 1.5 D), with
    q = 1.959964 (normal) or 2.5706 (Student t, 5 degrees of freedom);
  - a frequency response with one magnitude 0 refused ("magnitude must be
    positive in every row");
  - a ring-down whose one sample interval is 2 % longer than the others
    refused ("not uniformly spaced").

prints "RESULT: N passed, M failed"
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks  # noqa: E402
import fit_modal as fm  # noqa: E402

Q95 = 1.959964   # two-sided 95 % normal quantile (tables)
T95_5 = 2.570582  # two-sided 95 % Student t, 5 degrees of freedom (tables)


def refusal(f, *a):
    try:
        f(*a)
    except fm.cf.Refusal as e:
        return str(e)
    return None


def result(w0, d, sd_d, dof=None):
    return {"value": np.array([w0, d]), "cov": np.diag([1.0, sd_d * sd_d]), "dof": dof}


def damping(c, tmp):
    why = refusal(fm.check, result(5000.0, 1.0, 1e-4))
    c.check(why == "damping ratio 1: not an underdamped mode", "D = 1: refused (%s)" % why)
    why = refusal(fm.check, result(5000.0, 0.999, 1e-4))
    c.check(why is None, "D = 0.999: taken (%s)" % why)
    for q, dof in ((Q95, None), (T95_5, 5)):
        d = 0.02
        why = refusal(fm.check, result(5000.0, d, 0.9 * d / (2 * q), dof))
        c.check(why is None, "2 q sd = 0.9 D (dof %s): identified (%s)" % (dof, why))
        why = refusal(fm.check, result(5000.0, d, 1.5 * d / (2 * q), dof))
        c.check(why is not None and why.startswith("the damping is not identified: its 95 % interval"),
                "2 q sd = 1.5 D (dof %s): refused (%s)" % (dof, why))


def data(c, tmp):
    f = np.linspace(650.0, 950.0, 61)
    h = fm.sdof(2 * math.pi * f, 5000.0, 0.023, 1.0)
    mag = np.abs(h)
    mag[3] = 0.0
    why = refusal(fm.frf, f, mag, np.degrees(np.angle(h)), "receptance")
    c.check(why == "magnitude must be positive in every row", "FRF with one magnitude 0: refused (%s)" % why)
    rate = 48000.0
    t = np.arange(400) / rate
    t[200:] += 0.02 / rate  # one interval 1.02 steps
    y = np.exp(-115.0 * t) * np.sin(5000.0 * t)
    why = refusal(fm.ring_down, t, y)
    c.check(why == "the samples are not uniformly spaced in time", "one interval 2 %% long: refused (%s)" % why)


if __name__ == "__main__":
    sys.exit(Checks.run(damping, data))
