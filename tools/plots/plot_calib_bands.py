#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""The stability map of a calibrated brake with the uncertainty of its
borders: Monte Carlo over the fitted parameter distribution (5 / 50 / 95 %)
beside the first-order band that the firmware uses (firmware/model/
squeal_sigma.h), over disc surface speed v0 and pad force N.

usage: plot_calib_bands.py FILE.cal [--out DIR] [--name NAME] [--v-max MPS]
                           [--force-max N] [--samples K]

In the (v0, N) plane both borders are explicit: g = ln N_B(v0) - ln N with
  Hopf    ln N_H = ln(2 D w0 m / (a dmu)) + a v0        (unstable above)
  stable  ln N_S = ln N_H - ln(2 I1(s)/s), s = a v0     (stable below)
so the spread of ln N_B at a speed is the spread of the border function g.
Monte Carlo: m, w0, D independent normals, (a, dmu) bivariate normal with
slope_delta_mu_corr, from the calibration's *_sd keys (fixed seed).
First order: ln N_B +- 1.645 sigma_g with the closed-form sigma of
squeal_sigma.h (written again here in numpy with scipy's I0/I1; the firmware
itself is checked against Monte Carlo by tests/firmware/model/test_squeal_sigma.c).
The figure states how far the two pictures are apart: the largest relative
difference in N of the 5 %, 50 % and 95 % borders over the plotted speeds,
against the tolerance TOLERANCE.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
import plotlib as P  # noqa: E402
import helptext  # noqa: E402  (tools/, put on the path by plotlib)
from plotlib import plt, np  # noqa: E402
from scipy.special import i0e, i1e  # noqa: E402

import calibfit as cf  # noqa: E402

SEED = 20261129
TOLERANCE = 0.05   # relative, in N
Z95 = 1.6448536269514722
KEYS = ("mass_kg", "omega0_radps", "damping", "delta_mu", "slope_spm")


def read(path):
    raw = cf.read_calib(path)
    p = {}
    for k in KEYS:
        p[k] = float(raw.get(k, {"mass_kg": 1, "omega0_radps": 5000, "damping": 0.023,
                                   "delta_mu": 0.15, "slope_spm": 2}[k]))
        p[k + "_sd"] = float(raw.get(k + "_sd", 0.0))
    p["corr"] = float(raw.get("slope_delta_mu_corr", 0.0))
    return p


def g_bessel(s):
    """ln(2 I1(s)/s), vectorised, s > 0."""
    return np.log(2.0 * i1e(s) / s) + s


def ln_borders(m, w0, d, dmu, a, v):
    ln_h = np.log(2.0 * d * w0 * m / (a * dmu)) + a * v
    return ln_h, ln_h - g_bessel(a * v)


def monte_carlo(p, v, samples):
    rng = np.random.default_rng(SEED)
    z = rng.standard_normal((samples, 5))
    m = p["mass_kg"] + p["mass_kg_sd"] * z[:, 0]
    w0 = p["omega0_radps"] + p["omega0_radps_sd"] * z[:, 1]
    d = p["damping"] + p["damping_sd"] * z[:, 2]
    dmu = p["delta_mu"] + p["delta_mu_sd"] * z[:, 3]
    rho = p["corr"]
    a = p["slope_spm"] + p["slope_spm_sd"] * (rho * z[:, 3] + math.sqrt(1 - rho * rho) * z[:, 4])
    ok = (m > 0) & (w0 > 0) & (d > 0) & (dmu > 0) & (a > 0)
    ln_h, ln_s = ln_borders(m[ok, None], w0[ok, None], d[ok, None], dmu[ok, None],
                            a[ok, None], v[None, :])
    pct = (5, 50, 95)
    return np.percentile(ln_h, pct, axis=0), np.percentile(ln_s, pct, axis=0)


def first_order(p, v):
    """sigma of g_H and g_S: the closed form of squeal_sigma.h."""
    r = [p[k + "_sd"] / p[k] for k in KEYS]
    s = p["slope_spm"] * v
    # G'(s) = I0/I1 - 2/s
    dg = i0e(s) / i1e(s) - 2.0 / s
    base = r[0] ** 2 + r[1] ** 2 + r[2] ** 2 + r[3] ** 2
    out = []
    for fac in (s - 1.0, s - 1.0 - s * dg):
        e = r[4] * fac
        out.append(np.sqrt(np.maximum(base + e * e - 2.0 * p["corr"] * e * r[3], 0.0)))
    return out


