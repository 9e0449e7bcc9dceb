#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""tools/vehicle_calib.py against the fixture DBCs read by canmatrix, and the
self-tests of the vehicle harnesses (pure Python, no C needed):

  - every layout: each [input] equals the DBC signal as canmatrix reads it
    (identifier, extended, DLC, start bit in DBC numbering, length, order,
    sign, factor, offset, unit, multiplexer), the "not available" values and
    qualifier bits written down by hand for each fixture, the period from
    GenMsgCycleTime / the log / --period-ms, the protection keys from the
    DBC; one input per distinct MSG.SIG; the corners name the right inputs;
  - every refusal: one line on stderr, exit status != 0, no traceback;
    150 damaged DBCs: a calibration or a one-line refusal each;
  - the period estimate on logs at 10, 20 and 24 ms with jitter, dropped
    frames, heavy loss and a backward jump;
  - --dbc-out: canmatrix reads it; per corner the four Squeal* messages of
    squeal.dbc with the same signals, names suffixed, FL keeping today's;
  - --base: flat keys kept, legacy input keys and old sections dropped;
  - squeal.dbc's own inputs come out as P01 with their data IDs;
  - the drive generator: one 2.8 s jump back, periods, a few frames lost,
    P02 CRC-8H2F and counters as their definitions say (canmatrix decoding);
  - the references: CRC check values, the worked example (40 bar on 2290 mm^2: 9.16 kN), the
    cross-check harness on vehref's pure-Python extraction (and that it
    catches a wrong value), the end-to-end harness on its Python stand-in.
