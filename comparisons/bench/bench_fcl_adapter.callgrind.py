#!/usr/bin/env python3
"""Instructions per call of gq::fcl vs ::fcl (callgrind), per pair family of bench_fcl_adapter.

Usage: bench_fcl_adapter.callgrind.py <build>/comparisons/bench/bench_fcl_adapter [families...]
Runs the benchmark under callgrind once per family (collide and distance, both libraries) and prints, per family,
the inclusive instruction count of each library's entry point divided by its number of calls from the benchmark
loop (so the benchmark's own loop and result construction are excluded).
"""
import re
import subprocess
import sys
import tempfile

NAMES = ["sphere_sphere", "box_box", "capsule_capsule", "sphere_box", "capsule_box", "cylinder_box", "convex30",
         "convex100", "mesh_sphere", "mesh_convex30", "sphere_cylinder"]
# (label, benchmark loop function, callee prefix) for the four entry points.
ENTRIES = [("collide fcl", "BM_Collide<false>", "unsigned long fcl::collide<"),
           ("collide gq_fcl", "BM_Collide<true>", "unsigned long gq::fcl::collide<"),
           ("distance fcl", "BM_Distance<false>", "double fcl::distance<"),
           ("distance gq_fcl", "BM_Distance<true>", "double gq::fcl::distance<")]


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


def main():
    bench = sys.argv[1]
    families = [int(f) for f in sys.argv[2:]] or list(range(len(NAMES)))
    print("family," + ",".join(e[0].replace(" ", "_") for e in ENTRIES))
    for f in families:
        with tempfile.NamedTemporaryFile(suffix=".callgrind") as out:
            subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=" + out.name, bench,
                            "--benchmark_filter=(collide|distance)/(fcl|gq_fcl)/%d$" % f,
                            "--benchmark_min_time=0.3"], capture_output=True, text=True)
            c = per_call(out.name)
            if not c:
                print(NAMES[f] + ": no calls found", file=sys.stderr)
        print(NAMES[f] + "," + ",".join("%.0f" % c.get(e[0], float("nan")) for e in ENTRIES), flush=True)


if __name__ == "__main__":
    main()
