# SPDX-License-Identifier: MIT
"""A DBC file as it is found in the field, read for the messages asked for.

Community DBC files carry lines that no reader accepts: an 11-bit identifier
above 0x7FF without the extended flag, a multiplexer indicator without its
value (`m :`), a cut line. canmatrix skips such a line with a message that
names its own line count, and a bad BO_ line even hands its signals to the
message before it. So the file is checked here first, statement by
statement, against the DBC grammar of the statements the calibration needs
(BO_ with its SG_ lines, CM_, BA_, VAL_, SG_MUL_VAL_, SIG_VALTYPE_), and:

  - a bad BO_ or SG_ line of a message that was not asked for is dropped, with
    the message's whole block (BO_, its SG_ lines and every statement that
    names its identifier), and warned about once, with its real line
    number and the reason;
  - a bad statement without a message (a global definition) is dropped
    with a warning;
  - a bad statement of a message asked for refuses the file, naming the
    line: its layout would be incomplete;
  - an identifier above 0x7FF without the extended flag (bit 31) is a bad
    BO_ line like any other: a classic frame cannot carry it, and reading
    it as a 29-bit identifier would be a guess (canmatrix refuses it too).

The rest goes to canmatrix unchanged (the original bytes of the kept lines,
so every number is read exactly as in the file), but for one spelling: an
ENUM attribute's value written as its text ("StandardCAN_FD") instead of its
index (14) is handed over as the index, which is all canmatrix reads (it
stops at the text). A text the ENUM does not list is a bad statement.
Messages and signals are found by their DBC name or by their long name (the
SystemMessageLongSymbol and SystemSignalLongSymbol attributes, which
canmatrix makes the names).

A message's frame format (Index.frame_format) is its VFrameFormat attribute
read here, as the ENUM of its BA_DEF_ lists the values: the value by index or
by text, else the BA_DEF_DEF_ default (and whether the message's own BA_
said it); None without the attribute.
"""
import contextlib
import io
import os
import re
import tempfile
import warnings

NUM = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
NAME = r"[A-Za-z_][A-Za-z0-9_]*"
STR = r'"(?:[^"\\]|\\.)*"'
EXT_FLAG = 0x80000000
BLOCK_KINDS = ("BO_", "SG_")   # a bad one of these takes its whole message along
MULTILINE = ("CM_", "BA_", "BA_DEF_", "BA_DEF_DEF_", "BA_DEF_REL_", "BA_REL_", "EV_")
STARTS = re.compile(r"^\s*(?:BO_|SG_|CM_|BA_|BA_DEF_|BA_DEF_DEF_|VAL_|VAL_TABLE_|SG_MUL_VAL_|SIG_VALTYPE_|"
                    r"BO_TX_BU_|EV_|BU_|BS_|NS_|VERSION|SIG_GROUP_) ")

GRAMMAR = {
    "BO_": re.compile(r"^BO_ +(\d+) +(%s) *: *(\d+) +(%s)\s*$" % (NAME, NAME)),
    "SG_": re.compile(r"^SG_ +(%s) *(M|m\d+M?)? *: *(\d+)\|(\d+)@([01])([+-]) *\( *(%s) *, *(%s) *\) *"
                      r"\[ *(%s) *\| *(%s) *\] *(%s)(?: +(%s(?: *, *%s)*))? *$"
                      % (NAME, NUM, NUM, NUM, NUM, STR, NAME, NAME)),
    "CM_": re.compile(r"^CM_ +(?:(?:BO_ +(\d+)|SG_ +(\d+) +(%s)|BU_ +%s|EV_ +%s) +)?%s *;\s*$"
                      % (NAME, NAME, NAME, STR), re.S),
    "BA_": re.compile(r"^BA_ +%s +(?:(?:BO_ +(\d+)|SG_ +(\d+) +(%s)|BU_ +%s|EV_ +%s) +)?(?:%s|%s) *;\s*$"
                      % (STR, NAME, NAME, NAME, NUM, STR), re.S),
    "VAL_": re.compile(r"^VAL_ +(?:(\d+) +)?(%s)(?: +%s +%s)* *;\s*$" % (NAME, NUM, STR), re.S),
    "SG_MUL_VAL_": re.compile(r"^SG_MUL_VAL_ +(\d+) +(%s) +(%s) +\d+ *- *\d+(?: *, *\d+ *- *\d+)* *;\s*$"
                              % (NAME, NAME)),
    "SIG_VALTYPE_": re.compile(r"^SIG_VALTYPE_ +(\d+) +(%s) *:? *[0-3] *;\s*$" % NAME),
}
# the message a statement belongs to, read leniently (the statement may be bad)
OWNER = [
    re.compile(r"^BO_ +(\d+)\b"),
    re.compile(r"^CM_ +(?:BO_|SG_) +(\d+)\b"),
    re.compile(r'^BA_ +"[^"]*" +(?:BO_|SG_) +(\d+)\b'),
    re.compile(r"^(?:VAL_|SG_MUL_VAL_|SIG_VALTYPE_|BO_TX_BU_|SIG_GROUP_|SIG_TYPE_REF_) +(\d+)\b"),
    re.compile(r"^BA_REL_ +\"[^\"]*\" +BU_(?:SG|BO)_REL_ +%s +(?:SG_ +)?(\d+)\b" % NAME),
]
ENUM_DEF = re.compile(r'^BA_DEF_ +(BO_|SG_|BU_|EV_)? *"(%s)" +ENUM +(.*?) *;\s*$' % NAME, re.S)
ENUM_DEFAULT = re.compile(r'^BA_DEF_DEF_ +"(%s)" +(%s|%s) *;\s*$' % (NAME, STR, NUM), re.S)
# BA_ "name" [object] value; : 1 the text before the value, 2 the name, 3 the object, 4 the value
BA_VALUE = re.compile(r'^(BA_ +"(%s)" +(BO_ +\d+|SG_ +\d+ +%s|BU_ +%s|EV_ +%s)? *)(%s|%s) *;\s*$'
                      % (NAME, NAME, NAME, NAME, STR, NUM), re.S)
