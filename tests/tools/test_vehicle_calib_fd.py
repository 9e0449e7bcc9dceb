#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""tools/vehicle_calib.py on CAN FD layouts (tests/tools/fixtures/), pure
Python (the calibrations are checked by the stand-in stub_calib_check.py):

  - every FD fixture: each [input] equals the DBC signal as canmatrix reads
    it (identifier, extended, start bit, length, order, sign, factor,
    offset, unit), fd = yes exactly for canmatrix's FD frames, min_dlc the
    FD length, and the protection written down by hand per message: P05
    with its Data ID and CRC offset, or the counter (the block's own in a
    frame of two CRC-16 blocks);
  - VFrameFormat as the ENUM index, as text (a copy canmatrix cannot read),
    absent (the DLC says FD), contradicting the DLC, not in the ENUM; an FD
    length between the DLC codes; --protection p05 refusals and --data-id;
  - --log: an FD message's period from its FD frames only (classic frames
    of its identifier at another rate in the log), a classic message's from
    its classic frames, bad FD lines counted;
  - 3000 random frames per layout (FD lengths, short FD frames, classic
    frames of the FD identifiers): the raw and physical value the written
    calibration extracts (vehref's bit-by-bit extractor) equals canmatrix's
    decode, a short or classic frame is the dlc verdict;
  - the drive generator's P05 CRCs and counters against the bitwise CRC-16,
    its `##` lines; CRC-16/CCITT-FALSE's check value and the worked P05
    example; the end-to-end harness with its crc verdicts on its stand-in;
  - --help names every new option.
Prints "RESULT: N passed, M failed".
"""
import os
import random
import re
import sys
import tempfile
import zlib
# tests/ of this checkout, and the folders its helper modules live in
_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, d) for d in ("support", os.path.join("support", "reference"), "host-sim", "tools")]

import vehref  # noqa: E402
sys.path.insert(0, vehref.FIXTURES)
import fd_layouts  # noqa: E402
import gen_drive  # noqa: E402
import e2e_harness  # noqa: E402
import test_vehicle_calib_crosscheck as xcheck  # noqa: E402

FD_LENGTHS = (0, 1, 2, 3, 4, 5, 6, 7, 8, 12, 16, 20, 24, 32, 48, 64)
FRAMES = 3000


def tool(args):
    return vehref.run_tool([vehref.PY, vehref.TOOL] + list(args))


def build(layout, tmp, name, log=None, extra=()):
    cal = os.path.join(tmp, name + ".cal")
    rc, _, err = vehref.run_tool(vehref.calib_command(layout, log=log, out=cal, extra=extra))
    text = open(cal).read() if rc == 0 else ""
    return rc, text, err


def check_layout(r, name, layout, tmp):
    db = vehref.load_dbc(layout["dbc"])
    rc, text, err = build(layout, tmp, name)
    notes, other = vehref.notes_of(err)
    if not r.check(rc == 0 and not other, "%s: vehicle_calib.py exits 0 with notes only (%d: %s)" % (name, rc, other)):
        return
    _, inputs, corners = vehref.parse_calib(text)
    refs = {ref for _, spd, frc, _ in layout["corners"] for ref in (spd, frc)}
    r.check(len(inputs) == len(refs), "%s: one input per MSG.SIG (%d of %d)" % (name, len(inputs), len(refs)))
    for ref in sorted(refs):
        msg, signame = ref.split(".")
        fr = db.frame_by_name(msg)
        sig = fr.signal_by_name(signame)
        found = [d for d in inputs.values() if d.get("signal") == ref]
        if not r.check(len(found) == 1, "%s: one input for %s" % (name, ref)):
            continue
        inp = found[0]
        exp = layout["expect"][msg]
        want = {"id": fr.arbitration_id.id, "extended": "yes" if fr.arbitration_id.extended else "no",
                "start_bit": sig.get_startbit(bit_numbering=1), "length": sig.size,
                "byte_order": "intel" if sig.is_little_endian else "motorola",
                "signed": "yes" if sig.is_signed else "no", "unit": sig.unit,
                "min_dlc": exp["min_dlc"], "protection": exp["protection"]}
        bad = vehref.wrong_keys(inp, want, sig)
        r.check(not bad, "%s %s: layout keys equal canmatrix's signal (wrong: %s)" % (name, ref, bad))
        r.check(inp.get("fd") == ("yes" if fr.is_fd else None) == exp["fd"],
                "%s %s: fd = %s as canmatrix's is_fd %s" % (name, ref, inp.get("fd"), fr.is_fd))
        r.check(fr.size == exp["min_dlc"], "%s %s: min_dlc %s is the DBC's DLC %d" % (name, ref, inp.get("min_dlc"),
                                                                                      fr.size))
        if exp["protection"] == "p05":
            r.check(vehref.ival(inp, "data_id") == exp["data_id"]
                    and vehref.ival(inp, "e2e_offset_byte") == exp["e2e_offset_byte"]
                    and vehref.ival(inp, "max_delta_counter") == exp["max_delta_counter"]
                    and not any(k.startswith("counter_") for k in inp),
                    "%s %s: P05 with Data ID 0x%04X, CRC at byte %d (%s)"
                    % (name, ref, exp["data_id"], exp["e2e_offset_byte"], inp))
        elif exp["protection"] == "counter":
            cname = exp["counter"] if isinstance(exp["counter"], str) else exp["counter"][signame.split("_")[0]]
            c = fr.signal_by_name(cname)
            r.check(vehref.ival(inp, "counter_start_bit") == c.get_startbit(bit_numbering=1)
                    and vehref.ival(inp, "counter_length") == c.size
                    and inp.get("counter_byte_order") == ("intel" if c.is_little_endian else "motorola")
                    and vehref.ival(inp, "counter_modulus") == 1 << c.size
                    and vehref.ival(inp, "max_delta_counter") == min(3, (1 << c.size) - 1)
                    and "data_id" not in inp,
                    "%s %s: counter %s from the DBC (%s)" % (name, ref, cname, inp))
        r.check(any(("%s: protection" % ref) in n or ("%s: no protection" % ref) in n for n in notes),
                "%s %s: a note says which protection and why" % (name, ref))
    for pos, spd, frc, _ in layout["corners"]:
        c = corners.get(pos, {})
        r.check(inputs.get(c.get("speed"), {}).get("signal") == spd and
                inputs.get(c.get("force"), {}).get("signal") == frc,
                "%s: [corner %s] names its inputs" % (name, pos))


def variant(tmp, src, name, old, new):
    with open(src) as f:
        text = f.read()
    if old is not None:
        assert old in text, (src, old)
        text = text.replace(old, new)
    p = os.path.join(tmp, name)
    with open(p, "w") as f:
        f.write(text)
    return p


def body(text):
    return [l for l in text.splitlines() if not l.startswith("#")]


def check_formats(r, tmp):
    """VFrameFormat by index, text, absent, contradicting; FD lengths."""
    esc = fd_layouts.FD_LAYOUTS["fd_esc48"]
    args = esc["options"]
    corner = ["--corner", "FL", "--speed", "ESC_Chassis48.ESC_WhlSpd_FL", "--force", "ESC_Chassis48.ESC_BrkPrs_FL",
              "--piston-area-mm2", "2290"]
    rc, base, err = tool(["--dbc", esc["dbc"]] + corner + args)
    r.check(rc == 0 and "fd = yes" in base and "min_dlc = 48" in base, "esc48: FD by the ENUM index (%s)" % err)
    line = 'BA_ "VFrameFormat" BO_ 252 14;'
    cases = [
        ("as text", 'BA_ "VFrameFormat" BO_ 252 "StandardCAN_FD";', True),
        ("absent (DLC 48 says FD)", "", True),
        ("by the default", 'BA_DEF_DEF_  "VFrameFormat" "StandardCAN_FD";', True),
    ]
    for what, new, same in cases:
        src = esc["dbc"]
        if "DEF_DEF" in new:
            p = variant(tmp, src, "v.dbc", line, "")
            p = variant(tmp, p, "v.dbc", 'BA_DEF_DEF_  "VFrameFormat" "StandardCAN";', new)
        else:
            p = variant(tmp, src, "v.dbc", line, new)
        rc, out, err = tool(["--dbc", p] + corner + args)
        r.check(rc == 0 and body(out) == body(base), "esc48, VFrameFormat %s: the same calibration (%d %s)"
                % (what, rc, err.splitlines()[-1:]))
    refusals = [
        ("classic format with DLC 48", line, 'BA_ "VFrameFormat" BO_ 252 0;', "VFrameFormat StandardCAN"),
        ("a text the ENUM does not list", line, 'BA_ "VFrameFormat" BO_ 252 "CAN_FD_Fast";', "none of its values"),
        ("DLC 70", "BO_ 252 ESC_Chassis48: 48 ESC", "BO_ 252 ESC_Chassis48: 70 ESC", "more than the 64 bytes"),
    ]
    for what, old, new, needle in refusals:
        p = variant(tmp, esc["dbc"], "v.dbc", old, new)
        rc, out, err = tool(["--dbc", p] + corner + args)
        r.check(rc == 1 and out == "" and len(err.splitlines()) == 1 and needle in err and "Traceback" not in err,
                "esc48, %s: a one-line refusal naming %r (%s)" % (what, needle, err.strip()))
    # a DBC length between the FD lengths: the frame is padded to the next one
    w24 = fd_layouts.FD_LAYOUTS["fd_wheels24"]
    p = variant(tmp, w24["dbc"], "v.dbc", "BO_ 160 ESC_WheelSpdFD: 24 ESC", "BO_ 160 ESC_WheelSpdFD: 18 ESC")
    rc, out, err = tool(["--dbc", p, "--corner", "FL", "--speed", "ESC_WheelSpdFD.WHL_SPD_FL", "--force",
                         "ESC_BrakePrs.BRK_MC_Pressure", "--piston-area-mm2", "2290"])
    r.check(rc == 0 and "min_dlc = 20" in out and "padded to 20" in err, "DLC 18 of an FD frame: min_dlc 20 (%s)"
            % err.strip().splitlines()[-1:])
    # a signal beyond the frame
    p = variant(tmp, w24["dbc"], "v.dbc", "BO_ 160 ESC_WheelSpdFD: 24 ESC", "BO_ 160 ESC_WheelSpdFD: 12 ESC")
    rc, out, err = tool(["--dbc", p, "--corner", "FL", "--speed", "ESC_WheelSpdFD.WHL_SPD_RR", "--force",
                         "ESC_BrakePrs.BRK_MC_Pressure", "--piston-area-mm2", "2290"])
    r.check(rc == 1 and len(err.splitlines()) == 1 and "beyond the 12 bytes" in err,
            "a signal beyond the FD length: refused (%s)" % err.strip())


def check_protection(r, tmp):
    w24 = fd_layouts.FD_LAYOUTS["fd_wheels24"]
    blk = fd_layouts.FD_LAYOUTS["fd_block64"]
    speed = ["--corner", "FL", "--speed", "ESC_WheelSpdFD.WHL_SPD_FL", "--force", "ESC_WheelSpdFD.WHL_SPD_FR",
             "--force-unit", "bar", "--piston-area-mm2", "2290"]
    blk_args = ["--dbc", blk["dbc"], "--corner", "FL", "--speed", "BCM_Wheel64.BLK1_Spd_FL", "--force",
                "BCM_Wheel64.BLK2_Prs_FL", "--piston-area-mm2", "2290"]
    cases = [
        ("p05 without a Data ID", ["--dbc", w24["dbc"]] + speed + ["--protection", "p05"], "no Data ID"),
        ("p05 on a classic frame without CRC-16", ["--dbc", w24["dbc"], "--corner", "FL", "--speed",
                                                   "ESC_WheelSpdFD.WHL_SPD_FL", "--force",
                                                   "ESC_BrakePrs.BRK_MC_Pressure", "--piston-area-mm2", "2290",
                                                   "--protection", "p05", "--data-id-xor", "0xF800"],
         "ESC_BrakePrs has no P05 layout"),
        ("p05 on two CRC-16 blocks", blk_args + ["--protection", "p05"], "2 CRC-16 blocks (bytes 0, 32)"),
        ("bad --data-id", ["--dbc", w24["dbc"]] + speed + ["--protection", "p05", "--data-id", "ESC_WheelSpdFD=0x10000"],
         "--data-id ESC_WheelSpdFD=0x10000"),
        ("--data-id of an unknown message", ["--dbc", w24["dbc"]] + speed + ["--protection", "p05", "--data-id",
                                                                              "Nope=1"], "unknown message 'Nope'"),
        ("bad --data-id-xor", ["--dbc", w24["dbc"]] + speed + ["--protection", "p05", "--data-id-xor", "x"],
         "--data-id-xor"),
        ("the Data ID of a 29-bit identifier by XOR", blk_args + ["--protection", "p01", "--data-id-xor", "0xF800"],
         None),
    ]
    for what, args, needle in cases:
        rc, out, err = tool(args)
        if needle is None:
            r.check(rc == 0 and "data_id = 4660" in out, "%s: the E2E_DataID attribute comes first (%s)"
                    % (what, err.strip().splitlines()[-1:]))
            continue
        r.check(rc == 1 and out == "" and len(err.splitlines()) == 1 and needle in err and "Traceback" not in err,
                "refusal, %s: one line naming %r (%s)" % (what, needle, err.strip()))
    rc, out, err = tool(["--dbc", w24["dbc"]] + speed + ["--protection", "p05", "--data-id", "ESC_WheelSpdFD=0x1234",
                                                          "--data-id-xor", "0xF800"])
    r.check(rc == 0 and "data_id = 4660" in out and "e2e_offset_byte = 0" in out and "max_delta_counter = 3" in out,
            "--data-id by hand before --data-id-xor (%s)" % err.strip().splitlines()[-1:])
    rc, out, err = tool(blk_args + ["--protection", "auto"])
    r.check(rc == 0 and "2 CRC-16 blocks" in err and "counter_start_bit = 16" in out and "counter_start_bit = 272" in out,
            "auto on two blocks: each input its block's counter, the note says why not P05")


def fd_log_line(t, cid, ext, data, flags):
    return gen_drive.candump_line(t, cid, ext, gen_drive.fd_data(data, flags))


def check_log(r, tmp):
    """Periods from FD frames of FD messages only."""
    w24 = fd_layouts.FD_LAYOUTS["fd_wheels24"]
    p = variant(tmp, w24["dbc"], "nocycle.dbc", 'BA_ "GenMsgCycleTime" BO_ 160 10;\nBA_ "GenMsgCycleTime" BO_ 176 10;\n',
                "")
    lines = []
    t = 1700000000.0
    for k in range(400):   # FD 0xA0 every 20 ms, classic 0xA0 every 5 ms, classic 0xB0 every 10 ms, FD 0xB0 every 3 ms
        lines.append((t + 0.020 * k, fd_log_line(t + 0.020 * k, 0xA0, False, bytes(24), 0x5)))
    for k in range(1600):
        lines.append((t + 0.005 * k + 0.001, gen_drive.candump_line(t + 0.005 * k + 0.001, 0xA0, False, bytes(8))))
    for k in range(800):
        lines.append((t + 0.010 * k + 0.002, gen_drive.candump_line(t + 0.010 * k + 0.002, 0xB0, False, bytes(8))))
    for k in range(2600):
        lines.append((t + 0.003 * k + 0.0005, fd_log_line(t + 0.003 * k + 0.0005, 0xB0, False, bytes(8), 0x4)))
    lines.append((t + 0.5, "(1700000000.500000) can0 0A0##5" + "00" * 13 + "\n"))   # 13 bytes: no DLC length
    lines.sort()
    log = os.path.join(tmp, "mixed.log")
    with open(log, "w") as f:
        f.write("".join(l for _, l in lines))
    rc, out, err = tool(["--dbc", p, "--log", log, "--corner", "FL", "--speed", "ESC_WheelSpdFD.WHL_SPD_FL", "--force",
                         "ESC_BrakePrs.BRK_MC_Pressure", "--piston-area-mm2", "2290"])
    _, inputs, _ = vehref.parse_calib(out)
    per = {d.get("signal"): vehref.ival(d, "period_ms") for d in inputs.values()}
    r.check(rc == 0 and per.get("ESC_WheelSpdFD.WHL_SPD_FL") == 20,
            "--log: the FD message's period from its FD frames only (20 ms; classic frames of 0xA0 every 5 ms): %s"
            % per)
    r.check(per.get("ESC_BrakePrs.BRK_MC_Pressure") == 10,
            "--log: the classic message's period from its classic frames only (10 ms; FD frames of 0xB0 every 3 ms)")
    r.check("1 FD lines skipped" in err and "400 logged values" in err,
            "--log: a bad FD line counted, the FD message's counts from its FD frames (%s)"
            % [l for l in err.splitlines() if "log" in l][:3])


def random_fd_frames(db, inputs, n, seed):
    """[(t, id, extended, data)] of the inputs' messages: an FD message's
    frames at its length (FdData), shorter FD lengths, classic frames of its
    identifier; a classic message's classic frames, some short."""
    rng = random.Random(seed)
    keys = vehref.input_messages(inputs)
    frames = {(f.arbitration_id.id, bool(f.arbitration_id.extended)): f for f in db.frames}
    out = []
    for k in range(n):
        t = "%d.%06d" % (1700000000 + k // 1000, (k % 1000) * 1000)
        cid, ext = rng.choice(keys)
        fr = frames[(cid, ext)]
        x = rng.random()
        if gen_drive.fd_message(fr):
            if x < 0.75:
                n_bytes, fd = fr.size, True
            elif x < 0.88:
                n_bytes, fd = rng.choice([v for v in FD_LENGTHS if v < fr.size]), True
            else:
                n_bytes, fd = rng.randint(0, 8), False
        else:
            n_bytes, fd = (fr.size if x < 0.9 else rng.randint(0, fr.size - 1)), False
        data = bytes(rng.randrange(256) for _ in range(n_bytes))
        out.append((t, cid, ext, gen_drive.fd_data(data, 0x5) if fd else data))
    return out


def check_crosscheck(r, name, layout, tmp):
    db = vehref.load_dbc(layout["dbc"])
    rc, text, err = build(layout, tmp, name + "-x")
    if not r.check(rc == 0, "%s: calibration for the cross-check (%s)" % (name, err.strip()[-200:])):
        return 0
    _, inputs, _ = vehref.parse_calib(text)
    frames = random_fd_frames(db, inputs, FRAMES, zlib.crc32(name.encode()))
    exp = xcheck.canmatrix_rows(db, inputs, frames)
    n_classic = sum(1 for (t, _), v in exp.items() if v == "dlc")
    r.check(n_classic > 100, "%s: short and classic frames of the FD identifiers among them (%d)" % (name, n_classic))
    return xcheck.compare(r, name + " (vehref's extractor vs canmatrix)", xcheck.reference_csv(text, frames), exp,
                          inputs) or 0


def check_references(r):
    r.check(vehref.crc16_ccitt_false(b"123456789") == 0x29B1, "CRC-16/CCITT-FALSE check value 0x29B1")
    zero = bytearray(8)
    c = vehref.p05_crc(zero, 0x1234)
    r.check(bytes([c & 0xFF, c >> 8]) == bytes.fromhex("1cca"), "P05: 8 zero bytes, Data ID 0x1234 -> 1c ca")
    zero[2] = 1
    c = vehref.p05_crc(zero, 0x1234)
    r.check(bytes([c & 0xFF, c >> 8]) == bytes.fromhex("cf8d"), "P05: with the counter 1 -> cf 8d")


def check_drive(r, name, layout):
    db = vehref.load_dbc(layout["dbc"])
    frames = gen_drive.Drive(layout, seed=9).frames()
    lines = [gen_drive.candump_line(*f) for f in frames]
    for msg, period in layout["period_s"].items():
        f = db.frame_by_name(msg)
        mine = [d for t, i, e, d in frames if i == f.arbitration_id.id and e == bool(f.arbitration_id.extended)
                and gen_drive.is_message(f, d)]
        idt = ("%08X" if f.arbitration_id.extended else "%03X") % f.arbitration_id.id
        sep = "##%X" % layout["fd_flags"] if gen_drive.fd_message(f) else "#"
        line = re.compile(r" %s%s[0-9A-F]*$" % (idt, sep))
        r.check(mine and all(len(d) == f.size for d in mine) and
                sum(1 for l in lines if line.search(l)) == len(mine),
                "%s drive: %s as %s lines of %d bytes (%d)" % (name, msg, sep, f.size, len(mine)))
        blocks = layout.get("p05", {}).get(msg, ())
        ok, steps, prev = True, set(), None
        for d in mine:
            for start, off, end, did in blocks:
                blk = d[start:len(d) if end is None else end]
                ok = ok and vehref.p05_crc(blk, did, off - start) == d[off] | d[off + 1] << 8
            if blocks:
                ctr = d[blocks[0][1] + 2]
                if prev is not None:
                    steps.add((ctr - prev) % 256)
                prev = ctr
        if blocks:
            r.check(ok and steps == {1, 2, 3}, "%s drive: %s's P05 CRCs right (bitwise CRC-16), counter steps %s"
                    % (name, msg, sorted(steps)))


def check_help(r):
    rc, out, err = tool(["--help"])
    for word in ("--data-id", "--data-id-xor", "p05", "auto", "fd = yes", "StandardCAN_FD", "e2e_offset_byte",
                 "##"):
        r.check(rc == 0 and word in out, "--help documents %s" % word)


def main():
    r = vehref.Results()
    total = 0
    with tempfile.TemporaryDirectory() as tmp:
        for name, layout in fd_layouts.FD_LAYOUTS.items():
            check_layout(r, name, layout, tmp)
            total += check_crosscheck(r, name, layout, tmp)
            check_drive(r, name, layout)
        check_formats(r, tmp)
        check_protection(r, tmp)
        check_log(r, tmp)
        check_references(r)
        check_help(r)
        e2e_harness.run_layout(r, "self-test fd_wheels24", fd_layouts.FD_LAYOUTS["fd_wheels24"], tmp,
                               e2e_harness.fake_replay)
    print("FD cross-check: %d frame-input pairs over %d layouts" % (total, len(fd_layouts.FD_LAYOUTS)))
    r.finish()


if __name__ == "__main__":
    sys.exit(main())
