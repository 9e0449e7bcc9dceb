#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Prove that the C side of the CAN interface (firmware/protocol/squeal_msgs.h
defines and msg_table/msg_sig_table, printed by emit_frames --table) equals
the DBC, the single description of the interface: identifiers, DLCs, cycle
times, E2E data IDs, and per signal start bit, length, byte order, sign,
factor, offset, unit, raw range, not-available value and multiplexing; and
the value tables of SquealState/WarningLevel/SquealDiag_Page and the fault
bit masks. Ends with a self-test: deliberately wrong tables must fail."""
import copy
import os
import sys
from fractions import Fraction
# tests/ of this checkout, and the folders its helper modules live in
_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, d) for d in ("support", os.path.join("support", "reference"), "host-sim", "tools")]

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from dbc_common import Results, load_dbc, run_emitter, snake  # noqa: E402


def parse_table(text):
    msgs, sigs, defs = {}, {}, {}
    for line in text.splitlines():
        f = line.split("\t")
        if f[0] == "MSG":
            msgs[int(f[1], 16)] = dict(name=f[2], dlc=int(f[3]), period=int(f[4]),
                                       data_id=int(f[5], 16))
        elif f[0] == "SIG":
            sigs[(int(f[1], 16), f[2])] = dict(
                unit=f[3][1:-1], start=int(f[4]), length=int(f[5]), signed=int(f[6]) != 0,
                mux=f[7], num=int(f[8]), den=int(f[9]), off=int(f[10]),
                raw_min=int(f[11]), raw_max=int(f[12]),
                na=int(f[14]) if f[13] == "NA" else None)
        elif f[0] == "STATENAME":
            defs.setdefault("_state_names", {})[int(f[1])] = f[2]
        elif f[0] == "STATESLOT":
            defs.setdefault("_state_slots", {})[int(f[1])] = int(f[2])
        elif f[0] == "DEF":
            defs[f[1]] = int(f[2])
    return msgs, sigs, defs


def dbc_raw(sig, phys):
    """Physical DBC limit -> raw integer (exactly; a fraction is an error)."""
    r = (Fraction(phys) - Fraction(sig.offset)) / Fraction(sig.factor)
    return int(r) if r.denominator == 1 else None


def not_available(sig):
    keys = [int(k) for k, v in sig.values.items() if v == "not_available"]
    return keys[0] if len(keys) == 1 else None


def compare(db, msgs, sigs, defs, r):
    r.check(db.attributes.get("Baudrate") == "500000", "Baudrate attribute 500000")
    r.check(db.attributes.get("BusType") == "CAN", "BusType CAN")
    dbc_ids = {f.arbitration_id.id for f in db.frames}
    r.check(dbc_ids == set(msgs), "message sets: DBC %s C %s" %
            (sorted(map(hex, dbc_ids)), sorted(map(hex, msgs))))
    data_ids = []
    for frame in db.frames:
        fid = frame.arbitration_id.id
        c = msgs.get(fid)
        if not r.check(c is not None, "C has message 0x%X" % fid):
            continue
        name = frame.name
        r.check(not frame.arbitration_id.extended and fid <= 0x7FF, "%s 11-bit id" % name)
        r.check(c["name"] == name, "0x%X name DBC %s C %s" % (fid, name, c["name"]))
        r.check(c["dlc"] == frame.size, "%s DLC DBC %d C %d" % (name, frame.size, c["dlc"]))
        cyc = int(frame.attributes.get("GenMsgCycleTime", -1))
        r.check(c["period"] == cyc, "%s cycle DBC %d C %d" % (name, cyc, c["period"]))
        did = int(frame.attributes.get("E2E_DataID", -1))
        data_ids.append(did)
        r.check(0 <= did <= 0xFFFF and c["data_id"] == did,
                "%s E2E_DataID DBC %d C %d" % (name, did, c["data_id"]))
        r.check(frame.attributes.get("E2E_Profile") == "P01_1A", "%s E2E_Profile" % name)
        # the defines the monitor uses directly
        pre = "MSG_" + snake(name)
        for suffix, want in (("_ID", fid), ("_DLC", frame.size), ("_PERIOD_MS", cyc),
                             ("_DATA_ID", did)):
            r.check(defs.get(pre + suffix) == want, "%s%s = %s, DBC %s" %
                    (pre, suffix, defs.get(pre + suffix), want))
        # E2E header: CRC byte 0, counter low nibble of byte 1
        crc = frame.signal_by_name(name + "_CRC")
        cnt = frame.signal_by_name(name + "_Counter")
        r.check(crc is not None and (crc.start_bit, crc.size) == (0, 8), "%s_CRC at 0|8" % name)
        r.check(cnt is not None and (cnt.start_bit, cnt.size, int(cnt.max)) == (8, 4, 14),
                "%s_Counter at 8|4 max 14" % name)
        # signals
        csigs = {n for (i, n) in sigs if i == fid}
        dsigs = {s.name for s in frame.signals}
        r.check(csigs == dsigs, "%s signal sets differ: only DBC %s, only C %s" %
                (name, sorted(dsigs - csigs), sorted(csigs - dsigs)))
        for s in frame.signals:
            cs = sigs.get((fid, s.name))
            if cs is None:
                continue
            what = "%s.%s" % (name, s.name)
            r.check(s.is_little_endian, what + " Intel byte order")
            r.check(not s.is_float, what + " integer")
            r.check(cs["start"] == s.start_bit, "%s start DBC %d C %d" % (what, s.start_bit, cs["start"]))
            r.check(cs["length"] == s.size, "%s length DBC %d C %d" % (what, s.size, cs["length"]))
            r.check(cs["signed"] == bool(s.is_signed), what + " signedness")
            r.check(Fraction(cs["num"], cs["den"]) == Fraction(s.factor),
                    "%s factor DBC %s C %d/%d" % (what, s.factor, cs["num"], cs["den"]))
            r.check(Fraction(cs["off"], cs["den"]) == Fraction(s.offset),
                    "%s offset DBC %s C %d/%d" % (what, s.offset, cs["off"], cs["den"]))
            r.check(cs["unit"] == (s.unit or ""), "%s unit DBC '%s' C '%s'" % (what, s.unit, cs["unit"]))
            rmin, rmax = dbc_raw(s, s.min), dbc_raw(s, s.max)
            r.check(cs["raw_min"] == rmin and cs["raw_max"] == rmax,
                    "%s raw range DBC [%s, %s] C [%d, %d]" % (what, rmin, rmax, cs["raw_min"], cs["raw_max"]))
            na = not_available(s)
            r.check(cs["na"] == na, "%s not-available DBC %s C %s" % (what, na, cs["na"]))
            # the raw range and NA fit the field
            lo, hi = (-(1 << (s.size - 1)), (1 << (s.size - 1)) - 1) if s.is_signed else (0, (1 << s.size) - 1)
            r.check(rmin is not None and rmax is not None and lo <= rmin <= rmax <= hi
                    and (na is None or (lo <= na <= hi and not rmin <= na <= rmax)),
                    what + " range fits the field")
            if s.is_multiplexer:
                dmux = "M"
            elif s.mux_val is not None:
                dmux = "m%d" % s.mux_val
            else:
                dmux = "-"
            r.check(cs["mux"] == dmux, "%s mux DBC %s C %s" % (what, dmux, cs["mux"]))
            # per-signal _MAX/_NA defines, where the header has them
            for suffix, want in (("_MAX", rmax), ("_NA", na), ("_MIN", rmin)):
                key = "MSG_" + snake(s.name) + suffix
                if key in defs:
                    r.check(defs[key] == want, "%s = %d, DBC %s" % (key, defs[key], want))
            if s.name.startswith("Fault_"):
                key = "MSG_FAULT_" + snake(s.name[len("Fault_"):])
                r.check(defs.get(key) == 1 << (s.start_bit - 16),
                        "%s = %s, DBC bit %d" % (key, defs.get(key), s.start_bit))
    r.check(len(set(data_ids)) == len(data_ids), "E2E data IDs distinct")

    # value tables
    st = db.frame_by_name("SquealStatus")
    vals = {int(k): v for k, v in st.signal_by_name("SquealState").values.items()}
    r.check(vals == {0: "stable", 1: "bistable", 2: "unstable", 3: "not_sliding", 15: "fault"},
            "SquealState value table %s" % vals)
    for k, v in vals.items():
        r.check(defs.get("MSG_SQUEAL_STATE_" + v.upper()) == k, "MSG_SQUEAL_STATE_%s" % v.upper())
    r.check(defs.get("_state_names") == vals,
            "msg_squeal_state_name() names exactly the SquealState value table (%s)"
            % defs.get("_state_names"))
    # per-state tables: the model's values 0..3 in their own slot, every
    # other value (fault, or one the table does not name) in slot 4
    r.check(defs.get("_state_slots") == {v: (v if v < 4 else 4) for v in range(256)},
            "msg_squeal_state_slot(): 0..3 their own slot, every other value slot 4")
    vals = {int(k): v for k, v in st.signal_by_name("WarningLevel").values.items()}
    r.check(vals == {0: "none", 1: "advisory", 2: "warning", 3: "critical"},
            "WarningLevel value table %s" % vals)
    for k, v in vals.items():
        r.check(defs.get("MSG_WARNING_LEVEL_" + v.upper()) == k, "MSG_WARNING_LEVEL_%s" % v.upper())
    diag = db.frame_by_name("SquealDiag")
    pages = {int(k) for k in diag.signal_by_name("SquealDiag_Page").values}
    r.check(pages == set(range(defs.get("MSG_DIAG_PAGE_COUNT", -1))), "diag pages %s" % pages)
    used = {s.mux_val for s in diag.signals if s.mux_val is not None}
    r.check(used == pages, "every diag page carries signals")
    nfault = sum(1 for s in diag.signals if s.name.startswith("Fault_"))
    r.check(defs.get("MSG_FAULT_ALL") == (1 << nfault) - 1, "MSG_FAULT_ALL covers %d faults" % nfault)


def main():
    r = Results()
    db = load_dbc()
    table = run_emitter("--table")
    msgs, sigs, defs = parse_table(table)
    r.check(len(msgs) > 0 and len(sigs) > 0, "emitter printed the table")
    compare(db, msgs, sigs, defs, r)

    # Self-test: the comparison must notice a wrong C table or a wrong DBC.
    mutations = []
    m2 = copy.deepcopy(sigs)
    m2[(0x110, "DiscSpeed_radps")]["den"] = 1000
    mutations.append(("factor", db, msgs, m2, defs))
    m2 = copy.deepcopy(sigs)
    m2[(0x301, "HopfSpeed_mps")]["start"] += 1
    mutations.append(("start bit", db, msgs, m2, defs))
    m2 = copy.deepcopy(msgs)
    m2[0x300]["data_id"] ^= 0x0100
    mutations.append(("data id", db, m2, sigs, defs))
    d2 = dict(defs)
    d2["MSG_FAULT_CAN_INIT"] = 1 << 3
    mutations.append(("fault mask", db, msgs, sigs, d2))
    db2 = load_dbc()
    db2.frame_by_name("PadForce").signal_by_name("PadForce_N").is_signed = True
    mutations.append(("DBC sign", db2, msgs, sigs, defs))
    for what, mdb, mm, ms, md in mutations:
        rr = Results()
        quiet = open(os.devnull, "w")
        old, sys.stdout = sys.stdout, quiet
        try:
            compare(mdb, mm, ms, md, rr)
        finally:
            sys.stdout = old
            quiet.close()
        r.check(rr.failed > 0, "self-test: a wrong %s is detected" % what)
    r.finish()


if __name__ == "__main__":
    main()
