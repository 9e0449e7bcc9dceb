#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""The tool an engineer would otherwise write: read a candump -L log with
python-can and decode every frame of squeal.dbc to physical values with
canmatrix. Used by bench-replay.sh as the baseline for `squeal-sim replay`
and `squeal-sim decode`.

    pydecode.py LOG [--print] [--dbc FILE]

--dbc decodes with another DBC file (a vehicle's) instead of squeal.dbc.

Prints "frames N decoded M seconds S frames_per_s R" (the decoded values
are kept in a per-signal running sum so nothing is optimised away).
"""
import os
import sys
import time
import warnings

import can
import canmatrix.formats

DBC = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                   "firmware", "protocol", "squeal.dbc")


def main(argv):
    if not argv:
        print(__doc__)
        return 2
    show = "--print" in argv[1:]
    dbc = argv[argv.index("--dbc") + 1] if "--dbc" in argv[1:-1] else DBC
    t0 = time.perf_counter()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        db = list(canmatrix.formats.loadp(dbc).values())[0]
    by_id = {f.arbitration_id.id: f for f in db.frames}
    sums = {}
    n = 0
    decoded = 0
    for msg in can.io.CanutilsLogReader(argv[0]):
        n += 1
        fr = by_id.get(msg.arbitration_id)
        if fr is None or msg.is_extended_id or msg.is_remote_frame or len(msg.data) != fr.size:
            continue  # not this DBC's frame (another layout's length: not decoded)
        values = fr.decode(msg.data)
        for name, sig in values.items():
            sums[name] = sums.get(name, 0) + sig.phys_value
        decoded += 1
        if show:
            print("%.6f %s %s" % (msg.timestamp, fr.name,
                                  " ".join("%s=%s" % (k, v.phys_value) for k, v in values.items())))
    dt = time.perf_counter() - t0
    print("frames %d decoded %d seconds %.3f frames_per_s %.0f" % (n, decoded, dt, n / dt if dt > 0 else 0.0),
          file=sys.stderr if show else sys.stdout)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
