#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""tools/fit_friction.py on synthetic measurements with known parameters.

Recovery (mean estimate within 3 standard errors of the mean of the truth)
and coverage: the 95 % intervals of mu_inf, delta_mu and a must cover the
truth in 90-99 % of the repetitions (fixed seeds), for an unweighted fit
(the covariance scaled by the residuals, Student t) and a weighted one (an
mu_sd column, absolute covariance, heteroscedastic noise). Also the example
dynamometer run of docs/examples recovers the example brake."""

import sys

import numpy as np

from checks import ROOT, Checks

import fit_friction as ff  # noqa: E402  (tools/, via checks)
import gen_calib_examples as ex  # noqa: E402

REPS = 300
TRUTH = np.array([0.25, 0.15, 2.0])
NAMES = ("mu_inf", "delta_mu", "slope_spm")


def campaign(c, label, seed, weighted):
    rng = np.random.default_rng(seed)
    v = np.repeat(np.geomspace(0.05, 6.0, 12), 2)
    clean = ff.friction(v, *TRUTH)
    hits = np.zeros(3, dtype=int)
    est = []
    refused = 0
    for _ in range(REPS):
        if weighted:
            sd = 0.002 + 0.02 * clean * np.exp(-v)
            mu = clean + sd * rng.standard_normal(len(v))
        else:
            sd = None
            mu = clean + 0.005 * rng.standard_normal(len(v))
        try:
            res = ff.fit(v, mu, sd)
        except ff.cf.Refusal:
            refused += 1
            continue
        s = ff.summary(res)
        for i, k in enumerate(NAMES):
            lo, hi = s[k]["ci95"]
            hits[i] += lo <= TRUTH[i] <= hi
        est.append(res["value"])
    c.check(refused == 0, f"{label}: no repetition refused ({refused})")
    n = REPS - refused
    est = np.array(est)
    for i, k in enumerate(NAMES):
        c.coverage(int(hits[i]), n, f"{label} {k}")
        m = est[:, i].mean()
        se = est[:, i].std(ddof=1) / np.sqrt(n)
        c.check(abs(m - TRUTH[i]) <= 3 * se + 1e-3 * abs(TRUTH[i]),
                f"{label} {k}: mean estimate {m:.5g} vs truth {TRUTH[i]:g} "
                f"(3 standard errors {3 * se:.2g})")


def example(c):
    layout, cols = ff.cf.read_csv(f"{ROOT}/docs/examples/dyno.csv", ff.LAYOUTS)
    v, mu, sd = ff.to_mu(cols, ex.PAD_RADIUS_M, ex.PISTON_AREA_MM2, ex.FACES)
    s = ff.summary(ff.fit(v, mu, sd))
    for k in NAMES:
        lo, hi = s[k]["ci95"]
        c.check(layout == "dyno" and lo <= ex.TRUTH[k] <= hi,
                f"docs/examples/dyno.csv: {k} 95 % interval [{lo:.4g}, {hi:.4g}] "
                f"holds the example brake's {ex.TRUTH[k]:g}")


def main():
    c = Checks()
    campaign(c, "unweighted", 1201, weighted=False)
    campaign(c, "weighted (mu_sd)", 1202, weighted=True)
    example(c)
    return c.finish()


if __name__ == "__main__":
    sys.exit(main())
