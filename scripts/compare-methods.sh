#!/usr/bin/env bash
# The shape process beside the neighbourhood EM of Ma et al. 2011 and the region growing of
# Davison et al. 2018 on a set of exemplars (docs/methods.md): for each exemplar, `synthesize`
# with each method (2W x 2H, torus, seed 1; the EM also with its interleaved physics solver,
# growth also with `--overlap shapes`; VARIANTS="davison ..." picks some), then
# `stats OUTPUT --against EXEMPLAR` with the same metrics for all. Pictures go to
# out/compare/NAME-VARIANT.png. Options after the files go to every synthesize and stats call
# (e.g. --tile for seamless tiles). Prints a markdown table.
#   bash scripts/compare-methods.sh data/svg/*.svg
#   bash scripts/compare-methods.sh --tile -- tiles/a.svg tiles/b.svg
set -uo pipefail
cd "$(dirname "$0")/.."
shapeproc=${SHAPEPROC:-./build/tools/shapeproc}
options=()
if [ "${1:-}" != "" ] && [[ "$1" == --* ]]; then
  while [ $# -gt 0 ] && [ "$1" != "--" ]; do options+=("$1"); shift; done
  shift
fi
mkdir -p out/compare
echo "| exemplar | elements | method | output elements | density ratio | overlapping pairs | touching pairs | neighbourhood distance / d² | EM energy first → last (iterations) | seconds |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for file in "$@"; do
  name=$(basename "${file%.*}")
  exemplar_json=$("$shapeproc" stats "$file" "${options[@]}" --json 2>/dev/null) || {
    echo "| $name | failed to read |"
    continue
  }
  n=$(python3 -c 'import json, sys; print(json.loads(sys.argv[1])["elements"])' "$exemplar_json")
  size=$("$shapeproc" info "$file" "${options[@]}" | sed -n 's/^window: *\[\([-0-9.e]*\), \([-0-9.e]*\)\] x \[\([-0-9.e]*\), \([-0-9.e]*\)\].*/\1 \2 \3 \4/p' |
    awk '{printf "%g,%g", 2*($2-$1), 2*($4-$3)}')
  for variant in ${VARIANTS:-shape-process ma-em ma-em-physics davison davison-shapes}; do
    method=${variant%-physics}
    method=${method%-shapes}
    extra=()
    [ "$variant" = ma-em-physics ] && extra=(--physics)
    [ "$variant" = davison-shapes ] || [ "$variant" = ijiri-shapes ] && extra=(--overlap shapes)
    [ "$variant" = ijiri-circles ] && extra=(--overlap circles)
    method=${method%-circles}
    output="out/compare/$name-$variant.svg"
    start=$(date +%s.%N)
    if ! log=$("$shapeproc" synthesize "$file" "${options[@]}" --method "$method" "${extra[@]}" \
      --size "$size" --seed 1 --quiet --force -o "$output" --png "out/compare/$name-$variant.png" 2>&1); then
      echo "| $name | $n | $variant | failed: $(tail -n 1 <<< "$log") |"
      continue
    fi
    seconds=$(echo "$(date +%s.%N) - $start" | bc)
    energy=$(sed -n 's/.*energy \([-0-9.e+]*\) -> \([-0-9.e+]*\).*/\1 \2/p' <<< "$log" | head -1)
    iterations=$(sed -n 's/.*iterations \([0-9]*\)\/\([0-9]*\).*/\1/p' <<< "$log" | head -1)
    stats=$("$shapeproc" stats "$output" --against "$file" "${options[@]}" --json 2>/dev/null)
    python3 - "$stats" "$exemplar_json" "$name" "$n" "$variant" "$seconds" "$energy" "$iterations" <<'PY'
import json, sys
s, e = json.loads(sys.argv[1]), json.loads(sys.argv[2])
name, n, method, seconds, energy, iterations = sys.argv[3:9]
ratio = (s["elements"] / s["window_measure"]) / (e["elements"] / e["window_measure"])
c = s["collisions"]
nd = s["neighbourhood_distance"]["normalised"]
em = "–"
if energy:
    first, last = (float(x) for x in energy.split())
    em = f"{first:.4g} → {last:.4g} ({iterations})"
print(f"| {name} | {n} | {method} | {s['elements']} | ×{ratio:.2f} | {c['pairs']} | {c['touching']} | {nd:.2f} | {em} | {float(seconds):.1f} |")
PY
  done
done
