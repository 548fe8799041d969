#!/usr/bin/env python3
"""bench_bullet_adapter JSON runs -> bullet_adapter.csv.

Usage: bench_bullet_adapter.to_csv.py <run1.json> [<run2.json> ...] [--out CSV] [--machine TEXT]
Each run: bench_bullet_adapter (float Bullet) or bench_bullet_adapter_double (Bullet's float64 build; the build is
read from the run's executable name) --benchmark_repetitions=3 --benchmark_enable_random_interleaving=true
--benchmark_report_aggregates_only=true --benchmark_out=runK.json. One row per Bullet build, benchmark and backend: the median over
the runs of each run's CPU-time median (ms per iteration), the items per second, gq's speed relative to stock Bullet
(Bullet's time / gq's), the rest measures the stepping benchmarks report (largest body speed after 5 s, depth of the
lowest body below the ground, the stack's largest height error) and contacts per pair call, with the run's date,
machine and commit.
"""
import json
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import results_csv  # noqa: E402

HEADER = ["date", "machine", "commit", "bullet_build", "benchmark", "backend", "median_cpu_ms", "median_real_ms", "items_per_second",
          "ratio_gq_speed_vs_bullet", "max_speed_5s", "below_ground", "height_error", "contacts_per_call", "note"]
COMMENTS = ["# bench_bullet_adapter (float Bullet) and bench_bullet_adapter_double (float64): stock configuration (bullet) against gq::bullet's (gq), same world,"
            " solver and broadphase; CPU-time medians of alternating runs."]
# What one iteration of each benchmark does (the README's table shows it).
WHAT = {
    "Step/stack": "10-box stack, 500 steps (incl. world construction)",
    "Step/drops_mesh": "drops on BVH mesh, 500 steps",
    "Step/drops_heightfield": "drops on heightfield, 500 steps",
    "Step/grid": "BasicDemo 5x5x5 box grid dropped into a pile, 500 steps",
    "Step/mixed_pile": "200-body mixed pile on a triangle-mesh ground, 500 steps",
    "PairContacts/sphere_box": "contact generation, resting sphere-box pair",
    "PairContacts/box_box": "contact generation, resting box-box pair",
    "PairContacts/capsule_box": "contact generation, resting capsule-box pair",
    "PairContacts/hull_hull": "contact generation, resting 30-vertex hull pair",
    "PairContacts/box_mesh": "contact generation, box resting on a mesh",
    "RayTest": "10k rayTests per iteration",
    "ConvexSweepTest": "10k sphere (r 0.25) convexSweepTests per iteration",
}
TO_MS = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}


def split(name):
    """BM_Step/stack_gq_median -> ("Step/stack", "gq")."""
    base = name[len("BM_"):-len("_median")]
    family, _, rest = base.partition("/")
    key, _, backend = rest.rpartition("_")
    return (family + "/" + key if key else family), backend


def build_of(run):
    """float64 for a run of bench_bullet_adapter_double, else float."""
    exe = run.get("context", {}).get("executable", "")
    return "float64" if os.path.basename(exe).endswith("_double") else "float"


def main():
    args = results_csv.script_args("bullet_adapter.csv")
    samples = {}
    for path in args.runs:
        with open(path) as f:
            run = json.load(f)
        for b in run["benchmarks"]:
            if b.get("aggregate_name") != "median":
                continue
            samples.setdefault((build_of(run),) + split(b["name"]), []).append(b)
    cols = results_csv.run_columns(args.machine)
    order = [k for k in WHAT]
    rows = []
    for build, bench in ((b, n) for b in ("float", "float64") for n in order):
        med = {}
        for backend in ("bullet", "gq"):
            runs = samples.get((build, bench, backend))
            if not runs:
                continue
            unit = TO_MS[runs[0].get("time_unit", "ns")]
            med[backend] = {
                "cpu": statistics.median(r["cpu_time"] * unit for r in runs),
                "real": statistics.median(r["real_time"] * unit for r in runs),
                "ips": statistics.median(r.get("items_per_second", 0.0) for r in runs),
                "counters": {c: statistics.median(r[c] for r in runs) for c in
                             ("max_speed_5s", "below_ground", "height_error", "contacts") if c in runs[0]},
            }
        for backend, m in med.items():
            ratio = med["bullet"]["cpu"] / m["cpu"] if "bullet" in med else float("nan")
            c = m["counters"]
            rows.append(dict(cols, bullet_build=build, benchmark=bench, backend=backend, median_cpu_ms="%.3f" % m["cpu"],
                             median_real_ms="%.3f" % m["real"], items_per_second="%.0f" % m["ips"],
                             ratio_gq_speed_vs_bullet="%.2f" % ratio,
                             max_speed_5s="%.4f" % c["max_speed_5s"] if "max_speed_5s" in c else "",
                             below_ground="%.4f" % c["below_ground"] if "below_ground" in c else "",
                             height_error="%.5f" % c["height_error"] if "height_error" in c else "",
                             contacts_per_call="%.2f" % c["contacts"] if "contacts" in c else "",
                             note=WHAT[bench]))
    results_csv.write_runs(args.out, HEADER, rows, args.runs, comments=COMMENTS)


if __name__ == "__main__":
    main()
