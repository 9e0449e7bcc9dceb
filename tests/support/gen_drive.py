#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""A braking drive in a vehicle's layout, as a candump -L log, written with
canmatrix (Frame.encode) from the fixture DBC, independently of the firmware:

  - the wheel speeds and the pressures / torques of the corners follow one
    braking run (braking_run: v0 at the pad and pad force N), turned into the vehicle's signal values with the inverse of
    the conversions of docs/vehicle.md, a per-corner scale on top;
  - each message at its period (10, 20 or 24 ms) with a little jitter;
    multiplexed pages take turns;
  - the logger drops frames (about 3 %, sometimes two in a row; the sender's
    counter still advanced);
  - other traffic (other messages of the DBC and foreign identifiers);
  - the layout's protection: alive counter, E2E P02 (CRC-8H2F with the
    DataIDList indexed by the counter) or P01; maker checksum bits filled;
    E2E P05 blocks (layout "p05": message -> [(start byte, CRC offset byte,
    end byte or None, Data ID)]: CRC-16/CCITT-FALSE over the block's bytes
    but the CRC's, then the Data ID low byte first; 8-bit counter in the
    byte after the CRC);
  - CAN FD messages (the DBC's VFrameFormat, or a DLC above 8) as candump FD
    lines `ID##F<data>`, F the layout's flags digit (fd_flags: FDF 4 | BRS 1
    as newer can-utils write it, or BRS 1 alone as older ones do);
  - optionally the timestamps jump back 2.8 s (a logger restart).

    gen_drive.py LAYOUT OUT.log [--seed N] [--jump] [--unseen]
