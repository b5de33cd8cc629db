#!/usr/bin/env python3
"""The novelty table (docs/results/novelty.md): every exemplar of the folders given, synthesised as
a user would (`shapeproc synthesize`, defaults, an output of 3 x 3 exemplars' size), judged by
`shapeproc report` against its exemplar. One row per exemplar and seed:

  births and deaths accepted (of those proposed) by the output's chain; copy share and patch copy
  share with their chance levels, the largest copied patch and the repetition at the exemplar's
  period (docs/metrics.md, "Novelty"); density against the exemplar's; the class mix's p; overlaps;
  order; seconds of the whole synthesize command (fit included); the report's failed checks.

Usage: python3 scripts/novelty_table.py [--seeds 1,2,3,4] [--timeout 120] [--tile] [--flags F]
       [--multiple N] [--only A,B,...] OUT.md DIR...
Folders of .svg files; --tile reads them as seamless tiles (Hero Patterns); --only keeps the
exemplars named; --multiple N makes outputs of N x N exemplars' size (default 3). The pictures of
each output are kept in OUT's folder under novelty/ (PNG); with --flags or another multiple, under
novelty-FLAGS/ or novelty-Nx/.
"""
import argparse
import datetime
import json
import os
import re
import struct
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SHAPEPROC = os.environ.get("SHAPEPROC", os.path.join(ROOT, "build", "tools", "shapeproc"))


def run(args, timeout):
    start = time.monotonic()
    p = subprocess.run([SHAPEPROC] + args, capture_output=True, text=True, timeout=timeout)
    return p, time.monotonic() - start


def window_of(path, tile):
    p, _ = run(["info", path, "--json"] + (["--tile"] if tile else []), 60)
    if p.returncode != 0:
        raise RuntimeError(p.stderr.strip().splitlines()[-1] if p.stderr else "info failed")
    w = json.loads(p.stdout)["window"]
    return [hi - lo for lo, hi in zip(w["min"], w["max"])]


def strip_text_chunks(png):
    """Drops a PNG's text chunks: they hold the command line, with the local paths of whoever ran it."""
    with open(png, "rb") as f:
        data = f.read()
    out, i = [data[:8]], 8
    while i < len(data):
        length = struct.unpack(">I", data[i:i + 4])[0]
        if data[i + 4:i + 8] not in (b"tEXt", b"iTXt", b"zTXt"):
            out.append(data[i:i + 12 + length])
        i += 12 + length
    with open(png, "wb") as f:
        f.write(b"".join(out))


def counter(text, name):
    """The sampler's counter `name` (accepted / proposed), and the growth stages' own in brackets
    where the compressing burn-in ran."""
    m = re.search(r"(?<!growth )" + name + r"\D*(\d+)/(\d+)", text)
    shown = f"{int(m.group(1)):,} / {int(m.group(2)):,}" if m else "-"
    g = re.search(r"growth " + name + r"\D*(\d+)/(\d+)", text)
    return shown + (f" (growth {int(g.group(1)):,} / {int(g.group(2)):,})" if g else "")


def verdict(entry, check):
    for v in entry.get("verdicts", []):
        if v["check"] == check:
            return v
    return None


def row(path, seed, args, pictures):
    name = os.path.splitext(os.path.basename(path))[0]
    size = window_of(path, args.tile)
    with tempfile.TemporaryDirectory() as work:
        out = os.path.join(work, "out.svg")
        png = os.path.join(pictures, f"{name}-seed{seed}.png")
        reader = ["--tile"] if args.tile else []
        command = ["synthesize", path, *reader, "--size", ",".join(f"{args.multiple * s:g}" for s in size),
                   "--seed", str(seed), "-o", out, "--png", png, "--force", *args.flags.split()]
        try:
            p, seconds = run(command, args.timeout)
        except subprocess.TimeoutExpired:
            return f"| {name} | {seed} | timed out after {args.timeout} s |"
        if p.returncode != 0:
            last = (p.stderr.strip().splitlines() or ["?"])[-1].replace(work + os.sep, "")
            return f"| {name} | {seed} | failed: {last} |"
        if os.path.exists(png):
            strip_text_chunks(png)
        q, _ = run(["report", path, out, *reader, "-o", os.path.join(work, "report")], 600)
        if q.returncode != 0:
            last = (q.stderr.strip().splitlines() or ["?"])[-1].replace(work + os.sep, "")
            return f"| {name} | {seed} | report failed: {last} |"
        with open(os.path.join(work, "report", "metrics.json")) as f:
            entry = json.load(f)["outputs"][0]
    n = entry.get("novelty", {})
    o, c = n.get("output", {}), n.get("chance", {})
    ratio = sum(x["count"] for x in entry["categories"]) / max(1e-9, sum(
        x["count"] / x["intensity_ratio"] for x in entry["categories"] if x.get("intensity_ratio")))
    mix = verdict(entry, "shape mix")
    order = verdict(entry, "order")
    failed = [v["check"] for v in entry.get("verdicts", []) if v["outcome"] == "fail"]
    lattice = " (lattice)" if n.get("lattice_exemplar") else ""
    fmt = lambda v: f"{v:.2f}" if isinstance(v, (int, float)) else "-"
    return (f"| {name} | {seed} | {counter(p.stdout, 'births accepted')} | {counter(p.stdout, 'deaths')} "
            f"| {fmt(o.get('copy'))} ({fmt(c.get('copy'))}) | {fmt(o.get('patch'))} ({fmt(c.get('patch'))}){lattice} "
            f"| {fmt(o.get('largest_patch'))} | {fmt(o.get('repetition'))} ({fmt(c.get('repetition'))}) "
            f"| ×{ratio:.2f} | {mix['shown'] if mix else '-'} | {entry['collisions']['pairs']} "
            f"| {order['shown'] if order else '-'} | {seconds:.1f} | {', '.join(failed) or 'none'} |")


