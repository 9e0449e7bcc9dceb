#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Canmatrix cross-check of the input map: for every fixture
layout, a calibration built by tools/vehicle_calib.py from the DBC, thousands
of random frames of the configured messages (random payloads, random
multiplexer pages, 10 % of them shorter than the DBC's DLC), and
`squeal-sim decode --calib FILE --inputs-csv LOG` must give, for every frame
and configured input, the raw and physical value canmatrix decodes from the
DBC (and reason `dlc`, with raw and physical empty, for a short frame), and
no line for a frame of another page or another identifier.

    test_vehicle_crosscheck.py [--self-test] [--frames N]

--self-test runs the same harness on the pure-Python reference of
vehref.reference_rows instead of squeal-sim (no C needed).
Prints "RESULT: N passed, M failed".
"""
import csv
import io
import os
import random
import sys
import tempfile
import zlib
# tests/ of this checkout, and the folders its helper modules live in
_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, d) for d in ("support", os.path.join("support", "reference"), "host-sim", "tools")]

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import vehref  # noqa: E402
import gen_drive  # noqa: E402

# decode prints each unit in its canonical spelling (docs/calib-input-map.md):
# the calibration's "kph" or "Km/h" is "km/h" there, "1/min" is "rpm"
UNIT_SYNONYMS = {"kph": "km/h", "1/min": "rpm"}


def canon_unit(u):
    u = u.strip().lower()
    return UNIT_SYNONYMS.get(u, u)


HEADER = ["t_s", "iface", "id", "input", "raw", "physical", "unit", "valid", "reason"]
FRAMES_PER_LAYOUT = 3000


def random_frames(layout, db, inputs, n, seed):
    """[(t_text, id, extended, data)]: frames of the inputs' messages and a few
    foreign ones, each with its own timestamp (1 ms apart)."""
    rng = random.Random(seed)
    msgs = vehref.input_messages(inputs)
    out = []
    for k in range(n):
        t = "%d.%06d" % (1700000000 + k // 1000, (k % 1000) * 1000)
        r = rng.random()
        if r < 0.03:   # a foreign identifier, or ours with the other length
            cid, ext = rng.choice(msgs)
            if rng.random() < 0.5:
                cid, ext = (cid ^ 0x1) & (0x1FFFFFFF if ext else 0x7FF), ext
            else:
                ext = not ext
                if not ext and cid > 0x7FF:
                    cid &= 0x7FF
        else:
            cid, ext = rng.choice(msgs)
        size = 8
        for fr in db.frames:
            if fr.arbitration_id.id == cid and bool(fr.arbitration_id.extended) == ext:
                size = fr.size
        dlc = size if rng.random() >= 0.1 else rng.randint(2 if size >= 2 else 0, max(0, size - 1))
        data = bytearray(rng.randrange(256) for _ in range(dlc))
        if dlc >= 2 and rng.random() < 0.5:
            data[1] = (data[1] & 0x0F) | (rng.randint(0, 2) << 4)  # multiplexer pages 0..2 often
        out.append((t, cid, ext, bytes(data)))
    return out


def cm_carries(fr, sig, data):
    """canmatrix's rule for the page that carries a signal: what decode()
    returns, for plain and simple multiplexing; for extended multiplexing
    (SG_MUL_VAL_) the signal's chain of selectors (muxer_for_signal) with
    canmatrix's multiplexer_value_in_range on unpack()'s raw values: decode()
    follows the first multiplexor only, so the second of two independent
    multiplexors needs the chain (consistency with decode() is checked)."""
    if not fr.is_complex_multiplexed:
        return sig.name in fr.decode(data)
    raw = {n: v.raw_value for n, v in fr.unpack(data).items()}
    s = sig
    for _ in range(8):
        if s.muxer_for_signal is None:
            return s.mux_val is None
        m = fr.signal_by_name(s.muxer_for_signal)
        if not s.multiplexer_value_in_range(raw[m.name]):
            return False
        s = m
    return False


CM_CONSISTENCY = {"frames": 0, "bad": 0}


def canmatrix_rows(db, inputs, frames, scale=None):
    """The expectation from canmatrix: {(t, input): (raw, physical) or 'dlc'}
    (physical times the layout's scale of the input's MSG.SIG)."""
    by_key = {}
    for fr in db.frames:
        by_key[(fr.arbitration_id.id, bool(fr.arbitration_id.extended))] = fr
    sig_of = {}
    for name, inp in inputs.items():
        fr = by_key[(vehref.ival(inp, "id"), vehref.yes(inp, "extended"))]
        sig_of[name] = (fr, fr_signal(fr, inp))
    exp = {}
    for t, cid, ext, data in frames:
        fr = by_key.get((cid, ext))
        if fr is None:
            continue
        full = bytearray(data) + bytearray(fr.size - len(data))
        if fr.is_complex_multiplexed:
            CM_CONSISTENCY["frames"] += 1
            CM_CONSISTENCY["bad"] += sum(1 for n in fr.decode(full)
                                         if not cm_carries(fr, fr.signal_by_name(n), full))
        for name, (f, sig) in sig_of.items():
            if f is not fr or not cm_carries(fr, sig, full):
                continue
            if len(data) < fr.size:
                exp[(t, name)] = "dlc"
            else:
                d = fr.unpack(bytearray(data))[sig.name]
                k = (scale or {}).get(inputs[name].get("_ref"), 1.0)
                exp[(t, name)] = (int(d.raw_value), float(d.raw_value * sig.factor + sig.offset) * k)
    return exp


def fr_signal(fr, inp):
    """The DBC signal an input was built from: by its `signal` name, else the
    same start bit, length and page."""
    if "signal" in inp and fr.signal_by_name(inp["signal"].split(".", 1)[1]) is not None:
        return fr.signal_by_name(inp["signal"].split(".", 1)[1])
    for s in fr.signals:
        if (s.get_startbit(bit_numbering=1) == vehref.ival(inp, "start_bit") and s.size == vehref.ival(inp, "length")
                and (s.mux_val is None) == ("mux_value" not in inp)
                and (s.mux_val is None or s.mux_val == vehref.ival(inp, "mux_value"))):
            return s
    raise KeyError("no DBC signal for input %r" % inp)


def sim_rows(calib_path, log_path):
    rc, out, err = vehref.run_sim(["decode", "--calib", calib_path, "--inputs-csv", log_path])
    return rc, out.decode("utf-8", "replace"), err


def reference_csv(calib_text, frames):
    _, inputs, _ = vehref.parse_calib(calib_text)
    out = io.StringIO()
    w = csv.writer(out, lineterminator="\n")
    w.writerow(HEADER)
    for t, idt, name, raw, phys, reason in vehref.reference_rows(inputs, frames):
        w.writerow([t, "can0", idt, name, "" if raw is None else raw,
                    "" if phys is None else "%.9g" % phys, inputs[name]["unit"],
                    1 if reason == "ok" else 0, reason])
    return out.getvalue()


def compare(r, label, csv_text, exp, inputs):
    """Every expected (frame, input) once, with canmatrix's values; nothing else."""
    rows = list(csv.reader(io.StringIO(csv_text)))
    if not r.check(rows and rows[0] == HEADER, "%s: CSV header %s" % (label, rows[:1])):
        return
    got = {}
    dup = extra = bad = 0
    first_bad = []
    for row in rows[1:]:
        if len(row) != len(HEADER):
            bad += 1
            first_bad.append(row)
            continue
        key = (row[0], row[3])
        if key in got:
            dup += 1
        got[key] = row
    for key, row in got.items():
        e = exp.get(key)
        if e is None:
            extra += 1
            first_bad.append(("unexpected", row))
            continue
        if e == "dlc":
            ok = row[8] == "dlc" and row[4] == "" and row[5] == "" and row[7] == "0"
        else:
            try:
                ok = int(row[4]) == e[0] and abs(float(row[5]) - e[1]) <= 1e-7 * max(1.0, abs(e[1])) \
                    and canon_unit(row[6]) == canon_unit(inputs[row[3]]["unit"]) \
                    and row[8] != "dlc"
            except ValueError:
                ok = False
        if not ok:
            bad += 1
            if len(first_bad) < 5:
                first_bad.append((row, e))
    missing = [k for k in exp if k not in got]
    r.check(len(exp) > 1000, "%s: %d frame-input pairs to compare" % (label, len(exp)))
    r.check(dup == 0, "%s: no frame-input pair twice (%d)" % (label, dup))
    r.check(not missing, "%s: every configured input of every frame reported (%d missing, first %s)"
            % (label, len(missing), missing[:3]))
    r.check(extra == 0 and bad == 0, "%s: raw, physical, unit and dlc equal canmatrix's "
            "(%d wrong, %d unexpected; first %s)" % (label, bad, extra, first_bad[:5]))
    n_dlc = sum(1 for v in exp.values() if v == "dlc")
    r.check(n_dlc > 50, "%s: short frames compared (%d)" % (label, n_dlc))
    return len(exp)


def decoded_rows(r, name, cal, text, frames, tmp, self_test):
    """The input rows of frames decoded with cal: written as a candump log
    and decoded by `squeal-sim decode --calib --inputs-csv`, or by the
    reference decoder under --self-test; None (a counted failure) where the
    program did not run."""
    logp = os.path.join(tmp, name + "-random.log")
    with open(logp, "w") as f:
        for t, cid, ext, data in frames:
            f.write("(%s) can0 %s#%s\n" % (t, ("%08X" if ext else "%03X") % cid, data.hex().upper()))
    if self_test:
        return reference_csv(text, frames)
    rc, out, err = sim_rows(cal, logp)
    if rc != 0:
        vehref.sim_missing(r, "%s: decode --calib %s --inputs-csv" % (name, os.path.basename(cal)), rc, err)
        return None
    return out


def run_layout(r, name, layout, tmp, n, self_test):
    db = vehref.load_dbc(vehref.layout_dbc(layout))
    extra = []
    if layout["period_from"] == "log":
        drive = os.path.join(tmp, name + "-period.log")
        gen_drive.write_log(drive, gen_drive.Drive(layout, seed=3).frames())
        log = drive
    else:
        log = None
    cal = os.path.join(tmp, name + ".cal")
    rc, _, err = vehref.run_tool(vehref.calib_command(layout, log=log, out=cal, extra=extra))
    if not r.check(rc == 0, "%s: vehicle_calib.py builds the calibration: %s" % (name, err.strip())):
        return 0
    with open(cal) as f:
        text = f.read()
    _, inputs, _ = vehref.parse_calib(text)
    frames = random_frames(layout, db, inputs, n, seed=zlib.crc32(name.encode()))
    exp = canmatrix_rows(db, inputs, frames)
    out = decoded_rows(r, name, cal, text, frames, tmp, self_test)
    if out is None:
        return 0
    return compare(r, name, out, exp, inputs)


def run_field(r, name, layout, tmp, n, self_test):
    """A field layout: the tool's arguments as a user gives them, random
    frames with every page of every selector, the rows vs canmatrix's."""
    path = os.path.join(vehref.FIXTURES, layout["dbc"])
    db = vehref.load_dbc(path)
    cal = os.path.join(tmp, name + ".cal")
    rc, _, err = vehref.run_tool([vehref.PY, vehref.TOOL, "--dbc", path] + layout["args"] + ["-o", cal])
    notes, other = vehref.notes_of(err)
    if not r.check(rc == 0, "%s: vehicle_calib.py builds the calibration: %s" % (name, other)):
        return 0
    with open(cal) as f:
        text = f.read()
    _, inputs, _ = vehref.parse_calib(text)
    for inp in inputs.values():   # the scale is the layout's, by the input's signal = MSG.SIG
        inp["_ref"] = inp.get("signal")
    frames = random_frames(layout, db, inputs, n, seed=zlib.crc32(name.encode()))
    exp = canmatrix_rows(db, inputs, frames, layout["scale"])
    out = decoded_rows(r, name, cal, text, frames, tmp, self_test)
    if out is None:
        return 0
    r.check(CM_CONSISTENCY["bad"] == 0, "%s: the page rule agrees with canmatrix's decode() (%d frames, %d not)"
            % (name, CM_CONSISTENCY["frames"], CM_CONSISTENCY["bad"]))
    return compare(r, name, out, exp, inputs)


def main(argv):
    self_test = "--self-test" in argv
    n = FRAMES_PER_LAYOUT
    if "--frames" in argv:
        n = int(argv[argv.index("--frames") + 1])
    r = vehref.Results()
    total = 0
    sims = [None] if self_test else vehref.SIMS
    with tempfile.TemporaryDirectory() as tmp:
        for sim in sims:
            vehref.SIM = sim
            if sim is not None:
                vehref.use_checker(sim)
            for name, layout in vehref.LAYOUTS.items():
                c = run_layout(r, name, layout, tmp, n, self_test)
                total += c or 0
                print("%s: %d frame-input pairs compared (%s)" % (name, c or 0, sim or "pure-Python reference"))
            for name, layout in vehref.FIELD_LAYOUTS.items():
                c = run_field(r, name, layout, tmp, n, self_test)
                total += c or 0
                print("%s: %d frame-input pairs compared (%s)" % (name, c or 0, sim or "pure-Python reference"))
    print("cross-check: %d frame-input pairs over %d layouts and %d build(s)"
          % (total, len(vehref.LAYOUTS) + len(vehref.FIELD_LAYOUTS), len(sims)))
    r.finish()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
