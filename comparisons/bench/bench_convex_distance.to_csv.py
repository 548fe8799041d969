#!/usr/bin/env python3
"""bench_convex_distance penetration rows (BM_Pen* Google Benchmark JSON runs, callgrind) -> convex_distance.csv.

Usage: bench_convex_distance.to_csv.py [<run1.json> ...] [--exe <build>/comparisons/bench/bench_convex_distance]
       [--errors <build>/comparisons/bench/bench_convex_distance] [--out CSV] [--machine TEXT]
JSON runs: bench_convex_distance --benchmark_filter='BM_Pen' --benchmark_repetitions=5
--benchmark_report_aggregates_only=true --benchmark_out=pen_ns.json. Each gives, per backend and hull size, the
CPU-time median of the 64 overlapping pose pairs; a row's ns is that per query (the median over the runs when several
are given) and ratio_vs_libccd is libccd GJK+EPA's ns / the row's ns (the median over the runs of each run's ratio).
--exe: instructions per query by callgrind, `--once-penetration N` (hull-hull, double and float) and
`--once-penetration-shapes N` (sphere, capsule, box against the hull) for N = 30, 100, 300: the inclusive cost of each
runner / 64 (libccd's two rows share one runner, runCcdPenetrationWith, listed once per solver: GJK+EPA's is the one
that costs at least ccdGJKPenetration's inclusive cost, which only it calls).
--errors: the hull-hull rows' max_rel_depth_error and max_rel_direction_error, by `--once-penetration-errors N`
(each backend against the exact MTD, a long double SAT over every face normal and edge pair; deterministic, so it is
not timed and the row's ns and instructions keep their date, machine and commit; the note says at which commit the
errors were measured). A source that does not measure a column keeps it as it is.
Only the penetration rows are written: the rows a source measures are replaced in place (their date, machine and
commit become this run's; a hull-hull row measured by one source keeps the other's figure, its note saying at which
commit that was measured), every other row of the CSV is kept as it is.
"""
import argparse
import csv
import os
import re
import statistics
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import results_csv  # noqa: E402

SIZES = [30, 100, 300]
HEADER = ["date", "machine", "commit", "benchmark", "backend", "ns", "ratio_vs_libccd", "callgrind_ir_per_query",
          "max_rel_depth_error", "max_rel_direction_error", "note"]
ERROR_COLUMNS = ["max_rel_depth_error", "max_rel_direction_error"]
PAIRS = 64  # pose pairs per benchmark iteration and per runner call

# Hull-hull rows: backend -> (Google Benchmark function, callgrind function (a substring of the demangled name), note).
HULL_BACKENDS = [
    ("gq", "BM_PenGqPenetration", "::runGqPenetration(",
     "gq::computePenetration (exact MTD; Gauss-map tree search)"),
    ("gq_distance", "BM_PenGqDistance", "::runGqDistance(", "gq::distance (signed, EPA) on the same pairs"),
    ("libccd_gjk_epa", "BM_PenCcdGJKPenetration", None, "ccdGJKPenetration"),
    ("libccd_mpr", "BM_PenCcdMPRPenetration", None, "ccdMPRPenetration"),
    ("bullet64_gjk_epa", "BM_PenBulletGjkEpa", "::runBulletDistance(",
     "Bullet float64 btGjkPairDetector + btGjkEpaPenetrationDepthSolver"),
    ("fcl_libccd_contact", "BM_PenFclCollideContact", "::runFclPenetration(",
     "FCL collide with one contact (GST_LIBCCD)"),
]
FLOAT_BACKENDS = [
    ("gq", "::runGqPenetrationFloat(", "gq::computePenetration in float (the same points cooked in float; exact MTD)"),
    ("gq_distance", "::runGqDistanceFloat(", "gq::distance in float (signed, EPA) on the same pairs"),
]
SHAPES = ["sphere", "capsule", "box"]


def ns_per_query(paths):
    """{(backend, size): [ns per query, one per run]} and {size: [libccd ns / backend ns per run]} from the JSON runs."""
    by_name = {b[1]: b[0] for b in HULL_BACKENDS}
    medians = results_csv.median_aggregates(paths, key=lambda name: name)
    ns, ratios = {}, {}
    for name, aggregates in medians.items():
        m = re.match(r"^(BM_Pen\w+)/(\d+)", name)
        if not m or m.group(1) not in by_name:
            continue
        for b in aggregates:
            ns.setdefault((by_name[m.group(1)], int(m.group(2))), []).append(
                b["cpu_time"] * results_csv.TO_MS[b.get("time_unit", "ns")] * 1e6 / PAIRS)
    for (backend, size), values in ns.items():
        ccd = ns.get(("libccd_gjk_epa", size))
        if ccd and len(ccd) == len(values):
            ratios[(backend, size)] = [c / v for c, v in zip(ccd, values)]
    return ns, ratios


