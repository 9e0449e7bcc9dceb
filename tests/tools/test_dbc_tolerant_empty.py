#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""tools/dbc_tolerant.py on DBC text written here whose messages all go:
only the signals of VECTOR__INDEPENDENT_SIG_MSG (Vector's pseudo message,
which canmatrix leaves out), or one message whose only signal line is
broken (dropped: no message is asked for). Each is refused (DbcRefusal
naming the file: "holds no CAN database with messages"), never a database
without frames handed on; a file without BO_ is "not a DBC file"; one
message with one signal is read.

prints "RESULT: N passed, M failed"
"""
import contextlib
import io
import logging
import os
import sys
import tempfile
import warnings

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
with contextlib.redirect_stderr(io.StringIO()):  # canmatrix's optional formats' notes
    import dbc_tolerant as T  # noqa: E402

HEAD = ['VERSION ""', "", "NS_ :", "", "BS_:", "", "BU_: ESC BCM", ""]
ONE = ["BO_ 256 Wheel: 8 ESC", ' SG_ Speed : 0|16@1+ (0.01,0) [0|655.35] "km/h" BCM', ""]
INDEP = ["BO_ 3221225472 VECTOR__INDEPENDENT_SIG_MSG: 0 Vector__XXX", ' SG_ Free : 0|8@1+ (1,0) [0|255] "" BCM', ""]
BROKEN = ["BO_ 256 Wheel: 8 ESC", ' SG_ Speed : 0|16@1+ (0.01,0) [0|655.35 "km/h" BCM', ""]
results = []


def check(what, ok):
    results.append(ok)
    print(("PASS: " if ok else "FAIL: ") + what)


def refusal(path):
    logging.disable(logging.CRITICAL)
    try:
        with warnings.catch_warnings(), contextlib.redirect_stdout(io.StringIO()):
            warnings.simplefilter("ignore")
            T.load(path, [])
    except T.DbcRefusal as e:
        return str(e)
    return None


def main():
    with tempfile.TemporaryDirectory() as tmp:
        for name, lines, said in (("independent_only.dbc", HEAD + INDEP, "holds no CAN database with messages"),
                                  ("broken_only.dbc", HEAD + BROKEN, "holds no CAN database with messages"),
                                  ("nodes_only.dbc", HEAD, "is not a DBC file")):
            path = os.path.join(tmp, name)
            with open(path, "w", encoding="latin-1") as f:
                f.write("\n".join(lines) + "\n")
            why = refusal(path)
            check("%s: refused (%s)" % (name, why), why is not None and said in why and name in why)
        path = os.path.join(tmp, "one.dbc")
        with open(path, "w", encoding="latin-1") as f:
            f.write("\n".join(HEAD + ONE) + "\n")
        check("one message: read (%s)" % refusal(path), refusal(path) is None)
    print("RESULT: %d passed, %d failed" % (sum(results), len(results) - sum(results)))
    return 0 if all(results) else 1


if __name__ == "__main__":
    sys.exit(main())
