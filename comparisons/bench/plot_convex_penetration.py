#!/usr/bin/env python3
"""Hull-hull penetration depth: cost against error per backend, from bench_convex_distance's CSV.

python3 plot_convex_penetration.py [comparisons/results/convex_distance.csv] writes convex_penetration.png and .svg
beside the CSV: rows penetration_hull{30,100,300} (64 overlapping pose pairs of two equal hulls), x = nanoseconds per
query (left) and callgrind instructions per query (right), log; y = the max relative depth error against the exact
MTD (long double SAT), log; one colour per backend, one marker per hull size, a line joining a backend's sizes.
An error of 0 is drawn at FLOOR (the dotted line).
"""
import csv
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

BACKENDS = (("gq", "gq computePenetration"), ("gq_distance", "gq distance (signed)"),
            ("libccd_gjk_epa", "libccd ccdGJKPenetration"), ("libccd_mpr", "libccd ccdMPRPenetration"),
            ("bullet64_gjk_epa", "Bullet GJK-EPA (float64)"), ("fcl_libccd_contact", "FCL collide (libccd)"))
SIZES = ((30, "o"), (100, "s"), (300, "^"))
AXES = (("ns", "nanoseconds per query"), ("callgrind_ir_per_query", "instructions per query (callgrind)"))
FLOOR = 1e-16


def read_rows(path):
    """{(backend, hull size): row} of the hull-hull penetration rows that carry an error."""
    with open(path, newline="") as f:
        rows = csv.DictReader(line for line in f if not line.startswith("#"))
        out = {}
        for r in rows:
            m = re.match(r"^penetration_hull(\d+)$", r["benchmark"])
            if m and r.get("max_rel_depth_error"):
                out[(r["backend"], int(m.group(1)))] = r
        return out


def plot(path):
    rows = read_rows(path)
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.8), sharey=True)
    for ax, (column, label) in zip(axes, AXES):
        for i, (backend, name) in enumerate(BACKENDS):
            pts = [(float(rows[(backend, n)][column]), max(float(rows[(backend, n)]["max_rel_depth_error"]), FLOOR),
                    marker) for n, marker in SIZES if (backend, n) in rows and rows[(backend, n)][column]]
            if not pts:
                continue
            ax.plot([p[0] for p in pts], [p[1] for p in pts], color="C%d" % i, linewidth=1, alpha=0.6)
            for x, y, marker in pts:
                ax.scatter([x], [y], marker=marker, color="C%d" % i, s=36, zorder=3)
            ax.plot([], [], color="C%d" % i, label=name)
        ax.axhline(FLOOR, color="grey", linestyle=":", linewidth=1)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel(label)
        ax.grid(True, which="major", alpha=0.3)
    for n, marker in SIZES:
        axes[1].scatter([], [], marker=marker, color="black", label="%d-point hulls" % n)
    axes[0].set_ylabel("max relative depth error (64 pairs)")
    axes[1].legend(fontsize=8, loc="center right")
    axes[0].annotate("error 0 would be drawn here", (0.02, FLOOR), xycoords=("axes fraction", "data"),
                     xytext=(0, 4), textcoords="offset points", fontsize=7, color="grey")
    first = next(iter(rows.values()), {"date": "", "commit": ""})
    fig.suptitle("Hull-hull penetration depth: cost against error against the exact MTD (%s, %s)"
                 % (first["date"], first["commit"]))
    fig.tight_layout()
    stem = os.path.join(os.path.dirname(path), "convex_penetration")
    for ext in ("png", "svg"):
        fig.savefig(stem + "." + ext, dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    plot(sys.argv[1] if len(sys.argv) > 1 else "comparisons/results/convex_distance.csv")
