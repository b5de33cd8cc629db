#!/usr/bin/env bash
# Regenerates the gallery (docs/images/*-exemplar.png, *-synthesis.png; the README shows
# two-kinds, docs/results/gallery.md all of them): for each
# exemplar, fit and sample four times its area, then write a report whose two pictures share one
# scale. Needs a build (bash scripts/build.sh --target shapeproc). Work files go to out/gallery/.
# Names given (e.g. `bash scripts/gallery.sh two-kinds hero-bubbles`) regenerate only those; a
# run of all of them also writes their reports' verdicts to docs/results/gallery.md.
set -euo pipefail
cd "$(dirname "$0")/.."
shapeproc=./build/tools/shapeproc
mkdir -p out/gallery docs/images
wanted=("$@")
picture() {  # name exemplar size "reader options" [more synthesize options...]
  local name=$1 exemplar=$2 size=$3 reader=$4
  shift 4
  if [ ${#wanted[@]} -gt 0 ] && [[ ! " ${wanted[*]} " == *" $name "* ]]; then return; fi
  local output="out/gallery/$name-synthesis.${exemplar##*.}"
  # shellcheck disable=SC2086  # the reader options are words
  "$shapeproc" synthesize "$exemplar" $reader "$@" --model "out/gallery/$name-model.json" --size "$size" --seed 1 --force -o "$output"
  # shellcheck disable=SC2086
  "$shapeproc" report "$exemplar" "$output" $reader --model "out/gallery/$name-model.json" -o "out/gallery/$name-report"
  # A tile's report draws it repeated; the gallery shows the tile itself (docs/images/hero-*-tile.png).
  [[ $name == hero-* ]] || cp "out/gallery/$name-report/exemplar.png" "docs/images/$name-exemplar.png"
  cp "out/gallery/$name-report/output-1.png" "docs/images/$name-synthesis.png"
  reported+=("$name")
}
reported=()
picture two-kinds data/svg/two-kinds.svg 440,440 "--category-by fill"
picture dashes-rows data/svg/dashes-rows.svg 480,320 ""
picture crescents-grid data/svg/crescents-grid.svg 500,500 ""
picture pebbles data/mesh/pebbles.obj 22.6,22.4,5.3 "" --iterations 20000
# Seamless tiles over 3 x 3 tiles' area.
picture hero-bubbles data/third-party/hero-patterns/bubbles.svg 300,300 "--tile"
picture hero-tic-tac-toe data/third-party/hero-patterns/tic-tac-toe.svg 192,192 "--tile"
echo "pictures are in docs/images/"
[ ${#wanted[@]} -eq 0 ] || exit 0
{
  echo "# Gallery"
  echo
  echo "Command: \`bash scripts/gallery.sh\` at commit $(git rev-parse --short HEAD), $(date -u +%Y-%m-%d)."
  echo
  echo "Each output: \`shapeproc synthesize\` at seed 1 with the size and options in scripts/gallery.sh,"
  echo "from empty, judged by \`shapeproc report\` against its exemplar (docs/metrics.md, \"Verdicts\")."
  echo "Exemplar (a tile: the tile itself) and output are drawn at one scale."
  echo
  for name in "${reported[@]}"; do
    echo "## $name"
    echo
    exemplar="$name-exemplar.png"
    [[ $name == hero-* ]] && exemplar="$name-tile.png"
    echo "<img src=\"../images/$exemplar\" height=\"200\" alt=\"$name exemplar\"> <img src=\"../images/$name-synthesis.png\" height=\"300\" alt=\"$name output\">"
    echo
    cat "out/gallery/$name-report/verdicts.md"
    echo
  done
} > docs/results/gallery.md
echo "verdicts are in docs/results/gallery.md"
