# SPDX-License-Identifier: MIT
"""Shared pieces of the vehicle-bus tests, independent of the C code:

  - the fixture layouts (which DBC, which signals feed which corner, how the
    drive is sent) and the vehicle_calib.py command for each;
  - a reader of the calibration text's [input]/[corner] sections;
  - a reference extractor written from the DBC conventions (bit by bit, no
    canmatrix), used to validate the harnesses in their self-tests;
  - the conversions of docs/vehicle.md (speed -> v0, pressure/torque -> N);
  - CRC-8H2F (E2E P02) and CRC-8 0x1D (P01), CRC-16/CCITT-FALSE (P05),
    bitwise from their definitions.
"""
import contextlib
import io
import logging
import math
import os
import re
import subprocess
import sys
import warnings
# tests/ of this checkout, and the folders its helper modules live in
_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, d) for d in ("support", os.path.join("support", "reference"), "host-sim", "tools")]

HERE = os.path.dirname(os.path.abspath(__file__))
# the fixture DBCs of the vehicle tests
FIXTURES = os.path.join(_TESTS, "tools", "fixtures")
ROOT = os.path.dirname(_TESTS)
import dbc_common  # noqa: E402
TOOL = os.path.join(ROOT, "tools", "vehicle_calib.py")
SQUEAL_DBC = os.path.join(ROOT, "firmware", "protocol", "squeal.dbc")
PY = "/usr/bin/python3"
# squeal-sim under test: both numeric builds with the sanitizers (SQUEAL_SIM
# names one program instead); tests set SIM to each in turn.
SIMS = [os.environ["SQUEAL_SIM"]] if os.environ.get("SQUEAL_SIM") else \
    [os.path.join(ROOT, "build", v, "squeal-sim") for v in ("test", "test-fixed")]
SIM = SIMS[0]

WHEEL_RADIUS_M = 0.3   # calibration defaults (docs/calib-example.txt)
PAD_RADIUS_M = 0.12
MU_INF, DELTA_MU, SLOPE_SPM = 0.25, 0.15, 2.0
FRICTION_FACES = 2
POSITIONS = ("FL", "FR", "RL", "RR")