LONG_MSG = re.compile(r'^BA_ +"SystemMessageLongSymbol" +BO_ +(\d+) +"([^"]*)" *;')
LONG_SIG = re.compile(r'^BA_ +"SystemSignalLongSymbol" +SG_ +(\d+) +(%s) +"([^"]*)" *;' % NAME)


class DbcRefusal(Exception):
    """The file cannot serve the request; the text is one line."""


class Statement:
    __slots__ = ("first", "last", "text", "kind", "owner", "bad", "enum_index")

    def __init__(self, first, last, text):
        self.first, self.last, self.text = first, last, text   # 0-based line indices
        self.kind = text.split(None, 1)[0] if text.strip() else ""
        self.owner = None
        self.bad = None
        self.enum_index = None   # a BA_ of an ENUM written as text: the index to hand over


def _statements(lines):
    """Statements of the file: (first line, last line, text). A statement ends
    at its line's end unless a quoted string is still open (comments and
    attribute values may run over several lines). The NS_ block's indented
    keyword list is one statement."""
    out, i, n = [], 0, len(lines)
    while i < n:
        s = lines[i].strip()
        if not s:
            i += 1
            continue
        first, text = i, s
        if s.startswith("NS_"):
            while i + 1 < n and (not lines[i + 1].strip() or lines[i + 1][:1] in (" ", "\t")):
                i += 1
            out.append(Statement(first, i, "NS_"))
            i += 1
            continue
        # only comments and attribute texts run over lines; a quote left open
        # elsewhere (a bad line) ends with its line, and so does one before
        # a line that starts a statement
        while (_open_quote(text) and i + 1 < n and text.split(None, 1)[0] in MULTILINE
               and not STARTS.match(lines[i + 1])):
            i += 1
            text += "\n" + lines[i].rstrip("\r")
        out.append(Statement(first, i, text))
        i += 1
    return out


def _open_quote(text):
    q = False
    k = 0
    while k < len(text):
        c = text[k]
        if c == "\\" and q:
            k += 2
            continue
        if c == '"':
            q = not q
        k += 1
    return q


def _check(st, in_block):
    """The reason a statement is bad, or None."""
    kind = st.kind
    if kind == "SG_" and not in_block:
        return "signal line outside a BO_ message"
    rx = GRAMMAR.get(kind)
    if rx is None:
        return None
    m = rx.match(st.text.strip() if kind != "CM_" else st.text.strip())
    if m is None:
        if kind == "SG_":
            mm = re.match(r"^SG_ +%s +(\S+) *:" % NAME, st.text.strip())
            if mm and not re.match(r"^(M|m\d+M?)$", mm.group(1)):
                return "malformed multiplexer indicator %r" % mm.group(1)
        return "not a valid %s statement" % kind
    if kind == "BO_":
        cid = int(m.group(1))
        if cid & EXT_FLAG:
            if cid & ~EXT_FLAG > 0x1FFFFFFF:
                return "identifier 0x%X beyond 29 bits" % (cid & ~EXT_FLAG)
        elif cid > 0x7FF:
            return ("identifier 0x%X above 0x7FF without the extended flag (bit 31): "
                    "not an 11-bit identifier" % cid)
    if kind == "SG_":
        if int(m.group(4)) == 0:
            return "signal of length 0"
    return None


