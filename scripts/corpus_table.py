#!/usr/bin/env python3
"""The corpus table (docs/results/corpus.md): every exemplar of data/corpus/MANIFEST.tsv (and any
further SVG folders given, read with --tile as seamless tiles), synthesised as a user would
(`shapeproc synthesize EXEMPLAR FLAGS --size 2W,2H --seed S`, every other flag at its default) at
several seeds, and the output measured against its exemplar with `shapeproc stats --against`:

  whether it was refused; density overall and per category of 10 or more elements; the shares of
  each category's elements inside, or overlapping, another category's (against the exemplar's);
  W1 of nearest-neighbour distances in the exemplar's mean spacings; the patch copy share (with its
  chance level); the seconds of the whole command, fit included.

Rows are min / median / max over the seeds. Targets (docs/fit.md): no refusal; density within
±15% overall and ±25% per category; relation shares within 0.15; W1 at most 0.2 mean spacings.

Usage: python3 scripts/corpus_table.py [--seeds 1,2,3] [--timeout 600] [--only A,B]
       [--tiles DIR] OUT.md
"""
import argparse
import csv
import datetime
import json
import os
import statistics
import subprocess
import tempfile
import time

from novelty_table import strip_text_chunks

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SHAPEPROC = os.environ.get("SHAPEPROC", os.path.join(ROOT, "build", "tools", "shapeproc"))
# The build whose `stats` measures every output (SHAPEPROC_STATS): the same by default; another
# build's outputs (an earlier version's) are measured by this one's.
STATS = os.environ.get("SHAPEPROC_STATS", os.path.join(ROOT, "build", "tools", "shapeproc"))
CORPUS = os.path.join(ROOT, "data", "corpus")


def run(args, timeout, program=None):
    start = time.monotonic()
    p = subprocess.run([program or SHAPEPROC] + args, capture_output=True, text=True,
                       timeout=timeout)
    return p, time.monotonic() - start


def last_line(p, work):
    return (p.stderr.strip().splitlines() or ["?"])[-1].replace(work + os.sep, "")


def measure(path, flags, seed, timeout, pictures):
    """One output: a dict of figures, or {'error': text}."""
    name = os.path.splitext(os.path.basename(path))[0]
    with tempfile.TemporaryDirectory() as work:
        out = os.path.join(work, "out.svg")
        png = os.path.join(pictures, f"{name}-seed{seed}.png")
        command = ["synthesize", path, *flags, "--size", "2W,2H", "--seed", str(seed), "-o", out,
                   "--png", png, "--force"]
        try:
            p, seconds = run(command, timeout)
            if os.path.exists(png):
                strip_text_chunks(png)  # the command line there holds this machine's paths
        except subprocess.TimeoutExpired:
            return {"error": f"timed out after {timeout:g} s"}
        if p.returncode != 0:
            return {"error": last_line(p, work), "seconds": seconds}
        q, _ = run(["stats", out, "--against", path, *flags, "--json"], 600, STATS)
        e, _ = run(["stats", path, *flags, "--json"], 600, STATS)
        if q.returncode != 0 or e.returncode != 0:
            return {"error": "stats: " + last_line(q if q.returncode else e, work)}
        s, x = json.loads(q.stdout), json.loads(e.stdout)
    cats = s["categories"]
    wanted = sum(c["count"] / c["intensity_ratio"] for c in cats if c.get("intensity_ratio"))
    ex_counts = {c["name"]: c["count"] for c in x["categories"]}
    per_cat = [c["intensity_ratio"] for c in cats
               if c.get("intensity_ratio") is not None and ex_counts.get(c["name"], 0) >= 10]
    relation = 0.0
    ex_rel = {c["name"]: c for c in x["categories"]}
    for c in cats:
        r = ex_rel.get(c["name"], {})
        for key in ("nested", "overlapping"):
            if key in c and key in r:
                relation = max(relation, abs(c[key] - r[key]))
    w1 = s["all"]["w1"]["nearest"] * s["w1_scale"] / x["mean_spacing"]
    novelty = s.get("novelty", {})
    return {"density": sum(c["count"] for c in cats) / max(wanted, 1e-9),
            "worst": max(per_cat, key=lambda r: abs(r - 1)) if per_cat else None,
            "relation": relation, "w1": w1, "seconds": seconds,
            "patch": novelty.get("output", {}).get("patch"),
            "patch_chance": novelty.get("chance", {}).get("patch")}


