#!/usr/bin/env python3
"""The geomquery package's speed against the C++ calls it wraps, in one run (same machine, same load):

  rays:    1M rays through geomquery.trimesh.RayMeshIntersector.intersects_first (non-unit directions, normalised
           as trimesh does) against gq::raycastBatch on the same unit rays, timed in C++ (face index only, all
           threads); mesh: the Stanford bunny from the shared data folder, else an icosphere. Then the same pair of
           calls with one geomquery.BatchScratch kept across them (geomquery.raycast_batch_faces with scratch=).
  overlap: one geomquery.overlap(sphere, pose, box, pose) call against the same gq::overlap in a C++ loop; the
           difference is the Python overhead of a call.

Usage: PYTHONPATH=<build>/python /usr/bin/python3 comparisons/bench_python.py [--csv comparisons/results/python.csv]
Medians of --repeats runs; the CSV gets one row per figure with the date, machine, commit and load average. Writing
keeps the CSV's instruction rows (unit "instructions"); --instructions re-measures the ray row with callgrind:
instructions a ray = (I refs of a process casting 40000 rays - one casting 20000, the same rays) / 20000, for
intersects_first and for the C++ call that times the batch (PYTHONHASHSEED fixed, so both processes do the same
setup work).
"""

import argparse
import os
import csv
import re
import statistics
import subprocess
import sys
import tempfile
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
    scratch = gq.BatchScratch()
    py_times, cpp_times, kept_py_times, kept_cpp_times = [], [], [], []
    for _ in range(repeats):  # alternate, so both see the same load
        t0 = time.perf_counter()
        first = ray.intersects_first(origins, dirs)
        py_times.append(time.perf_counter() - t0)
        cpp_times.append(gq._geomquery._time_raycast_batch_faces(origins, unit, cooked, 0))
        # The same call with a kept scratch (the batch reuses its arrays instead of faulting in fresh ones).
        t0 = time.perf_counter()
        kept = gq.raycast_batch_faces(origins, dirs, cooked, None, float("inf"), True, 0, True, scratch=scratch)
        kept_py_times.append(time.perf_counter() - t0)
        kept_cpp_times.append(gq._geomquery._time_raycast_batch_faces(origins, unit, cooked, 0, scratch))
    hits = int((first >= 0).sum())
    assert np.array_equal(kept, first)
    return (name, len(f), statistics.median(py_times), statistics.median(cpp_times), hits,
            statistics.median(kept_py_times), statistics.median(kept_cpp_times))


def rays_for_instructions():
    """The bunny (or icosphere), its cooked intersector and 40000 rays, as bench_rays draws them."""
    shared = os.environ.get("GQ_SHARED_DIR") or os.path.join(HERE, "..", "..", "shared")
    bunny = os.path.join(shared, "meshes", "stanford-bunny.obj")
    v, f = load_obj(bunny) if os.path.exists(bunny) else icosphere(5)
    rng = np.random.default_rng(1)
    lo, hi = v.min(axis=0), v.max(axis=0)
    origins = rng.uniform(lo - (hi - lo) * 0.25, hi + (hi - lo) * 0.25, (40000, 3))
    dirs = rng.normal(size=(40000, 3)) * 2.5
    unit = dirs / np.linalg.norm(dirs, axis=1)[:, None]
    mesh = Mesh(v, f)
    ray = gtm.RayMeshIntersector(mesh)
    ray.intersects_first(origins[:10], dirs[:10])
    cooked = gtm.cooked_mesh(mesh).mesh
    gq._geomquery._time_raycast_batch_faces(origins[:10], unit[:10], cooked, 0)
    return ray, cooked, origins, dirs, unit


def cast_once(side, n):
    """The process callgrind counts: the setup, then one call on the first n rays."""
    ray, cooked, origins, dirs, unit = rays_for_instructions()
    if side == "python":
        ray.intersects_first(origins[:n], dirs[:n])
    else:
        gq._geomquery._time_raycast_batch_faces(origins[:n], unit[:n], cooked, 0)


