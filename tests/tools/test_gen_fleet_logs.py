#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""tools/gen_fleet_logs.py: a small fleet (12 logs, 5 broken) from
squeal-sim plant into a temporary directory, checked as a reader of the
fleet relies on it: where each log lies, that every good log is a candump
log python-can reads, that each broken log is broken the way the tool's
help says, that a seed gives the same fleet again, that --duration-scale
stretches the random drives' time and nothing else, and that bad options
and a failing simulator give one clear error.

usage: test_gen_fleet_logs.py [path/to/squeal-sim]   prints "RESULT: N passed, M failed"
"""
import filecmp
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks, ROOT, TOOLS  # noqa: E402

import can  # noqa: E402

SIM = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build", "host", "squeal-sim"))
GEN = os.path.join(TOOLS, "gen_fleet_logs.py")
COUNT, BROKEN = 12, 5
CANDUMP = re.compile(rb"^\(\d+\.\d{6}\) \w+ [0-9A-F]{3,8}#[0-9A-F]*$")
# the pad forces and speed ranges of a random drive (the tool's help text)
FORCES_N = {0, 2000, 4000, 6000, 9000, 12000, 15000, 18000}


def gen(out, *extra, sim=SIM):
    return subprocess.run([sys.executable, GEN, "--out", out, "--count", str(COUNT), "--broken", str(BROKEN),
                           "--sim", sim] + list(extra), capture_output=True, text=True, timeout=120)


def good_logs(out):
    """drive-NNN.log of drive n lies in car-(n mod 8)."""
    return [os.path.join(out, "car-%02d" % (n % 8), "drive-%03d.log" % n) for n in range(COUNT - BROKEN)]


def scenario_rows(path):
    rows = []
    with open(path) as f:
        for line in f:
            if line.strip() and not line.startswith("#"):
                t, v, n = line.split()
                rows.append((float(t), float(v), int(n)))
    return rows


def layout(c, out, r):
    c.check(r.returncode == 0, "a fleet of %d logs, %d broken: exit 0 (%s)" % (COUNT, BROKEN, r.stderr[-300:]))
    lines = r.stdout.strip().splitlines()
    c.check(lines[-1] == "gen_fleet_logs: %d logs (%d broken) in %s" % (COUNT, BROKEN, out),
            "its last line names the totals (%s)" % lines[-1])
    counts = [int(x.split()[-1]) for x in lines[:-1]]
    broken = [x.split()[1] for x in lines[:-1] if x.strip().startswith("broken:")]
    c.check(sum(counts) == COUNT and sorted(broken) == sorted(
        ["garbage", "cut-and-garbage", "empty", "directory", "dangling-link"]),
        "one line per kind, the kinds add up to %d, each broken kind once (%s)" % (COUNT, lines[:-1]))
    logs = good_logs(out)
    c.check(all(os.path.isfile(p) for p in logs),
            "the %d good logs lie in car-XX/drive-NNN.log, drive n in car n mod 8" % len(logs))
    cars = sorted(d for d in os.listdir(out) if d.startswith("car-"))
    c.check(cars == ["car-%02d" % k for k in range(min(8, COUNT - BROKEN))], "cars: %s" % cars)
    bad_frames = []
    n_frames = []
    for p in logs:
        with open(p, "rb") as f:
            lines_b = f.read().splitlines()
        bad_frames += [x for x in lines_b if not CANDUMP.match(x)]
        n_frames.append(sum(1 for _ in can.CanutilsLogReader(p)))
    c.check(not bad_frames and min(n_frames) > 100 and n_frames == [
        sum(1 for _ in open(p, "rb")) for p in logs],
        "every good log is candump text python-can reads line for line (%s frames)" % n_frames)


def broken_logs(c, out):
    b = [os.path.join(out, "broken-%03d.log" % k) for k in range(BROKEN)]
    with open(b[0], "rb") as f:
        garbage = f.read()
    c.check(len(garbage) == 4096 and not any(CANDUMP.match(x) for x in garbage.split(b"\n")),
            "broken-000: 4096 bytes of garbage, no candump line in it")
    # broken log k is cut from good log k mod the number of good logs
    with open(good_logs(out)[1 % (COUNT - BROKEN)], "rb") as f:
        good = f.read()
    with open(b[1], "rb") as f:
        cut = f.read()
    # 27 bytes of garbage (a cut timestamp, two bytes that are no UTF-8, an
    # unfinished frame) in place of 7 bytes in the middle of drive-001.log
    c.check(len(cut) == len(good) + 27 - 7 and cut.startswith(good[:len(good) // 2])
            and cut.endswith(good[len(good) // 2 + 7:]) and b"\xff\xfe" in cut,
            "broken-001: drive-001.log cut in the middle with garbage lines (%d of %d bytes)"
            % (len(cut), len(good)))
    c.check(os.path.isfile(b[2]) and os.path.getsize(b[2]) == 0, "broken-002: an empty file")
    c.check(os.path.isdir(b[3]), "broken-003: a directory named *.log")
    c.check(os.path.islink(b[4]) and not os.path.exists(b[4]), "broken-004: a dangling symbolic link")


def random_drives(c, out):
    files = sorted(os.path.join(d, f) for d, _, fs in os.walk(out) for f in fs if f.endswith(".scenario"))
    ok = bool(files)
    for path in files:
        rows = scenario_rows(path)
        times = [r[0] for r in rows]
        ok = ok and rows[0] == (0.0, rows[0][1], 0) and times == sorted(times)
        ok = ok and all(0.0 <= v <= 30.0 and n in FORCES_N for _, v, n in rows)
        ok = ok and os.path.isfile(path[:-len(".scenario")] + ".log")
    c.check(ok, "%d random drives: from t = 0 without force, time never backwards, 0..30 m/s, "
            "the listed pad forces, each with its log" % len(files))
    return files


def reproducible(c, tmp, out, scen1):
    again = os.path.join(tmp, "again")
    gen(again)
    same = all(filecmp.cmp(a, b, shallow=False) for a, b in zip(good_logs(out), good_logs(again)))
    c.check(same, "the same seed writes the same logs again")
    other = os.path.join(tmp, "other")
    gen(other, "--seed", "14")
    diff = any(not filecmp.cmp(a, b, shallow=False) for a, b in zip(good_logs(out), good_logs(other)))
    c.check(diff, "another seed writes another fleet")
    # --duration-scale 2: each braking's duration and each pause doubled,
    # the 0.2 s before each braking not: T2 = 2 T1 - 0.2 k for k brakings
    slow = os.path.join(tmp, "slow")
    gen(slow, "--duration-scale", "2")
    ok = bool(scen1)
    for path in scen1:
        r1 = scenario_rows(path)
        r2 = scenario_rows(os.path.join(slow, os.path.relpath(path, out)))
        k = sum(1 for _, _, n in r1 if n > 0) // 2
        ok = ok and [x[1:] for x in r1] == [x[1:] for x in r2]
        ok = ok and abs(r2[-1][0] - (2.0 * r1[-1][0] - 0.2 * k)) < 4e-3
    c.check(ok, "--duration-scale 2: the same speeds and forces, the time stretched "
            "(end 2 T - 0.2 s per braking)")


def refusals(c, tmp):
    for what, args in (("--broken above --count", ["--count", "3", "--broken", "4"]),
                       ("every log broken (none good to make them from)", ["--count", "2", "--broken", "2"]),
                       ("--count 0", ["--count", "0", "--broken", "0"]),
                       ("a negative --broken", ["--count", "3", "--broken", "-1"])):
        r = subprocess.run([sys.executable, GEN, "--out", os.path.join(tmp, "x"), "--sim", SIM] + args,
                           capture_output=True, text=True, timeout=60)
        c.check(r.returncode == 2 and "need --count >= 1 and 0 <= --broken < --count" in r.stderr
                and "Traceback" not in r.stderr, "%s: a usage error (exit %d)" % (what, r.returncode))
    r = gen(os.path.join(tmp, "false"), sim="/bin/false")
    c.check(r.returncode == 1 and "gen_fleet_logs: /bin/false plant --log" in r.stderr
            and "Traceback" not in r.stderr,
            "a simulator that fails: exit 1, the command named (%s)" % r.stderr.strip()[:120])


def main():
    c = Checks()
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "fleet")
        r = gen(out)
        layout(c, out, r)
        broken_logs(c, out)
        scen = random_drives(c, out)
        reproducible(c, tmp, out, scen)
        refusals(c, tmp)
    return c.finish()


if __name__ == "__main__":
    sys.exit(main())
