#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Acceptance on real recorded drives (optional).

For every recorded drive that has a matching community DBC in the folder
`realcan` beside the repository (../shared/realcan relative to the repo root;
public third-party material that is never copied into the project), this
makes a calibration with tools/vehicle_calib.py from the unedited DBC only,
replays the drive with `squeal-sim replay --calib`, and checks what a user
must be able to rely on:

  - every calibration either sets up or is refused by the tool with one
    line; a replay never runs on factory defaults;
  - a bench log whose inputs are "not available" codes is FAULT (na), never
    a state of the model;
  - a log with blocks written out of order replays over its real duration
    with at most 5 % FAULT;
  - a log with several buses raises no warning from another bus's frames;
  - the Honda FK8 and VW PQ DBC files load as they are.

Without the folder the whole check is one counted skip. `--table` prints the
table of the closing figures (share of time per state, FAULT reasons).
"""
import json
import os
import subprocess
import sys
import tempfile
# tests/ of this checkout, and the folders its helper modules live in
_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, d) for d in ("support", os.path.join("support", "reference"), "host-sim", "tools")]

import dbc_common  # noqa: E402

ROOT = os.path.dirname(_TESTS)
REALCAN = os.environ.get("REALCAN_DIR", os.path.join(os.path.dirname(ROOT), "shared", "realcan"))
SIM = os.path.join(ROOT, "build", "host", "squeal-sim")
VCAL = os.path.join(ROOT, "tools", "vehicle_calib.py")

FORD = "ford_lincoln_base_pt.dbc"
FORD_CORNERS = []
for _pos, _w, _share in (("FL", "Fl", "0.35"), ("FR", "Fr", "0.35"),
                         ("RL", "Rl", "0.15"), ("RR", "Rr", "0.15")):
    FORD_CORNERS += ["--corner", _pos, "--speed", "WheelSpeed.Whl%s_W_Meas" % _w,
                     "--force", "BrakeSnData_4.BrkTot_Tq_Actl", "--torque-share", _share]


def four(msg, fmt, force, extra=(), names=None):
    """Four corners on one message's wheel speeds and one brake signal;
    names: the DBC's word for each position where it is not FL/FR/RL/RR."""
    args = []
    for pos in ("FL", "FR", "RL", "RR"):
        word = (names or {}).get(pos, pos)
        args += ["--corner", pos, "--speed", "%s.%s" % (msg, fmt % word), "--force", force]
        args += list(extra)
    return args


# VW PQ names its wheels VL VR HL HR (front/rear left/right)
VW_WHEELS = {"FL": "VL", "FR": "VR", "RL": "HL", "RR": "HR"}

