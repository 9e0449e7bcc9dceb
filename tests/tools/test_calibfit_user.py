#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Calibrating a brake from measurements, fits to replay, run exactly as a user runs it:

  tools/fit_friction.py and tools/fit_modal.py on the documented example
  data (docs/examples/, the commands of `make plots-calib`) write a
  calibration; `squeal-sim classify --calib` reports border_margin_sigma for
  it and `squeal-sim replay --calib` runs the monitor with it, with
  BorderMargin_sigma on the bus. Both numeric builds.

References, independent of the firmware: the class from the model reference,
the margin from numerical first-order propagation
(tests/support/reference/sigma_margin_ref.py); the frames decoded with canmatrix from
firmware/protocol/squeal.dbc; the input log written by tests/host-sim/
gen_inputs.py (E2E computed there).
"""

import json
import os
import re
import subprocess
import sys
import tempfile

from checks import ROOT, TOOLS, Checks
import sigma_margin_ref as smr
# tests/ of this checkout, and the folders its helper modules live in
_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, d) for d in ("support", os.path.join("support", "reference"), "host-sim", "tools")]

import gen_inputs  # noqa: E402

PY = sys.executable
EX = os.path.join(ROOT, "docs", "examples")
BUILDS = ("host", "host-fixed")
K_SIGMA = 2.0
LINE = re.compile(r"^\((\d+\.\d+)\) (\S+) ([0-9A-F]{3})#([0-9A-F]*)$")


def sim(build):
    return os.path.join(ROOT, "build", build, "squeal-sim")


def fit(tmp):
    """The two fits of `make plots-calib` into tmp/brake.cal."""
    step1 = os.path.join(tmp, "friction.cal")
    step2 = os.path.join(tmp, "brake.cal")
    r1 = subprocess.run([PY, os.path.join(TOOLS, "fit_friction.py"),
                         os.path.join(EX, "dyno.csv"), "--pad-radius-m", "0.12",
                         "--piston-area-mm2", "2000", "--faces", "2",
                         "--base", os.path.join(ROOT, "docs", "calib-example.txt"),
                         "-o", step1], capture_output=True, text=True, timeout=300)
    r2 = subprocess.run([PY, os.path.join(TOOLS, "fit_modal.py"),
                         os.path.join(EX, "tap_test.wav"), "--mass-kg", "0.9",
                         "--mass-sd-kg", "0.01", "--base", step1, "-o", step2],
                        capture_output=True, text=True, timeout=300)
    return step2, r1.returncode == 0 and r2.returncode == 0


def classify_checks(c, cal_path):
    cal = smr.read_cal(cal_path)
    nom, sds, corr, mu_inf = smr.brake(cal)
    for build in BUILDS:
        for v0, force in ((0.3, 9000.0), (0.9, 9000.0), (1.0, 9000.0), (1.5, 9000.0),
                          (2.5, 9000.0), (1.0, 5000.0), (4.0, 3000.0)):
            r = subprocess.run([sim(build), "classify", "--v0", str(v0), "--force", str(force),
                                "--calib", cal_path, "--json"],
                               capture_output=True, text=True, timeout=60)
            got = json.loads(r.stdout) if r.returncode == 0 else {}
            st = smr.state_code(nom, mu_inf, v0, force)
            want = smr.margin_of(st, smr.margins(nom, sds, corr, v0, force))
            m = got.get("border_margin_sigma")
            ok = (got.get("state") == smr.STATE_NAME[st] and m is not None and
                  abs(m - want) <= 0.01 * want + 0.01)
            c.check(ok, f"{build} classify --calib v0={v0} N={force:g}: {got.get('state')} "
                        f"border_margin_sigma {m}, reference {smr.STATE_NAME[st]} {want:.4f}")


def replay_checks(c, tmp, cal_path):
    cal = smr.read_cal(cal_path)
    nom, sds, corr, mu_inf = smr.brake(cal)
    enc = gen_inputs.InputEncoder()
    frames = gen_inputs.braking_frames(enc)
    log = os.path.join(tmp, "drive.log")
    gen_inputs.write_python_can(log, frames)
    db = gen_inputs.load_dbc()
    status = db.frame_by_id(0x300) if hasattr(db, "frame_by_id") else None
    if status is None:
        status = [f for f in db.frames if f.arbitration_id.id == 0x300][0]
    for build in BUILDS:
        r = subprocess.run([sim(build), "replay", log, "--calib", cal_path],
                           capture_output=True, text=True, timeout=300)
        c.check(r.returncode == 0, f"{build} replay --calib brake.cal: exit {r.returncode}")
        n = avail = agree = near = 0
        bad = []
        for ln in r.stdout.splitlines():
            m = LINE.match(ln)
            if not m or int(m.group(3), 16) != 0x300:
                continue
            t = float(m.group(1))
            d = status.decode(bytearray(bytes.fromhex(m.group(4))))
            state = d["SquealState"].raw_value
            raw = d["BorderMargin_sigma"].raw_value
            if state not in (0, 1, 2):
                if raw != 0:
                    bad.append((t, state, raw))
                continue
            n += 1
            if raw == 0:
                bad.append((t, state, raw))
                continue
            avail += 1
            # the monitor's inputs: one of the last input pairs before t
            # (the frame may carry the classification of the pair before)
            before = [f for f in frames if f[0] <= t + 1e-9]
            pairs = []
            for back in (0, 2, 4):
                last = before[len(before) - 2 - back:len(before) - back]
                v0 = [f for f in last if f[1] == enc.speed_id][0][3]
                force = [f for f in last if f[1] == enc.force_id][0][4]
                pairs.append((v0, force))
            if smr.state_code(nom, mu_inf, *pairs[0]) != state:
                continue  # debounced class differs from the point's: skip
            refs = [smr.margins(nom, sds, corr, v0, force) for v0, force in pairs]
            ref = refs[0]
            wants = [smr.margin_of(state, x) for x in refs]
            got = 25.4 if raw == 255 else (raw - 1) * 0.1
            # 0.1 sigma steps; inputs quantised (0.01 rad/s, 0.5 N)
            if any((raw == 255 and want >= 25.3) or abs(got - want) <= 0.06 + 0.01 * want
                   for want in wants):
                agree += 1
            else:
                bad.append((t, state, got, [round(w, 3) for w in wants]))
            # the uncertain rule: bistable within k of Hopf -> critical,
            # stable within k of the stable border -> advisory
            # (the input pair whose margin the frame carries; asserted
            # where it is more than 0.1 sigma from k)
            best = min(range(len(wants)), key=lambda i: abs(got - wants[i]))
            key = "to_hopf" if state == 1 else "to_stable" if state == 0 else None
            level = d["WarningLevel"].raw_value
            if key is not None and abs(refs[best][key] - K_SIGMA) > 0.1:
                raised = 3 if state == 1 else 1
                if refs[best][key] < K_SIGMA:
                    near += 1
                    if level != raised:
                        bad.append((t, "level", state, level, round(refs[best][key], 3)))
                elif level == raised:
                    bad.append((t, "level", state, level, round(refs[best][key], 3)))
        c.check(n > 100 and avail == n and agree > n // 2 and not bad,
                f"{build} replay: BorderMargin_sigma on the bus in all {avail}/{n} classified "
                f"SquealStatus frames, {agree} equal to the reference, {near} within "
                f"{K_SIGMA:g} sigma with the raised level (problems: {bad[:4]})")


def main():
    c = Checks()
    with tempfile.TemporaryDirectory() as tmp:
        cal_path, ok = fit(tmp)
        c.check(ok, "fit_friction.py and fit_modal.py write brake.cal from docs/examples")
        if ok:
            text = open(cal_path, encoding="utf-8").read()
            c.check(all(f"\n{k} = " in text for k in ("mass_kg_sd", "omega0_radps_sd",
                                                     "damping_sd", "delta_mu_sd",
                                                     "slope_spm_sd", "slope_delta_mu_corr")),
                    "brake.cal carries the standard deviations")
            classify_checks(c, cal_path)
            replay_checks(c, tmp, cal_path)
    return c.finish()


if __name__ == "__main__":
    sys.exit(main())
