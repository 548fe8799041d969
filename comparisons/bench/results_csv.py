"""Shared by the scripts that write comparisons/results/*.csv: one current CSV per benchmark.

Every row starts with date, machine and commit (the commit of the code measured; "+dirty" when the working tree had
uncommitted changes). Writing replaces the file (git keeps the earlier runs); append=True adds another run of the
same benchmark (for example a second run to show the spread).
"""
import argparse
import csv
import datetime
import json
import os
import subprocess

REPO = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
RESULTS = os.path.join(REPO, "comparisons", "results")


def today():
    return datetime.datetime.now(datetime.timezone.utc).date().isoformat()


def machine():
    """CPU model and core count, e.g. "AMD EPYC 7B13, 2 cores"."""
    model = "unknown CPU"
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    model = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    return "%s, %d cores" % (model, os.cpu_count() or 1)


def commit():
    """Short hash of HEAD in this checkout, "+dirty" appended when tracked files differ from it."""
    try:
        head = subprocess.run(["git", "-C", REPO, "rev-parse", "--short=8", "HEAD"], capture_output=True,
                              text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"
    dirty = subprocess.run(["git", "-C", REPO, "diff", "--quiet", "HEAD", "--"], capture_output=True).returncode
    return head + ("+dirty" if dirty else "")


def script_args(default_csv, inputs="runs", nargs="+", note=False, append=False, machine=True, doc=None):
    """The command line of a *.to_csv.py script: the positional `inputs` (nargs as argparse's; None: exactly one),
    --out (default comparisons/results/<default_csv>), --machine (replaces the detected CPU description, e.g. to say
    how loaded the machine was) unless machine=False, and --note / --append when asked. doc: the script's docstring,
    whose first line describes it in --help."""
    ap = argparse.ArgumentParser(description=doc.split("\n")[0] if doc else None)
    ap.add_argument(inputs, nargs=nargs)
    ap.add_argument("--out", default=os.path.join(RESULTS, default_csv))
    if machine:
        ap.add_argument("--machine")
    if note:
        ap.add_argument("--note", default="")
    if append:
        ap.add_argument("--append", action="store_true")
    return ap.parse_args()


# Google Benchmark time units in milliseconds.
TO_MS = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}


def median_aggregates(paths, key=lambda name: name):
    """The "median" aggregate of each benchmark in Google Benchmark JSON runs (--benchmark_repetitions with
    --benchmark_report_aggregates_only): {key(name): [one aggregate dict per run that has it]}."""
    samples = {}
    for path in paths:
        with open(path) as f:
            for b in json.load(f)["benchmarks"]:
                if b.get("aggregate_name") == "median":
                    samples.setdefault(key(b["name"]), []).append(b)
    return samples


def run_columns(machine_override=None):
    """The three leading columns of every row of this run."""
    return {"date": today(), "machine": machine_override or machine(), "commit": commit()}


def write(path, header, rows, append=False, comments=()):
    """Writes rows (dicts keyed by header) to path; header must start with date, machine, commit.

    append=True keeps the existing rows (the header must match); otherwise the file is replaced.
    comments: lines written after the header, each starting with '#'."""
    assert header[:3] == ["date", "machine", "commit"], header
    keep = []
    if append and os.path.exists(path):
        with open(path, newline="") as f:
            lines = f.read().splitlines()
        if lines and next(csv.reader([lines[0]])) != header:
            raise SystemExit("%s: existing header differs; write without --append to replace the file" % path)
        keep = lines[1:]
    with open(path, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(header)
        if keep:
            f.write("\n".join(keep) + "\n")
        else:
            for c in comments:
                f.write(c + "\n")
        for r in rows:
            w.writerow([r.get(h, "") for h in header])


def write_runs(path, header, rows, runs, comments=()):
    """write() for a *.to_csv.py script: stops with a message when the runs gave no rows, prints what it wrote."""
    if not rows:
        raise SystemExit("no median rows in %s" % ", ".join(runs))
    write(path, header, rows, comments=comments)
    print("%d rows -> %s" % (len(rows), path))
