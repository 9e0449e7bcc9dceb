#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""make bench: squeal-sim replay against the tools a user would otherwise
run on the same log, as ratios from one run (figures, never pass/fail):

  - can-utils `log2asc` (parses each line and prints it again: the floor of
    any tool that reads a candump log);
  - python-can + canmatrix (tests/support/pydecode.py: read the log with
    python-can, decode every frame of the DBC with canmatrix).

Traffic, generated into build/replay-bench/ (not committed):
  project   the project's own frames (tests/host-sim/gen_inputs.py):
            DiscSpeed + PadForce, 10^6 frames;
  vehicle   a vehicle-layout drive, `squeal-sim plant --calib
            tests/firmware/monitor/fixtures/moto15_p02.cal --log` (four
            corners; braking cycles), 10^6 frames, decoded by python with
            tests/tools/fixtures/esc_motorola.dbc;
  bus       the same vehicle's drive among 40 other ECUs' identifiers
            (tests/host-sim/gen_vehicle_traffic.py), 10^6 frames;
  fd        a CAN FD layout's drive (plant --calib tests/host-sim/fd_p05.cal),
            10^6 frames, python with tests/tools/fixtures/fd_wheels24.dbc.
replay runs the release build (build/host/squeal-replay, what `squeal-sim
replay` execs) with the calibration and writes the ECU's frames; log2asc
writes its ASC file; both to /dev/null. CPU time (user + sys of the
process, from wait4) is the figure: the machine may be shared. Each ratio
is the median over RUNS pairs (default 3, BENCH_VS_RUNS) run in turn
(A B A B ...), so that a drift of the machine's speed hits both; python
runs on the first PY_FRAMES (default 10^5, BENCH_VS_PY_FRAMES) lines of
each log, once per pair (BENCH_VS_PY_RUNS, default 1), and its ratio is per
frame. On the same first lines, replay's and log2asc's instructions per
frame under callgrind (BENCH_VS_ICOUNT=0 leaves them out): the ratio that
does not move with the machine's load.
Builds nothing: make bench builds build/host/squeal-sim first.
"""
import os
import re
import statistics
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
from gen_vehicle_traffic import scenario  # noqa: E402

PY = "/usr/bin/python3"
SIM = os.path.join(ROOT, "build", "host", "squeal-sim")
REPLAY = os.path.join(ROOT, "build", "host", "squeal-replay")
DIR = os.path.join(ROOT, "build", "replay-bench")
RUNS = int(os.environ.get("BENCH_VS_RUNS", "3"))
PY_RUNS = int(os.environ.get("BENCH_VS_PY_RUNS", "1"))
PY_FRAMES = int(os.environ.get("BENCH_VS_PY_FRAMES", "100000"))
ICOUNT = os.environ.get("BENCH_VS_ICOUNT", "1") != "0"
FRAMES = 1000000
VCAL = os.path.join(ROOT, "tests", "firmware", "monitor", "fixtures", "moto15_p02.cal")
FDCAL = os.path.join(HERE, "fd_p05.cal")
FIX = os.path.join(ROOT, "tests", "tools", "fixtures")


def cpu_s(argv):
    """CPU seconds (user + sys) of one run of argv, its output thrown away."""
    with open(os.devnull, "wb") as null:
        p = subprocess.Popen(argv, stdout=null, stderr=null)
        _, status, ru = os.wait4(p.pid, 0)
    p.returncode = os.waitstatus_to_exitcode(status)
    if p.returncode != 0:
        raise SystemExit("bench_replay_vs: %s: exit %d" % (" ".join(argv), p.returncode))
    return ru.ru_utime + ru.ru_stime


def paired(cmd_a, cmd_b, runs):
    """runs pairs of A then B: A's and B's CPU seconds, and B/A pair by pair."""
    t_a, t_b, ratio = [], [], []
    for _ in range(runs):
        a = cpu_s(cmd_a)
        b = cpu_s(cmd_b)
        t_a.append(a)
        t_b.append(b)
        ratio.append(b / a if a > 0 else float("inf"))
    return t_a, t_b, ratio


def icount(argv):
    """Instructions of one run of argv under valgrind's callgrind (the
    stable figure: the same binary on the same input counts the same
    whatever else the machine does); None without valgrind."""
    try:
        p = subprocess.run(["valgrind", "--tool=callgrind",
                            "--callgrind-out-file=" + os.devnull] + argv,
                           stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, check=True)
    except (OSError, subprocess.CalledProcessError):
        return None
    m = re.search(rb"Collected : (\d+)", p.stderr)
    return int(m.group(1)) if m else None


def fresh(path, *sources):
    return os.path.exists(path) and all(os.path.getmtime(path) >= os.path.getmtime(s) for s in sources)


def head(src, n, dst):
    if not fresh(dst, src):
        with open(src, "rb") as f, open(dst, "wb") as g:
            for i, line in enumerate(f):
                if i >= n:
                    break
                g.write(line)
    return dst


def plant_log(name, cal, rate_s):
    """A drive of about FRAMES frames of cal's layout (rate_s frames/s)."""
    path = os.path.join(DIR, name + ".log")
    if not fresh(path, SIM, cal):
        scen = os.path.join(DIR, name + ".scenario")
        duration_s = FRAMES / rate_s
        scenario(scen, duration_s)
        subprocess.run([SIM, "plant", "--calib", cal, "--log", path, "--scenario", scen,
                        "--duration", "%.3f" % duration_s, "--quiet"], check=True)
    return path


