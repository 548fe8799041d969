#!/usr/bin/env python3
"""bench_raycast_mesh's Google Benchmark JSON -> comparisons/results/raycast_mesh.csv.

ns_per_ray uses CPU time (a shared machine's wall clock includes time waiting for other processes).
ratio_vs_embree = Embree ns / backend ns for the same query: speed relative to Embree (1.0 = as fast);
ratio_vs_bullet likewise against Bullet. Build rows: ns_per_ray holds the BVH build CPU time in us (benchmark
bvh_build_us), the benchmark name carries the bytes per triangle. Every row carries the run's date, machine and
commit.
Usage: raycast_mesh_to_csv.py bench.json [results.csv] [--append] [--machine TEXT]
"""
import argparse
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import results_csv  # noqa: E402

RAYS = 1000000
HEADER = ["date", "machine", "commit", "benchmark", "backend", "ns_per_ray", "ratio_vs_embree", "ratio_vs_bullet"]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("json")
    ap.add_argument("out", nargs="?", default=os.path.join(results_csv.RESULTS, "raycast_mesh.csv"))
    ap.add_argument("--append", action="store_true")
    ap.add_argument("--machine")
    a = ap.parse_args()
    with open(a.json) as f:
        data = json.load(f)
    rows = {}
    for b in data["benchmarks"]:
        if b.get("run_type") == "aggregate" and b.get("aggregate_name") != "median":
            continue
        _, query, backend = b["run_name"].split("_", 2) if "run_name" in b else b["name"].split("_", 2)
        cpu_ns = b["cpu_time"] * {"ns": 1, "us": 1e3, "ms": 1e6, "s": 1e9}[b["time_unit"]]
        if query == "build":
            name = "bvh_build_us (%s)" % ("%.1f bytes/triangle" % b["bytes_per_triangle"]
                                          if "bytes_per_triangle" in b else backend)
            value = cpu_ns / 1e3
        else:
            name, value = query, cpu_ns / RAYS
        rows[(query, backend)] = (name, value)
    run = results_csv.run_columns(a.machine)
    out = []
    for (query, backend), (name, value) in rows.items():
        def ratio(ref):
            r = rows.get((query, ref))
            return "%.3f" % (r[1] / value) if r else ""
        out.append(dict(run, benchmark=name, backend=backend, ns_per_ray="%.1f" % value if query != "build"
                        else "%.0f" % value, ratio_vs_embree=ratio("embree"), ratio_vs_bullet=ratio("bullet")))
    results_csv.write(a.out, HEADER, out, append=a.append)
    print("%d rows -> %s" % (len(out), a.out))


if __name__ == "__main__":
    main()
