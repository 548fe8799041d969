#!/usr/bin/env python3
"""Prints the README's speed-vs-error table from gq-compare's CSVs (comparisons/results/compare_<family>.csv)."""
import csv
import glob
import os
import sys


def fmt(x):
    if x in ("", None):
        return "–"
    v = float(x)
    return "0" if v == 0 else f"{v:.1e}"


def main(results):
    rows = []
    for path in sorted(glob.glob(os.path.join(results, "compare_*.csv"))):
        with open(path, newline="") as f:
            rows += [r for r in csv.DictReader(f) if int(r["answered"]) > 0]
    if not rows:
        sys.exit("no answered rows")
    print(f"Measured {rows[0]['date']} on {rows[0]['machine']} (suites: comparisons/cases/suites; errors relative to "
          "the shape scale; ns = median per query).\n")
    print("| family | backend | precision | answered | wrong booleans | median error | max error | median ns |")
    print("|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['family']} | {r['backend']} | {r['precision']} | {r['answered']}/{r['cases']} | "
              f"{r['wrong_booleans']} | {fmt(r['median_rel_error'])} | {fmt(r['max_rel_error'])} | "
              f"{float(r['median_ns']):.0f} |")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "results"))
