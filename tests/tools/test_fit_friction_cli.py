#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""The fitting tools as a user runs them (subprocess):

  - every bad input gets exactly one line on stderr, exit status 1, nothing
    on stdout and never a traceback: empty file, header only, wrong
    columns, NaN/inf, not a number, ragged row, a single speed, fewer than 6
    points, no falling friction (the issue's wording), speeds that cannot
    identify a, dynamometer columns without the geometry, a missing file;
    for fit_modal: a constant signal, a non-decaying sine, non-uniform time,
    too few samples, a broken WAV, an FRF without both half-power points;
  - --json has exactly the issue's keys; -o writes the calibration keys and
    their standard deviations, --base keeps every other line of the base
    file; --no-sd output (and the full file: tests/tools/test_calibfit_user.py)
    is accepted by `squeal-sim replay --calib`;
  - the example files in docs/examples are exactly what
    tools/gen_calib_examples.py generates, example-brake.cal what the two
    fits write from them, and its band picture states agreement within 5 %.
"""

import filecmp
import json
import math
import os
import subprocess
import sys

import numpy as np

from checks import ROOT, TOOLS, Checks

PY = sys.executable
FRICTION = os.path.join(TOOLS, "fit_friction.py")
MODAL = os.path.join(TOOLS, "fit_modal.py")
SIM = os.path.join(ROOT, "build", "host", "squeal-sim")
DYNO = ["--pad-radius-m", "0.12", "--piston-area-mm2", "2000", "--faces", "2"]


def run(args, stdin=None):
    return subprocess.run([PY] + args, capture_output=True, text=True, input=stdin,
                          timeout=120)


def write(tmp, name, text):
    path = os.path.join(tmp, name)
    with open(path, "w", encoding="ascii") as f:
        f.write(text)
    return path


def friction_rows(v, mu):
    return "v_mps,mu\n" + "".join(f"{a:.6g},{b:.6g}\n" for a, b in zip(v, mu))


def refusal(c, tool, args, phrase, what):
    r = run([tool] + args)
    lines = r.stderr.strip().splitlines()
    ok = (r.returncode == 1 and len(lines) == 1 and "Traceback" not in r.stderr
          and r.stdout == "" and phrase in r.stderr)
    c.check(ok, f"{os.path.basename(tool)} {what}: exit {r.returncode}, "
                f"{len(lines)} line(s): {lines[0] if lines else ''}")


def friction_refusals(c, tmp):
    v = np.geomspace(0.05, 6.0, 12)
    mu = 0.25 + 0.15 * np.exp(-2.0 * v)
    rng = np.random.default_rng(7)
    cases = [
        ("empty.csv", "", "empty file", "empty file"),
        ("header.csv", "v_mps,mu\n", "no data rows", "header only"),
        ("cols.csv", "speed,friction\n1,0.3\n", "expected v_mps,mu", "wrong columns"),
        ("nan.csv", "v_mps,mu\n0.1,0.3\n0.2,nan\n", "not a finite number", "NaN"),
        ("inf.csv", "v_mps,mu\n0.1,0.3\n0.2,inf\n", "not a finite number", "inf"),
        ("word.csv", "v_mps,mu\n0.1,0.3\n0.2,high\n", "is not a number", "not a number"),
        ("ragged.csv", "v_mps,mu\n0.1,0.3,7\n", "fields, the header has", "ragged row"),
        ("one_speed.csv", friction_rows([1.0] * 10, 0.3 + 0.01 * rng.standard_normal(10)),
         "all points at one speed", "a single speed"),
        ("five.csv", friction_rows(v[:5], mu[:5]), "at least 6", "5 points"),
        ("flat.csv", friction_rows(v, 0.3 + 0.002 * (-1.0) ** np.arange(len(v))),
         "no falling friction: this model predicts no friction-induced instability",
         "constant friction"),
        ("rising.csv", friction_rows(v, 0.4 - 0.15 * np.exp(-2.0 * v)
                                     + 0.003 * rng.standard_normal(len(v))),
         "no falling friction: this model predicts no friction-induced instability",
         "rising friction"),
        ("slow.csv", friction_rows(np.linspace(0.001, 0.01, 12),
                                   0.4 - 3.0 * np.linspace(0.001, 0.01, 12)
                                   + 0.0005 * rng.standard_normal(12)),
         "cannot identify a", "speeds far below 1/a"),
    ]
    for name, text, phrase, what in cases:
        refusal(c, FRICTION, [write(tmp, name, text)], phrase, what)
    dyno = write(tmp, "dyno.csv", "disc_rpm,torque_nm,pressure_bar\n10,300,20\n")
    refusal(c, FRICTION, [dyno], "need --pad-radius-m", "dyno columns without geometry")
    refusal(c, FRICTION, [os.path.join(tmp, "missing.csv")], "No such file", "missing file")


def modal_refusals(c, tmp):
    t = np.arange(2000) / 48000.0

    def ring(y, tt=t):
        return "t_s,accel\n" + "".join(f"{a:.9g},{b:.6g}\n" for a, b in zip(tt, y))

    sine = np.sin(2 * math.pi * 800 * t)
    uneven = t.copy()
    uneven[1000:] += 0.3 / 48000.0
    decay = np.exp(-100 * t) * np.sin(2 * math.pi * 800 * t)
    f = np.linspace(850, 950, 50)
    w = 2 * math.pi * f
    h = 1 / (5000.0 ** 2 - w ** 2 + 2j * 0.023 * 5000 * w)
    cases = [
        ("const.csv", ring(np.ones_like(t)), "constant", "constant signal"),
        ("sine.csv", ring(sine), "does not decay", "non-decaying sine"),
        ("uneven.csv", ring(decay, uneven), "not uniformly spaced", "non-uniform time"),
        ("short.csv", ring(decay[:20], t[:20]), "at least 64", "20 samples"),
        ("empty.csv", "", "empty file", "empty file"),
        ("cols.csv", "time,acc\n0,1\n", "expected t_s,accel", "wrong columns"),
        ("nan.csv", "t_s,accel\n0,1\n1,nan\n", "not a finite number", "NaN"),
        ("frf.csv", "f_hz,magnitude,phase_deg\n" + "".join(
            f"{a:.3f},{abs(b):.6e},{math.degrees(np.angle(b)):.3f}\n" for a, b in zip(f, h)),
         "half-power", "FRF without both half-power points"),
    ]
    for name, text, phrase, what in cases:
        refusal(c, MODAL, [write(tmp, name, text)], phrase, what)
    bad_wav = os.path.join(tmp, "bad.wav")
    with open(bad_wav, "wb") as fh:
        fh.write(b"RIFF\x10\x00\x00\x00WAVEjunk")
    refusal(c, MODAL, [bad_wav], "WAV", "broken WAV")


def outputs(c, tmp):
    ex = os.path.join(ROOT, "docs", "examples")
    r = run([FRICTION, os.path.join(ex, "dyno.csv")] + DYNO + ["--json"])
    keys = set(json.loads(r.stdout)) if r.returncode == 0 else set()
    c.check(keys == {"mu_inf", "delta_mu", "slope_spm", "corr_slope_delta_mu", "rms"},
            f"fit_friction --json keys {sorted(keys)}")
    r = run([MODAL, os.path.join(ex, "tap_test.wav"), "--json"])
    keys = set(json.loads(r.stdout)) if r.returncode == 0 else set()
    c.check({"omega0_radps", "damping"} <= keys and
            set(json.loads(r.stdout)["damping"]) == {"value", "stderr", "ci95"},
            f"fit_modal --json keys {sorted(keys)}")

    base = os.path.join(ROOT, "docs", "calib-example.txt")
    step1 = os.path.join(tmp, "step1.cal")
    step2 = os.path.join(tmp, "brake.cal")
    r1 = run([FRICTION, os.path.join(ex, "dyno.csv")] + DYNO + ["--base", base, "-o", step1])
    r2 = run([MODAL, os.path.join(ex, "tap_test.wav"), "--mass-kg", "0.9", "--mass-sd-kg",
              "0.01", "--base", step1, "-o", step2])
    c.check(r1.returncode == 0 and r2.returncode == 0, "friction then modal into one file")
    with open(step2, encoding="utf-8") as f:
        lines = f.read().splitlines()
    with open(base, encoding="utf-8") as f:
        base_lines = f.read().splitlines()
    keys = [ln.split("=")[0].strip() for ln in lines if "=" in ln and not ln.startswith("#")]
    want = {"mu_inf", "delta_mu", "slope_spm", "mu_inf_sd", "delta_mu_sd", "slope_spm_sd",
            "slope_delta_mu_corr", "omega0_radps", "damping", "mass_kg", "omega0_radps_sd",
            "damping_sd", "mass_kg_sd"}
    c.check(want <= set(keys) and len(keys) == len(set(keys)),
            f"calibration file has every fitted key once ({len(keys)} keys)")
    # the fitted keys and their deviations (the base file sets the deviations
    # to 0, the default, like every other key)
    fitted = {"mu_inf", "delta_mu", "slope_spm", "omega0_radps", "damping", "mass_kg",
              "mu_inf_sd", "delta_mu_sd", "slope_spm_sd", "slope_delta_mu_corr",
              "omega0_radps_sd", "damping_sd", "mass_kg_sd"}
    kept = [ln for ln in base_lines
            if not ("=" in ln and ln.split("=")[0].strip() in fitted)]
    c.check(all(ln in lines for ln in kept), "--base keeps every other line of the base file")
    plain = os.path.join(tmp, "plain.cal")
    run([FRICTION, os.path.join(ex, "dyno.csv")] + DYNO + ["--base", base, "--no-sd",
                                                           "-o", plain])
    with open(plain, encoding="utf-8") as f:
        plain_text = f.read()
    sd_values = [ln.split("=")[1].split("#")[0].strip() for ln in plain_text.splitlines()
                 if ("_sd =" in ln or "_corr =" in ln) and not ln.startswith("#")]
    c.check(all(v == "0" for v in sd_values),
            f"--no-sd writes no standard deviations (the base's zeros stay: {sd_values})")
    # one frame: a log without any is refused on its own
    rr = subprocess.run([SIM, "replay", "-", "--calib", plain], input="(0.000000) can0 123#\n",
                        capture_output=True, text=True, timeout=60)
    c.check(rr.returncode == 0, f"squeal-sim replay --calib accepts the --no-sd file "
                                f"(exit {rr.returncode})")
    png = os.path.join(tmp, "f.png")
    r = run([FRICTION, os.path.join(ex, "dyno.csv")] + DYNO + ["--plot", png])
    c.check(r.returncode == 0 and os.path.getsize(png) > 10000, "fit_friction --plot")
    png = os.path.join(tmp, "m.png")
    r = run([MODAL, os.path.join(ex, "frf.csv"), "--plot", png])
    c.check(r.returncode == 0 and os.path.getsize(png) > 10000, "fit_modal --plot (FRF)")


def examples_reproducible(c, tmp):
    out = os.path.join(tmp, "ex")
    r = run([os.path.join(TOOLS, "gen_calib_examples.py"), "--out", out])
    for name in ("dyno.csv", "tap_test.wav", "frf.csv"):
        same = r.returncode == 0 and filecmp.cmp(
            os.path.join(out, name), os.path.join(ROOT, "docs", "examples", name), shallow=False)
        c.check(same, f"docs/examples/{name} is what tools/gen_calib_examples.py generates")


def example_calibration(c, tmp):
    """docs/examples/example-brake.cal is what `make plots-calib` writes,
    and its map's first-order band agrees with Monte Carlo (the picture's
    own statement, 5 % in N)."""
    ex = os.path.join(ROOT, "docs", "examples")
    step1 = os.path.join(tmp, "ex1.cal")
    step2 = os.path.join(tmp, "example-brake.cal")
    run([FRICTION, os.path.join(ex, "dyno.csv")] + DYNO +
        ["--base", os.path.join(ROOT, "docs", "calib-example.txt"), "-o", step1])
    run([MODAL, os.path.join(ex, "tap_test.wav"), "--mass-kg", "0.9", "--mass-sd-kg", "0.01",
         "--base", step1, "-o", step2])
    c.check(filecmp.cmp(step2, os.path.join(ex, "example-brake.cal"), shallow=False),
            "docs/examples/example-brake.cal is what the two fits write (make plots-calib)")
    r = run([os.path.join(TOOLS, "plots", "plot_calib_bands.py"),
             os.path.join(ex, "example-brake.cal"), "--out", tmp, "--samples", "4000"])
    last = r.stdout.strip().splitlines()[-1] if r.stdout.strip() else r.stderr.strip()
    c.check(r.returncode == 0 and "agree within 5 %" in last and
            os.path.getsize(os.path.join(tmp, "calib_bands.png")) > 10000,
            f"plot_calib_bands: {last}")


def main():
    return Checks.run(friction_refusals, modal_refusals, outputs, examples_reproducible, example_calibration)


if __name__ == "__main__":
    sys.exit(main())