# (name, log, dbc, vehicle_calib arguments, replay arguments, what the car did)
CASES = [
    ("fusion_acc", "ford_fusion_2017/acc_80_to_30kmh.log", FORD, FORD_CORNERS, [],
     "ACC braking 75.7 -> 27 km/h, total torque to 760 Nm"),
    ("fusion_hard_stop", "ford_fusion_2017/collision_assist_activated.log", FORD, FORD_CORNERS, [],
     "driver hard stop from 73 km/h, total torque to 3048 Nm"),
    ("gt350_brakeswitch", "ford_mustang_gt350/brakeswitch.log", FORD, FORD_CORNERS, [],
     "parked, brake torque 0 -> 2380 Nm"),
    ("gt350_vss", "ford_mustang_gt350/vsslog.log", FORD, FORD_CORNERS, [],
     "rear wheels 0 -> 40.7 rad/s, fronts 0, no brake (on stands)"),
    ("gt350_disordered", "ford_mustang_gt350/holdingcutoutforfun.log", FORD, FORD_CORNERS, [],
     "parked, 22 blocks written about 2.8 s out of order"),
    ("civic_fk8", "honda_civic_typer_2019/turnonanddrive.log",
     "honda_civic_hatchback_ex_2017_can_generated.dbc",
     four("WHEEL_SPEEDS", "WHEEL_SPEED_%s", "VSA_STATUS.USER_BRAKE",
          ("--force-unit", "bar", "--force-scale", "1", "--piston-area-mm2", "2400")), [],
     "stop-and-go 0-9.4 km/h, unit-less pedal (taken as bar)"),
    ("civic_8th", "honda_civic_8thgen/vsslog.log", "honda_civic_touring_2016_can_generated.dbc",
     four("WHEEL_SPEEDS", "WHEEL_SPEED_%s", "VSA_STATUS.USER_BRAKE",
          ("--force-unit", "bar", "--force-scale", "1", "--piston-area-mm2", "2400")), [],
     "fronts 0 -> 120 km/h on a dyno, no brake signal in the log"),
    ("genesis", "hyundai_genesis/mphloggenesis.log", "hyundai_i30_2014.dbc",
     ["--corner", "FL", "--speed", "EMS1.VS", "--force", "ESP2.CYL_PRES",
      "--piston-area-mm2", "2400"], [],
     "held at standstill, braking 64 -> 32 and 29 -> 6 km/h at 11-17 bar"),
    ("kona_ev", "hyundai_kona_ev_2019/ccan_power_off_on_ready_off.log",
     "hyundai_can_generated.dbc",
     ["--bus", "can0"] + four("WHL_SPD11", "WHL_SPD_%s", "ESP12.CYL_PRES",
                              ("--piston-area-mm2", "2400")), [],
     "parked, pedal held at 20 bar, two buses"),
    ("kona_ice_turnon", "hyundai_kona_ice/turnonlog.log", "hyundai_can_generated.dbc",
     four("WHL_SPD11", "WHL_SPD_%s", "ESP12.CYL_PRES", ("--piston-area-mm2", "2400")), [],
     "parked, 0.2 -> 30 bar -> 0.2 bar"),
    ("kona_ice_start", "hyundai_kona_ice/startlog.from_trc.log", "hyundai_can_generated.dbc",
     four("WHL_SPD11", "WHL_SPD_%s", "ESP12.CYL_PRES", ("--piston-area-mm2", "2400")), [],
     "parked, engine start"),
    ("wrx", "subaru_wrx_va/allgears.log", "subaru_outback_2015_generated.dbc",
     four("Wheel_Speeds", "%s", "Brake_Pedal.Brake_Pedal",
          ("--force-unit", "bar", "--force-scale", "1", "--piston-area-mm2", "2400")), [],
     "pull 22 -> 94 km/h, 1.7 s light braking at the end (unit-less pedal as bar)"),
    ("rav4_can0", "toyota_rav4_2017_comma2k19/rav4_2017_comma2k19_ex1_can0.log",
     "toyota_new_mc_pt_generated.dbc",
     four("WHEEL_SPEEDS", "WHEEL_SPEED_%s", "BRAKE_MODULE.BRAKE_PRESSURE",
          ("--force-unit", "bar", "--force-scale", "0.1", "--piston-area-mm2", "2400")), [],
     "cruising 29-72 km/h, no braking"),
    ("rav4_allbus", "toyota_rav4_2017_comma2k19/rav4_2017_comma2k19_ex1_allbus.log",
     "toyota_new_mc_pt_generated.dbc",
     ["--bus", "can0"] + four("WHEEL_SPEEDS", "WHEEL_SPEED_%s", "BRAKE_MODULE.BRAKE_PRESSURE",
                              ("--force-unit", "bar", "--force-scale", "0.1",
                               "--piston-area-mm2", "2400")), [],
     "the same drive, four buses in one log (0x224 also on can1)"),
    ("rav4_hybrid", "toyota_rav4_hybrid_2017/rav4h_2017_drive_13min.log",
     "toyota_new_mc_pt_generated.dbc",
     ["--corner", "FL", "--speed", "SPEED.SPEED", "--force", "BRAKE.BRAKE_FORCE"], [],
     "13 min drive, four stops to 2.9-3.1 kN, lossy logger (1.6 Hz speed)"),
    ("passat_idling", "vw_pq_passat_b6/vw_passat_b6_idling.log", "vw_pq.dbc",
     four("Bremse_3", "Radgeschw__%s_4_1", "Bremse_5.BR5_Bremsdruck",
          ("--piston-area-mm2", "2400"), VW_WHEELS), [],
     "idling at standstill, 0 bar"),
    ("vw_pq_bench", "vw_pq_passat_b6/vw_pq_med_canhacker.log", "vw_pq.dbc",
     four("Bremse_3", "Radgeschw__%s_4_1", "Bremse_5.BR5_Bremsdruck",
          ("--piston-area-mm2", "2400"), VW_WHEELS), [],
     "ECU bench: every speed and pressure is a not-available code"),
]
STATES = ("stable", "bistable", "unstable", "not_sliding", "fault")


def run_case(case, tmp):
    name, log, dbc, vargs, rargs, _what = case
    cal = os.path.join(tmp, name + ".cal")
    logp = os.path.join(REALCAN, "logs", log)
    cmd = [sys.executable, VCAL, "--dbc", os.path.join(REALCAN, "dbc", dbc), "--log", logp] + vargs + ["-o", cal]
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    res = {"case": case, "calib_rc": p.returncode, "calib_err": p.stderr.strip(),
           "calib_cmd": cmd}
    if p.returncode != 0:
        return res
    r = subprocess.run([SIM, "replay", "--calib", cal, "--no-output", "--summary-json", "-"] + rargs + [logp],
                       capture_output=True, text=True, timeout=600)
    res["replay_rc"] = r.returncode
    res["replay_err"] = r.stderr
    if r.returncode == 0:
        res["summary"] = json.loads(r.stdout)
    return res


def shares(summary):
    """Share of time per state over every corner."""
    tot = {s: 0.0 for s in STATES}
    for c in summary.get("inputs_by_corner", []):
        for s in STATES:
            tot[s] += float(c.get("state_time_s", {}).get(s, 0.0))
    n = sum(tot.values())
    return {s: (tot[s] / n if n > 0 else 0.0) for s in STATES}, n