Prints "RESULT: N passed, M failed".
"""
import importlib.util
import os
import random
import sys
import tempfile
# tests/ of this checkout, and the folders its helper modules live in
_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, d) for d in ("support", os.path.join("support", "reference"), "host-sim", "tools")]

import vehref  # noqa: E402
import gen_drive  # noqa: E402
import e2e_harness  # noqa: E402
import test_vehicle_calib_crosscheck as xcheck  # noqa: E402

spec = importlib.util.spec_from_file_location("vehicle_calib", vehref.TOOL)
vc = importlib.util.module_from_spec(spec)
spec.loader.exec_module(vc)

# Written by hand from the fixture DBCs: (na_raw values, qualifier (bit, invalid value) or None, period ms)
EXPECT = {
    "esc_motorola": {
        "ESC_WheelSpeeds.WhlSpd_FL": ([32767], (7, 1), 20),
        "ESC_WheelSpeeds.WhlSpd_RL": ([32767], (39, 1), 20),
        # 4094 "Error" lies inside the declared [0|409.4] bar, 4095 "Init" (all ones) beyond it
        "ESC_Brake.BrkPrs_MC": ([4094, 4095], None, 20),
    },
    "esc_intel": dict([("ABS_WheelSpeed.WHEEL_SPEED_" + p, ([], None, 24)) for p in vehref.POSITIONS]
                      + [("ABS_WheelPressure.PRESS_" + p, ([4095], None, 24)) for p in vehref.POSITIONS]),
    "chassis_mux29": {
        "BrkCtl_WheelSpd.WheelRpm_FL": ([-32768], None, 20),   # 10 ms x 2 pages
        "BrkCtl_WheelSpd.WheelRpm_RL": ([-32768], None, 20),
        "BrkCtl_Torque.BrakeTorque_Front": ([16383], (30, 1), 10),  # --period-ms
        "BrkCtl_Torque.BrakeTorque_Rear": ([16383], (46, 1), 10),
    },
}


same_num = vehref.same_num


def signal_of(fr, inp):
    try:
        return xcheck.fr_signal(fr, inp)
    except KeyError:
        return None


class Quiet(vehref.Results):
    """Counts without printing (the harness's failures on a mutant are wanted)."""
    def check(self, cond, what):
        if cond:
            self.passed += 1
        else:
            self.failed += 1
        return cond


def check_layout(r, name, layout, tmp):
    db = vehref.load_dbc(vehref.layout_dbc(layout))
    log = None
    if layout["period_from"] == "log":
        log = os.path.join(tmp, name + ".log")
        gen_drive.write_log(log, gen_drive.Drive(layout, seed=5).frames())
    cal = os.path.join(tmp, name + ".cal")
    rc, out, err = vehref.run_tool(vehref.calib_command(layout, log=log, out=cal))
    notes, other = vehref.notes_of(err)
    if not r.check(rc == 0 and not other, "%s: vehicle_calib.py exits 0 with notes only (%d: %s)"
                   % (name, rc, other)):
        return
    with open(cal) as f:
        text = f.read()
    r.check(max(len(line) for line in text.splitlines()) < 510, "%s: every line under 510 characters" % name)
    flat, inputs, corners = vehref.parse_calib(text)
    refs = {}
    for pos, spd, frc, opts in layout["corners"]:
        refs.setdefault(spd, []).append(pos)
        refs.setdefault(frc, []).append(pos)
    r.check(len(inputs) == len(refs), "%s: one input per distinct MSG.SIG (%d inputs, %d signals)"
            % (name, len(inputs), len(refs)))
    sel_of = {}
    for ref, (na, qual, period) in EXPECT[name].items():
        msg, signame = ref.split(".")
        fr = db.frame_by_name(msg)
        sig = fr.signal_by_name(signame)
        found = [(n, d) for n, d in inputs.items() if vehref.ival(d, "id") == fr.arbitration_id.id
                 and signal_of(fr, d) is sig]
        if not r.check(len(found) == 1, "%s: one input for %s (%d)" % (name, ref, len(found))):
            continue
        inp_name, inp = found[0]
        sel_of[ref] = inp_name
        want = {
            "id": fr.arbitration_id.id, "extended": "yes" if fr.arbitration_id.extended else "no",
            "min_dlc": fr.size, "start_bit": sig.get_startbit(bit_numbering=1), "length": sig.size,
            "byte_order": "intel" if sig.is_little_endian else "motorola",
            "signed": "yes" if sig.is_signed else "no", "unit": sig.unit,
            "period_ms": period, "protection": layout["protection"],
        }
        bad = vehref.wrong_keys(inp, want, sig)
        r.check(not bad, "%s %s: layout keys equal canmatrix's signal (wrong: %s)" % (name, ref, bad))
        if sig.mux_val is not None:
            m = next(s for s in fr.signals if s.is_multiplexer)
            r.check(vehref.ival(inp, "mux_start_bit") == m.get_startbit(bit_numbering=1)
                    and vehref.ival(inp, "mux_length") == m.size
                    and inp.get("mux_byte_order") == ("intel" if m.is_little_endian else "motorola")
                    and vehref.ival(inp, "mux_value") == sig.mux_val,
                    "%s %s: multiplexer selector and value from the DBC" % (name, ref))
        else:
            r.check("mux_value" not in inp, "%s %s: no multiplexer" % (name, ref))
        got_na = [vehref.ival(inp, k) for k in ("na_raw", "na_raw2") if k in inp]
        r.check(got_na == na, "%s %s: not-available values %s (want %s)" % (name, ref, got_na, na))
        got_q = (vehref.ival(inp, "qualifier_bit"), vehref.ival(inp, "qualifier_invalid")) \
            if "qualifier_bit" in inp else None
        r.check(got_q == qual, "%s %s: qualifier %s (want %s)" % (name, ref, got_q, qual))
        if layout["protection"] == "counter":
            c = fr.signal_by_name(layout["counters"][msg])
            r.check(vehref.ival(inp, "counter_start_bit") == c.get_startbit(bit_numbering=1)
                    and vehref.ival(inp, "counter_length") == c.size
                    and inp.get("counter_byte_order") == ("intel" if c.is_little_endian else "motorola")
                    and vehref.ival(inp, "counter_modulus") == 1 << c.size,
                    "%s %s: counter signal %s from the DBC" % (name, ref, c.name))
        if layout["protection"] != "none":
            modulus = 1 << fr.signal_by_name(layout["counters"][msg]).size \
                if layout["protection"] == "counter" else 16
            pages = 2 if sig.mux_val is not None else 1   # the fixtures' multiplexed frame has 2 pages
            r.check(vehref.ival(inp, "max_delta_counter") == min(3 * pages, modulus - 1),
                    "%s %s: counter steps of a frame after two lost ones accepted (%s)"
                    % (name, ref, inp.get("max_delta_counter")))
        if layout["protection"] == "p02":
            lst = [int(x, 0) for x in fr.attributes["E2E_DataIDList"].split()]
            r.check([int(x, 0) for x in inp.get("data_id_list", "").split()] == lst,
                    "%s %s: P02 DataIDList from the DBC" % (name, ref))
        r.check(vehref.ival(inp, "stale_cycles", 0) >= 3 and float(inp["step_max"]) > 0
                and float(inp["max"]) > 0, "%s %s: staleness and plausibility set" % (name, ref))
    for pos, spd, frc, opts in layout["corners"]:
        c = corners.get(pos, {})
        area, eta, k = gen_drive.corner_params(opts)
        ok = c.get("speed") == sel_of.get(spd) and c.get("force") == sel_of.get(frc)
        if area is not None:
            ok = ok and same_num(c.get("piston_area_mm2", "nan"), area)
        ok = ok and same_num(c.get("efficiency", "1"), eta) and same_num(c.get("axle_factor", "1"), k)
        r.check(ok, "%s: [corner %s] names its inputs and brake (%s)" % (name, pos, c))
    r.check(set(corners) == {c[0] for c in layout["corners"]}, "%s: exactly the corners asked for" % name)


def refusal_dbc(tmp):
    """A DBC with what the monitor cannot read: a float, a 40-bit signal."""
    p = os.path.join(tmp, "odd.dbc")
    with open(p, "w") as f:
        f.write('VERSION ""\n\nNS_ :\n\nBS_:\n\nBU_: X\n\n'
                'BO_ 256 Odd: 8 X\n'
                ' SG_ WheelSpeedF : 0|32@1+ (1,0) [0|300] "km/h" X\n'
                ' SG_ Wide : 0|40@1+ (0.01,0) [0|300] "km/h" X\n'
                ' SG_ Pedal : 40|8@1+ (0.4,0) [0|100] "%" X\n'
                ' SG_ Pressure : 48|16@1+ (0.1,0) [0|400] "bar" X\n\n'
                'BA_DEF_ BO_  "GenMsgCycleTime" INT 0 65535;\nBA_DEF_DEF_  "GenMsgCycleTime" 0;\n'
                'BA_ "GenMsgCycleTime" BO_ 256 10;\nSIG_VALTYPE_ 256 WheelSpeedF : 1;\n')
    return p


def check_refusals(r, tmp):
    odd = refusal_dbc(tmp)
    intel = vehref.layout_dbc(vehref.LAYOUTS["esc_intel"])
    mot = vehref.layout_dbc(vehref.LAYOUTS["esc_motorola"])
    mux = vehref.layout_dbc(vehref.LAYOUTS["chassis_mux29"])
    garbage = os.path.join(tmp, "garbage.dbc")
    with open(garbage, "wb") as f:
        f.write(b"\x00\x01 this is no DBC \xff\n")
    broken = os.path.join(tmp, "broken.dbc")
    with open(broken, "w") as f:
        f.write('VERSION ""\nBO_ 256 Odd: 8 X\n SG_ S : 0|16@1+ (x,0) [0|1] "km/h" X\n')
    badlog = os.path.join(tmp, "bad.log")
    with open(badlog, "w") as f:
        f.write("no frames here\n")
    ok_force = ["--force", "Odd.Pressure", "--piston-area-mm2", "2000"]
    cases = [
        ("unknown message", [odd, "--corner", "FL", "--speed", "Nope.WheelSpeedF"] + ok_force, "unknown message 'Nope'"),
        ("unknown signal", [odd, "--corner", "FL", "--speed", "Odd.Nope"] + ok_force, "no signal 'Nope'"),
        ("float signal", [odd, "--corner", "FL", "--speed", "Odd.WheelSpeedF"] + ok_force, "float signal"),
        ("length over 32", [odd, "--corner", "FL", "--speed", "Odd.Wide"] + ok_force, "more than 32"),
        ("unknown unit", [mot, "--corner", "FL", "--speed", "ESC_WheelSpeeds.WhlSpd_FL", "--force",
                          "ESC_Brake.BrkPrs_MC", "--force-unit", "furlong"], "not a known unit"),
        ("unit not known without override", [odd, "--corner", "FL", "--speed", "Odd.Pedal"] + ok_force,
         "unit '%' is not known; state it with --speed-unit"),
        ("pressure without piston area", [odd, "--corner", "FL", "--speed", "Odd.Pedal", "--speed-unit",
                                          "km/h", "--force", "Odd.Pressure"], "give --piston-area-mm2"),
        ("a pressure as speed", [odd, "--corner", "FL", "--speed", "Odd.Pressure"] + ok_force, "not a speed"),
        ("missing DBC", [os.path.join(tmp, "none.dbc"), "--corner", "FL", "--speed", "A.B", "--force", "C.D"],
         "cannot read DBC"),
        ("DBC is a directory", [tmp, "--corner", "FL", "--speed", "A.B", "--force", "C.D"], "cannot read DBC"),
        ("garbage DBC", [garbage, "--corner", "FL", "--speed", "A.B", "--force", "C.D"], "not a DBC"),
        ("broken DBC", [broken, "--corner", "FL", "--speed", "Odd.S", "--force", "Odd.S"],
         "broken.dbc:3: not a valid SG_ statement, in message Odd which is asked for"),
        ("no period", [intel, "--corner", "FL", "--speed", "ABS_WheelSpeed.WHEEL_SPEED_FL", "--force",
                       "ABS_WheelPressure.PRESS_FL", "--piston-area-mm2", "2000"],
         "GenMsgCycleTime"),
        ("unreadable log", [intel, "--log", os.path.join(tmp, "none.log"), "--corner", "FL", "--speed",
                            "ABS_WheelSpeed.WHEEL_SPEED_FL", "--force", "ABS_WheelPressure.PRESS_FL",
                            "--piston-area-mm2", "2000"], "cannot read log"),
        ("log without frames", [intel, "--log", badlog, "--corner", "FL", "--speed",
                                "ABS_WheelSpeed.WHEEL_SPEED_FL", "--force", "ABS_WheelPressure.PRESS_FL",
                                "--piston-area-mm2", "2000"], "no candump frame"),
        ("no counter", [mot, "--corner", "FL", "--speed", "ESC_WheelSpeeds.WhlSpd_FL", "--force",
                        "ESC_Brake.BrkPrs_MC", "--piston-area-mm2", "2000", "--protection", "counter"],
         "--counter ESC_WheelSpeeds.SIGNAL"),
        ("p02 without DataIDList", [mot, "--corner", "FL", "--speed", "ESC_WheelSpeeds.WhlSpd_FL", "--force",
                                    "ESC_Brake.BrkPrs_MC", "--piston-area-mm2", "2000", "--protection", "p02"],
         "E2E_DataIDList"),
        ("p01 without data ID", [mux, "--corner", "FL", "--speed", "BrkCtl_WheelSpd.WheelRpm_FL", "--force",
                                 "BrkCtl_Torque.BrakeTorque_Front", "--protection", "p01", "--period-ms", "10"],
         "E2E_DataID"),
        ("bad corner", [odd, "--corner", "XX", "--speed", "Odd.Pedal"] + ok_force, "not one of FL"),
        ("corner twice", [odd, "--corner", "FL", "--speed", "Odd.Pedal", "--speed-unit", "km/h"] + ok_force
         + ["--corner", "fl"], "given twice"),
        ("no force", [odd, "--corner", "FL", "--speed", "Odd.Pedal", "--speed-unit", "km/h"], "--force MSG.SIG missing"),
        ("no corner", [odd], "no --corner"),
        ("bad number", [odd, "--corner", "FL", "--speed", "Odd.Pedal", "--speed-unit", "km/h", "--force",
                        "Odd.Pressure", "--piston-area-mm2", "big"], "not a number"),
        ("bad protection", [odd, "--corner", "FL", "--speed", "Odd.Pedal", "--speed-unit", "km/h"] + ok_force
         + ["--protection", "crc"], "invalid choice"),
    ]
    for what, args, needle in cases:
        rc, out, err = vehref.run_tool([vehref.PY, vehref.TOOL, "--dbc"] + args)
        lines = err.splitlines()
        r.check(rc != 0 and len(lines) == 1 and "Traceback" not in err and needle in err and out == "",
                "refusal, %s: exit %d, one line naming %r; got %r" % (what, rc, needle, err))
    # the override makes an unknown unit usable
    rc, out, err = vehref.run_tool([vehref.PY, vehref.TOOL, "--dbc", odd, "--corner", "FL", "--speed",
                                    "Odd.Pedal", "--speed-unit", "km/h"] + ok_force)
    r.check(rc == 0 and "unit = km/h" in out, "--speed-unit states an unknown unit (%d %s)" % (rc, err))


def check_periods(r):
    rng = random.Random(2)
    for period_ms in (10, 20, 24):
        for drop, label in ((0.03, "3 % dropped"), (0.2, "20 % dropped, bursts"), (0.6, "60 % dropped")):
            t, times = 0.0, []
            while len(times) < 400:
                if rng.random() >= drop:
                    times.append(t + rng.uniform(-0.0006, 0.0006))
                elif rng.random() < 0.3:
                    t += period_ms / 1000.0  # a second one lost
                t += period_ms / 1000.0
            times = times[:200] + [x - 2.8 for x in times[200:]]   # the logger's jump back
            got = vc.measure_period(times)
            r.check(got == period_ms, "period of a %d ms stream, %s, jump back: %s ms" % (period_ms, label, got))
    r.check(vc.measure_period([0.0, 0.01, 0.02]) is None, "too few frames: no period")


def check_dbc_out(r, tmp):
    layout = vehref.LAYOUTS["esc_intel"]
    log = os.path.join(tmp, "dbcout.log")
    gen_drive.write_log(log, gen_drive.Drive(layout, seed=5).frames())
    out = os.path.join(tmp, "outputs.dbc")
    rc, _, err = vehref.run_tool(vehref.calib_command(layout, log=log, out=os.path.join(tmp, "x.cal"),
                                                      extra=["--dbc-out", out]))
    if not r.check(rc == 0, "--dbc-out runs: %s" % err):
        return
    db = vehref.load_dbc(out)
    sq = vehref.load_dbc(vehref.SQUEAL_DBC)
    r.check(len(db.frames) == 16, "--dbc-out: 4 corners x 4 messages (%d)" % len(db.frames))
    for k, pos in enumerate(vehref.POSITIONS):
        for name in ("SquealStatus", "SquealDetail", "SquealDiag", "SquealDetail2"):
            orig = sq.frame_by_name(name)
            nm = name if pos == "FL" else name + "_" + pos
            f = db.frame_by_name(nm)
            if not r.check(f is not None, "--dbc-out: message %s" % nm):
                continue
            same = [(s.name, s.get_startbit(bit_numbering=1), s.size, s.is_little_endian, s.is_signed,
                     s.factor, s.offset, s.unit, s.multiplex, dict(s.values)) for s in f.signals] == \
                   [(s.name, s.get_startbit(bit_numbering=1), s.size, s.is_little_endian, s.is_signed,
                     s.factor, s.offset, s.unit, s.multiplex, dict(s.values)) for s in orig.signals]
            r.check(f.arbitration_id.id == orig.arbitration_id.id + 0x10 * k and same
                    and f.cycle_time == orig.cycle_time
                    and f.attributes.get("E2E_DataID") == orig.attributes.get("E2E_DataID"),
                    "--dbc-out: %s at 0x%X with squeal.dbc's signals, period and data ID"
                    % (nm, orig.arbitration_id.id + 0x10 * k))


def check_base(r, tmp):
    layout = vehref.LAYOUTS["esc_motorola"]
    base = os.path.join(tmp, "base.cal")
    with open(os.path.join(vehref.ROOT, "docs", "calib-example.txt")) as f:
        text = f.read()
    with open(base, "w") as f:
        f.write(text.replace("debounce_count = 3", "debounce_count = 4")
                + "\n[input Old]\nid = 0x5\n[corner RL]\nspeed = Old\n")
    rc, out, err = vehref.run_tool(vehref.calib_command(layout, extra=["--base", base, "--pad-radius-m", "0.13"]))
    if not r.check(rc == 0, "--base runs: %s" % err):
        return
    flat, inputs, corners = vehref.parse_calib(out)
    bflat, _, _ = vehref.parse_calib(text)
    kept = all(flat.get(k) == v for k, v in bflat.items()
               if k not in vc.LEGACY_KEYS and k not in ("debounce_count", "pad_radius_m"))
    r.check(kept and flat.get("debounce_count") == "4", "--base: its flat keys kept")
    r.check(not any(k in flat for k in vc.LEGACY_KEYS), "--base: legacy input keys dropped")
    r.check(flat.get("pad_radius_m") == "0.13", "--pad-radius-m overrides the base")
    r.check("Old" not in inputs and set(corners) == {"FL", "RL"}, "--base: its old sections dropped")


def check_references(r, tmp):
    r.check(vehref.crc8h2f(b"123456789") == 0xDF, "CRC-8H2F check value 0xDF")
    r.check(vehref.crc8(b"123456789", 0x1D, 0, 0) == 0x37, "CRC-8 0x1D check value 0x37")
    r.check(abs(vehref.force_of(40, "bar", area_mm2=2290) - 9160) < 1e-6, "40 bar on 2290 mm^2 is 9.16 kN")
    r.check(abs(vehref.v0_of(108, "km/h") - 12.0) < 1e-12 and abs(vehref.v0_of(60, "rpm") - 2 * 3.141592653589793 * 0.12) < 1e-12,
            "speed conversions (108 km/h at r_w 0.3 is v0 12 m/s at r_p 0.12)")
    n = vehref.force_of(648.0, "Nm", v0=50.0)
    r.check(abs(n - 648.0 / (2 * 0.25 * 0.12)) < 1e-6, "torque: N = T / (n_f mu(v0) r_p)")
    # the cross-check harness on the pure-Python reference, and that it sees a wrong value
    total = 0
    for name, layout in vehref.LAYOUTS.items():
        total += xcheck.run_layout(r, name, layout, tmp, 2000, True) or 0
    for name, layout in vehref.FIELD_LAYOUTS.items():   # extended, cascaded, independent multiplexing
        total += xcheck.run_field(r, name, layout, tmp, 3000, True) or 0
    print("cross-check harness self-test: %d frame-input pairs" % total)
    layout = vehref.LAYOUTS["esc_motorola"]
    rc, text, _ = vehref.run_tool(vehref.calib_command(layout))
    db = vehref.load_dbc(vehref.layout_dbc(layout))
    _, inputs, _ = vehref.parse_calib(text)
    frames = xcheck.random_frames(layout, db, inputs, 300, 1)
    exp = xcheck.canmatrix_rows(db, inputs, frames)
    wrong = text.replace("start_bit = 6\n", "start_bit = 5\n", 1)
    r2 = Quiet()
    xcheck.compare(r2, "mutant", xcheck.reference_csv(wrong, frames), exp, inputs)
    r.check(r2.failed > 0, "the cross-check harness catches a start bit off by one")
    # the end-to-end harness on its stand-in, including the jump
    for name, layout in vehref.LAYOUTS.items():
        e2e_harness.run_layout(r, "self-test " + name, layout, tmp, e2e_harness.fake_replay)


def check_mutants(r, tmp, n=150):
    """Damaged DBCs (lines dropped, doubled, cut, bytes flipped): the tool
    either builds a calibration or refuses in one line, never a traceback."""
    import contextlib
    import io
    rng = random.Random(4)
    layout = vehref.LAYOUTS["esc_motorola"]
    with open(vehref.layout_dbc(layout)) as f:
        lines = f.read().splitlines()
    bad = []
    built = 0
    path = os.path.join(tmp, "mutant.dbc")
    for k in range(n):
        m = list(lines)
        for _ in range(rng.randint(1, 3)):
            i = rng.randrange(len(m))
            op = rng.randrange(4)
            if op == 0:
                del m[i]
            elif op == 1:
                m.insert(i, m[i])
            elif op == 2:
                m[i] = m[i][:rng.randrange(len(m[i]) + 1)]
            elif m[i]:
                j = rng.randrange(len(m[i]))
                m[i] = m[i][:j] + chr(rng.choice(b"|@+-(),:;\"x0 ")) + m[i][j + 1:]
        with open(path, "w") as f:
            f.write("\n".join(m) + "\n")
        err, out = io.StringIO(), io.StringIO()
        argv = ["--dbc", path, "--corner", "FL", "--speed", "ESC_WheelSpeeds.WhlSpd_FL", "--force",
                "ESC_Brake.BrkPrs_MC", "--piston-area-mm2", "2290", "--period-ms", "20", "-o", "-"]
        try:
            with contextlib.redirect_stderr(err), contextlib.redirect_stdout(out):
                rc = vc.main(argv)
        except BaseException as e:  # noqa: B902  (anything escaping main is the failure)
            rc, err = -1, io.StringIO("%s %s" % (type(e).__name__, e))
        notes, other = vehref.notes_of(err.getvalue())
        built += rc == 0
        if not ((rc == 0 and not other) or (rc == 1 and err.getvalue().count("\n") == 1)):
            bad.append((k, rc, err.getvalue()[:200]))
    r.check(not bad, "%d damaged DBCs: a calibration or a one-line refusal each (%d not: %s)"
            % (n, len(bad), bad[:3]))
    r.check(built > n // 3, "damaged DBCs: most still give a calibration (%d of %d)" % (built, n))


def check_own_dbc(r):
    """Today's inputs from squeal.dbc: P01 with the DBC's data IDs."""
    rc, out, err = vehref.run_tool([vehref.PY, vehref.TOOL, "--dbc", vehref.SQUEAL_DBC, "--corner", "FL",
                                    "--speed", "DiscSpeed.DiscSpeed_radps", "--force", "PadForce.PadForce_N",
                                    "--protection", "p01"])
    _, inputs, corners = vehref.parse_calib(out)
    sq = vehref.load_dbc(vehref.SQUEAL_DBC)
    ok = rc == 0 and len(inputs) == 2
    for name, msg in (("DiscSpeed_radps", "DiscSpeed"), ("PadForce_N", "PadForce")):
        f = sq.frame_by_name(msg)
        inp = inputs.get(name, {})
        ok = ok and vehref.ival(inp, "id") == f.arbitration_id.id and inp.get("protection") == "p01" \
            and vehref.ival(inp, "data_id") == int(f.attributes["E2E_DataID"]) \
            and vehref.ival(inp, "period_ms") == f.cycle_time and inp.get("na_raw") == "65535" \
            and vehref.ival(inp, "start_bit") == 16 and vehref.ival(inp, "min_dlc") == f.size
    r.check(ok, "squeal.dbc's own inputs: P01 with E2E_DataID, 10 ms, 65535 not available (%s)" % err.strip())


def check_drive(r):
    """The drive generator against canmatrix and the protections' definitions."""
    for name, layout in vehref.LAYOUTS.items():
        db = vehref.load_dbc(vehref.layout_dbc(layout))
        frames = gen_drive.Drive(layout, seed=9, jump=True).frames()
        back = [b[0] - a[0] for a, b in zip(frames, frames[1:]) if b[0] < a[0]]
        r.check(len(back) == 1 and abs(back[0] + 2.8) < 0.03,   # less the gap between two frames
                "%s drive: one 2.8 s jump back (%s)" % (name, back))
        for msg, period in layout["period_s"].items():
            f = db.frame_by_name(msg)
            mine = [(t, d) for t, i, e, d in frames if i == f.arbitration_id.id
                    and e == bool(f.arbitration_id.extended)]
            expect = gen_drive.BRAKING_RUN_S / period
            r.check(0.9 * expect < len(mine) < 0.995 * expect,
                    "%s drive: %s every %g ms with a few frames dropped (%d of %d)"
                    % (name, msg, period * 1e3, len(mine), int(expect)))
            r.check(vc.measure_period([t for t, _ in mine]) == round(period * 1e3),
                    "%s drive: %s's period measured back" % (name, msg))
            ctr_name = layout.get("counters", {}).get(msg)
            prev, ok, steps = None, True, set()
            for t, d in mine:
                dec = f.decode(bytearray(d))
                if layout["protection"] == "p02":
                    lst = [int(x, 0) for x in f.attributes["E2E_DataIDList"].split()]
                    ctr = d[1] & 0x0F
                    ok = ok and d[0] == vehref.crc8h2f(list(d[1:]) + [lst[ctr]])
                    mod = 16
                elif ctr_name:
                    ctr = int(dec[ctr_name].raw_value)
                    mod = 1 << f.signal_by_name(ctr_name).size
                else:
                    continue
                if prev is not None:
                    steps.add((ctr - prev) % mod)
                prev = ctr
            if layout["protection"] != "none":
                r.check(ok and steps == {1, 2, 3}, "%s drive: %s's CRC right, counter steps %s (1, and 2-3 "
                        "after lost frames)" % (name, msg, sorted(steps)))


def main():
    os.environ["VEHICLE_CALIB_SIM"] = vehref.STUB_CHECKER   # for vc.main() in this process
    r = vehref.Results()
    with tempfile.TemporaryDirectory() as tmp:
        for name, layout in vehref.LAYOUTS.items():
            check_layout(r, name, layout, tmp)
        check_refusals(r, tmp)
        check_periods(r)
        check_own_dbc(r)
        check_mutants(r, tmp)
        check_drive(r)
        check_dbc_out(r, tmp)
        check_base(r, tmp)
        check_references(r, tmp)
    r.finish()


if __name__ == "__main__":
    sys.exit(main())
