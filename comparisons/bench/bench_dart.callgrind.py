#!/usr/bin/env python3
"""Instructions of DART's World::step with each collision detector (callgrind) -> dart_callgrind.csv.

Usage: bench_dart.callgrind.py <build>/comparisons/bench/bench_dart [--out CSV] [--machine TEXT] [--note TEXT]
Runs one iteration of each stepPile benchmark of bench_dart (600 steps of the 27-body pile) under callgrind,
collecting only inside dart::simulation::World::step (world construction excluded), and writes one row per detector:
instructions per step and the ratios to DART's bullet and fcl detectors, with the run's date, machine and commit.
Instruction counts do not depend on the machine's load.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import results_csv  # noqa: E402

HEADER = ["date", "machine", "commit", "benchmark", "detector", "instructions_per_step", "ratio_to_bullet",
          "ratio_to_fcl", "note"]
STEPS = 600


def instructions(exe, detector):
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "cg.out")
        subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=" + out,
                        "--toggle-collect=dart::simulation::World::step*", exe,
                        "--benchmark_filter=^stepPile/%s$" % detector, "--benchmark_min_time=0.000001"],
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
        with open(out) as f:
            for line in f:
                m = re.match(r"^(?:summary|totals): (\d+)", line)
                if m:
                    return int(m.group(1))
    raise RuntimeError("no instruction total for " + detector)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("exe")
    ap.add_argument("--out", default=os.path.join(results_csv.RESULTS, "dart_callgrind.csv"))
    ap.add_argument("--machine")
    ap.add_argument("--note", default="")
    args = ap.parse_args()
    counts = {d: instructions(args.exe, d) / STEPS for d in ("gq", "bullet", "fcl")}
    cols = results_csv.run_columns(args.machine)
    rows = [dict(cols, benchmark="pile27_600_steps", detector=d, instructions_per_step="%.0f" % n,
                 ratio_to_bullet="%.3f" % (n / counts["bullet"]), ratio_to_fcl="%.3f" % (n / counts["fcl"]),
                 note=args.note) for d, n in counts.items()]
    results_csv.write(args.out, HEADER, rows)


if __name__ == "__main__":
    main()
