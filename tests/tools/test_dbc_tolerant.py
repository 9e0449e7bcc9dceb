#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""tools/dbc_tolerant.py on small DBC files written here, statement by
statement, so that every line number below is known by construction.

The reference is canmatrix itself reading a clean copy (the same file
without the lines that should go): the messages kept must decode every
payload exactly as canmatrix decodes them from the clean copy, and the
messages dropped must be exactly the ones a bad line belongs to. The
reasons and refusals are the module's documented ones (its docstring).

prints "RESULT: N passed, M failed"
"""
import os
import random
import sys
import warnings

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks  # noqa: E402  (puts tools/ on the path)

import dbc_tolerant as T  # noqa: E402

HEAD = ['VERSION ""', "", "NS_ :", "    CM_", "    BA_DEF_", "", "BS_:", "", "BU_: ECU", ""]

# a good message asked for: two Intel signals, a comment, a value table
SPEED = ["BO_ 272 WheelSpeed: 8 ECU",
         ' SG_ WhlSpd_FL : 0|16@1+ (0.01,0) [0|655.35] "km/h" ECU',
         ' SG_ WhlSpd_FR : 16|16@1+ (0.01,0) [0|655.35] "km/h" ECU', ""]
# a good message asked for, Motorola, signed
PRESS = ["BO_ 288 BrakePress: 8 ECU",
         ' SG_ Press : 7|12@0- (0.1,-10) [-204.8|204.7] "bar" ECU', ""]
# 0x800 = 2048 without bit 31: not an 11-bit identifier
BAD_ID = ["BO_ 2048 Gateway: 8 ECU",
          ' SG_ GwCounter : 0|4@1+ (1,0) [0|15] "" ECU', ""]
# a multiplexer indicator without its value
BAD_MUX = ["BO_ 304 Chassis: 8 ECU",
           ' SG_ ChMux M : 0|4@1+ (1,0) [0|15] "" ECU',
           ' SG_ ChVal m : 8|8@1+ (1,0) [0|255] "" ECU', ""]
TAIL_DEFS = ['BA_DEF_ BO_ "VFrameFormat" ENUM "StandardCAN","ExtendedCAN","StandardCAN_FD";',
             'BA_DEF_ BO_ "SystemMessageLongSymbol" STRING ;',
             'BA_DEF_DEF_ "VFrameFormat" "StandardCAN";',
             'BA_DEF_DEF_ "SystemMessageLongSymbol" "";']


def write(tmp, name, lines):
    path = os.path.join(tmp, name)
    with open(path, "w", encoding="latin-1") as f:
        f.write("\n".join(lines) + "\n")
    return path


def line_of(lines, text):
    """1-based line of text in the file as written."""
    return lines.index(text) + 1


def load(path, wanted):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return T.load(path, wanted)


def refusal(path, wanted):
    try:
        load(path, wanted)
    except T.DbcRefusal as e:
        return str(e)
    return None


def canmatrix_db(path):
    import contextlib
    import io
    import logging
    import canmatrix.formats
    logging.disable(logging.CRITICAL)
    with warnings.catch_warnings(), contextlib.redirect_stdout(io.StringIO()):
        warnings.simplefilter("ignore")
        return list(canmatrix.formats.loadp(path, import_type="dbc").values())[0]


def decodes_alike(db, ref, names, seed):
    rng = random.Random(seed)
    for name in names:
        a, b = db.frame_by_name(name), ref.frame_by_name(name)
        if a is None or b is None:
            return False
        for _ in range(200):
            data = bytearray(rng.randrange(256) for _ in range(8))
            ra = {k: v.raw_value for k, v in a.decode(data).items()}
            rb = {k: v.raw_value for k, v in b.decode(data).items()}
            if ra != rb or set(ra) != {s.name for s in b.signals}:
                return False
    return True


def skipped_unwanted(c, tmp):
    """A bad BO_ and a bad SG_ of messages not asked for: each dropped with
    its whole block and every statement naming its identifier."""
    extra = ['CM_ BO_ 2048 "gateway frame";', 'VAL_ 2048 GwCounter 0 "zero" 15 "max" ;',
             'CM_ SG_ 304 ChVal "page value";', 'CM_ SG_ 272 WhlSpd_FL "front left";',
             'VAL_ 288 Press 2047 "invalid" ;']
    lines = HEAD + SPEED + BAD_ID + PRESS + BAD_MUX + TAIL_DEFS + extra
    path = write(tmp, "field.dbc", lines)
    clean = write(tmp, "clean.dbc", HEAD + SPEED + PRESS + TAIL_DEFS +
                  ['CM_ SG_ 272 WhlSpd_FL "front left";', 'VAL_ 288 Press 2047 "invalid" ;'])
    db, notes, idx = load(path, ["WheelSpeed", "BrakePress"])
    ref = canmatrix_db(clean)
    c.check(sorted(f.name for f in db.frames) == ["BrakePress", "WheelSpeed"],
            "the messages with a bad line are dropped, the others kept (%s)"
            % sorted(f.name for f in db.frames))
    c.check(decodes_alike(db, ref, ["WheelSpeed", "BrakePress"], 1),
            "the kept messages decode as canmatrix decodes the clean copy (200 payloads each)")
    bo = line_of(lines, BAD_ID[0])
    sg = line_of(lines, BAD_MUX[2])
    want_bo = "%s:%d: skipped (identifier 0x800 above 0x7FF without the extended flag" % (path, bo)
    want_sg = "%s:%d: skipped (malformed multiplexer indicator 'm'" % (path, sg)
    c.check(any(n.startswith(want_bo) and "message Gateway with it" in n for n in notes),
            "the bad identifier is named by its line %d and its message (%s)" % (bo, notes))
    c.check(any(n.startswith(want_sg) and "message Chassis with it" in n for n in notes),
            "the bare 'm' indicator is named by its line %d (%s)" % (sg, notes))
    c.check(len(notes) == 2, "one note per bad line, none for the statements dropped along (%d)"
            % len(notes))
    c.check(ref.frame_by_name("WheelSpeed").signal_by_name("WhlSpd_FL").comment == "front left"
            and db.frame_by_name("WheelSpeed").signal_by_name("WhlSpd_FL").comment == "front left",
            "a comment of a kept message is kept")
    c.check(idx.lookup("WheelSpeed") == 272 and idx.lookup("Gateway") == 2048
            and idx.msg_line[272] == line_of(lines, SPEED[0]),
            "the index holds every BO_ as written, with its line")


def refusals(c, tmp):
    lines = HEAD + SPEED + BAD_ID + PRESS + TAIL_DEFS
    path = write(tmp, "wanted_bad.dbc", lines)
    msg = refusal(path, ["Gateway"])
    c.check(msg is not None and msg.startswith("%s:%d: identifier 0x800" % (path, line_of(lines, BAD_ID[0])))
            and msg.endswith("in message Gateway which is asked for"),
            "a bad BO_ of a message asked for refuses the file, naming the line (%s)" % msg)
    bad_val = 'VAL_ 288 Press 2047 "invalid ;'
    lines = HEAD + SPEED + PRESS + TAIL_DEFS + [bad_val]
    path = write(tmp, "wanted_val.dbc", lines)
    msg = refusal(path, ["BrakePress"])
    c.check(msg == "%s:%d: not a valid VAL_ statement, of message BrakePress which is asked for"
            % (path, line_of(lines, bad_val)),
            "a bad VAL_ of a message asked for refuses the file (%s)" % msg)
    db, notes, _ = load(path, ["WheelSpeed"])
    c.check(notes == ["%s:%d: skipped (not a valid VAL_ statement)" % (path, line_of(lines, bad_val))]
            and sorted(f.name for f in db.frames) == ["BrakePress", "WheelSpeed"],
            "the same VAL_ of a message not asked for: only that statement goes (%s)" % notes)
    # a 29-bit identifier needs bit 31; beyond 29 bits it is bad
    ext_bad = "BO_ %d Far: 8 ECU" % (0x80000000 | 0x20000000)
    lines = HEAD + SPEED + [ext_bad, ' SG_ FarSig : 0|8@1+ (1,0) [0|255] "" ECU', ""] + TAIL_DEFS
    path = write(tmp, "ext.dbc", lines)
    msg = refusal(path, ["Far"])
    c.check(msg is not None and "identifier 0x20000000 beyond 29 bits" in msg,
            "an extended identifier beyond 29 bits is a bad BO_ (%s)" % msg)
    ok_ext = "BO_ %d Far: 8 ECU" % (0x80000000 | 0x18FEF100)
    path = write(tmp, "ext_ok.dbc", HEAD + SPEED + [ok_ext, ' SG_ FarSig : 0|8@1+ (1,0) [0|255] "" ECU', ""]
                 + TAIL_DEFS)
    db, notes, _ = load(path, ["Far"])
    c.check(notes == [] and db.frame_by_name("Far").arbitration_id.id == 0x18FEF100
            and db.frame_by_name("Far").arbitration_id.extended,
            "bit 31 makes a 29-bit identifier: 0x18FEF100, extended")
    zero = ' SG_ Zero : 0|0@1+ (1,0) [0|0] "" ECU'
    lines = HEAD + SPEED[:-1] + [zero, ""] + TAIL_DEFS
    path = write(tmp, "zero.dbc", lines)
    msg = refusal(path, ["WheelSpeed"])
    c.check(msg == "%s:%d: signal of length 0, in message WheelSpeed which is asked for"
            % (path, line_of(lines, zero)), "a signal of length 0 is bad (%s)" % msg)
    path = write(tmp, "not.dbc", ["just some text", "CM_ \"no message\";"])
    msg = refusal(path, ["X"])
    c.check(msg == "%s is not a DBC file (no BO_ message)" % path, "a file without BO_ (%s)" % msg)
    msg = refusal(os.path.join(tmp, "absent.dbc"), ["X"])
    c.check(msg is not None and msg.startswith("cannot read DBC %s" % os.path.join(tmp, "absent.dbc")),
            "a missing file is a refusal, not a traceback (%s)" % msg)


def globals_and_multiline(c, tmp):
    """A bad global statement goes alone; a comment over three lines is one
    statement, so the line after it keeps its number."""
    bad_global = 'BA_ "BusType" ;'   # a global attribute without its value
    long_cm = ['CM_ BO_ 272 "first line', "second line", 'third line";']
    bad_after = 'BA_ "GenMsgCycleTime" BO_ 2048 ;'
    lines = HEAD + SPEED + PRESS + TAIL_DEFS + [bad_global] + long_cm + [bad_after]
    path = write(tmp, "globals.dbc", lines)
    db, notes, _ = load(path, ["WheelSpeed"])
    c.check(sorted(f.name for f in db.frames) == ["BrakePress", "WheelSpeed"],
            "both messages kept (%s)" % sorted(f.name for f in db.frames))
    c.check(db.frame_by_name("WheelSpeed").comment == "first line\nsecond line\nthird line",
            "a comment over three lines is read whole (%r)" % db.frame_by_name("WheelSpeed").comment)
    want = ["%s:%d: skipped (not a valid BA_ statement)" % (path, line_of(lines, bad))
            for bad in (bad_global, bad_after)]
    c.check(notes == want, "the bad global BA_ goes alone, and the line after the comment keeps "
            "its number %d (%s)" % (line_of(lines, bad_after), notes))


def attributes(c, tmp):
    """ENUM values by index or by text, the default, long names."""
    lines = HEAD + SPEED + PRESS + BAD_ID[:-1] + [""] + TAIL_DEFS + [
        'BA_ "VFrameFormat" BO_ 272 "StandardCAN_FD";',
        'BA_ "VFrameFormat" BO_ 288 1;',
        'BA_ "SystemMessageLongSymbol" BO_ 288 "BrakePressure_Front_Axle";']
    path = write(tmp, "attrs.dbc", lines)
    db, notes, idx = load(path, ["WheelSpeed", "BrakePressure_Front_Axle"])
    c.check(idx.frame_format(272) == ("StandardCAN_FD", True),
            "an ENUM value written as text is read as its text (%s)" % (idx.frame_format(272),))
    c.check(idx.frame_format(288) == ("ExtendedCAN", True),
            "an ENUM value by index 1 is the list's second text (%s)" % (idx.frame_format(288),))
    c.check(idx.frame_format(2048) == ("StandardCAN", False),
            "without its own BA_: the BA_DEF_DEF_ default, marked as such (%s)" % (idx.frame_format(2048),))
    c.check(idx.lookup("BrakePressure_Front_Axle") == 288, "a long name finds its message")
    # canmatrix alone stops at the text; handed the index, it reads the text back
    try:
        canmatrix_db(path)
        raw_fails = False
    except ValueError:
        raw_fails = True
    got = {f.name: f.attributes.get("VFrameFormat") for f in db.frames}
    c.check(raw_fails and got.get("WheelSpeed") == "StandardCAN_FD"
            and got.get("BrakePressure_Front_Axle") == "ExtendedCAN",
            "canmatrix refuses the text, reads the index handed over as the text; "
            "the long name is the name (%s)" % got)
    bad = 'BA_ "VFrameFormat" BO_ 288 "FlexRay";'
    lines2 = HEAD + SPEED + PRESS + TAIL_DEFS + [bad]
    path = write(tmp, "attrs_bad.dbc", lines2)
    msg = refusal(path, ["BrakePress"])
    c.check(msg is not None and msg.startswith("%s:%d: value \"FlexRay\" of ENUM attribute VFrameFormat is none"
                                               % (path, line_of(lines2, bad))),
            "a text the ENUM does not list is a bad statement (%s)" % msg)
    path = write(tmp, "no_attr.dbc", HEAD + SPEED)
    _, _, idx = load(path, ["WheelSpeed"])
    c.check(idx.frame_format(272) == (None, False), "no VFrameFormat at all: (None, False)")


def main():
    return Checks.run(skipped_unwanted, refusals, globals_and_multiline, attributes)


if __name__ == "__main__":
    sys.exit(main())
