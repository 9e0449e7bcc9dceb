#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""tools/plots/plot_calib_bands.py on calibration files written here: the
paper's brake without uncertainty (both bands collapse onto the nominal
borders) and with only the damping uncertain (sd 10 % of D). Checked as
the reader of the picture relies on it: the files, the two panels with
their axes, units, titles and legend, the borders where docs/model.md's closed
forms put them and the bands as wide as derived by hand:
  N_H(v0) = 2 D w0 m / (a dmu) e^(a v0), at v0 = 1 m/s, a = 2 s/m:
            230 / 0.3 e^2 N = 5664.9 N
  N_S(v0) = N_H / (2 I1(s)/s), s = a v0 = 2: 5664.9 / I1(2) N (scipy's I1)
  first order, only D uncertain: ln N_H +- 1.645 sd(D)/D, so the 5 % and
            95 % borders are N_H e^-+0.1645
  Monte Carlo, D normal: the 95 % border is N_H (1 + 1.645 sd(D)/D)
  (within the sampling error of 4000 sets);
the verdict it prints and states in the title; a file it cannot read is
one line and exit 1.

prints "RESULT: N passed, M failed"
"""
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from figures import PLOTS, Checks, draw, files_ok, legend_texts, line_at, lines_of_colour, plotlib, suptitle  # noqa: E402,E501
from scipy.special import iv  # noqa: E402

N_H_1 = 2.0 * 0.023 * 5000.0 * 1.0 / (2.0 * 0.15) * math.exp(2.0) / 1000.0   # kN at v0 = 1 m/s
N_S_1 = N_H_1 / iv(1, 2.0)
Z95 = 1.6448536269514722
SAMPLES = "4000"


def write_cal(path, damping_sd):
    with open(path, "w") as f:
        f.write("# the paper's brake\nmass_kg = 1\nomega0_radps = 5000\ndamping = 0.023\n"
                "delta_mu = 0.15\nslope_spm = 2\nmu_inf = 0.25\n")
        if damping_sd:
            f.write("damping_sd = %r\n" % damping_sd)
    return path


def borders(ax, colour):
    """(solid 50 % line, [dashed lines low to high]) of one border."""
    lines = lines_of_colour(ax, colour)
    solid = [ln for ln in lines if ln.get_linestyle() == "-"]
    dashed = sorted((ln for ln in lines if ln.get_linestyle() == "--"), key=lambda ln: line_at(ln, 1.0))
    return solid, dashed


def nominal(c, tmp):
    cal = write_cal(os.path.join(tmp, "sharp.cal"), 0.0)
    rc, out, saved = draw("plot_calib_bands", [cal, "--out", tmp, "--name", "sharp", "--samples", SAMPLES])
    c.check(rc == 0 and len(saved) == 1 and saved[0][0] == "sharp" and files_ok(saved[0][2]),
            "sharp.png and .svg written, not empty (exit %r)" % (rc,))
    fig = saved[0][1]
    mc, fo = fig.axes[0], fig.axes[1]
    c.check(mc.get_title() == "Monte Carlo, 4000 parameter sets"
            and fo.get_title() == "first order (firmware, squeal_sigma.h)",
            "the two panels: Monte Carlo and first order (%r, %r)" % (mc.get_title(), fo.get_title()))
    wmc, wfo = fig.axes[2], fig.axes[3]
    c.check([a.get_xlabel() for a in (wmc, wfo)] == ["disc surface speed v0 [m/s]"] * 2
            and mc.get_ylabel() == "pad force N [kN]"
            and wmc.get_ylabel() == "band: N / N(50 %) - 1 [%]"
            and wmc.get_xlim() == mc.get_xlim(),
            "axes: speed v0 [m/s] across (shared), pad force N [kN] up; below, the band's width in %")
    c.check(mc.get_xlim() == (0.0, 3.0) and mc.get_ylim() == (0.0, 20.0),
            "default ranges: 0..3 m/s, 0..20 kN (%s %s)" % (mc.get_xlim(), mc.get_ylim()))
    c.check(legend_texts(mc.get_legend()) == [
                "Hopf border: 5-95 % band", "Hopf border: 50 %", "Hopf border: 5 % and 95 %",
                "stable border: 5-95 % band", "stable border: 50 %", "stable border: 5 % and 95 %",
                "region: unstable (squeal)", "region: bistable (squeal possible after a kick)",
                "region: stable"]
            and legend_texts(wmc.get_legend()) == ["Hopf border: 5-95 % band",
                                                   "stable border: 5-95 % band", "50 % border"],
            "legend: each border's 50 %% line and 5-95 %% band (%s)" % legend_texts(mc.get_legend()))
    ok = True
    for ax in (mc, fo):
        for colour, want in ((plotlib.LINE_HOPF["color"], N_H_1), (plotlib.LINE_EXACT["color"], N_S_1)):
            solid, dashed = borders(ax, colour)
            ok = ok and len(solid) == 1 and len(dashed) == 2
            ok = ok and all(abs(line_at(ln, 1.0) - want) < 1e-3 * want for ln in solid + dashed)
    c.check(ok, "no uncertainty: in both panels the 5, 50 and 95 %% borders at v0 = 1 m/s are "
            "N_H = %.4f kN and N_S = %.4f kN" % (N_H_1, N_S_1))
    verdict = "first order and Monte Carlo agree within 5 % in N (largest difference 0.0 %)"
    c.check(out.splitlines()[-1] == verdict and verdict in suptitle(fig),
            "the verdict printed and in the title: %r" % out.splitlines()[-1])


def damping_only(c, tmp):
    r = 0.1
    cal = write_cal(os.path.join(tmp, "soft.cal"), 0.023 * r)
    rc, out, saved = draw("plot_calib_bands", [cal, "--out", tmp, "--name", "soft", "--samples", SAMPLES])
    mc, fo = saved[0][1].axes[0], saved[0][1].axes[1]
    _, dashed = borders(fo, plotlib.LINE_HOPF["color"])
    got = [line_at(ln, 1.0) for ln in dashed]
    want = [N_H_1 * math.exp(-Z95 * r), N_H_1 * math.exp(Z95 * r)]
    c.check(len(got) == 2 and all(abs(g - w) < 1e-3 * w for g, w in zip(got, want)),
            "first order, sd(D) = 10 %%: Hopf 5 / 95 %% at v0 = 1 m/s %s kN (by hand %s)"
            % (["%.4f" % g for g in got], ["%.4f" % w for w in want]))
    _, dashed_s = borders(fo, plotlib.LINE_EXACT["color"])
    got_s = [line_at(ln, 1.0) / N_S_1 for ln in dashed_s]
    c.check(len(got_s) == 2 and all(abs(g - w / N_H_1) < 1e-3 for g, w in zip(got_s, want)),
            "the stable border's band the same factors e^-+0.1645 (only D, not s, is uncertain)")
    _, dashed = borders(mc, plotlib.LINE_HOPF["color"])
    hi = line_at(dashed[1], 1.0) if len(dashed) == 2 else -1.0
    c.check(abs(hi - N_H_1 * (1.0 + Z95 * r)) < 0.01 * N_H_1,
            "Monte Carlo: Hopf 95 %% at v0 = 1 m/s %.4f kN (by hand N_H (1 + 1.645 x 0.1) = %.4f)"
            % (hi, N_H_1 * (1.0 + Z95 * r)))
    c.check(rc == 0 and out.splitlines()[-1].startswith("first order and Monte Carlo agree within 5 % in N"),
            "the two agree within the tool's 5 %%: %r" % out.splitlines()[-1])


def refusal(c, tmp):
    bad = os.path.join(tmp, "bad.cal")
    with open(bad, "w") as f:
        f.write("mass_kg = 1\ndamping 0.023\n")
    r = subprocess.run([sys.executable, os.path.join(PLOTS, "plot_calib_bands.py"), bad, "--out", tmp,
                        "--name", "bad"], capture_output=True, text=True, timeout=60)
    c.check(r.returncode == 1 and r.stderr.strip() == "plot_calib_bands.py: %s:2: expected 'key = value'" % bad
            and not os.path.exists(os.path.join(tmp, "bad.png")),
            "a line without '=': one line naming it, exit 1, nothing drawn (%r)" % r.stderr.strip())


def main():
    return Checks.run(nominal, damping_only, refusal)


if __name__ == "__main__":
    sys.exit(main())
