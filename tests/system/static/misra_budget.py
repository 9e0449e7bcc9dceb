#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""The "Count" column of docs/misra-deviations.md as an enforced budget.

  misra_budget.py check DEVIATIONS FINDINGS...   one PASS/FAIL line per
      deviation row: the findings of that row (its rule or check id in one of
      its file globs, both numeric builds, each file:line:id once, no
      deviation applied) must not exceed the first number of its Count cell.
  misra_budget.py suppressions DEVIATIONS  the table as cppcheck
      suppressions "id:glob", one per glob of every row.
  misra_budget.py counts DEVIATIONS FINDINGS...  the rows of the Deviations
      table with today's counts in the Count cell, ready to paste over the
      table (the "Where and why" cells unchanged).

FINDINGS: cppcheck output lines "file:line:id:severity:message". A finding
belongs to the first row whose id and glob match it (cppcheck's suppression
globs: * and ? also match '/'). Rule rows "2.5" mean id misra-c2012-2.5.
"""
import fnmatch
import re
import sys

FINDING = re.compile(r"^([^:]+):(\d+):([A-Za-z0-9_.-]+):")


def parse_table(path):
    """Rows of the table under '## Deviations': (line, cells, id, globs, budget)."""
    rows = []
    in_dev = False
    with open(path, encoding="utf-8") as f:
        for line in f:
            line = line.rstrip("\n")
            if line.startswith("## "):
                in_dev = line.startswith("## Deviations")
                continue
            if not in_dev or not line.startswith("|"):
                continue
            cells = line.split("|")[1:-1]
            if len(cells) < 4:
                continue
            rule = cells[0].strip()
            if re.fullmatch(r"[0-9]+\.[0-9]+", rule):
                rid = "misra-c2012-" + rule
            elif re.fullmatch(r"[A-Za-z][A-Za-z0-9_]*", rule) and rule != "Rule":
                rid = rule
            else:
                continue
            globs = re.findall(r"`([^`]+)`", cells[1])
            m = re.match(r"\s*(\d+)", cells[2])
            budget = int(m.group(1)) if m else None
            rows.append((line, cells, rid, globs, budget))
    return rows


def read_findings(paths):
    seen = set()
    for p in paths:
        with open(p, encoding="utf-8", errors="replace") as f:
            for line in f:
                m = FINDING.match(line)
                if m:
                    seen.add((m.group(1), int(m.group(2)), m.group(3)))
    return sorted(seen)


def area(path):
    parts = path.split("/")
    return "/".join(parts[:2]) if len(parts) > 2 else path


def assign(rows, findings):
    """Per row index: the list of its findings."""
    per_row = [[] for _ in rows]
    for fil, ln, fid in findings:
        for i, (_, _, rid, globs, _) in enumerate(rows):
            if rid == fid and any(fnmatch.fnmatchcase(fil, g) for g in globs):
                per_row[i].append((fil, ln, fid))
                break
    return per_row


def count_cell(found, old_cell):
    n = len(found)
    if n == 0 and "hidden behind" in old_cell:
        return old_cell.strip()  # seen only once the rule it hides behind is deviated
    areas = {}
    for fil, _, _ in found:
        areas[area(fil)] = areas.get(area(fil), 0) + 1
    detail = ", ".join("%s %d" % (a, areas[a]) for a in sorted(areas))
    return "%d (%s)" % (n, detail) if detail else "0"


def main(argv):
    if len(argv) < 3 or argv[1] not in ("check", "counts", "suppressions"):
        print(__doc__)
        return 2
    rows = parse_table(argv[2])
    if argv[1] == "suppressions":
        for _, _, rid, globs, _ in rows:
            for g in globs:
                print("%s:%s" % (rid, g))
        return 0 if rows else 1
    per_row = assign(rows, read_findings(argv[3:]))
    if not rows:
        print("FAIL deviation table: no rows found in %s" % argv[2])
        return 1
    if argv[1] == "counts":
        print("Deviations table with today's counts (%s rows): paste over the table rows" % len(rows))
        for (line, cells, _, _, _), found in zip(rows, per_row):
            new = list(cells)
            new[2] = " " + count_cell(found, cells[2]) + " "
            print("|" + "|".join(new) + "|")
        return 0
    bad = 0
    for (line, cells, rid, globs, budget), found in zip(rows, per_row):
        name = "%s in %s" % (cells[0].strip(), " ".join(globs))
        if budget is None:
            print("FAIL deviation %s: no number in its Count cell" % name)
            bad += 1
        elif len(found) > budget:
            print("FAIL deviation %s: %d findings, budget %d (Count in %s)"
                  % (name, len(found), budget, argv[2]))
            for fil, ln, _ in found[:40]:
                print("    %s:%d" % (fil, ln))
            bad += 1
        else:
            print("PASS deviation %s: %d findings, budget %d" % (name, len(found), budget))
    print("BUDGETS: %d rows, %d over budget" % (len(rows), bad))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
