#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""squeal-sim --help, --version and every subcommand's --help (float and
fixed builds): exit 0, nothing written to the working folder, a first
paragraph that ends a sentence, and every --option of the usage described on
an option line of its own. The subcommands are the ones `squeal-sim --help`
lists; replay's --quiet is among them.
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
        check(rc == 0 and not written, "%s --help exits 0, writes nothing" % rel, "exit %s %s" % (rc, written))
        cmds = re.findall(r"^  ([a-z][a-z-]*) +\S", out.split("commands:", 1)[-1], re.M)
        check(len(cmds) >= 9, "%s --help lists the commands (%s)" % (rel, " ".join(cmds)))
        rc, out, written = H.run_help([sim, "--version"])
        check(rc == 0 and re.fullmatch(r"squeal-sim \d+\.\d+\.\d+ \(numeric build: %s\)\n" % numeric, out) is not None,
              "%s --version names the version and the %s build" % (rel, numeric), out.strip())
        for cmd in cmds:
            rc, out, written = H.run_help([sim, cmd, "--help"])
            where = "%s %s --help" % (rel, cmd)
            check(rc == 0, where + " exits 0", "exit %s" % rc)
            check(not written, where + " writes nothing to the working folder", " ".join(written))
            check(H.first_sentence_complete(out), where + ": the description is a full sentence",
                  repr(H.description(out)[-70:]))
            described = H.option_lines(out)
            missing = [o for o in H.usage_options(out) if o not in described]
            check(not missing, where + ": every option of the usage has its line", " ".join(missing))
            check("--help" in described, where + ": --help has its line")
            if cmd == "replay":
                check("--quiet" in described, where + ": --quiet is described")
    return _C.finish()


if __name__ == "__main__":
    sys.exit(main())
