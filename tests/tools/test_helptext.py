#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""tools/helptext.py: the parser takes the docstring's first paragraph as the
description and the rest verbatim after the options; a module run as a
program answers --help with exit 0 and anything else with one line, exit 2.
"""
import os
import subprocess
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "tools"))
import helptext  # noqa: E402
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks  # noqa: E402

DOC = """Do one thing, completely.

    tool.py IN [-o OUT]

Lines kept
  exactly as written.
"""

_C = Checks()


def check(ok, what, detail=""):
    _C.check(ok, what + ("" if ok or not detail else ": " + detail))


def main():
    p = helptext.parser(DOC, "tools/tool.py")
    p.add_argument("-o", metavar="OUT", help="where to write")
    text = p.format_help()
    check(text.startswith("usage: tools/tool.py [-h] [-o OUT]\n\nDo one thing, completely.\n"),
          "usage, then the first paragraph", text[:80])
    check("    tool.py IN [-o OUT]\n\nLines kept\n  exactly as written.\n" in text, "the rest verbatim", text)
    check(text.index("-o OUT") < text.index("Lines kept"), "the options before the rest")
    check(helptext.parser("One line only.", "t").epilog is None, "a one-paragraph docstring has no epilog")
    mod = os.path.join(ROOT, "tools", "calibfit.py")
    r = subprocess.run(["/usr/bin/python3", mod, "--help"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    check(r.returncode == 0 and "Shared parts of the calibration fitters" in r.stdout, "a module's --help: its doc")
    r = subprocess.run(["/usr/bin/python3", mod], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    check(r.returncode == 2 and r.stderr.count("\n") == 1 and "nothing to run" in r.stderr,
          "a module run without --help: one line, exit 2", r.stderr)
    return _C.finish()


if __name__ == "__main__":
    sys.exit(main())