def traffic():
    """(name, log, calibration or None, DBC for python or None)."""
    os.makedirs(DIR, exist_ok=True)
    proj = os.path.join(DIR, "in-1e6.log")
    gen = os.path.join(HERE, "gen_inputs.py")
    if not fresh(proj, gen):
        subprocess.run([PY, gen, "--frames", str(FRAMES), "--out", proj], check=True,
                       stderr=subprocess.DEVNULL)
    bus = os.path.join(DIR, "vehicle-1e6.log")
    if not fresh(bus, os.path.join(HERE, "gen_vehicle_traffic.py"), VCAL):
        subprocess.run([PY, os.path.join(HERE, "gen_vehicle_traffic.py"), "--calib", VCAL,
                        "--frames", str(FRAMES), "--out", bus, "--sim", SIM], check=True,
                       stdout=subprocess.DEVNULL)
    return [("project", proj, None, None),
            ("vehicle", plant_log("vehicle-drive", VCAL, 150.0), VCAL,
             os.path.join(FIX, "esc_motorola.dbc")),
            ("bus", bus, VCAL, os.path.join(FIX, "esc_motorola.dbc")),
            ("fd", plant_log("fd-drive", FDCAL, 200.0), FDCAL, os.path.join(FIX, "fd_wheels24.dbc"))]


def ifaces(log):
    seen = []
    with open(log) as f:
        for i, line in enumerate(f):
            parts = line.split()
            if len(parts) >= 2 and parts[1] not in seen:
                seen.append(parts[1])
            if i > 20000:
                break
    return seen


def log2asc_cmd(log, names):
    """can-utils log2asc on log, the interfaces names, its ASC to /dev/null."""
    return ["log2asc", "-I", log, "-O", os.devnull] + names


def lines(path):
    with open(path, "rb") as f:
        return sum(1 for _ in f)


def main():
    print("replay vs log2asc and python-can + canmatrix, CPU s (user + sys), medians; "
          "ratio = the other's time / replay's, pair by pair")
    for name, log, cal, dbc in traffic():
        n = lines(log)
        rep = [REPLAY, log] + (["--calib", cal] if cal else [])
        names = ifaces(log)
        l2a = log2asc_cmd(log, names)
        small = head(log, PY_FRAMES, os.path.join(DIR, "%s-head.log" % name))
        ns = lines(small)
        rep_small = [REPLAY, small] + (["--calib", cal] if cal else [])
        py = [PY, os.path.join(ROOT, "tests", "support", "pydecode.py"), small] + \
            (["--dbc", dbc] if dbc else [])
        r_a, r_l, q_l = paired(rep, l2a, RUNS)
        r_s, r_p, q_p = paired(rep_small, py, PY_RUNS)
        med = statistics.median
        print("%-8s %8d frames: replay %.3f s, log2asc %.3f s: replay %.2fx log2asc's speed "
              "(%d pairs; %.2f M frames/s)" % (name, n, med(r_a), med(r_l), med(q_l), RUNS,
                                                n / med(r_a) / 1e6 if med(r_a) > 0 else 0.0))
        if ICOUNT:
            i_r = icount(rep_small)
            i_l = icount(log2asc_cmd(small, names))
            if i_r and i_l:
                print("%-8s %8d frames: replay %.0f, log2asc %.0f instructions per frame "
                      "(callgrind): %.2fx" % ("", ns, i_r / ns, i_l / ns, i_l / i_r))
        if PY_RUNS > 0:  # BENCH_VS_PY_RUNS=0: log2asc only
            print("%-8s %8d frames: replay %.3f s, python-can+canmatrix %.3f s: replay %.1fx "
                  "python's speed (%d pairs)" % ("", ns, med(r_s), med(r_p), med(q_p), PY_RUNS))
        for cmd in (rep, l2a, py):
            print("           $ %s" % " ".join(os.path.relpath(x, ROOT) if x.startswith(ROOT) else x
                                              for x in cmd))
    return 0


if __name__ == "__main__":
    sys.exit(main())