def callgrind_inclusive(exe, args):
    """{demangled function: inclusive instructions} of one run of exe under callgrind, and the run's stdout."""
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "cg.out")
        run = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=" + out, exe] + args,
                             capture_output=True, text=True, check=True)
        text = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--threshold=100", out], capture_output=True,
                              text=True, check=True).stdout
    costs = []  # (name, cost): a name can be listed more than once (one entry per compiled copy)
    for line in text.splitlines():
        m = re.match(r"^\s*([\d,]+)\s+(?:\([^)]*\)\s+)?(\S.*?)(?:\s+\[[^\]]*\])?$", line)
        if m and ":" in m.group(2):
            costs.append((m.group(2).split(":", 1)[1], int(m.group(1).replace(",", ""))))
    return costs, run.stdout


def per_query(costs, needle):
    """Instructions per query of the function whose demangled name contains needle (one call per 64 pairs)."""
    hits = [c for name, c in costs if needle in name]
    if len(hits) != 1:
        raise SystemExit("callgrind: %d functions match %r" % (len(hits), needle))
    return hits[0] / PAIRS


def measure_instructions(exe):
    """{(benchmark, backend): (instructions per query, note suffix)} for every penetration row, by callgrind."""
    instr = {}
    for n in SIZES:
        costs, _ = callgrind_inclusive(exe, ["--once-penetration", str(n)])
        for backend, _, needle, _ in HULL_BACKENDS:
            if needle:
                instr[("penetration_hull%d" % n, backend)] = (per_query(costs, needle), "")
        ccd = sorted(c for name, c in costs if "::runCcdPenetrationWith(" in name)
        gjk = [c for name, c in costs if name.startswith("ccdGJKPenetration")]
        if len(ccd) != 2 or len(gjk) != 1 or not ccd[0] < gjk[0] <= ccd[1]:
            raise SystemExit("callgrind: libccd runners not told apart: %s, ccdGJKPenetration %s" % (ccd, gjk))
        instr[("penetration_hull%d" % n, "libccd_gjk_epa")] = (ccd[1] / PAIRS, "")
        instr[("penetration_hull%d" % n, "libccd_mpr")] = (ccd[0] / PAIRS, "")
        for backend, needle, _ in FLOAT_BACKENDS:
            instr[("penetration_hull%d_float" % n, backend)] = (per_query(costs, needle), "")
        costs, text = callgrind_inclusive(exe, ["--once-penetration-shapes", str(n)])
        # "overlapping of 64: sphere 47 (distance 47), capsule 49 (49), box 61 (61)", then the same after "float: ".
        counts = {}
        for line in text.splitlines():
            m = re.match(r"^(float: )?overlapping of \d+: sphere (\d+) .*capsule (\d+) .*box (\d+) ", line)
            if m:
                counts[bool(m.group(1))] = dict(zip(SHAPES, map(int, m.group(2, 3, 4))))
        for is_float, scene in ((False, "(anonymous namespace)::Scene,"), (True, "(anonymous namespace)::FloatScene,")):
            for shape in SHAPES:
                bench = "penetration_%s_hull%d%s" % (shape, n, "_float" if is_float else "")
                title = shape.capitalize()
                overlapping = counts.get(is_float, {}).get(shape)
                where = "%d of %d poses overlapping" % (overlapping, PAIRS) if overlapping is not None else ""
                instr[(bench, "gq")] = (per_query(costs, "run%sHullPenetration<%s" % (title, scene)), where)
                instr[(bench, "gq_distance")] = (per_query(costs, "run%sHullDistance<%s" % (title, scene)), "")
    return instr


def measure_errors(exe):
    """{(benchmark, backend): (max relative depth error, max relative direction error)} of the hull-hull rows."""
    errors = {}
    for n in SIZES:
        out = subprocess.run([exe, "--once-penetration-errors", str(n)], capture_output=True, text=True,
                             check=True).stdout
        # errors,penetration_hullN,<backend>,<depth error>,<direction error>,<missed pairs>
        for line in out.splitlines():
            f = line.split(",")
            if len(f) == 6 and f[0] == "errors":
                errors[(f[1], f[2])] = (float(f[3]), float(f[4]))
        if not any(b == "penetration_hull%d" % n for b, _ in errors):
            raise SystemExit("%s --once-penetration-errors %d printed no errors" % (exe, n))
    return errors


def error_text(x):
    return "0" if x == 0 else "%.1e" % x