def _owner(st, block_id):
    if st.kind == "SG_":
        return block_id
    for rx in OWNER:
        m = rx.match(st.text.strip())
        if m:
            return int(m.group(1))
    return None


class Index:
    """Names of the file as written: message name <-> identifier, long names."""

    def __init__(self):
        self.msg_id = {}      # DBC name or long name -> identifier (as in the file)
        self.msg_line = {}    # identifier -> 1-based line of its BO_
        self.long_sig = {}    # (identifier, long name) -> DBC name
        self.enums = {}       # ENUM attribute name -> [value texts] (BA_DEF_)
        self.defaults = {}    # attribute name -> BA_DEF_DEF_ value (text unquoted, or number text)
        self.msg_attr = {}    # (identifier, attribute name) -> BA_ value (text unquoted, or number text)

    def lookup(self, name):
        return self.msg_id.get(name)

    def enum_text(self, name, value):
        """An ENUM attribute's value as its text: a number is the index into
        the BA_DEF_'s list; None when it lists no such value."""
        values = self.enums.get(name)
        if values is None:
            return None
        if re.match(r"^\d+$", value):
            k = int(value)
            return values[k] if k < len(values) else None
        return value if value in values else None

    def frame_format(self, cid):
        """(the message's VFrameFormat text ("StandardCAN_FD", ...) or None,
        True when its own BA_ says so, False for the default or nothing)."""
        given = (cid, "VFrameFormat") in self.msg_attr
        v = self.msg_attr.get((cid, "VFrameFormat"), self.defaults.get("VFrameFormat"))
        if v is None:
            return None, False
        return (self.enum_text("VFrameFormat", v) if "VFrameFormat" in self.enums else v), given


def _unquote(v):
    return v[1:-1] if v.startswith('"') else v


def _attributes(sts, idx):
    """ENUM lists, defaults and message attribute values into idx; an ENUM
    value written as text is marked for its index, or bad when not listed."""
    for st in sts:
        t = st.text.strip()
        m = ENUM_DEF.match(t)
        if m and st.bad is None:
            idx.enums[m.group(2)] = [_unquote(v.strip()) for v in re.findall(r'"(?:[^"\\]|\\.)*"|[^,]+',
                                                                             m.group(3))]
            continue
        m = ENUM_DEFAULT.match(t)
        if m:
            idx.defaults[m.group(1)] = _unquote(m.group(2))
    for st in sts:
        m = BA_VALUE.match(st.text.strip()) if st.kind == "BA_" and st.bad is None else None
        if m is None:
            continue
        name, obj, value = m.group(2), m.group(3) or "", m.group(4)
        if name in idx.enums and value.startswith('"'):
            text = _unquote(value)
            if text not in idx.enums[name]:
                st.bad = "value %s of ENUM attribute %s is none of its values" % (value, name)
                continue
            st.enum_index = idx.enums[name].index(text)
        if obj.startswith("BO_"):
            idx.msg_attr[(int(obj.split()[1]), name)] = _unquote(value)


def scan(path):
    """(lines, statements, index) of a DBC file; DbcRefusal when unreadable."""
    try:
        with open(path, "rb") as f:
            raw = f.read()
    except OSError as e:
        raise DbcRefusal("cannot read DBC %s: %s" % (path, e.strerror or e))
    if re.search(rb"(^|\n)BO_\s", raw) is None:
        raise DbcRefusal("%s is not a DBC file (no BO_ message)" % path)
    blines = raw.split(b"\n")
    lines = [b.decode("latin-1").rstrip("\r") for b in blines]
    sts = _statements(lines)
    idx = Index()
    block = None
    for st in sts:
        if st.kind == "BO_":
            block = None
        st.owner = _owner(st, block)
        st.bad = _check(st, block is not None or st.kind != "SG_")
        if st.kind == "BO_":
            block = st.owner
            m = re.match(r"^BO_ +(\d+) +(%s)" % NAME, st.text.strip())
            if m:
                idx.msg_id.setdefault(m.group(2), int(m.group(1)))
                idx.msg_line.setdefault(int(m.group(1)), st.first + 1)
        elif st.kind != "SG_":
            block = None
        m = LONG_MSG.match(st.text.strip())
        if m:
            idx.msg_id.setdefault(m.group(2), int(m.group(1)))
        m = LONG_SIG.match(st.text.strip())
        if m:
            idx.long_sig[(int(m.group(1)), m.group(3))] = m.group(2)
    _attributes(sts, idx)
    return blines, sts, idx


