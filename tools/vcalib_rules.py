# SPDX-License-Identifier: MIT
"""How tools/vehicle_calib.py reads a DBC signal's meaning: exact numbers,
"not available" codes, qualifier bits and multiplexer conditions. Pure
functions of canmatrix's signals; every rule is stated once, here.

Not available (na_raw, na_raw2):
  - a VAL_ entry whose text means no value: "not available" (also
    "unavailable", "n/a"), "SNA", "init", "invalid", "error", "fault",
    "unknown", "undefined", "no value", in any case and spelling of blanks
    ("Signal not available", "NotAvailable", "SNA"); "no error", "no fault",
    "error free" and the like mean a value;
  - the all-ones raw value (0xFFF of 12 bits; -1 of a signed signal) where
    the DBC's declared [min|max] excludes it (the common SNA convention).
  At most two fit: codes inside the plausible range first (those outside are
  implausible anyway), then the others, all ones first.

Qualifier bit: a 1-bit signal of the same message that is present whenever
the value is (not multiplexed, or on the same page), named, in order of
preference:
  1. the value's name and a qualifier word: WhlSpd_FL_Flt, Speed_Q,
     QF_Speed, SpeedValid;
  2. the value's prefix (up to its last '_') and a remainder holding a part
     of the value's name and a qualifier word: BR5_Druckvalid for
     BR5_Bremsdruck;
  3. the value's name and _Stat/_Status, with a VAL_ table that names the
     invalid value.
  Qualifier words meaning "invalid when 1": Q QF Qual Qualifier Flt Fault
  Err Error Fail Failure Inv Invalid NV SNA; "invalid when 0": V Valid VLD
  OK. A VAL_ table on the bit that names one of 0/1 as invalid, fault or
  error (or the other as valid) decides instead. Two equally good
  candidates: none is chosen (say which with --qualifier).

Frame format (frame_kind): a message is an FD frame when its VFrameFormat
says StandardCAN_FD or ExtendedCAN_FD (canmatrix's is_fd), or, without a
VFrameFormat of its own, when its DLC exceeds 8 bytes (only an FD frame
carries more; a classic BA_DEF_DEF_ default then does not apply). Its own
classic VFrameFormat with a DLC above 8 is a refusal. An FD frame's
length is one of the DLC code lengths 0..8, 12, 16, 20, 24, 32, 48, 64: a DBC
length between them is the next one (the sender pads to it).

Counter: a signal of 2..8 bits named counter, alive, cnt, rolling or rc.

E2E Profile 5 layout (p05_layout): a 16-bit unsigned Intel signal on a byte
boundary named as a CRC or checksum (crc, checksum, chksum, chks) with an
8-bit unsigned counter signal in the byte after it (P05 stores the CRC
little-endian at its offset and the counter in the next byte); neither
multiplexed. The CRC of the monitor's P05 covers the whole frame, so a
message with several such blocks (each CRC over its own block) is not P05;
its counter check takes the counter of the block that holds the signal
(block_counter: a block runs from its CRC to the next block's CRC).
"""
import decimal
import re

D = decimal.Decimal
MAX_DIGITS = 17

NA_WORDS = re.compile(r"not[\s_-]*avail|unavail|\bn/a\b|(?:^|[^a-z])sna(?:$|[^a-z])|init|invalid|error|"
                      r"fault|unknown|undefined|no[\s_-]*value", re.I)
GOOD_NEGATION = re.compile(r"\b(?:no|not|without|non)[\s_-]*(?:error|fault|failure)s?\b|"
                           r"(?:error|fault)[\s_-]*free|\bnot[\s_-]*invalid\b", re.I)
BAD_WORDS = re.compile(r"invalid|fault|error|not[\s_-]*valid|\bnok\b|failure|defect", re.I)
GOOD_WORDS = re.compile(r"^\s*(?:valid|ok|okay|good|no[\s_-]*(?:error|fault))\b", re.I)
QUAL_BAD_WHEN_1 = ("qualifier", "failure", "invalid", "fault", "error", "qual", "fail", "flt", "err", "inv",
                   "sna", "qf", "nv", "q")
