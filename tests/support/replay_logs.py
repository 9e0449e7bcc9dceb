# SPDX-License-Identifier: MIT
"""The logs the replay tests run (test_replay_skip.py, test_cmd_replay_each.py),
all written here by `squeal-sim plant --log` (and
tests/host-sim/gen_vehicle_traffic.py for a vehicle bus):
  - every scenario: the built-in ones (stop, creep, sweep, point) and every
    file in scenarios/;
  - the stop drive with the sender's faults (frames lost, late, bad CRC, a
    frozen counter), with a hole of 0.3 s (the inputs go stale and come
    back), with timestamps off the 1 ms grid, with a gap beyond --max-gap,
    and run on with --tail-ms;
  - vehicle layouts: every fixture calibration under tests/ driven by
    plant --calib, and a vehicle bus of other ECUs' frames among the input
    map's (most of them stop at the controller's filters).
logs(sim, tmp, result) gives (name, path, replay options) of each."""
import glob
import os
import random
import re
import sys

from sim_cli import ROOT, run

HOST_SIM_TESTS = os.path.join(ROOT, "tests", "host-sim")
STAMP = re.compile(r"^\((\d+)\.(\d{6})\)(.*)$")
VEHICLE_CALS = sorted(glob.glob(os.path.join(ROOT, "tests", "firmware", "monitor", "fixtures", "*.cal")) +
                      [os.path.join(HOST_SIM_TESTS, "two_corners.cal"), os.path.join(HOST_SIM_TESTS, "fd_p05.cal")])


def restamp(lines, move):
    """Lines with each timestamp (us) replaced by move(us) (None: dropped)."""
    out = []
    for line in lines:
        m = STAMP.match(line)
        if not m:
            out.append(line)
            continue
        us = move(int(m.group(1)) * 1000000 + int(m.group(2)))
        if us is not None:
            out.append("(%010d.%06d)%s" % (us // 1000000, us % 1000000, m.group(3)))
    return out


def plant(sim, args, result):
    rc, out, err = run([sim, "plant", "--log", "-", "--quiet"] + args)
    result(rc == 0 and out.count("\n") > 100, "plant %s: rc %d, %d lines %s"
           % (" ".join(args), rc, out.count("\n"), err[-300:]))
    return out.splitlines()


def logs(sim, tmp, result):
    """(name, path, replay options) of every log compared."""
    made = []

    def write(name, lines, opts=()):
        path = os.path.join(tmp, name + ".log")
        with open(path, "w") as f:
            f.write("\n".join(lines) + "\n")
        made.append((name, path, list(opts)))

    for sc in ["stop", "creep", "sweep"] + sorted(glob.glob(os.path.join(ROOT, "scenarios", "*.txt"))):
        write("scenario-" + os.path.basename(sc), plant(sim, ["--scenario", sc], result))
    write("scenario-point", plant(sim, ["--scenario", "point", "--v0", "4", "--force", "5000",
                                        "--duration", "3"], result))
    for name, extra in (("drop", ["--drop", "0.2", "--seed", "3"]),
                        ("delay", ["--delay", "4", "--seed", "5"]),
                        ("crc", ["--corrupt-crc", "0.05", "--seed", "7"]),
                        ("frozen", ["--freeze-counter", "2"])):
        write("fault-" + name, plant(sim, ["--scenario", "stop"] + extra, result))
    stop = plant(sim, ["--scenario", "stop"], result)
    t0 = int(STAMP.match(stop[0]).group(1)) * 1000000 + int(STAMP.match(stop[0]).group(2))
    write("hole", restamp(stop, lambda us: None if 2000000 <= us - t0 < 2300000 else us))
    rnd = random.Random(11)
    write("off-grid", restamp(stop, lambda us: us + rnd.randrange(0, 1000)))
    write("gap", restamp(stop, lambda us: us + (20000000 if us - t0 >= 3000000 else 0)),
          ["--max-gap", "5"])
    write("tail", stop, ["--tail-ms", "2500"])
    for cal in VEHICLE_CALS:
        name = "vehicle-" + os.path.basename(cal)
        write(name, plant(sim, ["--scenario", "stop", "--calib", cal], result), ["--calib", cal])
    cal = os.path.join(ROOT, "tests", "firmware", "monitor", "fixtures", "moto15_p02.cal")
    bus = os.path.join(tmp, "vehicle-bus.log")
    rc, _, err = run([sys.executable, os.path.join(HOST_SIM_TESTS, "gen_vehicle_traffic.py"), "--calib", cal,
                      "--frames", "60000", "--out", bus, "--sim", sim])
    result(rc == 0, "gen_vehicle_traffic: rc %d %s" % (rc, err[-300:]))
    made.append(("vehicle-bus", bus, ["--calib", cal]))
    return made
