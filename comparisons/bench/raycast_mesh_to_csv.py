#!/usr/bin/env python3
"""Appends bench_raycast_mesh's Google Benchmark JSON to comparisons/results/raycast_mesh.csv.

ns_per_ray uses CPU time (the shared machine's wall clock includes time waiting for other processes).
ratio_vs_embree = Embree ns / backend ns for the same query: speed relative to Embree (1.0 = as fast, target >= 0.7).
Build rows: ns_per_ray holds the BVH build CPU time per triangle; the benchmark name carries bytes/triangle.
Usage: raycast_mesh_to_csv.py bench.json results.csv
"""
import csv, datetime, json, os, platform, sys

TRIANGLES = 69451
RAYS = 1000000


def machine():
    model = "unknown CPU"
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    model = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    return f"{platform.node()} {model}"


def main(src, dst):
    data = json.load(open(src))
    rows = {}
    for b in data["benchmarks"]:
        _, query, backend = b["name"].split("_", 2)  # BM_<query>_<backend>
        cpu_ns = b["cpu_time"] * {"ns": 1, "us": 1e3, "ms": 1e6, "s": 1e9}[b["time_unit"]]
        per_item = cpu_ns / (TRIANGLES if query == "build" else RAYS)
        name = query
        if query == "build":
            name = f"bvh_build ({b['bytes_per_triangle']:.1f} bytes/triangle)"
        rows[(query, backend)] = (name, per_item)
    date = datetime.date.today().isoformat()
    new = not os.path.exists(dst)
    with open(dst, "a", newline="") as f:
        w = csv.writer(f)
        if new:
            w.writerow(["date", "machine", "benchmark", "backend", "ns_per_ray", "ratio_vs_embree"])
        for (query, backend), (name, ns) in rows.items():
            ref = rows.get((query, "embree"))
            ratio = ref[1] / ns if ref else float("nan")
            w.writerow([date, machine(), name, backend, f"{ns:.1f}", f"{ratio:.3f}"])


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
