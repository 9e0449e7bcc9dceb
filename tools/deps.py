#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""The Debian package behind each module a tool imports.

A tool calls need("numpy", "scipy", ...) before its first third-party import.
A module that cannot be found ends the tool with one line on stderr naming
the Debian package(s) and the apt-get command, exit status 1, and no
traceback, whichever interpreter runs the tool: the packages install into
Debian's /usr/bin/python3, so under a venv or pyenv interpreter the line
also says which interpreter ran and that /usr/bin/python3 has them.

The check only looks the modules up (importlib.util.find_spec): it imports
nothing, so `--help` stays fast.
"""

import importlib.util
import os
import sys

DEBIAN_PYTHON = "/usr/bin/python3"

# module -> Debian 12 package
PACKAGES = {
    "numpy": "python3-numpy",
    "scipy": "python3-scipy",
    "matplotlib": "python3-matplotlib",
    "canmatrix": "python3-canmatrix",
    "can": "python3-can",
    "dask": "python3-dask",
    "distributed": "python3-distributed",
}

def missing_packages(modules):
    """The Debian packages of the modules this interpreter cannot find, in order, once each."""
    out = []
    for mod in modules:
        if importlib.util.find_spec(mod) is None:
            pkg = PACKAGES.get(mod, "python3-" + mod)
            if pkg not in out:
                out.append(pkg)
    return out


def interpreter_note():
    """Why an installed package may still be missing: another interpreter runs the tool."""
    if os.path.realpath(sys.executable or "") == os.path.realpath(DEBIAN_PYTHON):
        return ""
    return "; this is %s, Debian's packages are for %s" % (sys.executable, DEBIAN_PYTHON)


def message(prog, pkgs):
    return "%s: needs the Debian package%s %s (sudo apt-get install %s)%s" % (
        prog, "s" if len(pkgs) > 1 else "", ", ".join(pkgs), " ".join(pkgs), interpreter_note())


def need(*modules):
    """Exit 1 with one line naming the packages of the modules that are missing."""
    pkgs = missing_packages(modules)
    if pkgs:
        prog = os.path.basename(sys.argv[0]) if sys.argv and sys.argv[0] else "tool"
        sys.stderr.write(message(prog, pkgs) + "\n")
        sys.exit(1)


if __name__ == "__main__":
    import helptext
    helptext.module_main(__doc__, "tools/deps.py")
