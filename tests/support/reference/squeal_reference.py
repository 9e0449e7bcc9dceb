# SPDX-License-Identifier: MIT
"""Independent reference of the squeal model (docs/model.md sections 2-4).

Written from docs/model.md and firmware/model/squeal_model.h only, in double
precision with scipy, so it shares no code and no numerical method with the
firmware. Everything is done in the log domain:

    t = ln Q - ln(1/2) = ln(2 D w0 m / (a N dmu)) + a v0

so that the Hopf border is t = 0, and the stick-line border of the exact
criterion is t = g(s) with g(x) = ln(2 I1(x) / x) (cubic: ln(1 + s^2/8)).
g(x) is computed from the power series for small x (no cancellation next to
the border) and from scipy.special.ive (exponentially scaled I1) for large x
(no overflow for x in the thousands).

Run `python3 squeal_reference.py --self-check` to compare against the
numbers printed in docs/model.md.
"""

import math
import sys

import numpy as np
from scipy.optimize import brentq
from scipy.special import ive

LN2 = math.log(2.0)

STABLE = "stable"
BISTABLE = "bistable"
UNSTABLE = "unstable"
NOT_SLIDING = "not_sliding"
INVALID = "invalid"
STATE_CODE = {STABLE: 0, BISTABLE: 1, UNSTABLE: 2, NOT_SLIDING: 3, INVALID: 15}

EXACT = "exact"
CUBIC = "cubic"

# Input domain of squeal_model.h: (lo, hi, lo_open)
DOMAIN = {
    "mass": (0.0, 10000.0, True),
    "omega0": (0.0, 500000.0, True),
    "damping": (0.0, 1.0, True),
    "slope": (0.0, 20.0, False),
    "mu_inf": (0.0, 1.5, False),
    "delta_mu": (-1.5, 1.5, False),
    "v0": (0.0, 100.0, False),
    "force": (0.0, 500000.0, False),
}

# Defaults: docs/model.md section 8.
DEFAULTS = {
    "mass": 1.0,
    "omega0": 5000.0,
    "damping": 0.023,
    "mu_inf": 0.25,
    "delta_mu": 0.15,
    "slope": 2.0,
}

# Q-formats of the fixed build (squeal_model.h).
Q_FORMAT = {
    "mass": 16, "omega0": 12, "damping": 30, "mu_inf": 30, "delta_mu": 30,
    "slope": 24, "v0": 20, "force": 12,
    "ln_q": 16, "hopf_v0": 20, "hopf_margin": 20, "hopf_force": 12,
    "cycle_x": 20, "lc_amplitude_um": 12, "trigger_v": 20, "basin_ratio": 24,
}

OUTPUT_FIELDS = ("ln_q", "ln_r", "hopf_v0", "hopf_margin", "hopf_force",
                 "cycle_x", "lc_amplitude_um", "trigger_v", "basin_ratio")


def g_ratio(x):
    """ln(2 I1(x)/x) for x >= 0: 0 at x = 0, increasing, ~ x^2/8 near 0."""
    if x < 2.0:
        # 2 I1(x)/x = sum_k (x^2/4)^k / (k! (k+1)!) = 1 + sum_{k>=1} ...
        y = x * x / 4.0
        term = 1.0
        acc = 0.0
        for k in range(1, 40):
            term *= y / (k * (k + 1))
            acc += term
            if term < 1e-18 * acc:
                break
        return math.log1p(acc)
    # ive(1, x) = I1(x) e^-x: finite for any x.
    return math.log(2.0 * ive(1, x) / x) + x


def g_cubic(x):
    """ln(2 (1/2 + x^2/16)) = ln(1 + x^2/8): the paper's truncated form."""
    return math.log1p(x * x / 8.0)


def solve_exact_x(t):
    """x > 0 with ln(I1(x)/x) = ln Q, i.e. g_ratio(x) = t, for t > 0."""
    if not t > 0.0:
        raise ValueError("no cycle for t <= 0")
    # g(x) <= x^2/8 for all x (g is below its quadratic start), so
    # x >= sqrt(8 t); and g(x) >= x - 1.5 ln x - 0.92 + ln 2 for x >= 2.
    lo = math.sqrt(8.0 * t) * 0.5
    while g_ratio(lo) > t:
        lo *= 0.5
    hi = max(2.0, math.sqrt(8.0 * t) * 2.0)
    hi = max(hi, t + 1.5 * math.log(t + 2.0) + 10.0)
    while g_ratio(hi) < t:
        hi *= 2.0
    return brentq(lambda x: g_ratio(x) - t, lo, hi, xtol=1e-300,
                  rtol=4.0 * np.finfo(float).eps, maxiter=500)


