#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""make bench: fleet analysis speed (tools/fleet.py) on real-length
drives: 200 logs (5 broken), each good one a random drive of 10 minutes
(tools/gen_fleet_logs.py --minutes 10: 120,000 frames, about 4.5 MB), on a
LocalCluster of 1 and of 2 workers (tests/tools/bench_fleet.py's
figures, BENCH_FLEET_RUNS pairs, default 3 here). The logs take about
0.9 GB in build/fleet-bench-long/."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
os.environ.setdefault("BENCH_FLEET_RUNS", "3")
import bench_fleet  # noqa: E402

if __name__ == "__main__":
    bench_fleet.main("fleet-bench-long", ("--minutes", "10"),
                     "200 logs of 10 minutes (5 broken)", cluster=False)
