#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""make mutate: how many deliberate bugs the test suite catches.

Each mutant in tools/mutants.txt is one small source change (a flipped
comparison, an off-by-one bound, a changed constant, a deleted statement, a
changed operator; in Python also a changed default or a swapped branch) in
a module of firmware/, hal/, host-sim/ or tools/. The tree is copied once to
a scratch directory (build/mutate/tree: the files git knows, build/
excluded; its builds are kept between runs); for each mutant the harness
applies the change there, rebuilds and runs the tests of the mutated module,
fastest first, and puts the file back.

Which tests belong to a module follows from where they live
(tools/test_map.py, tests/README.md): tests/DIR/test_x*, check_x*, conf_x*
for DIR/x.c. A module without a test named after it (or with only tests that
need a system test's set-up) meets the tests of its folder (tests/DIR/)
instead, or where that has none every test under the folder above; marked
"(folder)". fuzz_ and bench_ files are
not pass/fail and are left out. A C test tests/P/NAME.c is the programs of
TEST_PROGS built from it (build/test/tests/P/NAME, build/test-fixed/...); a
.py or .sh test in TEST_PROGS is run after `make <test>` has built what it
depends on. A mutant is killed when a test fails, times out or does not
build (counted apart), survives otherwise.

  tools/mutate.py                 all mutants; report in build/mutate/report.txt
  tools/mutate.py ID...           only these (e.g. e2e-1 calib-3)
  tools/mutate.py --list          the mutants and the tests each one meets
  tools/mutate.py --folder DIR    only the mutants of modules under DIR

On a terminal a progress line shows done/total and the time left; with
-v (or when not on a terminal, nothing but) one line per mutant and the
summary: the score per folder, before (the previous run, kept in
build/mutate/results.json) and now, and every survivor. A figure, not a
pass/fail test: exit 0 unless the unmutated tree fails its own tests or a
mutant cannot be applied.
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
sys.path.insert(0, os.path.join(ROOT, "tools"))
import test_map  # noqa: E402  (the module -> tests map, derived from paths)

SCRATCH = os.path.join(ROOT, "build", "mutate", "tree")
LOGDIR = os.path.join(ROOT, "build", "mutate")
REPORT = os.path.join(LOGDIR, "report.txt")
RESULTS = os.path.join(LOGDIR, "results.json")
MUTANTS = os.path.join(ROOT, "tools", "mutants.txt")
# A test that takes this many times its unmutated time (and at least
# TIMEOUT_MIN_S) has met a mutant that makes it hang: killed.
TIMEOUT_FACTOR = 10
TIMEOUT_MIN_S = 60
NOT_PASS_FAIL = ("fuzz", "bench")
ENV = dict(os.environ, PYTHONDONTWRITEBYTECODE="1", CI="", MAKEFLAGS="")


def load_mutants(path=MUTANTS):
    """Rows "id  file: original text => replacement" (# comments)."""
    out = []
    with open(path, encoding="utf-8") as f:
        for n, line in enumerate(f, 1):
            line = line.rstrip("\n")
            if not line.strip() or line.lstrip().startswith("#"):
                continue
            mid, rest = line.split(None, 1)
            fil, change = rest.split(": ", 1)
            old, new = change.split(" => ", 1)
            out.append({"id": mid, "file": fil.strip(), "old": old.strip(),
                        "new": new.strip(), "where": "%s:%d" % (path, n)})
    return out


def test_progs():
    """TEST_PROGS as make sees it (the list make test runs)."""
    os.makedirs(LOGDIR, exist_ok=True)
    mk = os.path.join(LOGDIR, "print-test-progs.mk")
    with open(mk, "w") as f:
        f.write("print-test-progs:\n\t@echo $(TEST_PROGS)\n")
    out = subprocess.run(["make", "-s", "--no-print-directory", "-f", "Makefile", "-f", mk,
                          "print-test-progs"], cwd=ROOT, env=ENV, check=True,
                         stdout=subprocess.PIPE, universal_newlines=True).stdout
    return out.split()


def tests_of(module, tmap, progs):
    """(how, [(make target, program to run)]) for one module: its named
    tests, or the tests of its folder when it has none."""
    files = [t for t in tmap.get(module, [])
             if os.path.basename(t).split("_", 1)[0] not in NOT_PASS_FAIL]
    out = runnable(files, progs)
    if out:
        return "named", out
    # none named after it (or only ones that need a system test's set-up):
    # the tests of its folder, else every test under the folder above
    tests = sorted({t for ts in tmap.values() for t in ts
                    if os.path.basename(t).split("_", 1)[0] not in NOT_PASS_FAIL})
    folder = os.path.join("tests", os.path.dirname(module))
    out = runnable([t for t in tests if os.path.dirname(t) == folder], progs)
    if not out:
        up = os.path.dirname(folder) + "/"
        out = runnable([t for t in tests if t.startswith(up)], progs)
    return "folder", out


def runnable(files, progs):
    """[(make target, program)] of test files: the programs of TEST_PROGS
    built from a C test, a .py/.sh test of TEST_PROGS itself."""
    out = []
    for t in files:
        if t.endswith(".c"):
            stem = os.path.splitext(t)[0]
            built = [p for p in progs if p.startswith("build/") and p.endswith("/" + stem)]
            if not built:  # a program named after the file only
                built = [p for p in progs if p.startswith("build/")
                         and os.path.basename(p) == os.path.basename(stem)]
            out += [(p, p) for p in built]
        elif t in progs:
            out.append((t, t))
    return out


def check_mutants(mutants, root=ROOT):
    """Every original text occurs exactly once in its file; ids unique;
    every file is a module that tools/test_map.py knows."""
    errors = []
    ids = set()
    mods = set(test_map.modules())
    for m in mutants:
        if m["id"] in ids:
            errors.append("%s: duplicate id %s" % (m["where"], m["id"]))
        ids.add(m["id"])
        if m["file"] not in mods:
            errors.append("%s: %s is not a module (tools/test_map.py)" % (m["where"], m["file"]))
            continue
        with open(os.path.join(root, m["file"]), encoding="utf-8") as f:
            n = f.read().count(m["old"])
        if n != 1:
            errors.append("%s: '%s' occurs %d times in %s (must be once)"
                          % (m["where"], m["old"], n, m["file"]))
    return errors


def copy_tree():
    files = subprocess.run(["git", "ls-files", "-co", "--exclude-standard"], cwd=ROOT,
                           check=True, stdout=subprocess.PIPE,
                           universal_newlines=True).stdout.split("\n")
    for rel in files:
        if not rel or rel.startswith("build/"):
            continue
        src = os.path.join(ROOT, rel)
        dst = os.path.join(SCRATCH, rel)
        if not os.path.isfile(src):
            continue
        if os.path.exists(dst):
            with open(src, "rb") as a, open(dst, "rb") as b:
                if a.read() == b.read():
                    continue  # keep its time stamp: make need not rebuild it
        os.makedirs(os.path.dirname(dst), exist_ok=True)
        shutil.copy2(src, dst)
        os.utime(dst)


def make(targets, log):
    with open(log, "w") as f:
        return subprocess.run(["nice", "make", "-j2", "--no-print-directory"] + targets,
                              cwd=SCRATCH, env=ENV, stdout=f, stderr=subprocess.STDOUT).returncode


RESULT_RE = re.compile(r"^RESULT: (\d+) passed, (\d+) failed", re.M)
CMOCKA_FAILED_RE = re.compile(r"^\[  FAILED  \] \d+ test", re.M)


def run_one(prog, timeout_s):
    """(passed, seconds, why) of one test program in the scratch tree."""
    t0 = time.time()
    try:
        p = subprocess.run(["nice", os.path.join(SCRATCH, prog)], cwd=SCRATCH, env=ENV,
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                           timeout=timeout_s)
    except subprocess.TimeoutExpired:
        return False, time.time() - t0, "timeout"
    text = p.stdout.decode("utf-8", "replace")
    res = RESULT_RE.findall(text)
    failed = p.returncode != 0 or (res and int(res[-1][1]) > 0) or CMOCKA_FAILED_RE.search(text)
    return not failed, time.time() - t0, "" if not failed else "exit %d" % p.returncode


def folder_of(module):
    return os.path.dirname(module)


def fmt_s(s):
    s = int(s + 0.5)
    return "%d:%02d" % (s // 60, s % 60)


class Progress:
    """One line rewritten in place on a terminal; silent otherwise."""

    def __init__(self, total, enabled):
        self.total, self.enabled, self.t0 = total, enabled, time.time()

    def show(self, done, killed, survived, now):
        if not self.enabled:
            return
        el = time.time() - self.t0
        left = el / done * (self.total - done) if done else 0.0
        sys.stderr.write("\r\033[K[%d/%d] killed %d, survived %d, %s elapsed, ~%s left  %s"
                         % (done, self.total, killed, survived, fmt_s(el), fmt_s(left), now))
        sys.stderr.flush()

    def clear(self):
        if self.enabled:
            sys.stderr.write("\r\033[K")
            sys.stderr.flush()


def score_table(results, before):
    """Lines: per folder, killed / mutants before (previous run) and now."""
    folders = sorted({folder_of(r["file"]) for r in results})
    lines = ["%-22s %-14s %-14s %s" % ("folder", "before", "now", "modules")]

    def frac(rs):
        k = sum(1 for r in rs if r["how"] == "KILLED")
        return "%d/%d" % (k, len(rs)) if rs else "-"

    for fo in folders:
        now = [r for r in results if folder_of(r["file"]) == fo]
        old = [before[r["id"]] for r in now if r["id"] in before]
        lines.append("%-22s %-14s %-14s %d" % (fo, frac(old), frac(now),
                                               len({r["file"] for r in now})))
    old = [before[r["id"]] for r in results if r["id"] in before]
    lines.append("%-22s %-14s %-14s %d" % ("all", frac(old), frac(results),
                                           len({r["file"] for r in results})))
    return lines


def main(argv):
    ap = argparse.ArgumentParser(prog="tools/mutate.py", description=__doc__.split("\n\n")[0],
                                 epilog=__doc__.split("\n\n", 1)[1],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("ids", nargs="*", metavar="ID", help="run only these mutants")
    ap.add_argument("--list", action="store_true", help="print the mutants and their tests, run nothing")
    ap.add_argument("--folder", metavar="DIR", help="only the mutants of modules under DIR")
    ap.add_argument("--before", metavar="JSON", default=RESULTS,
                    help="the results to compare with (default: the previous run's, %(default)s)")
    ap.add_argument("-v", "--verbose", action="store_true", help="one line per mutant on a terminal too")
    args = ap.parse_args(argv[1:])

    mutants = load_mutants()
    errors = check_mutants(mutants)
    if errors:
        print("\n".join(errors))
        return 2
    tmap = test_map.test_map()
    progs = test_progs()
    plan = {f: tests_of(f, tmap, progs) for f in sorted({m["file"] for m in mutants})}
    errors = ["%s: no test meets %s (none named after it, none in its folder)" % (m["where"], m["file"])
              for m in mutants if not plan[m["file"]][1]]
    if errors:
        print("\n".join(errors))
        return 2
    if args.list:
        for m in mutants:
            how, tests = plan[m["file"]]
            print("%-10s %s: %s => %s\n           tests%s: %s"
                  % (m["id"], m["file"], m["old"], m["new"], " (folder)" if how == "folder" else "",
                     " ".join(t for _, t in tests) or "NONE"))
        return 0
    if args.ids:
        unknown = sorted(set(args.ids) - {m["id"] for m in mutants})
        if unknown:
            print("mutate.py: no such mutant: %s" % " ".join(unknown), file=sys.stderr)
            return 2
        mutants = [m for m in mutants if m["id"] in args.ids]
    if args.folder:
        mutants = [m for m in mutants if m["file"].startswith(args.folder.rstrip("/") + "/")]

    tty = sys.stderr.isatty()
    say = print if (args.verbose or not tty) else (lambda *a, **k: None)
    os.makedirs(SCRATCH, exist_ok=True)
    start = time.time()
    copy_tree()
    needed = sorted({t for m in mutants for t in plan[m["file"]][1]})
    targets = sorted({mk for mk, _ in needed})
    if tty:
        sys.stderr.write("baseline: building %d targets in %s ...\n" % (len(targets), SCRATCH))
    if make(targets, os.path.join(LOGDIR, "baseline-build.log")) != 0:
        print("baseline build failed: see build/mutate/baseline-build.log")
        return 1
    base_s = {}
    failing = []
    for i, (_, prog) in enumerate(needed):
        if tty:
            sys.stderr.write("\r\033[Kbaseline: running %d/%d %s" % (i + 1, len(needed), prog))
        ok, secs, why = run_one(prog, None)
        if not ok:
            failing.append("%s (%s)" % (prog, why))
        base_s[prog] = secs
    if failing:
        print("\nbaseline: fails on the unmutated tree, no score:\n  " + "\n  ".join(failing))
        return 1
    if tty:
        sys.stderr.write("\r\033[Kbaseline: %d tests pass (%s)\n" % (len(needed), fmt_s(time.time() - start)))

    before = {}
    if os.path.exists(args.before):
        with open(args.before, encoding="utf-8") as f:
            before = {r["id"]: r for r in json.load(f)}
    previous = {}
    if os.path.exists(RESULTS):
        with open(RESULTS, encoding="utf-8") as f:
            previous = {r["id"]: r for r in json.load(f)}
    results = []
    prog_bar = Progress(len(mutants), tty)
    killed = survived = 0
    for n, m in enumerate(mutants):
        prog_bar.show(n, killed, survived, m["id"])
        t0 = time.time()
        how_map, tests = plan[m["file"]]
        tests = sorted(tests, key=lambda t: base_s[t[1]])
        path = os.path.join(SCRATCH, m["file"])
        with open(path, encoding="utf-8") as f:
            orig = f.read()
        with open(path, "w", encoding="utf-8") as f:
            f.write(orig.replace(m["old"], m["new"], 1))
        how, by = "SURVIVED", ""
        try:
            # the fastest test first, built alone: most mutants die there,
            # and the others need not be linked
            for group in (tests[:1], tests[1:]):
                if not group or how == "KILLED":
                    continue
                if make(sorted({mk for mk, _ in group}), os.path.join(LOGDIR, "mutant-build.log")) != 0:
                    how, by = "KILLED", "(does not build)"
                    break
                for _, prog in group:
                    limit = max(TIMEOUT_MIN_S, TIMEOUT_FACTOR * base_s[prog])
                    ok, _, why = run_one(prog, limit)
                    if not ok:
                        how, by = "KILLED", prog + (" (timeout)" if why == "timeout" else "")
                        break
        finally:
            with open(path, "w", encoding="utf-8") as f:
                f.write(orig)
            now = time.time()
            os.utime(path, (now, now))
        killed += how == "KILLED"
        survived += how != "KILLED"
        r = dict(id=m["id"], file=m["file"], old=m["old"], new=m["new"], how=how, by=by,
                 map=how_map, secs=round(time.time() - t0, 1))
        results.append(r)
        if how != "KILLED":
            prog_bar.clear()
            if tty and not args.verbose:
                print("SURVIVED %-10s %s: %s => %s %s" % (m["id"], m["file"], m["old"], m["new"], by))
        say("%-8s %-10s %s: %s => %s%s  (%.0f s)" % (how, m["id"], m["file"], m["old"], m["new"],
                                                     "  by " + by if by else "", r["secs"]))
        sys.stdout.flush()
    prog_bar.clear()
    # leave the scratch build matching the sources again
    make(targets, os.path.join(LOGDIR, "restore-build.log"))

    stillborn = [r for r in results if r["by"] == "(does not build)"]
    survivors = [r for r in results if r["how"] != "KILLED"]
    untested = [r for r in survivors if r["by"] == "(no test)"]
    folder_mapped = sorted({r["file"] for r in results if r["map"] == "folder"})
    lines = ["mutation score: %d killed / %d mutants on %d modules (%d of them by not building), "
             "%d survived (%d with no test), %s"
             % (killed, len(results), len({r["file"] for r in results}), len(stillborn),
                len(survivors), len(untested), fmt_s(time.time() - start))]
    lines += score_table(results, before)
    if folder_mapped:
        lines.append("modules without a test named after them (met the tests of their folder): "
                     + " ".join(folder_mapped))
    lines += ["  survivor %s %s: %s => %s%s" % (r["id"], r["file"], r["old"], r["new"],
                                                "  " + r["by"] if r["by"] else "")
              for r in survivors]
    print("\n".join(lines))
    with open(REPORT, "w") as f:
        for r in results:
            f.write("%s %s %s: %s => %s %s\n" % (r["how"], r["id"], r["file"], r["old"], r["new"], r["by"]))
        f.write("\n".join(lines) + "\n")
    keep = dict(previous, **{r["id"]: r for r in results})  # the next run's "before"
    with open(RESULTS, "w", encoding="utf-8") as f:
        json.dump(sorted(keep.values(), key=lambda r: r["id"]), f, indent=0)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
