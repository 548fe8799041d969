#!/usr/bin/env python3
"""Instructions per call of gq's public queries in bench_primitives (callgrind) -> primitives_callgrind.csv.

Usage: bench_primitives.callgrind.py <build>/comparisons/bench/bench_primitives [--out CSV] [--machine TEXT]
       [--note TEXT]
Runs every gq row of bench_primitives (prepared shapes `gq`, plain geometries `gq_geometry`) under callgrind, takes
the inclusive instruction count of the public entry point (gq::overlap, gq::computePenetration, gq::distance)
divided by its number of calls (so the benchmark's loop is excluded), and writes one row per query and pair with the
run's date, machine and commit.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import results_csv  # noqa: E402

PAIRS = ["sphere_sphere", "sphere_capsule", "sphere_box", "capsule_capsule", "capsule_box", "box_box"]
# query row name -> the entry point's demangled prefix (the shape argument type follows)
ENTRY = {"overlap": "gq::Status gq::overlap<double>(gq::%s<double> const&",
         "contact": "gq::Status gq::computePenetration<double>(gq::PenetrationResult<double>&, gq::%s<double> const&",
         "distance": "gq::Status gq::distance<double>(gq::DistanceResult<double>&, gq::%s<double> const&"}
HEADER = ["date", "machine", "commit", "query", "pair", "gq_prepared_instr", "gq_geometry_instr", "note"]


def per_call(exe, name, callee):
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "cg.out")
        subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=" + out, exe,
                        "--benchmark_filter=^" + name + "$", "--benchmark_min_time=0.01"],
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
        text = subprocess.run(["callgrind_annotate", "--threshold=100", "--inclusive=yes", "--tree=caller", out],
                              capture_output=True, text=True).stdout
    cost = calls = 0
    for block in text.split("\n\n"):
        lines = block.strip("\n").split("\n")
        star = [l for l in lines if re.match(r"^\s*[\d,]+ \([^)]*\)\s+\*", l)]
        if not star or callee not in star[0]:
            continue
        for l in lines:
            m = re.match(r"^\s*([\d,]+) \([^)]*\)\s+<.*\(([\d,]+)x\)", l)
            if m:
                cost += int(m.group(1).replace(",", ""))
                calls += int(m.group(2).replace(",", ""))
    return cost / calls if calls else None


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("exe")
    ap.add_argument("--out", default=os.path.join(results_csv.RESULTS, "primitives_callgrind.csv"))
    ap.add_argument("--machine")
    ap.add_argument("--note", default="")
    a = ap.parse_args()
    run = results_csv.run_columns(a.machine)
    note = "per call from bench_primitives (64 poses), inclusive cost of the public entry point" + (
        "; " + a.note if a.note else "")
    rows = []
    for query, entry in ENTRY.items():
        for pair in PAIRS:
            prepared = per_call(a.exe, "%s/%s/gq" % (query, pair), entry % "Shape")
            plain = per_call(a.exe, "%s/%s/gq_geometry" % (query, pair), entry % "Geometry")
            fmt = lambda x: "%.0f" % x if x else ""
            rows.append(dict(run, query=query, pair=pair, gq_prepared_instr=fmt(prepared),
                             gq_geometry_instr=fmt(plain), note=note))
            print(query, pair, fmt(prepared), fmt(plain), flush=True)
    results_csv.write(a.out, HEADER, rows)
    print("%d rows -> %s" % (len(rows), a.out))


if __name__ == "__main__":
    main()
