#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Input logs for the replay tests and the benchmark, written independently
of the firmware: DiscSpeed / PadForce frames with E2E P01 protection computed
here (bitwise CRC-8, polynomial 0x1D, start 0, no final XOR, over the DBC's
E2E_DataID low byte, high byte, then bytes 1..3; alive counter 0..14), the
identifiers, data IDs and scalings read from squeal.dbc with canmatrix.

    gen_inputs.py --frames N --out FILE      fast plain writer (benchmark):
                                             N frames, both inputs every 10 ms,
                                             a repeating braking cycle
As a module: braking_run(), protect(), InputEncoder, write_python_can().
"""
import argparse
import os
import sys
import warnings
# tests/ of this checkout, and the folders its helper modules live in
_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, d) for d in ("support", os.path.join("support", "reference"), "host-sim", "tools")]

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(_TESTS)
DBC = os.path.join(ROOT, "firmware", "protocol", "squeal.dbc")

PAD_RADIUS_M = 0.12  # calibration default r_p (docs/model.md section 8)


def crc8_p01(data):
    """CRC-8, poly 0x1D, MSB first, start 0x00, no final XOR (bitwise)."""
    crc = 0
    for b in data:
        crc ^= b
        for _ in range(8):
            crc = ((crc << 1) ^ 0x1D) & 0xFF if crc & 0x80 else (crc << 1) & 0xFF
    return crc


# the same CRC one byte at a time (table from the bitwise definition)
CRC8_TABLE = [crc8_p01([i]) for i in range(256)]


def crc8_p01_fast(data):
    crc = 0
    for b in data:
        crc = CRC8_TABLE[crc ^ b]
    return crc


def load_dbc():
    import canmatrix.formats
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        dbs = canmatrix.formats.loadp(DBC)
    return list(dbs.values())[0]


class InputEncoder:
    """Raw frames of DiscSpeed and PadForce, from the DBC."""

    def __init__(self, db=None):
        db = db or load_dbc()
        self.speed = db.frame_by_name("DiscSpeed")
        self.force = db.frame_by_name("PadForce")
        self.speed_id = self.speed.arbitration_id.id
        self.force_id = self.force.arbitration_id.id
        self.speed_did = int(self.speed.attributes["E2E_DataID"])
        self.force_did = int(self.force.attributes["E2E_DataID"])
        self.speed_factor = float(self.speed.signal_by_name("DiscSpeed_radps").factor)
        self.force_factor = float(self.force.signal_by_name("PadForce_N").factor)
        self.counters = {self.speed_id: 0, self.force_id: 0}

    def speed_raw(self, v0_mps):
        omega = v0_mps / PAD_RADIUS_M
        return max(0, min(65534, int(round(omega / self.speed_factor))))

    def force_raw(self, force_n):
        return max(0, min(65534, int(round(force_n / self.force_factor))))

    def frame(self, can_id, raw, counter=None):
        """4 bytes: CRC, counter, raw value little-endian; counter advances."""
        did = self.speed_did if can_id == self.speed_id else self.force_did
        if counter is None:
            counter = self.counters[can_id]
            self.counters[can_id] = (counter + 1) % 15
        payload = bytes([counter & 0x0F, raw & 0xFF, (raw >> 8) & 0xFF])
        crc = crc8_p01_fast(bytes([did & 0xFF, did >> 8]) + payload)
        return bytes([crc]) + payload


def braking_run(t):
    """(v0 at the pad radius [m/s], pad force [N]) of the test's braking run
    at time t [s]: standing force-free, a stop from 12 m/s at 9 kN, a restart
    and a slower stop at 3 kN. Ramps stay inside the monitor's rate limits."""
    def lerp(t, t0, t1, a, b):
        return a + (b - a) * (t - t0) / (t1 - t0)
    if t < 0.5:
        return 12.0, 0.0
    if t < 0.6:
        return 12.0, lerp(t, 0.5, 0.6, 0.0, 9000.0)
    if t < 5.6:
        return max(0.0, lerp(t, 0.6, 5.6, 12.0, 0.0)), 9000.0
    if t < 6.0:
        return 0.0, 9000.0
    if t < 6.2:
        return 0.0, lerp(t, 6.0, 6.2, 9000.0, 3000.0)
    if t < 7.2:
        return lerp(t, 6.2, 7.2, 0.0, 8.0), 3000.0
    if t < 9.2:
        return lerp(t, 7.2, 9.2, 8.0, 0.5), 3000.0
    return 0.5, 3000.0


BRAKING_RUN_S = 9.5


def braking_frames(enc, t0=1700000000.0, duration=BRAKING_RUN_S):
    """[(time, id, data, v0, force)] every 10 ms: DiscSpeed at k*10 ms,
    PadForce 5 ms later (two senders)."""
    out = []
    k = 0
    while k * 0.01 < duration - 1e-9:
        t = k * 0.01
        v0, force = braking_run(t)
        out.append((t0 + t, enc.speed_id, enc.frame(enc.speed_id, enc.speed_raw(v0)), v0, force))
        v0, force = braking_run(t + 0.005)
        out.append((t0 + t + 0.005, enc.force_id, enc.frame(enc.force_id, enc.force_raw(force)), v0, force))
        k += 1
    return out


def write_python_can(path, frames, channel="can0"):
    """Write frames [(t, id, data, ...)] with python-can's candump writer."""
    import can
    w = can.io.CanutilsLogWriter(path, channel=channel)
    for fr in frames:
        w.on_message_received(can.Message(timestamp=fr[0], arbitration_id=fr[1],
                                          is_extended_id=False, data=fr[2], channel=channel))
    w.stop()


def cycle_point(t):
    """Benchmark profile: a 20 s cycle, braking from 15 m/s to standstill in
    12 s at 2..10 kN (the force changes per cycle), then 8 s rolling."""
    n = int(t // 20.0)
    tc = t - 20.0 * n
    force = 2000.0 + 1000.0 * (n % 9)
    if tc < 12.0:
        return 15.0 * (1.0 - tc / 12.0), force
    return 15.0 * (tc - 12.0) / 8.0, 0.0


def write_fast(path, n_frames, t0=1700000000):
    """The benchmark log, plain string writing (python-can's writer is the
    slow part otherwise); identical format."""
    enc = InputEncoder()
    hexs = ["%02X" % i for i in range(256)]
    with open(path, "w") as f:
        lines = []
        for i in range(n_frames):
            k, which = divmod(i, 2)
            us = k * 10000 + which * 5000
            v0, force = cycle_point(us / 1e6)
            if which == 0:
                cid, raw = enc.speed_id, enc.speed_raw(v0)
            else:
                cid, raw = enc.force_id, enc.force_raw(force)
            data = enc.frame(cid, raw)
            lines.append("(%010d.%06d) can0 %03X#%s\n" % (t0 + us // 1000000, us % 1000000, cid,
                                                         "".join(hexs[b] for b in data)))
            if len(lines) >= 10000:
                f.write("".join(lines))
                lines = []
        f.write("".join(lines))


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--frames", type=int, required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args(argv)
    write_fast(a.out, a.frames)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
