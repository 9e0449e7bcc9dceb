# SPDX-License-Identifier: MIT
# Drives: fleet analysis on Dask and the live view.
#   tools/fleet.py            replay --summary-json over many logs (Dask)
#   tools/gen_fleet_logs.py   a generated test fleet, a few logs broken
#   tools/live_view.py        the operating point live over the map
#   tests/tools/test_fleet.py 16 logs, LocalCluster + a separate cluster
#   tests/tools/bench_fleet.py  make bench: logs/s on 1, 2 workers, cluster
#   tests/tools/test_fleet_corners.py  both tools on a two-corner vehicle calibration
tests/tools/test_fleet.py: build/host/squeal-sim
TEST_PROGS += tests/tools/test_fleet.py
tests/tools/bench_fleet.py: build/host/squeal-sim
BENCH_PROGS += tests/tools/bench_fleet.py
tests/tools/test_live_view.py: build/host/squeal-sim
TEST_PROGS += tests/tools/test_live_view.py
tests/tools/test_fleet_corners.py: build/host/squeal-sim
TEST_PROGS += tests/tools/test_fleet_corners.py

# One command: a generated fleet of 110 logs (6 broken) and its report
# (build/fleet-report/index.html).
.PHONY: fleet-report
fleet-report: build/host/squeal-sim
	@rm -rf build/fleet
	@$(PYTHON) tools/gen_fleet_logs.py --out build/fleet --count 110 --broken 6
	@$(PYTHON) tools/fleet.py --dir build/fleet -o build/fleet-report

# make bench: the fleet on 200 real-length drives (10 minutes each), 1 and
# 2 workers (under a minute; 0.9 GB of logs, generated in seconds the
# first time)
tests/tools/bench_fleet_long.py: build/host/squeal-sim
BENCH_PROGS += tests/tools/bench_fleet_long.py

# fleet.py's tasks sized by work, the progress line, --dir nosuch (no Dask)
TEST_PROGS += tests/tools/test_fleet_tasks.py
