#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""tools/live_view.py's reading of the monitor's frames (LiveView.on_frame,
no drawing), on frames packed here by hand from firmware/protocol/squeal.dbc's
layout (Intel bit order):

  SquealStatus 0x300: SquealState bits 12..15, WarningLevel 16..19,
      HopfMargin_mps 40..55 (signed, 0.01 m/s);
  SquealDetail 0x301: V0_mps bits 12..25 (0.01 m/s);
  SquealDetail2 0x303: Force_N bits 16..31 (0.5 N).

  - SquealState 0..3 are stable, bistable, unstable, not_sliding; 4 and 15
    are shown as fault;
  - a speed before any force draws no trail point (the point needs both);
    the first force adds the point (v0, force, state);
  - the default window is 10 s: a report 9.9 s old is kept, one 10.5 s old
    is dropped.

prints "RESULT: N passed, M failed"
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks  # noqa: E402
import live_view  # noqa: E402


def status(state, warning=0, margin_cmps=150):
    d = bytearray(8)
    d[1] = (state & 0xF) << 4
    d[2] = warning & 0xF
    raw = margin_cmps & 0xFFFF
    d[5], d[6] = raw & 0xFF, raw >> 8
    return bytes(d)


def detail(v0_cmps):
    d = bytearray(8)
    d[1] = (v0_cmps & 0xF) << 4
    d[2] = (v0_cmps >> 4) & 0xFF
    d[3] = (v0_cmps >> 12) & 0x3
    return bytes(d)


def detail2(force_half_n):
    d = bytearray(8)
    d[2], d[3] = force_half_n & 0xFF, force_half_n >> 8
    return bytes(d)


def states(c, tmp):
    view = live_view.LiveView({})
    for raw, want in ((0, "stable"), (1, "bistable"), (2, "unstable"), (3, "not_sliding"), (4, "fault"),
                      (15, "fault"), (3, "not_sliding")):
        view.on_frame(1.0, 0x300, status(raw, 2))
        got = view.corners["FL"].state
        c.check(got == want, "SquealState %d: %s (%s)" % (raw, want, got))
    fl = view.corners["FL"]
    c.check(fl.warning == 2 and abs(fl.margin - 1.5) < 1e-9, "warning 2, Hopf margin 1.50 m/s (%s, %s)"
            % (fl.warning, fl.margin))


def trail(c, tmp):
    view = live_view.LiveView({})
    view.on_frame(0.0, 0x300, status(1))
    view.on_frame(0.01, 0x301, detail(500))
    fl = view.corners["FL"]
    c.check(abs(fl.v0 - 5.0) < 1e-9 and fl.force is None and len(fl.trail) == 0,
            "v0 5.00 m/s before any force: no trail point (%s)" % list(fl.trail))
    view.on_frame(0.02, 0x303, detail2(6000))
    c.check(len(fl.trail) == 1 and fl.trail[0][0] == 0.02 and abs(fl.trail[0][1] - 5.0) < 1e-9
            and abs(fl.trail[0][2] - 3000.0) < 1e-9 and fl.trail[0][3] == "bistable",
            "then force 3000 N: one point (0.02 s, 5 m/s, 3000 N, bistable) (%s)" % list(fl.trail))


def window(c, tmp):
    view = live_view.LiveView({})
    c.check(view.window_s == 10.0, "default window 10 s (%s)" % view.window_s)
    view.on_frame(0.0, 0x300, status(0))
    view.on_frame(9.9, 0x300, status(0))
    fl = view.corners["FL"]
    c.check([h[0] for h in fl.hist] == [0.0, 9.9], "at 9.9 s the report at 0 s is kept (%s)" % list(fl.hist))
    view.on_frame(10.5, 0x300, status(0))
    c.check([h[0] for h in fl.hist] == [9.9, 10.5], "at 10.5 s it is dropped (%s)" % list(fl.hist))


if __name__ == "__main__":
    sys.exit(Checks.run(states, trail, window))
