#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""squeal-sim classify (float and fixed builds) against the reference.

Runs build/host/squeal-sim and build/host-fixed/squeal-sim on a fixed
sample of golden vectors (tests/support/golden/model_vectors.csv, rows valid for
both builds) with --json, and compares with the expectation computed by
tests/support/reference/squeal_reference.py, with the tolerances of
tests/firmware/model/test_squeal_model.c (see the comment at its top). Also checks a few
literal invocations and that bad flags and values fail with a message.
Prints "RESULT: N passed, M failed". Run from the repository root.
"""

import csv
import json
import math
import os
import random
import subprocess
import sys
import tempfile
# tests/ of this checkout, and the folders its helper modules live in
_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, d) for d in ("support", os.path.join("support", "reference"), "host-sim", "tools")]

ROOT = os.path.dirname(_TESTS)
import squeal_reference as ref  # noqa: E402

from sim_cli import SIMS as BINARIES, Results  # noqa: E402
REL = {"float": 1e-5, "fixed": 1e-3}
CLASS_BORDER_TOL = 1e-3
FLT_MAX = 3.4028234663852886e38
CSV_PATH = os.path.join(ROOT, "tests", "support", "golden", "model_vectors.csv")
FLAG_OF = {"v0": "--v0", "force": "--force", "slope": "--slope", "damping": "--damping",
           "omega0": "--omega0", "mass": "--mass", "mu_inf": "--mu-inf",
           "delta_mu": "--delta-mu"}
# golden column -> (JSON key, factor from golden unit to JSON unit, Q of fixed field)
FIELDS = {
    "ln_q": ("ln_q", 1.0, 16),
    "hopf_v0": ("hopf_v0_mps", 1.0, 20),
    "hopf_margin": ("hopf_margin_mps", 1.0, 20),
    "hopf_force": ("hopf_force_n", 1.0, 12),
    "cycle_x": ("cycle_x", 1.0, 20),
    "lc_amplitude_um": ("lc_amplitude_m", 1e-6, 12),
    "trigger_v": ("trigger_velocity_mps", 1.0, 20),
    "basin_ratio": ("basin_ratio", 1.0, 24),
}

result = Results()


def field_max(build, q):
    return FLT_MAX if build == "float" else math.ldexp(2.0**31 - 1.0, -q)


def lsb(build, q):
    return 0.0 if build == "float" else math.ldexp(1.0, -q)


def dlnq(build, h):
    """Absolute uncertainty of ln Q: same rule as tests/unit/test_model.c."""
    l = h["slope"] * h["v0"]
    for k in ("force", "slope", "damping", "omega0", "mass", "delta_mu"):
        l += abs(math.log(h[k]))
    if build == "fixed":
        return 2.0**-12 + 1e-6 * l
    return 1e-6 + 8.0 * 2.0**-24 * l


def cycle_dx(crit, x, d):
    k = 1.0 + 4.0 / x if crit == "exact" else x / 2.0 + 4.0 / x
    return min(2.0 * k * d, 2.0 * math.sqrt(8.0 * d))


def tolerance(build, crit, h, name, want, x):
    d = dlnq(build, h)
    rel = REL[build]
    q = FIELDS[name][2]
    # 2 LSB in fixed; FLT_MIN in float (no relative precision below it)
    lsb2 = 2.0 * lsb(build, q) if build == "fixed" else 1.1754943508222875e-38
    a = h["slope"]
    if name == "ln_q":
        return d + lsb2
    if name == "hopf_v0":
        return rel * abs(want) + d / a + lsb2
    if name == "hopf_margin":
        return rel * max(abs(want), h["v0"]) + d / a + lsb2
    if name == "hopf_force":
        return (rel + d) * abs(want) + lsb2
    dx = cycle_dx(crit, x, d)
    if name == "cycle_x":
        return rel * want + dx + lsb2
    if name == "lc_amplitude_um":
        return rel * want + dx * 1e6 / (a * h["omega0"]) + lsb2
    if name == "trigger_v":
        return rel * want + dx / a + lsb2
    return rel * want + dx / (a * h["v0"]) + lsb2


def run(build, args):
    p = subprocess.run([BINARIES[build], "classify"] + args, capture_output=True,
                       text=True, timeout=20)
    return p.returncode, p.stdout, p.stderr


def load_rows():
    with open(CSV_PATH, encoding="ascii") as f:
        lines = [ln for ln in f if not ln.startswith("#")]
    return list(csv.DictReader(lines))


def sample(rows):
    rng = random.Random(4242)
    both = [r for r in rows if r["variant"] == "both"]
    picked = []
    groups = [
        (lambda r: r["state"] == "stable" and r["tag"] in ("grid", "map"), 8),
        (lambda r: r["state"] == "bistable" and r["tag"] in ("grid", "map"), 8),
        (lambda r: r["state"] == "unstable" and r["tag"] in ("grid", "map"), 8),
        (lambda r: r["tag"].startswith(("hopf", "stick")) and r["border_dist"]
         and float(r["border_dist"]) > CLASS_BORDER_TOL, 8),
        (lambda r: r["tag"] in ("domain", "corner") and r["state"] != "invalid", 8),
        (lambda r: r["state"] == "not_sliding", 4),
        (lambda r: r["state"] == "invalid", 6),
    ]
    for pred, n in groups:
        cands = [r for r in both if pred(r)]
        picked += rng.sample(cands, min(n, len(cands)))
    return picked


def check_row(build, row):
    crit = row["criterion"]
    inputs = {k: float(row[k]) for k in FLAG_OF}
    args = []
    for k, flag in FLAG_OF.items():
        args += [flag, row[k]]
    args += ["--criterion", crit, "--json"]
    rc, out, err = run(build, args)
    what = "%s row %s (%s %s %s): " % (build, row["id"], row["tag"], crit, row["state"])
    if row["state"] == "invalid":
        ok = rc != 0 and err.strip() != ""
        if ok and out.strip():
            try:
                ok = json.loads(out)["state"] == "invalid"
            except (ValueError, KeyError):
                ok = False
        result(ok, what + "want non-zero exit, message, state invalid; got rc %d, %r %r"
               % (rc, out[:200], err[:200]))
        return
    if rc != 0:
        result(False, what + "exit %d: %s" % (rc, err.strip()))
        return
    try:
        got = json.loads(out)
    except ValueError as e:
        result(False, what + "bad JSON (%s): %r" % (e, out[:300]))
        return
    h = ref.represent(inputs, build)
    problems = []
    border = float(row["border_dist"]) if row["border_dist"] else None
    if border is None or border > CLASS_BORDER_TOL:
        if got.get("state") != row["state"]:
            problems.append("state %s, want %s" % (got.get("state"), row["state"]))
    if got.get("criterion") != crit:
        problems.append("criterion %r" % got.get("criterion"))
    any_sat = False
    x = float(row["cycle_x"]) if row["cycle_x"] else None
    for name, (key, factor, q) in FIELDS.items():
        want = float(row[name]) if row[name] else None
        val = got.get(key, "missing")
        if val == "missing":
            problems.append("no key %s" % key)
            continue
        if want is None:
            if val is not None:
                problems.append("%s = %r, want null" % (key, val))
            continue
        tol = tolerance(build, crit, h, name, want, x)
        if abs(want) - tol > field_max(build, q):
            # Out of the build's range: clamped or null, and "saturated".
            any_sat = True
            continue
        if val is None:
            problems.append("%s null, want %.9g" % (key, want))
            continue
        if not abs(val / factor - want) <= tol:
            problems.append("%s = %.9g, want %.9g +- %.3g" % (key, val, want * factor,
                                                                tol * factor))
    if any_sat and got.get("saturated") is not True:
        problems.append("a value exceeds its range but saturated is %r" % got.get("saturated"))
    if row["ln_q"] and got.get("q") is not None:
        want_q = math.exp(float(row["ln_q"]))
        if want_q < 1e30 and not abs(got["q"] - want_q) <= 2.0 * (dlnq(build, h) + REL[build]) * want_q:
            problems.append("q = %.9g, want %.9g" % (got["q"], want_q))
    result(not problems, what + "; ".join(problems) + "\n     args: " + " ".join(args))


def check_literal(build):
    rc, out, err = run(build, ["--v0", "1.0", "--force", "9000", "--json"])
    result(rc == 0 and '"state": "unstable"' in out,
           "%s: --v0 1.0 --force 9000 --json: rc %d, %r" % (build, rc, out[:300]))
    rc, out, err = run(build, ["--v0", "1.5", "--force", "9000", "--json"])
    ok = rc == 0
    try:
        got = json.loads(out)
        # v_H = 1.2314639 m/s (docs/model.md section 8), so margin = 1.5 - v_H
        ok = ok and got["state"] in ("stable", "bistable", "unstable") and \
            abs(got["hopf_margin_mps"] - (1.5 - 1.2314639)) < 1e-4 and \
            got["hopf_force_n"] is not None and got["hopf_force_n"] > 9000.0
    except (ValueError, KeyError, TypeError):
        ok = False
    result(ok, "%s: --v0 1.5 --force 9000 --json: rc %d, %r" % (build, rc, out[:400]))
    bad = [
        ["--force", "9000"],                              # --v0 missing
        ["--v0", "1.0"],                                  # --force missing
        ["--v0", "abc", "--force", "9000"],
        ["--v0", "1.0", "--force", "9000", "--bogus"],
        ["--v0", "1.0", "--force", "9000", "--criterion", "quartic"],
        ["--v0", "1.0", "--force", "9000", "--slope"],    # value missing
        ["--v0", "1.0x", "--force", "9000"],
        ["--v0", "", "--force", "9000"],
        ["--v0", "-1", "--force", "9000"],                # outside the domain
        ["--v0", "1.0", "--force", "nan"],
        ["--v0", "1.0", "--force", "9000", "--damping", "0"],
        ["--v0", "1.0", "--force", "9000", "--mu-inf", "0.1", "--delta-mu", "-0.2"],
        ["--v0", "101", "--force", "9000", "--json"],
    ]
    for args in bad:
        rc, out, err = run(build, args)
        result(rc != 0 and err.strip() != "",
               "%s: classify %s: want non-zero exit and a message, got rc %d, stderr %r"
               % (build, " ".join(args), rc, err[:200]))

# our own two-corner calibration: flat radii 0.33 / 0.11 m, FR its own 0.30 / 0.15 m
RADII_CAL = """wheel_radius_m = 0.33
pad_radius_m = 0.11
[input w]
id = 0x1A0
start_bit = 7
length = 16
byte_order = motorola
factor = 0.01
unit = km/h
period_ms = 10
min = 0
max = 300
step_max = 300
[input b]
id = 0x1B0
start_bit = 0
length = 12
byte_order = intel
factor = 1
unit = N
period_ms = 10
min = 0
max = 4000
step_max = 4000
[corner FL]
speed = w
force = b
[corner FR]
speed = w
force = b
wheel_radius_m = 0.30
pad_radius_m = 0.15
"""


def check_vehicle_speed(build):
    """The vehicle km/h is v0 x r_w / r_p of the calibration's corner: the
    flat radii (3 x v0), a corner's own (2 x v0), the defaults without
    --calib (2.5 x v0); the same in text and JSON."""
    with tempfile.TemporaryDirectory() as tmp:
        cal = os.path.join(tmp, "radii.cal")
        with open(cal, "w") as f:
            f.write(RADII_CAL)
        for extra, ratio in (([], 2.5), (["--calib", cal], 3.0), (["--calib", cal, "--corner", "FL"], 3.0),
                             (["--calib", cal, "--corner", "FR"], 2.0)):
            rc, out, err = run(build, ["--v0", "2", "--force", "3000"] + extra)
            want = "(vehicle %.1f km/h)" % (2 * ratio * 3.6)
            result(rc == 0 and want in out, "%s: classify %s: %s in %r" % (build, " ".join(extra), want, out[:90]))
            rc, out, err = run(build, ["--v0", "2", "--force", "3000", "--json"] + extra)
            ok = rc == 0 and abs(json.loads(out)["vehicle_kmh"] - 2 * ratio * 3.6) < 1e-9
            result(ok, "%s: classify --json %s: vehicle_kmh %.3f" % (build, " ".join(extra), 2 * ratio * 3.6))
        with open(cal, "w") as f:
            f.write("no_such_key = 1\n")
        rc, out, err = run(build, ["--v0", "2", "--force", "3000", "--calib", cal])
        result(rc == 1 and err.strip().count("\n") == 0 and (cal + ":1:") in err,
               "%s: classify --calib with a refused file: exit 1, one line FILE:LINE (rc %d, %r)"
               % (build, rc, err))


def main():
    for build, path in BINARIES.items():
        if not os.access(path, os.X_OK):
            print("missing %s (make %s)" % (path, os.path.relpath(path, ROOT)))
            result(False, "binary %s" % path)
    if result.counts[False]:
        return result.finish()
    rows = sample(load_rows())
    for build in BINARIES:
        check_literal(build)
        check_vehicle_speed(build)
        for row in rows:
            check_row(build, row)
    print("%d golden rows x %d builds checked" % (len(rows), len(BINARIES)))
    return result.finish()


if __name__ == "__main__":
    sys.exit(main())
