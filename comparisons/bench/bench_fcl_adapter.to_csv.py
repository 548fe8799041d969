#!/usr/bin/env python3
"""bench_fcl_adapter JSON (--benchmark_repetitions=5 --benchmark_report_aggregates_only=true) -> dated CSV rows.

Usage: bench_fcl_adapter.to_csv.py <bench.json> <date> <machine> [load] > comparisons/results/fcl_adapter_<date>.csv
One row per query and family: FCL and gq::fcl CPU and real time medians (ns; us for the broadphase rows) and the
speedup FCL / gq (> 1: gq::fcl is faster).
"""
import json
import sys

data = json.load(open(sys.argv[1]))
date, machine = sys.argv[2], sys.argv[3]
load = sys.argv[4] if len(sys.argv) > 4 else ""
medians = {}
for b in data["benchmarks"]:
    if b.get("aggregate_name") != "median":
        continue
    name = b["run_name"]  # e.g. collide/fcl/0 or broadphase_self_1000/gq_fcl
    parts = name.split("/")
    query, lib = parts[0], parts[1]
    family = b.get("label", "") if len(parts) < 3 else b.get("label", parts[2])
    medians[(query, parts[2] if len(parts) > 2 else "", lib)] = (b["cpu_time"], b["real_time"], b.get("label", ""))

print("date,machine,query,family,fcl_cpu,gq_fcl_cpu,speedup_fcl_over_gq,fcl_real,gq_fcl_real,unit,note")
for (query, arg, lib), (cpu, real, label) in sorted(medians.items()):
    if lib != "fcl":
        continue
    g = medians.get((query, arg, "gq_fcl"))
    if not g:
        continue
    unit = "us" if query.startswith("broadphase") else "ns"
    family = label if not query.startswith("broadphase") else "mixed 1000 objects: fcl %s / gq %s" % (label, g[2])
    print('%s,"%s",%s,%s,%.0f,%.0f,%.2f,%.0f,%.0f,%s,"median of 5 repetitions (cpu time); %s"' %
          (date, machine, query, family, cpu, g[0], cpu / g[0], real, g[1], unit, load))
