#!/usr/bin/env python3
"""The benchmark tables (docs/results/benchmarks.md): every Google Benchmark program of the build
run with repetitions, and each benchmark's median (and its spread: min and max of the
repetitions) written as a table per program, with the command, commit, date and the machine's
load on top. docs/performance.md says what each benchmark measures and what its cost depends on.

Usage: python3 scripts/benchmarks.py [--build build] [--repetitions 3] [--only PROGRAM,...]
       [--filter REGEX] OUT.md
"""
import argparse
import datetime
import json
import os
import subprocess

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PROGRAMS = ["measurement_benchmarks", "io_benchmarks", "fit_benchmarks", "sample_benchmarks",
            "compare_benchmarks"]
TITLES = {
    "measurement_benchmarks": "Pair measurements (geometry)",
    "io_benchmarks": "Readers and writers (io)",
    "fit_benchmarks": "Maximum-likelihood fits (fit)",
    "sample_benchmarks": "The birth-death sampler (sample)",
    "compare_benchmarks": "The comparison methods (methods) and metrics",
}


def readable(seconds):
    for unit, scale in (("s", 1.0), ("ms", 1e-3), ("µs", 1e-6)):
        if seconds >= scale:
            return f"{seconds / scale:.3g} {unit}"
    return f"{seconds / 1e-9:.3g} ns"


def run(program, repetitions, pattern):
    """The program's benchmarks: name -> (median, min, max) of real time in seconds, and the
    counters of the median run."""
    command = [program, f"--benchmark_repetitions={repetitions}", "--benchmark_format=json"]
    if pattern:
        command.append(f"--benchmark_filter={pattern}")
    out = subprocess.run(command, capture_output=True, text=True, check=True).stdout
    runs, medians = {}, {}
    for b in json.loads(out)["benchmarks"]:
        scale = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}[b.get("time_unit", "ns")]
        if b.get("run_type") == "aggregate":
            # A benchmark that reports its aggregates only (its own repetitions): the median, with
            # the coefficient of variation for the spread.
            entry = medians.setdefault(b["run_name"], {})
            entry[b.get("aggregate_name")] = (b["real_time"] * scale, b)
            continue
        if b.get("run_type") != "iteration":
            continue
        counters = {k: v for k, v in b.items() if k not in (
            "name", "family_index", "per_family_instance_index", "run_name", "run_type",
            "repetitions", "repetition_index", "threads", "iterations", "real_time", "cpu_time",
            "time_unit", "aggregate_name", "aggregate_unit", "label", "error_occurred",
            "error_message")}
        runs.setdefault(b["run_name"], []).append((b["real_time"] * scale, counters))
    table = {}
    for name, values in runs.items():
        values.sort(key=lambda v: v[0])
        median = values[len(values) // 2]
        table[name] = (median[0], f"{readable(values[0][0])} – {readable(values[-1][0])}",
                       median[1])
    for name, entry in medians.items():
        if name in table or "median" not in entry:
            continue
        median, record = entry["median"]
        cv = entry.get("cv", (None, {}))[1].get("real_time")
        counters = {k: v for k, v in record.items() if isinstance(v, (int, float)) and k not in (
            "family_index", "per_family_instance_index", "repetitions", "threads", "iterations",
            "real_time", "cpu_time")}
        table[name] = (median, "-" if cv is None else f"cv {100 * cv:.0f}%", counters)
    return table


def counter_text(counters):
    parts = []
    for key, value in sorted(counters.items()):
        if isinstance(value, (int, float)):
            parts.append(f"{key} {value:.4g}")
    return ", ".join(parts)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--repetitions", type=int, default=3)
    parser.add_argument("--only", default="")
    parser.add_argument("--filter", default="")
    parser.add_argument("out")
    args = parser.parse_args()
    programs = args.only.split(",") if args.only else PROGRAMS
    commit = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"],
                            capture_output=True, text=True).stdout.strip()
    load_before = os.getloadavg()[0]
    sections = []
    for program in programs:
        path = os.path.join(args.build, "benchmarks", program)
        table = run(path, args.repetitions, args.filter)
        rows = [f"## {TITLES.get(program, program)}", "",
                f"`build/benchmarks/{program}`", "",
                "| benchmark | median | min – max (or the coefficient of variation) | counters (median run) |", "|---|---|---|---|"]
        for name, (median, range_text, counters) in table.items():
            rows.append(f"| `{name}` | {readable(median)} | {range_text} | "
                        f"{counter_text(counters)} |")
        sections.append("\n".join(rows))
        print(f"{program}: {len(table)} benchmarks", flush=True)
    load_after = os.getloadavg()[0]
    shown = " ".join(
        (["--only", args.only] if args.only else []) + (["--filter", args.filter] if args.filter
                                                        else []) +
        ["--repetitions", str(args.repetitions), "OUT.md"])
    head = [
        "# Benchmarks", "",
        f"Command: `python3 scripts/benchmarks.py {shown}` at commit {commit}, "
        f"{datetime.date.today().isoformat()}, Release build, on {os.cpu_count()} cores; load "
        f"average {load_before:.2f} at the start and {load_after:.2f} at the end.", "",
        f"Each benchmark ran {args.repetitions} times (Google Benchmark repetitions); the table "
        "gives the median wall-clock time per iteration, the fastest and slowest repetition, and "
        "the median run's counters; benchmarks that repeat themselves and report only their "
        "aggregates give their coefficient of variation instead of the range. What each benchmark measures, and what its cost depends on: "
        "docs/performance.md.", ""]
    with open(args.out, "w") as f:
        f.write("\n".join(head + ["\n\n".join(sections)]) + "\n")


if __name__ == "__main__":
    main()