QUAL_BAD_WHEN_0 = ("valid", "vld", "ok", "v")
LONG_WORDS = ("qualifier", "failure", "invalid", "fault", "error", "valid")   # also glued: Druckvalid
STAT_WORDS = ("stat", "status", "sts")
COUNTER_NAME = re.compile(r"counter|alive|cnt|rolling|\brc\b", re.I)
CRC_NAME = re.compile(r"crc|checksum|chksum|chks", re.I)
CLASSIC_MAX_DLEN = 8
FD_LENGTHS = (12, 16, 20, 24, 32, 48, 64)   # the FD lengths above 8 (DLC codes 9..15)
FD_FORMATS = ("StandardCAN_FD", "ExtendedCAN_FD")
CLASSIC_FORMATS = ("StandardCAN", "ExtendedCAN", "J1939PG")


class RuleRefusal(Exception):
    """One line saying why the signal cannot be read as asked."""


# ---------------------------------------------------------------- numbers

def dec(v):
    """An exact Decimal of a canmatrix number or a decimal text."""
    if isinstance(v, D):
        return v
    if isinstance(v, int):
        return D(v)
    if isinstance(v, float):
        return D(repr(v))
    return D(str(v).strip())


def digits(d):
    t = d.normalize().as_tuple()
    return len(t.digits) if d != 0 else 1


def text(d, what="number"):
    """The calibration text of an exact decimal: the integer, Python's repr
    of the double when that is the same number, else the exact decimal;
    RuleRefusal beyond 17 significant digits."""
    d = dec(d)
    if not d.is_finite():
        raise RuleRefusal("%s %s is not a finite number" % (what, d))
    if d == d.to_integral_value() and abs(d) < D(10) ** MAX_DIGITS:
        return str(int(d))
    if digits(d) > MAX_DIGITS:
        raise RuleRefusal("%s %s has more than %d significant digits, which the calibration does not take"
                          % (what, d, MAX_DIGITS))
    r = repr(float(d))
    if D(r) == d:
        return r
    return format(d.normalize(), "f")


def outward(d, up):
    """d rounded away from the inside of a range to 17 significant digits."""
    d = dec(d)
    if digits(d) <= MAX_DIGITS:
        return d
    q = D(1).scaleb(d.adjusted() - MAX_DIGITS + 1)
    return d.quantize(q, rounding=decimal.ROUND_CEILING if up else decimal.ROUND_FLOOR)


# ---------------------------------------------------------------- not available

def means_no_value(t):
    t = str(t)
    return bool(NA_WORDS.search(t)) and not GOOD_NEGATION.search(t)


def raw_limits(sig):
    n = int(sig.size)
    return (-(1 << (n - 1)), (1 << (n - 1)) - 1) if sig.is_signed else (0, (1 << n) - 1)


def all_ones(sig):
    return -1 if sig.is_signed else (1 << int(sig.size)) - 1


def na_codes(sig, phys, lo, hi, declared, keep_all_ones, limits):
    """(chosen codes, why) per the rule above. phys(raw) -> Decimal; lo/hi the
    plausible range; declared (dlo, dhi) or None when not used; limits the
    signal's raw range (a VAL_ entry beyond it can never be sent)."""
    named = sorted({int(k) for k, v in sig.values.items() if means_no_value(v)
                    and limits[0] <= int(k) <= limits[1]}, reverse=True)
    codes = set(named)
    ones = all_ones(sig)
    ones_rule = declared is not None and not keep_all_ones and \
        not (declared[0] <= phys(ones) <= declared[1])
    if ones_rule:
        codes.add(ones)
    inside = sorted((c for c in codes if lo <= phys(c) <= hi), reverse=True)
    outside = sorted((c for c in codes if not lo <= phys(c) <= hi), key=lambda c: (c != ones, -c))
    if len(inside) > 2:
        raise RuleRefusal("%d \"not available\" codes inside the plausible range (raw %s); the calibration "
                          "takes two: choose them with --na-raw %%s=RAW[,RAW]" % (len(inside),
                                                                                ", ".join(map(str, inside))))
    chosen = inside + outside[:2 - len(inside)]
    why = []
    for c in chosen:
        src = []
        if c in named:
            src.append("VAL_ %r" % str(sig.values.get(c, sig.values.get(str(c), ""))))
        if ones_rule and c == ones:
            src.append("all ones outside the declared range")
        why.append("%d (%s)" % (c, ", ".join(src)))
    return chosen, why


# ---------------------------------------------------------------- multiplexing

def _merged(ranges):
    out = []
    for a, b in sorted((int(a), int(b)) for a, b in ranges):
        if out and a <= out[-1][1] + 1:
            out[-1][1] = max(out[-1][1], b)
        else:
            out.append([a, b])
    return out


