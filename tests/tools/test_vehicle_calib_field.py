#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""tools/vehicle_calib.py on DBC files as they are in the field (fixtures in
tests/tools/fixtures/field/, written for these tests in the layouts community files
have), pure Python (the calibrations are checked by stub_calib_check.py;
calib-check's own refusals by a stand-in that refuses):

  - plausible range = the declared [min|max]; [0|0] and --ignore-dbc-range
    give the signal's whole range;
  - "not available": the all-ones code where the declared range excludes it
    (--keep-all-ones keeps it a value), VAL_ texts meaning no value, inside
    codes first, three inside refused naming them and --na-raw, --na-raw;
  - qualifier bits: the prefix rule (BS7_Druckvalid), _Flt, _Stat with a
    VAL_ table, long names; two equal candidates: none, and why; --qualifier
    by hand; refusals: another message, more than one bit, beyond the DLC;
  - tolerant reading: a malformed multiplexer indicator, an identifier above
    0x7FF without the extended flag and a bad comment in messages nobody asks
    for are skipped with their real line numbers, the requested signals
    decode as canmatrix decodes them from a hand-fixed copy; asked for, they
    refuse naming the real line;
  - multiplexing keys: SG_MUL_VAL_ ranges, cascaded selectors (mux_, mux2_),
    independent multiplexors, two ranges / three selectors refused; periods
    of multiplexed inputs (GenMsgCycleTime and a log);
  - --bus: periods on that interface, input_iface; a message on two
    interfaces without --bus refused; the log's counts per input;
  - unit-less signals with --force-unit/--unit-scale (folded exactly),
    --speed-scale, --torque-share per corner;
  - exact numbers (2^-10, 2147483647, 17 significant digits);
  - calib-check: its refusal printed, nothing written; a missing checker
    refused with "run make"; --help names every option with a help text.
Prints "RESULT: N passed, M failed".
"""
import os
import random
import re
import sys
import tempfile
import warnings
# tests/ of this checkout, and the folders its helper modules live in
_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, d) for d in ("support", os.path.join("support", "reference"), "host-sim", "tools")]

HERE = os.path.dirname(os.path.abspath(__file__))
import vehref  # noqa: E402

ESC = os.path.join(HERE, "fixtures", "field", "field_esc.dbc")
MUX = os.path.join(HERE, "fixtures", "field", "field_mux.dbc")
PRESS = ["--force", "Brems_7.BS7_Hauptdruck", "--piston-area-mm2", "2290"]
SPEED = ["--speed", "WhlRad.WhlRad_FR"]


def tool(args, checker=None):
    return vehref.run_tool([vehref.PY, vehref.TOOL] + args, checker=checker)


def calib(r, what, args, checker=None):
    """(inputs, corners, notes, flat) of a run that must succeed."""
    rc, out, err = tool(args, checker)
    notes, other = vehref.notes_of(err)
    if not r.check(rc == 0 and not other, "%s: builds (%d: %s)" % (what, rc, other[:2])):
        return {}, {}, [], {}
    flat, inputs, corners = vehref.parse_calib(out)
    return inputs, corners, notes, flat


def by_signal(inputs, sig):
    for d in inputs.values():
        if d.get("signal") == sig:
            return d
    return {}


def refused(r, what, args, needles, checker=None):
    rc, out, err = tool(args, checker)
    ok = rc == 1 and out == "" and err.count("\n") == 1 and "Traceback" not in err
    ok = ok and all(n in err for n in needles)
    r.check(ok, "%s: one-line refusal naming %s (%d: %r)" % (what, needles, rc, err[:300]))
    return err


def line_of(path, text):
    """1-based number of the line starting with text (found here, not by the tool)."""
    with open(path, encoding="latin-1") as f:
        for n, line in enumerate(f, 1):
            if line.startswith(text):
                return n
    raise KeyError(text)


def na_of(d):
    return [vehref.ival(d, k) for k in ("na_raw", "na_raw2") if k in d]


def qual_of(d):
    return (vehref.ival(d, "qualifier_bit"), vehref.ival(d, "qualifier_invalid")) if "qualifier_bit" in d else None


def check_ranges_na(r):
    base = ["--dbc", ESC, "--corner", "FL"]
    inputs, _, notes, _ = calib(r, "pressure with a ...valid bit", base + SPEED + PRESS)
    p = by_signal(inputs, "Brems_7.BS7_Hauptdruck")
    r.check(p.get("min") == "0" and p.get("max") == "250", "declared [0|250] bar is the plausible range (%s..%s)"
            % (p.get("min"), p.get("max")))
    r.check(na_of(p) == [4095], "0xFFF (409.5 bar, beyond [0|250]) is not available: %s" % na_of(p))
    r.check(qual_of(p) == (29, 0), "BS7_Druckvalid (bit 29, invalid when 0) qualifies BS7_Hauptdruck: %s" % (qual_of(p),))
    r.check(any("BS7_Hauptdruck: qualifier BS7_Druckvalid" in n and "prefix BS7_" in n for n in notes),
            "the choice and its reason printed: %s" % [n for n in notes if "qualifier" in n][:2])
    s = by_signal(inputs, "WhlRad.WhlRad_FR")
    r.check(na_of(s) == [32766] and s.get("max") == "327.67",
            "VAL_ 'Unknown' 0x7FFE inside [0|327.67] is not available, all ones inside the range is a value: %s"
            % na_of(s))
    inputs, _, _, _ = calib(r, "Fault and Unknown beyond the range", base + ["--speed", "WhlRad.WhlRad_FL"] + PRESS)
    s = by_signal(inputs, "WhlRad.WhlRad_FL")
    r.check(na_of(s) == [32767, 32766] and s.get("max") == "327.65",
            "two codes beyond [0|327.65]: all ones first (%s)" % na_of(s))
    inputs, _, _, _ = calib(r, "--ignore-dbc-range", base + ["--speed", "WhlRad.WhlRad_FL"] + PRESS
                            + ["--ignore-dbc-range"])
    s = by_signal(inputs, "WhlRad.WhlRad_FL")
    p = by_signal(inputs, "Brems_7.BS7_Hauptdruck")
    r.check(s.get("min") == "-0.005" and s.get("max") == "327.67" and na_of(s) == [32767, 32766]
            and p.get("max") == "409.5" and na_of(p) == [],
            "--ignore-dbc-range: from -half a step to the top, VAL_ codes only (%s %s %s %s)"
            % (s.get("min"), s.get("max"), na_of(s), na_of(p)))
    inputs, _, _, _ = calib(r, "[0|0]", base + ["--speed", "WhlRad.WhlRad_RR"] + PRESS)
    s = by_signal(inputs, "WhlRad.WhlRad_RR")
    r.check(s.get("min") == "-0.005" and s.get("max") == "327.67" and na_of(s) == [],
            "declared [0|0]: the signal's whole range, no all-ones rule (%s..%s %s)"
            % (s.get("min"), s.get("max"), na_of(s)))
    inputs, _, _, _ = calib(r, "--keep-all-ones", base + SPEED + PRESS + ["--keep-all-ones"])
    r.check(na_of(by_signal(inputs, "Brems_7.BS7_Hauptdruck")) == [], "--keep-all-ones: 0xFFF is a value")
    refused(r, "three codes inside the range", base + ["--speed", "WhlRad.WhlRad_RL"] + PRESS,
            ["32767, 32766, 32765", "--na-raw WhlRad.WhlRad_RL=RAW[,RAW]"])
    inputs, _, _, _ = calib(r, "--na-raw", base + ["--speed", "WhlRad.WhlRad_RL"] + PRESS
                            + ["--na-raw", "WhlRad.WhlRad_RL=32767,0x7FFD"])
    r.check(na_of(by_signal(inputs, "WhlRad.WhlRad_RL")) == [32767, 32765], "--na-raw sets them by hand")
    inputs, _, _, _ = calib(r, "--na-raw none", base + SPEED + PRESS + ["--na-raw", "Brems_7.BS7_Hauptdruck=none"])
    r.check(na_of(by_signal(inputs, "Brems_7.BS7_Hauptdruck")) == [], "--na-raw MSG.SIG=none: no code")
    refused(r, "--na-raw beyond the raw range", base + SPEED + PRESS + ["--na-raw", "Brems_7.BS7_Hauptdruck=4096"],
            ["4096 is not a raw value"])
    refused(r, "--na-raw of no input", base + SPEED + PRESS + ["--na-raw", "VehSpd.VehSpd_Value=1"],
            ["not an input"])


def check_qualifiers(r):
    base = ["--dbc", ESC, "--corner", "FL"]
    inputs, _, notes, _ = calib(r, "two equal qualifiers", base + ["--speed", "VehSpd.VehSpd_Value"] + PRESS)
    v = by_signal(inputs, "VehSpd.VehSpd_Value")
    r.check(qual_of(v) is None, "VehSpd_Value_Q and VehSpd_Value_Valid: no qualifier chosen (%s)" % (qual_of(v),))
    r.check(any("VehSpd_Value_Q and VehSpd_Value_Valid are equally good" in n and "--qualifier" in n for n in notes),
            "and why: %s" % [n for n in notes if "VehSpd" in n])
    inputs, _, _, _ = calib(r, "--qualifier", base + ["--speed", "VehSpd.VehSpd_Value"] + PRESS
                            + ["--qualifier", "VehSpd.VehSpd_Value=VehSpd.VehSpd_Value_Valid:invalid-when=0"])
    r.check(qual_of(by_signal(inputs, "VehSpd.VehSpd_Value")) == (17, 0), "--qualifier sets it by hand")
    inputs, _, _, _ = calib(r, "_Stat with VAL_", base + ["--speed", "VehSpd.VehSpd_Disp"] + PRESS)
    r.check(qual_of(by_signal(inputs, "VehSpd.VehSpd_Disp")) == (40, 1), "_Stat with VAL_ 1 'Invalid': bit 40")
    refused(r, "qualifier in another message", base + ["--speed", "VehSpd.VehSpd_Value"] + PRESS
            + ["--qualifier", "VehSpd.VehSpd_Value=Pedal_Stat.BrkPedal_Sw:invalid-when=1"], ["same message"])
    refused(r, "qualifier of more than one bit", base + ["--speed", "VehSpd.VehSpd_Value"] + PRESS
            + ["--qualifier", "VehSpd.VehSpd_Value=VehSpd.VehSpd_Disp:invalid-when=1"], ["a qualifier is one bit"])
    refused(r, "qualifier beyond the DLC", base + ["--speed", "WSL.WSL_Far_Sig"] + PRESS
            + ["--qualifier", "WSL.WSL_Far_Sig=WSL.WSL_Far_Sig_Q:invalid-when=1"], ["beyond the DLC 6"])
    refused(r, "bad --qualifier", base + SPEED + PRESS + ["--qualifier", "WhlRad.WhlRad_FR=WhlRad.X"],
            ["invalid-when=0|1"])
    inputs, _, notes, _ = calib(r, "automatic qualifier beyond the DLC", base + ["--speed", "WSL.WSL_Far_Sig"] + PRESS)
    r.check(qual_of(by_signal(inputs, "WheelSpeedLongMessageName.WSL_Far_Sig")) is None
            and any("WSL_Far_Sig_Q lies beyond the DLC 6" in n for n in notes),
            "a candidate beyond the DLC is not taken, and the note says so")
    inputs, _, _, _ = calib(r, "torque with _Flt", base + SPEED + ["--force", "Brk_Torque.BrkTot_Tq"])
    r.check(qual_of(by_signal(inputs, "Brk_Torque.BrkTot_Tq")) == (28, 1), "BrkTot_Tq_Flt: bit 28, invalid when 1")


def check_long_names_numbers(r):
    base = ["--dbc", ESC, "--corner", "FL"]
    a, _, _, _ = calib(r, "short names", base + ["--speed", "WSL.WSL_FL"] + PRESS)
    b, _, _, _ = calib(r, "long names", base + ["--speed", "WheelSpeedLongMessageName.WheelSpeed_FrontLeft_LongName"]
                       + PRESS)
    sa = by_signal(a, "WheelSpeedLongMessageName.WheelSpeed_FrontLeft_LongName")
    sb = by_signal(b, "WheelSpeedLongMessageName.WheelSpeed_FrontLeft_LongName")
    r.check(sa and sa == sb, "a signal found by its short or its long name is the same input")
    r.check(sa.get("id") == "0x514" and sa.get("factor") == "0.0009765625" and sa.get("max") == "63.9990234375"
            and qual_of(sa) == (16, 1), "long names: 2^-10 exactly, max 65535 x 2^-10, the _Invalid bit (%s)" % sa)
    inputs, _, _, _ = calib(r, "32-bit", base + ["--speed", "Big32.BigSpeed"] + PRESS)
    s = by_signal(inputs, "Big32.BigSpeed")
    r.check(s.get("max") == "2147483647" and s.get("factor") == "1", "max 2147483647 written exactly (%s)" % s.get("max"))
    inputs, _, _, _ = calib(r, "17 digits", base + ["--speed", "WSL.WSL_Far_Sig"] + PRESS)
    s = by_signal(inputs, "WheelSpeedLongMessageName.WSL_Far_Sig")   # the message's long name
    # 255 x 0.33333333333333331 = 84.99999999999999405, rounded up to 17 digits
    r.check(s.get("factor") == "0.33333333333333331" and s.get("max") == "84.999999999999995",
            "17 significant digits kept exactly (%s, max %s)" % (s.get("factor"), s.get("max")))
    for d in list(a.values()) + list(inputs.values()):
        for k in ("factor", "offset", "min", "max", "step_max"):
            t = d.get(k, "0")
            digits = len(re.sub(r"[^0-9]", "", t.split("e")[0]).strip("0")) if "e" not in t else 1
            if not r.check(digits <= 17 and float(t) == float(t), "%s = %s: at most 17 significant digits" % (k, t)):
                break


def check_units(r):
    base = ["--dbc", ESC]
    refused(r, "unit-less pedal", base + ["--corner", "FL"] + SPEED + ["--force", "Pedal_Stat.BrkPedal_Pos"],
            ["unit '' is not known", "--force-unit", "--unit-scale"])
    inputs, corners, _, _ = calib(r, "pedal with --force-unit bar --unit-scale 2",
                                  base + ["--corner", "FL"] + SPEED + ["--force", "Pedal_Stat.BrkPedal_Pos",
                                          "--force-unit", "bar", "--unit-scale", "2", "--piston-area-mm2", "2000"])
    p = by_signal(inputs, "Pedal_Stat.BrkPedal_Pos")
    r.check(p.get("factor") == "0.03125" and p.get("offset") == "-3.21875" and p.get("unit") == "bar"
            and p.get("max") == "2000" and p.get("min") == "0",
            "scale 2 folded exactly into factor, offset and range (%s)" % p)
    inputs2, _, _, _ = calib(r, "--force-scale", base + ["--corner", "FL"] + SPEED
                             + ["--force", "Pedal_Stat.BrkPedal_Pos", "--force-unit", "bar", "--force-scale", "2",
                                "--piston-area-mm2", "2000"])
    r.check(by_signal(inputs2, "Pedal_Stat.BrkPedal_Pos") == p, "--force-scale S equals --force-unit U --unit-scale S")
    inputs, _, _, _ = calib(r, "--speed-scale", base + ["--corner", "FL", "--speed", "VehSpd.VehSpd_Disp",
                                                         "--speed-scale", "1.5"] + PRESS)
    s = by_signal(inputs, "VehSpd.VehSpd_Disp")
    r.check(s.get("factor") == "0.015" and s.get("max") == "450" and s.get("unit") == "km/h",
            "--speed-scale 1.5: factor 0.015, range [0|450] (%s %s)" % (s.get("factor"), s.get("max")))
    refused(r, "--unit-scale without a unit option", base + ["--corner", "FL", "--unit-scale", "2"] + SPEED + PRESS,
            ["--unit-scale 2: give it after --speed-unit U or --force-unit U"])
    refused(r, "--unit-scale 0", base + ["--corner", "FL"] + SPEED + ["--speed-unit", "rad/s", "--unit-scale", "0"]
            + PRESS, ["must be in (0, inf]"])
    tq = []
    for pos, share in (("FL", "0.35"), ("FR", "0.35"), ("RL", "0.15"), ("RR", "0.15")):
        tq += ["--corner", pos, "--speed", "WhlRad.WhlRad_FL" if pos == "FL" else "WhlRad.WhlRad_FR",
               "--force", "Brk_Torque.BrkTot_Tq", "--torque-share", share]
    inputs, corners, _, _ = calib(r, "total torque", base + tq)
    t = [n for n, d in inputs.items() if d.get("signal") == "Brk_Torque.BrkTot_Tq"]
    r.check(len(t) == 1 and all(corners.get(p, {}).get("force") == t[0] for p in vehref.POSITIONS)
            and [corners.get(p, {}).get("torque_share") for p in vehref.POSITIONS] == ["0.35", "0.35", "0.15", "0.15"],
            "a total torque: one input, torque_share per corner (%s)" % corners)
    refused(r, "--torque-share on a pressure", base + ["--corner", "FL"] + SPEED + PRESS + ["--torque-share", "0.5"],
            ["--torque-share applies to a brake torque only"])
    refused(r, "--torque-share above 1", base + ["--corner", "FL"] + SPEED + ["--force", "Brk_Torque.BrkTot_Tq",
                                                                              "--torque-share", "1.5"],
            ["--torque-share 1.5: must be in (0, 1]"])


def canmatrix_load(path):
    return vehref.load_dbc(path)


def check_tolerant(r, tmp):
    base = ["--dbc", ESC, "--corner", "FL"] + SPEED + PRESS
    _, _, notes, _ = calib(r, "a file with bad lines", base)
    mux_line = line_of(ESC, " SG_ MO9_Code m :")
    id_line = line_of(ESC, "BO_ 13300 HUD_Info")
    cm_line = line_of(ESC, 'CM_ SG_ 1176 "a comment')
    for n, why in ((mux_line, "malformed multiplexer indicator"), (id_line, "identifier 0x33F4 above 0x7FF"),
                   (cm_line, "not a valid CM_ statement")):
        hits = [x for x in notes if "field_esc.dbc:%d: skipped (%s" % (n, why) in x]
        r.check(len(hits) == 1, "line %d skipped once with its real number and reason (%s)" % (n, why))
    r.check(len([x for x in notes if "skipped" in x]) == 3, "three lines skipped: %s" % notes)
    refused(r, "asked for: id above 0x7FF", ["--dbc", ESC, "--corner", "FL", "--speed", "HUD_Info.HUD_Speed"] + PRESS,
            ["field_esc.dbc:%d: identifier 0x33F4 above 0x7FF without the extended flag" % id_line, "HUD_Info"])
    refused(r, "asked for: bad multiplexer", ["--dbc", ESC, "--corner", "FL"] + SPEED
            + ["--force", "Motor_9.MO9_Temp", "--force-unit", "N"],
            ["field_esc.dbc:%d: malformed multiplexer indicator 'm'" % mux_line])
    # a bad line in a requested message refuses, a bad VAL_ of one too
    with open(ESC, encoding="latin-1") as f:
        lines = f.read().splitlines()
    broken = os.path.join(tmp, "broken_req.dbc")
    k = lines.index(" SG_ BS7_Stillstand : 28|1@1+ (1,0) [0|1] \"\" GW")
    with open(broken, "w", encoding="latin-1") as f:
        f.write("\n".join(lines[:k] + [" SG_ BS7_Stillstand : 28|1@1+ (1,0 [0|1] \"\" GW"] + lines[k + 1:]) + "\n")
    refused(r, "bad SG_ line in the requested message", ["--dbc", broken, "--corner", "FL"] + SPEED + PRESS,
            ["broken_req.dbc:%d: not a valid SG_ statement, in message Brems_7" % (k + 1)])
    # a bad VAL_ of a requested message refuses (its codes matter), a bad comment of one is skipped
    k = lines.index('VAL_ 1176 BS7_Druckvalid 0 "invalid" 1 "valid" ;')
    badval = os.path.join(tmp, "badval.dbc")
    with open(badval, "w", encoding="latin-1") as f:
        f.write("\n".join(lines[:k] + ['VAL_ 1176 BS7_Druckvalid 0 "invalid 1 "valid" ;'] + lines[k + 1:]) + "\n")
    refused(r, "bad VAL_ of the requested message", ["--dbc", badval, "--corner", "FL"] + SPEED + PRESS,
            ["badval.dbc:%d: not a valid VAL_ statement, of message Brems_7 which is asked for" % (k + 1)])
    _, _, notes, _ = calib(r, "bad comment of the requested message", base)
    r.check(any("field_esc.dbc:%d: skipped (not a valid CM_ statement)" % cm_line in x for x in notes),
            "a bad comment of a requested message (Brems_7) is skipped, not refused")
    # a quote left open in a bad line of another message ends with its line
    k = lines.index('VAL_ 535 WhlRad_FR 32766 "Unknown" 0 "Stopped" ;')
    openq = os.path.join(tmp, "openquote.dbc")
    with open(openq, "w", encoding="latin-1") as f:
        f.write("\n".join(lines[:k] + ['VAL_ 1040 VehSpd_Disp_Stat 0 "Valid 1 "Invalid" ;'] + lines[k:]) + "\n")
    inputs, _, notes, _ = calib(r, "an open quote", ["--dbc", openq, "--corner", "FL"] + SPEED + PRESS)
    r.check(na_of(by_signal(inputs, "WhlRad.WhlRad_FR")) == [32766]
            and any("openquote.dbc:%d: skipped (not a valid VAL_ statement)" % (k + 1) in x for x in notes),
            "a bad VAL_ with an open quote is skipped alone: the next line is still read (%s)"
            % [x for x in notes if "openquote" in x])
    # the requested signals decode as canmatrix decodes them from a hand-fixed copy
    fixed = os.path.join(tmp, "fixed.dbc")
    drop = set()
    for n in (mux_line, id_line, cm_line):
        drop.add(n - 1)
    for i in (id_line, mux_line):   # the whole messages of the bad lines
        j = i - 1
        while not lines[j].startswith("BO_ "):
            j -= 1
        j += 1
        while j < len(lines) and lines[j].startswith(" SG_"):
            drop.add(j)
            j += 1
        drop.add([x for x in range(i - 1, -1, -1) if lines[x].startswith("BO_ ")][0])
    drop |= {i for i, l in enumerate(lines) if re.match(r"^(BA_ \"\w+\" BO_ 648 |VAL_ 648 )", l)}
    with open(fixed, "w", encoding="latin-1") as f:
        f.write("\n".join(l for i, l in enumerate(lines) if i not in drop) + "\n")
    ref = canmatrix_load(fixed)
    sys.path.insert(0, os.path.join(vehref.ROOT, "tools"))
    import dbc_tolerant
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        db, _, _ = dbc_tolerant.load(ESC, ["Brems_7", "WhlRad"])
    rng = random.Random(7)
    same = True
    for msg in ("Brems_7", "WhlRad", "VehSpd", "Brk_Torque"):
        a, b = db.frame_by_name(msg), ref.frame_by_name(msg)
        for _ in range(300):
            data = bytearray(rng.randrange(256) for _ in range(8))
            da, dbb = a.decode(data), b.decode(data)
            same = same and {k: v.raw_value for k, v in da.items()} == {k: v.raw_value for k, v in dbb.items()}
    r.check(same and len(db.frames) == len(ref.frames),
            "the file read with its bad lines skipped decodes as canmatrix decodes the hand-fixed copy")


def check_mux(r, tmp):
    base = ["--dbc", MUX, "--corner", "FL"]

    def one(what, force, extra=()):
        inputs, _, _, _ = calib(r, what, base + ["--speed", "WhlMux_Indep.WMI_Plain", "--force", force,
                                                 "--force-unit", "bar", "--piston-area-mm2", "2000",
                                                 "--period-ms", "10"] + list(extra))
        return by_signal(inputs, force)

    def keys(d):
        return {k: d[k] for k in d if k.startswith("mux")}
    def mux(start, length, value, value_max=None, pre="mux"):
        """The calibration keys of one selector (intel), as written by hand."""
        k = {pre + "_start_bit": str(start), pre + "_length": str(length), pre + "_byte_order": "intel",
             pre + "_value": str(value)}
        if value_max is not None:
            k[pre + "_value_max"] = str(value_max)
        return k
    for what, force, want, label in (
            ("SG_MUL_VAL_ range", "WhlMux_Ext.WME_Front", mux(0, 4, 0, 2), "extended mux: pages 0-2"),
            ("one page", "WhlMux_Ext.WME_Press", mux(0, 4, 6), "extended mux, one page: no mux_value_max"),
            ("cascaded", "BrkMux_Casc.BMC_PressRear", dict(mux(0, 2, 1), **mux(2, 3, 2, 4, pre="mux2")),
             "cascaded: outer page 1, inner 2-4"),
            ("outer page only", "BrkMux_Casc.BMC_Speed", mux(0, 2, 2),
             "cascaded frame, a signal of the outer selector only"),
            ("independent", "WhlMux_Indep.WMI_PressB23", mux(2, 2, 2, 3),
             "independent multiplexors: the signal's own selector")):
        d = one(what, force)
        r.check(keys(d) == want, "%s (%s)" % (label, keys(d)))
    # d: the independent multiplexor's input, the last of the table
    r.check(d.get("period_ms") == "20", "GenMsgCycleTime 10 ms, 2 of 4 pages: 20 ms (%s)" % d.get("period_ms"))
    refused(r, "two ranges", base + ["--speed", "WhlMux_Indep.WMI_Plain", "--force", "WhlMux_Ext.WME_Temp",
                                     "--force-unit", "bar", "--piston-area-mm2", "2000", "--period-ms", "10"],
            ["values 0-0, 3-3 of selector WME_Page", "one range per selector"])
    refused(r, "three selectors", base + ["--speed", "WhlMux_Indep.WMI_Plain", "--force", "BrkMux_Casc.BMC_DeepVal",
                                          "--force-unit", "bar", "--piston-area-mm2", "2000", "--period-ms", "10"],
            ["three or more cascaded selectors"])
    r.check(qual_of(one("qualifier on another page", "WhlMux_Ext.WME_Front")) is None,
            "WME_Front_Q (page 3) does not qualify WME_Front (pages 0-2)")
    r.check(qual_of(one("qualifier on the same pages", "WhlMux_Ext.WME_Rear")) == (61, 1),
            "WME_Rear_Flt (pages 3-5) qualifies WME_Rear (pages 3-5)")
    refused(r, "--qualifier on another page", base + ["--speed", "WhlMux_Indep.WMI_Plain", "--force",
                                                      "WhlMux_Ext.WME_Front", "--force-unit", "bar",
                                                      "--piston-area-mm2", "2000", "--period-ms", "10",
                                                      "--qualifier", "WhlMux_Ext.WME_Front=WhlMux_Ext.WME_Front_Q"
                                                      ":invalid-when=1"],
            ["WME_Front_Q is not in every frame that carries WME_Front (another page)"])
    # periods from a log: pages 0..6 take turns every 10 ms
    log = os.path.join(tmp, "mux.log")
    with open(log, "w") as f:
        for k in range(700):
            f.write("(%d.%06d) can0 2C0#%02X00000000000000\n" % (1000 + k // 100, (k % 100) * 10000, k % 7))
            if k % 2 == 0:
                f.write("(%d.%06d) can0 2C2#00000000000000\n" % (1000 + k // 100, (k % 100) * 10000 + 500))
    inputs, _, _, _ = calib(r, "mux periods from a log", base + ["--log", log, "--speed", "WhlMux_Ext.WME_Front",
                                                                  "--force", "WhlMux_Ext.WME_Press", "--force-unit",
                                                                  "bar", "--piston-area-mm2", "2000"])
    r.check(by_signal(inputs, "WhlMux_Ext.WME_Front").get("period_ms") == "23"
            and by_signal(inputs, "WhlMux_Ext.WME_Press").get("period_ms") == "70",
            "a log: 10 ms x 7/3 pages = 23 ms, x 7 = 70 ms (%s, %s)"
            % (by_signal(inputs, "WhlMux_Ext.WME_Front").get("period_ms"),
               by_signal(inputs, "WhlMux_Ext.WME_Press").get("period_ms")))


def check_bus(r, tmp):
    with open(ESC, encoding="latin-1") as f:
        text = f.read()
    nocycle = os.path.join(tmp, "nocycle.dbc")
    with open(nocycle, "w", encoding="latin-1") as f:
        f.write("\n".join(l for l in text.splitlines() if not l.startswith('BA_ "GenMsgCycleTime"')) + "\n")
    log = os.path.join(tmp, "buses.log")
    n_ones = n_out = n = 0
    with open(log, "w") as f:
        for k in range(1000):
            t = 2000.0 + k * 0.010
            raw = 4095 if k % 10 == 3 else (3000 if k % 10 == 5 else 500)   # 0xFFF; 300 bar beyond [0|250]
            if k % 2 == 0:   # Brems_7 every 20 ms on can0, its pressure at bit 16 (Intel)
                d = bytearray(8)
                d[2], d[3] = raw & 0xFF, (raw >> 8) | 0x20
                f.write("(%.6f) can0 498#%s\n" % (t, d.hex().upper()))
                n += 1
                n_ones += raw == 4095
                n_out += raw in (4095, 3000)
            f.write("(%.6f) can1 498#0000000000000000\n" % (t + 0.001))   # another ECU's 0x498, every 10 ms
            f.write("(%.6f) can0 217#0000000000000000\n" % (t + 0.002))
    base = ["--dbc", nocycle, "--log", log, "--corner", "FL"] + SPEED + PRESS
    refused(r, "a message on two interfaces", base, ["Brems_7 is on 2 interfaces of the log (can0, can1)", "--bus"])
    inputs, _, notes, flat = calib(r, "--bus can0", base + ["--bus", "can0"])
    p = by_signal(inputs, "Brems_7.BS7_Hauptdruck")
    r.check(flat.get("input_iface") == "can0" and p.get("period_ms") == "20"
            and by_signal(inputs, "WhlRad.WhlRad_FR").get("period_ms") == "10",
            "--bus can0: input_iface, periods of can0 (%s, %s)" % (flat.get("input_iface"), p.get("period_ms")))
    want = "Brems_7.BS7_Hauptdruck: %d logged values, %d outside the declared range [0|250] bar, %d all ones (raw 4095)" \
        % (n, n_out, n_ones)
    r.check(any(want in x for x in notes), "the log's counts per input: %r in %s" % (want, notes))
    inputs, _, _, flat = calib(r, "--bus can1", base + ["--bus", "can1"] + ["--period-ms", "10"])
    r.check(flat.get("input_iface") == "can1" and by_signal(inputs, "Brems_7.BS7_Hauptdruck").get("period_ms") == "10",
            "--bus can1: the other ECU's 10 ms")
    refused(r, "--bus without frames", base + ["--bus", "can7"], ["--bus can7: the log has no frame on can7"])
    refused(r, "--bus bad name", base + ["--bus", "a b"], ["--bus 'a b'"])


def check_checker(r, tmp):
    bad = os.path.join(tmp, "refusing-check")
    with open(bad, "w") as f:
        f.write('#!/bin/sh\necho "$2:12: [input X] something the firmware refuses" >&2\nexit 1\n')
    os.chmod(bad, 0o755)
    out = os.path.join(tmp, "out", "car.cal")
    os.makedirs(os.path.dirname(out))
    args = ["--dbc", ESC, "--corner", "FL"] + SPEED + PRESS + ["-o", out]
    refused(r, "calib-check refuses", args,
            ["the firmware refuses the calibration: %s:12: [input X] something the firmware refuses" % out],
            checker=bad)
    r.check(os.listdir(os.path.dirname(out)) == [], "nothing written when calib-check refuses (%s)"
            % os.listdir(os.path.dirname(out)))
    refused(r, "no checker", args, ["is missing; run make first", "build/host/squeal-sim"],
            checker=os.path.join(tmp, "none", "squeal-sim"))
    rc, _, err = tool(args)
    r.check(rc == 0 and os.listdir(os.path.dirname(out)) == ["car.cal"], "checked, then written (%s)" % err[-200:])


def check_help(r):
    rc, out, err = tool(["--help"])
    r.check(rc == 0 and "usage:" in out, "--help: usage, exit 0")
    lines = out.splitlines()
    opts = ["--dbc", "--log", "--bus", "--wheel-radius-m", "--pad-radius-m", "--period-ms", "--protection",
            "--counter", "--qualifier", "--na-raw", "--ignore-dbc-range", "--keep-all-ones", "--base", "--output",
            "--dbc-out", "--corner", "--speed", "--force", "--speed-unit", "--force-unit", "--speed-scale",
            "--force-scale", "--unit-scale", "--piston-area-mm2", "--efficiency", "--axle-factor", "--torque-share"]
    for o in opts:
        k = next((i for i, l in enumerate(lines) if re.match(r"^\s+(?:-\w \S+, )?%s\b" % re.escape(o), l)), None)
        has = k is not None and (len(re.split(r"\s{2,}", lines[k].strip())) > 1
                                 or (k + 1 < len(lines) and lines[k + 1].startswith(" " * 10)))
        r.check(has, "--help: %s with a help line" % o)
    r.check("not available" in out and "SNA" in out and "unknown" in out and "undefined" in out,
            "--help states the texts that mean no value")


def main():
    r = vehref.Results()
    with tempfile.TemporaryDirectory() as tmp:
        check_ranges_na(r)
        check_qualifiers(r)
        check_long_names_numbers(r)
        check_units(r)
        check_tolerant(r, tmp)
        check_mux(r, tmp)
        check_bus(r, tmp)
        check_checker(r, tmp)
        check_help(r)
    r.finish()


if __name__ == "__main__":
    sys.exit(main())
