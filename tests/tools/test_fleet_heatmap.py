#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""The fleet report's heat map (tools/fleet.py's plotting functions), drawn
in this process from fixture logs (tools/gen_fleet_logs.py: 6 logs, 2 of
them broken: one that fails, one with malformed lines that is still
drawn) replayed one by one without Dask, and read from the Figure:

  - the totals: each panel's "reported" time is the sum over the drawn logs
    of `squeal-sim replay LOG`'s text summary (state_time_s, parsed here),
    the same number as the HTML table's total; the time in the cells is
    cells.csv's sum; their difference is named as the time without v0 or N;
  - the title counts the drawn logs and the failed ones apart;
  - the colour key (a colour bar of the time per cell, in seconds), the
    legend (the borders, the map's fills and the reported states in words),
    the axes with units; the files: PNG at 150 dpi and the SVG beside it.
Prints "RESULT: N passed, M failed, K skipped".
"""
import glob
import os
import re
import subprocess
import sys
import tempfile
_TESTS = os.path.abspath(__file__).rsplit(os.sep + "tests" + os.sep, 1)[0] + os.sep + "tests"
sys.path[:0] = [os.path.join(_TESTS, d) for d in ("support", os.path.join("support", "reference"), "host-sim", "tools")]

sys.path.insert(0, os.path.join(os.path.dirname(_TESTS), "tools"))
import fleet  # noqa: E402
from test_fleet import PY, ROOT, SIM, Results, text_state_times  # noqa: E402

R = Results()


def replayed(logdir):
    logs = sorted(glob.glob(os.path.join(logdir, "**", "*.log"), recursive=True))
    batch = fleet.replay_batch(logs, SIM, None, 120)
    return batch.results, batch.cells, batch.grid


def main():
    with tempfile.TemporaryDirectory() as tmp:
        logdir = os.path.join(tmp, "logs")
        subprocess.run([PY, os.path.join(ROOT, "tools", "gen_fleet_logs.py"), "--out", logdir,
                        "--count", "6", "--broken", "2", "--seed", "7"], check=True, timeout=120,
                       stdout=subprocess.DEVNULL)
        results, cells, grid = replayed(logdir)
        failed = [r for r in results if r["status"] == "failed"]
        drawn = [r for r in results if r["status"] != "failed"]
        # independent: replay's text summary of each drawn log
        want = sum(sum(text_state_times(r["log"])[0].values()) for r in drawn)
        rep = os.path.join(tmp, "rep")
        os.makedirs(rep)
        totals, _ = fleet.write_csvs(rep, results)
        title = fleet.heat_title(results)
        fig, panels = fleet.heat_figure(cells, grid, fleet.corner_setups(None), title, totals)
        R.check(title.startswith("%d logs drawn (%d failed, not drawn" % (len(drawn), len(failed)))
                and len(failed) >= 1 and len(drawn) + len(failed) == 6 and len(drawn) >= 4,
                "title: %r; failed: %s" % (title, [r["reason"] for r in failed]))
        ax = panels["FL"]
        head = ax.get_title()
        m = re.match(r"FL: ([\d.]+) s reported \(the table's total\); ([\d.]+) s of it in (\d+) cells"
                     r".*\n([\d.]+) s without a reported v0 or N", head)
        R.check(m is not None, "panel title names both totals: %r" % head)
        if m:
            reported, in_cells, _, without = (float(x) for x in m.groups())
            R.check(abs(reported - want) < 0.05,
                    "reported %.1f s = sum of replay's text summaries %.3f s" % (reported, want))
            cell_sum = sum(cells["FL"].values())
            R.check(abs(in_cells - cell_sum) < 0.05 and abs(reported - in_cells - without) < 0.11,
                    "in cells %.1f s (sum %.3f s), without v0/N %.1f s: the difference" %
                    (in_cells, cell_sum, without))
        keys = [a for a in fig.axes if a.get_ylabel().startswith("time in the cell [s]")]
        R.check(len(keys) == 1 and len(keys[0].get_yticks()) >= 2,
                "colour key: a bar of the time per cell in seconds (%d)" % len(keys))
        texts = [t.get_text() for t in ax.get_legend().get_texts()]
        R.check(texts[:2] == ["Hopf border (unstable above)", "exact stability limit (bistable above)"]
                and "map: bistable (squeal possible after a kick)" in texts
                and "cell: reported unstable" in texts
                and "cell: reported not sliding" in texts and not any("_" in t for t in texts),
                "legend: borders, fills, reported states in words (%s)" % texts)
        R.check(ax.get_xlabel().startswith("disc surface speed v0 [m/s]")
                and ax.get_ylabel() == "pad force N [kN]", "axes with units")
        out = os.path.join(tmp, "pic")
        paths = fleet.draw_heatmap(out, cells, grid, fleet.corner_setups(None), title, totals)
        from PIL import Image
        with Image.open(paths[0]) as im:
            dpi = tuple(round(x) for x in im.info.get("dpi", (0, 0)))
        R.check(dpi == (150, 150) and paths[1].endswith("heatmap.svg") and os.path.getsize(paths[1]) > 0,
                "heatmap.png at 150 dpi (%s), heatmap.svg beside it" % (dpi,))
    R.finish()


if __name__ == "__main__":
    main()
