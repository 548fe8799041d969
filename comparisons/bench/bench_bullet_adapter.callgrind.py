#!/usr/bin/env python3
"""Instructions of stock Bullet vs gq::bullet (callgrind) per bench_bullet_adapter scene -> bullet_adapter_callgrind.csv.

Usage: bench_bullet_adapter.callgrind.py <build>/comparisons/bench/bench_bullet_adapter [names...] [--out CSV]
       [--machine TEXT] [--builds float,float64] [--cache-sim]
Measures the float build (bench_bullet_adapter) and Bullet's float64 build (bench_bullet_adapter_double, beside it).
Runs each benchmark once (one iteration) under callgrind. Stepping scenes: the instructions inside
btDiscreteDynamicsWorld::stepSimulation (the timed 500 steps plus the untimed rest-measure run of 500 more; world
construction excluded). Pair scenes: instructions per contact call (the benchmark switches collection on around its
1000 calls). Prints the rows and writes comparisons/results/bullet_adapter_callgrind.csv (or --out) with the run's
date, machine and commit; measuring only some names (or builds) replaces their rows and keeps the others'.
--cache-sim runs callgrind's cache simulation instead and prints each backend's L1 and last-level misses and the
ratio of cycle estimates (Ir + 10 x L1 misses + 100 x LL misses): scenes whose code outgrows the L1 instruction
cache lose there what instruction counts do not show.
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

STEPS = ["stack", "drops_mesh", "drops_heightfield", "grid", "mixed_pile"]
PAIRS = ["sphere_box", "box_box", "capsule_box", "hull_hull", "box_mesh"]
PAIR_CALLS = 1000  # kPairCalls of bench_bullet_adapter.cpp
BUILDS = {"float": "", "float64": "_double"}  # Bullet build -> suffix of the benchmark program
HEADER = ["date", "machine", "commit", "bullet_build", "benchmark", "bullet_instr", "gq_instr", "ratio_gq_speed_vs_bullet", "note"]


def cycle_estimate(events):
    """Ir + 10 x L1 misses + 100 x last-level misses (callgrind's cache simulation): a load-independent proxy of
    cycles for scenes whose instruction working set outgrows the L1 cache."""
    l1 = events["I1mr"] + events["D1mr"] + events["D1mw"]
    ll = events["ILmr"] + events["DLmr"] + events["DLmw"]
    return events["Ir"] + 10 * l1 + 100 * ll


def instructions(bench, name, backend, cache_sim=False):
    """Collected instructions of one benchmark run (Ir total of the callgrind output); with cache_sim, the events
    of the cache simulation by name instead."""
    step = name in STEPS
    with tempfile.NamedTemporaryFile(suffix=".callgrind") as out:
        args = ["valgrind", "--tool=callgrind", "--callgrind-out-file=" + out.name]
        args += ["--cache-sim=yes"] if cache_sim else []
        args += ["--toggle-collect=btDiscreteDynamicsWorld::stepSimulation(*"] if step else ["--collect-atstart=no"]
        args += [bench, "--benchmark_filter=BM_%s/%s_%s$" % ("Step" if step else "PairContacts", name, backend),
                 "--benchmark_min_time=0.000001"]
        run = subprocess.run(args, capture_output=True, text=True)
        m = re.search(r"Collected : ([\d ]+)", run.stderr)
        if not m:
            raise SystemExit("%s %s: no callgrind total\n%s" % (name, backend, run.stderr[-2000:]))
        totals = [int(v) for v in m.group(1).split()]
        if cache_sim:
            return dict(zip(re.search(r"Events +: ([\w ]+)", run.stderr).group(1).split(), totals))
        total = totals[0]
    return total if step else total / PAIR_CALLS


def print_cache_sim(bench, build, name):
    """One scene's cache-simulated events for both backends and the ratio of their cycle estimates (printed only)."""
    ev = {backend: instructions(bench, name, backend, cache_sim=True) for backend in ("bullet", "gq")}
    for backend in ("bullet", "gq"):
        e = ev[backend]
        print("%s,%s,%s,Ir=%d,I1mr=%d,D1mr=%d,D1mw=%d,LLmiss=%d,cycles~%d" % (
            build, name, backend, e["Ir"], e["I1mr"], e["D1mr"], e["D1mw"], e["ILmr"] + e["DLmr"] + e["DLmw"],
            cycle_estimate(e)), flush=True)
    print("%s,%s,ratio_gq_speed_vs_bullet(cycle estimate)=%.2f" % (
        build, name, cycle_estimate(ev["bullet"]) / cycle_estimate(ev["gq"])), flush=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("bench")
    ap.add_argument("names", nargs="*")
    ap.add_argument("--out", default=os.path.join(results_csv.RESULTS, "bullet_adapter_callgrind.csv"))
    ap.add_argument("--machine")
    ap.add_argument("--builds", default="float,float64", help="comma-separated subset of " + ",".join(BUILDS))
    ap.add_argument("--cache-sim", action="store_true",
                    help="print L1/LL misses and the ratio of cycle estimates (Ir + 10 L1 + 100 LL misses) instead "
                         "of writing the CSV")
    a = ap.parse_args()
    names = a.names or STEPS + PAIRS
    builds = a.builds.split(",")
    if any(b not in BUILDS for b in builds):
        raise SystemExit("--builds: one of " + ",".join(BUILDS))
    if a.cache_sim:
        for build, name in ((b, n) for b in builds for n in names):
            print_cache_sim(a.bench + BUILDS[build], build, name)
        return
    run = results_csv.run_columns(
        a.machine or results_csv.machine() + " (callgrind: instruction counts, load-independent)")
    rows = []
    for build, name in ((b, n) for b in builds for n in names):
        bench = a.bench + BUILDS[build]
        bullet, gq = (instructions(bench, name, backend) for backend in ("bullet", "gq"))
        note = ("instructions in stepSimulation, 2 x 500 steps" if name in STEPS else
                "instructions per contact call, resting pair wobbling by up to 1 mm")
        r = dict(run, bullet_build=build, benchmark=("Step/" if name in STEPS else "PairContacts/") + name, bullet_instr="%.0f" % bullet,
                 gq_instr="%.0f" % gq, ratio_gq_speed_vs_bullet="%.2f" % (bullet / gq), note=note)
        print(",".join(str(r[h]) for h in HEADER[3:-1]), flush=True)
        rows.append(r)
    measured = {(r["bullet_build"], r["benchmark"]) for r in rows}
    old = []
    if os.path.exists(a.out):
        with open(a.out, newline="") as fh:
            old = [r for r in csv.DictReader(l for l in fh if not l.startswith("#")) if (r.get("bullet_build", "float"), r["benchmark"]) not in measured]
        for r in old:
            r.setdefault("bullet_build", "float")
    order = ["Step/" + n for n in STEPS] + ["PairContacts/" + n for n in PAIRS]
    rank = lambda r: (list(BUILDS).index(r["bullet_build"]) if r["bullet_build"] in BUILDS else len(BUILDS),
                      order.index(r["benchmark"]) if r["benchmark"] in order else len(order))
    merged = sorted(old + rows, key=rank)
    results_csv.write(a.out, HEADER, merged)
    print("%d rows -> %s" % (len(merged), a.out))


if __name__ == "__main__":
    main()