def shown_arguments(args):
    """The command's arguments as the header shows them: the folders by --name when given."""
    shown = [f"--seeds {args.seeds}", f"--timeout {args.timeout:g}"]
    if args.tile:
        shown.append("--tile")
    if args.flags:
        shown.append(f"--flags '{args.flags}'")
    if args.multiple != 3:
        shown.append(f"--multiple {args.multiple}")
    if args.only:
        shown.append(f"--only {args.only}")
    return " ".join(shown + [args.out] + ([args.name] if args.name else args.dirs))


def summary(rows):
    """One paragraph of totals over the rows that were made."""
    made = [[x.strip() for x in r.strip().strip("|").split("|")] for r in rows]
    made = [c for c in made if len(c) >= 14]
    if not made:
        return ["", "No row could be made."]
    density = [float(c[8].lstrip("×")) for c in made]
    seconds = [float(c[12]) for c in made]
    births = sum(1 for c in made if not c[2].startswith("0 "))
    deaths = sum(1 for c in made if not c[3].startswith("0 "))
    repeats = sum(1 for c in made if "novelty" in c[13])
    return ["", f"Totals over {len(made)} of {len(rows)} rows: births accepted in {births}, deaths "
            f"in {deaths}; density within ×0.9–×1.1 in {sum(0.9 <= d <= 1.1 for d in density)}; "
            f"'repeats the exemplar' in {repeats}; overlapping pairs in "
            f"{sum(1 for c in made if c[10] != '0')}; seconds {min(seconds):.1f} to "
            f"{max(seconds):.1f}, over 30 s in {sum(s > 30 for s in seconds)}."]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", default="1,2,3,4")
    parser.add_argument("--timeout", type=float, default=120)
    parser.add_argument("--tile", action="store_true")
    parser.add_argument("out")
    parser.add_argument("dirs", nargs="+")
    parser.add_argument("--name", help="how the header names the folders (default: as given)")
    parser.add_argument("--flags", default="",
                        help="further synthesize flags, e.g. '--near-births 0.5' (default: none)")
    parser.add_argument("--multiple", type=int, default=3,
                        help="outputs of N x N exemplars' size (default 3)")
    parser.add_argument("--only", default="",
                        help="the exemplars to keep, by name without .svg, comma-separated")
    args = parser.parse_args()
    # Pictures of outputs made with further flags or another size go to a folder of their own.
    folder = "novelty" + ("-" + re.sub(r"[^a-z0-9.]+", "-", args.flags.lower()).strip("-")
                          if args.flags else "") + (f"-{args.multiple}x" if args.multiple != 3 else "")
    pictures = os.path.join(os.path.dirname(os.path.abspath(args.out)), folder)
    os.makedirs(pictures, exist_ok=True)
    commit = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"],
                            capture_output=True, text=True).stdout.strip()
    lines = [
        "# Novelty of " + (f"outputs with {args.flags}" if args.flags else "default outputs"),
        "",
        f"Command: `python3 scripts/novelty_table.py {shown_arguments(args)}` at commit {commit}, "
        f"{datetime.date.today().isoformat()}.",
        "",
        f"Each output: `shapeproc synthesize EXEMPLAR --size {args.multiple}W,{args.multiple}H --seed S"
        + (f" {args.flags}" if args.flags else "") + "` with every other flag at "
        "its default, judged by `shapeproc report` (docs/metrics.md). Chance levels in brackets: "
        "the same measure of the output's elements placed at random.",
        "",
        "| exemplar | seed | births accepted (in the growth stages) | deaths accepted | copy share (chance) | "
        "patch copy share (chance) | largest copied patch | repetition (chance) | density | "
        "class mix | overlapping pairs | order | seconds | failed checks |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    seeds = [int(s) for s in args.seeds.split(",")]
    for folder in args.dirs:
        for file in sorted(os.listdir(folder)):
            if not file.endswith(".svg"):
                continue
            if args.only and file[:-4] not in args.only.split(","):
                continue
            for seed in seeds:
                try:
                    line = row(os.path.join(folder, file), seed, args, pictures)
                except Exception as e:  # a row that could not be made says why
                    line = f"| {file} | {seed} | error: {e} |"
                print(line, flush=True)
                lines.append(line)
    lines += summary([l for l in lines if l.startswith("| ") and not l.startswith("| exemplar")])
    with open(args.out, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