# Each layout: the DBC, the corners (speed MSG.SIG, force MSG.SIG, extra
# per-corner options), global options, and how the drive is sent: frame
# period per message, the protection, per-corner scale of the wheel speed and
# of the force (so a swapped corner shows), other traffic.
LAYOUTS = {
    "esc_motorola": {
        "dbc": "esc_motorola.dbc",
        "corners": [("FL", "ESC_WheelSpeeds.WhlSpd_FL", "ESC_Brake.BrkPrs_MC", ["--piston-area-mm2", "2290"]),
                    ("RL", "ESC_WheelSpeeds.WhlSpd_RL", "ESC_Brake.BrkPrs_MC",   # unit written "Km/h"
                     ["--piston-area-mm2", "1500", "--axle-factor", "0.8", "--efficiency", "0.95"])],
        "options": ["--protection", "none"],
        "period_s": {"ESC_WheelSpeeds": 0.020, "ESC_Brake": 0.020},
        "protection": "none",
        "other": ["BCM_Status", 0x7E8, 0x5A0],
        "qualifier_ok": {"WhlSpd_FL_Flt": 0, "WhlSpd_FR_Flt": 0, "WhlSpd_RL_Flt": 0, "WhlSpd_RR_Flt": 0,
                         "BrkPrs_MC_Stat": 0},
        "speed_scale": {"FL": 1.0, "RL": 0.98},
        "period_from": "GenMsgCycleTime",
    },
    "esc_intel": {
        "dbc": "esc_intel.dbc",
        "corners": [(p, "ABS_WheelSpeed.WHEEL_SPEED_" + p, "ABS_WheelPressure.PRESS_" + p,
                     ["--piston-area-mm2", a]) for p, a in
                    (("FL", "2290"), ("FR", "2290"), ("RL", "1250"), ("RR", "1250"))],
        "options": ["--protection", "counter"],
        "period_s": {"ABS_WheelSpeed": 0.024, "ABS_WheelPressure": 0.024},
        "protection": "counter",
        "counters": {"ABS_WheelSpeed": "ABS_COUNTER", "ABS_WheelPressure": "PRESS_COUNTER"},
        "other": ["ABS_Misc", 0x3E9, 0x130],
        "speed_scale": {"FL": 1.0, "FR": 1.01, "RL": 0.99, "RR": 0.985},
        "pressure_scale": {"FL": 1.0, "FR": 0.96, "RL": 0.7, "RR": 0.68},
        "period_from": "log",
    },
    "chassis_mux29": {
        "dbc": "chassis_mux29.dbc",
        "corners": [("FL", "BrkCtl_WheelSpd.WheelRpm_FL", "BrkCtl_Torque.BrakeTorque_Front", []),
                    ("RL", "BrkCtl_WheelSpd.WheelRpm_RL", "BrkCtl_Torque.BrakeTorque_Rear", [])],
        "options": ["--protection", "p02", "--period-ms", "10"],
        "period_s": {"BrkCtl_WheelSpd": 0.010, "BrkCtl_Torque": 0.010},
        "protection": "p02",
        "other": ["Chassis_Info", 0x123, 0x18FEF100],
        "qualifier_ok": {"BrakeTorque_Front_Invalid": 0, "BrakeTorque_Rear_Invalid": 0},
        "speed_scale": {"FL": 1.0, "RL": 1.02},
        "torque_scale": {"FL": 1.0, "RL": 0.5},
        "period_from": "GenMsgCycleTime x pages / --period-ms",
    },
}
# Kept apart: no unit test uses it (the check on a layout no other test uses).
UNSEEN = {
    "dbc": os.path.join("unseen", "ev_chassis.dbc"),
    "corners": [("FL", "VDC_WheelSpeeds.WheelSpeed_FrontLeft", "VDC_BrakePressure.MasterCylPressure",
                 ["--piston-area-mm2", "2290"]),
                ("RR", "VDC_WheelSpeeds.WheelSpeed_RearRight", "VDC_BrakePressure.MasterCylPressure",
                 ["--piston-area-mm2", "1200"])],
    "options": ["--protection", "counter"],
    "period_s": {"VDC_WheelSpeeds": 0.010, "VDC_BrakePressure": 0.010},
    "protection": "counter",
    "counters": {"VDC_WheelSpeeds": "VDC_WS_Counter", "VDC_BrakePressure": "VDC_BP_Counter"},
    "qualifier_ok": {"WheelSpeed_FrontLeft_V": 1},
    "other": [0x101, 0x6F0],
    "speed_scale": {"FL": 1.0, "RR": 0.99},
    "period_from": "GenMsgCycleTime",
}

# Field layouts (tests/tools/fixtures/field/): cross-checked only (decode vs
# canmatrix); the tool's arguments as a user gives them, and the scale the
# tool folds into an input, by its signal = MSG.SIG (canmatrix's physical
# value times it).
FIELD_LAYOUTS = {
    "field_esc": {
        "dbc": os.path.join("field", "field_esc.dbc"),
        "args": ["--corner", "FL", "--speed", "WhlRad.WhlRad_FL", "--force", "Brems_7.BS7_Hauptdruck",
                 "--piston-area-mm2", "2290",
                 "--corner", "FR", "--speed", "WhlRad.WhlRad_FR", "--force", "Brk_Torque.BrkTot_Tq",
                 "--torque-share", "0.35",
                 "--corner", "RL", "--speed", "WSL.WSL_FL", "--force", "Pedal_Stat.BrkPedal_Pos",
                 "--force-unit", "bar", "--unit-scale", "2", "--piston-area-mm2", "2000",
                 "--corner", "RR", "--speed", "VehSpd.VehSpd_Disp", "--speed-scale", "1.5",
                 "--force", "Brk_Torque.BrkTot_Tq", "--torque-share", "0.15"],
        "scale": {"Pedal_Stat.BrkPedal_Pos": 2.0, "VehSpd.VehSpd_Disp": 1.5},
    },
    "field_mux": {
        "dbc": os.path.join("field", "field_mux.dbc"),
        "args": ["--corner", "FL", "--speed", "WhlMux_Ext.WME_Front", "--force", "WhlMux_Ext.WME_Press",
                 "--piston-area-mm2", "2290",
                 "--corner", "FR", "--speed", "WhlMux_Ext.WME_Rear", "--force", "BrkMux_Casc.BMC_PressFront",
                 "--piston-area-mm2", "2290",
                 "--corner", "RL", "--speed", "BrkMux_Casc.BMC_Speed", "--force", "BrkMux_Casc.BMC_PressRear",
                 "--piston-area-mm2", "1500",
                 "--corner", "RR", "--speed", "WhlMux_Indep.WMI_SpeedA1", "--force", "WhlMux_Indep.WMI_PressB23",
                 "--piston-area-mm2", "1500", "--period-ms", "10"],
        "scale": {},
    },
}


