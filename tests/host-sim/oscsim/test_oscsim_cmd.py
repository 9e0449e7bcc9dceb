#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""The simulator's commands (host-sim/oscsim/oscsim_cmd.c: `map`, `simulate`)
from outside, on the sanitizer builds of the oscsim program (float, fixed),
against docs/model.md's closed forms computed here with numpy/scipy:

  - map --csv: the header, one row per grid point at a_i = a_max i / n_a,
    v0_j = v_max j / n_v, s = a v0 and
    ln Q = ln(D w0 m / (a N dmu)) + a v0 for each brake's D, w0, N;
    simulated truth "unstable" exactly where Q <= 1/2; the model's exact
    and cubic classes and cycles against I1(x)/x = Q and
    x3 = 4 sqrt(Q - 1/2) (scipy.special.i1, brentq) away from the borders;
    the summary's truth counts are the CSV's;
  - map --list, --na/--nv, and the refusals (unknown brake, --grid 0, a
    CSV file that cannot be written) with their exit codes;
  - simulate: steady sliding at x_s = N mu(v0) / (m w0^2) stays there, the
    samples every 2 pi / w0 / 64; --truth's ln Q and s; one line and exit 2
    for two modes, --dimless without --q, v0 = 0.
Usage: test_oscsim_cmd.py [OSCSIM ...]  (default build/test{,-fixed}/oscsim)
Prints "RESULT: N passed, M failed".
"""
import csv
import io
import math
import os
import subprocess
import sys
import tempfile

from scipy.optimize import brentq
from scipy.special import i1

ROOT = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0]
sys.path[:0] = [os.path.join(ROOT, "tests", "support")]
import dbc_common  # noqa: E402  (Results)

PROGS = sys.argv[1:] or [os.path.join(ROOT, "build", b, "oscsim") for b in ("test", "test-fixed")]

# docs/model.md section 8's brake and its variations (oscsim map --list)
M_KG, MU_INF, DMU = 1.0, 0.25, 0.15
BRAKES = {  # name: (D, w0 [rad/s], N [N])
    "default": (0.023, 5000.0, 9000.0),
    "d0.05": (0.05, 5000.0, 9000.0),
    "d0.1": (0.1, 5000.0, 9000.0),
    "k2": (0.023, 5000.0 * math.sqrt(2.0), 9000.0),
    "k0.5": (0.023, 5000.0 * math.sqrt(0.5), 9000.0),
    "n5000": (0.023, 5000.0, 5000.0),
    "n20000": (0.023, 5000.0, 20000.0),
}
# the fixed build holds a cycle x in Q20 (squeal_model.h: range 2048); the
# cubic cycle of a far-stable point (Q ~ 1e6) lies beyond it
CYCLE_X_RANGE = 2048.0
HEADER = ("brake,a_spm,v0_mps,ln_q,s,truth,sim_x,linear_grows,exact,exact_x,cubic,cubic_x,"
          "ln_q_border,border_dist,basin_in,basin_out")

R = dbc_common.Results()
check = R.check


def run(prog, args):
    p = subprocess.run([prog] + args, capture_output=True, text=True, timeout=120)
    return p.returncode, p.stdout, p.stderr


def ln_q_of(brake, a, v0):
    d, w0, n = BRAKES[brake]
    return math.log(d * w0 * M_KG / (a * n * DMU)) + a * v0


def exact_class(ln_q, s):
    """docs/model.md's exact criterion: (class, x of I1(x)/x = Q or None, distance to a border)."""
    border = math.log(i1(s) / s)
    dist = min(abs(ln_q - math.log(0.5)), abs(ln_q - border))
    if ln_q <= math.log(0.5):
        return "unstable", None, dist
    q = math.exp(ln_q)
    x = brentq(lambda x: i1(x) / x - q, 1e-9, 200.0, xtol=1e-14)
    return ("bistable" if ln_q < border else "stable"), x, dist


def cubic_class(ln_q, s):
    q = math.exp(ln_q)
    border = math.log(0.5 + s * s / 16.0)
    dist = min(abs(ln_q - math.log(0.5)), abs(ln_q - border))
    if q <= 0.5:
        return "unstable", None, dist
    return ("bistable" if ln_q < border else "stable"), 4.0 * math.sqrt(q - 0.5), dist


