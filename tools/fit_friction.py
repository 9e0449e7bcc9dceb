#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Fit the friction law mu(v) = mu_inf + delta_mu exp(-a v) to measurements.

    tools/fit_friction.py DATA.csv [--base FILE.cal] [-o FILE.cal] [--plot FILE.png] [--json]

DATA.csv columns (header line; '#' comments allowed):
  v_mps,mu[,mu_sd]                      friction coefficient over sliding speed
  disc_rpm,torque_nm,pressure_bar[,torque_sd_nm]
                                        a brake dynamometer run; needs
                                        --pad-radius-m --piston-area-mm2 --faces:
      mu = T / (faces p A r_p),  v = 2 pi rpm / 60 * r_p
With an uncertainty column (mu_sd, or torque_sd_nm propagated to mu) the fit
is weighted by it and the covariance is absolute; without, all points weigh
the same and the covariance is scaled by the residuals (Student t intervals).

Weighted nonlinear least squares (scipy.optimize.curve_fit, several starting
slopes, the best kept). Refused with one line and exit status 1: fewer than 6
points, fewer than 3 distinct speeds, speeds that cannot identify a (its 95 %
interval wider than its value), no falling friction (delta_mu <= 0 within its
95 % interval, or a <= 0), values outside the calibration's ranges, and bad
files (empty, wrong columns, not a number).

