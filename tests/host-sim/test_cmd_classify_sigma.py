#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""`squeal-sim classify --calib FILE --json` reports border_margin_sigma, in
both numeric builds, against the Monte Carlo file of round one
(tests/support/golden/sigma_vectors.csv, tests/support/reference/gen_sigma_reference.py):
for every row a calibration file with the row's brake and standard
deviations, and the margin of the reference class from the file's
first-order sigmas (numerical derivatives) and g values, within 1 %; and
within 7 % of the Monte Carlo margin where first order holds (mc_vs_lin <
5 %). Zero standard deviations, no --calib, a point not sliding (null), a
parameter option next to --calib and a --corner the file lacks (refused)
are checked too.
"""

import csv
import json
import os
import subprocess
import sys
import tempfile

# tests/ of this checkout: the shared checks live in tests/tools
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools"))
from checks import ROOT, Checks  # noqa: E402

GOLDEN = os.path.join(ROOT, "tests", "support", "golden", "sigma_vectors.csv")
BUILDS = ("host", "host-fixed")
STATE = {0: "stable", 1: "bistable", 2: "unstable"}


def sim(build):
    return os.path.join(ROOT, "build", build, "squeal-sim")


def classify(build, args):
    r = subprocess.run([sim(build), "classify"] + args + ["--json"], capture_output=True,
                       text=True, timeout=60)
    return r.returncode, (json.loads(r.stdout) if r.stdout.strip().startswith("{") else {})


def margin(state, gh, gs, sh, ss):
    to_h, to_s = abs(gh) / sh, abs(gs) / ss
    return {2: to_h, 0: to_s, 1: min(to_h, to_s)}[state]


def cal_text(row):
    return "".join(f"{k} = {row[c]}\n" for k, c in (
        ("mass_kg", "mass"), ("omega0_radps", "omega0"), ("damping", "damping"),
        ("mu_inf", "mu_inf"), ("delta_mu", "delta_mu"), ("slope_spm", "slope"),
        ("mass_kg_sd", "mass_sd"), ("omega0_radps_sd", "omega0_sd"),
        ("damping_sd", "damping_sd"), ("delta_mu_sd", "delta_mu_sd"),
        ("slope_spm_sd", "slope_sd"), ("slope_delta_mu_corr", "corr")))


def main():
    c = Checks()
    with open(GOLDEN, encoding="utf-8") as f:
        rows = [r for r in csv.DictReader(ln for ln in f if not ln.startswith("#"))]
    with tempfile.TemporaryDirectory() as tmp:
        for build in BUILDS:
            worst = 0.0
            worst_mc = 0.0
            fails = []
            n = 0
            for row in rows[::3]:
                st = int(row["state"])
                if st not in STATE:
                    continue
                path = os.path.join(tmp, "r.cal")
                with open(path, "w", encoding="ascii") as f:
                    f.write(cal_text(row))
                rc, got = classify(build, ["--v0", row["v0"], "--force", row["force"],
                                           "--calib", path])
                g = [float(row[k]) for k in ("g_hopf", "g_stable")]
                want = margin(st, g[0], g[1], float(row["sigma_hopf_lin"]),
                              float(row["sigma_stable_lin"]))
                mc = margin(st, g[0], g[1], float(row["sigma_hopf_mc"]),
                            float(row["sigma_stable_mc"]))
                m = got.get("border_margin_sigma")
                n += 1
                if rc != 0 or got.get("state") != STATE[st] or m is None:
                    fails.append((row["id"], rc, got.get("state"), m))
                    continue
                err = abs(m - want) / max(want, 1.0)
                worst = max(worst, err)
                if float(row["mc_vs_lin"]) < 0.05:
                    worst_mc = max(worst_mc, abs(m - mc) / max(mc, 1.0))
                if err > 0.01:
                    fails.append((row["id"], m, want))
            c.check(n > 50 and not fails,
                    f"{build}: border_margin_sigma of {n} golden rows within 1 % of first order "
                    f"(largest {100 * worst:.3f} %; problems {fails[:3]})")
            c.check(worst_mc < 0.07,
                    f"{build}: and within 7 % of Monte Carlo where first order holds "
                    f"(largest {100 * worst_mc:.2f} %)")
            # zero deviations: no margin; not sliding: none either
            path = os.path.join(tmp, "zero.cal")
            with open(path, "w", encoding="ascii") as f:
                f.write("slope_spm = 2\n")
            rc, got = classify(build, ["--v0", "1.2", "--force", "9000", "--calib", path])
            c.check(rc == 0 and "border_margin_sigma" in got and
                    got["border_margin_sigma"] is None,
                    f"{build}: zero standard deviations: border_margin_sigma null ({got.get('border_margin_sigma', 'missing')})")
            rc, got = classify(build, ["--v0", "1.2", "--force", "9000"])
            c.check(rc == 0 and got.get("border_margin_sigma", 0) is None,
                    f"{build}: without --calib: border_margin_sigma null")
            path = os.path.join(tmp, "sd.cal")
            with open(path, "w", encoding="ascii") as f:
                f.write(cal_text(rows[0]))
            rc, got = classify(build, ["--v0", "0", "--force", "9000", "--calib", path])
            c.check(rc == 0 and got.get("state") == "not_sliding" and
                    got.get("border_margin_sigma", 0) is None,
                    f"{build}: not sliding: border_margin_sigma null")
            r = subprocess.run([sim(build), "classify", "--v0", "1", "--force", "9000",
                                "--calib", path, "--slope", "3"], capture_output=True,
                               text=True, timeout=60)
            c.check(r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1,
                    f"{build}: --calib with --slope refused in one line (exit {r.returncode})")
            r = subprocess.run([sim(build), "classify", "--v0", "1", "--force", "9000",
                                "--calib", path, "--corner", "RR"], capture_output=True,
                               text=True, timeout=60)
            c.check(r.returncode == 2 and "no [corner RR]" in r.stderr,
                    f"{build}: --corner RR of a file without it refused: {r.stderr.strip()}")
    return c.finish()


if __name__ == "__main__":
    sys.exit(main())
