#!/usr/bin/env python3
"""bench_primitives JSON runs (--benchmark_repetitions=5 --benchmark_enable_random_interleaving=true
--benchmark_report_aggregates_only=true) -> primitives.csv.

Usage: bench_primitives.to_csv.py <run1.json> [<run2.json> ...] [--out CSV] [--machine TEXT] [--note TEXT]
One row per query and pair: CPU-time medians per query (ns) of gq on prepared shapes (`gq`), gq on plain geometries
(`gq_geometry`) and FCL (the median over the runs of each run's median), the ratios FCL / gq for both gq forms (the
median over the runs of each run's ratio; the note gives the prepared ratio's range over the runs), and the pairs each backend reported overlapping
(counter hits, which must agree), with the run's date, machine and commit.
"""
import json
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import results_csv  # noqa: E402

HEADER = ["date", "machine", "commit", "query", "pair", "gq_ns", "gq_geometry_ns", "fcl_ns", "ratio_fcl_over_gq",
          "ratio_fcl_over_gq_geometry", "note"]
COMMENTS = [
    "# bench_primitives, double, 64 seeded pose pairs per pair type, CPU-time medians of 5 interleaved repetitions per run, median over the runs (ns = per query).",
    "# gq = prepared shapes (gq::Shape made once, as FCL's collision objects are); gq_geometry = Geometry<T> validated"
    " on every call.",
    "# overlap = gq::overlap, contact = gq::computePenetration (depth + direction), distance = gq::distance (signed,"
    " witness points).",
    "# FCL 0.7 default request (GST_LIBCCD): overlap = collide without contacts, contact = collide with one contact,"
    " distance = distance with signed distance + nearest points.",
]


def main():
    a = results_csv.script_args("primitives.csv", inputs="json", note=True, doc=__doc__)
    runs = []
    for path in a.json:
        with open(path) as f:
            data = json.load(f)
        med, hits = {}, {}
        for b in data["benchmarks"]:
            query, pair, lib = b["run_name"].split("/")[:3]
            if b.get("aggregate_name") == "median":
                med[(query, pair, lib)] = b["cpu_time"] / 64.0 * (1e3 if b.get("time_unit") == "us" else 1.0)
                hits[(query, pair, lib)] = b.get("hits")
        runs.append((med, hits))
    run = results_csv.run_columns(a.machine)
    rows = []
    pairs = ["sphere_sphere", "sphere_capsule", "sphere_box", "capsule_capsule", "capsule_box", "box_box"]
    order = lambda key: (["overlap", "contact", "distance"].index(key[0]), pairs.index(key[1]))
    mid = statistics.median
    for (query, pair, lib) in sorted(runs[0][0], key=order):
        if lib != "fcl":
            continue
        per = [(m[(query, pair, "fcl")], m[(query, pair, "gq")], m[(query, pair, "gq_geometry")]) for m, _ in runs]
        agree = all(h.get((query, pair, "gq")) == h.get((query, pair, "fcl")) == h.get((query, pair, "gq_geometry"))
                    for _, h in runs)
        ratios = [f / g for f, g, _ in per]
        spread = "prepared ratio %.2f-%.2f over %d runs" % (min(ratios), max(ratios), len(runs)) if len(runs) > 1 else ""
        note = "; ".join(x for x in ["hits agree" if agree else "HITS DIFFER", spread, a.note] if x)
        rows.append(dict(run, query=query, pair=pair, gq_ns="%.1f" % mid(p[1] for p in per),
                         gq_geometry_ns="%.1f" % mid(p[2] for p in per), fcl_ns="%.1f" % mid(p[0] for p in per),
                         ratio_fcl_over_gq="%.2f" % mid(ratios),
                         ratio_fcl_over_gq_geometry="%.2f" % mid(f / g for f, _, g in per), note=note))
    results_csv.write(a.out, HEADER, rows, comments=COMMENTS)
    print("%d rows -> %s" % (len(rows), a.out))
    for r in rows:
        print(r["query"], r["pair"], r["gq_ns"], r["gq_geometry_ns"], r["fcl_ns"], r["ratio_fcl_over_gq"],
              r["ratio_fcl_over_gq_geometry"], r["note"])


if __name__ == "__main__":
    main()
