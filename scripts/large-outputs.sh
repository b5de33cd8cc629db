#!/usr/bin/env bash
# Writes docs/results/large-outputs.md: is a large decomposed output stationary? Fits
# data/svg/dots-random.svg, samples outputs of about 100,000 elements (--threads 2, the automatic
# stop) for seeds 1 and 2, and compares their density with a long whole-domain run of the same
# model on a 1000 x 1000 torus (30,000,000 steps; the mean count over its second half, with a
# batch-means standard error). Needs a build (bash scripts/build.sh). About 3 minutes on 2 cores;
# MILLION=1 adds an output of about 1,000,000 elements (seed 1, about 5 more minutes).
set -euo pipefail
cd "$(dirname "$0")/.."
out=docs/results/large-outputs.md
bin=./build/tools/shapeproc
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$bin" fit data/svg/dots-random.svg -o "$work/model.json" -q > /dev/null
side=11550
runs="1:$side 2:$side"
[ "${MILLION:-0}" = 1 ] && runs="$runs 1:36524"
for run in $runs; do
  seed=${run%%:*} size=${run#*:}
  start=$(date +%s.%N)
  "$bin" sample "$work/model.json" --size "$size,$size" --threads 2 --seed "$seed" \
    -o "$work/large-$seed-$size.csv" --force > "$work/large-$seed-$size.log" 2>&1
  end=$(date +%s.%N)
  echo "$seed-$size $(python3 -c "print($end - $start)")" >> "$work/seconds"
done
"$bin" sample "$work/model.json" --size 1000,1000 --seed 7 --iterations 30000000 \
  --trace "$work/reference.csv" -o "$work/reference-out.csv" --force -q > /dev/null
python3 - "$work" "$runs" "$out" "$(git rev-parse --short HEAD)" <<'PY'
import datetime, math, os, sys
work, runs, out, commit = sys.argv[1], sys.argv[2].split(), sys.argv[3], sys.argv[4]
counts = [float(l.split(",")[1]) for l in open(os.path.join(work, "reference.csv"))
          if l[0].isdigit()]
half = counts[len(counts) // 2:]
mean = sum(half) / len(half)
size = len(half) // 10
batches = [sum(half[i * size:(i + 1) * size]) / size for i in range(10)]
se = math.sqrt(sum((b - mean) ** 2 for b in batches) / 9 / 10)
reference = mean / 1e6
seconds = dict(l.split() for l in open(os.path.join(work, "seconds")))
lines = [
    "# Large outputs: stationary?", "",
    f"Command: `{'MILLION=1 ' if len(runs) > 2 else ''}bash scripts/large-outputs.sh` at commit {commit}, "
    f"{datetime.date.today().isoformat()}, 2 threads.", "",
    "Model: `shapeproc fit data/svg/dots-random.svg` (defaults). Reference: one whole-domain chain "
    "on a 1000 × 1000 torus, 30,000,000 steps, mean count over its second half: density "
    f"{reference:.4e} per px² (standard error {se / mean:.2%}, batch means).", "",
    f"| seed | output | elements | sweeps | density against the reference | seconds |",
    "|---|---|---|---|---|---|",
]
for run in runs:
    seed, side = run.split(":")
    name = f"{seed}-{side}"
    side = float(side)
    n = sum(1 for l in open(os.path.join(work, f"large-{name}.csv")) if l[:1].isdigit() or l[:1] == "-")
    log = open(os.path.join(work, f"large-{name}.log")).read()
    sweeps = log.split("sweeps ")[1].split(",")[0] if "sweeps " in log else "?"
    ratio = n / (side * side) / reference
    lines.append(f"| {seed} | {side:.0f} × {side:.0f} | {n:,} | {sweeps} | ×{ratio:.4f} | "
                 f"{float(seconds[name]):.1f} |")
open(out, "w").write("\n".join(lines) + "\n")
print("wrote", out)
PY
