#!/usr/bin/env python3
"""The parameters the default fit chooses per exemplar of data/corpus (docs/results/
corpus-parameters.md): `shapeproc fit EXEMPLAR FLAGS` (FLAGS from data/corpus/MANIFEST.tsv), then
`shapeproc show`, whose lines say the fit's path, each pair's chosen axes and bands (and why), the
parameters fitted and the density check on the output's scale.

Usage: python3 scripts/corpus_parameters.py [--only A,B] [--timeout 600] OUT.md
"""
import argparse
import csv
import datetime
import os
import subprocess
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SHAPEPROC = os.environ.get("SHAPEPROC", os.path.join(ROOT, "build", "tools", "shapeproc"))
CORPUS = os.path.join(ROOT, "data", "corpus")


# The fit's notes that say what it chose: layers, saturation, clusters and the density check.
CHOICE_NOTES = ("note: density on a torus", "note: layer ", "note: saturation ", "note: clusters: ")


def summary(show):
    """The lines of `show` that say what was chosen."""
    out, pair = [], None
    for line in show.splitlines():
        if line.startswith("pair "):
            pair = line.split(":", 1)[1].split("(")[0].strip()
            out.append(f"- {pair}: every axis and band its thresholds gave")
        elif line.strip().startswith("chosen:") and pair:
            out[-1] = f"- {pair}: {line.strip()[len('chosen: '):]}"
        elif line.startswith("path:"):
            out.insert(0, f"- {line}")
        elif line.startswith(CHOICE_NOTES) or "of clustered categories set to 1" in line:
            out.append(f"- {line[len('note: '):]}")
        elif "saturated at" in line and pair:
            out[-1] += " (some bands saturated: see `show`)" if "saturated" not in out[-1] else ""
    return out


def gammas(show):
    return sum(line.count("|") for line in show.splitlines() if line.strip().startswith("axis"))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--only", default="")
    parser.add_argument("--timeout", type=float, default=600)
    parser.add_argument("out")
    args = parser.parse_args()
    only = [o for o in args.only.split(",") if o]
    with open(os.path.join(CORPUS, "MANIFEST.tsv")) as f:
        rows = {r["file"]: r for r in csv.DictReader(f, delimiter="\t")}
    names = only or list(rows)
    commit = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"],
                            capture_output=True, text=True).stdout.strip()
    # The output as the reader would type it: relative to the repository, or a placeholder.
    out = os.path.abspath(args.out)
    shown_out = os.path.relpath(out, ROOT) if out.startswith(ROOT + os.sep) else "OUT.md"
    shown = (f"--only {args.only} " if args.only else "") + f"--timeout {args.timeout:g} {shown_out}"
    lines = ["# The parameters the default fit chooses, per corpus exemplar", "",
             f"Command: `python3 scripts/corpus_parameters.py {shown}` at commit {commit}, "
             f"{datetime.date.today().isoformat()}, on 2 cores.", "",
             "Each exemplar: `shapeproc fit EXEMPLAR FLAGS` (FLAGS from data/corpus/MANIFEST.tsv), "
             "then `shapeproc show`: the fit's path, per pair of categories the axes and bands "
             "kept and why (docs/fit.md, \"As many parameters as the data carry\"), the count of "
             "band strengths γ, the layers (docs/fit.md, \"Layers and anchors\") and the "
             "density check on a torus of 2 x 2 windows.", ""]
    for name in names:
        row = rows[name]
        with tempfile.TemporaryDirectory() as work:
            model = os.path.join(work, "model.json")
            try:
                p = subprocess.run([SHAPEPROC, "fit", os.path.join(CORPUS, name),
                                    *row["flags"].split(), "-o", model],
                                   capture_output=True, text=True, timeout=args.timeout)
            except subprocess.TimeoutExpired:
                lines += [f"## {name}", "", f"timed out after {args.timeout:g} s", ""]
                continue
            if p.returncode != 0:
                lines += [f"## {name}", "", "refused: " + p.stderr.strip().splitlines()[-1], ""]
                continue
            show = subprocess.run([SHAPEPROC, "show", model], capture_output=True,
                                  text=True).stdout
        lines += [f"## {name}", "", f"{row['what']}; {gammas(show)} band strengths γ.", ""]
        lines += summary(show) + [""]
        print(name, flush=True)
    with open(args.out, "w") as f:
        f.write("\n".join(lines))


if __name__ == "__main__":
    main()