def shape_note(bench, backend, where):
    if backend == "gq_distance":
        return "gq::distance%s (signed, EPA) on the same poses" % (" in float" if bench.endswith("_float") else "")
    inner = "the same points cooked in float; exact MTD" if bench.endswith("_float") else "exact MTD"
    return "gq::computePenetration%s (%s%s)" % (" in float" if bench.endswith("_float") else "", inner,
                                                "; " + where if where else "")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("json", nargs="*")
    ap.add_argument("--exe")
    ap.add_argument("--errors", metavar="EXE")
    ap.add_argument("--out", default=os.path.join(results_csv.RESULTS, "convex_distance.csv"))
    ap.add_argument("--machine")
    a = ap.parse_args()
    if not a.json and not a.exe and not a.errors:
        raise SystemExit("give JSON runs, --exe, --errors, or several")
    with open(a.out, newline="") as f:
        lines = f.read().splitlines()
    header = next(csv.reader([lines[0]]))
    if header != HEADER and header != [h for h in HEADER if h not in ERROR_COLUMNS]:
        raise SystemExit("%s: unexpected header" % a.out)
    comments = [l for l in lines[1:] if l.startswith("#")]
    rows = [dict(zip(header, r)) for r in csv.reader(l for l in lines[1:] if not l.startswith("#"))]

    ns, ratios = ns_per_query(a.json) if a.json else ({}, {})
    instr = measure_instructions(a.exe) if a.exe else {}
    errors = measure_errors(a.errors) if a.errors else {}
    run = results_csv.run_columns(a.machine)
    mid = statistics.median
    hull_notes = {b[0]: b[3] for b in HULL_BACKENDS}
    float_notes = {b[0]: b[2] for b in FLOAT_BACKENDS}
    replaced = 0
    for r in rows:
        bench, backend = r["benchmark"], r["backend"]
        m = re.match(r"^penetration_hull(\d+)$", bench)
        if m and backend in hull_notes:
            size = int(m.group(1))
            timed = (backend, size) in ns
            counted = (bench, backend) in instr
            checked = (bench, backend) in errors
            if checked:
                r["max_rel_depth_error"], r["max_rel_direction_error"] = map(error_text, errors[(bench, backend)])
            errors_at = None  # the commit at which the errors were measured, when it is not the row's
            if r.get("max_rel_depth_error"):
                kept = re.search(r"\berrors at ([\w+]+)", r["note"])
                errors_at = run["commit"] if checked else (kept.group(1) if kept else r["commit"])
            if not timed and not counted:
                if checked:
                    r["note"] = re.sub(r"; errors at \S+", "", r["note"]) + "; errors at %s" % errors_at
                    replaced += 1
                continue
            note = hull_notes[backend]
            columns = dict(run)
            if timed:
                r["ns"] = "%.0f" % mid(ns[(backend, size)])
                r["ratio_vs_libccd"] = "%.2f" % mid(ratios[(backend, size)]) if (backend, size) in ratios else ""
            elif r["ns"]:  # the timing's machine is kept with it
                columns["machine"] = r["machine"]
                kept = re.search(r"\bns at (\w+)", r["note"])
                note += "; ns at %s" % (kept.group(1) if kept else r["commit"])
            if counted:
                r["callgrind_ir_per_query"] = "%.0f" % instr[(bench, backend)][0]
            elif r["callgrind_ir_per_query"]:
                kept = re.search(r"instructions at (\w+)", r["note"])
                note += "; instructions at %s" % (kept.group(1) if kept else r["commit"])
            if errors_at and errors_at != run["commit"]:
                note += "; errors at %s" % errors_at
            r.update(columns, note=note)
            replaced += 1
        elif (bench, backend) in instr and bench.startswith("penetration_"):
            count, where = instr[(bench, backend)]
            if re.match(r"^penetration_hull\d+_float$", bench):
                note = float_notes[backend]
            else:
                note = shape_note(bench, backend, where)
            r.update(run, ns="", ratio_vs_libccd="", callgrind_ir_per_query="%.0f" % count, note=note)
            replaced += 1
    if not replaced:
        raise SystemExit("no penetration rows measured (JSON without BM_Pen* medians?)")
    results_csv.write(a.out, HEADER, rows, comments=comments)
    print("%d of %d rows replaced -> %s" % (replaced, len(rows), a.out))
    for r in rows:
        if r["benchmark"].startswith("penetration_"):
            print(r["benchmark"], r["backend"], r["ns"], r["ratio_vs_libccd"], r["callgrind_ir_per_query"],
                  r.get("max_rel_depth_error", ""), r.get("max_rel_direction_error", ""))


if __name__ == "__main__":
    main()
