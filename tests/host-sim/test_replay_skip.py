#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""squeal-sim replay skips the ticks that change nothing
(host-sim/cmd_replay.c, squeal_app_next_event_us() in firmware/app): its
output must be the bytes of 1 ms stepping (--step-every-ms), both numeric
builds.

Logs, all written here by `squeal-sim plant --log` (and
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
For each: stdout (the ECU's frames), stderr (notes and summary), the exit
status and --summary-json are the same with and without skipping.
Prints "RESULT: N passed, M failed". Run from the repository root.
"""
import glob
import os
import random
import re
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "support"))
from sim_cli import ROOT, Results, run  # noqa: E402

result = Results()
STAMP = re.compile(r"^\((\d+)\.(\d{6})\)(.*)$")
VEHICLE_CALS = sorted(glob.glob(os.path.join(ROOT, "tests", "firmware", "monitor", "fixtures", "*.cal")) +
                      [os.path.join(HERE, "two_corners.cal"), os.path.join(HERE, "fd_p05.cal")])


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


def plant(sim, args):
    rc, out, err = run([sim, "plant", "--log", "-", "--quiet"] + args)
    result(rc == 0 and out.count("\n") > 100, "plant %s: rc %d, %d lines %s"
           % (" ".join(args), rc, out.count("\n"), err[-300:]))
    return out.splitlines()


def logs(sim, tmp):
    """(name, path, replay options) of every log compared."""
    made = []

    def write(name, lines, opts=()):
        path = os.path.join(tmp, name + ".log")
        with open(path, "w") as f:
            f.write("\n".join(lines) + "\n")
        made.append((name, path, list(opts)))

    for sc in ["stop", "creep", "sweep"] + sorted(glob.glob(os.path.join(ROOT, "scenarios", "*.txt"))):
        write("scenario-" + os.path.basename(sc), plant(sim, ["--scenario", sc]))
    write("scenario-point", plant(sim, ["--scenario", "point", "--v0", "4", "--force", "5000",
                                        "--duration", "3"]))
    for name, extra in (("drop", ["--drop", "0.2", "--seed", "3"]),
                        ("delay", ["--delay", "4", "--seed", "5"]),
                        ("crc", ["--corrupt-crc", "0.05", "--seed", "7"]),
                        ("frozen", ["--freeze-counter", "2"])):
        write("fault-" + name, plant(sim, ["--scenario", "stop"] + extra))
    stop = plant(sim, ["--scenario", "stop"])
    t0 = int(STAMP.match(stop[0]).group(1)) * 1000000 + int(STAMP.match(stop[0]).group(2))
    write("hole", restamp(stop, lambda us: None if 2000000 <= us - t0 < 2300000 else us))
    rnd = random.Random(11)
    write("off-grid", restamp(stop, lambda us: us + rnd.randrange(0, 1000)))
    write("gap", restamp(stop, lambda us: us + (20000000 if us - t0 >= 3000000 else 0)),
          ["--max-gap", "5"])
    write("tail", stop, ["--tail-ms", "2500"])
    for cal in VEHICLE_CALS:
        name = "vehicle-" + os.path.basename(cal)
        write(name, plant(sim, ["--scenario", "stop", "--calib", cal]), ["--calib", cal])
    cal = os.path.join(ROOT, "tests", "firmware", "monitor", "fixtures", "moto15_p02.cal")
    bus = os.path.join(tmp, "vehicle-bus.log")
    rc, _, err = run([sys.executable, os.path.join(HERE, "gen_vehicle_traffic.py"), "--calib", cal,
                      "--frames", "60000", "--out", bus, "--sim", sim])
    result(rc == 0, "gen_vehicle_traffic: rc %d %s" % (rc, err[-300:]))
    made.append(("vehicle-bus", bus, ["--calib", cal]))
    return made


def check_build(build, sim):
    with tempfile.TemporaryDirectory() as tmp:
        for name, path, opts in logs(sim, tmp):
            outs = []
            for mode in ([], ["--step-every-ms"]):
                js = os.path.join(tmp, "summary%d.json" % len(outs))
                rc, out, err = run([sim, "replay", path, "--summary-json", js] + opts + mode)
                with open(js) as f:
                    outs.append((rc, out, err, f.read()))
            skip, step = outs
            result(step[0] == 0 and step[1].count("\n") > 10,
                   "%s %s: stepping replays (rc %d, %d frames)" % (build, name, step[0], step[1].count("\n")))
            for i, what in enumerate(("exit status", "stdout", "stderr", "summary JSON")):
                result(skip[i] == step[i], "%s %s: the %s is the same with skipping" % (build, name, what))


result.each_build(check_build)
sys.exit(result.finish())
