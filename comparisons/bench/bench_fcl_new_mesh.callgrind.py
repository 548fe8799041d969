#!/usr/bin/env python3
"""Instructions per query on new BVHModels, gq::fcl vs ::fcl (callgrind) -> fcl_new_mesh_callgrind.csv.

Usage: bench_fcl_new_mesh.callgrind.py <build>/comparisons/bench/bench_fcl_new_mesh [--sizes 1000 10000] [--out CSV]
       [--machine TEXT] [--note TEXT]
Runs each case of bench_fcl_new_mesh under callgrind with collection on only inside the query functions
(collideOnce / distanceOnce: the models' construction, FCL's tree build included, is not counted) and divides by the
number of queries: the first query on a new model per size, probe (box, sphere, capsule) and query (collide,
distance), and the MoveIt-like pattern (100 new models x 3 collides: per model). Writes
comparisons/results/fcl_new_mesh_callgrind.csv (or --out) with the run's date, machine and commit.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import results_csv  # noqa: E402

HEADER = ["date", "machine", "commit", "case", "triangles", "probe", "query", "fcl_instr", "gq_fcl_instr",
          "ratio_gq_over_fcl", "note"]
PROBES = ["box", "sphere", "capsule"]


def instructions(binary, bench_filter, function):
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "cg.out")
        subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=" + out,
                        "--toggle-collect=*" + function + "*", binary, "--benchmark_filter=" + bench_filter],
                       capture_output=True, check=True)
        with open(out) as f:
            for line in f:
                m = re.match(r"^summary:\s+(\d+)", line) or re.match(r"^totals:\s+(\d+)", line)
                if m:
                    return int(m.group(1))
    raise RuntimeError("no totals from callgrind")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("binary")
    ap.add_argument("--sizes", nargs="+", type=int, default=[1000, 10000])
    ap.add_argument("--out", default=os.path.join(results_csv.RESULTS, "fcl_new_mesh_callgrind.csv"))
    ap.add_argument("--machine")
    ap.add_argument("--note", default="")
    a = ap.parse_args()
    run = results_csv.run_columns(a.machine)
    rows = []
    for size in a.sizes:
        for probe in range(3):
            for query, function in ((0, "collideOnce"), (1, "distanceOnce")):
                counts = {}
                for lib in ("fcl", "gq_fcl"):
                    total = instructions(a.binary, "^first_query/%s/%d/%d/%d/" % (lib, size, probe, query), function)
                    counts[lib] = total / 50  # the case's Iterations
                rows.append(dict(run, case="first_query", triangles=size, probe=PROBES[probe],
                                 query="distance" if query else "collide", fcl_instr="%.0f" % counts["fcl"],
                                 gq_fcl_instr="%.0f" % counts["gq_fcl"],
                                 ratio_gq_over_fcl="%.2f" % (counts["gq_fcl"] / counts["fcl"]), note=a.note))
                print(rows[-1])
        counts = {lib: instructions(a.binary, "^moveit_100_objects/%s/%d/" % (lib, size), "collideOnce") / 300  # 1 iteration x 100 models x 3
                  for lib in ("fcl", "gq_fcl")}
        rows.append(dict(run, case="moveit_100_objects", triangles=size, probe="box, sphere, capsule",
                         query="collide, per query", fcl_instr="%.0f" % counts["fcl"],
                         gq_fcl_instr="%.0f" % counts["gq_fcl"],
                         ratio_gq_over_fcl="%.2f" % (counts["gq_fcl"] / counts["fcl"]), note=a.note))
        print(rows[-1])
    results_csv.write(a.out, HEADER, rows)
    print("%d rows -> %s" % (len(rows), a.out))


if __name__ == "__main__":
    main()