def fault_reasons(summary):
    """The input stage's verdicts that rejected frames, and the input
    faults behind the time in FAULT, over every corner, largest first."""
    rejected, fault_s = {}, {}
    for c in summary.get("inputs_by_corner", []):
        for q in ("speed", "force"):
            inp = c.get(q, {})
            for k, v in inp.get("rejected", {}).items():
                if v:
                    rejected[k] = rejected.get(k, 0) + int(v)
            for k, v in inp.get("fault_time_s", {}).items():
                if v:
                    fault_s["%s %s" % (q, k)] = fault_s.get("%s %s" % (q, k), 0.0) + float(v)
    return (sorted(rejected.items(), key=lambda kv: -kv[1]),
            sorted(fault_s.items(), key=lambda kv: -kv[1]))


def main(argv):
    table = "--table" in argv
    if not os.path.isdir(os.path.join(REALCAN, "logs")):
        print("SKIP: realcan drives (no recorded drives at %s)" % REALCAN)
        print("RESULT: 0 passed, 0 failed, 1 skipped")
        return 0
    counts = dbc_common.Results()
    counts.OK = "PASS: "
    check = counts.check

    results = {}
    with tempfile.TemporaryDirectory() as tmp:
        for case in CASES:
            res = run_case(case, tmp)
            results[case[0]] = res
            name = case[0]
            refused_one_line = res["calib_rc"] == 1 and len(res["calib_err"].splitlines()) >= 1 \
                and "Traceback" not in res["calib_err"]
            check(res["calib_rc"] == 0 or refused_one_line,
                  "%s: the calibration is written or refused with a reason" % name)
            if res["calib_rc"] == 0:
                s = res.get("summary", {})
                check(res.get("replay_rc") == 0 and s.get("firmware_init_status") == 0,
                      "%s: replay runs on the calibration, never on defaults" % name)
    b = results["vw_pq_bench"]
    if "summary" in b:
        sh, _ = shares(b["summary"])
        reasons = dict(fault_reasons(b["summary"])[0])
        check(sh["fault"] > 0.9 and sh["stable"] == 0.0 and sh["bistable"] == 0.0,
              "VW PQ bench log: FAULT, never a model state (fault %.1f %%)" % (100 * sh["fault"]))
        check(reasons.get("na", 0) > 0, "VW PQ bench log: the reason is not available")
    else:
        check(False, "VW PQ bench log replayed")
    g = results["gt350_disordered"]
    if "summary" in g:
        sh, _ = shares(g["summary"])
        vt = float(g["summary"].get("virtual_time_s", 1e9))
        check(vt < 34.0, "GT350: virtual time %.1f s for a 32.9 s drive" % vt)
        check(sh["fault"] <= 0.05, "GT350: FAULT %.1f %% <= 5 %%" % (100 * sh["fault"]))
    else:
        check(False, "GT350 log replayed")
    a = results["rav4_allbus"]
    if "summary" in a:
        w = a["summary"].get("warnings_raised", {})
        check(all(int(w.get(k, 0)) == 0 for k in ("advisory", "warning", "critical")),
              "RAV4 all-bus log: no warning raised")
    else:
        check(False, "RAV4 all-bus log replayed")
    for n in ("civic_fk8", "vw_pq_bench"):
        check(results[n]["calib_rc"] == 0, "%s: its DBC loads as it is" % n)

    if table:
        print()
        print("| drive | what the car did | calibration | stable | bistable | unstable | not sliding | FAULT | frames rejected | FAULT time by input fault (s, all corners) | warnings |")
        print("|---|---|---|---|---|---|---|---|---|---|---|")
        for case in CASES:
            res = results[case[0]]
            if res["calib_rc"] != 0:
                print("| %s | %s | refused: %s | | | | | | | | |" % (case[1], case[5], res["calib_err"].splitlines()[-1] if res["calib_err"] else "?"))
                continue
            s = res.get("summary")
            if not s:
                print("| %s | %s | ok | replay failed: %s |" % (case[1], case[5], res.get("replay_err", "").strip()[:80]))
                continue
            sh, tot = shares(s)
            w = s.get("warnings_raised", {})
            rej, fts = fault_reasons(s)
            print("| %s | %s | ok | %s | %s | %s | %s |" % (
                case[1], case[5],
                " | ".join("%.1f %%" % (100 * sh[k]) for k in STATES),
                ", ".join("%s %d" % kv for kv in rej[:3]) or "-",
                ", ".join("%s %.1f" % kv for kv in fts[:3]) or "-",
                "adv %s, warn %s, crit %s" % (w.get("advisory", 0), w.get("warning", 0), w.get("critical", 0))))
        print()
        for case in CASES:
            print("%s: %s" % (case[0], " ".join(results[case[0]]["calib_cmd"][1:]).replace(REALCAN, "realcan")))
    print("RESULT: %d passed, %d failed, 0 skipped" % (counts.passed, counts.failed))
    return 1 if counts.failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
