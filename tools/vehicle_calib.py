#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Build a calibration text (input map and corners) from a vehicle's DBC, by
message and signal name; checked by the firmware's own reader before it is
written.

    vehicle_calib.py --dbc CAR.dbc [--log DRIVE.log [--bus IFACE]]
        --corner FL --speed MSG.SIG --force MSG.SIG [--speed-unit U [--unit-scale S]]
            [--force-unit U [--unit-scale S]] [--piston-area-mm2 A] [--efficiency E]
            [--axle-factor K] [--torque-share K]
        [--corner FR ...] [--wheel-radius-m R] [--pad-radius-m R] [--period-ms MS]
        [--protection none|p01|p02|p05|counter|auto] [--counter MSG.SIG]
        [--data-id MSG=ID] [--data-id-xor MASK]
        [--qualifier MSG.SIG=MSG.QSIG:invalid-when=0|1] [--na-raw MSG.SIG=RAW[,RAW]]
        [--ignore-dbc-range] [--keep-all-ones] [--base FILE.cal] [-o FILE.cal] [--dbc-out FILE.dbc]

What is taken from where:
  - start bit, length, byte order, sign, factor, offset, unit: the DBC signal
    (canmatrix; start bits in the DBC's own numbering); factor and offset as
    the DBC writes them (exact), times the --unit-scale when one is given;
  - signal = MSG.SIG: the DBC names (long names where the DBC has them);
  - min_dlc: the message's DLC in the DBC (a shorter frame is a bad DLC),
    up to 64 bytes for an FD frame;
  - fd = yes: the message is a CAN FD frame: its VFrameFormat attribute is
    StandardCAN_FD or ExtendedCAN_FD (as the text or as the index into the
    BA_DEF_'s ENUM list), or, without a VFrameFormat, its DLC exceeds 8; an
    FD length between the DLC code lengths is the next one (12, 16, 20, 24,
    32, 48, 64); a classic VFrameFormat with a DLC above 8 is refused. A
    classic frame with an FD message's identifier is not that message;
  - multiplexing: the selectors the DBC defines, simple (m3), extended
    (SG_MUL_VAL_ with value ranges), cascaded (the outer selector's page is
    mux_*, the inner one's mux2_*) and independent multiplexors (the one
    selector the signal depends on); one range per selector, two selectors
    at most, else a refusal;
  - plausible range (min, max): the DBC's declared [min|max] (within what
    the signal can carry), unless it is [0|0] or --ignore-dbc-range is given:
    then from 0 (less half a step) to the largest value the signal carries;
    steps up to 100 m/s^2 (speed) or a quarter of the range (force) per
    period;
  - "not available" raw values (na_raw, na_raw2): VAL_ entries whose text
    means no value (not available, unavailable, n/a, SNA, init, invalid,
    error, fault, unknown, undefined, no value; any case; "no error" is a
    value), and the all-ones raw value where the declared range excludes it
    (unless --keep-all-ones); codes inside the plausible range first; more
    than two inside it: a refusal naming them (choose with --na-raw);
  - qualifier bit: a 1-bit signal of the same message and page named as the
    value's qualifier (Speed_Q, Speed_QF, Speed_Valid, BR5_Druckvalid for
    BR5_Bremsdruck, Speed_Invalid, Speed_Flt, Speed_Fault, Speed_Stat with a
    VAL_ table; the rule in tools/vcalib_rules.py); the choice and its reason
    are printed, one line per input; two equally good candidates: none
    (choose with --qualifier); a bit beyond the DLC is refused;
  - period: GenMsgCycleTime (a multiplexed input: times the pages that take
    turns), else measured from --log on the --bus interface (median interval
    corrected for heavy frame loss, see measure_period; a multiplexed input:
    the message's period times the frames per carrying frame), else
    --period-ms;
  - input_iface: --bus. Without --bus, a message seen on two interfaces of
    the log is refused (choose the bus with --bus);
  - protection: --protection for every input: p01 takes the message's
    E2E_DataID attribute, p02 its E2E_DataIDList attribute (16 bytes), counter
    the signal named by --counter (repeatable, one per message) or else the
    one sibling whose name says counter/alive/cnt/rolling (in a message of
    several CRC-16 blocks: the one of the signal's block);
    p05 (AUTOSAR E2E Profile 5, CRC-16/CCITT-FALSE) the message's CRC-16
    signal (16 bits, Intel, on a byte boundary, named CRC/checksum) with an
    8-bit counter in the byte after it, written as e2e_offset_byte, and the
    Data ID: --data-id MSG=ID, else the E2E_DataID attribute, else the CAN
    identifier XOR --data-id-xor MASK (a maker's rule: Hyundai/Kia FD frames
    use 0xF800); a message with several CRC-16 blocks is not P05 (the
    monitor's CRC covers the whole frame);
    auto, per message: p05 where it has that layout and a Data ID, else its
    counter, else none, each with a note saying why.
With --log, each input's line says how many logged values lie outside the
declared range and how many are all ones. The log may hold CAN FD lines
(`ID##F<data>`, F the flags digit); an FD message's period and counts come
from its FD frames only, a classic message's from its classic frames.
DBC files as found in the field: a line no reader accepts that the request
does not need is skipped with a warning naming its line (tools/dbc_tolerant.py).
A recorded drive drops frames (gaps of 2-3 periods), so the inputs accept
counter steps up to 3 (times the pages for a multiplexed input, below the
counter's modulus: max_delta_counter) and go stale after 5 missed periods.
The text is checked with `squeal-sim calib-check` (build/host/squeal-sim; the
environment variable VEHICLE_CALIB_SIM names another) before it is written;
its refusal is printed and nothing is written. Every refusal, bad usage
included, is one line on stderr and exit status 1; notes (qualifier choices,
skipped DBC lines, log counts) go to stderr after a successful run.
"""
import decimal
import math
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import deps  # noqa: E402  (names the Debian package of a missing module)

deps.need("canmatrix")
import dbc_tolerant  # noqa: E402
import vcalib_rules as rules  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SQUEAL_DBC = os.path.join(ROOT, "firmware", "protocol", "squeal.dbc")
CHECKER = os.path.join(ROOT, "build", "host", "squeal-sim")

D = decimal.Decimal
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
SIGNAL_MAX = 63
IFACE = re.compile(r"^[A-Za-z0-9_.-]{1,15}$")
LEGACY_KEYS = ("disc_speed_id", "pad_force_id", "e2e_check_inputs", "input_period_ms",
               "speed_max_radps", "speed_step_max_radps", "force_max_n", "force_step_max_n")
OUTPUT_KEYS = (("status_id", 0x300), ("detail_id", 0x301), ("diag_id", 0x302), ("detail2_id", 0x303))
OUTPUT_MSGS = (("SquealStatus", 0x300), ("SquealDetail", 0x301), ("SquealDiag", 0x302),
               ("SquealDetail2", 0x303))
P05_COUNTER_MODULUS = 256


class Refusal(Exception):
    """A reason to refuse, printed as one line."""


def num(value):
    """A number of an option as the calibration text writes it (exact)."""
    try:
        return rules.text(value)
    except rules.RuleRefusal as e:
        raise Refusal(str(e))


# ---------------------------------------------------------------- DBC access

class Dbc:
    """The DBC, read for the messages asked for (dbc_tolerant), with lookups
    by DBC name or long name."""

    def __init__(self, path, wanted):
        try:
            self.db, self.notes, self.idx = dbc_tolerant.load(path, wanted)
        except dbc_tolerant.DbcRefusal as e:
            raise Refusal(str(e))
        self.path = path
        self.short_to_long = {(cid, short): lng for (cid, lng), short in self.idx.long_sig.items()}

    def frame(self, name):
        import canmatrix
        cid = self.idx.lookup(name)
        if cid is not None:
            f = self.db.frame_by_id(canmatrix.ArbitrationId.from_compound_integer(cid))
            if f is not None:
                return f, cid
        f = self.db.frame_by_name(name)
        if f is not None:
            return f, f.arbitration_id.to_compound_integer()
        return None, None

    def kind(self, frame):
        """(fd, data length, why) of a message (vcalib_rules.frame_kind)."""
        try:
            vformat, given = self.idx.frame_format(frame.arbitration_id.to_compound_integer())
            return rules.frame_kind(frame.name, frame.size, vformat, given, bool(getattr(frame, "is_fd", False)))
        except rules.RuleRefusal as e:
            raise Refusal(str(e))

    def find(self, ref, what):
        """(frame, signal) of MSG.SIG, or Refusal naming what is unknown."""
        if "." not in ref:
            raise Refusal("%s %r: give it as MESSAGE.SIGNAL" % (what, ref))
        msg, sig = ref.split(".", 1)
        frame, cid = self.frame(msg)
        if frame is None:
            raise Refusal("%s %s: unknown message %r in the DBC" % (what, ref, msg))
        s = frame.signal_by_name(sig)
        if s is None and (cid, sig) in self.short_to_long:
            s = frame.signal_by_name(self.short_to_long[(cid, sig)])
        if s is None:
            raise Refusal("%s %s: message %s has no signal %r" % (what, ref, msg, sig))
        return frame, s


def dbc_start_bit(sig):
    """Start bit in the DBC's numbering (Intel: LSB, Motorola: MSB)."""
    return int(sig.get_startbit(bit_numbering=1))


def order(sig):
    return "intel" if sig.is_little_endian else "motorola"


def signal_bits(start, length, intel):
    """DBC bit numbers (8*byte + bit) a signal occupies, MSB first for Motorola."""
    if intel:
        return list(range(start, start + length))
    bits, b = [], start
    for _ in range(length):
        bits.append(b)
        b = b - 1 if b % 8 else b + 15
    return bits


def find_counter(dbc, frame, sig, counters):
    """The counter signal for counter-only protection."""
    for ref in counters:
        f, s = dbc.find(ref, "--counter")
        if f is frame:
            return s
    mine = rules.block_counter(frame, sig, dbc_start_bit)
    if mine is not None:
        return mine
    cands = []
    for s in frame.signals:
        if s is sig or s.is_multiplexer or not rules.COUNTER_NAME.search(s.name) or not 2 <= s.size <= 8:
            continue
        try:
            if rules.same_page(frame, sig, s):
                cands.append(s)
        except rules.RuleRefusal:
            continue
    if len(cands) != 1:
        raise Refusal("message %s: %s; name its counter with --counter %s.SIGNAL"
                      % (frame.name, "no alive counter signal found" if not cands else
                         "several counter candidates (%s)" % ", ".join(c.name for c in cands),
                         frame.name))
    return cands[0]


# ---------------------------------------------------------------- logs and periods

def read_log(path):
    """([(t, iface, id, extended, data, fd)], FD lines skipped) of a candump
    log (-L or the default format); an FD line (ID##F<data>) of a length that
    is no DLC code length is skipped and counted."""
    rx_l = re.compile(r"^\((\d+(?:\.\d+)?)\)\s+(\S+)\s+([0-9A-Fa-f]{1,8})#(#[0-9A-Fa-f]|R?)([0-9A-Fa-f]*)")
    rx_d = re.compile(r"^\((\d+(?:\.\d+)?)\)\s+(\S+)\s+([0-9A-Fa-f]{3,8})\s+\[(\d)\]\s*((?:[0-9A-Fa-f]{2}\s*)*)")
    try:
        f = open(path, "r", errors="replace")
    except OSError as e:
        raise Refusal("cannot read log %s: %s" % (path, e.strerror or e))
    frames, skipped = [], 0
    with f:
        try:
            text = f.read()
        except OSError as e:
            raise Refusal("cannot read log %s: %s" % (path, e.strerror or e))
    for line in re.split(r"\r\n|\r|\n", text):
        m = rx_l.match(line)
        if m:
            if m.group(4) == "R":
                continue
            ids, hexd, fd = m.group(3), m.group(5), m.group(4).startswith("#")
            if len(hexd) % 2 or (fd and len(hexd) // 2 > rules.CLASSIC_MAX_DLEN
                                 and len(hexd) // 2 not in rules.FD_LENGTHS):
                skipped += fd
                continue
            frames.append((float(m.group(1)), m.group(2), int(ids, 16), len(ids) == 8, bytes.fromhex(hexd), fd))
            continue
        m = rx_d.match(line)
        if m:
            ids = m.group(3)
            frames.append((float(m.group(1)), m.group(2), int(ids, 16), len(ids) == 8,
                           bytes.fromhex(m.group(5).replace(" ", "")), False))
    if not frames:
        raise Refusal("log %s holds no candump frame" % path)
    return frames, skipped


def message_frames(frame, fd, log_frames):
    """[(t, data)] of the log's frames of a message: its identifier and kind
    (a classic frame with an FD message's identifier is another message)."""
    ext = bool(frame.arbitration_id.extended)
    fid = frame.arbitration_id.id
    return [(t, d) for t, _, i, e, d, f in log_frames if i == fid and e == ext and f == fd]


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






def extract(data, start, length, intel, signed):
    """Raw value per the DBC bit layout; None when the frame is too short."""
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


def carries(conds, data):
    """The frame's selectors lie in every condition's range."""
    for sel, (lo, hi) in conds:
        v = extract(data, dbc_start_bit(sel), int(sel.size), sel.is_little_endian, False)
        if v is None or not lo <= v <= hi:
            return False
    return True


def input_period(frame, fd, sig, conds, log_frames, period_ms, what):
    pages = rules.pages_factor(frame, conds)
    if frame.cycle_time and frame.cycle_time > 0:
        return int(math.ceil(int(frame.cycle_time) * pages - 1e-9)), "GenMsgCycleTime" + (
            " x %g pages" % pages if conds else "")
    if log_frames is not None:
        mine = message_frames(frame, fd, log_frames)
        if conds:
            p = measure_period([t for t, _ in mine])
            n_in = sum(1 for _, d in mine if carries(conds, d))
            if p is not None and n_in >= 5:
                return int(round(p * len(mine) / float(n_in))), (
                    "the log (%d frames, %d of them carry it)" % (len(mine), n_in))
        else:
            p = measure_period([t for t, _ in mine])
            if p is not None:
                return p, "the log (%d frames)" % len(mine)
    if period_ms is not None:
        return period_ms, "--period-ms"
    raise Refusal("%s %s.%s: no period: the DBC has no GenMsgCycleTime for %s%s; give --log DRIVE.log "
                  "to measure it or --period-ms MS" % (what, frame.name, sig.name, frame.name,
                                                         ", the log has too few of its %s frames"
                                                         % ("FD" if fd else "classic")
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






def manual_options(args):
    """--qualifier and --na-raw by MSG.SIG (parsed, not yet resolved)."""
    quals, nas = {}, {}
    for spec in args.qualifier:
        m = re.match(r"^([^=\s]+\.[^=\s]+)=(?:(none)|([^:\s]+\.[^:\s]+):invalid-when=([01]))$", spec)
        if not m:
            raise Refusal("--qualifier %s: give MSG.SIG=MSG.QSIG:invalid-when=0|1 or MSG.SIG=none" % spec)
        if m.group(1) in quals:
            raise Refusal("--qualifier %s given twice" % m.group(1))
        quals[m.group(1)] = None if m.group(2) else (m.group(3), int(m.group(4)))
    for spec in args.na_raw:
        m = re.match(r"^([^=\s]+\.[^=\s]+)=(none|[-+]?(?:0[xX][0-9A-Fa-f]+|\d+)(?:,[-+]?(?:0[xX][0-9A-Fa-f]+|\d+))?)$",
                     spec)
        if not m:
            raise Refusal("--na-raw %s: give MSG.SIG=RAW[,RAW] (at most two raw values) or MSG.SIG=none" % spec)
        if m.group(1) in nas:
            raise Refusal("--na-raw %s given twice" % m.group(1))
        nas[m.group(1)] = [] if m.group(2) == "none" else [int(x, 0) for x in m.group(2).split(",")]
    return quals, nas


def decimal_option(text, what, lo_open, hi):
    """An exact decimal option in (lo_open, hi]."""
    try:
        v = D(str(text).strip())
    except decimal.InvalidOperation:
        raise Refusal("%s %s: not a number" % (what, text))
    if not v.is_finite() or not (v > lo_open and (hi is None or v <= hi)):
        raise Refusal("%s %s: must be in (%s, %s]" % (what, text, lo_open, "inf" if hi is None else hi))
    num(v)
    return v


def build_input(dbc, ref, role, c, args, log_frames, manual, notes):
    what = "--speed" if role == "speed" else "--force"
    frame, sig = dbc.find(ref, what)
    if sig.is_float:
        raise Refusal("%s %s: a float signal, which the monitor does not read" % (what, ref))
    if sig.size > 32:
        raise Refusal("%s %s: length %d bits, more than 32" % (what, ref, sig.size))
    if sig.size < 1:
        raise Refusal("%s %s: length 0" % (what, ref))
    if rules.dec(sig.factor) == 0:
        raise Refusal("%s %s: factor 0" % (what, ref))
    unit_override = c.get(role + "_unit")
    unit = unit_override if unit_override is not None else (sig.unit or "").strip()
    q = UNITS.get(unit.lower())
    if q is None:
        if unit_override is not None:
            raise Refusal("%s-unit %r: not a known unit (%s)" % (what, unit, " ".join(sorted(UNITS))))
        raise Refusal("%s %s: unit %r is not known; state it with %s-unit U (one of: %s; --unit-scale S "
                      "after it when one raw physical unit is S U)"
                      % (what, ref, unit, what, ", ".join(sorted(UNITS))))
    if role == "speed" and q != "speed":
        raise Refusal("%s %s: unit %r is a %s, not a speed" % (what, ref, unit, q))
    if role == "force" and q == "speed":
        raise Refusal("%s %s: unit %r is a speed, not a force, pressure or torque" % (what, ref, unit))
    scale = c.get(role + "_scale", D(1))
    try:
        factor = rules.dec(sig.factor) * scale
        offset = rules.dec(sig.offset) * scale
        conds = rules.conditions(frame, sig)
    except rules.RuleRefusal as e:
        raise Refusal("%s %s: %s" % (what, ref, e))
    cid_text = "%s.%s" % (frame.name, sig.name)
    fd, length, kind_why = dbc.kind(frame)
    if log_frames is not None:
        fd, kind_why = rules.frame_kind_on_bus(frame.name, fd, length, kind_why,
                                               len(message_frames(frame, True, log_frames)),
                                               len(message_frames(frame, False, log_frames)))
    last_bit = max(signal_bits(dbc_start_bit(sig), int(sig.size), sig.is_little_endian))
    if last_bit // 8 >= length:
        raise Refusal("%s %s: bit %d lies beyond the %d bytes of %s" % (what, ref, last_bit, length, frame.name))
    d = {"id": frame.arbitration_id.id, "extended": bool(frame.arbitration_id.extended),
         "min_dlc": length, "start_bit": dbc_start_bit(sig), "length": int(sig.size),
         "byte_order": order(sig), "signed": bool(sig.is_signed), "factor": factor, "offset": offset,
         "unit": unit}
    if fd:
        d["fd"] = True
        notes.append("%s: an FD frame of %d bytes (%s)" % (cid_text, length, kind_why))
        if length <= rules.CLASSIC_MAX_DLEN and log_frames is None:
            notes.append("%s: many DBC files mark every message CAN FD, also on a classic bus; "
                         "give --log DRIVE.log and the frames on the bus decide" % cid_text)
    elif "the log carries" in kind_why:
        notes.append("%s: a classic frame of %d bytes (%s)" % (cid_text, length, kind_why))
    if re.match(r"^[!-~]{1,%d}$" % SIGNAL_MAX, cid_text):   # the key takes 1..63 printable non-blanks
        d["signal"] = cid_text
    for k, (sel, (lo, hi)) in enumerate(conds):
        p = "mux" if k == 0 else "mux2"
        d.update({p + "_start_bit": dbc_start_bit(sel), p + "_length": int(sel.size),
                  p + "_byte_order": order(sel), p + "_value": lo})
        if hi != lo:
            d[p + "_value_max"] = hi

    def phys(raw):
        return D(raw) * factor + offset
    rlo, rhi = rules.raw_limits(sig)
    carried = sorted((phys(rlo), phys(rhi)))
    dmin, dmax = rules.dec(sig.min) * scale, rules.dec(sig.max) * scale
    declared = None if (dmin == 0 and dmax == 0) else tuple(sorted((dmin, dmax)))
    unit_txt = unit + (" (x %s)" % num(scale) if scale != 1 else "")
    if declared is not None and not args.ignore_dbc_range:
        lo, hi = max(declared[0], carried[0]), min(declared[1], carried[1])
        rng_src = "the declared range [%s|%s] %s" % (num(declared[0]), num(declared[1]), unit)
        if hi <= 0 or lo > hi:
            raise Refusal("%s %s: the declared range [%s|%s] %s holds no positive value the signal can carry "
                          "(%s..%s); --ignore-dbc-range uses the signal's whole range"
                          % (what, ref, num(declared[0]), num(declared[1]), unit_txt, num(carried[0]),
                             num(carried[1])))
        used_declared = declared
    else:
        lo, hi = -abs(factor) / 2, carried[1]
        rng_src = "the whole range of the signal (%s)" % ("--ignore-dbc-range" if declared is not None
                                                           else "the DBC declares [0|0]")
        if hi <= 0:
            raise Refusal("%s %s: the signal cannot be positive (range %s..%s %s)"
                          % (what, ref, num(carried[0]), num(carried[1]), unit))
        used_declared = None
    d["min"], d["max"] = rules.outward(lo, False), rules.outward(hi, True)
    # not available
    if ref in manual[1] or cid_text in manual[1]:
        na = manual[1].get(ref, manual[1].get(cid_text))
        for v in na:
            if not rlo <= v <= rhi:
                raise Refusal("--na-raw %s: %d is not a raw value of the signal (%d..%d)" % (ref, v, rlo, rhi))
        why = ["%d (--na-raw)" % v for v in na]
    else:
        try:
            na, why = rules.na_codes(sig, phys, lo, hi, used_declared, args.keep_all_ones, (rlo, rhi))
        except rules.RuleRefusal as e:
            raise Refusal("%s %s: %s" % (what, ref, str(e).replace("%s", ref)))
    for key, v in zip(("na_raw", "na_raw2"), na):
        d[key] = v
    notes.append("%s: range %s..%s %s from %s; not available: %s" % (
        cid_text, num(d["min"]), num(d["max"]), unit_txt, rng_src, ", ".join(why) if why else "none"))
    # qualifier
    bit_of = dbc_start_bit
    mq = manual[0].get(ref, manual[0].get(cid_text, False))
    if mq is not False:
        if mq is None:
            qsig, bad, qnote = None, None, "no qualifier bit (--qualifier %s=none)" % ref
        else:
            qf, qsig = dbc.find(mq[0], "--qualifier %s=" % ref)
            bad = mq[1]
            if qf is not frame:
                raise Refusal("--qualifier %s=%s: the qualifier must be in the same message (%s)"
                              % (ref, mq[0], frame.name))
            if int(qsig.size) != 1:
                raise Refusal("--qualifier %s=%s: %s has %d bits, a qualifier is one bit"
                              % (ref, mq[0], qsig.name, qsig.size))
            try:
                page_ok = rules.same_page(frame, sig, qsig)
            except rules.RuleRefusal as e:
                raise Refusal("--qualifier %s=%s: %s" % (ref, mq[0], e))
            if not page_ok:
                raise Refusal("--qualifier %s=%s: %s is not in every frame that carries %s (another page)"
                              % (ref, mq[0], qsig.name, sig.name))
            if bit_of(qsig) // 8 >= length:
                raise Refusal("--qualifier %s=%s: bit %d lies beyond the DLC %d of %s"
                              % (ref, mq[0], bit_of(qsig), length, frame.name))
            qnote = "qualifier %s (bit %d, invalid when %d): --qualifier" % (qsig.name, bit_of(qsig), bad)
    else:
        qsig, bad, qnote = rules.choose_qualifier(frame, sig, bit_of, length)
    if qsig is not None:
        d["qualifier_bit"], d["qualifier_invalid"] = bit_of(qsig), bad
    notes.append("%s: %s" % (cid_text, qnote))
    d["period_ms"], d["period_source"] = input_period(frame, fd, sig, conds, log_frames, args.period_ms, what)
    if not 1 <= d["period_ms"] <= 1000:
        raise Refusal("%s %s: period %d ms outside 1..1000" % (what, ref, d["period_ms"]))
    protection(d, dbc, frame, sig, conds, args, length, notes)
    d["stale_cycles"] = STALE_CYCLES
    if q == "speed":
        si, kind = SPEED_SI[unit.lower()]
        per_unit = si if kind == "linear" else si * args.wheel_radius_m
        step = STEP_ACCEL_MPS2 * d["period_ms"] / 1000.0 / per_unit
    else:
        step = float(d["max"]) / 4.0
    d["step_max"] = D("%.6g" % max(step, float(abs(factor))))
    if log_frames is not None:
        notes.append("%s: %s" % (cid_text, log_counts(frame, fd, length, sig, conds, log_frames, phys, declared,
                                                       unit)))
    d["_ref"], d["_quantity"], d["_scale"] = ref, q, scale
    return d


def log_counts(frame, fd, length, sig, conds, log_frames, phys, declared, unit):
    """How many logged values lie outside the declared range, how many are all ones."""
    n = out = ones = 0
    ones_raw = rules.all_ones(sig)
    for _, data in message_frames(frame, fd, log_frames):
        if len(data) < length or not carries(conds, data):
            continue
        raw = extract(data, dbc_start_bit(sig), int(sig.size), sig.is_little_endian, sig.is_signed)
        if raw is None:
            continue
        n += 1
        if declared is not None and not declared[0] <= phys(raw) <= declared[1]:
            out += 1
        if raw == ones_raw:
            ones += 1
    rng = "outside the declared range [%s|%s] %s" % (num(declared[0]), num(declared[1]), unit) \
        if declared is not None else "outside a declared range (none: [0|0])"
    return "%d logged values, %d %s, %d all ones (raw %d)" % (n, out, rng, ones, ones_raw)


def data_id_of(frame, args):
    """(Data ID, where from) of a message for p01/p05, or (None, why not)."""
    if frame.name in args.data_ids:
        return args.data_ids[frame.name], "--data-id"
    if "E2E_DataID" in frame.attributes:
        try:
            v = int(str(frame.attributes["E2E_DataID"]).strip('"'), 0)
        except ValueError:
            v = -1
        if not 0 <= v <= 0xFFFF:
            raise Refusal("message %s: E2E_DataID %s is not a number in 0..65535"
                          % (frame.name, frame.attributes["E2E_DataID"]))
        return v, "its E2E_DataID attribute"
    if args.data_id_xor is not None:
        v = frame.arbitration_id.id ^ args.data_id_xor
        if v > 0xFFFF:
            return None, "identifier 0x%X XOR --data-id-xor 0x%X is beyond 16 bits" % (
                frame.arbitration_id.id, args.data_id_xor)
        return v, "identifier 0x%X XOR 0x%X (--data-id-xor)" % (frame.arbitration_id.id, args.data_id_xor)
    return None, ("message %s has no E2E_DataID attribute; give --data-id %s=ID (or --data-id-xor MASK where "
                  "the maker derives it from the identifier)" % (frame.name, frame.name))


def p05_keys(frame, sig, length, args):
    """The P05 keys of the input, or Refusal saying why the message is not P05."""
    try:
        off, crc, ctr = rules.p05_layout(frame, sig, dbc_start_bit, length)
    except rules.RuleRefusal as e:
        raise Refusal(str(e))
    did, src = data_id_of(frame, args)
    if did is None:
        raise Refusal("%s has the P05 layout (CRC %s in bytes %d-%d, counter %s in byte %d) but no Data ID: %s"
                      % (frame.name, crc.name, off, off + 1, ctr.name, off + 2, src))
    return {"data_id": did, "e2e_offset_byte": off}, "p05: CRC %s in bytes %d-%d, counter %s in byte %d, Data ID " \
        "0x%04X from %s" % (crc.name, off, off + 1, ctr.name, off + 2, did, src)


def counter_keys(dbc, frame, sig, args):
    c = find_counter(dbc, frame, sig, args.counter)
    return {"counter_start_bit": dbc_start_bit(c), "counter_length": int(c.size),
            "counter_byte_order": order(c), "counter_modulus": 1 << int(c.size)}, c


def protection(d, dbc, frame, sig, conds, args, length, notes):
    prot = args.protection
    where = "%s.%s" % (frame.name, sig.name)
    if prot == "auto":
        try:
            keys, why = p05_keys(frame, sig, length, args)
            prot = "p05"
            d.update(keys)
            notes.append("%s: protection %s" % (where, why))
        except Refusal as e:
            no_p05 = str(e)
            try:
                keys, c = counter_keys(dbc, frame, sig, args)
                prot = "counter"
                d.update(keys)
                notes.append("%s: protection counter %s only (not p05: %s)" % (where, c.name, no_p05))
            except Refusal as e2:
                prot = "none"
                notes.append("%s: no protection (not p05: %s; no counter: %s)" % (where, no_p05, e2))
    d["protection"] = prot
    if prot == "p01":
        did, src = data_id_of(frame, args)
        if did is None:
            raise Refusal("--protection p01: %s" % src)
        d["data_id"] = did
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
    elif prot == "p05" and args.protection == "p05":
        try:
            keys, why = p05_keys(frame, sig, length, args)
        except Refusal as e:
            raise Refusal("--protection p05: %s" % e)
        d.update(keys)
        notes.append("%s: protection %s" % (where, why))
    elif prot == "counter" and args.protection == "counter":
        d.update(counter_keys(dbc, frame, sig, args)[0])
    if prot != "none":
        # the sender counts frames; a multiplexed input sees every pages-th of them
        modulus = d.get("counter_modulus", {"p01": 15, "p05": P05_COUNTER_MODULUS}.get(prot, 16))
        pages = int(math.ceil(rules.pages_factor(frame, conds) - 1e-9))
        d["max_delta_counter"] = min(MAX_DELTA_COUNTER * pages, modulus - 1)


CORNER_HELP = (
    ("--corner", "POS", "start a corner: FL, FR, RL or RR; the options below belong to the last --corner"),
    ("--speed", "MSG.SIG", "the corner's wheel (or vehicle) speed signal, by DBC or long name"),
    ("--force", "MSG.SIG", "the corner's brake signal: a force, pressure or torque"),
    ("--speed-unit", "U", "the speed's unit where the DBC has none or a wrong one (km/h kph m/s mph rad/s rpm 1/min)"),
    ("--force-unit", "U", "the brake signal's unit where the DBC has none or a wrong one (N kN bar kPa MPa psi Nm)"),
    ("--speed-scale", "S", "one raw physical unit of the speed signal is S speed units (folded exactly into "
     "factor, offset and range)"),
    ("--force-scale", "S", "one raw physical unit of the brake signal is S force units (a unit-less pedal value)"),
    ("--unit-scale", "S", "the scale of the --speed-unit or --force-unit just before it (same as "
     "--speed-scale / --force-scale)"),
    ("--piston-area-mm2", "A", "pressure: the total piston area on one side of the caliper, mm^2"),
    ("--efficiency", "E", "pressure: efficiency eta in (0, 1], default 1"),
    ("--axle-factor", "K", "pressure: axle factor in (0, 4], default 1"),
    ("--torque-share", "K", "torque: the share in (0, 1] of the signal acting on this corner (a total or "
     "per-axle brake torque), default 1"),
)
CORNER_TYPES = {"--speed": str, "--force": str, "--speed-unit": str, "--force-unit": str,
                "--piston-area-mm2": float, "--efficiency": float, "--axle-factor": float,
                "--speed-scale": "dec", "--force-scale": "dec", "--unit-scale": "dec",
                "--torque-share": "dec"}


def parse_args(argv):
    """Global options by argparse; per-corner options belong to the last --corner."""
    import argparse

    class P(argparse.ArgumentParser):
        def error(self, message):
            raise Refusal(message)

    corners, rest, cur, last_unit = [], [], None, None
    i = 0
    while i < len(argv):
        tok = argv[i]
        key, val = (tok.split("=", 1) + [None])[:2] if tok.startswith("--") else (tok, None)
        if key == "--corner" or key in CORNER_TYPES:
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
                cur, last_unit = {"pos": pos}, None
                corners.append(cur)
            else:
                if cur is None:
                    raise Refusal("%s before any --corner" % key)
                if key == "--unit-scale":
                    if last_unit is None:
                        raise Refusal("--unit-scale %s: give it after --speed-unit U or --force-unit U" % val)
                    key = "--%s-scale" % last_unit
                if key in ("--speed-unit", "--force-unit"):
                    last_unit = key[2:-5]
                name = key[2:].replace("-", "_")
                if name in cur:
                    raise Refusal("%s given twice for corner %s" % (key, cur["pos"]))
                kind = CORNER_TYPES[key]
                if kind == "dec":
                    cur[name] = decimal_option(val, key, 0, 1 if key == "--torque-share" else None)
                else:
                    try:
                        cur[name] = kind(val)
                    except ValueError:
                        raise Refusal("%s %s: not a number" % (key, val))
        else:
            rest.append(tok)
        i += 1
    p = P(prog="vehicle_calib.py", description=__doc__.split("\n\n")[0].replace("\n", " "),
          epilog=__doc__.split("\n\n", 1)[1], formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--dbc", required=True, metavar="CAR.dbc", help="the vehicle's DBC file")
    p.add_argument("--log", metavar="DRIVE.log", help="a candump log of the vehicle: periods and value counts")
    p.add_argument("--bus", metavar="IFACE", help="the log's interface the inputs come from: periods measured "
                   "there only, written as input_iface")
    p.add_argument("--wheel-radius-m", type=float, metavar="R", help="wheel radius [m] (default: --base's or 0.3)")
    p.add_argument("--pad-radius-m", type=float, metavar="R", help="effective pad radius [m] (default: --base's)")
    p.add_argument("--period-ms", type=int, metavar="MS", help="period where neither the DBC nor the log has one")
    p.add_argument("--protection", choices=("none", "p01", "p02", "p05", "counter", "auto"), default="none",
                   help="the inputs' protection (default none): p05 is AUTOSAR E2E Profile 5 (CRC-16 and "
                   "8-bit counter found in the message); auto: p05 where the message has its layout and a "
                   "Data ID, else its counter, else none")
    p.add_argument("--data-id", action="append", default=[], metavar="MSG=ID",
                   help="the Data ID (0..65535) of a message for p01/p05 where the DBC has no E2E_DataID "
                   "attribute (repeatable, one per message)")
    p.add_argument("--data-id-xor", metavar="MASK",
                   help="p01/p05: a message without E2E_DataID or --data-id has the Data ID identifier XOR "
                   "MASK (a maker's rule, e.g. 0xF800 for Hyundai/Kia CAN FD frames)")
    p.add_argument("--counter", action="append", default=[], metavar="MSG.SIG",
                   help="the alive counter of a message for --protection counter (one per message)")
    p.add_argument("--qualifier", action="append", default=[], metavar="MSG.SIG=MSG.QSIG:invalid-when=0|1",
                   help="the input's qualifier bit by hand (same message and page), or MSG.SIG=none")
    p.add_argument("--na-raw", action="append", default=[], metavar="MSG.SIG=RAW[,RAW]",
                   help="the input's 'not available' raw values by hand (at most two), or MSG.SIG=none")
    p.add_argument("--ignore-dbc-range", action="store_true",
                   help="the DBC's declared ranges are wrong: plausible from 0 to the largest value carried")
    p.add_argument("--keep-all-ones", action="store_true",
                   help="the all-ones raw value is a value, not 'not available'")
    p.add_argument("--base", metavar="FILE.cal", help="a calibration whose flat keys (the brake) are kept")
    p.add_argument("-o", "--output", metavar="FILE.cal", help="where to write the calibration (default stdout)")
    p.add_argument("--dbc-out", metavar="FILE.dbc", help="also write the monitor's output messages per corner")
    g = p.add_argument_group("per corner (after --corner POS)")
    for opt, meta, h in CORNER_HELP:
        g.add_argument(opt, metavar=meta, help=h, dest="_corner_" + opt[2:].replace("-", "_"))
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
    if args.bus is not None and not IFACE.match(args.bus):
        raise Refusal("--bus %r: 1..15 characters of A-Z a-z 0-9 _ . -" % args.bus)
    args.data_ids = {}
    for spec in args.data_id:
        m = re.match(r"^([A-Za-z_][A-Za-z0-9_]*)=(0[xX][0-9A-Fa-f]+|\d+)$", spec)
        if not m or not 0 <= int(m.group(2), 0) <= 0xFFFF:
            raise Refusal("--data-id %s: give MSG=ID with ID in 0..65535 (0x0000..0xFFFF)" % spec)
        if m.group(1) in args.data_ids:
            raise Refusal("--data-id %s given twice" % m.group(1))
        args.data_ids[m.group(1)] = int(m.group(2), 0)
    if args.data_id_xor is not None:
        try:
            args.data_id_xor = int(args.data_id_xor, 0)
        except ValueError:
            args.data_id_xor = -1
        if not 0 <= args.data_id_xor <= 0xFFFF:
            raise Refusal("--data-id-xor: give a mask in 0..0xFFFF")
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






def wanted_messages(corners, args):
    refs = [c[k] for c in corners for k in ("speed", "force")] + list(args.counter)
    refs += [s.split("=", 1)[0] for s in args.qualifier + args.na_raw]
    refs += [s.split("=", 1)[1].split(":", 1)[0] for s in args.qualifier if "=" in s]
    return {r.split(".", 1)[0] for r in refs if "." in r} | set(args.data_ids)


def select_bus(log_frames, inputs_msgs, args):
    """The log's frames on the inputs' interface; Refusal when a message is on several."""
    ifaces = sorted({f[1] for f in log_frames})
    if args.bus is not None:
        if args.bus not in ifaces:
            raise Refusal("--bus %s: the log has no frame on %s (its interfaces: %s)"
                          % (args.bus, args.bus, ", ".join(ifaces)))
        return [f for f in log_frames if f[1] == args.bus]
    seen = {}
    for _, iface, i, e, _, _ in log_frames:
        seen.setdefault((i, e), set()).add(iface)
    for name, key in inputs_msgs:
        on = sorted(seen.get(key, ()))
        if len(on) > 1:
            raise Refusal("message %s is on %d interfaces of the log (%s): choose the inputs' bus with --bus IFACE"
                          % (name, len(on), ", ".join(on)))
    return log_frames


def build(argv):
    args, corners = parse_args(argv)
    base = read_base(args.base) if args.base else []
    base_vals = dict(base)
    if args.wheel_radius_m is None:
        try:
            args.wheel_radius_m = float(base_vals.get("wheel_radius_m", 0.3))
        except ValueError:
            raise Refusal("--base: wheel_radius_m = %s is not a number" % base_vals["wheel_radius_m"])
    manual = manual_options(args)
    dbc = Dbc(args.dbc, wanted_messages(corners, args))
    notes = list(dbc.notes)
    ids = {}
    for name, v in args.data_ids.items():
        f, _ = dbc.frame(name)
        if f is None:
            raise Refusal("--data-id %s=%d: unknown message %r in the DBC" % (name, v, name))
        ids[f.name] = v
    args.data_ids = ids
    log_frames = None
    if args.log:
        log_frames, skipped = read_log(args.log)
        if skipped:
            notes.append("log %s: %d FD lines skipped (a data length that is no DLC code length)"
                         % (args.log, skipped))
        msgs = []
        for c in corners:
            for role in ("speed", "force"):
                f, _ = dbc.find(c[role], "--" + role)
                msgs.append((f.name, (f.arbitration_id.id, bool(f.arbitration_id.extended))))
        log_frames = select_bus(log_frames, msgs, args)
    inputs, by_ref = [], {}
    for c in corners:
        for role in ("speed", "force"):
            ref = c[role]
            if ref not in by_ref:
                d = build_input(dbc, ref, role, c, args, log_frames, manual, notes)
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
                if c.get(role + "_scale", D(1)) != d["_scale"]:
                    raise Refusal("%s: scale %s here but %s for another corner"
                                  % (ref, num(c.get(role + "_scale", D(1))), num(d["_scale"])))
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
        if c.get("torque_share") is not None and fq != "torque":
            raise Refusal("corner %s: --torque-share applies to a brake torque only (--force %s is a %s)"
                          % (c["pos"], c["force"], fq))
        if c.get("piston_area_mm2") is not None and not c["piston_area_mm2"] > 0:
            raise Refusal("corner %s: --piston-area-mm2 must be > 0" % c["pos"])
        if c.get("efficiency") is not None and not 0 < c["efficiency"] <= 1:
            raise Refusal("corner %s: --efficiency must be in (0, 1]" % c["pos"])
        if c.get("axle_factor") is not None and not 0 < c["axle_factor"] <= 4:
            raise Refusal("corner %s: --axle-factor must be in (0, 4]" % c["pos"])
    if len(inputs) > MAX_INPUTS:
        raise Refusal("%d inputs, at most %d" % (len(inputs), MAX_INPUTS))
    refs = set(by_ref) | {"%s.%s" % tuple(d["signal"].split(".", 1)) for d in inputs if "signal" in d}
    for opt, table in (("--qualifier", manual[0]), ("--na-raw", manual[1])):
        for ref in table:
            if ref not in refs:
                raise Refusal("%s %s: not an input (give it with --speed or --force)" % (opt, ref))
    return args, corners, inputs, base, notes


INPUT_KEYS = ("signal", "id", "extended", "fd", "min_dlc", "start_bit", "length", "byte_order", "signed", "factor",
              "offset", "unit", "mux_start_bit", "mux_length", "mux_byte_order", "mux_value", "mux_value_max",
              "mux2_start_bit", "mux2_length", "mux2_byte_order", "mux2_value", "mux2_value_max",
              "na_raw", "na_raw2", "qualifier_bit", "qualifier_invalid", "protection", "data_id", "e2e_offset_byte",
              "data_id_list", "counter_start_bit", "counter_length", "counter_byte_order",
              "counter_modulus", "max_delta_counter", "period_ms", "stale_cycles", "min", "max",
              "step_max")


def fmt_value(key, v):
    if isinstance(v, bool):
        return "yes" if v else "no"
    if key == "id":
        return "0x%X" % v
    if isinstance(v, (D, float)):
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
        if key in LEGACY_KEYS or key in ("wheel_radius_m", "pad_radius_m", "input_iface"):
            continue
        out.append("%s = %s" % (key, val))
        base_keys.add(key)
    base_vals = dict(base)
    for key, opt in (("wheel_radius_m", args.wheel_radius_m), ("pad_radius_m", args.pad_radius_m)):
        if opt is not None:
            out.append("%s = %s" % (key, num(opt)))
        elif key in base_vals:
            out.append("%s = %s" % (key, base_vals[key]))
    if args.bus is not None:
        out.append("input_iface = %s" % args.bus)
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
        for k in ("piston_area_mm2", "efficiency", "axle_factor", "torque_share"):
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




# ---------------------------------------------------------------- checked writing

def checked_write(text, path):
    """Write the calibration only when the firmware's reader sets it up:
    `squeal-sim calib-check` on a temporary file, then rename (or print)."""
    sim = os.environ.get("VEHICLE_CALIB_SIM") or CHECKER
    if not (os.path.isfile(sim) and os.access(sim, os.X_OK)):
        raise Refusal("cannot check the calibration: %s is missing; run make first (it builds %s)"
                      % (sim, os.path.relpath(CHECKER, ROOT)))
    to_stdout = path is None or path == "-"
    folder = None if to_stdout else (os.path.dirname(os.path.abspath(path)))
    try:
        fd, tmp = tempfile.mkstemp(prefix=".vehicle_calib-", suffix=".cal", dir=folder)
    except OSError as e:
        raise Refusal("cannot write %s: %s" % (path, e.strerror or e))
    try:
        with os.fdopen(fd, "w") as f:
            f.write(text)
        try:
            p = subprocess.run([sim, "calib-check", tmp], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                               timeout=60)
        except (OSError, subprocess.TimeoutExpired) as e:
            raise Refusal("cannot check the calibration with %s: %s" % (sim, e))
        if p.returncode != 0:
            lines = [l for l in p.stderr.decode("utf-8", "replace").splitlines() if l.strip()]
            why = lines[-1] if lines else "exit status %d, no message" % p.returncode
            shown = "<stdout>" if to_stdout else path
            raise Refusal("the firmware refuses the calibration: %s" % why.replace(tmp, shown))
        if to_stdout:
            sys.stdout.write(text)
        else:
            try:
                os.replace(tmp, path)
            except OSError as e:
                raise Refusal("cannot write %s: %s" % (path, e.strerror or e))
            tmp = None
    finally:
        if tmp is not None and os.path.exists(tmp):
            os.unlink(tmp)


def main(argv):
    try:
        args, corners, inputs, base, notes = build(argv)
        text = render(args, corners, inputs, base, argv)
        checked_write(text, args.output)
        if args.dbc_out:
            dbc_out(corners, dict(base), args.dbc_out)
        for n in notes:
            sys.stderr.write("vehicle_calib.py: note: %s\n" % n)
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
