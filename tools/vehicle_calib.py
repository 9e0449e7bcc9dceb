#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Build a calibration text (input map and corners, issue 11) from a vehicle's
DBC, by message and signal name.

    vehicle_calib.py --dbc CAR.dbc [--log DRIVE.log]
        --corner FL --speed MSG.SIG --force MSG.SIG [--speed-unit U] [--force-unit U]
            [--piston-area-mm2 A] [--efficiency E] [--axle-factor K]
        [--corner FR ...] [--wheel-radius-m R] [--pad-radius-m R] [--period-ms MS]
        [--protection none|p01|p02|counter] [--counter MSG.SIG] [--base FILE.cal]
        [-o FILE.cal] [--dbc-out FILE.dbc]

The keys written are those of the agreed interface (input-map calibration
text). What is taken from where:
  - start bit, length, byte order, sign, factor, offset, unit, multiplexer:
    the DBC signal (canmatrix; start bits in the DBC's own numbering);
  - min_dlc: the message's DLC in the DBC (a shorter frame is a bad DLC);
  - "not available" raw values (na_raw, na_raw2): entries of the signal's VAL_
    table whose text says not available / SNA / invalid / init / error /
    fault (at most two, the highest raw values first);
  - qualifier bit: a 1-bit signal of the same message (and multiplexer page)
    whose name is the value's name plus a qualifier word, or a qualifier word
    plus the value's name, separated by '_' or nothing, case-insensitive.
    Words meaning "invalid when 1": Q QF Qual Qualifier Flt Fault Err Error
    Inv Invalid NV SNA; words meaning "invalid when 0": V Valid VLD OK.
    When the bit has a VAL_ table, the value whose text says invalid / fault /
    error / not valid decides instead;
  - period: GenMsgCycleTime (for a multiplexed input: times the number of
    multiplexer values the DBC defines, since the pages take turns), else
    measured from --log (median interval of the input's frames, corrected
    for heavy frame loss, see measure_period), else --period-ms;
  - protection: --protection for every input: p01 takes the message's
    E2E_DataID attribute, p02 its E2E_DataIDList attribute (16 bytes), counter
    the signal named by --counter (repeatable, one per message) or else the
    one sibling whose name says counter/alive/cnt/rolling.
A recorded drive drops frames (gaps of 2-3 periods), so the inputs accept
counter steps up to 3 (times the number of pages for a multiplexed input,
below the counter's modulus: max_delta_counter) and go stale after 5 missed
periods (stale_cycles); plausibility: from 0 (less half a step) to the
largest value the signal can carry (declared DBC ranges are often wrong),
steps up to 100 m/s^2 (speed) or a quarter of the range (force) per period.
Every refusal, bad usage included, is one line on stderr and exit status 1.
"""
import contextlib
import io
import math
import os
import re
import sys
import warnings

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SQUEAL_DBC = os.path.join(ROOT, "firmware", "protocol", "squeal.dbc")

POSITIONS = ("FL", "FR", "RL", "RR")
# unit (lower case) -> quantity, as the calibration text accepts them
UNITS = {
    "km/h": "speed", "kph": "speed", "m/s": "speed", "mph": "speed",
    "rad/s": "speed", "rpm": "speed", "1/min": "speed",
    "n": "force", "kn": "force",
    "bar": "pressure", "kpa": "pressure", "mpa": "pressure", "psi": "pressure",
    "nm": "torque",
}
# unit -> m/s (linear) or rad/s (angular) per unit, for the plausible step
SPEED_SI = {"km/h": (1 / 3.6, "linear"), "kph": (1 / 3.6, "linear"), "m/s": (1.0, "linear"),
            "mph": (0.44704, "linear"), "rad/s": (1.0, "angular"),
            "rpm": (2 * math.pi / 60, "angular"), "1/min": (2 * math.pi / 60, "angular")}
STEP_ACCEL_MPS2 = 100.0   # plausible speed change per period: 10 g
STALE_CYCLES = 5          # loggers drop 2-3 frames in a row
MAX_DELTA_COUNTER = 3     # counter step of a frame after two dropped ones
MAX_INPUTS = 8
NAME_MAX = 15
LEGACY_KEYS = ("disc_speed_id", "pad_force_id", "e2e_check_inputs", "input_period_ms",
               "speed_max_radps", "speed_step_max_radps", "force_max_n", "force_step_max_n")
OUTPUT_KEYS = (("status_id", 0x300), ("detail_id", 0x301), ("diag_id", 0x302), ("detail2_id", 0x303))
OUTPUT_MSGS = (("SquealStatus", 0x300), ("SquealDetail", 0x301), ("SquealDiag", 0x302),
               ("SquealDetail2", 0x303))

QUAL_BAD_WHEN_1 = ("q", "qf", "qual", "qualifier", "flt", "fault", "err", "error", "inv",
                   "invalid", "nv", "sna")
QUAL_BAD_WHEN_0 = ("v", "valid", "vld", "ok")
NA_TEXT = re.compile(r"not.?avail|\bsna\b|\bn/?a\b|unavailable|invalid|\binit|error|fault|snv", re.I)
BAD_TEXT = re.compile(r"invalid|fault|error|not.?valid|\bnok\b|failure", re.I)
COUNTER_NAME = re.compile(r"counter|alive|cnt|rolling|\brc\b", re.I)


class Refusal(Exception):
    """A reason to refuse, printed as one line."""


def num(text):
    """A number as the calibration text writes it (no exponent surprises)."""
    if isinstance(text, int):
        return str(text)
    v = float(text)
    if v == int(v) and abs(v) < 1e15:
        return str(int(v))
    # the calibration keeps decimals of at most 9 significant digits: a
    # computed range (32767 x 0.1 = 3276.7000000000003) is written 3276.7
    return "%.9g" % v


# ---------------------------------------------------------------- DBC access

def load_dbc(path):
    """The one database of a DBC file; Refusal when it cannot be read."""
    try:
        with open(path, "rb") as f:
            text = f.read()
    except OSError as e:
        raise Refusal("cannot read DBC %s: %s" % (path, e.strerror or e))
    if b"BO_ " not in text:
        raise Refusal("%s is not a DBC file (no BO_ message)" % path)
    import logging
    logging.disable(logging.CRITICAL)  # canmatrix logs missing optional formats
    out = io.StringIO()
    try:
        with warnings.catch_warnings(), contextlib.redirect_stdout(out):
            warnings.simplefilter("ignore")
            import canmatrix.formats
            dbs = canmatrix.formats.loadp(path, import_type="dbc")
    except Exception as e:  # canmatrix raises many kinds on bad files
        raise Refusal("cannot parse DBC %s: %s" % (path, str(e).splitlines()[0] if str(e) else type(e).__name__))
    m = re.search(r"error with line no: (\d+)", out.getvalue())
    if m:
        raise Refusal("cannot parse DBC %s: bad line %s" % (path, m.group(1)))
    if len(dbs) != 1 or not list(dbs.values())[0].frames:
        raise Refusal("%s holds no CAN database with messages" % path)
    return list(dbs.values())[0]


def find_signal(db, ref, what):
    """(frame, signal) of MSG.SIG, or Refusal naming what is unknown."""
    if "." not in ref:
        raise Refusal("%s %r: give it as MESSAGE.SIGNAL" % (what, ref))
    msg, sig = ref.split(".", 1)
    frame = db.frame_by_name(msg)
    if frame is None:
        raise Refusal("%s %s: unknown message %r in the DBC" % (what, ref, msg))
    s = frame.signal_by_name(sig)
    if s is None:
        raise Refusal("%s %s: message %s has no signal %r" % (what, ref, msg, sig))
    return frame, s


def dbc_start_bit(sig):
    """Start bit in the DBC's numbering (Intel: LSB, Motorola: MSB)."""
    return int(sig.get_startbit(bit_numbering=1))


def signal_bits(start, length, intel):
    """DBC bit numbers (8*byte + bit) a signal occupies, MSB first for Motorola."""
    if intel:
        return list(range(start, start + length))
    bits, b = [], start
    for _ in range(length):
        bits.append(b)
        b = b - 1 if b % 8 else b + 15
    return bits


def same_page(a, b):
    """Two signals of one frame that can be in the same frame instance."""
    return a.mux_val is None or b.mux_val is None or a.mux_val == b.mux_val


def mux_selector(frame):
    for s in frame.signals:
        if s.is_multiplexer:
            return s
    return None


def na_values(sig):
    vals = sorted((int(k) for k, v in sig.values.items() if NA_TEXT.search(str(v))), reverse=True)
    return vals[:2]


def qualifier_of(frame, sig):
    """(bit, invalid value) of the sibling qualifier bit, or None (rule in the doc)."""
    base = sig.name.lower()
    found = []
    for s in frame.signals:
        if s is sig or s.size != 1 or not same_page(s, sig) or s.is_multiplexer:
            continue
        n = s.name.lower()
        word = None
        for pre in (base + "_", base):
            if n.startswith(pre) and n[len(pre):]:
                word = n[len(pre):]
                break
        if word is None:
            for suf in ("_" + base, base):
                if n.endswith(suf) and n[:-len(suf)]:
                    word = n[:-len(suf)]
                    break
        if word is None:
            continue
        word = word.strip("_")
        if word in QUAL_BAD_WHEN_1:
            bad = 1
        elif word in QUAL_BAD_WHEN_0:
            bad = 0
        else:
            continue
        named = [int(k) for k, v in s.values.items() if BAD_TEXT.search(str(v))]
        if len(named) == 1 and named[0] in (0, 1):
            bad = named[0]
        found.append((dbc_start_bit(s), bad))
    return found[0] if len(found) == 1 else None


def find_counter(db, frame, sig, counters):
    """The counter signal for counter-only protection."""
    for ref in counters:
        f, s = find_signal(db, ref, "--counter")
        if f is frame:
            return s
    cands = [s for s in frame.signals if s is not sig and not s.is_multiplexer
             and COUNTER_NAME.search(s.name) and 2 <= s.size <= 8 and same_page(s, sig)]
    if len(cands) != 1:
        raise Refusal("message %s: %s; name its counter with --counter %s.SIGNAL"
                      % (frame.name, "no alive counter signal found" if not cands else
                         "several counter candidates (%s)" % ", ".join(c.name for c in cands),
                         frame.name))
    return cands[0]


# ---------------------------------------------------------------- periods

def read_log(path):
    """[(t, id, extended, data)] of a candump log (-L or the default format)."""
    rx_l = re.compile(r"^\((\d+(?:\.\d+)?)\)\s+\S+\s+([0-9A-Fa-f]{1,8})#(R?)([0-9A-Fa-f]*)")
    rx_d = re.compile(r"^\((\d+(?:\.\d+)?)\)\s+\S+\s+([0-9A-Fa-f]{3,8})\s+\[(\d)\]\s*((?:[0-9A-Fa-f]{2}\s*)*)")
    try:
        f = open(path, "r", errors="replace")
    except OSError as e:
        raise Refusal("cannot read log %s: %s" % (path, e.strerror or e))
    frames = []
    with f:
        for line in f:
            m = rx_l.match(line)
            if m:
                if m.group(3):
                    continue
                ids, hexd = m.group(2), m.group(4)
                if len(hexd) % 2:
                    continue
                frames.append((float(m.group(1)), int(ids, 16), len(ids) == 8, bytes.fromhex(hexd)))
                continue
            m = rx_d.match(line)
            if m:
                ids = m.group(2)
                frames.append((float(m.group(1)), int(ids, 16), len(ids) == 8,
                               bytes.fromhex(m.group(4).replace(" ", ""))))
    if not frames:
        raise Refusal("log %s holds no candump frame" % path)
    return frames


def measure_period(times):
    """Robust period [ms] of a frame stream with dropped frames and jitter:
    the median interval; if a fifth or more of the intervals lie near half of
    it (more than half the frames dropped), the lower mode is the period;
    then the median of the intervals within +-30 % of it. Backward jumps and
    intervals over 2 s are not intervals. None with fewer than 5 intervals."""
    iv = sorted(b - a for a, b in zip(times, times[1:]) if 0 < b - a < 2.0)
    if len(iv) < 5:
        return None

    def median(xs):
        n = len(xs)
        return xs[n // 2] if n % 2 else 0.5 * (xs[n // 2 - 1] + xs[n // 2])
    m = median(iv)
    low = [x for x in iv if 0.35 * m <= x <= 0.65 * m]
    if len(low) >= 0.2 * len(iv):
        m = median(low)
    near = [x for x in iv if 0.7 * m <= x <= 1.3 * m]
    return int(round(median(near) * 1000.0))


def mux_matches(frame, sig, data):
    sel = mux_selector(frame)
    if sel is None or sig.mux_val is None:
        return True
    return extract(data, dbc_start_bit(sel), sel.size, sel.is_little_endian, False) == sig.mux_val


def extract(data, start, length, intel, signed):
    """Raw value per vehicle-bus.md; None when the frame is too short."""
    v = 0
    bits = signal_bits(start, length, intel)
    if intel:
        bits = bits[::-1]  # MSB first
    for b in bits:
        if b // 8 >= len(data):
            return None
        v = (v << 1) | ((data[b // 8] >> (b % 8)) & 1)
    if signed and v >> (length - 1):
        v -= 1 << length
    return v


def mux_pages(frame, sig):
    """How many pages take turns in the frame of a multiplexed signal (the
    values the DBC defines for the selector or uses in its signals); 1 for a
    plain signal."""
    if sig.mux_val is None:
        return 1
    sel = mux_selector(frame)
    return max(1, len({s.mux_val for s in frame.signals if s.mux_val is not None}
                      | set(int(k) for k in (sel.values if sel else {}))))


def input_period(frame, sig, log_frames, period_ms, what):
    if frame.cycle_time and frame.cycle_time > 0:
        return int(frame.cycle_time) * mux_pages(frame, sig), "GenMsgCycleTime"
    if log_frames is not None:
        ext = bool(frame.arbitration_id.extended)
        fid = frame.arbitration_id.id
        times = [t for t, i, e, d in log_frames if i == fid and e == ext and mux_matches(frame, sig, d)]
        p = measure_period(times)
        if p is not None:
            return p, "measured from the log (%d frames)" % len(times)
    if period_ms is not None:
        return period_ms, "--period-ms"
    raise Refusal("%s %s.%s: no period: the DBC has no GenMsgCycleTime for %s%s; give --log DRIVE.log "
                  "to measure it or --period-ms MS" % (what, frame.name, sig.name, frame.name,
                                                         ", the log has too few of its frames"
                                                         if log_frames is not None else ""))


# ---------------------------------------------------------------- the map

def sanitize(name, room=NAME_MAX):
    """An input name from a signal name: the name itself when it fits,
    otherwise each word (CamelCase or _ separated) cut short until it fits
    (WheelSpeed_FrontLeft -> WheeSpeeFronLeft -> WheSpeFroLef)."""
    n = re.sub(r"[^A-Za-z0-9_]", "_", name)
    if len(n) <= room:
        return n or "in"
    words = re.findall(r"[A-Z]+(?![a-z])|[A-Z]?[a-z0-9]+|[A-Z]", n)
    for k in (4, 3, 2, 1):
        short = "".join(w[:k] for w in words)
        if 0 < len(short) <= room:
            return short
    return n[:room]


def physical_range(sig):
    lo, hi = sig.calculate_raw_range()
    f, o = float(sig.factor), float(sig.offset)
    a, b = lo * f + o, hi * f + o
    return min(a, b), max(a, b)


def build_input(db, ref, role, unit_override, args, log_frames):
    what = "--speed" if role == "speed" else "--force"
    frame, sig = find_signal(db, ref, what)
    if sig.is_float:
        raise Refusal("%s %s: a float signal, which the monitor does not read" % (what, ref))
    if sig.size > 32:
        raise Refusal("%s %s: length %d bits, more than 32" % (what, ref, sig.size))
    if sig.size < 1:
        raise Refusal("%s %s: length 0" % (what, ref))
    if float(sig.factor) == 0.0:
        raise Refusal("%s %s: factor 0" % (what, ref))
    unit = unit_override if unit_override is not None else (sig.unit or "").strip()
    q = UNITS.get(unit.lower())
    if q is None:
        if unit_override is not None:
            raise Refusal("%s-unit %r: not a known unit (%s)" % (what, unit, " ".join(sorted(UNITS))))
        raise Refusal("%s %s: unit %r is not known; state it with %s-unit U (one of: %s)"
                      % (what, ref, unit, what, ", ".join(sorted(UNITS))))
    if role == "speed" and q != "speed":
        raise Refusal("%s %s: unit %r is a %s, not a speed" % (what, ref, unit, q))
    if role == "force" and q == "speed":
        raise Refusal("%s %s: unit %r is a speed, not a force, pressure or torque" % (what, ref, unit))
    d = {"id": frame.arbitration_id.id, "extended": bool(frame.arbitration_id.extended),
         "min_dlc": int(frame.size), "start_bit": dbc_start_bit(sig), "length": int(sig.size),
         "byte_order": "intel" if sig.is_little_endian else "motorola",
         "signed": bool(sig.is_signed), "factor": sig.factor, "offset": sig.offset, "unit": unit}
    sel = mux_selector(frame)
    if sig.mux_val is not None and sel is not None:
        d.update(mux_start_bit=dbc_start_bit(sel), mux_length=int(sel.size),
                 mux_byte_order="intel" if sel.is_little_endian else "motorola",
                 mux_value=int(sig.mux_val))
    for key, v in zip(("na_raw", "na_raw2"), na_values(sig)):
        d[key] = v
    qual = qualifier_of(frame, sig)
    if qual is not None:
        d["qualifier_bit"], d["qualifier_invalid"] = qual
    d["period_ms"], d["period_source"] = input_period(frame, sig, log_frames, args.period_ms, what)
    if not 1 <= d["period_ms"] <= 1000:
        raise Refusal("%s %s: period %d ms outside 1..1000" % (what, ref, d["period_ms"]))
    prot = args.protection
    d["protection"] = prot
    if prot == "p01":
        try:
            d["data_id"] = int(str(frame.attributes["E2E_DataID"]).strip('"'), 0)
        except (KeyError, ValueError):
            raise Refusal("--protection p01: message %s has no E2E_DataID attribute (0..65535)" % frame.name)
        if not 0 <= d["data_id"] <= 0xFFFF:
            raise Refusal("--protection p01: message %s: E2E_DataID %d outside 0..65535" % (frame.name, d["data_id"]))
    elif prot == "p02":
        lst = frame.attributes.get("E2E_DataIDList")
        try:
            vals = [int(x, 0) for x in re.split(r"[\s,]+", str(lst).strip().strip('"')) if x] if lst else []
        except ValueError:
            vals = []
        if len(vals) != 16 or any(not 0 <= v <= 255 for v in vals):
            raise Refusal("--protection p02: message %s has no E2E_DataIDList attribute of 16 bytes"
                          % frame.name)
        d["data_id_list"] = " ".join("0x%02X" % v for v in vals)
    elif prot == "counter":
        c = find_counter(db, frame, sig, args.counter)
        d.update(counter_start_bit=dbc_start_bit(c), counter_length=int(c.size),
                 counter_byte_order="intel" if c.is_little_endian else "motorola",
                 counter_modulus=1 << int(c.size))
    if prot != "none":
        # the sender counts frames; a multiplexed input sees every pages-th of them
        modulus = d.get("counter_modulus", 15 if prot == "p01" else 16)
        d["max_delta_counter"] = min(MAX_DELTA_COUNTER * mux_pages(frame, sig), modulus - 1)
    d["stale_cycles"] = STALE_CYCLES
    # community DBC files often declare a wrong [min|max]: the plausible
    # maximum is the largest value the signal can carry
    lo, top = physical_range(sig)
    if top <= 0:
        raise Refusal("%s %s: the signal cannot be positive (range %g..%g %s)" % (what, ref, lo, top, unit))
    # zero within half a step: raw x factor + offset of a standstill with a
    # negative offset (6767 x 0.01 - 67.67) may come out a hair below zero
    d["min"], d["max"] = -float("%.6g" % (abs(float(sig.factor)) / 2)), top
    if q == "speed":
        si, kind = SPEED_SI[unit.lower()]
        per_unit = si if kind == "linear" else si * args.wheel_radius_m
        step = STEP_ACCEL_MPS2 * d["period_ms"] / 1000.0 / per_unit
    else:
        step = top / 4.0
    d["step_max"] = float("%.6g" % max(step, abs(float(sig.factor))))
    d["_ref"], d["_quantity"] = ref, q
    return d


def parse_args(argv):
    """Global options by argparse; per-corner options belong to the last --corner."""
    import argparse

    class P(argparse.ArgumentParser):
        def error(self, message):
            raise Refusal(message)

    corner_opts = {"--speed": str, "--force": str, "--speed-unit": str, "--force-unit": str,
                   "--piston-area-mm2": float, "--efficiency": float, "--axle-factor": float}
    corners, rest, cur = [], [], None
    i = 0
    while i < len(argv):
        tok = argv[i]
        key, val = (tok.split("=", 1) + [None])[:2] if tok.startswith("--") else (tok, None)
        if key == "--corner" or key in corner_opts:
            if val is None:
                if i + 1 >= len(argv):
                    raise Refusal("%s needs a value" % key)
                val = argv[i + 1]
                i += 1
            if key == "--corner":
                pos = val.upper()
                if pos not in POSITIONS:
                    raise Refusal("--corner %s: not one of FL, FR, RL, RR" % val)
                if any(c["pos"] == pos for c in corners):
                    raise Refusal("--corner %s given twice" % pos)
                cur = {"pos": pos}
                corners.append(cur)
            else:
                if cur is None:
                    raise Refusal("%s before any --corner" % key)
                name = key[2:].replace("-", "_")
                if name in cur:
                    raise Refusal("%s given twice for corner %s" % (key, cur["pos"]))
                try:
                    cur[name] = corner_opts[key](val)
                except ValueError:
                    raise Refusal("%s %s: not a number" % (key, val))
        else:
            rest.append(tok)
        i += 1
    p = P(prog="vehicle_calib.py", description=__doc__.splitlines()[0])
    p.add_argument("--dbc", required=True)
    p.add_argument("--log")
    p.add_argument("--wheel-radius-m", type=float)
    p.add_argument("--pad-radius-m", type=float)
    p.add_argument("--period-ms", type=int)
    p.add_argument("--protection", choices=("none", "p01", "p02", "counter"), default="none")
    p.add_argument("--counter", action="append", default=[])
    p.add_argument("--base")
    p.add_argument("-o", "--output")
    p.add_argument("--dbc-out")
    args = p.parse_args(rest)
    if not corners:
        raise Refusal("no --corner given (e.g. --corner FL --speed MSG.SIG --force MSG.SIG)")
    for c in corners:
        for k in ("speed", "force"):
            if k not in c:
                raise Refusal("corner %s: --%s MSG.SIG missing" % (c["pos"], k))
    for name in ("wheel_radius_m", "pad_radius_m"):
        v = getattr(args, name)
        if v is not None and not 0.01 <= v <= 2.0:
            raise Refusal("--%s %g: outside 0.01 .. 2 m" % (name.replace("_", "-"), v))
    if args.period_ms is not None and not 1 <= args.period_ms <= 1000:
        raise Refusal("--period-ms %d: outside 1 .. 1000" % args.period_ms)
    return args, corners


def read_base(path):
    """Flat key lines of an existing calibration text (sections dropped)."""
    try:
        with open(path) as f:
            lines = f.read().splitlines()
    except OSError as e:
        raise Refusal("cannot read --base %s: %s" % (path, e.strerror or e))
    flat, in_section = [], False
    for n, line in enumerate(lines, 1):
        s = line.split("#", 1)[0].strip()
        if s.startswith("["):
            in_section = True
            continue
        if in_section or not s:
            continue
        if "=" not in s:
            raise Refusal("%s:%d: not a key = value line" % (path, n))
        key, val = (x.strip() for x in s.split("=", 1))
        flat.append((key, val))
    return flat


def build(argv):
    args, corners = parse_args(argv)
    base = read_base(args.base) if args.base else []
    base_vals = dict(base)
    if args.wheel_radius_m is None:
        args.wheel_radius_m = float(base_vals.get("wheel_radius_m", 0.3))
    db = load_dbc(args.dbc)
    log_frames = read_log(args.log) if args.log else None
    inputs, by_ref = [], {}
    for c in corners:
        for role in ("speed", "force"):
            ref = c[role]
            if ref not in by_ref:
                d = build_input(db, ref, role, c.get(role + "_unit"), args, log_frames)
                names = {x["name"] for x in inputs}
                name = sanitize(ref.split(".", 1)[1])
                k = 2
                while name in names:
                    suffix = "_%d" % k
                    name = sanitize(ref.split(".", 1)[1], NAME_MAX - len(suffix)) + suffix
                    k += 1
                d["name"] = name
                by_ref[ref] = d
                inputs.append(d)
            else:
                d = by_ref[ref]
                override = c.get(role + "_unit")
                if override is not None and override != d["unit"]:
                    raise Refusal("%s: unit %s here but %s for another corner" % (ref, override, d["unit"]))
                if (role == "speed") != (d["_quantity"] == "speed"):
                    raise Refusal("%s: used as a speed and as a force" % ref)
            c[role + "_input"] = by_ref[ref]
        fq = c["force_input"]["_quantity"]
        if fq == "pressure":
            if c.get("piston_area_mm2") is None:
                raise Refusal("corner %s: --force %s is a pressure (%s): give --piston-area-mm2 A"
                              % (c["pos"], c["force"], c["force_input"]["unit"]))
        for k in ("piston_area_mm2", "efficiency", "axle_factor"):
            if c.get(k) is not None and fq != "pressure":
                raise Refusal("corner %s: --%s applies to a pressure only" % (c["pos"], k.replace("_", "-")))
        if c.get("piston_area_mm2") is not None and not c["piston_area_mm2"] > 0:
            raise Refusal("corner %s: --piston-area-mm2 must be > 0" % c["pos"])
        if c.get("efficiency") is not None and not 0 < c["efficiency"] <= 1:
            raise Refusal("corner %s: --efficiency must be in (0, 1]" % c["pos"])
        if c.get("axle_factor") is not None and not 0 < c["axle_factor"] <= 4:
            raise Refusal("corner %s: --axle-factor must be in (0, 4]" % c["pos"])
    if len(inputs) > MAX_INPUTS:
        raise Refusal("%d inputs, at most %d" % (len(inputs), MAX_INPUTS))
    return args, corners, inputs, base


INPUT_KEYS = ("id", "extended", "min_dlc", "start_bit", "length", "byte_order", "signed", "factor",
              "offset", "unit", "mux_start_bit", "mux_length", "mux_byte_order", "mux_value",
              "na_raw", "na_raw2", "qualifier_bit", "qualifier_invalid", "protection", "data_id",
              "data_id_list", "counter_start_bit", "counter_length", "counter_byte_order",
              "counter_modulus", "max_delta_counter", "period_ms", "stale_cycles", "min", "max",
              "step_max")


def fmt_value(key, v):
    if isinstance(v, bool):
        return "yes" if v else "no"
    if key == "id":
        return "0x%X" % v
    if key in ("factor", "offset"):
        t = str(v)  # canmatrix keeps the DBC's decimal text (Decimal)
        return t if "E" not in t.upper() else repr(float(v))
    if isinstance(v, float):
        return num(v)
    return str(v)


def render(args, corners, inputs, base, argv):
    out = ["# Calibration of the brake-squeal monitor for a vehicle bus from %s," % os.path.basename(args.dbc),
           "# written by tools/vehicle_calib.py (edit freely; README 'On a vehicle'):"]
    line = "#  "
    for a in argv:  # the command, in lines the calibration reader accepts
        a = a if len(a) < 200 else "..." + a[-196:]
        if len(line) + len(a) > 76:
            out.append(line)
            line = "#   "
        line += " " + a
    out.append(line)
    base_keys = set()
    for key, val in base:
        if key in LEGACY_KEYS or key in ("wheel_radius_m", "pad_radius_m"):
            continue
        out.append("%s = %s" % (key, val))
        base_keys.add(key)
    base_vals = dict(base)
    for key, opt in (("wheel_radius_m", args.wheel_radius_m), ("pad_radius_m", args.pad_radius_m)):
        if opt is not None:
            out.append("%s = %s" % (key, num(opt)))
        elif key in base_vals:
            out.append("%s = %s" % (key, base_vals[key]))
    for d in inputs:
        out.append("")
        out.append("[input %s]" % d["name"])
        out.append("# %s, period from %s" % (d["_ref"], d["period_source"]))
        for k in INPUT_KEYS:
            if k in d:
                out.append("%s = %s" % (k, fmt_value(k, d[k])))
    for c in sorted(corners, key=lambda c: POSITIONS.index(c["pos"])):
        out.append("")
        out.append("[corner %s]" % c["pos"])
        out.append("speed = %s" % c["speed_input"]["name"])
        out.append("force = %s" % c["force_input"]["name"])
        for k in ("piston_area_mm2", "efficiency", "axle_factor"):
            if c.get(k) is not None:
                out.append("%s = %s" % (k, num(c[k])))
        for k, v in output_ids(c["pos"], base_vals).items():
            if k in base_keys:
                out.append("%s = 0x%X" % (k, v))
    return "\n".join(out) + "\n"


def output_ids(pos, base_vals):
    """The corner's output identifiers: the flat ones (default 0x300..) + 0x10 k."""
    k = POSITIONS.index(pos)
    ids = {}
    for key, dflt in OUTPUT_KEYS:
        try:
            v = int(base_vals[key], 0) if key in base_vals else dflt
        except ValueError:
            raise Refusal("--base: %s = %s is not an identifier" % (key, base_vals[key]))
        ids[key] = v + 0x10 * k
    return ids


# ---------------------------------------------------------------- DBC out

def dbc_out(corners, base_vals, path):
    """squeal.dbc's output messages once per corner (suffix _FL ...; corner FL
    keeps today's message names and identifiers), with their comments,
    attributes and value tables."""
    with open(SQUEAL_DBC) as f:
        lines = f.read().splitlines()
    first_bo = next(i for i, l in enumerate(lines) if l.startswith("BO_ "))
    head = lines[:first_bo]
    blocks, i = {}, first_bo
    while i < len(lines):
        m = re.match(r"^BO_ (\d+) (\w+):", lines[i])
        if m:
            j = i + 1
            while j < len(lines) and lines[j].startswith(" SG_"):
                j += 1
            blocks[int(m.group(1))] = (m.group(2), lines[i:j])
            i = j
        else:
            i += 1
    tail = [l for l in lines[first_bo:] if not l.startswith((" SG_", "BO_ ")) and l.strip()]
    out_ids = {old: key for (name, old), (key, _) in zip(OUTPUT_MSGS, OUTPUT_KEYS)}
    body, extra = [], []
    for c in sorted(corners, key=lambda c: POSITIONS.index(c["pos"])):
        ids = output_ids(c["pos"], base_vals)
        suffix = "" if c["pos"] == "FL" else "_" + c["pos"]
        for name, old in OUTPUT_MSGS:
            new = ids[out_ids[old]]
            oname, blk = blocks[old]
            body.append(blk[0].replace("BO_ %d %s:" % (old, oname), "BO_ %d %s%s:" % (new, oname, suffix), 1))
            body.extend(blk[1:])
            body.append("")
            for l in tail:
                m = re.match(r'^(CM_ (?:BO_|SG_) |BA_ "\w+" BO_ |VAL_ )(\d+)( .*)$', l)
                if m and int(m.group(2)) == old:
                    t = m.group(3)
                    if l.startswith("CM_ BO_") and suffix:
                        t = t.replace(' "', ' "Corner %s: ' % c["pos"], 1)
                    extra.append(m.group(1) + str(new) + t)
    glob = [l for l in tail if not re.match(r'^(CM_ (?:BO_|SG_) |BA_ "\w+" BO_ |VAL_ )\d+ ', l)]
    cm = [l for l in glob if l.startswith("CM_ ")]
    defs = [l for l in glob if not l.startswith("CM_ ")]
    text = "\n".join(head + body + [""] + cm + [l for l in extra if l.startswith("CM_")] + defs
                     + [l for l in extra if l.startswith("BA_ ")] + [l for l in extra if l.startswith("VAL_")]) + "\n"
    try:
        with open(path, "w") as f:
            f.write(text)
    except OSError as e:
        raise Refusal("cannot write %s: %s" % (path, e.strerror or e))


def main(argv):
    try:
        args, corners, inputs, base = build(argv)
        text = render(args, corners, inputs, base, argv)
        if args.dbc_out:
            dbc_out(corners, dict(base), args.dbc_out)
        if args.output and args.output != "-":
            try:
                with open(args.output, "w") as f:
                    f.write(text)
            except OSError as e:
                raise Refusal("cannot write %s: %s" % (args.output, e.strerror or e))
        else:
            sys.stdout.write(text)
    except Refusal as e:
        sys.stderr.write("vehicle_calib.py: %s\n" % e)
        return 1
    except KeyboardInterrupt:
        sys.stderr.write("vehicle_calib.py: interrupted\n")
        return 1
    except Exception as e:  # a DBC canmatrix reads but in a shape not foreseen here
        sys.stderr.write("vehicle_calib.py: cannot handle this input (%s: %s)\n"
                         % (type(e).__name__, str(e).splitlines()[0] if str(e) else ""))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