def test_map_csv(prog, tag):
    rc, out, err = run(prog, ["map", "--brake", "all", "--grid", "3", "--csv", "-"])
    check(rc == 0, "%s: map --brake all --grid 3 --csv - exits 0 (%d: %s)" % (tag, rc, err[-200:]))
    lines = out.splitlines()
    check(lines[:1] == [HEADER], "%s: the CSV header" % tag)
    rows = list(csv.DictReader(io.StringIO(out)))
    check(len(rows) == 9 * len(BRAKES), "%s: 9 rows per brake (%d)" % (tag, len(rows)))
    want_grid = [(6.0 * i / 3, 3.0 * j / 3) for j in (1, 2, 3) for i in (1, 2, 3)]
    bad = []
    counts = {}
    compared = 0
    for name in BRAKES:
        mine = [r for r in rows if r["brake"] == name]
        got_grid = sorted((float(r["a_spm"]), float(r["v0_mps"])) for r in mine)
        if got_grid != sorted(want_grid):
            bad.append((name, "grid", got_grid))
            continue
        counts[name] = {}
        for r in mine:
            a, v0 = float(r["a_spm"]), float(r["v0_mps"])
            lq, s = ln_q_of(name, a, v0), a * v0
            counts[name][r["truth"]] = counts[name].get(r["truth"], 0) + 1
            if abs(float(r["ln_q"]) - lq) > 1e-6 or abs(float(r["s"]) - s) > 1e-9:
                bad.append((name, a, v0, "ln_q/s", r["ln_q"], lq))
            if (r["truth"] == "unstable") != (lq <= math.log(0.5)):
                bad.append((name, a, v0, "truth vs Q <= 1/2", r["truth"]))
            for col, xcol, ref in (("exact", "exact_x", exact_class), ("cubic", "cubic_x", cubic_class)):
                cls, x, dist = ref(lq, s)
                if dist < 1e-3:
                    continue  # at a border the float/fixed model may fall either way
                compared += 1
                if r[col] != cls:
                    bad.append((name, a, v0, col, r[col], cls))
                elif x is not None and x < CYCLE_X_RANGE and abs(float(r[xcol]) - x) > 1e-3 * x:
                    bad.append((name, a, v0, xcol, r[xcol], x))
                elif x is None and r[xcol] != "nan":
                    bad.append((name, a, v0, xcol, r[xcol], "nan"))
    check(not bad, "%s: grid, ln Q, s, truth and the model's classes and cycles as docs/model.md says "
          "(%d compared; %s)" % (tag, compared, bad[:4]))
    check(compared > 100, "%s: most points away from a border (%d of %d)" % (tag, compared, 2 * len(rows)))
    # the summary (on stderr with --csv -) counts what the CSV holds
    for name, c in counts.items():
        want = "  simulated truth: %d unstable, %d bistable, %d stable;" % (
            c.get("unstable", 0), c.get("bistable", 0), c.get("stable", 0))
        check(any(ln.startswith(want) for ln in err.splitlines()),
              "%s: %s: summary %r" % (tag, name, want))
    check(err.splitlines()[:1] == ["model build: %s; grid 3 x 3, a in (0, 6] s/m, v0 in (0, 3] m/s"
                                   % ("fixed" if "fixed" in tag else "float")],
          "%s: the summary's first line (%r)" % (tag, err.splitlines()[:1]))


