#!/usr/bin/env python3
"""Instructions per call of gq::fcl vs ::fcl (callgrind), per pair family of bench_fcl_adapter -> fcl_adapter_callgrind.csv.

Usage: bench_fcl_adapter.callgrind.py <build>/comparisons/bench/bench_fcl_adapter [families...] [--out CSV]
       [--machine TEXT] [--note TEXT]
Runs the benchmark under callgrind once per family (collide and distance, both libraries), takes per family the
inclusive instruction count of each library's entry point divided by its number of calls from the benchmark loop
(so the benchmark's own loop and result construction are excluded), prints the rows and writes
comparisons/results/fcl_adapter_callgrind.csv (or --out) with the run's date, machine and commit. Measuring only
some families replaces their rows and keeps the others'.
"""
import argparse
import csv
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import results_csv  # noqa: E402

NAMES = ["sphere_sphere", "box_box", "capsule_capsule", "sphere_box", "capsule_box", "cylinder_box", "convex30",
         "convex100", "mesh_sphere", "mesh_convex30", "sphere_cylinder"]
# (label, benchmark loop function, callee prefix) for the four entry points.
ENTRIES = [("collide fcl", "BM_Collide<false>", "unsigned long fcl::collide<"),
           ("collide gq_fcl", "BM_Collide<true>", "unsigned long gq::fcl::collide<"),
           ("distance fcl", "BM_Distance<false>", "double fcl::distance<"),
           ("distance gq_fcl", "BM_Distance<true>", "double gq::fcl::distance<")]
HEADER = ["date", "machine", "commit", "family", "collide_fcl_instr", "collide_gq_fcl_instr", "collide_ratio",
          "distance_fcl_instr", "distance_gq_fcl_instr", "distance_ratio", "note"]


def per_call(out_file):
    text = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--tree=caller", out_file],
                          capture_output=True, text=True).stdout
    costs = {}
    for block in text.split("\n\n"):
        lines = block.strip("\n").split("\n")
        star = [l for l in lines if re.match(r"^\s*[\d,]+ \([^)]*\)\s+\*", l)]
        if not star:
            continue
        for label, loop, callee in ENTRIES:
            if callee not in star[0]:
                continue
            for l in lines:
                m = re.match(r"^\s*([\d,]+) \([^)]*\)\s+<.*" + re.escape(loop) + r".*\(([\d,]+)x\)", l)
                if m:
                    cost, calls = int(m.group(1).replace(",", "")), int(m.group(2).replace(",", ""))
                    costs[label] = costs.get(label, (0, 0))
                    costs[label] = (costs[label][0] + cost, costs[label][1] + calls)
    return {k: c / n for k, (c, n) in costs.items() if n}


def ratio(a, b):
    return "%.2f" % (a / b) if a and b else ""


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("bench")
    ap.add_argument("families", nargs="*", type=int)
    ap.add_argument("--out", default=os.path.join(results_csv.RESULTS, "fcl_adapter_callgrind.csv"))
    ap.add_argument("--machine")
    ap.add_argument("--note", default="")
    a = ap.parse_args()
    families = a.families or list(range(len(NAMES)))
    run = results_csv.run_columns(
        a.machine or results_csv.machine() + " (callgrind: instruction counts, load-independent)")
    note = "per call over the 256 bench poses; bench_fcl_adapter.callgrind.py" + ("; " + a.note if a.note else "")
    rows = []
    for f in families:
        with tempfile.NamedTemporaryFile(suffix=".callgrind") as out:
            subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=" + out.name, a.bench,
                            "--benchmark_filter=(collide|distance)/(fcl|gq_fcl)/%d$" % f,
                            "--benchmark_min_time=0.3"], capture_output=True, text=True)
            c = per_call(out.name)
        if not c:
            print(NAMES[f] + ": no calls found", file=sys.stderr)
        cf, cg, df, dg = (c.get(e[0]) for e in ENTRIES)
        r = dict(run, family=NAMES[f], note=note)
        r.update(collide_fcl_instr="%.0f" % cf if cf else "", collide_gq_fcl_instr="%.0f" % cg if cg else "",
                 collide_ratio=ratio(cf, cg), distance_fcl_instr="%.0f" % df if df else "",
                 distance_gq_fcl_instr="%.0f" % dg if dg else "", distance_ratio=ratio(df, dg))
        print(",".join(str(r[h]) for h in HEADER[3:-1]), flush=True)
        rows.append(r)
    # A partial run replaces only the measured families' rows.
    measured = {r["family"] for r in rows}
    old = []
    if len(measured) < len(NAMES) and os.path.exists(a.out):
        with open(a.out, newline="") as fh:
            old = [r for r in csv.DictReader(l for l in fh if not l.startswith("#")) if r["family"] not in measured]
    merged = sorted(old + rows, key=lambda r: NAMES.index(r["family"]) if r["family"] in NAMES else len(NAMES))
    results_csv.write(a.out, HEADER, merged)
    print("%d rows -> %s" % (len(old) + len(rows), a.out))


if __name__ == "__main__":
    main()
