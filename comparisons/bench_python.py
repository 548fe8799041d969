#!/usr/bin/env python3
"""The geomquery package's speed against the C++ calls it wraps, in one run (same machine, same load):

  rays:    1M rays through geomquery.trimesh.RayMeshIntersector.intersects_first (non-unit directions, normalised
           as trimesh does) against gq::raycastBatch on the same unit rays, timed in C++ (face index only, all
           threads); mesh: the Stanford bunny from the shared data folder, else an icosphere.
  overlap: one geomquery.overlap(sphere, pose, box, pose) call against the same gq::overlap in a C++ loop; the
           difference is the Python overhead of a call.

Usage: PYTHONPATH=<build>/python /usr/bin/python3 comparisons/bench_python.py [--csv comparisons/results/python.csv]
Medians of --repeats runs; the CSV gets one row per figure with the date, machine, commit and load average.
"""

import argparse
import os
import statistics
import sys
import time

import numpy as np

import geomquery as gq
import geomquery.trimesh as gtm

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "bench"))
import results_csv  # noqa: E402  (date, machine and commit columns; one current CSV per benchmark)


def load_obj(path):
    vertices, faces = [], []
    with open(path) as f:
        for line in f:
            parts = line.split()
            if parts and parts[0] == "v":
                vertices.append([float(x) for x in parts[1:4]])
            elif parts and parts[0] == "f":
                idx = [int(p.split("/")[0]) - 1 for p in parts[1:]]
                faces += [[idx[0], idx[k], idx[k + 1]] for k in range(1, len(idx) - 1)]
    return np.array(vertices), np.array(faces, dtype=np.int64)


def icosphere(levels):
    sys.path.insert(0, os.path.join(HERE, "..", "tests", "python"))
    from conftest import icosphere as make

    return make(levels)


class Mesh:
    def __init__(self, vertices, faces):
        self.vertices, self.faces = vertices, faces


def bench_rays(n, repeats):
    shared = os.environ.get("GQ_SHARED_DIR") or os.path.join(HERE, "..", "..", "shared")
    bunny = os.path.join(shared, "meshes", "stanford-bunny.obj")
    name, (v, f) = ("stanford-bunny", load_obj(bunny)) if os.path.exists(bunny) else ("icosphere-5", icosphere(5))
    mesh = Mesh(v, f)
    rng = np.random.default_rng(1)
    lo, hi = v.min(axis=0), v.max(axis=0)
    origins = rng.uniform(lo - (hi - lo) * 0.25, hi + (hi - lo) * 0.25, (n, 3))
    dirs = rng.normal(size=(n, 3)) * 2.5
    unit = dirs / np.linalg.norm(dirs, axis=1)[:, None]
    ray = gtm.RayMeshIntersector(mesh)
    first = ray.intersects_first(origins[:10], dirs[:10])  # cooks the mesh once
    cooked = gtm.cooked_mesh(mesh).mesh
    py_times, cpp_times = [], []
    for _ in range(repeats):  # alternate, so both see the same load
        t0 = time.perf_counter()
        first = ray.intersects_first(origins, dirs)
        py_times.append(time.perf_counter() - t0)
        cpp_times.append(gq._geomquery._time_raycast_batch_faces(origins, unit, cooked, 0))
    hits = int((first >= 0).sum())
    return name, len(f), statistics.median(py_times), statistics.median(cpp_times), hits


def bench_overlap(calls, repeats):
    sphere, box = gq.Sphere(0.5), gq.Box((1.0, 1.0, 1.0))
    p0, p1 = gq.Pose((1.2, 0.3, 0.0)), gq.Pose()
    overlap = gq.overlap
    py_ns, cpp_ns, empty_ns = [], [], []
    for _ in range(repeats):
        t0 = time.perf_counter()
        for _ in range(calls):
            overlap(sphere, p0, box, p1)
        py_ns.append((time.perf_counter() - t0) / calls * 1e9)
        seconds, _ = gq._geomquery._time_overlap_loop(sphere, p0, box, p1, calls)
        cpp_ns.append(seconds / calls * 1e9)
        t0 = time.perf_counter()
        for _ in range(calls):
            pass
        empty_ns.append((time.perf_counter() - t0) / calls * 1e9)
    return statistics.median(py_ns), statistics.median(cpp_ns), statistics.median(empty_ns)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--rays", type=int, default=1_000_000)
    parser.add_argument("--calls", type=int, default=1_000_000)
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--csv", help="append the figures to this CSV (written with a header if new)")
    parser.add_argument("--note", default="", help="a note for every row (e.g. the machine's load)")
    args = parser.parse_args()

    name, tris, py_s, cpp_s, hits = bench_rays(args.rays, args.repeats)
    py_ns, cpp_ns, loop_ns = bench_overlap(args.calls, args.repeats)
    load = os.getloadavg()[0]
    rows = [
        ("intersects_first_1M_rays", "%s (%d triangles), %d rays, %d hits" % (name, tris, args.rays, hits),
         py_s * 1e3, cpp_s * 1e3, "ms", py_s / cpp_s),
        ("overlap_single_call", "sphere-box, Pose objects; python includes the for-loop (%.0f ns a turn)" % loop_ns,
         py_ns, cpp_ns, "ns", py_ns / cpp_ns),
        ("overlap_python_overhead", "python call minus the C++ call minus the empty loop turn",
         py_ns - cpp_ns - loop_ns, 0.0, "ns", float("nan")),
    ]
    print("%-26s %12s %12s %6s %7s  %s" % ("figure", "python", "c++", "unit", "ratio", "what"))
    for fig, what, py_v, cpp_v, unit, ratio in rows:
        print("%-26s %12.2f %12.2f %6s %7.3f  %s" % (fig, py_v, cpp_v, unit, ratio, what))
    if args.csv:
        header = ["date", "machine", "commit", "load_1min", "figure", "python", "cpp", "unit", "ratio_python_vs_cpp",
                  "what", "note"]
        cols = results_csv.run_columns()
        results_csv.write(args.csv, header, [
            dict(cols, load_1min="%.1f" % load, figure=fig, python="%.2f" % py_v, cpp="%.2f" % cpp_v, unit=unit,
                 ratio_python_vs_cpp="%.3f" % ratio, what=what, note=args.note)
            for fig, what, py_v, cpp_v, unit, ratio in rows])

if __name__ == "__main__":
    sys.exit(main())
