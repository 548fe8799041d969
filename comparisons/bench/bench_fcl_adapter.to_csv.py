#!/usr/bin/env python3
"""bench_fcl_adapter JSON (--benchmark_repetitions=5 --benchmark_report_aggregates_only=true) -> fcl_adapter.csv.

Usage: bench_fcl_adapter.to_csv.py <bench.json> [--out CSV] [--append] [--machine TEXT] [--note TEXT]
Writes comparisons/results/fcl_adapter.csv (or --out): one row per query and family with the run's date, machine
and commit, FCL and gq::fcl CPU and real time medians (ns; us for the broadphase rows) and the speedup FCL / gq
(> 1: gq::fcl is faster). --append adds the rows as another run (e.g. "--note 'full run 2 of 3'") instead of
replacing the file; --machine replaces the detected CPU description (e.g. to say the machine was idle).
"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import results_csv  # noqa: E402

HEADER = ["date", "machine", "commit", "query", "family", "fcl_cpu", "gq_fcl_cpu", "speedup_fcl_over_gq", "fcl_real",
          "gq_fcl_real", "unit", "note"]


def main():
    a = results_csv.script_args("fcl_adapter.csv", inputs="json", nargs=None, note=True, append=True, doc=__doc__)
    with open(a.json) as f:
        data = json.load(f)
    medians = {}
    for b in data["benchmarks"]:
        if b.get("aggregate_name") != "median":
            continue
        parts = b["run_name"].split("/")  # e.g. collide/fcl/0 or broadphase_self_1000/gq_fcl
        query, lib = parts[0], parts[1]
        medians[(query, parts[2] if len(parts) > 2 else "", lib)] = (b["cpu_time"], b["real_time"], b.get("label", ""))
    run = results_csv.run_columns(a.machine)
    note = "median of 5 repetitions (cpu time)" + ("; " + a.note if a.note else "")
    rows = []
    for (query, arg, lib), (cpu, real, label) in sorted(medians.items()):
        if lib != "fcl":
            continue
        g = medians.get((query, arg, "gq_fcl"))
        if not g:
            continue
        broadphase = query.startswith("broadphase")
        family = "mixed 1000 objects: fcl %s / gq %s" % (label, g[2]) if broadphase else label
        rows.append(dict(run, query=query, family=family, fcl_cpu="%.0f" % cpu, gq_fcl_cpu="%.0f" % g[0],
                         speedup_fcl_over_gq="%.2f" % (cpu / g[0]), fcl_real="%.0f" % real,
                         gq_fcl_real="%.0f" % g[1], unit="us" if broadphase else "ns", note=note))
    results_csv.write(a.out, HEADER, rows, append=a.append)
    print("%d rows -> %s" % (len(rows), a.out))


if __name__ == "__main__":
    main()
