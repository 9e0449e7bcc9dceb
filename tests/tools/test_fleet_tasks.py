#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""tools/fleet.py's tasks and progress, without Dask:
  - batches(): every log in exactly one task; about 8 tasks per worker of
    about equal bytes; a log larger than a task's share is a task alone;
    small logs share tasks; one worker or many, none empty;
  - Progress: nothing written when the stream is not a terminal; on a
    terminal (a pty) "fleet: D/T logs, S s left" after each task, and the
    line cleared at the end;
  - `fleet.py --dir nosuch`: one line "fleet: nosuch: no such folder" on
    stderr, exit 1.
Prints "RESULT: N passed, M failed"."""
import io
import os
import pty
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "tools"))
import fleet  # noqa: E402

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
    total = 150 * 1000 + 200000
    for workers in (1, 2, 4):
        tasks = fleet.batches(logs, workers)
        flat = [x for t in tasks for x in t]
        check(sorted(flat) == sorted(logs) and len(flat) == len(logs),
              "%d workers: every log in exactly one task" % workers)
        check(all(tasks), "%d workers: no empty task" % workers)
        share = total / (workers * fleet.TASKS_PER_WORKER)
        check([big] in tasks, "%d workers: the large log is a task alone" % workers)
        sizes = [sum(os.path.getsize(x) for x in t) for t in tasks if t != [big]]
        check(all(s <= share + 1000 for s in sizes),
              "%d workers: no task of small logs beyond its share %.0f (%r)" % (workers, share, sizes))
        check(len(tasks) <= workers * fleet.TASKS_PER_WORKER + 1,
              "%d workers: about %d tasks per worker (%d)" % (workers, fleet.TASKS_PER_WORKER, len(tasks)))
        check(max(len(t) for t in tasks) > 1, "%d workers: small logs share a task" % workers)
    missing = os.path.join(tmp, "missing.log")
    tasks = fleet.batches([missing], 2)
    check(tasks == [[missing]], "a log that is not there is still a task (its replay reports it)")


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


with tempfile.TemporaryDirectory() as tmpdir:
    test_batches(tmpdir)
    test_progress(tmpdir)
test_no_such_folder()
print("RESULT: %d passed, %d failed" % (COUNTS[True], COUNTS[False]))
sys.exit(0 if COUNTS[False] == 0 else 1)
