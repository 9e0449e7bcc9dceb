#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Writes tests/support/golden/model_vectors.csv from the independent reference.

    /usr/bin/python3 tests/support/reference/gen_model_vectors.py -o tests/support/golden/model_vectors.csv

Deterministic (fixed seed). Every row holds the inputs, the criterion, and
the expected state and fields (empty = the field must be absent) for the
numeric build named in `variant`:
  both   the inputs are exactly representable in float and in every fixed
         Q-format (grid points are rounded so), or both builds' roundings
         lead to the same expectation (e.g. NaN -> invalid);
  float  expectation for the float build (inputs rounded to float32);
  fixed  expectation for the fixed build (inputs converted like
         tests/support/sq_num.c: round to nearest LSB, saturate, NaN -> min).
border_dist = min |ln Q - border| over the two borders of the criterion
(empty where no ln Q exists); ln_r = ln(a N dmu / (2 D w0 m)).
"""

import argparse
import math
import os
import sys

import numpy as np
# tests/ of this checkout, and the folders its helper modules live in
_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, d) for d in ("support", os.path.join("support", "reference"), "host-sim", "tools")]

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import squeal_reference as ref  # noqa: E402

SEED = 20261122
INPUTS = ("v0", "force", "slope", "damping", "omega0", "mass", "mu_inf", "delta_mu")
COLUMNS = ("id", "tag", "variant", "criterion") + INPUTS + (
    "state",) + ref.OUTPUT_FIELDS + ("border_dist",)


def qboth(v, key):
    """Round v to a value held exactly by the float build and the fixed one."""
    q = ref.Q_FORMAT[key]
    out = ref.to_float32(ref.to_fixed(v, q))
    assert ref.to_fixed(out, q) == out and ref.to_float32(out) == out, (key, v)
    return out


def quantize(p):
    return {k: qboth(p[k], k) for k in INPUTS}


def fmt_in(v):
    return repr(float(v))


def fmt_out(v):
    if v is None:
        return ""
    if isinstance(v, str):
        return v
    if math.isinf(v):
        return "inf" if v > 0 else "-inf"
    return "%.10g" % v


class Writer:
    def __init__(self):
        self.rows = []

    def add(self, tag, p):
        """Adds rows for both criteria; p holds raw (maybe hostile) inputs."""
        for crit in (ref.EXACT, ref.CUBIC):
            r_float = ref.classify(ref.represent(p, "float"), crit)
            r_fixed = ref.classify(ref.represent(p, "fixed"), crit)
            if r_float == r_fixed:
                self._row(tag, "both", crit, p, r_float)
            else:
                self._row(tag, "float", crit, p, r_float)
                self._row(tag, "fixed", crit, p, r_fixed)

    def _row(self, tag, variant, crit, p, r):
        row = [str(len(self.rows)), tag, variant, crit]
        row += [fmt_in(p[k]) for k in INPUTS]
        row.append(r["state"])
        row += [fmt_out(r[f]) for f in ref.OUTPUT_FIELDS]
        row.append(fmt_out(r["border_dist"]))
        self.rows.append(row)


def base(**kw):
    p = {"v0": 1.5, "force": 9000.0, "slope": 2.0, "damping": 0.023,
         "omega0": 5000.0, "mass": 1.0, "mu_inf": 0.25, "delta_mu": 0.15}
    p.update(kw)
    return p


def ln_c(p):
    """ln(D w0 m / (a N dmu)) for a valid point with a, N, dmu > 0."""
    return (math.log(p["damping"]) + math.log(p["omega0"]) + math.log(p["mass"])
            - math.log(p["slope"]) - math.log(p["force"]) - math.log(p["delta_mu"]))


def random_params(rng):
    return {
        "slope": float(rng.uniform(0.0, 10.0)) if rng.random() < 0.5
        else float(10.0 ** rng.uniform(-2.0, 1.0)),
        "damping": float(10.0 ** rng.uniform(math.log10(0.005), math.log10(0.3))),
        "omega0": float(10.0 ** rng.uniform(math.log10(500.0), math.log10(50000.0))),
        "mass": float(10.0 ** rng.uniform(-0.7, 0.7)),
        "mu_inf": float(rng.uniform(0.1, 0.5)),
        "delta_mu": float(rng.uniform(0.01, 0.4)),
    }


def gen(w):
    rng = np.random.default_rng(SEED)

    # 1. Wide random grid (values on the default brake's scale, docs/model.md section 8).
    for _ in range(2400):
        p = random_params(rng)
        p["v0"] = float(rng.uniform(0.0, 40.0)) if rng.random() < 0.6 \
            else float(10.0 ** rng.uniform(-3.0, math.log10(40.0)))
        p["force"] = float(rng.uniform(0.0, 30000.0)) if rng.random() < 0.6 \
            else float(10.0 ** rng.uniform(0.0, math.log10(30000.0)))
        w.add("grid", quantize(p))

    # 2. The default brake's map (docs/model.md section 6: a up to 6 s/m, v0 up to 3 m/s).
    for a in np.linspace(0.25, 6.0, 24):
        for v0 in np.linspace(0.125, 3.0, 24):
            w.add("map", quantize(base(slope=float(a), v0=float(v0))))

    # 3. Exactly on and around the borders. Offsets in ln Q; the smallest
    # ones are below the tests' class tolerance (1e-3), the others above.
    offsets = (0.0, 1e-9, -1e-9, 1e-6, -1e-6, 2e-4, -2e-4, 2e-3, -2e-3, 1e-2, -1e-2)
    n_border = 0
    while n_border < 2000:
        p = random_params(rng)
        if p["slope"] < 0.05:
            continue
        kind = n_border % 4
        if kind == 0:
            # v0 = v_H exactly (+ offset/a in speed): N fixed, solve v0.
            p["force"] = float(rng.uniform(1000.0, 30000.0))
            ln_r = -(ln_c(p) + ref.LN2)
            if ln_r <= 0.0:
                continue
            off = offsets[int(rng.integers(len(offsets)))]
            p["v0"] = ln_r / p["slope"] + off / p["slope"]
            tag = "hopf_v"
        else:
            # ln Q = border(s) + offset: v0 fixed, solve N.
            p["v0"] = float(rng.uniform(0.01, 40.0))
            s = p["slope"] * p["v0"]
            if kind == 1:
                border = 0.0
                tag = "hopf_q"
            elif kind == 2:
                border = ref.g_ratio(s)
                tag = "stick_exact"
            else:
                border = ref.g_cubic(s)
                tag = "stick_cubic"
            off = offsets[int(rng.integers(len(offsets)))]
            t = border + off       # = ln Q + ln 2
            # t = ln(2 D w0 m / (a N dmu)) + s  ->  ln N
            p["force"] = 1.0
            ln_n = ln_c(p) + ref.LN2 + s - t
            if ln_n > math.log(500000.0) or ln_n < math.log(1.0):
                continue
            p["force"] = math.exp(ln_n)
        if not 0.0 < p["v0"] <= 100.0:
            continue
        w.add(tag, quantize(p))
        n_border += 1

    # 4. Whole documented domain, log-uniform: exercises saturation of the
    # fixed formats (v_H, N_H, amplitude, trigger and basin ranges).
    for _ in range(600):
        p = {
            "v0": float(10.0 ** rng.uniform(-5.0, 2.0)),
            "force": float(10.0 ** rng.uniform(-2.0, math.log10(500000.0))),
            "slope": float(10.0 ** rng.uniform(-6.0, math.log10(20.0))),
            "damping": float(10.0 ** rng.uniform(-8.0, 0.0)),
            "omega0": float(10.0 ** rng.uniform(-3.0, math.log10(500000.0))),
            "mass": float(10.0 ** rng.uniform(-4.0, 4.0)),
            "mu_inf": float(rng.uniform(0.0, 1.5)),
            "delta_mu": float(10.0 ** rng.uniform(-8.0, math.log10(1.5))),
        }
        if p["mu_inf"] + p["delta_mu"] > 3.0:
            continue
        w.add("domain", quantize(p))

    # 5. Hostile values, one field at a time, on three base points.
    flt_max = float(np.finfo(np.float32).max)
    common = [0.0, -0.0, 1e-45, 1e-40, 1.1754943508222875e-38, 1e-300, 5e-324,
              -1e-45, -1.0, math.nan, -math.nan, math.inf, -math.inf,
              1e30, -1e30, 1e300, flt_max, 3.5e38, 1e-7, 1e-5]
    limits = {
        "mass": (0.0, 10000.0), "omega0": (0.0, 500000.0), "damping": (0.0, 1.0),
        "slope": (0.0, 20.0), "mu_inf": (0.0, 1.5), "delta_mu": (-1.5, 1.5),
        "v0": (0.0, 100.0), "force": (0.0, 500000.0),
    }
    bases = [base(v0=1.0), base(v0=3.0, slope=1.2)]
    for key in INPUTS:
        q = ref.Q_FORMAT[key]
        lsb = math.ldexp(1.0, -q)
        lo, hi = limits[key]
        vals = list(common)
        vals += [lsb, 0.5 * lsb, 0.49 * lsb, 0.51 * lsb, 1.5 * lsb, -lsb,
                 lo, hi, hi - lsb, hi + lsb, hi + 0.4 * lsb, hi * (1.0 + 1e-7),
                 float(np.nextafter(np.float32(hi), np.float32(np.inf))),
                 float(np.nextafter(np.float32(hi), np.float32(0.0))),
                 lo - lsb, -hi, -hi - lsb, ref.fixed_max(q), ref.fixed_max(q) * 2.0]
        for b in bases:
            for v in vals:
                p = dict(b)
                p[key] = v
                w.add("hostile_" + key, p)
    # mu_inf + delta_mu >= 0 edge.
    for mu, dmu in ((0.0, 0.0), (0.1, -0.1), (0.1, -0.1 - 2**-30), (0.0, -2**-30),
                    (1.5, -1.5), (0.0, -1.5), (1.5, 1.5), (0.0, 1e-40), (0.25, -1e-40)):
        w.add("hostile_mu_sum", base(mu_inf=mu, delta_mu=dmu))
    # Corners of the domain.
    for v0 in (2**-20, 1e-3, 100.0):
        for f in (2**-12, 1.0, 500000.0):
            for a in (2**-24, 1e-3, 20.0):
                for d in (2**-30, 1e-4, 1.0):
                    for w0 in (2**-12, 1.0, 500000.0):
                        for m in (2**-16, 10000.0):
                            for dmu in (2**-30, 1.5):
                                w.add("corner", quantize({
                                    "v0": v0, "force": f, "slope": a,
                                    "damping": d, "omega0": w0, "mass": m,
                                    "mu_inf": 0.0, "delta_mu": dmu}))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("-o", "--output", default="-")
    args = ap.parse_args()
    w = Writer()
    gen(w)
    out = sys.stdout if args.output == "-" else open(args.output, "w", encoding="ascii")
    out.write("# generated by: /usr/bin/python3 tests/support/reference/gen_model_vectors.py "
              "-o tests/support/golden/model_vectors.csv (seed %d); do not edit\n" % SEED)
    out.write(",".join(COLUMNS) + "\n")
    for row in w.rows:
        out.write(",".join(row) + "\n")
    if out is not sys.stdout:
        out.close()
    counts = {}
    for row in w.rows:
        key = (row[2], row[12])
        counts[key] = counts.get(key, 0) + 1
    print("%d rows; %s" % (len(w.rows), ", ".join(
        "%s/%s %d" % (k[0], k[1], v) for k, v in sorted(counts.items()))), file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
