#!/usr/bin/env python3
"""bench_fcl_new_mesh JSON (--benchmark_repetitions=N --benchmark_report_aggregates_only=true) -> fcl_new_mesh.csv.

Usage: bench_fcl_new_mesh.to_csv.py <bench.json> [--out CSV] [--machine TEXT] [--note TEXT]
Writes comparisons/results/fcl_new_mesh.csv (or --out): one row per case (first query on a new BVHModel per size,
probe and query; the MoveIt-like 100 new models x 3 collides) with the run's date, machine and commit, FCL's and
gq::fcl's median time (us, manual time around the queries only) and the ratio gq::fcl / FCL (<= 3 is the target of
the first query).
"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import results_csv  # noqa: E402

HEADER = ["date", "machine", "commit", "case", "args", "fcl_us", "gq_fcl_us", "ratio_gq_over_fcl", "label", "note"]


def main():
    a = results_csv.script_args("fcl_new_mesh.csv", inputs="json", nargs=None, note=True, doc=__doc__)
    with open(a.json) as f:
        data = json.load(f)
    medians = {}
    for b in data["benchmarks"]:
        if b.get("aggregate_name", "median") != "median":
            continue
        parts = b["run_name"].split("/")  # first_query/fcl/1000/0/1/iterations:200/manual_time
        case, lib = parts[0], parts[1]
        args = "/".join(p for p in parts[2:] if p[0].isdigit())
        medians[(case, args, lib)] = (b["real_time"], b.get("label", ""))
    run = results_csv.run_columns(a.machine)
    note = "median (manual time around the queries)" + ("; " + a.note if a.note else "")
    rows = []
    for (case, args, lib), (us, label) in sorted(medians.items()):
        g = medians.get((case, args, "gq_fcl"))
        if lib != "fcl" or not g:
            continue
        rows.append(dict(run, case=case, args=args, fcl_us="%.2f" % us, gq_fcl_us="%.2f" % g[0],
                         ratio_gq_over_fcl="%.2f" % (g[0] / us), label=label, note=note))
    results_csv.write(a.out, HEADER, rows)
    print("%d rows -> %s" % (len(rows), a.out))


if __name__ == "__main__":
    main()
