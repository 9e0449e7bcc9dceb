#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Reference values of tests/firmware/model/test_squeal_sigma_criterion.c: the two border
functions of both stability criteria and their first-order standard
deviations, by central differences (numpy) of the functions themselves,
with scipy's Bessel functions for the exact criterion; no closed-form
derivative is shared with the firmware.

  g_H = ln(2 D w0 m / (a N dmu)) + a v0                       (both)
  g_S = g_H - ln(2 I1(s)/s)       exact criterion, s = a v0
  g_S = g_H - ln(1 + s^2/8)       cubic criterion (Q = 1/2 + s^2/16)
  sigma^2 = J C J^T, C diagonal in the deviations of m, w0, D, dmu, a with
            cov(a, dmu) = rho sd_a sd_dmu (mu_inf enters no border)

Prints one C initialiser row per operating point and criterion:
  { v0_mps, force_n, criterion, state, g_H, g_S, sigma_H, sigma_S }
"""
import math

import numpy as np
from scipy.special import ive

BRAKE = dict(m=1.0, w0=5000.0, D=0.023, dmu=0.15, a=2.0)
SD = dict(m=0.05, w0=50.0, D=0.002, dmu=0.01, a=0.1)
RHO = -0.3
NAMES = ("m", "w0", "D", "dmu", "a")
POINTS = ((1.0, 9000.0), (1.5, 9000.0), (1.9, 9000.0), (3.0, 9000.0), (0.6, 4000.0))


def g_h(p, v0, n):
    return math.log(2.0 * p["D"] * p["w0"] * p["m"] / (p["a"] * n * p["dmu"])) + p["a"] * v0


def big_g(s, criterion):
    if criterion == "cubic":
        return math.log1p(s * s / 8.0)
    # ln(2 I1(s)/s) with the scaled Bessel function: I1(s) = ive(1, s) e^s
    return math.log(2.0 * ive(1, s) / s) + s


def g_s(p, v0, n, criterion):
    return g_h(p, v0, n) - big_g(p["a"] * v0, criterion)


def sigma(f, p):
    jac = []
    for k in NAMES:
        h = p[k] * 1e-6
        up = dict(p, **{k: p[k] + h})
        dn = dict(p, **{k: p[k] - h})
        jac.append((f(up) - f(dn)) / (2.0 * h))
    jac = np.array(jac)
    sd = np.array([SD[k] for k in NAMES])
    cov = np.diag(sd * sd)
    ia, idm = NAMES.index("a"), NAMES.index("dmu")
    cov[ia, idm] = cov[idm, ia] = RHO * SD["a"] * SD["dmu"]
    return float(math.sqrt(jac @ cov @ jac))


def state(gh, gs):
    if gh <= 0.0:
        return "SQUEAL_STATE_UNSTABLE"
    return "SQUEAL_STATE_STABLE" if gs >= 0.0 else "SQUEAL_STATE_BISTABLE"


def main():
    for v0, n in POINTS:
        for crit in ("exact", "cubic"):
            gh = g_h(BRAKE, v0, n)
            gs = g_s(BRAKE, v0, n, crit)
            sh = sigma(lambda p: g_h(p, v0, n), BRAKE)
            ss = sigma(lambda p: g_s(p, v0, n, crit), BRAKE)
            print("\t{ %.3f, %.1f, SQUEAL_CRITERION_%s, %s, %.9f, %.9f, %.9f, %.9f },"
                  % (v0, n, crit.upper(), state(gh, gs), gh, gs, sh, ss))


if __name__ == "__main__":
    main()