def layout_dbc(layout):
    return os.path.join(FIXTURES, layout["dbc"])


def calib_command(layout, log=None, out=None, extra=()):
    cmd = [PY, TOOL, "--dbc", layout_dbc(layout)]
    if log:
        cmd += ["--log", log]
    for pos, spd, frc, opts in layout["corners"]:
        cmd += ["--corner", pos, "--speed", spd, "--force", frc] + list(opts)
    cmd += list(layout["options"]) + list(extra)
    if out:
        cmd += ["-o", out]
    return cmd


# What checks the calibrations vehicle_calib.py writes: the stand-in
# (stub_calib_check.py) in the Python-only tests; the tests that run
# squeal-sim set it to the program under test (use_checker).
STUB_CHECKER = os.path.join(_TESTS, "tools", "stub_calib_check.py")
CHECKER = STUB_CHECKER


def has_calib_check(sim):
    """squeal-sim answers `calib-check --help` (the command exists)."""
    try:
        p = subprocess.run([sim, "calib-check", "--help"], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                           timeout=60)
    except (OSError, subprocess.TimeoutExpired):
        return False
    return p.returncode == 0


def use_checker(sim):
    """Check with sim's calib-check; a squeal-sim without the command is
    reported (printed) and the stand-in checks instead."""
    global CHECKER
    if sim and has_calib_check(sim):
        CHECKER = sim
    else:
        print("note: %s has no calib-check command; the calibrations are checked by %s"
              % (sim, os.path.basename(STUB_CHECKER)))
        CHECKER = STUB_CHECKER
    return CHECKER


def run_tool(args, cwd=None, checker=None):
    env = dict(os.environ)
    env["VEHICLE_CALIB_SIM"] = checker or CHECKER
    p = subprocess.run(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, cwd=cwd, env=env)
    return p.returncode, p.stdout.decode("utf-8", "replace"), p.stderr.decode("utf-8", "replace")


def notes_of(err):
    """The note lines of a successful run's stderr, and the other lines."""
    notes = [l for l in err.splitlines() if l.startswith("vehicle_calib.py: note: ")]
    other = [l for l in err.splitlines() if l and not l.startswith("vehicle_calib.py: note: ")]
    return notes, other


def load_dbc(path):
    logging.disable(logging.CRITICAL)
    with warnings.catch_warnings(), contextlib.redirect_stdout(io.StringIO()):
        warnings.simplefilter("ignore")
        import canmatrix.formats
        dbs = canmatrix.formats.loadp(path)
    return list(dbs.values())[0]


# ------------------------------------------------------------ calibration text

def parse_calib(text):
    """(flat {key: value}, inputs {name: {key: value}} in file order,
    corners {POS: {key: value}}) of a calibration text."""
    flat, inputs, corners = {}, {}, {}
    cur = flat
    for line in text.splitlines():
        s = line.split("#", 1)[0].strip()
        if not s:
            continue
        m = re.match(r"^\[(input|corner)\s+(\w+)\]$", s)
        if m:
            cur = {}
            (inputs if m.group(1) == "input" else corners)[m.group(2) if m.group(1) == "input"
                                                          else m.group(2).upper()] = cur
            continue
        k, v = (x.strip() for x in s.split("=", 1))
        cur[k] = v
    return flat, inputs, corners


def ival(d, k, default=None):
    return int(d[k], 0) if k in d else default


def yes(d, k):
    return d.get(k, "no").lower() in ("yes", "1")


