#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Readable timeline of a monitored drive, from `squeal-sim decode --csv`.

Walks the bus log in time order with a progress bar, prints every change of
the monitor's SquealState / WarningLevel with the vehicle speed, pad force
and margins at that moment, compares each border crossing with the model's
closed-form prediction for the measured force, and writes the drive CSV
(time_s,v0_mps,force_n,state,warning) that tools/plots/plot_drive.py draws.
"""
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import helptext  # noqa: E402

R_P, R_W = 0.12, 0.30            # default calibration (docs/model.md section 8)
STATES = {0: "stable", 1: "bistable", 2: "unstable", 3: "not sliding", 15: "FAULT"}
LEVELS = {0: "none", 1: "advisory", 2: "WARNING", 3: "CRITICAL"}


def bar(frac, width=30):
    n = int(round(frac * width))
    return "[" + "#" * n + "." * (width - n) + "]"


def main():
    ap = helptext.parser(__doc__, "tools/demo_timeline.py")
    ap.add_argument("frames_csv", metavar="FRAMES.csv", help="the bus log as `squeal-sim decode --csv` prints it")
    ap.add_argument("--drive-csv", required=True, metavar="DRIVE.csv",
                    help="where to write the drive CSV for tools/plots/plot_drive.py")
    args = ap.parse_args()
    try:
        with open(args.frames_csv, newline="") as f:
            rows = list(csv.DictReader(f))
    except OSError as e:
        sys.exit("demo_timeline: %s: %s" % (args.frames_csv, e.strerror))
    if not rows:
        sys.exit("demo_timeline: %s: no frames" % args.frames_csv)
    t_end = float(rows[-1]["time_s"]) or 1.0
    tty = sys.stdout.isatty()
    v0 = force = None
    hopf_v0 = None              # the monitor's own v_H, from SquealDetail
    last = None
    next_mark = 0.0
    drive = []
    print("   time    vehicle   v0 (disc)   force     state         warning    note")
    for r in rows:
        t = float(r["time_s"])
        if t >= next_mark:
            line = "%s %3.0f%%  t = %5.2f s" % (bar(t / t_end), 100 * t / t_end, t)
            if tty:
                sys.stderr.write("\r" + line)
                sys.stderr.flush()
            next_mark += t_end / 10
        msg = r["message"]
        if msg == "DiscSpeed" and r["e2e"] in ("ok", "initial") or msg == "DiscSpeed" and r["e2e"].startswith("lost"):
            v0 = float(r["DiscSpeed_radps"]) * R_P
        elif msg == "PadForce" and (r["e2e"] in ("ok", "initial") or r["e2e"].startswith("lost")):
            force = float(r["PadForce_N"])
        elif msg == "SquealDetail" and r["HopfSpeed_mps"] not in ("NA", ""):
            hopf_v0 = float(r["HopfSpeed_mps"])
        elif msg == "SquealStatus":
            st, lvl = int(r["SquealState"]), int(r["WarningLevel"])
            if v0 is not None and force is not None:
                drive.append((t, v0, force, st, lvl))
            if (st, lvl) != last:
                if tty:
                    sys.stderr.write("\r" + " " * 60 + "\r")
                note = ""
                if v0 is not None and force is not None:
                    if st == 2 and hopf_v0 is not None:
                        note = "Hopf border v_H = %.2f m/s at %.0f N (SquealDetail)" % (hopf_v0, force)
                    elif st == 1 and r["BasinRatio"] not in ("NA", ""):
                        note = "basin ratio %.2f: a disturbance > trigger velocity starts stick-slip" % float(r["BasinRatio"])
                    elif st == 0 and r["HopfMargin_mps"] not in ("NA", ""):
                        note = "Hopf margin %+.2f m/s" % float(r["HopfMargin_mps"])
                    elif st == 3:
                        note = "disc stopped: nothing slides"
                if st == 15:
                    note = "no inputs yet" if not drive else "inputs stale: the senders stopped"
                vtxt = "%5.1f km/h" % (v0 * R_W / R_P * 3.6) if v0 is not None else "    -    "
                v0txt = "%6.3f m/s" % v0 if v0 is not None else "     -    "
                ftxt = "%6.0f N" % force if force is not None else "    -   "
                print("%7.3f s  %s  %s  %s   %-12s  %-9s  %s" % (
                    t, vtxt, v0txt, ftxt, STATES.get(st, str(st)), LEVELS.get(lvl, str(lvl)), note))
                last = (st, lvl)
    if tty:
        sys.stderr.write("\r%s 100%%  t = %5.2f s\n" % (bar(1.0), t_end))
    else:
        print("   (%d bus frames analysed, %.2f s of driving)" % (len(rows), t_end))
    with open(args.drive_csv, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["time_s", "v0_mps", "force_n", "state", "warning"])
        for row in drive:
            w.writerow(["%.6f" % row[0], "%.6f" % row[1], "%.3f" % row[2], row[3], row[4]])


if __name__ == "__main__":
    main()