def ray_instructions():
    """Callgrind instructions a ray: (python, c++)."""
    def refs(side, n):
        with tempfile.TemporaryDirectory() as tmp:
            env = dict(os.environ, PYTHONHASHSEED="0")
            run = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=" + os.path.join(tmp, "cg"),
                                  sys.executable, os.path.abspath(__file__), "--cast-once", side, str(n)],
                                 env=env, capture_output=True, text=True, check=True)
            return int(re.search(r"Collected : (\d+)", run.stderr).group(1))
    return tuple((refs(side, 40000) - refs(side, 20000)) / 20000 for side in ("python", "cpp"))


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
    parser.add_argument("--instructions", action="store_true", help="re-measure the ray instruction row (callgrind)")
    parser.add_argument("--cast-once", nargs=2, metavar=("SIDE", "N"), help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.cast_once:
        return cast_once(args.cast_once[0], int(args.cast_once[1]))

    name, tris, py_s, cpp_s, hits, kept_py_s, kept_cpp_s = bench_rays(args.rays, args.repeats)
    py_ns, cpp_ns, loop_ns = bench_overlap(args.calls, args.repeats)
    load = os.getloadavg()[0]
    rows = [
        ("intersects_first_1M_rays", "%s (%d triangles), %d rays, %d hits" % (name, tris, args.rays, hits),
         py_s * 1e3, cpp_s * 1e3, "ms", py_s / cpp_s),
        ("raycast_batch_faces_1M_rays_kept_scratch",
         "the same rays through geomquery.raycast_batch_faces(normalize=True) with a kept BatchScratch, against the "
         "C++ batch with it", kept_py_s * 1e3, kept_cpp_s * 1e3, "ms", kept_py_s / kept_cpp_s),
        ("overlap_single_call", "sphere-box, Pose objects; python includes the for-loop (%.0f ns a turn)" % loop_ns,
         py_ns, cpp_ns, "ns", py_ns / cpp_ns),
        ("overlap_python_overhead", "python call minus the C++ call minus the empty loop turn",
         py_ns - cpp_ns - loop_ns, 0.0, "ns", float("nan")),
    ]
    print("%-26s %12s %12s %6s %7s  %s" % ("figure", "python", "c++", "unit", "ratio", "what"))
    for fig, what, py_v, cpp_v, unit, ratio in rows:
        print("%-26s %12.2f %12.2f %6s %7.3f  %s" % (fig, py_v, cpp_v, unit, ratio, what))
    instruction_rows = []
    if args.csv and os.path.exists(args.csv):
        with open(args.csv) as f:
            instruction_rows = [r for r in csv.DictReader(f) if r.get("unit") == "instructions"]
    if args.instructions:
        py_i, cpp_i = ray_instructions()
        print("%-26s %12.0f %12.0f %6s %7.3f" % ("intersects_first_ray_instr", py_i, cpp_i, "instr", py_i / cpp_i))
        ray_row = dict(results_csv.run_columns(), load_1min="", figure="intersects_first_ray_instructions",
                       python="%.0f" % py_i, cpp="%.0f" % cpp_i, unit="instructions",
                       ratio_python_vs_cpp="%.3f" % (py_i / cpp_i),
                       what="callgrind, per ray: (I refs at 40000 rays - at 20000) / 20000, %s, the same rays; c++ = "
                            "the whole _time_raycast_batch_faces call (its input copy and result buffers included)"
                            % name,
                       note="instruction counts do not depend on the load")
        instruction_rows = [ray_row] + [r for r in instruction_rows if r["figure"] != ray_row["figure"]]
    if args.csv:
        header = ["date", "machine", "commit", "load_1min", "figure", "python", "cpp", "unit", "ratio_python_vs_cpp",
                  "what", "note"]
        cols = results_csv.run_columns()
        results_csv.write(args.csv, header, [
            dict(cols, load_1min="%.1f" % load, figure=fig, python="%.2f" % py_v, cpp="%.2f" % cpp_v, unit=unit,
                 ratio_python_vs_cpp="%.3f" % ratio, what=what, note=args.note)
            for fig, what, py_v, cpp_v, unit, ratio in rows] + instruction_rows)

if __name__ == "__main__":
    sys.exit(main())