def exemplar_points(path, flags):
    """The exemplar's element centres and window (x0, x1, y0, y1): CSV columns x, y with the
    --window flag, or an SVG's circles and viewBox; None for anything else."""
    if path.endswith(".csv") and "--window" in flags:
        window = [float(v) for v in flags[flags.index("--window") + 1].split(",")][:4]
        with open(path) as f:
            points = [(float(r["x"]), float(r["y"])) for r in csv.DictReader(f)]
        return points, window
    if path.endswith(".svg"):
        import xml.etree.ElementTree as ET
        root = ET.parse(path).getroot()
        box = [float(v) for v in root.get("viewBox", "").split()]
        circles = [e for e in root.iter() if e.tag.endswith("circle")]
        if len(box) != 4 or not circles:
            return None
        points = [(float(c.get("cx")), float(c.get("cy"))) for c in circles]
        return points, [box[0], box[0] + box[2], box[1], box[1] + box[3]]
    return None


def natural_spread(path, flags, multiple=2.0):
    """The standard deviation of the element count of a piece of multiple x multiple windows of a
    stationary pattern with the exemplar's second-order structure, over its mean:
    Var N(A) = λ|A| (1 + λ (K(R) − πR²)) for A much larger than the range R of the correlations,
    with Ripley's K estimated from the exemplar (translation edge correction) at R, a quarter of
    the window's shorter side. A clustered or layered pattern varies far more than a Poisson one
    of its density. None when the exemplar's positions cannot be read here."""
    read = exemplar_points(path, flags)
    if read is None:
        return None
    points, (x0, x1, y0, y1) = read
    a, b = x1 - x0, y1 - y0
    n = len(points)
    if n < 2:
        return None
    radius = min(a, b) / 4
    k = 0.0
    for i, (px, py) in enumerate(points):
        for qx, qy in points[i + 1:]:
            dx, dy = abs(px - qx), abs(py - qy)
            if dx * dx + dy * dy <= radius * radius and dx < a and dy < b:
                k += 2 * a * b / ((a - dx) * (b - dy))
    k *= a * b / (n * (n - 1))
    density = n / (a * b)
    area = multiple * multiple * a * b
    variance_ratio = max(1.0 + density * (k - 3.141592653589793 * radius * radius), 0.0)
    return (variance_ratio / (density * area)) ** 0.5


def spread(values, fmt):
    values = [v for v in values if v is not None]
    if not values:
        return "-"
    return " / ".join(fmt(v) for v in (min(values), statistics.median(values), max(values)))


def table_row(name, results, natural=None):
    failed = [r["error"] for r in results if "error" in r]
    made = [r for r in results if "error" not in r]
    if not made:
        return (f"| {name} | {len(failed)} of {len(results)}: {failed[0]} | - | - | - | - | - | - "
                f"| - | - |")
    ok = lambda r: (0.85 <= r["density"] <= 1.15 and (r["worst"] is None or 0.75 <= r["worst"] <= 1.25)
                    and r["relation"] <= 0.15 and r["w1"] <= 0.2)
    return (f"| {name} | {len(failed) and f'{len(failed)}: ' + failed[0] or 'none'} "
            f"| {spread([r['density'] for r in made], lambda v: f'×{v:.2f}')} "
            f"| {spread([r['worst'] for r in made], lambda v: f'×{v:.2f}')} "
            f"| {spread([r['relation'] for r in made], lambda v: f'{v:.2f}')} "
            f"| {spread([r['w1'] for r in made], lambda v: f'{v:.2f}')} "
            f"| {spread([r['patch'] for r in made], lambda v: f'{v:.2f}')} "
            f"| {spread([r['seconds'] for r in made], lambda v: f'{v:.0f}')} "
            f"| {sum(map(ok, made))} of {len(results)} "
            f"| {'-' if natural is None else ('<1%' if natural < 0.005 else f'±{100 * natural:.0f}%')} |")


