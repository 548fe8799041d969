#!/usr/bin/env python3
"""Certified error bound against query cost for every fit representation, from bench_fit's CSV.

python3 plot_fit.py [comparisons/results/fit.csv] writes fit.png and fit.svg beside the CSV: one panel per query
(overlap and distance of a moving sphere and a moving box), x = the query's time against the fit over the same
query against the mesh (log), y = the certified bound relative to the mesh size (log); one colour and marker per
representation, one point per mesh or robot link. The mesh itself (bound 0, time 1) is the dashed line x = 1.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

QUERIES = (("overlap_sphere_vs_mesh", "overlap, sphere"), ("distance_sphere_vs_mesh", "distance, sphere"),
           ("overlap_box_vs_mesh", "overlap, box"), ("distance_box_vs_mesh", "distance, box"))
MARKERS = {"sphere": "o", "capsule": "D", "box": "s", "cylinder": "^", "simplified-hull": "v", "hull": "P",
           "decomposition": "*"}


def read_rows(path):
    with open(path, newline="") as f:
        return [r for r in csv.DictReader(f) if r["representation"] != "mesh"]


def plot(path):
    rows = read_rows(path)
    representations = [r for r in MARKERS if any(row["representation"] == r for row in rows)]
    fig, axes = plt.subplots(2, 2, figsize=(10, 7.5), sharey=True)
    for ax, (column, title) in zip(axes.flat, QUERIES):
        for i, rep in enumerate(representations):
            sel = [r for r in rows if r["representation"] == rep and float(r[column]) > 0]
            ax.scatter([float(r[column]) for r in sel], [max(float(r["error_bound_rel"]), 1e-9) for r in sel],
                       marker=MARKERS[rep], color="C%d" % i, s=28, alpha=0.8, label=rep)
        ax.axvline(1.0, color="grey", linestyle="--", linewidth=1)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_title(title)
        ax.set_xlabel("query time against the fit / against the mesh")
        ax.grid(True, which="major", alpha=0.3)
    for ax in axes[:, 0]:
        ax.set_ylabel("certified bound / mesh size")
    axes[0, 0].legend(fontsize=8, loc="lower left")
    first = rows[0] if rows else {"date": "", "commit": ""}
    fig.suptitle("fitShape: certified bound against query cost, every mesh and robot link (%s, %s)"
                 % (first["date"], first["commit"]))
    fig.tight_layout()
    stem = os.path.splitext(path)[0]
    for ext in ("png", "svg"):
        fig.savefig(stem + "." + ext, dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    plot(sys.argv[1] if len(sys.argv) > 1 else "comparisons/results/fit.csv")