def input_messages(inputs):
    """The (identifier, extended) of the messages the inputs read, each once,
    in the order of the inputs."""
    keys = []
    for inp in inputs.values():
        k = (ival(inp, "id"), yes(inp, "extended"))
        if k not in keys:
            keys.append(k)
    return keys


def same_num(text, value):
    return abs(float(text) - float(value)) <= 1e-12 * max(1.0, abs(float(value)))


def wrong_keys(inp, want, sig):
    """[(key, written, wanted)] where an input's keys differ from want
    (integers compared by value) or its factor and offset from the DBC
    signal's."""
    bad = []
    for k, v in want.items():
        got = inp.get(k)
        if got is None or not (int(got, 0) == v if isinstance(v, int) else got == v):
            bad.append((k, got, v))
    for k in ("factor", "offset"):
        if not same_num(inp.get(k, "0"), getattr(sig, k)):
            bad.append((k, inp.get(k), getattr(sig, k)))
    return bad


# ------------------------------------------------------------ reference extraction

def bits_of(start, length, intel):
    """DBC bit numbers of a signal, MSB first (the DBC bit numbering of firmware/protocol/can_signal.h)."""
    if intel:
        return list(range(start + length - 1, start - 1, -1))
    out, b = [], start
    for _ in range(length):
        out.append(b)
        b = b - 1 if b % 8 else b + 15
    return out


