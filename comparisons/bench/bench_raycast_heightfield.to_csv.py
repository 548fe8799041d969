#!/usr/bin/env python3
"""bench_raycast_heightfield JSON runs -> raycast_heightfield.csv.

Usage: bench_raycast_heightfield.to_csv.py <run1.json> [<run2.json> ...] [--out CSV] [--machine TEXT] [--note TEXT]
Each run: bench_raycast_heightfield --benchmark_repetitions=3 --benchmark_enable_random_interleaving=true
--benchmark_report_aggregates_only=true --benchmark_out=runK.json. One row per backend and ray set: the median over
the runs of each run's median CPU time per ray, hits per ray, the exactness counters (gq checked against the
long-double reference before timing; Bullet's disagreements with it counted) and gq's speed against Bullet's faster
variant (Bullet's time / gq's), with the run's date, machine and commit.
"""
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import results_csv  # noqa: E402

HEADER = ["date", "machine", "commit", "rays", "backend", "ns_per_ray", "hits_per_ray", "reference_hits_per_ray",
          "ambiguous_double", "ambiguous_float", "bullet_mismatches", "speed_vs_best_bullet", "note"]
COMMENTS = ["# 512 x 512 heightfield (unit cells, heights spanning ~24), 4096 seeded rays a set, closest hit, both faces;"
            " gq through prepared shapes, Bullet 3.24 float btHeightfieldTerrainShape::performRaycast (plain and"
            " buildAccelerator). gq must match a long-double reference on every ray not within 1e-9 (double) or 1e-4"
            " (float) of a triangle edge (the bench stops otherwise)."]


def main():
    args = results_csv.script_args("raycast_heightfield.csv", note=True, doc=__doc__)
    samples = results_csv.median_aggregates(args.runs, key=lambda name: name[:-len("_median")])
    med = {}
    for name, runs in samples.items():
        unit = results_csv.TO_MS[runs[0].get("time_unit", "ns")] * 1e6  # -> ns
        backend, rays = name.split("/")
        med[(rays, backend)] = (statistics.median(r["cpu_time"] * unit for r in runs), runs[-1])
    cols = results_csv.run_columns(args.machine)
    rows = []
    for (rays, backend), (ns, b) in sorted(med.items()):
        bullet = [med[(rays, k)][0] for k in ("bullet", "bullet_accelerated") if (rays, k) in med]
        speed = "%.2f" % (min(bullet) / ns) if bullet and backend.startswith("gq") else ""
        rows.append(dict(cols, rays=rays, backend=backend, ns_per_ray="%.1f" % (ns / 4096.0),
                         hits_per_ray="%.4f" % b["hits_per_ray"],
                         reference_hits_per_ray="%.4f" % b["reference_hits_per_ray"],
                         ambiguous_double=int(b["ambiguous_double"]), ambiguous_float=int(b["ambiguous_float"]),
                         bullet_mismatches=int(b["bullet_mismatches"]), speed_vs_best_bullet=speed, note=args.note))
    results_csv.write_runs(args.out, HEADER, rows, args.runs, comments=COMMENTS)


if __name__ == "__main__":
    main()