def _parent(frame, sig):
    """(selector signal, (lo, hi)) the signal depends on, or None."""
    if getattr(sig, "muxer_for_signal", None):
        sel = frame.signal_by_name(sig.muxer_for_signal)
        if sel is None:
            raise RuleRefusal("SG_MUL_VAL_ names the selector %s, which message %s does not have"
                              % (sig.muxer_for_signal, frame.name))
        rng = _merged(sig.mux_val_grp) if sig.mux_val_grp else [[sig.mux_val, sig.mux_val]]
        if len(rng) != 1:
            raise RuleRefusal("%s is carried on values %s of selector %s: the calibration takes one range "
                              "per selector" % (sig.name, ", ".join("%d-%d" % tuple(r) for r in rng), sel.name))
        return sel, tuple(rng[0])
    if sig.mux_val is None:
        return None
    roots = [s for s in frame.signals if s.is_multiplexer]
    if len(roots) != 1:
        raise RuleRefusal("%s is multiplexed (m%d) but message %s has %d multiplexors and no SG_MUL_VAL_ "
                          "says which one selects it" % (sig.name, sig.mux_val, frame.name, len(roots)))
    return roots[0], (int(sig.mux_val), int(sig.mux_val))


def conditions(frame, sig):
    """[(selector, (lo, hi))], outer selector first; at most two."""
    chain, cur, seen = [], sig, set()
    while True:
        p = _parent(frame, cur)
        if p is None:
            break
        if p[0].name in seen or p[0] is sig:
            raise RuleRefusal("the multiplexors of message %s select each other in a loop" % frame.name)
        seen.add(p[0].name)
        chain.append(p)
        cur = p[0]
        if len(chain) > 2:
            raise RuleRefusal("%s sits under three or more cascaded selectors; the calibration takes two"
                              % sig.name)
    for sel, _ in chain:
        if sel.is_signed or sel.is_float:
            raise RuleRefusal("selector %s is signed or float; the calibration reads an unsigned selector"
                              % sel.name)
    return list(reversed(chain))


def selector_values(frame, sel):
    """The selector values the DBC uses (its pages)."""
    vals = set(int(k) for k in sel.values)
    for s in frame.signals:
        if s is sel:
            continue
        p = None
        try:
            p = _parent(frame, s)
        except RuleRefusal:
            continue
        if p is not None and p[0] is sel:
            if getattr(s, "muxer_for_signal", None) and s.mux_val_grp:
                for a, b in s.mux_val_grp:
                    vals.update(range(int(a), min(int(b), int(a) + 4096) + 1))
            else:
                vals.update(range(p[1][0], p[1][1] + 1))
    return vals


def pages_factor(frame, conds):
    """How many frames of the message pass per frame that carries the input:
    per condition the selector's pages over those in its range (pages take
    turns), multiplied."""
    f = 1.0
    for sel, (lo, hi) in conds:
        vals = selector_values(frame, sel)
        inside = len([v for v in vals if lo <= v <= hi]) or 1
        f *= max(1.0, len(vals) / float(inside))
    return f


def same_page(frame, a, b):
    """b is present in every frame that carries a."""
    cb = conditions(frame, b)
    return not cb or [(s.name, r) for s, r in cb] == [(s.name, r) for s, r in conditions(frame, a)]


# ---------------------------------------------------------------- qualifiers

def _word_of(rest, glued):
    """(word, invalid value) when rest is a qualifier word (or ends/starts in
    one, for the glued form), else None."""
    r = rest.strip("_").lower()
    for w in QUAL_BAD_WHEN_1 + QUAL_BAD_WHEN_0:
        bad = 1 if w in QUAL_BAD_WHEN_1 else 0
        if r == w:
            return w, bad, ""
    if not glued:
        return None
    raw = rest.strip("_")
    for w in sorted(QUAL_BAD_WHEN_1 + QUAL_BAD_WHEN_0, key=len, reverse=True):
        bad = 1 if w in QUAL_BAD_WHEN_1 else 0
        n = len(w)
        # long words may be glued (Druckvalid); short ones only at a boundary
        # (Druck_V, DruckQF: capital or '_')
        for stem, word in ((raw[:-n], raw[-n:]), (raw[n:], raw[:n])):
            if word.lower() != w or not stem:
                continue
            if w in LONG_WORDS or word[0].isupper() or stem.endswith("_") or stem.startswith("_"):
                return w, bad, stem.strip("_")
    return None


