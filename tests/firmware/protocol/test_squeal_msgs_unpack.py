#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""The firmware's unpackers against canmatrix, on random frames.

unpack_random (tests/firmware/protocol/unpack_random.c) feeds thousands of random
frames of every input message (and of the outputs SquealStatus, SquealDetail,
SquealDetail2) through the firmware's unpack functions and
prints what they returned. Here canmatrix decodes the same bytes from the
DBC, independently:
  - a frame of the message's DLC whose alive counter is not 15 unpacks
    (SQ_OK), and every DBC signal of the message is printed with exactly
    canmatrix's raw value (E2E CRC and counter included);
  - a frame of any other DLC, or with counter 15 (reserved by E2E P01), is
    refused with SQ_EBADMSG;
  - the descriptor-driven reader msg_sig_get_raw() (host tools' decode)
    reads every signal of every frame of the right DLC as canmatrix does;
  - every message of the table appears, each with both outcomes.
A new message: one row in unpack_random.c (its DBC name and adapter).
Its DBC: DBC_FOR below when it is not squeal.dbc.
"""
import os
import sys
# tests/ of this checkout, and the folders its helper modules live in
_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, d) for d in ("support", os.path.join("support", "reference"), "host-sim", "tools")]

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from dbc_common import DBC, ROOT, Results, load_dbc  # noqa: E402
import subprocess  # noqa: E402

UNPACK = os.environ.get("UNPACK_RANDOM",
                        os.path.join(ROOT, "build", "test", "tests", "firmware", "protocol", "unpack_random"))
FRAMES_PER_MESSAGE = 3000
SEED = 20261129
SQ_OK = 0
SQ_EBADMSG = -74
# message name -> DBC file, for input messages not in squeal.dbc
DBC_FOR = {}


def parse(line):
    f = line.split()
    name, dlc, data = f[0], int(f[1]), bytes.fromhex(f[2])
    vals = {}
    generic = {}
    rc = None
    for item in f[3:]:
        k, v = item.split("=", 1)
        if k == "rc":
            rc = int(v)
        elif k.startswith("@"):
            generic[k[1:]] = int(v)
        else:
            vals[k] = int(v)
    return name, dlc, data, vals, rc, generic


def main():
    r = Results()
    out = subprocess.run([UNPACK, str(FRAMES_PER_MESSAGE), str(SEED)], check=True,
                         stdout=subprocess.PIPE, universal_newlines=True).stdout
    dbs = {}
    frames = {}
    seen = {}
    mismatches = 0
    for line in out.splitlines():
        name, dlc, data, vals, rc, generic = parse(line)
        path = DBC_FOR.get(name, DBC)
        if path not in dbs:
            dbs[path] = load_dbc(path)
        if name not in frames:
            fr = dbs[path].frame_by_name(name)
            if not r.check(fr is not None, "%s is a message of %s" % (name, path)):
                return r.finish()
            frames[name] = fr
        fr = frames[name]
        counter_sig = fr.signal_by_name(name + "_Counter")
        payload = bytearray(data[:dlc])
        good_dlc = dlc == fr.size
        counter = None
        if good_dlc:
            decoded = fr.decode(bytearray(data[:fr.size]))
            counter = decoded[counter_sig.name].raw_value if counter_sig else None
        want_ok = good_dlc and counter != 15
        key = (name, "ok" if want_ok else "refused")
        seen[key] = seen.get(key, 0) + 1
        if want_ok:
            want = {s: int(d.raw_value) for s, d in decoded.items()}
            ok = rc == SQ_OK and vals == want
            what = "unpacks to canmatrix's raw values %s, got %s rc=%s" % (want, vals, rc)
        else:
            ok = rc == SQ_EBADMSG and not vals
            what = "refused (SQ_EBADMSG): dlc %d, counter %s; got rc=%s %s" % (dlc, counter, rc, vals)
        # msg_sig_get_raw: every signal of a frame of the right DLC, counter
        # 15 included (it reads signals, it does not judge the frame)
        want_generic = {s: int(d.raw_value) for s, d in decoded.items()} if good_dlc else {}
        if generic != want_generic:
            ok = False
            what += "; msg_sig_get_raw read %s, canmatrix %s" % (generic, want_generic)
        if not ok:
            mismatches += 1
            if mismatches <= 20:
                r.check(False, "%s %s: %s" % (name, payload.hex().upper() or "(empty)", what))
    r.check(mismatches == 0, "%d random frames: %d differ from canmatrix" %
            (len(out.splitlines()), mismatches))
    for name in sorted(frames):
        print("%s: %d frames unpacked, %d refused" % (name, seen.get((name, "ok"), 0),
                                                      seen.get((name, "refused"), 0)))
        for outcome in ("ok", "refused"):
            n = seen.get((name, outcome), 0)
            r.check(n >= 100, "%s: %d frames %s" % (name, n, outcome))
    r.check({"DiscSpeed", "PadForce"} <= set(frames), "input messages checked: %s" % sorted(frames))
    r.finish()


if __name__ == "__main__":
    main()
