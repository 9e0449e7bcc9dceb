#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Which tests belong to which module, derived from where the tests live.

The rule (tests/README.md): the tests of DIR/x.c or DIR/x.py live in
tests/DIR/ and are named after the module: KIND_NAME.ext or KIND_NAME_*.ext
with KIND one of test, fuzz, bench, check, conf. A module's NAME is its file
name without the extension and without a numeric-build suffix (_common,
_float, _fixed: squeal_model_float.c is the module squeal_model). Where two
modules of one folder could claim a test (calib and calib_map for
test_calib_map.c), the longest name wins.

  tools/test_map.py                 module -> its tests, one line each
  tools/test_map.py --missing       modules with logic but no test named
                                    after them (exit 1 when there is one)
  tools/test_map.py --module FILE   the tests of one module
  tools/test_map.py --check         make test's check: one counted check per
                                    module, "RESULT: N passed, M failed"

No module has a test table kept by hand; make mutate (tools/mutate.py) asks
this file.
"""
import argparse
import os
import subprocess
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
SOURCE_DIRS = ("firmware", "hal", "host-sim", "tools")
KINDS = ("test", "fuzz", "bench", "check", "conf")
BUILD_SUFFIXES = ("_common", "_float", "_fixed")
TEST_EXTS = (".c", ".py", ".sh")

# Source files without logic of their own to test, each with the reason.
NO_LOGIC = {
    "firmware/model/bessel_table.c": "a generated table (tools/gen_bessel_table.py, checked by test_squeal_model)",
    "hal/stm32f4/placeholder_app.c": "a placeholder image's empty main",
    "hal/stm32f4/test_events.c": "test-image hooks, exercised by tests/system/target",
    "hal/stm32f4/test_run.c": "test-image hooks, exercised by tests/system/target",
    "hal/stm32f4/semihost.c": "two semihosting calls for test images",
    "hal/stm32f4/startup.c": "vector table and C runtime start, run by every tests/system/target image",
    "hal/stm32f4/libc_min.c": "memcpy/memset for the freestanding image, run by every image",
    "host-sim/squeal_sim.c": "main(): the subcommand dispatch, run by every host-sim test",
    "host-sim/squeal_replay.c": "main() of the squeal-replay program",
    "host-sim/oscsim/oscsim_main.c": "main() of the oscsim program",
    "tools/mutate.py": "the mutation harness itself",
    "tools/test_map.py": "this map",
    "tools/gen_bessel_table.py": "writes firmware/model/bessel_table.c",
    "tools/gen_calib_examples.py": "writes docs/examples",
    "tools/demo_timeline.py": "prints the demo's timeline, run by tests/system/demo",
    "tools/stack_usage.py": "a report of -fstack-usage files for make bench",
}


def git_files():
    out = subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True)
    if out.returncode != 0:  # not a checkout: walk the tree
        found = []
        for top in SOURCE_DIRS + ("tests",):
            for d, _, names in os.walk(os.path.join(ROOT, top)):
                found += [os.path.relpath(os.path.join(d, n), ROOT) for n in names]
        return sorted(found)
    return sorted(out.stdout.split())


def module_name(path):
    stem = os.path.splitext(os.path.basename(path))[0]
    for suffix in BUILD_SUFFIXES:
        if stem.endswith(suffix):
            return stem[: -len(suffix)]
    return stem


def modules(files=None):
    files = git_files() if files is None else files
    return [f for f in files
            if f.split("/", 1)[0] in SOURCE_DIRS and f.endswith((".c", ".py"))
            and not os.path.basename(f).startswith("__")]


def test_stem(path):
    """NAME part of KIND_NAME.ext, or None for a file that is not a test."""
    base = os.path.basename(path)
    stem, ext = os.path.splitext(base)
    if ext not in TEST_EXTS:
        return None
    for kind in KINDS:
        if stem.startswith(kind + "_"):
            return stem[len(kind) + 1:]
    return None


def owner(test_path, mods):
    """The module a test file belongs to (longest matching name), or None."""
    stem = test_stem(test_path)
    if stem is None:
        return None
    folder = os.path.dirname(os.path.relpath(test_path, "tests"))
    best = None
    for m in mods:
        if os.path.dirname(m) != folder:
            continue
        name = module_name(m)
        if stem == name or stem.startswith(name + "_"):
            if best is None or len(module_name(best)) < len(name):
                best = m
    return best


def test_map(files=None):
    files = git_files() if files is None else files
    mods = modules(files)
    tests = [f for f in files if f.startswith("tests/") and test_stem(f) is not None]
    out = {m: [] for m in mods}
    for t in tests:
        m = owner(t, mods)
        if m is not None:
            # a test of a module family (squeal_model) belongs to each part
            for part in mods:
                if os.path.dirname(part) == os.path.dirname(m) and module_name(part) == module_name(m):
                    out[part].append(t)
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog=__doc__.split("\n\n", 1)[1])
    ap.add_argument("--missing", action="store_true", help="list modules with logic and no named test")
    ap.add_argument("--module", metavar="FILE", help="print the tests of this module")
    ap.add_argument("--check", action="store_true", help="one counted check per module (make test)")
    args = ap.parse_args()
    tmap = test_map()
    if args.module:
        if args.module not in tmap:
            print(f"test_map.py: {args.module}: not a module (firmware/, hal/, host-sim/, tools/ .c or .py)",
                  file=sys.stderr)
            return 1
        print("\n".join(tmap[args.module]))
        return 0
    missing = [m for m, t in tmap.items() if not t and m not in NO_LOGIC]
    if args.check:
        for m in sorted(tmap):
            if m in NO_LOGIC:
                continue
            print(("ok   " if tmap[m] else "FAIL ") + m + ("" if tmap[m] else ": no test named after it under tests/"
                                                       + os.path.dirname(m) + "/"))
        print(f"RESULT: {len(tmap) - len(NO_LOGIC) - len(missing)} passed, {len(missing)} failed")
        return 1 if missing else 0
    if args.missing:
        print("\n".join(missing))
        return 1 if missing else 0
    for m in sorted(tmap):
        tag = "  (no logic: " + NO_LOGIC[m] + ")" if m in NO_LOGIC else ""
        print(f"{m}: {' '.join(tmap[m]) or '-'}{tag}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