def _val_decides(q):
    """The invalid value a 1-bit signal's VAL_ table names, or None."""
    bad = [int(k) for k, v in q.values.items() if BAD_WORDS.search(str(v)) and not GOOD_NEGATION.search(str(v))]
    good = [int(k) for k, v in q.values.items() if GOOD_WORDS.search(str(v))]
    if len(bad) == 1 and bad[0] in (0, 1):
        return bad[0]
    if not bad and len(good) == 1 and good[0] in (0, 1):
        return 1 - good[0]
    return None


def qualifier_candidates(frame, sig, bit_of):
    """[(rank, q, invalid value, why)] of the message's 1-bit signals."""
    base = sig.name
    lb = base.lower()
    cut = base.rfind("_")
    prefix = base[:cut + 1] if cut > 0 else ""
    found = []
    for q in frame.signals:
        if q is sig or int(q.size) != 1 or q.is_multiplexer:
            continue
        try:
            if not same_page(frame, sig, q):
                continue
        except RuleRefusal:
            continue
        n = q.name
        ln = n.lower()
        hit = None
        if ln.startswith(lb) and len(n) > len(base):
            w = _word_of(n[len(base):], False)
            if w:
                hit = (1, w[1], "the value's name and the word '%s'" % w[0])
        if hit is None and ln.endswith(lb) and len(n) > len(base):
            w = _word_of(n[:-len(base)], False)
            if w:
                hit = (1, w[1], "the word '%s' and the value's name" % w[0])
        if hit is None and prefix and n.startswith(prefix) and len(n) > len(prefix):
            w = _word_of(n[len(prefix):], True)
            if w and w[2] and len(w[2]) >= 3 and w[2].lower() in base[len(prefix):].lower():
                hit = (2, w[1], "the prefix %s, '%s' of the value's name and the word '%s'"
                       % (prefix, w[2], w[0]))
        if hit is None and ln.startswith(lb) and n[len(base):].strip("_").lower() in STAT_WORDS:
            v = _val_decides(q)
            if v is not None:
                hit = (3, v, "the value's name and '%s' with a VAL_ table" % n[len(base):].strip("_"))
        if hit is None:
            continue
        rank, bad, why = hit
        v = _val_decides(q)
        if v is not None and v != bad:
            why += "; its VAL_ table names %d invalid" % v
            bad = v
        found.append((rank, q, bad, why))
    return found


def choose_qualifier(frame, sig, bit_of, dlc):
    """(q, invalid value, note) or (None, None, note)."""
    cands = []
    late = []
    for rank, q, bad, why in qualifier_candidates(frame, sig, bit_of):
        if bit_of(q) // 8 >= dlc:
            late.append(q.name)
            continue
        cands.append((rank, q, bad, why))
    if not cands:
        note = "no qualifier bit (no 1-bit signal of %s named as the value's qualifier%s)" % (
            frame.name, "; %s lies beyond the DLC %d" % (", ".join(late), dlc) if late else "")
        return None, None, note
    best = min(c[0] for c in cands)
    top = [c for c in cands if c[0] == best]
    if len(top) > 1:
        return None, None, ("no qualifier bit: %s are equally good candidates; choose one with --qualifier "
                            "%s.%s=%s.QSIG:invalid-when=0|1" % (" and ".join(c[1].name for c in top), frame.name,
                                                               sig.name, frame.name))
    rank, q, bad, why = top[0]
    return q, bad, "qualifier %s (bit %d, invalid when %d): %s" % (q.name, bit_of(q), bad, why)


# ---------------------------------------------------------------- frame format

