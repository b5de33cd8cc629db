#!/usr/bin/env bash
# A gallery of `shapeproc compare` pages (docs/methods.md): every method on each exemplar of
# data/svg, and, given the folder of the Hero Patterns tiles, on a dozen of them (as seamless
# tiles). Each output domain is 2W x 2H of its exemplar (larger for tiles of few elements: at
# least 64 in the output), seed 1. Writes OUT/NAME/index.html for
# each exemplar, OUT/index.html linking them all and OUT/gallery.md, every page's verdict table
# under its exemplar's name.
#   bash scripts/compare-gallery.sh                      # data/svg only, into out/gallery
#   bash scripts/compare-gallery.sh HERO_FOLDER [OUT]    # and a dozen Hero tiles
# METHODS=shape-process,davison picks the methods (default: `compare`'s own, the tile repeated
# first). RESULT=docs/results/compare-gallery.md also writes the tables there, under the command,
# the commit and the date.
set -uo pipefail
cd "$(dirname "$0")/.."
shapeproc=${SHAPEPROC:-./build/tools/shapeproc}
hero=${1:-}
out=${2:-out/gallery}
methods=${METHODS:-tile,shape-process,ma-em,ijiri,davison}
tiles=(anchors-away bamboo bubbles circles-and-squares fancy-rectangles happy-intersection
  heavy-rain jupiter lines-in-motion polka-dots random-shapes tic-tac-toe)
mkdir -p "$out"
: > "$out/gallery.md"
links=()

# compare NAME FILE [reader options...]
compare() {
  local name=$1 file=$2
  shift 2
  local info size elements times
  info=$("$shapeproc" info "$file" "$@")
  # 2W x 2H, or larger for a tile of few elements: at least 64 in the output.
  elements=$(echo "$info" | sed -n 's/^elements: *\([0-9]*\).*/\1/p')
  times=$(awk -v n="${elements:-0}" 'BEGIN { t = 2; while (n > 0 && t * t * n < 64) t++; print t }')
  size=$(echo "$info" |
    sed -n 's/^window: *\[\([-0-9.e]*\), \([-0-9.e]*\)\] x \[\([-0-9.e]*\), \([-0-9.e]*\)\].*/\1 \2 \3 \4/p' |
    awk -v t="$times" '{printf "%g,%g", t*($2-$1), t*($4-$3)}')
  if [ -z "$size" ]; then
    echo "$name: cannot read its window; left out" >&2
    return
  fi
  echo "== $name ($size)" >&2
  if "$shapeproc" compare "$file" "$@" --methods "$methods" --size "$size" --seed 1 \
    -o "$out/$name" >"$out/$name.log" 2>&1; then
    { echo "### $name"; echo; cat "$out/$name/verdicts.md"; echo; } >>"$out/gallery.md"
    links+=("<li><a href=\"$name/index.html\">$name</a></li>")
  else
    echo "$name: compare failed (see $out/$name.log)" >&2
  fi
}

for file in data/svg/*.svg; do
  name=$(basename "${file%.*}")
  if [ "$name" = two-kinds ]; then compare "$name" "$file" --category-by fill; else compare "$name" "$file"; fi
done
if [ -n "$hero" ]; then
  for tile in "${tiles[@]}"; do
    [ -f "$hero/$tile.svg" ] && compare "hero-$tile" "$hero/$tile.svg" --tile
  done
fi
{
  echo '<!DOCTYPE html><html lang="en"><head><meta charset="utf-8"/><title>shapeproc gallery</title></head><body>'
  echo "<h1>Every method on each exemplar</h1><ul>"
  printf '%s\n' "${links[@]}"
  echo "</ul></body></html>"
} >"$out/index.html"
echo "wrote $out/index.html and $out/gallery.md" >&2
if [ -n "${RESULT:-}" ]; then
  {
    echo "# Every method on data/ and a dozen Hero tiles"
    echo
    echo "Command: \`RESULT=$RESULT bash scripts/compare-gallery.sh${hero:+ HERO}\` at commit" \
      "$(git rev-parse --short HEAD), $(date -u +%Y-%m-%d)."
    echo
    echo "\`shapeproc compare EXEMPLAR --methods $methods --size S --seed 1\`: S is 2W x 2H of the"
    echo "exemplar, larger for a tile of few elements (at least 64 elements in the output); tiles"
    echo "are read with \`--tile\`. Each cell is the figure a check reads, with its verdict"
    echo "(docs/evaluation.md); s is the method's wall time, fit included for the shape process."
    echo
    cat "$out/gallery.md"
  } >"$RESULT"
  echo "wrote $RESULT" >&2
fi
