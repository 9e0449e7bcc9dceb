#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""tools/plots/plot_drive.py's reading of a drive (read_drive, state_name),
nothing drawn, on CSVs written here:

  - a `squeal-sim decode --csv` table: before the monitor's own SquealDetail
    frames the point is the inputs' DiscSpeed_radps x the pad radius (by
    default 0.12 m: 50 rad/s -> 6.0 m/s) and PadForce_N; once the monitor
    sends Force_N (SquealDetail2) and V0_mps, those are taken, not the
    inputs; the state and warning are forward-filled, one point per
    SquealStatus frame;
  - a state as a number: 0 stable, 1 bistable, 2 unstable, 3 not sliding,
    15 fault, another number a fault; or as its name.

prints "RESULT: N passed, M failed"
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from figures import Checks  # noqa: E402
import plot_drive as D  # noqa: E402

HEAD = "time_s,message,DiscSpeed_radps,PadForce_N,V0_mps,Force_N,SquealState,WarningLevel"
ROWS = ["0.00,DiscSpeed,50.00,,,,,",
        "0.00,PadForce,,3000.0,,,,",
        "0.01,SquealStatus,,,,,1,1",
        "0.02,SquealDetail,,,5.50,,,",
        "0.02,SquealDetail2,,,,4000.0,,",
        "0.03,SquealStatus,,,,,2,3",
        "0.04,PadForce,,3500.0,,,,",
        "0.05,SquealStatus,,,,,3,0"]


def decode(c, tmp):
    path = os.path.join(tmp, "drive.csv")
    with open(path, "w") as f:
        f.write("\n".join([HEAD] + ROWS) + "\n")
    t, v, n, st, w = D.read_drive(path)
    c.check(list(t) == [0.01, 0.03, 0.05], "one point per SquealStatus frame (%s)" % list(t))
    c.check(abs(v[0] - 6.0) < 1e-12 and abs(n[0] - 3000.0) < 1e-12,
            "before the monitor's details: 50 rad/s x 0.12 m = 6.0 m/s, the input's 3000 N (%s, %s)" % (v[0], n[0]))
    c.check(list(v[1:]) == [5.5, 5.5] and list(n[1:]) == [4000.0, 4000.0],
            "then the monitor's V0_mps 5.5 and Force_N 4000, not the input's 3500 N (%s, %s)"
            % (list(v[1:]), list(n[1:])))
    c.check(st == ["bistable", "unstable", "not_sliding"] and list(w) == [1.0, 3.0, 0.0],
            "states and warnings as sent (%s, %s)" % (st, list(w)))
    t, v, n, st, w = D.read_drive(path, pad_radius=0.2)
    c.check(abs(v[0] - 10.0) < 1e-12, "--pad-radius 0.2: 50 rad/s -> 10 m/s (%s)" % v[0])


def states(c, tmp):
    for text, want in (("0", "stable"), ("1", "bistable"), ("2", "unstable"), ("3", "not_sliding"),
                       ("15", "fault"), ("4", "fault"), ("2.0", "unstable"), (" unstable ", "unstable"),
                       ("squeal", "fault")):
        got = D.state_name(text)
        c.check(got == want, "state %r: %s (%s)" % (text, want, got))


if __name__ == "__main__":
    sys.exit(Checks.run(decode, states))
