#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Writes tests/support/golden/sigma_vectors.csv: the spread of the two border
functions under the calibration's uncertainty, by Monte Carlo.

    /usr/bin/python3 tests/support/reference/gen_sigma_reference.py -o tests/support/golden/sigma_vectors.csv

For every row (brake x operating point x set of standard deviations) it draws
SAMPLES parameter sets (fixed seed): m, w0, D independent normals, (a, dmu) a
bivariate normal with correlation rho; and takes the sample standard
deviation of
    g_H = ln 2Q = ln(2 D w0 m / (a N dmu)) + a v0
    g_S = g_H - ln(2 I1(s)/s),  s = a v0
(I1 from scipy.special.ive, so no overflow). It also writes the first-order
sigma computed here in double precision with numerical derivatives (central
differences of the same g functions: no closed form shared with the
firmware), and the class and g values at the nominal parameters from the
model reference (squeal_reference.py).

The grid keeps every relative standard deviation at or below 10 %, where
first order is meant to hold; the column mc_vs_lin is |MC / first order - 1|
so that the file itself documents how far first order is from Monte Carlo.
"""

import argparse
import math
import os
import sys

import numpy as np
from scipy.special import ive
# tests/ of this checkout, and the folders its helper modules live in
_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, d) for d in ("support", os.path.join("support", "reference"), "host-sim", "tools")]

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import squeal_reference as ref  # noqa: E402

SEED = 20261129
SAMPLES = 20000

BRAKES = (  # slope, damping, omega0, mass, delta_mu
    (2.0, 0.023, 5000.0, 1.0, 0.15),
    (1.0, 0.05, 5000.0, 1.0, 0.15),
    (4.0, 0.023, 7071.0, 1.0, 0.10),
)
POINTS = [(v0, f) for v0 in (0.2, 0.6, 1.2, 2.0, 3.0, 6.0) for f in (5000.0, 9000.0, 15000.0)]
SD_SETS = (  # relative sd of m, w0, D, dmu, a; corr(a, dmu)
    (0.02, 0.015, 0.10, 0.04, 0.05, 0.85),
    (0.0, 0.01, 0.03, 0.02, 0.08, 0.0),
    (0.0, 0.02, 0.06, 0.06, 0.08, -0.6),
)
MU_INF = 0.25
COLUMNS = ("id", "v0", "force", "mass", "omega0", "damping", "mu_inf", "delta_mu",
           "slope", "mass_sd", "omega0_sd", "damping_sd", "delta_mu_sd", "slope_sd",
           "corr", "state", "g_hopf", "g_stable", "sigma_hopf_mc", "sigma_stable_mc",
           "sigma_hopf_lin", "sigma_stable_lin", "mc_vs_lin")


def g_of_x(x):
    """ln(2 I1(x)/x) for x > 0, vectorised (ive = I1 e^-x)."""
    return np.log(2.0 * ive(1, x) / x) + x


def borders(m, w0, d, dmu, a, v0, force):
    gh = np.log(2.0 * d * w0 * m / (a * force * dmu)) + a * v0
    return gh, gh - g_of_x(a * v0)


def first_order(nom, sds, corr, v0, force):
    """sqrt(J C J^T) with J from central differences (step 1e-6 relative)."""
    names = ("m", "w0", "d", "dmu", "a")
    jac = np.zeros((2, 5))
    for i, k in enumerate(names):
        h = nom[k] * 1e-6
        up = dict(nom)
        dn = dict(nom)
        up[k] += h
        dn[k] -= h
        gu = np.array(borders(up["m"], up["w0"], up["d"], up["dmu"], up["a"], v0, force))
        gd = np.array(borders(dn["m"], dn["w0"], dn["d"], dn["dmu"], dn["a"], v0, force))
        jac[:, i] = (gu - gd) / (2.0 * h)
    cov = np.diag(np.square(sds))
    cov[3, 4] = cov[4, 3] = corr * sds[3] * sds[4]
    return np.sqrt(np.einsum("ij,jk,ik->i", jac, cov, jac))


def rows():
    rng = np.random.default_rng(SEED)
    rid = 0
    for slope, damping, omega0, mass, dmu in BRAKES:
        for v0, force in POINTS:
            for rel in SD_SETS:
                nom = {"m": mass, "w0": omega0, "d": damping, "dmu": dmu, "a": slope}
                sds = np.array([rel[0] * mass, rel[1] * omega0, rel[2] * damping,
                                rel[3] * dmu, rel[4] * slope])
                corr = rel[5]
                z = rng.standard_normal((SAMPLES, 5))
                m = mass + sds[0] * z[:, 0]
                w0 = omega0 + sds[1] * z[:, 1]
                d = damping + sds[2] * z[:, 2]
                dm = dmu + sds[3] * z[:, 3]
                a = slope + sds[4] * (corr * z[:, 3] + math.sqrt(1.0 - corr * corr) * z[:, 4])
                gh, gs = borders(m, w0, d, dm, a, v0, force)
                mc = (float(np.std(gh, ddof=1)), float(np.std(gs, ddof=1)))
                lin = first_order(nom, sds, corr, v0, force)
                p = ref.default_point(v0, force, slope=slope, damping=damping,
                                     omega0=omega0, mass=mass, mu_inf=MU_INF,
                                     delta_mu=dmu)
                res = ref.classify(p)
                g_h = float(borders(mass, omega0, damping, dmu, slope, v0, force)[0])
                g_s = g_h - ref.g_ratio(slope * v0)
                dev = max(abs(mc[0] / lin[0] - 1.0), abs(mc[1] / lin[1] - 1.0))
                yield (rid, v0, force, mass, omega0, damping, MU_INF, dmu, slope,
                       *sds, corr, ref.STATE_CODE[res["state"]], g_h, g_s,
                       mc[0], mc[1], lin[0], lin[1], dev)
                rid += 1


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("-o", "--output", required=True)
    args = ap.parse_args(argv)
    with open(args.output, "w", encoding="ascii") as f:
        f.write("# generated by tests/support/reference/gen_sigma_reference.py "
                f"(seed {SEED}, {SAMPLES} samples per row): do not edit\n")
        f.write(",".join(COLUMNS) + "\n")
        for r in rows():
            f.write(",".join(str(v) if isinstance(v, int) else f"{v:.9g}" for v in r) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
