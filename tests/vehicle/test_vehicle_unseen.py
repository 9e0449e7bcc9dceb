#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Issue 11's Done-when check: a drive in a layout no other test uses
(tests/vehicle/unseen/), configured only with tools/vehicle_calib.py from its
DBC, replays with the inputs used (no FAULT after start-up); V0_mps and
Force_N follow the vehicle's signals and the states equal the reference at
the converted operating points (e2e_harness.py, same checks as the other
layouts, including the 2.8 s timestamp jump).
Prints "RESULT: N passed, M failed".
"""
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import e2e_harness  # noqa: E402
import vehref  # noqa: E402


def main(argv):
    replay = e2e_harness.fake_replay if "--self-test" in argv else e2e_harness.sim_replay
    r = vehref.Results()
    sims = [None] if "--self-test" in argv else vehref.SIMS
    with tempfile.TemporaryDirectory() as tmp:
        for sim in sims:
            vehref.SIM = sim
            label = "unseen" if sim is None else "unseen (%s)" % os.path.basename(os.path.dirname(sim))
            e2e_harness.run_layout(r, label, vehref.UNSEEN, tmp, replay, seed=11)
    return r.finish()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
