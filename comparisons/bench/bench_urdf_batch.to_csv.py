#!/usr/bin/env python3
"""bench_urdf_batch JSON runs -> urdf_batch.csv.

Usage: bench_urdf_batch.to_csv.py <run1.json> [<run2.json> ...] [--out CSV] [--note TEXT]
Each run: bench_urdf_batch --benchmark_repetitions=3 --benchmark_enable_random_interleaving=true
--benchmark_report_aggregates_only=true --benchmark_out=runK.json. One row per benchmark: the median over the runs of
each run's median wall time for 100k Panda configurations, checks per second, and the speed against the row it is
read with (the loop for 1 thread, 1 thread for 2 threads), with the run's date, machine and commit.
"""
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import results_csv  # noqa: E402

HEADER = ["date", "machine", "commit", "benchmark", "model", "threads", "wall_ms", "checks_per_second", "versus",
          "speed_vs", "note"]
COMMENTS = ["# bench_urdf_batch: Panda self-collision (first colliding pair ends a check) over 100k seeded random"
            " configurations; a loop of single checks against gq::urdf::checkSelfCollisionBatch on gq's pool."]
MODELS = {"0": "mesh", "1": "hull"}


def key(name):
    """BM_PandaBatch/1/2/real_time_median -> ("batch", "hull", "2")."""
    parts = name[len("BM_Panda"):-len("_median")].replace("/real_time", "").split("/")
    kind = parts[0].lower()
    return kind, MODELS.get(parts[1], parts[1]), parts[2] if len(parts) > 2 else "1"


def main():
    args = results_csv.script_args("urdf_batch.csv", note=True)
    samples = results_csv.median_aggregates(args.runs, key=key)
    med = {k: (statistics.median(b["real_time"] * results_csv.TO_MS[b.get("time_unit", "ns")] for b in v),
               statistics.median(b.get("items_per_second", 0.0) for b in v)) for k, v in samples.items()}
    cols = results_csv.run_columns(args.machine)
    rows = []
    for model in ("hull", "mesh"):
        for kind, threads, versus in (("loop", "1", None), ("batch", "1", ("loop", "1")), ("batch", "2", ("batch", "1"))):
            m = med.get((kind, model, threads))
            if not m:
                continue
            other = med.get((versus[0], model, versus[1])) if versus else None
            rows.append(dict(cols, benchmark=kind, model=model, threads=threads, wall_ms="%.1f" % m[0],
                             checks_per_second="%.0f" % m[1],
                             versus="%s/%s thread" % versus if versus else "",
                             speed_vs="%.2f" % (m[1] / other[1]) if other and other[1] else "", note=args.note))
    results_csv.write_runs(args.out, HEADER, rows, args.runs, comments=COMMENTS)


if __name__ == "__main__":
    main()
