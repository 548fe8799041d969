#!/usr/bin/env python3
"""bench_raycast_mesh's Google Benchmark JSON (one file per run) -> comparisons/results/raycast_mesh.csv.

Benchmark names: <query>_<backend>/<mesh>/d<distance> (query closest, any or all) and build_<backend>/<mesh>.
ns_per_ray is the median over the given runs (files) of the CPU time per ray (a shared machine's wall clock
includes time waiting for other processes); the runs alternate gq and its peers within each mesh and distance.
ratio_vs_embree = Embree ns / backend ns for the same query, mesh and distance, from the medians: speed relative to
Embree (1.0 = as fast); ratio_vs_bullet likewise against Bullet (bunny at 4 units only). Build rows: ns_per_ray holds
the BVH build CPU time in us, the benchmark name carries the bytes per triangle. Every row carries the date, machine
and commit.
Usage: raycast_mesh_to_csv.py run1.json [run2.json ...] [--out results.csv] [--append] [--machine TEXT]
"""
import argparse
import json
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import results_csv  # noqa: E402

RAYS = 100000
HEADER = ["date", "machine", "commit", "mesh", "origin_distance", "benchmark", "backend", "ns_per_ray",
          "ratio_vs_embree", "ratio_vs_bullet", "runs"]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("json", nargs="+")
    ap.add_argument("--out", default=os.path.join(results_csv.RESULTS, "raycast_mesh.csv"))
    ap.add_argument("--append", action="store_true")
    ap.add_argument("--machine")
    a = ap.parse_args()
    values, extra, order = {}, {}, []
    for path in a.json:
        with open(path) as f:
            data = json.load(f)
        for b in data["benchmarks"]:
            if b.get("run_type") == "aggregate":
                continue
            parts = b.get("run_name", b["name"]).split("/")
            query, backend = parts[0].split("_", 1)
            mesh = parts[1]
            dist = parts[2][1:] if len(parts) > 2 else ""
            cpu_ns = b["cpu_time"] * {"ns": 1, "us": 1e3, "ms": 1e6, "s": 1e9}[b["time_unit"]]
            key = (mesh, dist, query, backend)
            if key not in values:
                order.append(key)
            values.setdefault(key, []).append(cpu_ns / 1e3 if query == "build" else cpu_ns / RAYS)
            if "bytes_per_triangle" in b:
                extra[key] = "%.1f bytes/triangle" % b["bytes_per_triangle"]
    med = {k: statistics.median(v) for k, v in values.items()}
    run = results_csv.run_columns(a.machine)
    out = []
    for key in order:
        mesh, dist, query, backend = key

        def ratio(ref):
            r = med.get((mesh, dist, query, ref))
            return "%.3f" % (r / med[key]) if r else ""
        name = "bvh_build_us (%s)" % extra.get(key, backend) if query == "build" else query
        out.append(dict(run, mesh=mesh, origin_distance=dist, benchmark=name, backend=backend,
                        ns_per_ray=("%.0f" if query == "build" else "%.1f") % med[key],
                        ratio_vs_embree=ratio("embree"), ratio_vs_bullet=ratio("bullet"), runs=len(values[key])))
    results_csv.write(a.out, HEADER, out, append=a.append)
    print("%d rows -> %s" % (len(out), a.out))


if __name__ == "__main__":
    main()
