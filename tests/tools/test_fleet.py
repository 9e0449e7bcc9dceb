#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""tools/fleet.py end to end, in bounded time: 16 generated logs (5 broken
in every way gen_fleet_logs.py knows) on a LocalCluster of 2 workers,
then the same job once on a separately started `dask scheduler`
+ `dask worker` on 127.0.0.1 (the cluster path). Checked independently:

  - every broken log is listed with its reason, and the run goes on;
  - time per state per log equals replay's text summary of that log (run
    here, without Dask), the ALL rows are the sums, and each log has
    state changes + 1 episodes (the generated logs have one corner, FL);
  - the heat map: cells.csv's time is within each corner's total and each
    cell's is the sum of the logs' own cells (each log's --summary-json), the PNG
    has pixels in the reported-state colours of the states the fleet spent
    time in, the SVG draws both border lines; the HTML page shows it all;
  - the cluster path gives the same CSVs as the LocalCluster;
  - two corners (FL and an RR copied from it by a wrapper around squeal-sim,
    so the aggregation is checked on identical corners; a real two-corner
    vehicle calibration is tests/tools/test_fleet_corners.py): RR rows equal
    FL rows, and the heat map gets a panel per corner.
Prints "RESULT: N passed, M failed, K skipped".
"""
import csv
import json
import os
import re
import subprocess
import sys
import tempfile
# tests/ of this checkout, and the folders its helper modules live in
_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, d) for d in ("support", os.path.join("support", "reference"), "host-sim", "tools")]

ROOT = os.path.dirname(_TESTS)
import dbc_common  # noqa: E402
PY = "/usr/bin/python3"
SIM = os.path.join(ROOT, "build", "host", "squeal-sim")
STATES = ("stable", "bistable", "unstable", "not_sliding", "fault")
COLOURS = {"stable": "#1a9850", "bistable": "#d98e04", "unstable": "#b2182b"}


class Results(dbc_common.Results):
    """The protocol tests' counter, with skips."""
    skipped = 0

    def skip(self, what, why):
        self.skipped += 1
        print("SKIP: %s (%s)" % (what, why))

    def finish(self):
        print("RESULT: %d passed, %d failed, %d skipped" % (self.passed, self.failed, self.skipped))
        sys.exit(1 if self.failed else 0)


R = Results()


def fleet(logdir, out, *extra):
    p = subprocess.run([PY, os.path.join(ROOT, "tools", "fleet.py"), "--dir", logdir, "-o", out] +
                       list(extra), stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=300)
    print(p.stdout.decode()[-3000:])
    return p.returncode


def rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def text_state_times(log):
    p = subprocess.run([SIM, "replay", log, "--no-output"], stdout=subprocess.PIPE,
                       stderr=subprocess.PIPE, timeout=60)
    err = p.stderr.decode()
    st = re.search(r"state_time_s\s+(.*)", err).group(1)
    ch = int(re.search(r"state_changes\s+(\d+)", err).group(1))
    return {k: float(v) for k, v in re.findall(r"(\w+)=([\d.]+)", st)}, ch


def ref_cells(logs):
    """{(corner, v0_lo, force_lo, state): seconds} as cells.csv prints them,
    added up here from each log's own --summary-json (one replay per log)."""
    acc, grid = {}, None
    with tempfile.TemporaryDirectory() as tmp:
        doc = os.path.join(tmp, "s.json")
        for log in logs:
            subprocess.run([SIM, "replay", log, "--no-output", "--quiet", "--summary-json", doc],
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=60)
            with open(doc) as f:
                j = json.load(f)
            grid = j["cells_grid"]
            for c in j["corners"]:
                for i, k, state, sec in c["cells"]:
                    key = (c["corner"], i, k, state)
                    acc[key] = acc.get(key, 0.0) + sec
    dv, dn = float(grid["v0_bin_mps"]), float(grid["force_bin_n"])
    return {(c, "%.2f" % (i * dv), "%g" % (k * dn), s): "%.6f" % sec
            for (c, i, k, s), sec in acc.items()}


def check_report(logdir, out):
    probs = {r["log"]: r for r in rows(os.path.join(out, "problems.csv"))}
    broken = sorted(os.path.join(logdir, f) for f in os.listdir(logdir) if f.startswith("broken-"))
    R.check(sorted(probs) == broken and all(r["reason"] for r in probs.values()),
            "all %d broken logs listed with a reason: %s" % (len(broken),
                                                            [(os.path.basename(k), v["status"], v["reason"][:50])
                                                             for k, v in sorted(probs.items())]))
    st = rows(os.path.join(out, "state_time.csv"))
    eps = rows(os.path.join(out, "episodes.csv"))
    per_log = [r for r in st if r["log"] != "ALL"]
    good = [r["log"] for r in per_log if r["log"] not in probs]
    R.check(len(good) == 11, "11 good logs in state_time.csv (got %d)" % len(good))
    bad_time = bad_eps = 0
    for r in per_log:
        ref, changes = text_state_times(r["log"])
        if any(abs(float(r[s + "_s"]) - ref[s]) > 1e-9 for s in STATES):
            bad_time += 1
            print("  state times differ:", r, ref)
        if sum(e["log"] == r["log"] for e in eps) != changes + 1:
            bad_eps += 1
    R.check(bad_time == 0, "time per state of every log equals replay's text summary")
    R.check(bad_eps == 0, "every log has (state changes + 1) episodes")
    all_fl = [r for r in st if r["log"] == "ALL" and r["corner"] == "FL"]
    total = {s: sum(float(r[s + "_s"]) for r in per_log) for s in STATES}
    R.check(len(all_fl) == 1 and all(abs(float(all_fl[0][s + "_s"]) - total[s]) < 1e-6 for s in STATES),
            "ALL,FL row is the sum over the logs")
    cells = rows(os.path.join(out, "cells.csv"))
    cell_t = sum(float(c["time_s"]) for c in cells)
    grand = sum(total.values())
    R.check(0.5 * grand < cell_t <= grand + 1e-6, "cells hold %.1f s of %.1f s" % (cell_t, grand))
    want = ref_cells(sorted({r["log"] for r in per_log}))
    got = {(c["corner"], c["v0_lo_mps"], c["force_lo_n"], c["state"]): c["time_s"] for c in cells}
    R.check(got == want, "cells.csv: each cell's time is the sum of the drawn logs' own cells "
            "(%d cells; replay --summary-json of each log)" % len(want))
    # the picture: pixels in the colours of the reported states
    import matplotlib.image as mpimg
    import numpy as np
    img = mpimg.imread(os.path.join(out, "heatmap.png"))[..., :3]
    for s, col in COLOURS.items():
        if total[s] <= 0:
            continue
        rgb = np.array([int(col[i:i + 2], 16) / 255.0 for i in (1, 3, 5)])
        n = int((np.abs(img - rgb).max(axis=2) < 0.06).sum())
        R.check(n > 50, "heat map has %d pixels in the reported-%s colour" % (n, s))
    svg = open(os.path.join(out, "heatmap.svg")).read()
    R.check("<image" in svg and "#b2182b" in svg and "#2166ac" in svg,
            "SVG: the cells (image) over the Hopf border and the stability limit lines")
    page = open(os.path.join(out, "index.html")).read()
    R.check('src="heatmap.png"' in page and all(os.path.basename(b) in page for b in broken),
            "HTML page shows the heat map and lists the broken logs")


FAKE_SIM = """#!/usr/bin/python3
import json, subprocess, sys
p = subprocess.run([%r] + sys.argv[1:], stdout=subprocess.PIPE, stderr=subprocess.PIPE)
sys.stderr.buffer.write(p.stderr)
for line in p.stdout.decode().splitlines():  # one document per log (--each)
    d = json.loads(line)
    d["episodes"] = d.get("episodes", [])
    d["episodes"] += [dict(e, corner="RR") for e in d["episodes"] if e["corner"] == "FL"]
    d["corners"] = d.get("corners", [])
    d["corners"] += [dict(c, corner="RR") for c in d["corners"] if c["corner"] == "FL"]
    print(json.dumps(d))
sys.exit(p.returncode)
"""


def check_two_corners(tmp, logdir, local):
    import matplotlib.image as mpimg
    fake = os.path.join(tmp, "fake-sim")
    with open(fake, "w") as f:
        f.write(FAKE_SIM % SIM)
    os.chmod(fake, 0o755)
    two = os.path.join(tmp, "two")
    R.check(fleet(logdir, two, "--workers", "1", "--sim", fake) == 0, "two corners: exit 0")
    st = rows(os.path.join(two, "state_time.csv"))
    fl = [{k: v for k, v in r.items() if k != "corner"} for r in st if r["corner"] == "FL"]
    rr = [{k: v for k, v in r.items() if k != "corner"} for r in st if r["corner"] == "RR"]
    R.check(fl == rr and len(fl) == 13, "two corners: %d RR rows equal the FL rows" % len(rr))
    eps = rows(os.path.join(two, "episodes.csv"))
    R.check(sum(e["corner"] == "RR" for e in eps) == sum(e["corner"] == "FL" for e in eps) > 0,
            "two corners: as many RR episodes as FL")
    w1 = mpimg.imread(os.path.join(local, "heatmap.png")).shape[1]
    w2 = mpimg.imread(os.path.join(two, "heatmap.png")).shape[1]
    R.check(w2 > 1.5 * w1, "two corners: heat map %d px wide against %d for one" % (w2, w1))


def main():
    try:
        import dask.distributed  # noqa: F401
    except ImportError as e:
        R.skip("fleet on Dask (LocalCluster and cluster path)", "python3-distributed missing: %s" % e)
        R.finish()
    with tempfile.TemporaryDirectory() as tmp:
        logdir = os.path.join(tmp, "logs")
        subprocess.run([PY, os.path.join(ROOT, "tools", "gen_fleet_logs.py"), "--out", logdir,
                        "--count", "16", "--broken", "5", "--seed", "5"], check=True, timeout=120)
        local = os.path.join(tmp, "local")
        R.check(fleet(logdir, local, "--workers", "2") == 0, "fleet on a LocalCluster: exit 0")
        check_report(logdir, local)
        check_two_corners(tmp, logdir, local)
        import dask_local
        try:
            with dask_local.separate_cluster(tmp, nworkers=1) as address:
                R.check(address.startswith("tcp://127.0.0.1:"), "scheduler on 127.0.0.1: " + address)
                remote = os.path.join(tmp, "remote")
                R.check(fleet(logdir, remote, "--scheduler", address) == 0,
                        "fleet on the separately started cluster: exit 0")
        except RuntimeError as e:
            R.check(False, "separate cluster: %s" % e)
            R.finish()
        for name in ("state_time.csv", "episodes.csv", "cells.csv", "problems.csv"):
            same = open(os.path.join(local, name)).read() == open(os.path.join(remote, name)).read()
            R.check(same, "cluster path: %s equals the LocalCluster's" % name)
    R.finish()


if __name__ == "__main__":
    main()