def frame_kind(name, size, vformat, given, is_fd):
    """(fd, data length, why) of a message of DLC size whose VFrameFormat
    reads vformat (None: not given; given: by the message's own BA_, not the
    default); RuleRefusal when they contradict."""
    size = int(size)
    if size > FD_LENGTHS[-1]:
        raise RuleRefusal("message %s: DLC %d, more than the %d bytes of an FD frame" % (name, size, FD_LENGTHS[-1]))
    if vformat in FD_FORMATS or is_fd:
        fd, why = True, "VFrameFormat %s" % (vformat or "FD")
    elif vformat in CLASSIC_FORMATS and (given or size <= CLASSIC_MAX_DLEN):
        if size > CLASSIC_MAX_DLEN:
            raise RuleRefusal("message %s: VFrameFormat %s (a classic frame, at most %d bytes) but DLC %d"
                              % (name, vformat, CLASSIC_MAX_DLEN, size))
        fd, why = False, "VFrameFormat %s" % vformat
    elif size > CLASSIC_MAX_DLEN:
        fd, why = True, "DLC %d: more than a classic frame carries (%s)" % (
            size, "the VFrameFormat default %s is not the message's own" % vformat if vformat
            else "no VFrameFormat says so")
    else:
        fd, why = False, "classic (no VFrameFormat%s)" % (" %s" % vformat if vformat else "")
    length = size
    if fd and size > CLASSIC_MAX_DLEN and size not in FD_LENGTHS:
        length = next(n for n in FD_LENGTHS if n > size)
        why += "; DLC %d is no FD length, the frame is padded to %d" % (size, length)
    return fd, length, why


def frame_kind_on_bus(name, fd, length, why, n_fd, n_classic):
    """(fd, why) of a message once a log shows how the bus carries it.
    Many DBC files mark every message CAN FD (VFrameFormat StandardCAN_FD
    by default or per message) although a classic bus carries it: an 8-byte
    "FD" message that the log shows only in classic frames is classic (and
    the other way round). A message longer than 8 bytes is FD whatever the
    log says; without frames of it in the log the DBC decides."""
    if length > CLASSIC_MAX_DLEN or (n_fd > 0) == (n_classic > 0):
        return fd, why
    on_bus = n_fd > 0
    if on_bus == fd:
        return fd, why
    return on_bus, "%s, but the log carries %s in %d %s frames and no %s frame: %s" % (
        why, name, n_fd if on_bus else n_classic, "FD" if on_bus else "classic",
        "classic" if on_bus else "FD", "FD" if on_bus else "classic")


# ---------------------------------------------------------------- E2E Profile 5

def _plain(s):
    return s.mux_val is None and not getattr(s, "muxer_for_signal", None) and not s.is_multiplexer \
        and not s.is_signed and not s.is_float


def _in_byte(s, k, bit_of):
    """s is 8 bits exactly filling byte k."""
    if int(s.size) != 8:
        return False
    return bit_of(s) == 8 * k if s.is_little_endian else bit_of(s) == 8 * k + 7


def p05_blocks(frame, bit_of):
    """[(offset byte, CRC signal, counter signal)] of the message, by offset."""
    out = []
    for c in frame.signals:
        if not (CRC_NAME.search(c.name) and int(c.size) == 16 and c.is_little_endian and _plain(c)
                and bit_of(c) % 8 == 0):
            continue
        off = bit_of(c) // 8
        ctrs = [s for s in frame.signals if s is not c and COUNTER_NAME.search(s.name) and _plain(s)
                and _in_byte(s, off + 2, bit_of)]
        if len(ctrs) == 1:
            out.append((off, c, ctrs[0]))
    return sorted(out, key=lambda b: b[0])


def p05_layout(frame, sig, bit_of, length):
    """(offset byte, CRC signal, counter signal) of the message's one P05
    block, or RuleRefusal saying why it has none."""
    blocks = [b for b in p05_blocks(frame, bit_of) if b[0] + 3 <= length]
    if not blocks:
        raise RuleRefusal("message %s has no P05 layout (a 16-bit Intel CRC or checksum signal on a byte "
                          "boundary with an 8-bit counter in the byte after it)" % frame.name)
    if len(blocks) > 1:
        raise RuleRefusal("message %s has %d CRC-16 blocks (bytes %s), each CRC over its own block; the "
                          "monitor's P05 takes one CRC over the whole frame"
                          % (frame.name, len(blocks), ", ".join(str(b[0]) for b in blocks)))
    if sig in blocks[0][1:]:
        raise RuleRefusal("%s is the message's P05 CRC or counter" % sig.name)
    return blocks[0]


def block_counter(frame, sig, bit_of):
    """The counter of the P05-like block holding sig, when the message has
    several blocks; else None."""
    blocks = p05_blocks(frame, bit_of)
    if len(blocks) < 2:
        return None
    mine = [b for b in blocks if b[0] <= bit_of(sig) // 8]   # the start bit's byte lies in the block
    return mine[-1][2] if mine else None


if __name__ == "__main__":
    import helptext
    helptext.module_main(__doc__, "tools/vcalib_rules.py")
