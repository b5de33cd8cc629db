#!/usr/bin/env bash
# Regenerates the README's pictures (docs/images/*-exemplar.png, *-synthesis.png): for each
# exemplar, fit and sample four times its area, then write a report whose two pictures share one
# scale. Needs a build (bash scripts/build.sh --target shapeproc). Work files go to out/gallery/.
set -euo pipefail
cd "$(dirname "$0")/.."
shapeproc=./build/tools/shapeproc
mkdir -p out/gallery docs/images
picture() {  # name exemplar size "reader options" [more synthesize options...]
  local name=$1 exemplar=$2 size=$3 reader=$4
  shift 4
  local output="out/gallery/$name-synthesis.${exemplar##*.}"
  # shellcheck disable=SC2086  # the reader options are words
  "$shapeproc" synthesize "$exemplar" $reader "$@" --model "out/gallery/$name-model.json" --size "$size" --seed 1 --force -o "$output"
  # shellcheck disable=SC2086
  "$shapeproc" report "$exemplar" "$output" $reader --model "out/gallery/$name-model.json" -o "out/gallery/$name-report"
  cp "out/gallery/$name-report/exemplar.png" "docs/images/$name-exemplar.png"
  cp "out/gallery/$name-report/output-1.png" "docs/images/$name-synthesis.png"
}
picture two-kinds data/svg/two-kinds.svg 440,440 "--category-by fill"
picture dashes-rows data/svg/dashes-rows.svg 480,320 ""
picture crescents-grid data/svg/crescents-grid.svg 500,500 ""
picture pebbles data/mesh/pebbles.obj 22.6,22.4,5.3 "" --iterations 20000
echo "pictures are in docs/images/"
