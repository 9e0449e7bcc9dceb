#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""tools/gen_fleet_logs.py's layout and option bounds, fast: main() run
in-process with a stand-in simulator (a shell script that writes a one-line
log where --log says), so no scenario is simulated:

  - 14 logs with 5 broken: the 9 good ones lie in car-(n mod 8), so car-00
    holds drive-000 and drive-008 and car-07 drive-007 only; broken-000 ..
    broken-004 are garbage, cut, an empty file (it exists, 0 bytes), a
    directory, a dangling link;
  - --broken equal to --count is a usage error (exit 2: a broken log is made
    from a good one), --broken one below it is taken.

prints "RESULT: N passed, M failed"
"""
import contextlib
import io
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks  # noqa: E402
import gen_fleet_logs as G  # noqa: E402

LINE = "(0.000000) vcan0 110#0011223344556677\n"


def stub(tmp):
    path = os.path.join(tmp, "sim.sh")
    with open(path, "w") as f:
        f.write('#!/bin/sh\n# plant --log PATH ...\nprintf "%s" > "$3"\n' % LINE.replace("\n", "\\n"))
    os.chmod(path, 0o755)
    return path


def run(*argv):
    """(exit status or the exception, stdout)."""
    old = sys.argv
    sys.argv = ["gen_fleet_logs.py"] + list(argv)
    out = io.StringIO()
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(io.StringIO()):
            rc = G.main()
    except SystemExit as e:
        rc = e.code
    except Exception as e:  # noqa: BLE001  (a crash is a failed check, shown)
        rc = "%s: %s" % (type(e).__name__, e)
    finally:
        sys.argv = old
    return rc, out.getvalue()


def layout(c, tmp):
    out = os.path.join(tmp, "fleet")
    rc, text = run("--out", out, "--count", "14", "--broken", "5", "--sim", stub(tmp))
    c.check(rc == 0 and text.endswith("gen_fleet_logs: 14 logs (5 broken) in %s\n" % out),
            "14 logs, 5 broken: done (%s, %r)" % (rc, text[-60:]))
    logs = {car: sorted(f for f in os.listdir(os.path.join(out, car)) if f.endswith(".log"))
            for car in sorted(os.listdir(out)) if car.startswith("car-")}
    want = {"car-%02d" % k: ["drive-%03d.log" % k] + (["drive-008.log"] if k == 0 else []) for k in range(8)}
    c.check(logs == want, "drive n in car n mod 8 (%s)" % logs)
    b = [os.path.join(out, "broken-%03d.log" % n) for n in range(5)]
    c.check(os.path.isfile(b[0]) and os.path.getsize(b[0]) == 4096, "broken-000: 4096 bytes of garbage")
    c.check(os.path.isfile(b[1]) and b"garbage" in open(b[1], "rb").read(), "broken-001: cut, with garbage")
    c.check(os.path.isfile(b[2]) and not os.path.islink(b[2]) and os.path.getsize(b[2]) == 0,
            "broken-002: an empty file (%s)" % os.path.exists(b[2]))
    c.check(os.path.isdir(b[3]), "broken-003: a directory")
    c.check(os.path.islink(b[4]) and not os.path.exists(b[4]), "broken-004: a dangling link")


def bounds(c, tmp):
    sim = stub(tmp)
    rc, _ = run("--out", os.path.join(tmp, "all"), "--count", "3", "--broken", "3", "--sim", sim)
    c.check(rc == 2, "--count 3 --broken 3: a usage error, exit 2 (%s)" % rc)
    rc, text = run("--out", os.path.join(tmp, "one"), "--count", "3", "--broken", "2", "--sim", sim)
    c.check(rc == 0 and "3 logs (2 broken)" in text, "--count 3 --broken 2: done (%s)" % rc)


if __name__ == "__main__":
    sys.exit(Checks.run(layout, bounds))