def exemplars(args):
    corpus = os.path.abspath(args.corpus)
    with open(os.path.join(corpus, "MANIFEST.tsv")) as f:
        for row in csv.DictReader(f, delimiter="\t"):
            yield row["file"], os.path.join(corpus, row["file"]), row["flags"].split()
    for folder in args.tiles:
        for file in sorted(os.listdir(folder)):
            if file.endswith(".svg"):
                yield file + " (tile)", os.path.join(folder, file), ["--tile"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", default="1,2,3")
    parser.add_argument("--timeout", type=float, default=600)
    parser.add_argument("--only", default="",
                        help="exemplars to keep, by file name, comma-separated, run in that order")
    parser.add_argument("--tiles", action="append", default=[], help="a folder of seamless tiles")
    parser.add_argument("--corpus", default=CORPUS,
                        help="a folder with a MANIFEST.tsv (data/corpus/held-out: the held-out one)")
    parser.add_argument("out")
    args = parser.parse_args()
    held_out = os.path.abspath(args.corpus) != CORPUS
    pictures = os.path.join(os.path.dirname(os.path.abspath(args.out)),
                            "corpus-held-out" if held_out else "corpus")
    os.makedirs(pictures, exist_ok=True)
    commit = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"],
                            capture_output=True, text=True).stdout.strip()
    # The output as the reader would type it: relative to the repository, or a placeholder.
    out = os.path.abspath(args.out)
    shown_out = os.path.relpath(out, ROOT) if out.startswith(ROOT + os.sep) else "OUT.md"
    shown = " ".join([f"--seeds {args.seeds}", f"--timeout {args.timeout:g}"]
                     + ([f"--only {args.only}"] if args.only else [])
                     + [f"--tiles {os.path.relpath(t, ROOT)}" for t in args.tiles]
                     + ([f"--corpus {os.path.relpath(os.path.abspath(args.corpus), ROOT)}"]
                        if held_out else []) + [shown_out])
    lines = [
        "# The held-out corpus: the same kinds, drawn again" if held_out else
        "# The corpus: every exemplar, several seeds", "",
        f"Command: `python3 scripts/corpus_table.py {shown}` at commit {commit}, "
        f"{datetime.date.today().isoformat()}, on 2 cores.", "",
        "Each output: `shapeproc synthesize EXEMPLAR FLAGS --size 2W,2H --seed S` (FLAGS from "
        f"{os.path.relpath(os.path.abspath(args.corpus), ROOT)}/MANIFEST.tsv), measured by `shapeproc stats OUTPUT --against EXEMPLAR`. "
        "Figures are min / median / max over the seeds. Density: the output's count over the "
        "exemplar's density times its area; worst category: the category of 10 or more elements "
        "farthest from ×1; relation: the largest difference, over categories, between the output's "
        "and the exemplar's shares of elements inside or overlapping another category's; W1: of "
        "nearest-neighbour distances, in the exemplar's mean spacings; patch copy share: 0 is new "
        "(docs/metrics.md). A seed meets the targets with density ×0.85–×1.15, every category "
        "×0.75–×1.25, relation ≤ 0.15 and W1 ≤ 0.2. Natural spread: one standard deviation of "
        "the count of a 2W × 2H piece of a stationary pattern with the exemplar's Ripley's K, "
        "over its mean (Var N = λ|A|(1 + λ(K(R) − πR²)), R a quarter of the window's shorter "
        "side; '-' where this script cannot read the positions): a faithful model's outputs vary "
        "by that much from seed to seed, so a density target narrower than twice it is missed "
        "by chance.", "",
        "| exemplar | refused | density | worst category | relation | W1 / spacing | patch copy "
        "share | seconds | seeds on target | natural spread |",
        "|---|---|---|---|---|---|---|---|---|---|",
    ]
    seeds = [int(s) for s in args.seeds.split(",")]
    chosen = list(exemplars(args))
    if args.only:  # in the order given
        order = args.only.split(",")
        chosen = sorted((e for e in chosen if e[0] in order), key=lambda e: order.index(e[0]))
    for name, path, flags in chosen:
        results = [measure(path, flags, seed, args.timeout, pictures) for seed in seeds]
        line = table_row(name, results, natural_spread(path, flags))
        print(line, flush=True)
        lines.append(line)
    with open(args.out, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
