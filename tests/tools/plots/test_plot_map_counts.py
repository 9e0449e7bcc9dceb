#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""tools/plots/plot_map.py's count of the points each criterion gets wrong,
fast (nothing rendered: the Figures are read as drawn), on the map CSV of
test_plot_map.py (a 4 x 3 grid of the paper's brake, the exact criterion
wrong at (a 3, v0 1.5) only, the cubic at (2, 2.5), (3, 2.5), (4, 2.5); the
damping variation D = 0.05 with both right everywhere):

  - grid_of lists exactly those points as the disagreements;
  - one disagreement is enough for the legend's entry "exact criterion
    disagrees with simulation" on the large map; the variations' legend,
    with none, has no such entry.

prints "RESULT: N passed, M failed"
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from figures import Checks, draw, legend_texts  # noqa: E402
import test_plot_map as T  # noqa: E402  (its map CSV)
import plot_map  # noqa: E402

BAD = "exact criterion disagrees with simulation"


def counts(c, tmp):
    path = os.path.join(tmp, "map.csv")
    T.write_map(path)
    rows = plot_map.read_map(path)
    _, _, _, _, exact_bad, cubic_bad = plot_map.grid_of(rows["default"])
    c.check(exact_bad == [(3.0, 1.5)], "exact criterion wrong at (3, 1.5) only (%s)" % exact_bad)
    c.check(sorted(cubic_bad) == [(2.0, 2.5), (3.0, 2.5), (4.0, 2.5)],
            "cubic criterion wrong at (2, 2.5), (3, 2.5), (4, 2.5) (%s)" % cubic_bad)
    _, _, _, _, exact_bad, cubic_bad = plot_map.grid_of(rows["d0.05"])
    c.check(exact_bad == [] and cubic_bad == [], "D = 0.05: none wrong (%s %s)" % (exact_bad, cubic_bad))
    rc, _, saved = draw("plot_map", [path, "--out", tmp], write=False)
    big = legend_texts(saved[0][1].legends[0]) if saved and saved[0][1].legends else []
    c.check(rc in (None, 0) and big.count(BAD) == 1 and big[-1] == BAD,
            "one disagreement: the large map's legend names it (%s)" % big[-1:])
    var = legend_texts(saved[1][1].legends[0]) if len(saved) > 1 and saved[1][1].legends else None
    c.check(var is not None and BAD not in var and len(var) == 7,
            "none in the variations: their legend has 7 entries, not that one (%s)" % var)


if __name__ == "__main__":
    sys.exit(Checks.run(counts))
