#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""make mutate: how many deliberate bugs the test suite catches.

Each mutant in tools/mutants.txt is one small source change (a flipped
comparison, an off-by-one bound, a changed constant, a deleted statement)
in firmware/ or host-sim's parsers. The tree is copied once to a scratch
directory (build/mutate/tree: the files git knows, build/ excluded); for
each mutant the harness applies the change there, rebuilds only the test
programs mapped to the mutated file (TESTS_FOR below), runs them, and puts
the file back. A mutant is killed when a mapped test fails (or does not
build: a "build" kill is counted apart), survives otherwise.

  tools/mutate.py                 all mutants; report in build/mutate/report.txt
  tools/mutate.py ID...           only these (e.g. e2e-1 calib-3)
  tools/mutate.py --list          the mutants and the tests each one meets

Prints one line per mutant and "mutation score: K killed / N mutants" with
every survivor; a figure for make bench, not a pass/fail test (exit 0
unless the unmutated tree fails its own tests or a mutant cannot be applied).
"""
import os
import shutil
import subprocess
import sys
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
SCRATCH = os.path.join(ROOT, "build", "mutate", "tree")
REPORT = os.path.join(ROOT, "build", "mutate", "report.txt")
MUTANTS = os.path.join(ROOT, "tools", "mutants.txt")
TEST_TIMEOUT_S = 120

# The mapping table: source file -> the tests that should notice a change in
# it (make targets; each one is built, then run). Host builds are the ASan +
# UBSan variants, float and fixed.
MODEL_TESTS = ["build/test/tests/firmware/model/test_squeal_model", "build/test-fixed/tests/firmware/model/test_squeal_model",
               "build/test/tests/firmware/model/test_squeal_model_props", "build/test-fixed/tests/firmware/model/test_squeal_model_props"]
MONITOR_TESTS = ["build/test/tests/firmware/monitor/test_monitor", "build/test-fixed/tests/firmware/monitor/test_monitor",
                 "build/test/tests/firmware/monitor/test_monitor_faults", "build/test-fixed/tests/firmware/monitor/test_monitor_faults",
                 "build/test/tests/firmware/app/test_squeal_app", "build/test-fixed/tests/firmware/app/test_squeal_app",
                 "build/test/tests/firmware/monitor/test_monitor_bounds", "build/test-fixed/tests/firmware/monitor/test_monitor_bounds"]
CALIB_TESTS = ["build/test/tests/firmware/monitor/test_calib", "build/test-fixed/tests/firmware/monitor/test_calib",
               "build/test/tests/host-sim/test_calib_text"]
PROTOCOL_TESTS = ["build/test/tests/firmware/protocol/test_squeal_msgs",
                  "tests/firmware/protocol/test_squeal_msgs_canmatrix.py",
                  "tests/firmware/protocol/test_squeal_msgs_unpack.py"]
# the vehicle input map (issue 11): extraction, protection, conversion
INPUTMAP_TESTS = ["build/test/tests/firmware/monitor/test_input_conv", "build/test-fixed/tests/firmware/monitor/test_input_conv",
                  "build/test/tests/firmware/monitor/test_input_rx", "build/test-fixed/tests/firmware/monitor/test_input_rx"]
TESTS_FOR = {
    "firmware/protocol/crc8_p01.c": PROTOCOL_TESTS,
    "firmware/protocol/e2e_p01.c": PROTOCOL_TESTS + ["build/test/tests/firmware/monitor/test_monitor_faults"],
    "firmware/protocol/squeal_msgs.c": PROTOCOL_TESTS + ["build/test/tests/firmware/app/test_squeal_app"],
    "firmware/monitor/monitor.c": MONITOR_TESTS,
    "firmware/monitor/calib.c": CALIB_TESTS + ["build/test/tests/firmware/monitor/test_monitor"],
    "firmware/monitor/model_adapter.c": MONITOR_TESTS + ["build/test-fixed/tests/firmware/model/test_squeal_model",
                                                         "build/test/tests/firmware/monitor/test_model_adapter",
                                                         "build/test-fixed/tests/firmware/monitor/test_model_adapter"],
    "firmware/app/squeal_app.c": ["build/test/tests/firmware/app/test_squeal_app", "build/test-fixed/tests/firmware/app/test_squeal_app",
                                  "build/test/tests/firmware/app/test_squeal_app_fault_injection"],
    "firmware/model/squeal_model_common.c": MODEL_TESTS,
    "firmware/model/squeal_model_float.c": ["build/test/tests/firmware/model/test_squeal_model", "build/test/tests/firmware/model/test_squeal_model_props"],
    "firmware/model/squeal_model_fixed.c": ["build/test-fixed/tests/firmware/model/test_squeal_model",
                                            "build/test-fixed/tests/firmware/model/test_squeal_model_props"],
    "firmware/model/fixmath.c": ["build/test-fixed/tests/firmware/model/test_squeal_model", "build/test-fixed/tests/firmware/model/test_squeal_model_props",
                                 "build/test-fixed/tests/firmware/model/test_fixmath"],
    "firmware/model/sq_mathf.c": ["build/test/tests/firmware/model/test_squeal_model", "build/test/tests/firmware/model/test_squeal_model_props"],
    "firmware/protocol/can_signal.c": INPUTMAP_TESTS,
    "firmware/protocol/e2e_p02.c": INPUTMAP_TESTS,
    "firmware/monitor/input_conv.c": INPUTMAP_TESTS,
    "firmware/monitor/input_rx.c": INPUTMAP_TESTS + MONITOR_TESTS,
    "host-sim/candump_log.c": ["build/test/tests/host-sim/test_candump_log"],
    "host-sim/calib_text.c": ["build/test/tests/host-sim/test_calib_text"],
}


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


def check_mutants(mutants):
    """Every original text occurs exactly once in its file; ids unique."""
    errors = []
    ids = set()
    for m in mutants:
        if m["id"] in ids:
            errors.append("%s: duplicate id %s" % (m["where"], m["id"]))
        ids.add(m["id"])
        if m["file"] not in TESTS_FOR:
            errors.append("%s: no tests mapped to %s" % (m["where"], m["file"]))
            continue
        with open(os.path.join(ROOT, m["file"]), encoding="utf-8") as f:
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
        if os.path.exists(dst) and open(src, "rb").read() == open(dst, "rb").read():
            continue  # keep its time stamp: make need not rebuild it
        os.makedirs(os.path.dirname(dst), exist_ok=True)
        shutil.copy2(src, dst)
        os.utime(dst)


def make(targets, log):
    with open(log, "w") as f:
        return subprocess.run(["nice", "make", "-j2", "--no-print-directory"] + targets,
                              cwd=SCRATCH, stdout=f, stderr=subprocess.STDOUT).returncode


def run_tests(tests):
    """The first failing test, or None when all pass."""
    for t in tests:
        try:
            rc = subprocess.run(["nice", os.path.join(SCRATCH, t)], cwd=SCRATCH,
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                timeout=TEST_TIMEOUT_S).returncode
        except subprocess.TimeoutExpired:
            return t + " (timeout)"
        if rc != 0:
            return t
    return None


def set_file(rel, text):
    path = os.path.join(SCRATCH, rel)
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)
    now = time.time()
    os.utime(path, (now, now))


def main(argv):
    mutants = load_mutants()
    errors = check_mutants(mutants)
    if errors:
        print("\n".join(errors))
        return 2
    if "--list" in argv:
        for m in mutants:
            print("%-10s %s: %s => %s\n           tests: %s" % (m["id"], m["file"], m["old"], m["new"],
                                                           " ".join(TESTS_FOR[m["file"]])))
        return 0
    only = [a for a in argv[1:] if not a.startswith("-")]
    if only:
        mutants = [m for m in mutants if m["id"] in only]
    os.makedirs(SCRATCH, exist_ok=True)
    copy_tree()
    logdir = os.path.join(ROOT, "build", "mutate")
    needed = sorted({t for m in mutants for t in TESTS_FOR[m["file"]]})
    start = time.time()
    print("baseline: building and running %d test programs in %s" % (len(needed), SCRATCH))
    sys.stdout.flush()
    if make(needed, os.path.join(logdir, "baseline-build.log")) != 0:
        print("baseline build failed: see build/mutate/baseline-build.log")
        return 1
    bad = run_tests(needed)
    if bad:
        print("baseline: %s fails on the unmutated tree: no score" % bad)
        return 1
    results = []
    for m in mutants:
        t0 = time.time()
        orig = open(os.path.join(SCRATCH, m["file"]), encoding="utf-8").read()
        set_file(m["file"], orig.replace(m["old"], m["new"], 1))
        try:
            tests = TESTS_FOR[m["file"]]
            if make(tests, os.path.join(logdir, "mutant-build.log")) != 0:
                how, by = "KILLED", "(does not build)"
            else:
                by = run_tests(tests)
                how = "KILLED" if by else "SURVIVED"
        finally:
            set_file(m["file"], orig)
        results.append((m, how, by))
        print("%-8s %-10s %s: %s => %s%s  (%.0f s)" % (how, m["id"], m["file"], m["old"], m["new"],
                                                     "  by " + by if by else "", time.time() - t0))
        sys.stdout.flush()
    # leave the scratch build matching the sources again
    make(needed, os.path.join(logdir, "restore-build.log"))
    killed = [r for r in results if r[1] == "KILLED"]
    stillborn = [r for r in killed if r[2] == "(does not build)"]
    survivors = [r for r in results if r[1] == "SURVIVED"]
    lines = ["mutation score: %d killed / %d mutants (%d of them by not building), %d survived, %.0f s"
             % (len(killed), len(results), len(stillborn), len(survivors), time.time() - start)]
    lines += ["  survivor %s %s: %s => %s" % (m["id"], m["file"], m["old"], m["new"])
              for m, _, _ in survivors]
    print("\n".join(lines))
    with open(REPORT, "w") as f:
        for m, how, by in results:
            f.write("%s %s %s: %s => %s %s\n" % (how, m["id"], m["file"], m["old"], m["new"], by or ""))
        f.write("\n".join(lines) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
