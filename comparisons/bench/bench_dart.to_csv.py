#!/usr/bin/env python3
"""bench_dart JSON runs -> dart.csv.

Usage: bench_dart.to_csv.py <run1.json> [<run2.json> ...] [--out CSV] [--machine TEXT] [--note TEXT]
Each run: bench_dart --benchmark_repetitions=3 --benchmark_report_aggregates_only=true --benchmark_out=runK.json.
One row per detector: the median over the runs of each run's CPU-time median (ms per 600 steps), ms per step, the
detector's speed relative to DART's bullet detector (bullet's time / this one's) and to fcl, with the run's date,
machine and commit; --note says how loaded the machine was.
"""
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import results_csv  # noqa: E402

HEADER = ["date", "machine", "commit", "benchmark", "detector", "median_cpu_ms", "ms_per_step", "speed_vs_bullet",
          "speed_vs_fcl", "runs", "note"]
COMMENTS = ["# bench_dart: a 27-body pile (boxes, spheres, capsules) dropped on a ground box, 600 DART steps of 1 ms"
            " per iteration (world construction not timed), the detector chosen by name; CPU-time medians."]


def main():
    args = results_csv.script_args("dart.csv", note=True)
    runs = results_csv.median_aggregates(args.runs, key=lambda name: name[len("stepPile/"):].split("_")[0])
    samples = {d: [b["cpu_time"] * results_csv.TO_MS[b.get("time_unit", "ns")] for b in v] for d, v in runs.items()}
    med = {d: statistics.median(v) for d, v in samples.items()}
    cols = results_csv.run_columns(args.machine)
    rows = []
    for detector in ("gq", "bullet", "fcl"):
        if detector not in med:
            continue
        ms = med[detector]
        rows.append(dict(cols, benchmark="pile27_600_steps", detector=detector, median_cpu_ms="%.1f" % ms,
                         ms_per_step="%.3f" % (ms / 600.0),
                         speed_vs_bullet="%.2f" % (med["bullet"] / ms) if "bullet" in med else "",
                         speed_vs_fcl="%.2f" % (med["fcl"] / ms) if "fcl" in med else "",
                         runs=len(samples[detector]), note=args.note))
    results_csv.write(args.out, HEADER, rows, comments=COMMENTS)


if __name__ == "__main__":
    main()
