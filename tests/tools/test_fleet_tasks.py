#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""tools/fleet.py's tasks and progress, without a Dask cluster:
  - batches(): every log in exactly one task; guided shares of the bytes
    left (by hand: 16 equal logs in 8 4 2 1 1 for one worker); a log
    larger than a task's share is a task alone, and first; small logs share
    tasks; one worker or many, none empty;
  - local_layout(): N replays at a time as ceil(N / 4) processes, the
    threads spread evenly (one process of N threads up to 4);
  - Progress: nothing written when the stream is not a terminal; on a
    terminal (a pty) "fleet: D/T logs, S s left" after each task, and the
    line cleared at the end;
  - `fleet.py --dir nosuch`: one line "fleet: nosuch: no such folder" on
    stderr, exit 1; --workers 0 or no log: refused with the rule, exit 2;
  - outcome(): a document's verdict: exit status 0 with one malformed line
    is partial (with the first bad line), a failed or never started replay
    is failed with its error;
  - replay_batch(): a task's logs in one `replay --each`; when that process
    crashes or hangs on one log (a stand-in squeal-sim that kills itself or
    sleeps there), every other log still gets its result from a replay of
    its own, and only that log fails, with the reason; the finished logs'
    cells come back added up, and each log's summary with only its state
    times and episodes; dask.sizeof weighs the result as the bytes of the
    documents read (the stand-in's own lines), and it pickles.
Prints "RESULT: N passed, M failed"."""
import io
import os
import pickle
import pty
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "tools"))
import fleet  # noqa: E402
from dask.sizeof import sizeof  # noqa: E402

COUNTS = {True: 0, False: 0}


def check(ok, what):
    COUNTS[bool(ok)] += 1
    if not ok:
        print("FAIL  " + what)


def write(path, nbytes):
    with open(path, "wb") as f:
        f.write(b"x" * nbytes)
    return path


def test_batches(tmp):
    small = [write(os.path.join(tmp, "s%03d.log" % i), 1000) for i in range(150)]
    big = write(os.path.join(tmp, "big.log"), 200000)
    logs = small + [big]
    for workers in (1, 2, 4):
        tasks = fleet.batches(logs, workers)
        flat = [x for t in tasks for x in t]
        check(sorted(flat) == sorted(logs) and len(flat) == len(logs),
              "%d workers: every log in exactly one task" % workers)
        check(all(tasks), "%d workers: no empty task" % workers)
        check([big] in tasks, "%d workers: the large log is a task alone" % workers)
        check(tasks[0] == [big], "%d workers: the large log goes first" % workers)
        check(2 * workers <= len(tasks) <= workers * fleet.MIN_TASKS_PER_WORKER + 1,
              "%d workers: %d tasks, enough to balance, no smaller than the floor" % (workers, len(tasks)))
        check(max(len(t) for t in tasks) > 1, "%d workers: small logs share a task" % workers)
    # guided shares, by hand: 16 logs of 1000 bytes; a task closes when it
    # holds max(left / (2 workers), 16000 / (16 workers)) bytes
    even = [write(os.path.join(tmp, "e%02d.log" % i), 1000) for i in range(16)]
    got = [len(t) for t in fleet.batches(even, 1)]
    check(got == [8, 4, 2, 1, 1], "1 worker: 8 4 2 1 1 logs (left/2, floor 1000 B) (%r)" % got)
    got = [len(t) for t in fleet.batches(even, 2)]
    check(got == [4, 3, 3, 2, 1, 1, 1, 1], "2 workers: 4 3 3 2 1 1 1 1 logs (left/4, floor 500 B) (%r)" % got)
    missing = os.path.join(tmp, "missing.log")
    tasks = fleet.batches([missing], 2)
    check(tasks == [[missing]], "a log that is not there is still a task (its replay reports it)")


def test_local_layout():
    # by hand: ceil(N / 4) processes, the N replays spread evenly over them
    want = {1: (1, 1), 2: (1, 2), 4: (1, 4), 5: (2, 3), 8: (2, 4), 9: (3, 3), 16: (4, 4)}
    got = {n: fleet.local_layout(n) for n in want}
    check(got == want, "LocalCluster layout (processes, threads) per replays at a time: %r" % got)


def test_progress(tmp):
    logs = [write(os.path.join(tmp, "p%d.log" % i), 100 * (i + 1)) for i in range(5)]
    quiet = io.StringIO()
    p = fleet.Progress(logs, stream=quiet)
    p.update(logs[:2])
    p.update(logs[2:])
    p.close()
    check(quiet.getvalue() == "", "not a terminal: no progress written")
    master, slave = pty.openpty()
    with os.fdopen(slave, "w") as tty:
        p = fleet.Progress(logs, stream=tty)
        p.update(logs[:3])
        p.update(logs[3:])
        p.close()
    out = b""
    while True:
        try:
            chunk = os.read(master, 4096)
        except OSError:
            break
        if not chunk:
            break
        out += chunk
    os.close(master)
    text = out.decode()
    check("fleet: 3/5 logs, " in text and " s left" in text and "fleet: 5/5 logs, 0.0 s left" in text,
          "terminal: done/total and the time left (%r)" % text)
    check(text.rstrip(" ").endswith("\r"), "terminal: the line is cleared at the end")


def test_no_such_folder():
    p = subprocess.run([sys.executable, os.path.join(ROOT, "tools", "fleet.py"), "--dir", "nosuch"],
                       stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True)
    check(p.returncode == 1 and p.stderr == "fleet: nosuch: no such folder\n" and p.stdout == "",
          "--dir nosuch: one line, exit 1 (%d %r)" % (p.returncode, p.stderr))


def test_refusals():
    for argv, what in ((["x.log", "--workers", "0"], "--workers 0"), ([], "no LOG and no --dir")):
        try:
            p = subprocess.run([sys.executable, os.path.join(ROOT, "tools", "fleet.py")] + argv,
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True,
                               timeout=10)
        except subprocess.TimeoutExpired:
            check(False, "%s: refused at once (it ran on for 10 s)" % what)
            continue
        check(p.returncode == 2 and "--workers >= 1" in p.stderr and p.stdout == "",
              "%s: refused with the rule, exit 2 (%d %r)" % (what, p.returncode, p.stderr[-120:]))


def doc(status=0, started=True, malformed=0, error="", bad=None):
    return {"exit_status": status, "started": started, "error": error, "first_malformed": bad,
            "lines": {"total": 10, "malformed": malformed}}


def test_outcome():
    bad = {"line": 7, "column": 3, "error": "bad identifier"}
    r = fleet.outcome("a.log", doc(malformed=1, bad=bad))
    check(r["status"] == "partial" and r["reason"] == "1 malformed lines skipped (first: a.log:7: bad "
          "identifier (column 3))", "one malformed line: partial, with the line (%r)" % r)
    r = fleet.outcome("a.log", doc())
    check(r["status"] == "ok" and r["reason"] == "", "no malformed line: ok (%r)" % r)
    r = fleet.outcome("b.log", doc(1, False, 1, "b.log: no CAN frame in 1 line",
                                   {"line": 1, "column": 0, "error": "not a candump -L line"}))
    check(r["status"] == "failed" and r["reason"] == "b.log: no CAN frame in 1 line; first malformed "
          "line: b.log:1: not a candump -L line", "no frame: failed, with its error (%r)" % r)
    r = fleet.outcome("c.log", doc(1, True, 0, "squeal-sim replay: c.log: read error"))
    check(r["status"] == "failed" and r["reason"] == "squeal-sim replay: c.log: read error",
          "a failed replay: failed, with its error (%r)" % r)


STAND_IN = """#!/usr/bin/python3
# squeal-sim replay --each, but the process dies (crash.log) or hangs
# (slow.log) when it reaches those logs
import json, os, signal, sys, time
logs = [a for a in sys.argv[2:] if a.endswith(".log")]
for log in logs:
    if log.endswith("crash.log"):
        sys.stdout.flush()
        os.kill(os.getpid(), signal.SIGSEGV)
    if log.endswith("slow.log"):
        sys.stdout.flush()
        time.sleep(30)
    print(json.dumps({"log": log, "exit_status": 0, "error": "", "started": True,
                      "first_malformed": None, "lines": {"total": 1, "malformed": 0},
                      "corners": [{"corner": "FL", "state_time_s": {"stable": 1.0},
                                   "cells": [[1, 2, "stable", 0.25]]}],
                      "episodes": [], "cells_grid": {"v0_bins": 4}}))
"""


def test_batch_fallback(tmp):
    sim = os.path.join(tmp, "stand-in-sim")
    with open(sim, "w") as f:
        f.write(STAND_IN)
    os.chmod(sim, 0o755)
    for bad in ("crash.log", "slow.log"):
        logs = [os.path.join(tmp, n) for n in ("a.log", "b.log", bad, "c.log", "d.log")]
        batch = fleet.replay_batch(logs, sim, None, 1.0)
        res = batch.results
        check([r["log"] for r in res] == logs, "%s: a result per log, in order" % bad)
        ok = [r["status"] for r in res]
        check(ok == ["ok", "ok", "failed", "ok", "ok"], "%s: only that log fails (%r)" % (bad, ok))
        why = res[2]["reason"]
        want = "exit status -11" if bad == "crash.log" else "replay took longer than 1 s"
        check(why == want, "%s: the reason %r (%r)" % (bad, want, why))
        # the four logs that finished: their cells added up, 4 x 0.25 s
        check(batch.cells == {"FL": {(1, 2, "stable"): 1.0}} and batch.grid == {"v0_bins": 4},
              "%s: the finished logs' cells added up (%r)" % (bad, batch.cells))
        check(res[0]["summary"] == {"corners": [{"corner": "FL", "state_time_s": {"stable": 1.0}}],
                                    "episodes": []},
              "%s: a log's summary keeps its state times and episodes, not its cells" % bad)
        # Dask weighs a result by its __sizeof__ (not by walking it): the
        # text of the four documents read, as the stand-in prints them, and
        # the garbage collector's header that sys.getsizeof adds to any object
        good = [x for x in logs if x != os.path.join(tmp, bad)]
        text = subprocess.run([sim, "replay", "--each"] + good, stdout=subprocess.PIPE,
                              check=True).stdout.decode().splitlines()
        want = sum(len(x) for x in text) + sys.getsizeof([]) - [].__sizeof__()
        check(sizeof(batch) == want, "%s: dask.sizeof of the result is its documents' bytes "
              "and the header, %d (%d)" % (bad, want, sizeof(batch)))
        back = pickle.loads(pickle.dumps(batch))
        check((back.results, back.cells, back.grid) == (batch.results, batch.cells, batch.grid),
              "%s: the result survives pickling (to a client of a remote cluster)" % bad)


with tempfile.TemporaryDirectory() as tmpdir:
    test_batches(tmpdir)
    test_local_layout()
    test_progress(tmpdir)
    test_outcome()
    test_batch_fallback(tmpdir)
test_no_such_folder()
test_refusals()
print("RESULT: %d passed, %d failed" % (COUNTS[True], COUNTS[False]))
sys.exit(0 if COUNTS[False] == 0 else 1)