def test_map_options(prog, tag):
    rc, out, _ = run(prog, ["map", "--list"])
    check(rc == 0 and [ln.split()[0] for ln in out.splitlines()] == list(BRAKES),
          "%s: map --list names the seven brakes in order" % tag)
    rc, out, _ = run(prog, ["map", "--na", "2", "--nv", "1", "--a-max", "4", "--v-max", "0.5",
                            "--no-linear", "--csv", "-"])
    rows = list(csv.DictReader(io.StringIO(out)))
    check(rc == 0 and [(r["a_spm"], r["v0_mps"], r["linear_grows"]) for r in rows] ==
          [("2.000000", "0.500000", "-1"), ("4.000000", "0.500000", "-1")],
          "%s: --na 2 --nv 1 --a-max 4 --v-max 0.5 --no-linear: two points, linear test not run" % tag)
    rc, out, err = run(prog, ["map", "--brake", "d0.2"])
    check(rc == 2 and out == "" and "unknown brake 'd0.2' (--list)" in err and len(err.splitlines()) <= 2,
          "%s: unknown brake: usage error, exit 2 (%d %r)" % (tag, rc, err))
    rc, _, err = run(prog, ["map", "--grid", "0"])
    check(rc == 2, "%s: --grid 0: exit 2 (%d)" % (tag, rc))
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "no", "map.csv")
        rc, _, err = run(prog, ["map", "--grid", "1", "--csv", path])
        check(rc == 1 and err.startswith("squeal-sim map: cannot write %s: " % path),
              "%s: an unwritable CSV: one line, exit 1 (%d %r)" % (tag, rc, err))
        path = os.path.join(tmp, "map.csv")
        rc, out, _ = run(prog, ["map", "--grid", "2", "--no-linear", "--csv", path])
        with open(path) as f:
            text = f.read()
        check(rc == 0 and out.startswith("model build: ") and len(text.splitlines()) == 1 + 4,
              "%s: --csv FILE: 4 rows in the file, the summary on stdout" % tag)


def test_simulate(prog, tag):
    d, w0, n = BRAKES["default"]
    a, v0 = 2.0, 1.0
    x_s = n * (MU_INF + DMU * math.exp(-a * v0)) / (M_KG * w0 * w0)
    rc, out, err = run(prog, ["simulate", "--t-end", "0.002"])
    lines = out.splitlines()
    samples = [ln.split(",") for ln in lines[1:] if ln.startswith("sample,")]
    dt = 2.0 * math.pi / w0 / 64.0
    check(rc == 0 and lines[0] == "kind,t_s,x_m,v_mps,mode" and len(samples) >= 20,
          "%s: simulate: CSV header and samples (%d)" % (tag, len(samples)))
    check(all(abs(float(sm[1]) - k * dt) < 1e-12 for k, sm in enumerate(samples[:20])),
          "%s: a sample every 2 pi / w0 / 64 = %.3e s" % (tag, dt))
    check(all(abs(float(sm[2]) - x_s) < 1e-12 * 1e3 and abs(float(sm[3])) < 1e-9 and sm[4] == "slip"
              for sm in samples),
          "%s: started at x_s = N mu(v0) / (m w0^2) = %.9e m it stays, sliding" % (tag, x_s))
    check(err.startswith("x_s=%.9e " % x_s), "%s: x_s in the summary (%r)" % (tag, err[:30]))

    rc, out, _ = run(prog, ["simulate", "--v0", "2", "--slope", "1.5", "--truth"])
    kv = dict(w.split("=", 1) for w in out.split())
    check(rc == 0 and abs(float(kv["ln_q"]) - ln_q_of("default", 1.5, 2.0)) < 1e-8 and
          abs(float(kv["s"]) - 3.0) < 1e-9,
          "%s: --truth: ln Q and s at a 1.5 s/m, v0 2 m/s (%s)" % (tag, out.strip()[:60]))

    for args, what in ((["--truth", "--cycle"], "give one of --cycle, --truth, --basin, --dimless"),
                       (["--dimless", "--damping", "0.023"], "needs --damping D > 0 and --q Q > 0"),
                       (["--v0", "0"], "parameters out of range")):
        rc, out, err = run(prog, ["simulate"] + args)
        check(rc == 2 and out == "" and what in err and len(err.strip().splitlines()) <= 2,
              "%s: simulate %s: exit 2, %r (%d %r)" % (tag, " ".join(args), what, rc, err))


def main():
    for prog in PROGS:
        tag = os.path.basename(os.path.dirname(prog))
        test_map_csv(prog, tag)
        test_map_options(prog, tag)
        test_simulate(prog, tag)
    R.finish()


if __name__ == "__main__":
    main()
