#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""tools/vehicle_calib.py's bounds, on one small DBC written here (build()
called directly, no firmware check): a message period of 1000 ms is taken
and 1001 ms refused ("outside 1..1000"); P02's E2E_DataIDList must hold 16
bytes, a value 256 among 16 is refused; P01's counter counts modulo 15, so
an input on one page of five (pages take turns, 3 counts per frame seen)
may step by at most 14, not 15 (an unpaged one by 3); a pressure's
--efficiency must lie in (0, 1]: 1 taken, 1.01, 0 and -0.5 refused.

prints "RESULT: N passed, M failed"
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks  # noqa: E402
import vehicle_calib as vc  # noqa: E402

DBC = """VERSION ""

NS_ :

BS_:

BU_: ESC BCM

BO_ 256 Wheel: 8 ESC
 SG_ Speed : 0|16@1+ (0.01,0) [0|300] "km/h" BCM
 SG_ Press : 16|16@1+ (0.1,0) [0|250] "bar" BCM

BO_ 257 SlowWheel: 8 ESC
 SG_ SlowSpeed : 0|16@1+ (0.01,0) [0|300] "km/h" BCM

BO_ 258 EdgeWheel: 8 ESC
 SG_ EdgeSpeed : 0|16@1+ (0.01,0) [0|300] "km/h" BCM

BO_ 259 PagedWheel: 8 ESC
 SG_ Page M : 0|8@1+ (1,0) [0|4] "" BCM
 SG_ PagedSpeed m0 : 8|16@1+ (0.01,0) [0|300] "km/h" BCM
 SG_ Other1 m1 : 8|16@1+ (1,0) [0|1000] "" BCM
 SG_ Other2 m2 : 8|16@1+ (1,0) [0|1000] "" BCM
 SG_ Other3 m3 : 8|16@1+ (1,0) [0|1000] "" BCM
 SG_ Other4 m4 : 8|16@1+ (1,0) [0|1000] "" BCM

BO_ 260 BadList: 8 ESC
 SG_ ListSpeed : 0|16@1+ (0.01,0) [0|300] "km/h" BCM

BA_DEF_ BO_  "GenMsgCycleTime" INT 0 65535;
BA_DEF_ BO_  "E2E_DataID" INT 0 65535;
BA_DEF_ BO_  "E2E_DataIDList" STRING ;
BA_DEF_DEF_  "GenMsgCycleTime" 0;
BA_DEF_DEF_  "E2E_DataID" 0;
BA_DEF_DEF_  "E2E_DataIDList" "";
BA_ "GenMsgCycleTime" BO_ 256 20;
BA_ "GenMsgCycleTime" BO_ 257 1001;
BA_ "GenMsgCycleTime" BO_ 258 1000;
BA_ "GenMsgCycleTime" BO_ 259 10;
BA_ "GenMsgCycleTime" BO_ 260 20;
BA_ "E2E_DataID" BO_ 256 291;
BA_ "E2E_DataID" BO_ 259 292;
BA_ "E2E_DataIDList" BO_ 256 "0x01 0x02 0x03 0x04 0x05 0x06 0x07 0x08 0x09 0x0A 0x0B 0x0C 0x0D 0x0E 0x0F 0xFF";
BA_ "E2E_DataIDList" BO_ 260 "0x01 0x02 0x03 0x04 0x05 0x06 0x07 0x08 0x09 0x0A 0x0B 0x0C 0x0D 0x0E 0x0F 0x100";
"""


def build(dbc, speed, *extra):
    """(inputs by MSG.SIG, None) or (None, the refusal's text)."""
    argv = ["--dbc", dbc, "--corner", "FL", "--speed", speed, "--force", "Wheel.Press",
            "--piston-area-mm2", "2000"] + list(extra)
    try:
        _, _, inputs, _, _ = vc.build(argv)
    except vc.Refusal as e:
        return None, str(e)
    return {d["_ref"]: d for d in inputs}, None


def periods(c, dbc):
    got, why = build(dbc, "EdgeWheel.EdgeSpeed")
    c.check(got is not None and got["EdgeWheel.EdgeSpeed"]["period_ms"] == 1000,
            "GenMsgCycleTime 1000 ms: taken as the period (%s)" % why)
    got, why = build(dbc, "SlowWheel.SlowSpeed")
    c.check(got is None and "period 1001 ms outside 1..1000" in (why or ""),
            "GenMsgCycleTime 1001 ms: refused (%s)" % why)


def data_id_list(c, dbc):
    got, why = build(dbc, "Wheel.Speed", "--protection", "p02")
    c.check(got is not None and got["Wheel.Speed"]["data_id_list"] ==
            "0x01 0x02 0x03 0x04 0x05 0x06 0x07 0x08 0x09 0x0A 0x0B 0x0C 0x0D 0x0E 0x0F 0xFF",
            "p02: 16 bytes up to 0xFF taken as the list (%s)" % why)
    got, why = build(dbc, "BadList.ListSpeed", "--protection", "p02")
    c.check(got is None and why == "--protection p02: message BadList has no E2E_DataIDList attribute of 16 bytes",
            "p02: a list with 0x100 among its 16 values refused (%s)" % why)


def counter_step(c, dbc):
    got, why = build(dbc, "PagedWheel.PagedSpeed", "--protection", "p01")
    d = got and got["PagedWheel.PagedSpeed"]
    c.check(d is not None and d["data_id"] == 292 and d["period_ms"] == 50 and d["max_delta_counter"] == 14,
            "p01, one page of five: period 5 x 10 ms, counter step at most 14 = 15 - 1, not 3 x 5 (%s)"
            % (d and {k: d.get(k) for k in ("data_id", "period_ms", "max_delta_counter")} or why))
    d = got and got["Wheel.Press"]
    c.check(d is not None and d["max_delta_counter"] == 3, "p01, an unpaged input: counter step at most 3")


def efficiency(c, dbc):
    got, why = build(dbc, "Wheel.Speed", "--efficiency", "1")
    c.check(got is not None, "--efficiency 1: taken (%s)" % why)
    for e in ("1.01", "0", "-0.5"):
        got, why = build(dbc, "Wheel.Speed", "--efficiency", e)
        c.check(got is None and why == "corner FL: --efficiency must be in (0, 1]",
                "--efficiency %s: refused (%s)" % (e, why))


def main():
    def all_groups(c, tmp):
        dbc = os.path.join(tmp, "limits.dbc")
        with open(dbc, "w", encoding="latin-1") as f:
            f.write(DBC)
        for g in (periods, data_id_list, counter_step, efficiency):
            g(c, dbc)
    return Checks.run(all_groups)


if __name__ == "__main__":
    sys.exit(main())
