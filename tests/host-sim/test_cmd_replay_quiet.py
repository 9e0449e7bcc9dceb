#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""squeal-sim replay --quiet (host-sim/cmd_replay.c), both numeric builds.

The log is made here: `squeal-sim plant --log` (the stop scenario), with a
line that is not a candump line and a gap of 10 s beyond --max-gap 5, so
that a plain replay writes a note per line on stderr and the ECU's frames on
stdout.
With --quiet:
  - nothing on stdout (no frame lines);
  - no "LOG:LINE: ..." note on stderr, and the summary is the plain run's,
    line for line (the notes are only left out, each still counted: the
    malformed line, the segment and the gap appear in the summary);
  - the exit status is the plain run's (0);
  - with --summary-json - the JSON (alone on stdout) parses and says that
    no frames were written, its counts the same as with --no-output.
Prints "RESULT: N passed, M failed". Run from the repository root.
"""
import json
import os
import re
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                                "support"))
from sim_cli import ROOT, Results, run  # noqa: E402

result = Results()
NOTE = re.compile(r"^\S+:\d+: ")
FRAME = re.compile(r"^\(\d+\.\d{6}\) \S+ [0-9A-F]{3}#[0-9A-F]*$")

def shifted(line, dt_s):
    """A candump -L line with its timestamp moved by dt_s seconds."""
    m = re.match(r"^\((\d+)\.(\d{6})\)(.*)$", line)
    us = int(m.group(1)) * 1000000 + int(m.group(2)) + int(round(dt_s * 1e6))
    return "(%010d.%06d)%s" % (us // 1000000, us % 1000000, m.group(3))


def make_log(sim, path):
    rc, out, err = run([sim, "plant", "--log", "-", "--scenario", "stop", "--quiet"])
    lines = out.splitlines()
    result(rc == 0 and len(lines) > 1000, "plant --log: %d lines, rc %d" % (len(lines), rc))
    a, b = lines[:300], lines[300:]
    text = a + ["this is not a candump line"]
    text += [shifted(l, 10.0) for l in b]           # 10 s later: a gap
    with open(path, "w") as f:
        f.write("\n".join(text) + "\n")


def check_build(build, sim):
    with tempfile.TemporaryDirectory() as tmp:
        log = os.path.join(tmp, "drive.log")
        make_log(sim, log)
        base = [sim, "replay", log, "--max-gap", "5"]
        rc, out, err = run(base)
        notes = [l for l in err.splitlines() if NOTE.match(l)]
        frames = out.splitlines()
        result(rc == 0 and len(frames) > 10 and all(FRAME.match(l) for l in frames),
               "%s: plain replay writes the ECU's frames (%d), rc %d" % (build, len(frames), rc))
        result(len(notes) == 2 and ":301:" in notes[0] and "gap" in notes[1],
               "%s: plain replay notes the bad line and the gap: %r"
               % (build, notes))
        rq, outq, errq = run(base + ["--quiet"])
        result(rq == rc, "%s: --quiet exits as the plain run (%d, %d)" % (build, rq, rc))
        result(outq == "", "%s: --quiet writes no frame lines (%d bytes)" % (build, len(outq)))
        result(not any(NOTE.match(l) for l in errq.splitlines()),
               "%s: --quiet writes no note per line" % build)
        summary = [l for l in err.splitlines() if not NOTE.match(l)]
        result(errq.splitlines() == summary and len(summary) > 10,
               "%s: --quiet's summary is the plain run's (%d lines)" % (build, len(summary)))
        text = "\n".join(summary)
        result(re.search(r"malformed 1\b", text) is not None,
               "%s: the summary counts the bad line" % build)
        result(re.search(r"gaps? skipped\D*1\b|gaps_skipped\D*1\b|skipped gaps?\D*1\b", text)
               is not None, "%s: the summary counts the gap: %r" % (build, text[-800:]))
        rj, outj, errj = run(base + ["--quiet", "--summary-json", "-"])
        rn, outn, errn = run(base + ["--no-output", "--summary-json", "-"])
        try:
            quiet_json = json.loads(outj)
            plain_json = json.loads(outn)
            ok = quiet_json == plain_json
        except ValueError:
            ok = False
        result(rj == 0 and ok, "%s: --quiet --summary-json -: the JSON of --no-output" % build)


def main():
    result.each_build(check_build)
    return result.finish()


if __name__ == "__main__":
    sys.exit(main())
