#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""`squeal-sim replay --summary-json` against independent references:

  - every document parses with Python's json module (strict: no NaN, no raw
    control characters), also for log names with quotes, backslashes,
    control characters and bytes that are not UTF-8;
  - the episodes, the time per state per corner and the (v0, force)
    occupancy (float and fixed builds) equal a recomputation here from the ECU's output frames,
    decoded with canmatrix from squeal.dbc (values compared as exact
    decimals); for four-corner streams that today's firmware cannot send,
    through tests/host-sim/summary_driver (the summary module alone);
  - the counts equal the text summary's; --no-output writes no frames and
    the same JSON; '--summary-json -' needs --no-output;
  - segments: a log whose clock jumps back 2.8 s (a logger restart) and
    then 0.4 s: the count equals the text summary's, the rebase point is the
    line, jump and time the log was built with (and replay's message).
Prints "RESULT: N passed, M failed".
"""
import json
import os
import random
import re
import subprocess
import sys
import tempfile
from decimal import Decimal
# tests/ of this checkout, and the folders its helper modules live in
_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, d) for d in ("support", os.path.join("support", "reference"), "host-sim", "tools")]

ROOT = os.path.dirname(_TESTS)
import dbc_common  # noqa: E402
from sim_cli import SAN_SIMS  # noqa: E402

SIM, SIM_FIXED = SAN_SIMS["float"], SAN_SIMS["fixed"]
DRIVER = os.path.join(ROOT, "build", "test", "tests", "host-sim", "summary_driver")
R = dbc_common.Results()
DB = dbc_common.load_dbc()
MSG = {name: DB.frame_by_name(name) for name in ("SquealStatus", "SquealDetail", "SquealDetail2")}
CORNERS = ("FL", "FR", "RL", "RR")
STATES = ("stable", "bistable", "unstable", "not_sliding", "fault")
LINE = re.compile(r"^\((\d+)\.(\d{6})\) \S+ ([0-9A-F]{3})#([0-9A-F]*)$")
V0_BIN, V0_BINS, F_BIN, F_BINS = Decimal("0.2"), 80, Decimal(500), 64


def load_strict(text):
    def bad(c):
        raise ValueError("non-standard constant " + c)
    return json.loads(text, parse_float=Decimal, parse_constant=bad)


def read_frames(text):
    out = []
    for line in text.splitlines():
        m = LINE.match(line)
        if m:
            out.append((int(m.group(1)) * 1000000 + int(m.group(2)), int(m.group(3), 16),
                        bytes.fromhex(m.group(4))))
    return out


def decode(name, data):
    """{signal: (raw, Decimal phys or None when 'not_available')}, or None
    for a frame of the wrong length."""
    msg = MSG[name]
    if len(data) != msg.size:
        return None
    out = {}
    for sname, dec in msg.decode(data).items():
        sig = msg.signal_by_name(sname)
        na = sig.values.get(dec.raw_value) == "not_available"
        out[sname] = None if na else Decimal(dec.phys_value)
    return out


def recompute(frames, end_us, base=(0x300, 0x301, 0x303)):
    """Episodes, time per state and occupancy per corner, from the frames."""
    ids = {}
    for k in range(4):
        for name, b in zip(("SquealStatus", "SquealDetail", "SquealDetail2"), base):
            ids[b + 0x10 * k] = (k, name)
    cs = {}
    episodes = []

    def account(c, t):
        if c["seen"] and t > c["last"]:
            dt = t - c["last"]
            c["time"][c["state"]] += dt
            if c["v0"] is not None and c["force"] is not None:
                key = (min(int(c["v0"] / V0_BIN), V0_BINS - 1),
                       min(int(c["force"] / F_BIN), F_BINS - 1), c["state"])
                c["cells"][key] = c["cells"].get(key, 0) + dt
            c["last"] = t

    def close(k, c, t):
        e = c["ep"]
        episodes.append(dict(corner=CORNERS[k], state=e["state"], start_us=e["start"], end_us=t,
                             warning_level=e["warn"], v0_min_mps=min(e["v0"], default=None),
                             v0_max_mps=max(e["v0"], default=None),
                             force_min_n=min(e["f"], default=None),
                             force_max_n=max(e["f"], default=None),
                             min_hopf_margin_mps=min(e["m"], default=None)))
        c["ep"] = None

    for t, cid, data in frames:
        if cid not in ids:
            continue
        k, name = ids[cid]
        c = cs.setdefault(k, dict(seen=False, last=0, first=0, state="fault", v0=None,
                                  force=None, ep=None, time={s: 0 for s in STATES}, cells={}))
        account(c, t)
        sig = decode(name, data)
        if name == "SquealStatus":
            if sig is None:
                continue
            raw_state = int(sig["SquealState"])
            st = STATES[raw_state] if raw_state < 4 else "fault"
            if not c["seen"]:
                c.update(seen=True, first=t, last=t)
            c["state"] = st
            if c["ep"] is not None and c["ep"]["state"] != st:
                close(k, c, t)
            if c["ep"] is None:
                c["ep"] = dict(state=st, start=t, warn=0, v0=[], f=[], m=[])
            c["ep"]["warn"] = max(c["ep"]["warn"], int(sig["WarningLevel"]))
            if sig["HopfMargin_mps"] is not None:
                c["ep"]["m"].append(sig["HopfMargin_mps"])
        elif name == "SquealDetail":
            c["v0"] = None if sig is None else sig["V0_mps"]
            if c["v0"] is not None and c["ep"] is not None:
                c["ep"]["v0"].append(c["v0"])
        else:
            c["force"] = None if sig is None else sig["Force_N"]
            if c["force"] is not None and c["ep"] is not None:
                c["ep"]["f"].append(c["force"])
    for k in sorted(cs):
        account(cs[k], end_us)
        if cs[k]["ep"] is not None:
            close(k, cs[k], end_us)
    return episodes, cs


def us(dec):
    return int((dec * 1000000).to_integral_value())


def compare(doc, frames, end_us, what, base=(0x300, 0x301, 0x303)):
    episodes, cs = recompute(frames, end_us, base)
    got = []
    for e in doc["episodes"]:
        e = dict(e)
        got.append(dict(e, start_us=us(e.pop("start_s")), end_us=us(e.pop("end_s"))))
    # the C writes an episode when it ends: compare as sets per corner, in order
    key = lambda e: (e["corner"], e["start_us"])  # noqa: E731
    R.check(sorted(got, key=key) == sorted(episodes, key=key),
            "%s: %d episodes equal the recomputation from canmatrix-decoded frames (got %d)"
            % (what, len(episodes), len(got)))
    if sorted(got, key=key) != sorted(episodes, key=key):
        for a, b in zip(sorted(got, key=key), sorted(episodes, key=key)):
            if a != b:
                print("  C:  ", a, "\n  ref:", b)
                break
    corners = {c["corner"]: c for c in doc["corners"]}
    R.check(sorted(corners) == sorted(CORNERS[k] for k in cs), "%s: corners %s" % (what, sorted(corners)))
    for k, c in cs.items():
        jc = corners.get(CORNERS[k])
        if jc is None:
            continue
        R.check({s: us(v) for s, v in jc["state_time_s"].items()} == c["time"],
                "%s %s: time per state" % (what, CORNERS[k]))
        cells = {(i, j, s): us(v) for i, j, s, v in jc["cells"]}
        R.check(cells == c["cells"], "%s %s: %d occupancy cells" % (what, CORNERS[k], len(c["cells"])))
    return episodes


def read_log_ifaces(path):
    """(line, interface) of every frame line of a candump -L log."""
    out = []
    with open(path) as f:
        for ln in f:
            if ln.startswith("("):
                out.append((ln, ln.split()[1]))
    return out


def text_summary(stderr):
    """The text summary's numbers: {key: [numbers...]} and state times."""
    out = {}
    for line in stderr.splitlines():
        m = re.match(r"^\s+(\w+)\s+(.*)$", line)
        if m:
            out[m.group(1)] = m.group(2)
    return out


def nums(text):
    return [Decimal(x) for x in re.findall(r"(?<![\w.])-?\d+(?:\.\d+)?", text)]


def run(args, **kw):
    return subprocess.run([SIM] + args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, **kw)


def check_fixed(log, name):
    """The fixed-point build's document against the same recomputation."""
    p = subprocess.run([SIM_FIXED, "replay", log, "--summary-json", "/dev/stderr"],
                       stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    text = p.stderr.decode()
    doc = load_strict(text[:text.index("replay summary:")])
    compare(doc, read_frames(p.stdout.decode()), us(doc["t0_s"] + doc["virtual_time_s"]),
            name + " (fixed build)")


def check_log(tmp, name, plant_args):
    log = os.path.join(tmp, name + ".log")
    subprocess.run([SIM, "plant", "--log", log, "--quiet"] + plant_args, check=True)
    check_fixed(log, name)
    js = os.path.join(tmp, name + ".json")
    p = run(["replay", log, "--summary-json", js])
    R.check(p.returncode == 0, "%s: replay exit 0" % name)
    doc = load_strict(open(js, encoding="utf-8").read())
    R.check(doc["format"] == "squeal-replay-summary" and doc["version"] == 1, name + ": format")
    frames = read_frames(p.stdout.decode())
    end_us = us(doc["t0_s"] + doc["virtual_time_s"])
    t = text_summary(p.stderr.decode())
    vt = nums(t["virtual_time_s"])
    R.check(us(vt[0]) + us(vt[1]) == end_us, name + ": end time equals the text summary's")
    eps = compare(doc, frames, end_us, name)
    # the counts of the text summary
    R.check(nums(t["frames_read"])[0] == doc["frames_read"], name + ": frames_read")
    R.check(nums(t["frames_used"]) == [doc["frames_used"][k] for k in ("total", "DiscSpeed", "PadForce")],
            name + ": frames_used")
    for key in ("e2e_wrong_crc", "e2e_wrong_sequence", "repeated", "implausible", "bad_dlc"):
        R.check(nums(t[key]) == [doc["rejected"][key][k] for k in ("total", "DiscSpeed", "PadForce")],
                "%s: rejected.%s" % (name, key))
    for key in ("e2e_frames_lost", "stale_events"):
        R.check(nums(t[key]) == [doc[key][k] for k in ("total", "DiscSpeed", "PadForce")],
                "%s: %s" % (name, key))
    R.check(nums(t["malformed_lines"])[0] == doc["rejected"]["malformed_lines"], name + ": malformed")
    st = dict(re.findall(r"(\w+)=([\d.]+)", t["state_time_s"]))
    R.check({k: Decimal(v) for k, v in st.items()} == doc["state_time_s"], name + ": state_time_s")
    wr = dict(re.findall(r"(\w+)=(\d+)", t["warnings_raised"]))
    R.check(all(int(wr[k]) == doc["warnings_raised"][k] for k in ("advisory", "warning", "critical")),
            name + ": warnings_raised")
    R.check(nums(t["state_changes"])[0] == doc["state_changes"]["total"], name + ": state_changes")
    R.check(nums(t["output_frames"])[0] == doc["output_frames"]["total"] == len(frames),
            name + ": output_frames")
    # the keys added for the corners' inputs agree with the older ones (one
    # legacy corner: its inputs are DiscSpeed and PadForce)
    ic = doc["inputs_by_corner"]
    R.check(len(ic) == 1 and ic[0]["corner"] == "FL" and
            ic[0]["state_time_s"] == doc["state_time_s"] and
            ic[0]["final_state"] == doc["final_state"] and
            [ic[0]["speed"]["label"], ic[0]["force"]["label"]] == ["DiscSpeed", "PadForce"] and
            ic[0]["speed"]["used"] == doc["frames_used"]["DiscSpeed"] and
            ic[0]["force"]["used"] == doc["frames_used"]["PadForce"] and
            ic[0]["speed"]["rejected"]["crc"] == doc["rejected"]["e2e_wrong_crc"]["DiscSpeed"] and
            ic[0]["force"]["rejected"]["crc"] == doc["rejected"]["e2e_wrong_crc"]["PadForce"] and
            ic[0]["speed"]["rejected"]["dlc"] == doc["rejected"]["bad_dlc"]["DiscSpeed"] and
            ic[0]["speed"]["stale_events"] == doc["stale_events"]["DiscSpeed"],
            name + ": inputs_by_corner agrees with state_time_s, frames_used and rejected")
    R.check(doc["buses"]["interfaces"] == sorted({f[1] for f in read_log_ifaces(log)}) and
            doc["reordered"]["frames"] == 0 and doc["time_backwards"] == 0,
            name + ": buses lists the log's interface, nothing reordered in a plant log")
    # --no-output: no frames, the same document
    p2 = run(["replay", log, "--no-output", "--summary-json", "-"])
    doc2 = load_strict(p2.stdout.decode())
    R.check(p2.returncode == 0 and doc2.pop("output_written") is False and
            doc.pop("output_written") is True and doc2 == doc,
            name + ": --no-output --summary-json - gives the same document and no frames")
    return eps


def check_segments(tmp):
    """A braking run, the same run again from 2.8 s before its end (the
    logger's clock restarted), then three frames 0.4 s back (jitter, not a
    restart)."""
    one = os.path.join(tmp, "seg-one.log")
    subprocess.run([SIM, "plant", "--log", one, "--quiet", "--scenario", "stop"], check=True)
    lines = open(one).read().splitlines()
    stamp = re.compile(r"^\((\d+)\.(\d{6})\)(.*)$")

    def shifted(line, d_us):
        m = stamp.match(line)
        t = int(m.group(1)) * 1000000 + int(m.group(2)) + d_us
        return "(%010d.%06d)%s" % (t // 1000000, t % 1000000, m.group(3))
    last = stamp.match(lines[-1])
    last_us = int(last.group(1)) * 1000000 + int(last.group(2))
    two = lines + [shifted(x, last_us - 2800000) for x in lines]
    jitter = [shifted(x, -400000) for x in two[-3:]]
    log = os.path.join(tmp, "segments.log")
    with open(log, "w") as f:
        f.write("\n".join(two + jitter) + "\n")
    p = run(["replay", log, "--no-output", "--summary-json", "-"])
    doc = load_strict(p.stdout.decode())
    err = p.stderr.decode()
    t = text_summary(err)
    seg = doc["segments"]
    text = re.match(r"(\d+) \(new after a jump back of more than 1 s: (\d+)\)$", t["segments"])
    R.check(p.returncode == 0 and text is not None and
            [int(text.group(1)), int(text.group(2))] == [seg["total"], seg["new"]] == [2, 1],
            "segments: total and new %s = the text summary's %s" % ([seg["total"], seg["new"]],
                                                                    t["segments"]))
    R.check(seg["rebase_points"] == [{"segment": 2, "line": len(lines) + 1, "back_s": Decimal("2.8"),
                                      "at_s": Decimal(last_us) / 1000000}] and
            seg["points_not_listed"] == 0,
            "segments: rebase point at line %d, 2.8 s back, at %d us: %s" %
            (len(lines) + 1, last_us, seg["rebase_points"]))
    msg = re.findall(r":(\d+): timestamp goes back by ([\d.]+) s: new segment (\d+)", err)
    R.check(msg == [(str(p["line"]), "%.6f" % p["back_s"], str(p["segment"])) for p in seg["rebase_points"]],
            "segments: the rebase points are replay's messages %s" % msg)
    R.check(doc["time_backwards"] == 0 == nums(t["time_backwards"])[0] and
            doc["reordered"]["frames"] == 3 == nums(t["reordered"])[0] and
            doc["reordered"]["blocks"] == 0,
            "segments: the 0.4 s jumps back are put back in order (reordered 3), not segments")
    empty = os.path.join(tmp, "seg-empty.log")
    open(empty, "w").close()
    p = run(["replay", empty, "--no-output", "--summary-json", "-"])
    doc = load_strict(p.stdout.decode())
    R.check(p.returncode == 1 and p.stderr.decode() == "%s: no CAN frame in 0 lines\n" % empty,
            "segments: an empty log is one line and exit 1")
    R.check(doc["segments"] == {"total": 0, "new": 0, "rebase_points": [], "points_not_listed": 0},
            "segments: none in an empty log")


def four_corners(tmp):
    """FL, FR and RR (no RL) through the summary module alone (canmatrix's
    encode takes raw values: NA values included on purpose)."""
    rnd = random.Random(13)
    lines = []
    t = 1000000
    state = {k: 0 for k in (0, 1, 3)}
    for step in range(600):
        t += 10000
        for k in (0, 1, 3):
            if rnd.random() < 0.05:
                state[k] = rnd.choice([0, 1, 2, 3, 15, 7])
            st = MSG["SquealStatus"].encode({
                "SquealStatus_CRC": 0, "SquealStatus_Counter": step % 15, "SquealState": state[k],
                "WarningLevel": rnd.randint(0, 3), "BasinRatio": 5000,
                "HopfMargin_mps": rnd.choice([-32768, -125, 50, 307])})
            lines.append((t + k, 0x300 + 0x10 * k, st))
            if step % 10 == k:
                d = MSG["SquealDetail"].encode({
                    "SquealDetail_CRC": 0, "SquealDetail_Counter": 0,
                    "V0_mps": rnd.choice([16383, 0, 37, 123, 1599, 2050]),
                    "HopfSpeed_mps": 1, "TriggerVelocity_mps": 1, "VehicleSpeedBorder_kph": 1})
                d2 = MSG["SquealDetail2"].encode({
                    "SquealDetail2_CRC": 0, "SquealDetail2_Counter": 0,
                    "Force_N": rnd.choice([65535, 0, 999, 18000, 63999, 65534]),
                    "HopfForce_N": 1, "LcAmplitude_um": 1})
                lines.append((t + k, 0x301 + 0x10 * k, d))
                lines.append((t + k, 0x303 + 0x10 * k, d2))
            if step == 300 and k == 1:
                lines.append((t + k, 0x310, bytes(st[:5])))  # wrong DLC: not a status
    text = "".join("(%d.%06d) vcan0 %03X#%s\n" % (ts // 1000000, ts % 1000000, cid, bytes(d).hex().upper())
                   for ts, cid, d in lines)
    p = subprocess.run([DRIVER, "25"], input=text.encode(), stdout=subprocess.PIPE)
    R.check(p.returncode == 0, "summary_driver exit 0")
    doc = load_strict(p.stdout.decode())
    eps = compare(doc, read_frames(text), lines[-1][0] + 25000, "four corners")
    R.check({e["corner"] for e in eps} == {"FL", "FR", "RR"} and len(eps) > 60,
            "four corners: %d episodes over FL, FR, RR" % len(eps))
    R.check(any(e["min_hopf_margin_mps"] is None for e in eps) and
            any(e["v0_max_mps"] == Decimal("20.5") for e in eps),
            "four corners: not-available margins give null, values beyond the grid are kept")


def main():
    with tempfile.TemporaryDirectory() as tmp:
        eps = check_log(tmp, "stop", ["--scenario", "stop"])
        # the replay ends with the last frame: the final state is the one the
        # last inputs gave (standstill), not a fault of inputs gone stale after
        # the end of the log
        R.check([e["state"] for e in eps] == ["fault", "stable", "bistable", "unstable",
                                              "not_sliding"],
                "stop: the braking run's states in order, ending not sliding")
        check_log(tmp, "sweep-faults", ["--scenario", "sweep", "--drop", "0.01",
                                        "--corrupt-crc", "0.01", "--seed", "7"])
        check_log(tmp, "stop-and-go", ["--scenario", os.path.join(ROOT, "scenarios", "stop-and-go.txt"),
                                       "--freeze-counter", "14"])
        four_corners(tmp)
        check_segments(tmp)
        # escaping: a log name with quotes, backslash, control characters, UTF-8, a bad byte
        name = b'we"ird\\na\tme\x01\xc3\xa4\xff.log'
        path = os.path.join(tmp.encode(), name)
        with open(path, "wb") as f:
            f.write(b"(0.000000) vcan0 110#00\nnot a frame\n")
        p = subprocess.run([SIM.encode(), b"replay", path, b"--no-output", b"--summary-json", b"-"],
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        try:
            doc = load_strict(p.stdout.decode("utf-8"))
            R.check(doc["log"] == path.decode("utf-8", errors="replace"),
                    "log name escaped (quotes, backslash, controls, UTF-8 kept, bad byte U+FFFD)")
            R.check(doc["lines"]["malformed"] == 1 and doc["started"] is True, "malformed line counted")
        except ValueError as e:
            R.check(False, "escaped document parses: %s" % e)
        empty = os.path.join(tmp, "empty.log")
        open(empty, "w").close()
        p = run(["replay", empty, "--no-output", "--summary-json", "-"])
        doc = load_strict(p.stdout.decode())
        R.check(p.returncode == 1 and doc["started"] is False and doc["episodes"] == [] and
                doc["corners"] == [] and doc["final_state"] is None and
                doc["inputs_by_corner"] == [],
                "empty log: exit 1, and still a valid empty document")
        p = run(["replay", empty, "--summary-json", "-"])
        R.check(p.returncode == 2 and b"--no-output" in p.stderr, "--summary-json - without --no-output: exit 2")
        p = run(["replay", empty, "--summary-json", os.path.join(tmp, "no", "dir.json")])
        R.check(p.returncode == 1 and b"cannot write" in p.stderr, "unwritable --summary-json: exit 1, reason")
    R.finish()


if __name__ == "__main__":
    main()
