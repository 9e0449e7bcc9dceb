#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Figures of tests/system/integration/bench-live.sh from the guest's captures.

Latency: for every force step of tests/system/integration/latency-steps.txt, the
first PadForce frame carrying the new force (candump -L timestamp) to the
first SquealStatus frame with the new state. Rate: frames per second the
plant sustained into each consumer, and whether any frame was lost.
usage: bench_live.py OUTDIR
"""
import glob
import os
import re
import statistics
import sys
# tests/ of this checkout, and the folders its helper modules live in
_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, d) for d in ("support", os.path.join("support", "reference"), "host-sim", "tools")]

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_vcan import read_log, read_summary  # noqa: E402

ID_FORCE, ID_STATUS = 0x111, 0x300


def latencies(path):
    frames = read_log(path)
    res = []
    pending = None  # (t, wanted state)
    last_force = None
    state = None
    for f in frames:
        if f.err:
            continue
        if f.id == ID_FORCE and len(f.data) == 4:
            force_n = (f.data[2] | f.data[3] << 8) * 0.5
            side = 2 if force_n > 5000 else 0     # unstable at 9 kN, stable at 2 kN
            if last_force is not None and side != last_force and state is not None:
                pending = (f.t, side)
            last_force = side
        elif f.id == ID_STATUS and len(f.data) == 8:
            state = f.data[1] >> 4
            if pending is not None and state == pending[1]:
                res.append(f.t - pending[0])
                pending = None
    return res


def pct(xs, p):
    xs = sorted(xs)
    k = min(len(xs) - 1, max(0, int(round(p / 100.0 * (len(xs) - 1)))))
    return xs[k]


def plant_rate(path):
    txt = open(path).read() if os.path.exists(path) else ""
    sent = sum(int(x) for x in re.findall(r"sent (\d+)", txt))
    m = re.search(r"([\d.]+) s wall time", txt)
    wall = float(m.group(1)) if m else 0.0
    return sent, wall


def main(argv):
    out = argv[1]
    print("live path inside the QEMU TCG guest: EMULATED time (correct in order,")
    print("not in absolute value; compare only ratios within this run)")
    med = {}
    for name in ("idle", "load"):
        lat = latencies(os.path.join(out, "lat-%s.cap" % name))
        if not lat:
            print("latency %-4s: no state changes captured" % name)
            continue
        med[name] = statistics.median(lat)
        print("latency %-4s: input frame -> status frame: median %.3f ms, p99 %.3f ms, "
              "max %.3f ms (%d steps)%s" % (name, 1e3 * med[name], 1e3 * pct(lat, 99),
                                           1e3 * max(lat), len(lat),
                                           "" if name == "idle" else
                                           " with a cangen flood beside it"))
    if "idle" in med and "load" in med:
        print("latency ratio loaded/idle (median): %.2f" % (med["load"] / med["idle"]))
    def rate_of(tag):
        return int(re.search(r"-(\d+)\.\w+$", tag).group(1))

    def dropcount(path):
        n = 0
        with open(path) as f:
            for line in f:
                m = re.search(r"DROPCOUNT: dropped (\d+)", line)
                if m:
                    n += int(m.group(1))
        return n

    best = {}
    for p in sorted(glob.glob(os.path.join(out, "rate-ecu-*.ecu")), key=lambda p: -rate_of(p)):
        s = read_summary(p)
        sent, wall = plant_rate(p[:-4] + ".plant")
        got = s.get("speed_frames", 0) + s.get("force_frames", 0)
        lost = s.get("hal_rx_kernel_drops", -1) + s.get("speed_e2e_lost", 0) + s.get("force_e2e_lost", 0)
        rate = sent / wall if wall > 0 else 0.0
        print("ecu     <- plant (%s): %.0f frames/s for %.1f s, got %d of %d, kernel drops %s, "
              "E2E lost %s/%s" % ("full speed" if rate_of(p) >= 1000000 else
                                  "%d Hz per message" % rate_of(p), rate, wall, got, sent,
                                  s.get("hal_rx_kernel_drops"), s.get("speed_e2e_lost"),
                                  s.get("force_e2e_lost")))
        if lost == 0 and got == sent and "ecu" not in best:
            best["ecu"] = rate
    for p in sorted(glob.glob(os.path.join(out, "rate-cd-*.log")), key=lambda p: -rate_of(p)):
        sent, wall = plant_rate(p[:-4] + ".plant")
        got = len(read_log(p))
        drops = dropcount(p)
        rate = sent / wall if wall > 0 else 0.0
        print("candump <- plant (%s): %.0f frames/s for %.1f s, got %d of %d, dropped %d" %
              ("full speed" if rate_of(p) >= 1000000 else "%d Hz per message" % rate_of(p),
               rate, wall, got, sent, drops))
        if drops == 0 and got == sent and "cd" not in best:
            best["cd"] = rate
    if "ecu" in best and "cd" in best:
        print("highest sustained input rate with zero loss (of the rates tried): ecu %.0f "
              "frames/s, plain candump -L %.0f frames/s, ratio ecu/candump %.2f" %
              (best["ecu"], best["cd"], best["ecu"] / best["cd"]))
    else:
        print("highest sustained input rate with zero loss: none of the rates tried (%s)" % best)
    deep = os.path.join(out, "deep-ecu.ecu")
    if os.path.exists(deep):
        s = read_summary(deep)
        sent, wall = plant_rate(os.path.join(out, "deep-ecu.plant"))
        got = s.get("speed_frames", 0) + s.get("force_frames", 0)
        print("ecu --rcvbuf 4 MiB <- plant (full speed): %.0f frames/s, got %d of %d, kernel "
              "drops %s, E2E lost %s/%s" % (sent / wall if wall else 0.0, got, sent,
                                            s.get("hal_rx_kernel_drops"),
                                            s.get("speed_e2e_lost"), s.get("force_e2e_lost")))
    # cangen flood: frames the consumer took off the socket per second
    def span(name):
        try:
            t0, t1 = open(os.path.join(out, name)).read().split()
            return float(t1) - float(t0)
        except (OSError, ValueError):
            return 0.0
    s = read_summary(os.path.join(out, "gen-ecu.ecu"))
    ecu_got = s.get("hal_rx_frames", 0)
    ecu_span = span("gen-ecu.time")
    cd_lines = read_log(os.path.join(out, "gen-cd.log"))
    cd_drops = 0
    with open(os.path.join(out, "gen-cd.log")) as f:
        for line in f:
            m = re.search(r"DROPCOUNT: dropped (\d+)", line)
            if m:
                cd_drops += int(m.group(1))
    cd_span = span("gen-cd.time")
    if ecu_span > 0 and cd_span > 0:
        er, cr = ecu_got / ecu_span, len(cd_lines) / cd_span
        print("cangen -g 0 flood (random DiscSpeed payloads): ecu took %.0f frames/s "
              "(kernel drops %s), plain candump -L %.0f frames/s (dropped %d); ratio %.2f"
              % (er, s.get("hal_rx_kernel_drops"), cr, cd_drops, er / cr if cr else 0.0))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
