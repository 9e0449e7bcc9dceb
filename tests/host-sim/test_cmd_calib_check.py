#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""squeal-sim calib-check, and every --calib command refusing a calibration
that does not set up (float and fixed builds).

Two calibrations written here (a speed in km/h and a force in N, corner
FL):
  - "used to be refused at set-up": a force factor 0.0009765625 (2^-10, as
    some vehicles scale) on 16 raw bits with max 63.99: the text parser took
    it and the corner fell back to the factory defaults; now it loads and
    sets up: calib-check says ok, plant sends its frames, classify and ecu
    take it (ecu then stops at the interface, this kernel has no CAN);
  - "used to be accepted by the parser": the speed's max below its min: now
    refused by calib-check, ecu, plant and classify with exit 1 and the one
    line FILE:LINE: reason at the max line.
Also: the fixture layouts of tests/firmware/monitor/fixtures check ok with their counts,
--help exits 0, a missing file is one line and exit 1, bad usage exit 2
(no FILE, or two: it checks one file per run).
Prints "RESULT: N passed, M failed". Run from the repository root.
"""
import os
import subprocess
import sys
import tempfile
# tests/ of this checkout, and the folders its helper modules live in
_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, d) for d in ("support", os.path.join("support", "reference"), "host-sim", "tools")]

ROOT = os.path.dirname(_TESTS)
from sim_cli import SIMS as BINARIES, Results  # noqa: E402

TEMPLATE = """# written by test_calib_check.py
[input S]
id = 0x1A0
start_bit = 0
length = 16
byte_order = intel
factor = 0.01
unit = km/h
period_ms = 10
max = {speed_max}
min = {speed_min}
step_max = 20
[input F]
id = 0x1A1
start_bit = 16
length = 16
byte_order = intel
factor = {force_factor}
unit = N
period_ms = 10
max = 63.99
step_max = 63.99
[corner FL]
speed = S
force = F
"""
MAX_LINE = 10  # the speed's max

FIXTURES = {  # file -> (inputs, corners)
    "ext29_kn.cal": (2, 1),
    "intel14_counter.cal": (4, 2),
    "moto15_p02.cal": (5, 4),
    "mux_psi.cal": (3, 2),
    "torque_rpm.cal": (2, 1),
}

result = Results()


def run(args):
    p = subprocess.run(args, capture_output=True, text=True, timeout=60)
    return p.returncode, p.stdout, p.stderr


def one_line(text):
    lines = text.splitlines()
    return lines[0] if len(lines) == 1 else None


def main():
    tmp = tempfile.mkdtemp(prefix="calib-check-")
    good = os.path.join(tmp, "toyota_style.cal")
    bad = os.path.join(tmp, "max_below_min.cal")
    with open(good, "w") as f:
        f.write(TEMPLATE.format(speed_max="250", speed_min="0", force_factor="0.0009765625"))
    with open(bad, "w") as f:
        f.write(TEMPLATE.format(speed_max="10", speed_min="20", force_factor="0.5"))
    want_bad = "%s:%d: [input S] max is below min" % (bad, MAX_LINE)

    for build, sim in BINARIES.items():
        if not os.access(sim, os.X_OK):
            result(False, "%s: %s not built" % (build, sim))
            continue
        rc, out, err = run([sim, "calib-check", good])
        result(rc == 0 and out == "%s: ok (2 inputs, 1 corners)\n" % good and err == "",
               "%s calib-check 2^-10 factor: rc %d out %r err %r" % (build, rc, out, err))
        rc, out, err = run([sim, "calib-check", bad])
        result(rc == 1 and out == "" and one_line(err) == want_bad,
               "%s calib-check max<min: rc %d err %r" % (build, rc, err))
        for name, (ni, nc) in FIXTURES.items():
            path = os.path.join("tests", "firmware", "monitor", "fixtures", name)
            rc, out, err = run([sim, "calib-check", path])
            result(rc == 0 and out == "%s: ok (%d inputs, %d corners)\n" % (path, ni, nc),
                   "%s calib-check %s: rc %d out %r err %r" % (build, name, rc, out, err))
        rc, out, err = run([sim, "calib-check", "docs/calib-example.txt"])
        result(rc == 0 and out == "docs/calib-example.txt: ok (2 inputs, 1 corners)\n",
               "%s calib-check legacy example: %r %r" % (build, out, err))
        rc, out, err = run([sim, "calib-check", "--help"])
        result(rc == 0 and out.startswith("usage: squeal-sim calib-check FILE"),
               "%s calib-check --help: rc %d" % (build, rc))
        missing = os.path.join(tmp, "none.cal")
        rc, out, err = run([sim, "calib-check", missing])
        line = one_line(err)
        result(rc == 1 and line is not None and line.startswith(missing + ": cannot open"),
               "%s calib-check missing file: rc %d err %r" % (build, rc, err))
        rc, out, err = run([sim, "calib-check"])
        result(rc == 2, "%s calib-check without FILE: rc %d" % (build, rc))
        # one file per run: a second one is bad usage, not checked silently
        rc, out, err = run([sim, "calib-check", good, bad])
        result(rc == 2 and out == "" and err.startswith("squeal-sim calib-check: "),
               "%s calib-check with two FILEs: rc %d out %r err %r" % (build, rc, out, err))

        # every command taking --calib: the same one line, exit 1
        cmds = {
            "ecu": [sim, "ecu", "--iface", "vcan0", "--duration", "0.1", "--calib"],
            "plant": [sim, "plant", "--log", os.path.join(tmp, "p.log"), "--scenario",
                      "stop", "--duration", "0.1", "--calib"],
            "classify": [sim, "classify", "--v0", "1", "--force", "1000", "--calib"],
        }
        for name, cmd in cmds.items():
            rc, out, err = run(cmd + [bad])
            line = one_line(err)
            result(rc == 1 and line is not None and line.endswith(want_bad),
                   "%s %s --calib max<min: rc %d err %r" % (build, name, rc, err))
        # ... and the 2^-10 calibration is taken, not replaced by defaults
        rc, out, err = run(cmds["classify"] + [good])
        result(rc == 0, "%s classify --calib 2^-10: rc %d err %r" % (build, rc, err))
        log = os.path.join(tmp, "p.log")
        rc, out, err = run(cmds["plant"] + [good])
        frames = []
        if rc == 0:
            with open(log) as f:
                frames = [ln.split()[2] for ln in f if ln.startswith("(")]
        result(rc == 0 and any(fr.startswith("1A1#") for fr in frames) and
               not any(fr.startswith("110#") for fr in frames),
               "%s plant --calib 2^-10: rc %d, the layout's frames (%s)" %
               (build, rc, frames[:3]))
        rc, out, err = run(cmds["ecu"] + [good])
        result(rc != 0 and "calib" not in err and good not in err,
               "%s ecu --calib 2^-10: stops at the interface, not the file: %r" % (build, err))

    return result.finish()


if __name__ == "__main__":
    sys.exit(main())
