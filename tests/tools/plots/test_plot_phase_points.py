#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""tools/plots/plot_phase.py's operating points, fast: a stand-in simulator
(a shell script here that logs its arguments and prints a few rows in the
`simulate` CSV form) instead of oscsim, and nothing rendered:

  - steady_x(v0) = N mu(v0) / (m w0^2), mu(v0) = mu_inf + dmu e^(-a v0): for
    the paper's brake (N 9 kN, mu_inf 0.25, dmu 0.15, a 2 s/m, w0 5000 rad/s)
    at 1.0 m/s 9.7308e-5 m, at 2.5 m/s 9.0364e-5 m (oscsim's x_s too);
  - a trajectory is the "sample" rows, the "switch" rows (the instants the
    mode changes) left out;
  - the bistable panel starts at 0.8 and 1.2 times the cycle's amplitude
    r / (2 x 5000): with r = 0.5 from `--truth`, --dx 4e-05 and 6e-05.

prints "RESULT: N passed, M failed"
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from figures import Checks, draw  # noqa: E402
import plot_phase as PH  # noqa: E402

STUB = r"""#!/bin/sh
echo "$*" >> "%s"
case "$*" in
  *--truth*) echo "truth=bistable ln_q=-0.156 s=3 cycle_x=2.0 r=0.5 amplitude_m=5e-05" ;;
  *--cycle*) printf 'kind,t_s,x_m,v_mps,mode\ncycle,0,1e-05,0,slip\ncycle,1e-05,0,0.1,slip\n' ;;
  *) printf 'kind,t_s,x_m,v_mps,mode\nsample,0,1e-05,0,slip\nswitch,5e-06,2e-05,1.0,stick\n'
     printf 'sample,1e-05,2e-05,1.0,stick\nsample,0.03,1.5e-05,0.5,slip\n' ;;
esac
"""


def stub(tmp):
    path, log = os.path.join(tmp, "sim.sh"), os.path.join(tmp, "calls.txt")
    with open(path, "w") as f:
        f.write(STUB % log)
    os.chmod(path, 0o755)
    return path, log


def steady(c, tmp):
    for v0, want in ((1.0, 9000.0 * (0.25 + 0.15 * math.exp(-2.0)) / 5000.0 ** 2),
                     (2.5, 9000.0 * (0.25 + 0.15 * math.exp(-5.0)) / 5000.0 ** 2)):
        got = float(PH.steady_x(v0))
        c.check(abs(got - want) < 1e-15 and abs(want - {1.0: 9.7308e-5, 2.5: 9.0364e-5}[v0]) < 1e-9,
                "steady sliding at %g m/s: x_s = %.4e m (%.4e)" % (v0, want, got))


def trajectory(c, tmp):
    sim, _ = stub(tmp)
    t, x, v, stick = PH.trajectory(sim, ["--v0", "1.0"])
    c.check(list(t) == [0.0, 1e-05, 0.03] and list(x) == [1e-05, 2e-05, 1.5e-05]
            and list(v) == [0.0, 1.0, 0.5] and list(stick) == [False, True, False],
            "the sample rows only, the switch row left out (t %s, stick %s)" % (list(t), list(stick)))


def bistable_starts(c, tmp):
    sim, log = stub(tmp)
    rc, _, saved = draw("plot_phase", ["--sim", sim, "--out", tmp], write=False)
    calls = open(log).read().splitlines() if os.path.exists(log) else []
    dx = [float(a.split()[a.split().index("--dx") + 1]) for a in calls
          if "--v0 1.5" in a and "--dx" in a]
    c.check(rc in (None, 0) and len(saved) == 1 and len(dx) == 2
            and abs(dx[0] - 4e-5) < 1e-18 and abs(dx[1] - 6e-5) < 1e-18,
            "bistable panel from 0.8 and 1.2 x 0.5 / 10000 m: --dx %s" % dx)


if __name__ == "__main__":
    sys.exit(Checks.run(steady, trajectory, bistable_starts))
