#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""A vehicle-bus log for the replay benchmark, as real traffic looks: the
vehicle's own frames for a calibration's input map (written by
`squeal-sim plant --calib CAL --log`, braking cycles 30 -> 0 m/s) among
many frames of other ECUs on other identifiers (40 identifiers at 10, 20,
50 and 100 ms, 8 random bytes each, or --fd-bytes N: CAN FD frames of N
bytes; 1,800 frames/s against the input map's own few hundred), merged in
time order, candump -L.

    gen_vehicle_traffic.py --calib CAL --frames N --out FILE [--sim PATH] [--fd-bytes N]

Prints the share of frames on the input map's identifiers.
"""
import argparse
import os
import random
import re
import subprocess
import sys
import tempfile
# tests/ of this checkout, and the folders its helper modules live in
_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, d) for d in ("support", os.path.join("support", "reference"), "host-sim", "tools")]

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(_TESTS)
OTHER_PERIODS_MS = [10] * 10 + [20] * 10 + [50] * 10 + [100] * 10
OTHER_RATE_HZ = sum(1000 // p for p in OTHER_PERIODS_MS)
CYCLE_S = 30.0  # one braking cycle of the scenario


def scenario(path, duration_s):
    """Braking cycles: 30 m/s, a 6 s stop at 9 kN, 4 s standing, pull away."""
    t = 0.0
    with open(path, "w") as f:
        while t <= duration_s + CYCLE_S:
            for dt, v, n in ((0.0, 30, 0), (10.0, 30, 0), (10.5, 30, 9000), (16.0, 0.5, 9000),
                             (20.0, 0.0, 2000), (22.0, 0.0, 0), (29.9, 28, 0)):
                f.write("%.3f %g %g\n" % (t + dt, v, n))
            t += CYCLE_S


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--calib", required=True)
    ap.add_argument("--frames", type=int, required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--sim", default=os.path.join(ROOT, "build", "host", "squeal-sim"))
    ap.add_argument("--fd-bytes", type=int, default=0,
                    help="the other ECUs' frames as CAN FD frames of this many bytes (##1)")
    args = ap.parse_args()
    used = {int(x, 0) for x in re.findall(r"^\s*(?:id|status_id|detail_id|detail2_id|diag_id)\s*=\s*(\S+)",
                                          open(args.calib).read(), re.M)}
    used |= {0x300 + 0x10 * k + j for k in range(4) for j in range(4)}
    rnd = random.Random(11)
    ids = rnd.sample([i for i in range(0x080, 0x7F0) if i not in used], len(OTHER_PERIODS_MS))
    with tempfile.TemporaryDirectory() as tmp:
        scen, vlog = os.path.join(tmp, "cycles.txt"), os.path.join(tmp, "vehicle.log")
        # the map's own frames: estimate their rate from a short run first
        scenario(scen, 10.0)
        subprocess.run([args.sim, "plant", "--calib", args.calib, "--scenario", scen, "--duration",
                        "10", "--log", vlog, "--quiet"], check=True)
        own_hz = sum(1 for _ in open(vlog)) / 10.0
        duration_s = args.frames / (own_hz + OTHER_RATE_HZ)
        scenario(scen, duration_s)
        subprocess.run([args.sim, "plant", "--calib", args.calib, "--scenario", scen, "--duration",
                        "%.3f" % duration_s, "--log", vlog, "--quiet"], check=True)
        stamp = re.compile(r"^\((\d+)\.(\d{6})\) (\S+) (.*)$")
        own = []
        with open(vlog) as f:
            for line in f:
                m = stamp.match(line)
                own.append((int(m.group(1)) * 1000000 + int(m.group(2)), m.group(3), m.group(4)))
    iface = own[0][1] if own else "vcan0"
    end_us = int(duration_s * 1e6)
    other = []
    for k, (cid, per) in enumerate(zip(ids, OTHER_PERIODS_MS)):
        phase = (k * 137) % (per * 1000)  # spread over the period
        for t in range(phase, end_us, per * 1000):
            if args.fd_bytes:
                other.append((t, iface, "%03X##1%0*X" % (cid, 2 * args.fd_bytes,
                                                         rnd.getrandbits(8 * args.fd_bytes))))
            else:
                other.append((t, iface, "%03X#%016X" % (cid, rnd.getrandbits(64))))
    frames = sorted(own + other, key=lambda x: x[0])[:args.frames]
    with open(args.out, "w") as f:
        f.writelines("(%010d.%06d) %s %s\n" % (t // 1000000, t % 1000000, i, body)
                     for t, i, body in frames)
    n_own = sum(1 for t, _, _ in own if t <= frames[-1][0])
    print("%s: %d frames over %.0f s, %d (%.1f %%) on the input map's identifiers" %
          (args.out, len(frames), frames[-1][0] / 1e6, n_own, 100.0 * n_own / len(frames)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
