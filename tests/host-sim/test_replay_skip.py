#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""squeal-sim replay skips the ticks that change nothing
(host-sim/cmd_replay.c, squeal_app_next_event_us() in firmware/app): its
output must be the bytes of 1 ms stepping (--step-every-ms), both numeric
builds, on every log of tests/support/replay_logs.py (every scenario, the
sender's faults, holes, gaps, off-grid times, vehicle layouts and a
vehicle bus).
For each: stdout (the ECU's frames), stderr (notes and summary), the exit
status and --summary-json are the same with and without skipping.
Prints "RESULT: N passed, M failed". Run from the repository root.
"""
import os
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "support"))
from sim_cli import Results, run  # noqa: E402
from replay_logs import logs  # noqa: E402

result = Results()


def check_build(build, sim):
    with tempfile.TemporaryDirectory() as tmp:
        for name, path, opts in logs(sim, tmp, result):
            outs = []
            for mode in ([], ["--step-every-ms"]):
                js = os.path.join(tmp, "summary%d.json" % len(outs))
                rc, out, err = run([sim, "replay", path, "--summary-json", js] + opts + mode)
                with open(js) as f:
                    outs.append((rc, out, err, f.read()))
            skip, step = outs
            result(step[0] == 0 and step[1].count("\n") > 10,
                   "%s %s: stepping replays (rc %d, %d frames)" % (build, name, step[0], step[1].count("\n")))
            for i, what in enumerate(("exit status", "stdout", "stderr", "summary JSON")):
                result(skip[i] == step[i], "%s %s: the %s is the same with skipping" % (build, name, what))


result.each_build(check_build)
sys.exit(result.finish())
