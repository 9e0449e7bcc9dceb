#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""squeal-sim ecu's command line, without a CAN interface: each bad option
is refused with exit status 2 and a message naming it, each good one is
taken (the program goes on to open the interface, which does not exist
here: exit 1 naming it). Running on vcan is tests/system/integration's.

usage: test_cmd_ecu.py [path/to/squeal-sim]  prints "RESULT: N passed, M failed"
"""
import os
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
SIM = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build", "host", "squeal-sim")
IFACE = "sqnosuch0"  # an interface that does not exist
results = []


def check(what, ok, detail=""):
    results.append(ok)
    print(("PASS: " if ok else "FAIL: ") + what + ("" if ok else "  " + detail))


def ecu(*args):
    p = subprocess.run([SIM, "ecu"] + list(args), capture_output=True, text=True, timeout=20)
    return p.returncode, p.stderr


def refused(what, args, needle):
    rc, err = ecu(*args)
    check("%s is refused (exit 2, names it)" % what, rc == 2 and needle in err, "exit %d: %s" % (rc, err.strip()))


def taken(what, args):
    rc, err = ecu(*args)
    check("%s is taken (fails only at the interface)" % what, rc == 1 and IFACE in err,
          "exit %d: %s" % (rc, err.strip()))


refused("no --iface", ["--duration", "0"], "--iface")
refused("--duration -1", ["--iface", IFACE, "--duration", "-1"], "--duration")
refused("--duration 1x", ["--iface", IFACE, "--duration", "1x"], "--duration")
refused("--rcvbuf -5", ["--iface", IFACE, "--rcvbuf", "-5"], "--rcvbuf")
refused("--rcvbuf 2^28 + 1", ["--iface", IFACE, "--rcvbuf", "268435457"], "--rcvbuf")
refused("an extra operand", ["--iface", IFACE, "extra"], "extra")
taken("--duration 0", ["--iface", IFACE, "--duration", "0"])
taken("--rcvbuf 0 and 2^28", ["--iface", IFACE, "--rcvbuf", "268435456", "--rcvbuf", "0", "--duration", "0"])

with tempfile.TemporaryDirectory() as d:
    for key in ("output_bus", "input_bus"):
        cal = os.path.join(d, key + ".cal")
        with open(cal, "w") as f:
            f.write("%s = 1\n" % key)
        rc, err = ecu("--iface", IFACE, "--calib", cal, "--duration", "0")
        check("%s = 1 without --out-iface is refused before the interface" % key,
              rc != 0 and "--out-iface" in err and IFACE not in err, "exit %d: %s" % (rc, err.strip()))
    bad = os.path.join(d, "bad.cal")
    with open(bad, "w") as f:
        f.write("mass_kg = 1\nno_such_key = 3\n")
    rc, err = ecu("--iface", IFACE, "--calib", bad, "--duration", "0")
    check("a bad calibration is refused with its line", rc != 0 and "2" in err and "no_such_key" in err,
          "exit %d: %s" % (rc, err.strip()))

print("RESULT: %d passed, %d failed" % (sum(results), len(results) - sum(results)))
sys.exit(0 if all(results) else 1)
