#!/usr/bin/env bash
# The fidelity table (docs/fit.md) over a folder of exemplars: for each one, `shapeproc fidelity`
# fits it (maximum likelihood unless the options say otherwise) and checks that the model
# reproduces it. Options after the folder go to every `shapeproc fidelity` call, e.g.
#   bash scripts/fidelity.sh data/svg
#   bash scripts/fidelity.sh tiles/ --split-subpaths --edge periodic
# Columns: elements of the exemplar; largest |z| of the element counts (categories and shape
# classes) and of the pair counts, 50 chains on the exemplar's own window, in standard errors that
# add the fit's own Monte Carlo error (bands the attraction prior holds down are left out and
# counted as "held"); mean density ± its standard error of 4 outputs (--outputs) of 2 x 2
# exemplars (torus) against the exemplar's; colliding pairs in the exemplar / all outputs;
# p-value of the chi-square test of the outputs' pooled shape classes (their number in brackets).
set -uo pipefail
cd "$(dirname "$0")/.."
if [ $# -lt 1 ] || [ ! -d "$1" ]; then
  echo "usage: scripts/fidelity.sh DIR [shapeproc fidelity options]" >&2
  exit 2
fi
dir=$1
shift
shapeproc=${SHAPEPROC:-./build/tools/shapeproc}
echo "| exemplar | elements | counts max abs(z) | pairs max abs(z) | density ratio (mean ± se) | collisions exemplar / outputs | class chi-square p (classes) |"
echo "|---|---|---|---|---|---|---|"
for file in "$dir"/*.svg "$dir"/*.obj "$dir"/*.csv; do
  [ -e "$file" ] || continue
  if ! row=$("$shapeproc" fidelity "$file" --row --quiet "$@" 2>&1); then
    row="| $(basename "$file") | failed: $(tail -n 1 <<< "$row") |"
  fi
  echo "$row"
done