def ln_cubic_x(t):
    """ln x3 with x3 = 4 sqrt(Q - 1/2) = 4 sqrt((e^t - 1)/2), for t > 0."""
    if t > 30.0:
        ln_em1 = t + math.log1p(-math.exp(-t))
    else:
        ln_em1 = math.log(math.expm1(t))
    return math.log(4.0) + 0.5 * (ln_em1 - LN2)


def safe_exp(v):
    if v > 709.0:
        return math.inf
    return math.exp(v)


def in_domain(p):
    for key, (lo, hi, lo_open) in DOMAIN.items():
        v = p[key]
        if not math.isfinite(v):
            return False
        if v > hi:
            return False
        if lo_open and not v > lo:
            return False
        if not lo_open and v < lo:
            return False
    if p["mu_inf"] + p["delta_mu"] < 0.0:
        return False
    return True


def classify(p, criterion=EXACT):
    """Reference classification of one point.

    p: dict with mass, omega0, damping, mu_inf, delta_mu, slope, v0, force
    (plain floats; the caller rounds them to what the build can represent).
    Returns a dict: state, the OUTPUT_FIELDS (None where undefined) and the
    border distances (None where undefined).
    """
    res = {"state": INVALID, "border_dist": None, "hopf_dist": None,
           "cycle_dist": None}
    for f in OUTPUT_FIELDS:
        res[f] = None
    if criterion not in (EXACT, CUBIC) or not in_domain(p):
        return res
    if p["v0"] == 0.0 or p["force"] == 0.0:
        res["state"] = NOT_SLIDING
        return res
    if p["slope"] == 0.0 or p["delta_mu"] <= 0.0:
        res["state"] = STABLE
        return res

    a = p["slope"]
    v0 = p["v0"]
    s = a * v0
    ln_a = math.log(a)
    ln_v0 = math.log(v0)
    ln_s = ln_a + ln_v0
    ln_dw0m = math.log(p["damping"]) + math.log(p["omega0"]) + math.log(p["mass"])
    ln_andmu = ln_a + math.log(p["force"]) + math.log(p["delta_mu"])
    c = ln_dw0m - ln_andmu            # ln Q = c + s
    t = c + LN2 + s                   # ln Q - ln(1/2)
    ln_r = -(c + LN2)                 # ln(a N dmu / (2 D w0 m))
    res["ln_q"] = c + s
    res["ln_r"] = ln_r
    res["hopf_dist"] = abs(ln_r)
    res["cycle_dist"] = abs(t)

    # Hopf border as a speed: exists only when a N dmu > 2 D w0 m.
    if ln_r > 0.0:
        res["hopf_v0"] = ln_r / a
        res["hopf_margin"] = v0 - ln_r / a
    # Hopf border as a force: N_H = 2 D w0 m e^(a v0) / (a dmu).
    res["hopf_force"] = safe_exp(LN2 + ln_dw0m - ln_a - math.log(p["delta_mu"]) + s)

    border = g_ratio(s) if criterion == EXACT else g_cubic(s)
    res["border_dist"] = min(abs(t), abs(t - border))
    if t <= 0.0:
        res["state"] = UNSTABLE
        return res
    res["state"] = BISTABLE if t < border else STABLE

    if criterion == EXACT:
        x = solve_exact_x(t)
        ln_x = math.log(x)
    else:
        ln_x = ln_cubic_x(t)
        x = safe_exp(ln_x)
    res["cycle_x"] = x
    res["lc_amplitude_um"] = safe_exp(ln_x - ln_a - math.log(p["omega0"]) + math.log(1e6))
    res["trigger_v"] = safe_exp(ln_x - ln_a)
    res["basin_ratio"] = safe_exp(ln_x - ln_s)
    return res


def default_point(v0, force, **kw):
    p = dict(DEFAULTS)
    p["v0"] = v0
    p["force"] = force
    p.update(kw)
    return p


# ---- representation of inputs in each numeric build ------------------------

def to_float32(v):
    """What the float build holds for a double input (round to nearest even,
    overflow to +-inf, NaN stays NaN)."""
    with np.errstate(over="ignore"):
        return float(np.float32(v))


def to_fixed_raw(v, q):
    """What tests/support/sq_num.c makes of a double for a field with q
    fraction bits: floor(v 2^q + 0.5), saturated to int32, NaN -> INT32_MIN.
    Must stay identical to sq_num_from_double() there."""
    if math.isnan(v):
        return -2**31
    if not abs(v) < 2.0**40:
        return 2**31 - 1 if v > 0 else -2**31
    scaled = math.ldexp(v, q)
    if scaled >= 2147483647.0:
        return 2**31 - 1
    if scaled <= -2147483648.0:
        return -2**31
    return int(math.floor(scaled + 0.5))


