#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Generate a test fleet: COUNT candump logs from `squeal-sim plant`
scenarios, BROKEN of them broken in the ways real recordings break.

Good logs (car-XX/drive-NNN.log): the built-in scenarios (stop, creep,
sweep, point at a random v0 and force), the files in scenarios/, and random
drives (a few brakings from random speeds at random pad forces, written as
scenario files next to the logs), some with dropped, delayed or corrupted
frames or a frozen counter. --duration-scale stretches the random drives
(longer logs for benchmarks). --minutes M makes every good log a random
drive of M minutes (brakings one after the other, as a real drive's log).
Broken logs (broken-NNN.log), cycling through: binary garbage; a log cut
in the middle of a line with garbage lines; an empty file; a directory
named *.log (cannot be read); a dangling symbolic link (cannot be opened).
Prints one line per log kind and the totals.
"""
import os
import random
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import helptext  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def random_drive(rnd, path, scale, min_s=0.0):
    """A scenario file: brakings from random speeds, standing and driving off
    (2 to 4 of them, more until the drive lasts min_s seconds)."""
    v = rnd.uniform(8.0, 30.0)
    t, rows = 0.0, [(0.0, v, 0)]
    n = rnd.randint(2, 4)
    while n > 0 or t < min_s:
        n -= 1
        force = rnd.choice([2000, 4000, 6000, 9000, 12000, 15000, 18000])
        v_end = rnd.choice([0.0, 0.0, rnd.uniform(1.0, 6.0)])
        dur = max(1.0, (v - v_end) / rnd.uniform(2.0, 7.0)) * scale
        rows += [(t + 0.2, v, force), (t + 0.2 + dur, v_end, force)]
        t += 0.2 + dur
        rows.append((t + 0.5 * scale, v_end, 0))
        t += 0.5 * scale
        v = rnd.uniform(5.0, 30.0)
        rows.append((t + 1.0 * scale, v, 0))
        t += 1.0 * scale
    with open(path, "w") as f:
        f.write("# random drive (tools/gen_fleet_logs.py)\n# time_s speed_mps force_n\n")
        for row in rows:
            f.write("%.3f %.3f %d\n" % row)


def broken(kind, path, good_log):
    if kind == 0:
        with open(path, "wb") as f:
            f.write(bytes(random.Random(path).getrandbits(8) for _ in range(4096)))
    elif kind == 1:
        with open(good_log, "rb") as f:
            data = f.read()
        with open(path, "wb") as f:
            f.write(data[:len(data) // 2] + b"(00000\xff\xfe garbage\nvcan0 12#\n" + data[len(data) // 2 + 7:])
    elif kind == 2:
        open(path, "w").close()
    elif kind == 3:
        os.makedirs(path, exist_ok=True)
    else:
        os.symlink(os.path.join(os.path.dirname(path), "no-such-recording"), path)
    return ("garbage", "cut-and-garbage", "empty", "directory", "dangling-link")[kind]


def main():
    ap = helptext.parser(__doc__, "tools/gen_fleet_logs.py")
    ap.add_argument("--out", required=True, metavar="DIR", help="folder the logs are written to")
    ap.add_argument("--count", type=int, default=100, metavar="N", help="logs in all, broken ones included (default 100)")
    ap.add_argument("--broken", type=int, default=5, metavar="K", help="of them broken on purpose (default 5)")
    ap.add_argument("--seed", type=int, default=13, metavar="S", help="random seed: same seed, same fleet (default 13)")
    ap.add_argument("--duration-scale", type=float, default=1.0, metavar="X",
                    help="stretch the random drives by X (default 1)")
    ap.add_argument("--minutes", type=float, default=0.0, metavar="M",
                    help="make every good log a random drive of M minutes (real-length drives; default 0: the mix above)")
    ap.add_argument("--sim", default=os.path.join(ROOT, "build", "host", "squeal-sim"), metavar="PATH",
                    help="the squeal-sim that writes the logs (default build/host/squeal-sim)")
    args = ap.parse_args()
    # a broken log is cut or corrupted from a good one: one good log at least
    if args.count < 1 or not 0 <= args.broken < args.count:
        ap.error("need --count >= 1 and 0 <= --broken < --count (broken logs are made from good ones)")
    rnd = random.Random(args.seed)
    if not os.access(args.sim, os.X_OK):
        sys.exit("gen_fleet_logs.py: --sim %s: no such program (make build/host/squeal-sim)" % args.sim)
    try:
        os.makedirs(args.out, exist_ok=True)
    except OSError as e:
        sys.exit("gen_fleet_logs.py: --out %s: %s" % (args.out, e.strerror))
    files = sorted(os.path.join(ROOT, "scenarios", f) for f in os.listdir(os.path.join(ROOT, "scenarios")))
    kinds = {}
    good = []
    for n in range(args.count - args.broken):
        car = os.path.join(args.out, "car-%02d" % (n % 8))
        os.makedirs(car, exist_ok=True)
        log = os.path.join(car, "drive-%03d.log" % n)
        pick = 1.0 if args.minutes > 0 else rnd.random()
        if pick < 0.15:
            scen = [rnd.choice(["stop", "creep", "sweep"])]
        elif pick < 0.25:
            scen = ["point", "--v0", "%.2f" % rnd.uniform(0.3, 3.0),
                    "--force", "%d" % rnd.randint(1000, 20000), "--duration", "5"]
        elif pick < 0.35:
            scen = [rnd.choice(files)]
        else:
            sf = os.path.join(car, "drive-%03d.scenario" % n)
            random_drive(rnd, sf, args.duration_scale, 60.0 * args.minutes)
            scen = [sf] + (["--duration", "%g" % (60.0 * args.minutes)] if args.minutes > 0 else [])
        faults = []
        if rnd.random() < 0.3:
            faults = rnd.choice([["--drop", "0.01"], ["--corrupt-crc", "0.005"],
                                 ["--delay", "3"], ["--freeze-counter", "2"]])
        cmd = [args.sim, "plant", "--log", log, "--quiet", "--seed", str(n), "--scenario"] + scen + faults
        if subprocess.run(cmd).returncode != 0:
            print("gen_fleet_logs: %s failed" % " ".join(cmd), file=sys.stderr)
            return 1
        kind = scen[0] if not scen[0].startswith("/") else (
            "random drive" if scen[0].endswith(".scenario") else "scenario file")
        kinds[kind] = kinds.get(kind, 0) + 1
        good.append(log)
    for n in range(args.broken):
        kind = broken(n % 5, os.path.join(args.out, "broken-%03d.log" % n), good[n % len(good)])
        kinds["broken: " + kind] = kinds.get("broken: " + kind, 0) + 1
    for k in sorted(kinds):
        print("  %-28s %d" % (k, kinds[k]))
    print("gen_fleet_logs: %d logs (%d broken) in %s" % (args.count, args.broken, args.out))
    return 0


if __name__ == "__main__":
    sys.exit(main())