def main(argv):
    ap = helptext.parser(__doc__, "tools/plots/plot_calib_bands.py")
    ap.add_argument("calib", metavar="FILE.cal", help="calibration file with the *_sd keys of a fit")
    ap.add_argument("--out", default="build/plots", metavar="DIR", help="folder for NAME.png and NAME.svg (default build/plots)")
    ap.add_argument("--name", default="calib_bands", help="file name without extension (default calib_bands)")
    ap.add_argument("--v-max", type=float, default=3.0, metavar="MPS", help="largest disc surface speed drawn [m/s] (default 3.0)")
    ap.add_argument("--force-max", type=float, default=20000.0, metavar="N", help="largest pad force drawn [N] (default 20000)")
    ap.add_argument("--samples", type=int, default=20000, metavar="K", help="Monte Carlo parameter sets (default 20000, fixed seed)")
    args = ap.parse_args(argv)
    p = read(args.calib)
    v = np.linspace(args.v_max / 300.0, args.v_max, 300)
    mc_h, mc_s = monte_carlo(p, v, args.samples)
    nom_h, nom_s = ln_borders(p["mass_kg"], p["omega0_radps"], p["damping"], p["delta_mu"],
                              p["slope_spm"], v)
    sig_h, sig_s = first_order(p, v)
    fo_h = np.array([nom_h - Z95 * sig_h, nom_h, nom_h + Z95 * sig_h])
    fo_s = np.array([nom_s - Z95 * sig_s, nom_s, nom_s + Z95 * sig_s])
    # compare at the speeds where a border band reaches into the picture
    inside = np.exp(np.minimum(fo_h[0], fo_s[0])) < args.force_max
    worst = max(float(np.max(np.abs(np.expm1(mc[:, inside] - fo[:, inside]))))
                for mc, fo in ((mc_h, fo_h), (mc_s, fo_s)))
    verdict = (f"first order and Monte Carlo agree within {100 * TOLERANCE:.0f} % in N "
               f"(largest difference {100 * worst:.1f} %)" if worst <= TOLERANCE else
               f"first order and Monte Carlo differ by up to {100 * worst:.1f} % in N "
               f"(more than the {100 * TOLERANCE:.0f} % tolerance)")

    fig, grid = plt.subplots(2, 2, figsize=(12, 7.6), sharex=True,
                             gridspec_kw=dict(height_ratios=(3.0, 1.35), hspace=0.12))
    axes, widths = grid[0], grid[1]
    kn = 1e-3
    for ax, aw, (title, bh, bs) in zip(axes, widths, (
            (f"Monte Carlo, {args.samples} parameter sets", mc_h, mc_s),
            ("first order (firmware, squeal_sigma.h)", fo_h, fo_s))):
        top = args.force_max * kn
        ax.fill_between(v, np.exp(nom_h) * kn, top, color=P.STATE_COLORS["unstable"], lw=0)
        ax.fill_between(v, np.exp(nom_s) * kn, np.minimum(np.exp(nom_h) * kn, top),
                        color=P.STATE_COLORS["bistable"], lw=0)
        ax.fill_between(v, 0, np.minimum(np.exp(nom_s) * kn, top),
                        color=P.STATE_COLORS["stable"], lw=0)
        for b, line, name in ((bh, P.LINE_HOPF, "Hopf border"),
                              (bs, P.LINE_EXACT, "stable border")):
            ax.fill_between(v, np.exp(b[0]) * kn, np.exp(b[2]) * kn, color=line["color"],
                            alpha=0.45, lw=0, label=f"{name}: 5-95 % band")
            ax.plot(v, np.exp(b[1]) * kn, color=line["color"], lw=1.8, label=f"{name}: 50 %")
            for k in (0, 2):
                ax.plot(v, np.exp(b[k]) * kn, color=line["color"], lw=0.8, ls="--",
                        label=f"{name}: 5 % and 95 %" if k == 0 else None)
            # the band's width, readable where it is thin on the map
            aw.fill_between(v, 100.0 * np.expm1(b[0] - b[1]), 100.0 * np.expm1(b[2] - b[1]),
                            color=line["color"], alpha=0.45, lw=0,
                            label=f"{name}: 5-95 % band")
        aw.axhline(0.0, color="0.3", lw=0.8, label="50 % border")
        ax.set_xlim(0, args.v_max)
        ax.set_ylim(0, top)
        ax.set_title(title, fontsize=10)
        aw.set_xlabel("disc surface speed v0 [m/s]")
        for a in (ax, aw):
            a.grid(alpha=0.3)
    axes[0].set_ylabel("pad force N [kN]")
    widths[0].set_ylabel("band: N / N(50 %) - 1 [%]")
    handles, _ = axes[0].get_legend_handles_labels()
    axes[0].legend(handles=handles + P.region_handles(), fontsize=7, loc="lower right",
                   framealpha=0.92)
    widths[0].legend(fontsize=7, loc="upper right", framealpha=0.92)
    fig.suptitle(f"{os.path.basename(args.calib)}: borders with the calibration's uncertainty"
                 f"\n{verdict}", fontsize=11)
    for path in P.save(fig, args.out, args.name):
        print(path)
    print(verdict)
    return 0


if __name__ == "__main__":
    sys.exit(cf.run_tool(main, sys.argv[1:]))