--json prints {"mu_inf": {"value", "stderr", "ci95": [lo, hi]}, "delta_mu":
{...}, "slope_spm": {...}, "corr_slope_delta_mu", "rms"}. -o writes the
calibration keys mu_inf, delta_mu, slope_spm and their standard deviations
mu_inf_sd, delta_mu_sd, slope_spm_sd, slope_delta_mu_corr (--base keeps the
other lines of a calibration file; --no-sd leaves the standard deviations
out, for firmware that does not read them yet).
"""

import math
import os
import sys
import warnings

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import deps  # noqa: E402  (names the Debian package of a missing module)

deps.need("numpy", "scipy")
import numpy as np  # noqa: E402
from scipy.optimize import OptimizeWarning, curve_fit  # noqa: E402

import calibfit as cf  # noqa: E402
import helptext  # noqa: E402

MIN_POINTS = 6
MIN_SPEEDS = 3
# calibration ranges (docs/calib-example.txt)
RANGES = {"mu_inf": (0.0, 1.5), "delta_mu": (-1.5, 1.5), "slope_spm": (0.0, 20.0)}
LAYOUTS = {
    "mu": (("v_mps", "mu"), ("mu_sd",)),
    "dyno": (("disc_rpm", "torque_nm", "pressure_bar"), ("torque_sd_nm",)),
}
COMMENTS = {
    "mu_inf": "fitted: friction coefficient at high sliding speed",
    "delta_mu": "fitted: mu_0 - mu_inf",
    "slope_spm": "fitted: friction slope a [s/m]",
    "mu_inf_sd": "fitted: standard deviation of mu_inf",
    "delta_mu_sd": "fitted: standard deviation of delta_mu",
    "slope_spm_sd": "fitted: standard deviation of slope_spm [s/m]",
    "slope_delta_mu_corr": "fitted: correlation of slope_spm and delta_mu",
}


def friction(v, mu_inf, delta_mu, a):
    return mu_inf + delta_mu * np.exp(-a * v)


def to_mu(cols, pad_radius_m, piston_area_mm2, faces):
    """Dynamometer columns -> (v_mps, mu, mu_sd or None)."""
    if pad_radius_m is None or piston_area_mm2 is None or faces is None:
        raise cf.Refusal("dynamometer columns (disc_rpm,torque_nm,pressure_bar) need "
                         "--pad-radius-m, --piston-area-mm2 and --faces")
    if not (pad_radius_m > 0 and piston_area_mm2 > 0 and faces > 0):
        raise cf.Refusal("--pad-radius-m, --piston-area-mm2 and --faces must be positive")
    p = cols["pressure_bar"]
    if np.any(p <= 0):
        raise cf.Refusal("pressure_bar must be positive in every row "
                         f"(row {int(np.argmax(p <= 0)) + 1} is {p[p <= 0][0]:g})")
    if np.any(cols["disc_rpm"] < 0):
        raise cf.Refusal("disc_rpm must not be negative")
    normal_n = faces * p * 1e5 * piston_area_mm2 * 1e-6
    mu = cols["torque_nm"] / (normal_n * pad_radius_m)
    v = cols["disc_rpm"] * 2.0 * math.pi / 60.0 * pad_radius_m
    sd = None
    if "torque_sd_nm" in cols:
        sd = cols["torque_sd_nm"] / (normal_n * pad_radius_m)
    return v, mu, sd


def fit(v, mu, mu_sd=None):
    """Fit and check. Returns a dict: value (3), cov (3x3), dof (None when
    the covariance is absolute), rms. Raises cf.Refusal."""
    v = np.asarray(v, dtype=float)
    mu = np.asarray(mu, dtype=float)
    n = len(v)
    if n < MIN_POINTS:
        raise cf.Refusal(f"{n} points: the fit needs at least {MIN_POINTS}")
    if np.any(v < 0):
        raise cf.Refusal("sliding speeds must not be negative")
    speeds = np.unique(v)
    if len(speeds) == 1:
        raise cf.Refusal(f"all points at one speed ({speeds[0]:g} m/s): "
                         "a friction-speed curve needs several speeds")
    if len(speeds) < MIN_SPEEDS:
        raise cf.Refusal(f"{len(speeds)} distinct speeds: three parameters need at least "
                         f"{MIN_SPEEDS}")
    if mu_sd is not None and np.any(np.asarray(mu_sd) <= 0):
        raise cf.Refusal("uncertainty column must be positive in every row")
    absolute = mu_sd is not None
    vspan = float(np.max(v) - np.min(v))
    best = None
    with warnings.catch_warnings(), np.errstate(all="ignore"):
        warnings.simplefilter("ignore", OptimizeWarning)
        warnings.simplefilter("ignore", RuntimeWarning)
        for a0 in (0.3, 1.0, 3.0, 10.0, 30.0):
            a0 = a0 / vspan
            # for a given a the model is linear in (mu_inf, delta_mu)
            e = np.exp(-a0 * v)
            A = np.column_stack([np.ones_like(v), e])
            lin, *_ = np.linalg.lstsq(A, mu, rcond=None)
            try:
                p, cov = curve_fit(friction, v, mu, p0=[lin[0], lin[1], a0], sigma=mu_sd,
                                   absolute_sigma=absolute, maxfev=4000)
            except (RuntimeError, ValueError):
                continue
            r = (mu - friction(v, *p)) / (1.0 if mu_sd is None else mu_sd)
            cost = float(np.sum(r * r))
            if np.all(np.isfinite(p)) and np.all(np.isfinite(cov)) and \
                    (best is None or cost < best[2]):
                best = (p, cov, cost)
    if best is None:
        raise cf.Refusal("the fit did not converge: the data do not follow "
                         "mu_inf + delta_mu exp(-a v)")
    p, cov, _ = best
    res = {"value": p, "cov": cov, "dof": None if absolute else n - 3,
           "rms": float(np.sqrt(np.mean((mu - friction(v, *p)) ** 2)))}
    check(res, v)
    return res


def intervals(res):
    q = cf.t_quantile(res["dof"])
    se = np.sqrt(np.diag(res["cov"]))
    return q, se


NO_FALL = "no falling friction: this model predicts no friction-induced instability"


def check(res, v):
    """The refusals, in this order: friction that does not fall over the
    measured speeds (the fitted drop mu(v_min) - mu(v_max) is not above 0
    within its 95 % interval: a statement about the data that holds even
    when a and delta_mu are not separately determined); a not identified;
    delta_mu <= 0 within its interval; values outside the calibration."""
    mu_inf, dmu, a = res["value"]
    q, se = intervals(res)
    lo_v, hi_v = float(np.min(v)), float(np.max(v))
    e_lo, e_hi = math.exp(-a * lo_v), math.exp(-a * hi_v)
    drop = dmu * (e_lo - e_hi)
    jac = np.array([0.0, e_lo - e_hi, -dmu * (lo_v * e_lo - hi_v * e_hi)])
    drop_sd = math.sqrt(max(float(jac @ res["cov"] @ jac), 0.0))
    if a <= 0.0 or drop - q * drop_sd <= 0.0:
        raise cf.Refusal(f"{NO_FALL} (mu falls by {drop:.3g} +- {q * drop_sd:.2g} from "
                         f"{lo_v:.3g} to {hi_v:.3g} m/s)")
    if 2.0 * q * se[2] > a:
        raise cf.Refusal(f"the speeds cannot identify a: its 95 % interval "
                         f"[{a - q * se[2]:.3g}, {a + q * se[2]:.3g}] s/m is wider than "
                         f"its value {a:.3g} s/m (measure over a wider speed range, "
                         f"around 1/a)")
    if dmu - q * se[1] <= 0.0:
        raise cf.Refusal(f"{NO_FALL} (delta_mu = {dmu:.4g} +- {q * se[1]:.2g})")
    for name, val in zip(("mu_inf", "delta_mu", "slope_spm"), (mu_inf, dmu, a)):
        lo, hi = RANGES[name]
        if not lo <= val <= hi:
            raise cf.Refusal(f"fitted {name} = {val:.4g} is outside the calibration's "
                             f"range {lo:g} .. {hi:g}")


def summary(res):
    """The --json object of the issue."""
    q, se = intervals(res)
    out = {}
    for i, name in enumerate(("mu_inf", "delta_mu", "slope_spm")):
        out[name] = cf.param_json(res["value"][i], se[i], q)
    out["corr_slope_delta_mu"] = float(res["cov"][1, 2] / (se[1] * se[2]))
    out["rms"] = res["rms"]
    return out


def calib_values(res, with_sd=True):
    s = summary(res)
    vals = {k: s[k]["value"] for k in ("mu_inf", "delta_mu", "slope_spm")}
    if with_sd:
        vals.update({"mu_inf_sd": s["mu_inf"]["stderr"],
                     "delta_mu_sd": s["delta_mu"]["stderr"],
                     "slope_spm_sd": s["slope_spm"]["stderr"],
                     "slope_delta_mu_corr": s["corr_slope_delta_mu"]})
    return vals


def plot(path, v, mu, mu_sd, res, title):
    plt = cf.pyplot()

    p = res["value"]
    cov = res["cov"]
    q, _ = intervals(res)
    vv = np.linspace(0.0, max(float(np.max(v)) * 1.05, 1e-3), 300)
    e = np.exp(-p[2] * vv)
    jac = np.column_stack([np.ones_like(vv), e, -p[1] * vv * e])
    band = q * np.sqrt(np.einsum("ij,jk,ik->i", jac, cov, jac))
    fitc = friction(vv, *p)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    if mu_sd is None:
        ax.plot(v, mu, "o", ms=4, color="0.3", label="measured")
    else:
        ax.errorbar(v, mu, yerr=mu_sd, fmt="o", ms=4, color="0.3", label="measured (1 sd)")
    ax.fill_between(vv, fitc - band, fitc + band, color="tab:blue", alpha=0.25,
                    label="95 % band of the fitted curve")
    s = summary(res)
    ax.plot(vv, fitc, color="tab:blue",
            label=(f"fit μ(v) = μ∞ + Δμ e^(-a v): μ∞ {p[0]:.4f}, Δμ {p[1]:.4f}, a {p[2]:.3f} s/m\n"
                   f"corr(a, Δμ) {s['corr_slope_delta_mu']:+.2f}, rms {res['rms']:.2g}"))
    ax.set_xlabel("sliding speed v [m/s]")
    ax.set_ylabel("friction coefficient μ [-]")
    cf.finish_plot(fig, ax, title, path)


def main(argv):
    ap = helptext.parser(__doc__, "tools/fit_friction.py")
    ap.add_argument("data", metavar="DATA.csv", help="the measurements (columns below)")
    ap.add_argument("--pad-radius-m", type=float, metavar="R",
                    help="dynamometer data: effective pad radius r_p [m]")
    ap.add_argument("--piston-area-mm2", type=float, metavar="A",
                    help="dynamometer data: piston area per face A [mm^2]")
    ap.add_argument("--faces", type=int, metavar="K",
                    help="dynamometer data: friction faces (2 for a floating caliper)")
    cf.add_output_args(ap, "PNG of the data, the fit and its band")
    args = ap.parse_args(argv)

    layout, cols = cf.read_csv(args.data, LAYOUTS)
    if layout == "dyno":
        v, mu, mu_sd = to_mu(cols, args.pad_radius_m, args.piston_area_mm2, args.faces)
    else:
        v, mu, mu_sd = cols["v_mps"], cols["mu"], cols.get("mu_sd")
    try:
        res = fit(v, mu, mu_sd)
    except cf.Refusal as e:
        raise cf.Refusal(f"{args.data}: {e}") from None
    if args.output:
        cf.write_calib(args.output, calib_values(res, not args.no_sd), COMMENTS, args.base,
                       header=(f"friction law fitted by tools/fit_friction.py from "
                               f"{os.path.basename(args.data)}",))
    if args.plot:
        plot(args.plot, v, mu, mu_sd, res, f"friction law from {os.path.basename(args.data)}")
    if args.json:
        cf.print_json(summary(res))
    elif args.output != "-":
        s = summary(res)
        print(f"{len(v)} points, {len(np.unique(v))} speeds, rms residual {res['rms']:.3g}")
        for k, unit in (("mu_inf", ""), ("delta_mu", ""), ("slope_spm", " s/m")):
            lo, hi = s[k]["ci95"]
            print(f"{k:10s} {s[k]['value']:.5g} +- {s[k]['stderr']:.2g}{unit}"
                  f"  (95 %: {lo:.5g} .. {hi:.5g})")
        print(f"corr(slope, delta_mu) {s['corr_slope_delta_mu']:+.3f}")
    return 0


if __name__ == "__main__":
    sys.exit(cf.run_tool(main, sys.argv[1:]))
