#!/usr/bin/env python3
"""bench_scene JSON runs -> scene.csv.

Usage: bench_scene.to_csv.py <run1.json> [<run2.json> ...] [--out CSV] [--machine TEXT]
Each run: bench_scene --benchmark_repetitions=3 --benchmark_enable_random_interleaving=true
--benchmark_report_aggregates_only=true --benchmark_out=runK.json. One row per benchmark: the median over the runs of
each run's median time (CPU time; wall time for the threaded batches, whose work runs on other threads), items per
second, the answer counter (hits or pairs) and the comparison the row is read against (speed = the other row's time /
this row's), with the run's date, machine and commit.
"""
import json
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import results_csv  # noqa: E402

HEADER = ["date", "machine", "commit", "benchmark", "time_ms", "clock", "items_per_second", "answers", "versus",
          "speed_vs", "note"]
COMMENTS = ["# bench_scene (double unless noted): 1000 mixed objects (spheres, capsules, boxes, hulls, 8 bunnies) in a"
            " 40-unit cube, 1M rays into it, 1M rays at the bunny; peers on the same objects and rays in the same run."]
# benchmark -> (the row it is compared with, what it is)
ROWS = {
    "SceneRaycast": ("BruteRaycast", "Scene::raycastClosest, 1M rays"),
    "BruteRaycast": ("", "every object's raycast per ray (2000 rays; per-ray speed compared)"),
    "EmbreeSceneRaycast": ("SceneRaycast", "Embree 3 BVH over the objects, gq's raycast per object (float rays)"),
    "SceneRaycastBatch/1": ("SceneRaycast", "raycastBatch over the scene, 1 thread"),
    "SceneRaycastBatch/2": ("SceneRaycastBatch/1", "raycastBatch over the scene, 2 threads"),
    "BunnyRaycastLoop": ("", "1M rays at the bunny, a loop of single prepared raycasts storing hits into arrays"),
    "BunnyRaycastBatch/1": ("BunnyRaycastLoop", "1M bunny rays as one raycastBatch (coherent ray order), 1 thread"),
    "BunnyRaycastBatchInputOrder/1": ("BunnyRaycastLoop",
                                      "the same batch in input order (coherentRayOrder false), 1 thread"),
    "BunnyRaycastBatch/2": ("BunnyRaycastBatch/1",
                            "1M bunny rays as one raycastBatch, 2 threads"),
    "BunnyRaycastBatchInputOrder/2": ("BunnyRaycastBatchInputOrder/1", "the input-order batch, 2 threads"),
    "BunnyRaycastBatchKeptScratch/1": ("BunnyRaycastLoop", "the coherent batch with a BatchScratch kept across calls, 1 thread"),
    "BunnyRaycastBatchKeptScratch/2": ("BunnyRaycastBatchKeptScratch/1", "the same, 2 threads"),
    "GqFloatBunnyRaycastBatch/1": ("EmbreeBunnyIntersect1M", "1M bunny rays, float mesh, one raycastBatch, 1 thread"),
    "GqFloatBunnyRaycastBatch/2": ("GqFloatBunnyRaycastBatch/1", "the same, 2 threads"),
    "EmbreeBunnyIntersect1": ("", "Embree 3 rtcIntersect1 per ray, 1M bunny rays (float)"),
    "EmbreeBunnyIntersect1M": ("EmbreeBunnyIntersect1", "Embree 3 rtcIntersect1M over the 1M bunny rays (float)"),
    "SelfPairs": ("FclSelfPairs", "Scene::overlappingPairs over the 1000 objects"),
    "BruteSelfPairs": ("", "every pair through overlap()"),
    "FclSelfPairs": ("", "FCL 0.7 DynamicAABBTreeCollisionManager self-collide, fcl::collide in the callback"),
}
TO_MS = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}


def key(name):
    """BM_SceneRaycastBatch/1/real_time_median -> SceneRaycastBatch/1."""
    base = name[len("BM_"):-len("_median")]
    return base.replace("/real_time", "")


def main():
    args = results_csv.script_args("scene.csv")
    samples = {}
    for path in args.runs:
        with open(path) as f:
            for b in json.load(f)["benchmarks"]:
                if b.get("aggregate_name") == "median":
                    samples.setdefault(key(b["name"]), []).append(b)
    med = {}
    for bench, runs in samples.items():
        unit = TO_MS[runs[0].get("time_unit", "ns")]
        wall = "/real_time" in runs[0]["name"]
        med[bench] = {
            "ms": statistics.median((r["real_time"] if wall else r["cpu_time"]) * unit for r in runs),
            "clock": "wall" if wall else "cpu",
            "ips": statistics.median(r.get("items_per_second", 0.0) for r in runs),
            "answers": statistics.median(r.get("hits", r.get("pairs", 0.0)) for r in runs),
        }
    cols = results_csv.run_columns(args.machine)
    rows = []
    for bench, (versus, note) in ROWS.items():
        m = med.get(bench)
        if not m:
            continue
        speed = ""
        if versus in med:
            other = med[versus]
            # Per item where both count items (the brute loop times fewer rays), else per iteration.
            speed = "%.2f" % (m["ips"] / other["ips"] if m["ips"] and other["ips"] else other["ms"] / m["ms"])
        rows.append(dict(cols, benchmark=bench, time_ms="%.3f" % m["ms"], clock=m["clock"],
                         items_per_second="%.0f" % m["ips"], answers="%.0f" % m["answers"], versus=versus,
                         speed_vs=speed, note=note))
    results_csv.write_runs(args.out, HEADER, rows, args.runs, comments=COMMENTS)


if __name__ == "__main__":
    main()