def load(path, wanted):
    """canmatrix's database of the file with the lines the request does not
    need and no reader accepts dropped.

    wanted: message names (DBC or long names) asked for.
    Returns (db, notes, idx): notes are one-line warnings of the lines
    skipped; idx the Index of the file as written (message ids and lines,
    ENUM lists, attribute defaults and values) that canmatrix may lose.
    DbcRefusal when the file or a statement of a wanted message is bad."""
    blines, sts, idx = scan(path)
    want_ids = {idx.lookup(n) for n in wanted} - {None}
    drop_ids, notes = set(), []
    for st in sts:
        if st.bad is None:
            continue
        where = "%s:%d" % (path, st.first + 1)
        if st.kind not in BLOCK_KINDS:
            # a comment or an attribute, a value table: only this statement
            # goes, unless the monitor needs it (a wanted message's VAL_ or BA_)
            if st.owner is not None and st.owner in want_ids and st.kind != "CM_":
                raise DbcRefusal("%s: %s, of message %s which is asked for" % (where, st.bad,
                                 _name_of(idx, st.owner)))
            notes.append("%s: skipped (%s)" % (where, st.bad))
            continue
        if st.owner is not None and st.owner in want_ids:
            raise DbcRefusal("%s: %s, in message %s which is asked for" % (where, st.bad,
                             _name_of(idx, st.owner)))
        if st.owner is not None:
            drop_ids.add(st.owner)
            notes.append("%s: skipped (%s; message %s with it, not asked for)"
                         % (where, st.bad, _name_of(idx, st.owner)))
        else:
            notes.append("%s: skipped (%s)" % (where, st.bad))
    keep = [True] * len(blines)
    for st in sts:
        if (st.bad is not None) or (st.owner is not None and st.owner in drop_ids):
            for k in range(st.first, st.last + 1):
                keep[k] = False
    kept_lines = [k for k in range(len(blines)) if keep[k]]
    for st in sts:   # ENUM values written as text: the index, as canmatrix reads them
        if st.enum_index is not None and keep[st.first] and st.first == st.last:
            line = blines[st.first].decode("latin-1")
            m = BA_VALUE.match(line.strip())
            blines[st.first] = (m.group(1) + str(st.enum_index) + ";").encode("latin-1")
    fd, tmp = tempfile.mkstemp(prefix="vcalib-", suffix=".dbc")
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(b"\n".join(blines[k] for k in kept_lines) + b"\n")
        db, residual = _canmatrix(tmp, path)
    finally:
        os.unlink(tmp)
    for text in residual:   # what canmatrix still skipped: found by its content
        real = next((k for k in kept_lines if blines[k].strip() == text.strip()), None)
        st = next((s for s in sts if real is not None and s.first <= real <= s.last), None)
        line = "%s:%s" % (path, real + 1 if real is not None else "?")
        if st is not None and st.owner in want_ids:
            raise DbcRefusal("%s: canmatrix cannot read this line of message %s, which is asked for"
                             % (line, _name_of(idx, st.owner)))
        notes.append("%s: skipped (canmatrix cannot read it)" % line)
    return db, notes, idx


def _name_of(idx, cid):
    names = [n for n, i in idx.msg_id.items() if i == cid]
    return names[0] if names else str(cid)


def _canmatrix(tmp, path):
    import logging
    logging.disable(logging.CRITICAL)  # canmatrix logs missing optional formats
    out = io.StringIO()
    try:
        with warnings.catch_warnings(), contextlib.redirect_stdout(out):
            warnings.simplefilter("ignore")
            import canmatrix.formats
            dbs = canmatrix.formats.loadp(tmp, import_type="dbc")
    except Exception as e:  # canmatrix raises many kinds on bad files
        raise DbcRefusal("cannot parse DBC %s: %s" % (path, str(e).splitlines()[0] if str(e)
                                                      else type(e).__name__))
    residual = []
    lines = out.getvalue().splitlines()
    for k, l in enumerate(lines):
        if l.startswith("error with line no:") and k + 1 < len(lines):
            t = lines[k + 1]
            try:
                import ast
                t = ast.literal_eval(t).decode("latin-1")
            except (ValueError, SyntaxError, AttributeError):
                pass
            residual.append(t)
    if len(dbs) != 1 or not list(dbs.values())[0].frames:
        raise DbcRefusal("%s holds no CAN database with messages" % path)
    return list(dbs.values())[0], residual


if __name__ == "__main__":
    import helptext
    helptext.module_main(__doc__, "tools/dbc_tolerant.py")