"""
import argparse
import binascii
import os
import random
import sys
# tests/ of this checkout, and the folders its helper modules live in
_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, d) for d in ("support", os.path.join("support", "reference"), "host-sim", "tools")]

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import vehref  # noqa: E402

BRAKING_RUN_S = 9.5


# (t [s], v0 at the pad [m/s], pad force [N]) of the reference corner,
# linear in between: rolling force-free, a stop from 12 m/s at 9 kN that slows
# down through the bistable and unstable speeds (each several hundred ms long,
# so the states can be compared away from their borders), standstill, then
# pulling away at 3 kN through the same states backwards. The ramps stay
# inside the plausible steps that vehicle_calib.py writes.
PROFILE = [(0.0, 12.0, 0.0), (0.5, 12.0, 0.0), (0.6, 12.0, 9000.0), (3.6, 2.0, 9000.0),
           (6.6, 0.6, 9000.0), (7.0, 0.0, 9000.0), (7.4, 0.0, 9000.0), (7.6, 0.0, 3000.0),
           (9.5, 3.0, 3000.0)]


def braking_run(t):
    """(v0 [m/s], force [N]) of PROFILE at drive time t [s]."""
    for (t0, v0, n0), (t1, v1, n1) in zip(PROFILE, PROFILE[1:]):
        if t < t1:
            w = max(0.0, (t - t0) / (t1 - t0))
            return v0 + (v1 - v0) * w, n0 + (n1 - n0) * w
    return PROFILE[-1][1], PROFILE[-1][2]


class FdData(bytes):
    """The data of a CAN FD frame (written as a `##` line), with its flags digit."""
    flags = 0x5


def fd_message(frame):
    """The DBC message is sent as CAN FD frames (VFrameFormat, or a DLC above 8)."""
    return bool(frame.is_fd) or frame.size > 8


def is_message(frame, data):
    """A logged frame of the message's identifier is that message: its
    format (FD or classic) and at least its DLC."""
    return isinstance(data, FdData) == fd_message(frame) and len(data) >= frame.size


def fd_data(data, flags):
    d = FdData(data)
    d.flags = flags
    return d


def p05_fill(data, block, counter):
    """E2E P05 on the block (start byte, CRC offset byte, end byte or None for
    the frame's end, Data ID): the counter in the byte after the CRC, then the
    CRC (binascii.crc_hqx is CRC-16/CCITT-FALSE from init 0xFFFF) over the
    block's bytes but the CRC's and the Data ID low byte first, stored
    little-endian."""
    start, off, end, data_id = block
    end = len(data) if end is None else end
    data[off + 2] = counter & 0xFF
    covered = bytes(data[start:off]) + bytes(data[off + 2:end]) + bytes([data_id & 0xFF, data_id >> 8])
    crc = binascii.crc_hqx(covered, 0xFFFF)
    data[off:off + 2] = bytes([crc & 0xFF, crc >> 8])


T0 = 1700000000.0
JUMP_AT_S = 4.0
JUMP_BACK_S = 2.8


def corner_params(opts):
    """piston area, efficiency, axle factor of a corner's option list."""
    d = dict(zip(opts[::2], opts[1::2]))
    return (float(d["--piston-area-mm2"]) if "--piston-area-mm2" in d else None,
            float(d.get("--efficiency", 1.0)), float(d.get("--axle-factor", 1.0)))


class Drive:
    def __init__(self, layout, seed=1, jump=False, drop_p=0.03, duration_s=BRAKING_RUN_S):
        self.layout = layout
        self.db = vehref.load_dbc(vehref.layout_dbc(layout))
        self.rng = random.Random(seed)
        self.jump = jump
        self.drop_p = drop_p
        self.duration_s = duration_s
        # message -> {signal: function(t) -> physical}
        self.feeds = {}
        for pos, spd, frc, opts in layout["corners"]:
            area, eta, k = corner_params(opts)
            sscale = layout.get("speed_scale", {}).get(pos, 1.0)
            msg, sig = spd.split(".")
            unit = self.db.frame_by_name(msg).signal_by_name(sig).unit
            self.feeds.setdefault(msg, {})[sig] = (
                lambda t, u=unit, s=sscale: vehref.speed_value(braking_run(t)[0] * s, u))
            msg, sig = frc.split(".")
            if sig in self.feeds.get(msg, {}):
                continue  # one pressure feeds several corners: the first one sets it
            unit = self.db.frame_by_name(msg).signal_by_name(sig).unit
            pscale = layout.get("pressure_scale", {}).get(pos, 1.0)
            tscale = layout.get("torque_scale", {}).get(pos, 1.0)

            def force(t, u=unit, area=area, eta=eta, k=k, s=sscale, ps=pscale, ts=tscale):
                v0, n = braking_run(t)
                return vehref.force_value(n * ps * ts, u, v0 * s, area, eta, k)
            self.feeds.setdefault(msg, {})[sig] = force

    def raw(self, sig, phys):
        lo, hi = sig.calculate_raw_range()
        na = [int(k) for k in sig.values]
        r = int(round((phys - float(sig.offset)) / float(sig.factor)))
        r = max(lo, min(hi, r))
        while r in na:
            r -= 1
        return r

    def encode(self, frame, seq, t):
        """One frame of `frame` (sequence number seq) at drive time t."""
        values = {}
        sel = next((s for s in frame.signals if s.is_multiplexer), None)
        page = None
        if sel is not None:
            pages = sorted({s.mux_val for s in frame.signals if s.mux_val is not None})
            page = pages[seq % len(pages)]
            values[sel.name] = page
        feeds = self.feeds.get(frame.name, {})
        for s in frame.signals:
            if s.is_multiplexer or (s.mux_val is not None and s.mux_val != page):
                continue
            if s.name in feeds:
                values[s.name] = self.raw(s, feeds[s.name](t))
            elif s.name in self.layout.get("qualifier_ok", {}):
                values[s.name] = self.layout["qualifier_ok"][s.name]
            elif s.name in counter_names(self.layout, frame.name):
                values[s.name] = seq % (1 << s.size)
            else:
                values[s.name] = 0
        # maker checksums the monitor does not check: a byte sum, as a sender fills them
        chk = [s for s in frame.signals if "CHECKSUM" in s.name.upper() and s.name in values]
        if chk:
            total = sum(frame.encode(values))
            for s in chk:
                values[s.name] = total % (1 << s.size)
        data = bytearray(frame.encode(values))
        prot = self.layout["protection"]
        if prot == "p02":
            ctr = seq % 16
            data[1] = (data[1] & 0xF0) | ctr
            lst = [int(x, 0) for x in frame.attributes["E2E_DataIDList"].replace(",", " ").split()]
            data[0] = vehref.p02_crc(data, lst, ctr)
        elif prot == "p01":
            ctr = seq % 15
            data[1] = (data[1] & 0xF0) | ctr
            data[0] = vehref.p01_crc(data, int(frame.attributes["E2E_DataID"]))
        for block in self.layout.get("p05", {}).get(frame.name, ()):
            p05_fill(data, block, seq)
        if fd_message(frame):
            return fd_data(data, self.layout.get("fd_flags", FdData.flags))
        return bytes(data)

    def frames(self):
        """[(log time, id, extended, data)] in time order."""
        out = []
        for idx, (name, period) in enumerate(sorted(self.layout["period_s"].items())):
            frame = self.db.frame_by_name(name)
            seq, t, skip, lost = 0, 0.003 * idx, 0, False
            while t < self.duration_s:
                data = self.encode(frame, seq, t)
                if skip:
                    skip -= 1
                elif not lost and self.rng.random() < self.drop_p:
                    skip = 1 if self.rng.random() < 0.3 else 0   # one or two frames in a row
                    lost = True
                else:
                    lost = False
                    tj = t + self.rng.uniform(-0.0003, 0.0003)
                    out.append((max(0.0, tj), frame.arbitration_id.id, bool(frame.arbitration_id.extended), data))
                seq += 1
                t += period
        for j, other in enumerate(self.layout.get("other", [])):
            t = 0.0011 * (j + 1)
            while t < self.duration_s:
                if isinstance(other, str):
                    f = self.db.frame_by_name(other)
                    cid, ext, n = f.arbitration_id.id, bool(f.arbitration_id.extended), f.size
                else:
                    cid, ext, n = other, other > 0x7FF, self.rng.randint(0, 8)
                out.append((t, cid, ext, bytes(self.rng.randrange(256) for _ in range(n))))
                t += 0.05
        out.sort(key=lambda f: f[0])
        if self.jump:
            out = [(t - JUMP_BACK_S if t >= JUMP_AT_S else t, i, e, d) for t, i, e, d in out]
        return [(T0 + t, i, e, d) for t, i, e, d in out]


def counter_names(layout, msg):
    """The counter signals of a message (one name, or a list for several blocks)."""
    c = layout.get("counters", {}).get(msg, ())
    return (c,) if isinstance(c, str) else tuple(c)


def candump_line(t, cid, ext, data, iface="can0"):
    us = int(round(t * 1e6))
    sep = "##%X" % data.flags if isinstance(data, FdData) else "#"
    return "(%010d.%06d) %s %s%s%s\n" % (us // 1000000, us % 1000000, iface,
                                         ("%08X" if ext else "%03X") % cid, sep, data.hex().upper())


def write_log(path, frames):
    with open(path, "w") as f:
        for fr in frames:
            f.write(candump_line(*fr))


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("layout")
    ap.add_argument("out")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--jump", action="store_true")
    a = ap.parse_args(argv)
    layout = vehref.UNSEEN if a.layout == "unseen" else vehref.LAYOUTS[a.layout]
    write_log(a.out, Drive(layout, a.seed, a.jump).frames())
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
