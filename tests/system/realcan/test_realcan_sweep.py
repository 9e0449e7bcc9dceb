#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Acceptance sweep of tools/vehicle_calib.py over real community DBC files
(the dbc/ folder of the realcan collection of real vehicle files beside the
repository; a counted skip where it is absent): every integer signal of 1..32 bits of every file, made into a
speed input with --speed-unit km/h beside a fixed force input of the same
file (--force-unit N), either sets up (the written file passes
`squeal-sim calib-check`, run here once more) or is refused with one line.
Never a traceback, never several lines, never a written file that
calib-check refuses. Prints the counts per file, then
"RESULT: N passed, M failed".

The tool runs in this process (vehicle_calib.main) with its DBC scan and
canmatrix's parse of each file kept between runs (the same file gives the
same result), so the sweep takes minutes, not hours.
"""
import collections
import contextlib
import hashlib
import io
import os
import re
import subprocess
import sys
import tempfile
# tests/ of this checkout, and the folders its helper modules live in
_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, d) for d in ("support", os.path.join("support", "reference"), "host-sim", "tools")]

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import vehref  # noqa: E402

REALCAN = os.path.join(os.path.dirname(vehref.ROOT), "shared", "realcan", "dbc")
# the checker of the written files (and the tool's): build/host/squeal-sim,
# or the program VEHICLE_CALIB_SIM names
CHECKER = os.environ.get("VEHICLE_CALIB_SIM") or os.path.join(vehref.ROOT, "build", "host", "squeal-sim")


def candidates(db):
    """(MSG.SIG, signal) of every integer signal of 1..32 bits."""
    out = []
    for f in db.frames:
        for s in f.signals:
            if not s.is_float and 1 <= int(s.size) <= 32:
                out.append(("%s.%s" % (f.name, s.name), s, f))
    return out


def reason_of(err):
    """A refusal line without its file, line and signal: what it says."""
    why = err.strip()
    why = why[len("vehicle_calib.py: "):] if why.startswith("vehicle_calib.py: ") else why
    if why.startswith("the firmware refuses the calibration: "):
        rest = why[len("the firmware refuses the calibration: "):]
        return "calib-check: " + re.sub(r"^\S+?:\d+: ", "", rest)[:70]
    why = re.sub(r"^--(?:speed|force) \S+: ", "", why)
    why = re.sub(r"^\S+\.dbc:\d+: ", "", why)
    return re.sub(r"\d+", "N", why)[:70]


def run(vc, argv):
    err, out = io.StringIO(), io.StringIO()
    try:
        with contextlib.redirect_stderr(err), contextlib.redirect_stdout(out):
            rc = vc.main(argv)
    except BaseException as e:  # noqa: B902  (anything escaping main is the failure)
        return -1, "%s: %s" % (type(e).__name__, e)
    return rc, err.getvalue()


def main():
    r = vehref.Results()
    if not os.path.isdir(REALCAN):
        print("SKIP: realcan sweep (no realcan collection beside the repository)")
        print("RESULT: 0 passed, 0 failed, 1 skipped")
        return 0
    if not vehref.has_calib_check(CHECKER):
        r.check(False, "realcan sweep: %s has no calib-check command (run make)" % CHECKER)
        r.finish()
    os.environ["VEHICLE_CALIB_SIM"] = CHECKER
    sys.path.insert(0, os.path.join(vehref.ROOT, "tools"))
    import importlib.util
    spec = importlib.util.spec_from_file_location("vehicle_calib", vehref.TOOL)
    vc = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(vc)
    dt = vc.dbc_tolerant
    scans, parses = {}, {}
    real_scan, real_parse = dt.scan, dt._canmatrix

    def scan(path):
        if path not in scans:
            scans[path] = real_scan(path)
        return scans[path]

    def parse(tmp, path):
        with open(tmp, "rb") as f:
            key = (path, hashlib.sha1(f.read()).hexdigest())
        if key not in parses:
            parses[key] = real_parse(tmp, path)
        return parses[key]
    dt.scan, dt._canmatrix = scan, parse
    totals = collections.Counter()
    reasons = collections.Counter()
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "sweep.cal")
        for name in sorted(os.listdir(REALCAN)):
            if not name.lower().endswith(".dbc"):
                continue
            path = os.path.join(REALCAN, name)
            # the signals as the tool reads the file (canmatrix alone hands the signals
            # of a refused BO_ line to the message before it)
            try:
                db = dt.load(path, [])[0]
            except dt.DbcRefusal as e:
                r.check(False, "%s: the file reads: %s" % (name, e))
                continue
            cands = candidates(db)
            force = None
            plain = [c for c in cands if c[1].size >= 8 and c[1].mux_val is None and not c[1].is_multiplexer]
            for ref, s, f in plain[:60]:   # the first 8..32-bit plain signal that sets up as a force
                for speed in [c for c in plain if c[0] != ref][:8]:   # beside a speed that sets up
                    rc, _ = run(vc, ["--dbc", path, "--corner", "FL", "--speed", speed[0], "--speed-unit", "km/h",
                                     "--force", ref, "--force-unit", "N", "--period-ms", "10", "-o", out])
                    if rc == 0:
                        force = ref
                        break
                if force is not None:
                    break
            if not r.check(force is not None, "%s: a force signal that sets up" % name):
                continue
            ok = refused = bad = 0
            first_bad = []
            for ref, s, f in cands:
                if ref == force:
                    continue
                if os.path.exists(out):
                    os.unlink(out)
                rc, err = run(vc, ["--dbc", path, "--corner", "FL", "--speed", ref, "--speed-unit", "km/h",
                                   "--force", force, "--force-unit", "N", "--period-ms", "10", "-o", out])
                lines = [l for l in err.splitlines() if not l.startswith("vehicle_calib.py: note: ")]
                if rc == 0 and not lines and os.path.exists(out):
                    p = subprocess.run([CHECKER, "calib-check", out], stdout=subprocess.PIPE,
                                       stderr=subprocess.PIPE)
                    if p.returncode == 0:
                        ok += 1
                        continue
                    bad += 1
                    first_bad.append((ref, "written but refused: " + p.stderr.decode("utf-8", "replace")[:200]))
                elif rc == 1 and err.count("\n") == 1 and "Traceback" not in err and not os.path.exists(out):
                    refused += 1
                    reasons[reason_of(err)] += 1
                else:
                    bad += 1
                    first_bad.append((ref, rc, err[:300]))
            print("%s: %d signals: %d set up, %d refused with one line, %d otherwise (force %s)"
                  % (name, ok + refused + bad, ok, refused, bad, force))
            totals.update(ok=ok, refused=refused, bad=bad)
            r.check(bad == 0, "%s: every signal sets up or is refused in one line (%d not: %s)"
                    % (name, bad, first_bad[:3]))
    print("realcan sweep: %d signals, %d set up, %d refused, %d otherwise"
          % (totals["ok"] + totals["refused"] + totals["bad"], totals["ok"], totals["refused"], totals["bad"]))
    for why, k in reasons.most_common(12):
        print("  refused %5d: %s" % (k, why))
    r.finish()


if __name__ == "__main__":
    sys.exit(main())
