#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""tools/deps.py: a tool whose modules are missing says, in one line on
stderr and exit status 1, which Debian packages have them, and no traceback.

Missing modules are made real by running the tools with `python3 -S` (no
site-packages: Debian's dist-packages are not on the path, as under a venv
without system packages). The package names are checked against Debian 12's
names written here, not against deps.PACKAGES.
"""
import os
import subprocess
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "tools"))
import deps  # noqa: E402
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks  # noqa: E402

# tool -> the Debian packages it must name when none of them is importable
TOOLS = {
    "tools/fit_friction.py": ["python3-numpy", "python3-scipy"],
    "tools/fit_modal.py": ["python3-numpy", "python3-scipy"],
    "tools/gen_bessel_table.py": ["python3-numpy", "python3-scipy"],
    "tools/gen_calib_examples.py": ["python3-numpy"],
    "tools/vehicle_calib.py": ["python3-canmatrix"],
    "tools/fleet.py": ["python3-numpy", "python3-scipy", "python3-matplotlib"],
}

_C = Checks()


def check(ok, what, detail=""):
    _C.check(ok, what + ("" if ok or not detail else ": " + detail))


def main():
    for tool, pkgs in TOOLS.items():
        r = subprocess.run(["/usr/bin/python3", "-S", os.path.join(ROOT, tool), "--help"], stdout=subprocess.PIPE,
                           stderr=subprocess.PIPE, text=True, timeout=60)
        lines = r.stderr.strip().splitlines()
        check(r.returncode == 1, "%s without site-packages: exit 1" % tool, "exit %d" % r.returncode)
        check(len(lines) == 1 and "Traceback" not in r.stderr, "%s: one line, no traceback" % tool, r.stderr[-300:])
        line = lines[0] if lines else ""
        check(all(p in line for p in pkgs) and "apt-get install " + " ".join(pkgs) in line,
              "%s: names %s and the apt-get line" % (tool, " ".join(pkgs)), line)
    # the mapping for a module Debian calls differently, and a made-up one
    check(deps.missing_packages(["can", "distributed", "no_such_module_zz"]) ==
          [p for p, m in (("python3-can", "can"), ("python3-distributed", "distributed")) if not
           __import__("importlib").util.find_spec(m)] + ["python3-no_such_module_zz"],
          "missing_packages: python-can is python3-can, an unknown module python3-NAME")
    check(deps.missing_packages(["os", "sys"]) == [], "missing_packages: nothing for modules that exist")
    real = sys.executable
    try:
        sys.executable = "/opt/venv/bin/python3"
        msg = deps.message("x.py", ["python3-scipy"])
        check(msg == "x.py: needs the Debian package python3-scipy (sudo apt-get install python3-scipy); this is "
              "/opt/venv/bin/python3, Debian's packages are for /usr/bin/python3",
              "message under another interpreter says which one ran", msg)
        sys.executable = "/usr/bin/python3"
        msg = deps.message("x.py", ["python3-a", "python3-b"])
        check(msg == "x.py: needs the Debian packages python3-a, python3-b (sudo apt-get install python3-a python3-b)",
              "message under Debian's interpreter: packages and the apt-get line only", msg)
    finally:
        sys.executable = real
    return _C.finish()


if __name__ == "__main__":
    sys.exit(main())
