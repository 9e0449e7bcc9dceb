#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""tools/plots/plot_calib_bands.py's border functions and Monte Carlo
percentiles, called directly (nothing drawn), against values by hand:

  - g(s) = ln(2 I1(s)/s) with I1(1) = 0.5651591, I1(2) = 1.5906369,
    I1(3) = 3.9533702 (tables): 0.122499, 0.464134, 0.969103;
  - the paper's brake (m 1, w0 5000, D 0.023, dmu 0.15, a 2) at v0 = 1:
    ln N_H = ln(2 D w0 m / (a dmu)) + a v0 = ln(766.667) + 2 = 8.642052,
    ln N_S = ln N_H - g(2) = 8.177918;
  - Monte Carlo with only D uncertain (sd 0.001): the 5 / 50 / 95 % borders
    are those of D + z sd, z = -1.6449, 0, +1.6449 (20000 draws: within a
    tenth of sd).

prints "RESULT: N passed, M failed"
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from figures import Checks  # noqa: E402
import plot_calib_bands as B  # noqa: E402

I1 = {1.0: 0.5651591040, 2.0: 1.5906368546, 3.0: 3.9533702174}  # modified Bessel I1 (tables)
Z95 = 1.6448536


def bessel(c, tmp):
    for s, i1 in I1.items():
        want = math.log(2.0 * i1 / s)
        got = float(B.g_bessel(np.array([s]))[0])
        c.check(abs(got - want) < 1e-8, "g(%g) = ln(2 I1/s) = %.6f (%.6f)" % (s, want, got))


def borders(c, tmp):
    ln_h, ln_s = B.ln_borders(1.0, 5000.0, 0.023, 0.15, 2.0, np.array([1.0]))
    want_h = math.log(2 * 0.023 * 5000.0 / (2.0 * 0.15)) + 2.0
    want_s = want_h - math.log(2.0 * I1[2.0] / 2.0)
    c.check(abs(want_h - 8.642052) < 1e-6 and abs(float(ln_h[0]) - want_h) < 1e-9,
            "ln N_H at v0 1 m/s: 8.642052 (%.6f)" % float(ln_h[0]))
    c.check(abs(want_s - 8.177918) < 1e-6 and abs(float(ln_s[0]) - want_s) < 1e-8,
            "ln N_S at v0 1 m/s: 8.177918 (%.6f)" % float(ln_s[0]))


def percentiles(c, tmp):
    p = {"mass_kg": 1.0, "omega0_radps": 5000.0, "damping": 0.023, "delta_mu": 0.15, "slope_spm": 2.0,
         "corr": 0.0}
    p.update({k + "_sd": 0.0 for k in B.KEYS})
    p["damping_sd"] = sd = 0.001
    v = np.array([0.5, 1.0])
    mc_h, mc_s = B.monte_carlo(p, v, 20000)
    for row, z in ((0, -Z95), (1, 0.0), (2, Z95)):
        d = 0.023 + z * sd
        want = np.log(2 * d * 5000.0 / (2.0 * 0.15)) + 2.0 * v
        tol = 0.1 * sd / d   # a tenth of sd in D, in ln N
        err = float(np.max(np.abs(mc_h[row] - want)))
        c.check(mc_h.shape == (3, 2) and err < tol,
                "Monte Carlo %s %% Hopf border: that of D = %.5f (off by %.2g, bound %.2g)"
                % (("5", "50", "95")[row], d, err, tol))


if __name__ == "__main__":
    sys.exit(Checks.run(bessel, borders, percentiles))
