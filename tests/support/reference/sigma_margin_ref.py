# SPDX-License-Identifier: MIT
"""BorderMargin in standard deviations, computed independently of the
firmware: the class from the model reference (tests/support/reference/
squeal_reference.py), the border functions and their first-order sigma with
numerical derivatives and the covariance of the parameters
(tests/support/reference/gen_sigma_reference.py, no closed form shared with
firmware/model/squeal_sigma*). The margin of a class (docs/uncertainty.md):
unstable |g_H|/s_H, stable g_S/s_S, bistable min(g_H/s_H, -g_S/s_S)."""

import os
import sys
# tests/ of this checkout, and the folders its helper modules live in
_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, d) for d in ("support", os.path.join("support", "reference"), "host-sim", "tools")]

HERE = os.path.dirname(os.path.abspath(__file__))
import gen_sigma_reference as gsr  # noqa: E402
import squeal_reference as ref  # noqa: E402

STATE_NAME = {0: "stable", 1: "bistable", 2: "unstable", 3: "not_sliding", 15: "invalid"}


def read_cal(path):
    """key -> float of the brake keys of a calibration text file."""
    out = {}
    with open(path, encoding="utf-8") as f:
        for ln in f:
            ln = ln.split("#")[0].strip()
            if "=" in ln and not ln.startswith("["):
                k, v = (x.strip() for x in ln.split("=", 1))
                try:
                    out[k] = float(v)
                except ValueError:
                    pass
    return out


def brake(cal):
    """(nominal dict for gen_sigma_reference, sds array, corr, mu_inf) of a calibration."""
    nom = {"m": cal.get("mass_kg", 1.0), "w0": cal.get("omega0_radps", 5000.0),
           "d": cal.get("damping", 0.023), "dmu": cal.get("delta_mu", 0.15),
           "a": cal.get("slope_spm", 2.0)}
    sds = [cal.get("mass_kg_sd", 0.0), cal.get("omega0_radps_sd", 0.0),
           cal.get("damping_sd", 0.0), cal.get("delta_mu_sd", 0.0), cal.get("slope_spm_sd", 0.0)]
    return nom, sds, cal.get("slope_delta_mu_corr", 0.0), cal.get("mu_inf", 0.25)


def state_code(nom, mu_inf, v0, force):
    p = ref.default_point(v0, force, slope=nom["a"], damping=nom["d"], omega0=nom["w0"],
                          mass=nom["m"], mu_inf=mu_inf, delta_mu=nom["dmu"])
    return ref.STATE_CODE[ref.classify(p)["state"]]


def borders_sigma(nom, sds, corr, v0, force):
    """(g_H, g_S, sigma_H, sigma_S) at the point."""
    import numpy as np
    g_h, g_s = gsr.borders(nom["m"], nom["w0"], nom["d"], nom["dmu"], nom["a"], v0, force)
    s_h, s_s = gsr.first_order(nom, np.array(sds, dtype=float), corr, v0, force)
    return float(g_h), float(g_s), float(s_h), float(s_s)


def margins(nom, sds, corr, v0, force):
    """{"to_hopf", "to_stable"}: |g|/sigma of each border (inf for sigma 0)."""
    g_h, g_s, s_h, s_s = borders_sigma(nom, sds, corr, v0, force)
    inf = float("inf")
    return {"to_hopf": abs(g_h) / s_h if s_h > 0 else inf,
            "to_stable": abs(g_s) / s_s if s_s > 0 else inf}


def margin_of(state, m):
    """The margin of class `state` (code) from margins(); None for no class."""
    if state == 2:
        return m["to_hopf"]
    if state == 0:
        return m["to_stable"]
    if state == 1:
        return min(m["to_hopf"], m["to_stable"])
    return None