def extract(data, start, length, order, signed=False):
    """Raw value, None when a bit lies beyond the frame."""
    v = 0
    for b in bits_of(start, length, order == "intel"):
        if b // 8 >= len(data):
            return None
        v = (v << 1) | ((data[b // 8] >> (b % 8)) & 1)
    if signed and (v >> (length - 1)) & 1:
        v -= 1 << length
    return v


def mux_match(inp, data):
    """Every selector condition of the input (mux_*, mux2_*) holds: the
    selector's raw value lies in [value, value_max]."""
    for p in ("mux", "mux2"):
        if p + "_start_bit" not in inp:
            continue
        sel = extract(data, ival(inp, p + "_start_bit"), ival(inp, p + "_length"), inp[p + "_byte_order"])
        lo = ival(inp, p + "_value")
        if sel is None or not lo <= sel <= ival(inp, p + "_value_max", lo):
            return False
    return True


def reference_rows(inputs, frames):
    """What `decode --calib --inputs-csv` must print, from the calibration
    text alone: [(t_text, id_text, input, raw or None, physical or None, reason)]
    for frames [(t_text, can_id, extended, data)]. Reasons modelled: dlc, na,
    qualifier, ok (protection is not modelled: the harness compares raw,
    physical and dlc only). A classic frame of an FD input's identifier
    (data not marked FD: gen_drive.FdData) is the wrong format: dlc."""
    rows = []
    for t, cid, ext, data in frames:
        for name, inp in inputs.items():
            if ival(inp, "id") != cid or yes(inp, "extended") != ext or not mux_match(inp, data):
                continue
            idt = ("%08X" if ext else "%03X") % cid
            if len(data) < ival(inp, "min_dlc", 8) or (yes(inp, "fd") and not hasattr(data, "flags")):
                rows.append((t, idt, name, None, None, "dlc"))
                continue
            raw = extract(data, ival(inp, "start_bit"), ival(inp, "length"), inp["byte_order"],
                          yes(inp, "signed"))
            phys = raw * float(inp["factor"]) + float(inp.get("offset", "0"))
            reason = "ok"
            if raw in (ival(inp, "na_raw"), ival(inp, "na_raw2")):
                reason = "na"
            elif "qualifier_bit" in inp:
                q = extract(data, ival(inp, "qualifier_bit"), 1, "intel")
                if q == ival(inp, "qualifier_invalid", 1):
                    reason = "qualifier"
            rows.append((t, idt, name, raw, phys, reason))
    return rows


# ------------------------------------------------------------ conversions (docs/vehicle.md)

LINEAR = {"km/h": 1 / 3.6, "kph": 1 / 3.6, "m/s": 1.0, "mph": 0.44704}
ANGULAR = {"rad/s": 1.0, "rpm": 2 * math.pi / 60, "1/min": 2 * math.pi / 60}
PRESSURE_PA = {"bar": 1e5, "kpa": 1e3, "mpa": 1e6, "psi": 6894.757}
FORCE_N = {"n": 1.0, "kn": 1e3}


def mu(v0):
    return MU_INF + DELTA_MU * math.exp(-SLOPE_SPM * v0)


def v0_of(value, unit, r_w=WHEEL_RADIUS_M, r_p=PAD_RADIUS_M):
    u = unit.lower()
    if u in LINEAR:
        return value * LINEAR[u] * r_p / r_w
    return value * ANGULAR[u] * r_p


def force_of(value, unit, v0=None, area_mm2=None, eta=1.0, k=1.0, n_f=FRICTION_FACES, r_p=PAD_RADIUS_M):
    u = unit.lower()
    if u in FORCE_N:
        return value * FORCE_N[u]
    if u in PRESSURE_PA:
        return value * PRESSURE_PA[u] * area_mm2 * 1e-6 * eta * k
    return value / (n_f * mu(v0) * r_p)  # torque in Nm


def speed_value(v0, unit, r_w=WHEEL_RADIUS_M, r_p=PAD_RADIUS_M):
    """Inverse of v0_of: the signal value that gives v0."""
    return v0 / v0_of(1.0, unit, r_w, r_p)


def force_value(n, unit, v0=None, area_mm2=None, eta=1.0, k=1.0):
    return n / force_of(1.0, unit, v0, area_mm2, eta, k)


# ------------------------------------------------------------ CRCs

def crc8(data, poly, init, xorout):
    c = init
    for b in data:
        c ^= b
        for _ in range(8):
            c = ((c << 1) ^ poly) & 0xFF if c & 0x80 else (c << 1) & 0xFF
    return c ^ xorout


def crc8h2f(data):
    """CRC-8H2F (AUTOSAR): poly 0x2F, init 0xFF, final XOR 0xFF."""
    return crc8(data, 0x2F, 0xFF, 0xFF)


def p02_crc(frame, data_id_list, counter):
    """E2E P02: CRC over bytes 1..n-1 then DataIDList[counter]."""
    return crc8h2f(list(frame[1:]) + [data_id_list[counter]])


def crc16_ccitt_false(data):
    """CRC-16/CCITT-FALSE: poly 0x1021, init 0xFFFF, not reflected, no final XOR."""
    c = 0xFFFF
    for b in data:
        c ^= b << 8
        for _ in range(8):
            c = ((c << 1) ^ 0x1021) & 0xFFFF if c & 0x8000 else (c << 1) & 0xFFFF
    return c


def p05_crc(frame, data_id, offset=0):
    """E2E P05: CRC-16 over the frame's bytes but the two at offset, then the Data ID low byte, high byte."""
    return crc16_ccitt_false(list(frame[:offset]) + list(frame[offset + 2:]) + [data_id & 0xFF, data_id >> 8])


def p01_crc(frame, data_id):
    return crc8([data_id & 0xFF, data_id >> 8] + list(frame[1:]), 0x1D, 0x00, 0x00)


# ------------------------------------------------------------ results and squeal-sim

Results = dbc_common.Results   # check(cond, what); finish() prints RESULT and exits


def run_sim(args, stdin=None):
    """(exit status, stdout bytes, stderr text) of squeal-sim; 127 when absent."""
    try:
        p = subprocess.run([SIM] + list(args), input=stdin, stdout=subprocess.PIPE,
                           stderr=subprocess.PIPE, timeout=600)
    except OSError as e:
        return 127, b"", "cannot run %s: %s" % (SIM, e.strerror or e)
    except subprocess.TimeoutExpired:
        return 124, b"", "timed out after 600 s"
    return p.returncode, p.stdout, p.stderr.decode("utf-8", "replace")


def sim_missing(r, what, rc, err):
    """A C-side feature this test needs is missing: one clear failure."""
    r.check(False, "%s: squeal-sim (%s) exited %d; the C side of the vehicle input map is missing or broken: %s"
            % (what, SIM, rc, (err.strip().splitlines() or ["no message"])[-1][:300]))
