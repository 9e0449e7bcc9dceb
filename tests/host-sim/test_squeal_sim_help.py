#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""The descriptions of squeal-sim's commands are whole: the first paragraph
of `squeal-sim CMD --help` after the usage ends a sentence, for every
command `squeal-sim --help` lists, in both numeric builds.

(tests/host-sim/test_cli_help.py checks the rest of every --help: exit
status, no side effects, each option of the tables described, --version;
tests/host-sim/test_cmd_replay_quiet.py replay's --quiet.)
"""
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools"))
import help_checks as H  # noqa: E402
from checks import Checks  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
BUILDS = (("float", "build/host/squeal-sim"), ("fixed", "build/host-fixed/squeal-sim"))

_C = Checks()


def check(ok, what, detail=""):
    _C.check(ok, what + ("" if ok or not detail else ": " + detail))


def main():
    for numeric, rel in BUILDS:
        sim = os.path.join(ROOT, rel)
        if not os.access(sim, os.X_OK):
            check(False, "%s exists (make %s)" % (rel, rel))
            continue
        rc, out, written = H.run_help([sim, "--help"])
        cmds = re.findall(r"^  ([a-z][a-z-]*) +\S", out.split("commands:", 1)[-1], re.M)
        check(rc == 0 and len(cmds) >= 9, "%s --help lists the commands (%s)" % (rel, " ".join(cmds)))
        for cmd in cmds:
            rc, out, written = H.run_help([sim, cmd, "--help"])
            check(rc == 0 and H.first_sentence_complete(out),
                  "%s %s --help: the description is a full sentence" % (rel, cmd), repr(H.description(out)[-70:]))
    return _C.finish()


if __name__ == "__main__":
    sys.exit(main())
