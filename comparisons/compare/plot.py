#!/usr/bin/env python3
"""Speed-vs-error plot per query family from gq-compare's CSVs: python3 plot.py RESULTS_DIR.

Writes RESULTS_DIR/compare_<family>.png and .svg. Each backend is one series: x = median ns per query,
y = median relative error (bar up to the max); float and double are separate markers. Families without a
value (overlap) plot the fraction of wrong booleans instead. Zeros are drawn at the 1e-18 floor of the log axis.
"""
import csv
import glob
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

FLOOR = 1e-18


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def plot_family(path):
    rows = [r for r in read_rows(path) if int(r["answered"]) > 0]
    if not rows:
        return
    family = rows[0]["family"]
    uses_error = any(r["median_rel_error"] for r in rows)
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    backends = sorted({r["backend"] for r in rows})
    for i, backend in enumerate(backends):
        color = "C%d" % i
        for precision, marker in (("double", "o"), ("float", "s")):
            sel = [r for r in rows if r["backend"] == backend and r["precision"] == precision]
            if not sel:
                continue
            r = sel[0]
            x = float(r["median_ns"])
            if uses_error:
                y = max(float(r["median_rel_error"] or 0), FLOOR)
                top = max(float(r["max_rel_error"] or 0), FLOOR)
                ax.errorbar([x], [y], yerr=[[0], [top - y]], fmt=marker, color=color, capsize=3,
                            label="%s %s" % (backend, precision))
            else:
                y = max(int(r["wrong_booleans"]) / int(r["answered"]), FLOOR)
                ax.plot([x], [y], marker, color=color, label="%s %s" % (backend, precision))
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("median ns per query")
    ax.set_ylabel("relative error (median, bar to max)" if uses_error else "fraction of wrong booleans")
    commit = (", " + rows[0]["commit"]) if rows[0].get("commit") else ""
    ax.set_title("%s: speed vs error (%s, %s%s)" % (family, rows[0]["date"], rows[0]["machine"][:40], commit),
                 fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    stem = os.path.splitext(path)[0]
    fig.savefig(stem + ".png", dpi=110)
    fig.savefig(stem + ".svg")
    plt.close(fig)


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: plot.py RESULTS_DIR")
    for path in sorted(glob.glob(os.path.join(sys.argv[1], "compare_*.csv"))):
        plot_family(path)


if __name__ == "__main__":
    main()
