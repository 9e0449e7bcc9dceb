#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""make mutate: how many deliberate bugs the test suite catches.

Each mutant in tools/mutants.txt is one small source change (a flipped
comparison, an off-by-one bound, a changed constant, a deleted statement, a
changed operator; in Python also a changed default or a swapped branch) in
a module of firmware/, hal/, host-sim/ or tools/. The tree is copied to
scratch directories (build/mutate/tree, tree-1, ...: the files git knows,
build/ excluded; their builds are kept between runs), one per worker (-j,
default 2: the cores); each worker applies one mutant in its tree,
rebuilds and runs the tests of the mutated module, and puts the file back.
The test that killed a mutant last time runs first, then the others,
fastest first; the first failure ends the mutant. A Python tool's mutant
builds nothing.

Which tests belong to a module follows from where they live
(tools/test_map.py, tests/README.md): tests/DIR/test_x*, check_x*, conf_x*
for DIR/x.c. A module without a test named after it (or with only tests that
need a system test's set-up) meets the tests of its folder (tests/DIR/)
instead, or where that has none every test under the folder above; marked
"(folder)". fuzz_ and bench_ files are
not pass/fail and are left out. A C test tests/P/NAME.c is the programs of
TEST_PROGS built from it (build/test/tests/P/NAME, build/test-fixed/...); a
.py or .sh test in TEST_PROGS is run after `make <test>` has built what it
depends on. A mutant is killed when a test fails, takes more than 4 times
its unmutated time (at least 10 s; 300 s for a test never timed: it hangs)
or does not build (counted apart); it survives otherwise. The unmutated
tree's baseline is run for the tests that killed a mutant, after the
mutants, once per sources (build/mutate/baseline.json): a kill counts only
when that test passes unmutated, else there is no score. A test that a
mutant passes needs no baseline, so the slow tests that kill nothing do not
run twice. Test times (the order and the time-outs) are kept in
build/mutate/test_times.json from every passing run. Mutants argued equivalent in docs/mutation.md (its table
"Equivalent mutants") are left out of the score's denominator.

  tools/mutate.py                 all mutants; report in build/mutate/report.txt
  tools/mutate.py ID...           only these (e.g. e2e-1 calib-3)
  tools/mutate.py --list          the mutants and the tests each one meets
  tools/mutate.py --folder DIR    only the mutants of modules under DIR

On a terminal a progress line shows done/total and the time left; with
-v (or when not on a terminal, nothing but) one line per mutant and the
summary: the score per folder, before (the previous run, kept in
build/mutate/results.json, or --before FILE) and now, every survivor, and
the wall and CPU time (CPU / cores: the time on an idle machine). A figure,
not a pass/fail test: exit 0 unless the unmutated tree fails its own tests
or a mutant cannot be applied.
"""
import argparse
import hashlib
import json
import os
import queue
import re
import resource
import shutil
import signal
import subprocess
import sys
import threading
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
sys.path.insert(0, os.path.join(ROOT, "tools"))
import test_map  # noqa: E402  (the module -> tests map, derived from paths)

SCRATCH = os.path.join(ROOT, "build", "mutate", "tree")
LOGDIR = os.path.join(ROOT, "build", "mutate")
REPORT = os.path.join(LOGDIR, "report.txt")
RESULTS = os.path.join(LOGDIR, "results.json")
BASELINE = os.path.join(LOGDIR, "baseline.json")
TIMES = os.path.join(LOGDIR, "test_times.json")
EQUIV_DOC = os.path.join(ROOT, "docs", "mutation.md")
# what the harness reads itself, no test of a mutated module: a change here
# keeps the baseline
NOT_FINGERPRINTED = ("tools/mutants.txt", "docs/mutation.md", "tools/mutate.py")
MUTANTS = os.path.join(ROOT, "tools", "mutants.txt")
# A test that takes this many times its unmutated time (and at least
# TIMEOUT_MIN_S) has met a mutant that makes it hang: killed.
TIMEOUT_FACTOR = 4
TIMEOUT_MIN_S = 10
# A test never timed yet: its place in the order is a guess by kind; it is
# first run for PROBE_S (cut off there, it runs in full after the mutant's
# other tests), and a mutant that makes it hang is stopped after
# UNKNOWN_LIMIT_S.
UNKNOWN_C_S = 1.0
UNKNOWN_SCRIPT_S = 10.0
UNKNOWN_LIMIT_S = 300
PROBE_S = 3
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


def tree_files():
    out = subprocess.run(["git", "ls-files", "-co", "--exclude-standard"], cwd=ROOT,
                         check=True, stdout=subprocess.PIPE,
                         universal_newlines=True).stdout.split("\n")
    return [rel for rel in out if rel and not rel.startswith("build/")
            and os.path.isfile(os.path.join(ROOT, rel))]


def copy_tree(dst, files):
    """Bring scratch tree dst up to date with the sources; returns a
    fingerprint of their contents (the baseline is reused while it holds)."""
    h = hashlib.sha1()
    for rel in files:
        src = os.path.join(ROOT, rel)
        out = os.path.join(dst, rel)
        with open(src, "rb") as a:
            data = a.read()
        if rel not in NOT_FINGERPRINTED:
            h.update(rel.encode() + b"\0" + hashlib.sha1(data).digest())
        mode = os.stat(src).st_mode & 0o777
        h.update(b"%o" % mode)  # an exec bit is part of what a test runs
        if os.path.exists(out):
            with open(out, "rb") as b:
                if b.read() == data:
                    if os.stat(out).st_mode & 0o777 != mode:
                        os.chmod(out, mode)
                    continue  # keep its time stamp: make need not rebuild it
        os.makedirs(os.path.dirname(out), exist_ok=True)
        shutil.copy2(src, out)
        os.utime(out)
    return h.hexdigest()


def make(tree, targets, log, jobs):
    with open(log, "w") as f:
        return subprocess.run(["nice", "make", "-j%d" % jobs, "--no-print-directory"] + targets,
                              cwd=tree, env=ENV, stdout=f, stderr=subprocess.STDOUT).returncode


RESULT_RE = re.compile(r"^RESULT: (\d+) passed, (\d+) failed", re.M)
CMOCKA_FAILED_RE = re.compile(r"^\[  FAILED  \] \d+ test", re.M)


def run_one(tree, prog, timeout_s):
    """(passed, seconds, why) of one test program in a scratch tree."""
    t0 = time.time()
    try:
        p = subprocess.run(["nice", os.path.join(tree, prog)], cwd=tree, env=ENV,
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


def equivalent_ids(path=EQUIV_DOC):
    """The mutants argued equivalent: the first column of the table under
    "## Equivalent mutants" in docs/mutation.md (one place for the list and
    the arguments)."""
    ids = set()
    if not os.path.exists(path):
        return ids
    inside = False
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("## "):
                inside = line.strip() == "## Equivalent mutants"
            elif inside:
                m = re.match(r"^\| ([a-z0-9]+-[a-z0-9]+) ", line)
                if m:
                    ids.add(m.group(1))
    return ids


def score_table(results, before, equivalent=frozenset()):
    """Lines: per folder, killed / non-equivalent mutants before (previous
    run) and now."""
    folders = sorted({folder_of(r["file"]) for r in results})
    lines = ["%-22s %-14s %-14s %s" % ("folder", "before", "now", "modules")]

    def frac(rs):
        rs = [r for r in rs if r["id"] not in equivalent]
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


class TestTimes:
    """How long each test takes on the unmutated tree, as far as known:
    build/mutate/test_times.json, kept across runs and source changes (an
    estimate for the order and the time-outs, updated by every passing
    run), and which tests passed on the unmutated tree of these sources
    (build/mutate/baseline.json, with the sources' fingerprint)."""

    def __init__(self, fingerprint, fresh):
        self.fingerprint = fingerprint
        self.secs = {}
        self.passed = {}
        self.floor = {}  # cut off after this many seconds: slower than that
        self.lock = threading.Lock()
        if os.path.exists(TIMES):
            with open(TIMES, encoding="utf-8") as f:
                self.secs = json.load(f)
        if os.path.exists(BASELINE) and not fresh:
            with open(BASELINE, encoding="utf-8") as f:
                doc = json.load(f)
            if doc.get("fingerprint") == fingerprint:
                self.passed = doc.get("secs", {})
        self.secs.update(self.passed)

    def estimate(self, prog):
        """Seconds: the last known time, else how long it ran before it
        was cut off, else a guess by kind (a C program is quick, a script
        may start other programs)."""
        if prog in self.secs:
            return self.secs[prog]
        if prog in self.floor:
            return self.floor[prog]
        return UNKNOWN_C_S if prog.startswith("build/") else UNKNOWN_SCRIPT_S

    def cut_off(self, prog, secs):
        """prog ran secs and was stopped: it takes at least that long."""
        with self.lock:
            self.floor[prog] = max(self.floor.get(prog, 0.0), round(secs, 2), UNKNOWN_SCRIPT_S + 1.0)

    def known(self, prog):
        return prog in self.secs

    def limit(self, prog):
        """The time-out of a test on a mutant (None: no known time)."""
        if prog not in self.secs:
            return UNKNOWN_LIMIT_S
        return max(TIMEOUT_MIN_S, TIMEOUT_FACTOR * self.secs[prog])

    def ran(self, prog, secs):
        with self.lock:
            self.secs[prog] = round(secs, 2)

    def save(self):
        with self.lock:
            with open(TIMES, "w", encoding="utf-8") as f:
                json.dump(self.secs, f, indent=0, sort_keys=True)
            with open(BASELINE, "w", encoding="utf-8") as f:
                json.dump({"fingerprint": self.fingerprint, "secs": self.passed}, f, indent=0, sort_keys=True)


def confirm_killers(results, times, trees, tty):
    """The baseline, for the tests that matter: every test that killed a
    mutant must pass on the unmutated tree (else its kills say nothing),
    run once per sources; a test that only passed needs no baseline, and a
    slow test that kills nothing is never run unmutated. Returns the tests
    that fail there, and the mutants a time-out killed with a limit below
    TIMEOUT_FACTOR times the test's unmutated time (to be run again)."""
    killers = sorted({r["by"].split(" ")[0] for r in results
                      if r["how"] == "KILLED" and not r["by"].startswith("(")} - set(times.passed))
    failing = []
    work = queue.Queue()
    for p in killers:
        work.put(p)

    def worker(tree):
        while True:
            try:
                prog = work.get_nowait()
            except queue.Empty:
                return
            ok, secs, why = run_one(tree, prog, None)
            with times.lock:
                if ok:
                    times.passed[prog] = round(secs, 2)
                    times.secs[prog] = round(secs, 2)
                else:
                    failing.append("%s (%s)" % (prog, why))
                if tty:
                    sys.stderr.write("\r\033[Kbaseline: the unmutated tree passes %d/%d tests that killed a mutant"
                                     % (len(killers) - work.qsize(), len(killers)))
    threads = [threading.Thread(target=worker, args=(t,)) for t in trees]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    if tty and killers:
        sys.stderr.write("\r\033[K")
    again = [r["id"] for r in results if r["by"].endswith(" (timeout)")
             and r.get("limit", 0) < TIMEOUT_FACTOR * times.passed.get(r["by"].split(" ")[0], 0)]
    return failing, again


def run_mutant(tree, m, how_map, tests, times, make_jobs):
    """Apply one mutant in a scratch tree, build and run its tests (in the
    given order, stop at the first failure), put the file back."""
    t0 = time.time()
    path = os.path.join(tree, m["file"])
    log = os.path.join(LOGDIR, "mutant-build-%s.log" % os.path.basename(tree))
    with open(path, encoding="utf-8") as f:
        orig = f.read()
    with open(path, "w", encoding="utf-8") as f:
        f.write(orig.replace(m["old"], m["new"], 1))
    how, by = "SURVIVED", ""
    limit = 0
    # a Python tool builds nothing: its tests run at once (the baseline
    # built what they need)
    python = m["file"].endswith(".py")
    try:
        # the first test (last time's killer, else the fastest) built
        # alone: most mutants die there, and the others need not be linked
        for group in (tests[:1], tests[1:]):
            if not group or how == "KILLED":
                continue
            if not python and make(tree, sorted({mk for mk, _ in group}), log, make_jobs) != 0:
                how, by = "KILLED", "(does not build)"
                break
            # a test never timed first gets PROBE_S: most mutants die in a
            # quick test, so a slow one is cut off and run in full only
            # when no other test has killed the mutant
            later = []
            for _, prog in group:
                probe = not times.known(prog)
                limit = PROBE_S if probe else times.limit(prog)
                ok, secs, why = run_one(tree, prog, limit)
                if ok:
                    times.ran(prog, secs)  # a pass: the test's own time
                elif probe and why == "timeout":
                    times.cut_off(prog, secs)
                    later.append(prog)
                else:
                    how, by = "KILLED", prog + (" (timeout)" if why == "timeout" else "")
                    break
            for prog in later if how != "KILLED" else ():
                limit = times.limit(prog)
                ok, secs, why = run_one(tree, prog, limit)
                if ok:
                    times.ran(prog, secs)
                else:
                    how, by = "KILLED", prog + (" (timeout)" if why == "timeout" else "")
                    break
    finally:
        with open(path, "w", encoding="utf-8") as f:
            f.write(orig)
        now = time.time()
        os.utime(path, (now, now))
    return dict(id=m["id"], file=m["file"], old=m["old"], new=m["new"], how=how, by=by,
                map=how_map, secs=round(time.time() - t0, 1),
                limit=limit if by.endswith(" (timeout)") else 0)


def summary(results, before, timing):
    """The report's lines: the score, per folder before and now, the
    survivors."""
    killed = sum(1 for r in results if r["how"] == "KILLED")
    stillborn = [r for r in results if r["by"] == "(does not build)"]
    equivalent = equivalent_ids() & {r["id"] for r in results}
    survivors = [r for r in results if r["how"] != "KILLED"]
    real = len(results) - len(equivalent)
    killed_real = sum(1 for r in results if r["how"] == "KILLED" and r["id"] not in equivalent)
    untested = [r for r in survivors if r["by"] == "(no test)"]
    folder_mapped = sorted({r["file"] for r in results if r["map"] == "folder"})
    lines = ["mutation score: %d killed / %d mutants on %d modules (%d of them by not building), "
             "%d survived (%d with no test), %s"
             % (killed, len(results), len({r["file"] for r in results}), len(stillborn),
                len(survivors), len(untested), timing[0]),
             timing[1],
             "score: %d of %d non-equivalent mutants killed (%.1f %%); %d argued equivalent in docs/mutation.md"
             % (killed_real, real, 100.0 * killed_real / max(1, real), len(equivalent))]
    logic = [m for m in test_map.modules() if m not in test_map.NO_LOGIC]
    per = {}
    for r in results:
        per[r["file"]] = per.get(r["file"], 0) + 1
    covered = [m for m in logic if per.get(m, 0) >= 3]
    lines.append("modules with logic that have at least 3 mutants here: %d of %d (%.0f %%)%s"
                 % (len(covered), len(logic), 100.0 * len(covered) / max(1, len(logic)),
                    "; not: " + " ".join(sorted(set(logic) - set(covered)))
                    if 0 < len(logic) - len(covered) <= 12 else ""))
    lines += score_table(results, before, equivalent)
    if folder_mapped:
        lines.append("modules without a test named after them (met the tests of their folder): "
                     + " ".join(folder_mapped))
    lines += ["  survivor %s %s: %s => %s%s%s" % (r["id"], r["file"], r["old"], r["new"],
                                                  "  " + r["by"] if r["by"] else "",
                                                  "  (argued equivalent)" if r["id"] in equivalent else "")
              for r in survivors]
    return lines


def main(argv):
    ap = argparse.ArgumentParser(prog="tools/mutate.py", description=__doc__.split("\n\n")[0],
                                 epilog=__doc__.split("\n\n", 1)[1],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("ids", nargs="*", metavar="ID", help="run only these mutants")
    ap.add_argument("--list", action="store_true", help="print the mutants and their tests, run nothing")
    ap.add_argument("--report", action="store_true",
                    help="print the score of the last results of every mutant (build/mutate/results.json), run nothing")
    ap.add_argument("--folder", metavar="DIR", help="only the mutants of modules under DIR")
    ap.add_argument("--before", metavar="JSON", default=RESULTS,
                    help="the results to compare with (default: the previous run's, %(default)s)")
    ap.add_argument("-j", "--jobs", type=int, default=min(2, os.cpu_count() or 1),
                    help="mutants at once, each in its own scratch tree (default %(default)s)")
    ap.add_argument("--cheap-first", action="store_true",
                    help="start the quickest mutants first (the default starts the longest: the workers end together)")
    ap.add_argument("--fresh-baseline", action="store_true",
                    help="run the unmutated tree's tests even when the sources are unchanged")
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
    if args.report:
        # the last result of every mutant of today's list (runs of a few
        # IDs add to it), nothing run
        last = {}
        if os.path.exists(RESULTS):
            with open(RESULTS, encoding="utf-8") as f:
                last = {r["id"]: r for r in json.load(f)}
        have = [last[m["id"]] for m in mutants if m["id"] in last
                and (last[m["id"]]["old"], last[m["id"]]["new"]) == (m["old"], m["new"])]
        missing = [m["id"] for m in mutants if m["id"] not in {r["id"] for r in have}]
        before = {}
        if args.before != RESULTS and os.path.exists(args.before):
            with open(args.before, encoding="utf-8") as f:
                before = {r["id"]: r for r in json.load(f)}
        lines = summary(have, before, ("-", "time: (the last results of %d mutants, %d not run yet%s)"
                                       % (len(have), len(missing),
                                          ": " + " ".join(missing) if 0 < len(missing) <= 20 else "")))
        print("\n".join(lines))
        return 0
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
    start = time.time()
    cpu0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    jobs = max(1, args.jobs)
    make_jobs = max(1, (os.cpu_count() or 1) // jobs)
    trees = [SCRATCH] + ["%s-%d" % (SCRATCH, k) for k in range(1, jobs)]
    files = tree_files()
    os.makedirs(SCRATCH, exist_ok=True)
    fingerprint = copy_tree(SCRATCH, files)
    needed = sorted({t for m in mutants for t in plan[m["file"]][1]})
    targets = sorted({mk for mk, _ in needed})
    if tty:
        sys.stderr.write("baseline: building %d targets in %s ...\n" % (len(targets), SCRATCH))
    if make(SCRATCH, targets, os.path.join(LOGDIR, "baseline-build.log"), os.cpu_count() or 1) != 0:
        print("baseline build failed: see build/mutate/baseline-build.log")
        return 1
    for tree in trees[1:]:
        # a second tree starts as a copy of the first, builds and all
        # (time stamps kept), so that it need not be built again
        if not os.path.isdir(os.path.join(tree, "build")):
            shutil.rmtree(tree, ignore_errors=True)
            shutil.copytree(SCRATCH, tree, symlinks=True)
        copy_tree(tree, files)
        if make(tree, targets, os.path.join(LOGDIR, "baseline-build-%s.log" % os.path.basename(tree)),
                os.cpu_count() or 1) != 0:
            print("baseline build failed in %s" % tree)
            return 1
    times = TestTimes(fingerprint, args.fresh_baseline)
    if tty:
        sys.stderr.write("\r\033[Kbuilt (%s); the unmutated tree runs the tests that kill a mutant at the end\n"
                         % fmt_s(time.time() - start))

    before = {}
    if os.path.exists(args.before):
        with open(args.before, encoding="utf-8") as f:
            before = {r["id"]: r for r in json.load(f)}
    previous = {}
    if os.path.exists(RESULTS):
        with open(RESULTS, encoding="utf-8") as f:
            previous = {r["id"]: r for r in json.load(f)}
    def order_of(m):
        """The mutant's tests, fastest first as far as known when it
        starts (what earlier mutants learnt counts), last time's killer
        first: most mutants die there again."""
        tests = sorted(plan[m["file"]][1], key=lambda t: (times.estimate(t[1]), t[1]))
        killer = previous.get(m["id"], {}).get("by", "").split(" ")[0]
        tests.sort(key=lambda t: t[1] != killer)
        return tests

    # the longest first, so that the workers end together
    expect = {m["id"]: sum(times.estimate(p) for _, p in
                           order_of(m)[:1 if previous.get(m["id"], {}).get("how") == "KILLED" else None])
              for m in mutants}
    work = queue.Queue()
    for m in sorted(mutants, key=lambda m: expect[m["id"]] if args.cheap_first else -expect[m["id"]]):
        work.put(m)
    lock = threading.Lock()
    results = {}
    prog_bar = Progress(len(mutants), tty)
    count = {"killed": 0, "survived": 0}
    busy = {}

    def worker(tree):
        while not stop:
            try:
                m = work.get_nowait()
            except queue.Empty:
                return
            with lock:
                busy[tree] = m["id"]
                prog_bar.show(len(results), count["killed"], count["survived"], " ".join(sorted(busy.values())))
            r = run_mutant(tree, m, plan[m["file"]][0], order_of(m), times, make_jobs)
            with lock:
                del busy[tree]
                results[m["id"]] = r
                save_results(previous, results.values())
                count["killed" if r["how"] == "KILLED" else "survived"] += 1
                if r["how"] != "KILLED":
                    prog_bar.clear()
                    if tty and not args.verbose:
                        print("SURVIVED %-10s %s: %s => %s %s" % (m["id"], m["file"], m["old"], m["new"], r["by"]))
                say("%-8s %-10s %s: %s => %s%s  (%.0f s)" % (r["how"], m["id"], m["file"], m["old"], m["new"],
                                                             "  by " + r["by"] if r["by"] else "", r["secs"]))
                sys.stdout.flush()
                prog_bar.show(len(results), count["killed"], count["survived"], " ".join(sorted(busy.values())))

    stop = []
    signal.signal(signal.SIGTERM, interrupted)
    threads = [threading.Thread(target=worker, args=(t,)) for t in trees]
    for t in threads:
        t.start()
    try:
        for t in threads:
            while t.is_alive():
                t.join(0.5)
    except KeyboardInterrupt:
        # the mutants under way end (their files are put back); the
        # results so far are kept in build/mutate/results.json
        stop.append(True)
        prog_bar.clear()
        print("interrupted: finishing the %d mutants under way" % len(busy))
        for t in threads:
            t.join()
    prog_bar.clear()
    results = [results[m["id"]] for m in mutants if m["id"] in results]
    killed = count["killed"]
    # leave the scratch builds matching the sources again: the baseline of
    # the killing tests runs there
    for tree in trees:
        make(tree, targets, os.path.join(LOGDIR, "restore-build.log"), os.cpu_count() or 1)
    failing, again = confirm_killers(results, times, trees, tty)
    if again and not failing:
        # killed by a time-out shorter than the test's own time allows: again
        by_id = {m["id"]: m for m in mutants}
        for mid in again:
            r = run_mutant(trees[0], by_id[mid], plan[by_id[mid]["file"]][0], order_of(by_id[mid]), times, make_jobs)
            results = [r if x["id"] == mid else x for x in results]
            say("%-8s %-10s again, the time-out from the test's unmutated time" % (r["how"], mid))
        make(trees[0], targets, os.path.join(LOGDIR, "restore-build.log"), os.cpu_count() or 1)
        failing, _ = confirm_killers(results, times, trees, tty)
    times.save()
    save_results(previous, results)
    if failing:
        print("baseline: fails on the unmutated tree, no score:\n  " + "\n  ".join(sorted(failing)))
        return 1
    cpu1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu_s = (cpu1.ru_utime - cpu0.ru_utime) + (cpu1.ru_stime - cpu0.ru_stime)

    timing = (fmt_s(time.time() - start),
              "time: %s wall with %d workers, %s CPU (user + system of every build and test; "
              "on an idle %d-core machine about %s)"
              % (fmt_s(time.time() - start), jobs, fmt_s(cpu_s), os.cpu_count() or 1,
                 fmt_s(cpu_s / max(1, min(jobs, os.cpu_count() or 1)))))
    lines = summary(results, before, timing)
    print("\n".join(lines))
    with open(REPORT, "w") as f:
        for r in results:
            f.write("%s %s %s: %s => %s %s\n" % (r["how"], r["id"], r["file"], r["old"], r["new"], r["by"]))
        f.write("\n".join(lines) + "\n")
    save_results(previous, results)
    return 0


def interrupted(signum, frame):
    raise KeyboardInterrupt


def save_results(previous, results):
    """build/mutate/results.json: the last result of every mutant (the
    next run's "before" and its order), written after each mutant."""
    keep = dict(previous, **{r["id"]: r for r in results})
    tmp = RESULTS + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        json.dump(sorted(keep.values(), key=lambda r: r["id"]), f, indent=0)
    os.replace(tmp, RESULTS)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