def to_fixed(v, q):
    return math.ldexp(float(to_fixed_raw(v, q)), -q)


def fixed_max(q):
    return math.ldexp(2.0**31 - 1.0, -q)


def represent(p, build):
    out = dict(p)
    for k in DOMAIN:
        if build == "float":
            out[k] = to_float32(p[k])
        else:
            out[k] = to_fixed(p[k], Q_FORMAT[k])
    return out


# ---- self check against docs/model.md ---------------------------------------

def self_check():
    fails = 0

    def check(name, got, want, tol):
        nonlocal fails
        ok = abs(got - want) <= tol
        print("%-44s got %-12.6g want %-10.6g %s" % (name, got, want, "ok" if ok else "FAIL"))
        if not ok:
            fails += 1

    r = classify(default_point(1.0, 9000.0))
    check("v_H default brake, N=9000 (docs/model.md section 8)", r["hopf_v0"], 1.2315, 5e-5)
    check("state at v0=1 N=9000 is unstable", float(r["state"] == UNSTABLE), 1.0, 0)
    # N_H at v0 = 1: 2 * 0.023 * 5000 * 1 * e^2 / (2 * 0.15) = 766.667 e^2
    check("N_H at v0=1 m/s", r["hopf_force"], 766.6666666666666 * math.exp(2.0), 1e-9)
    for q, x_exact, x_cubic in ((0.6, 1.2259, 1.2649), (1.0, 2.4868, 2.8284),
                                (2.0, 3.6924, 4.8990), (3.0, 4.3089, 6.3246)):
        t = math.log(q) + LN2
        check("exact averaged x at Q=%.1f (docs/model.md section 6)" % q, solve_exact_x(t), x_exact, 6e-5)
        check("cubic x3 at Q=%.1f (docs/model.md section 6)" % q, math.exp(ln_cubic_x(t)), x_cubic, 6e-5)
    # g_ratio: series branch and ive branch agree at the switch, and with a
    # direct evaluation of I1 at moderate x.
    from scipy.special import i1
    for x in (1e-6, 0.1, 1.0, 1.999999, 2.0, 2.000001, 5.0, 30.0):
        check("g(%g) vs ln(2 i1(x)/x)" % x, g_ratio(x), math.log(2.0 * i1(x) / x), 1e-13)
    # I1 from its integral definition, I1(x) = (1/pi) int_0^pi e^(x cos t) cos t dt,
    # independent of scipy.special: checks the ive-based branch of g.
    from scipy.integrate import quad
    for x in (0.5, 2.4868, 10.0, 60.0):
        val, _ = quad(lambda th: math.exp(x * (math.cos(th) - 1.0)) * math.cos(th), 0.0, math.pi,
                      epsabs=0.0, epsrel=1e-13, limit=200)
        g_int = math.log(2.0 * val / math.pi / x) + x
        check("g(%g) vs integral definition of I1" % x, g_ratio(x), g_int, 1e-11 * max(1.0, x))
    # Inversion is consistent for tiny and huge t.
    for t in (1e-12, 1e-6, 0.5, 10.0, 300.0, 2500.0):
        x = solve_exact_x(t)
        check("g(solve(t)) = t, t=%g" % t, g_ratio(x), t, 1e-12 * max(1.0, t))
    # Classification by the table of section 4 at a few points.
    r = classify(default_point(1.5, 9000.0))
    check("v0=1.5 N=9000: Q>1/2, cycle exists", float(r["cycle_x"] is not None), 1.0, 0)
    check("hostile: NaN v0 invalid", float(classify(default_point(math.nan, 1.0))["state"] == INVALID), 1.0, 0)
    check("v0 = 0 not sliding", float(classify(default_point(0.0, 9000.0))["state"] == NOT_SLIDING), 1.0, 0)
    check("slope 0 stable", float(classify(default_point(1.0, 9000.0, slope=0.0))["state"] == STABLE), 1.0, 0)
    check("huge a v0 (20*100) no overflow", float(classify(default_point(100.0, 9000.0, slope=20.0))["state"] == STABLE), 1.0, 0)
    print("SELF-CHECK: %s" % ("ok" if fails == 0 else "%d FAILED" % fails))
    return 1 if fails else 0


def main(argv):
    if "--self-check" in argv:
        return self_check()
    print(__doc__)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
