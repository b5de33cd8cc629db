#!/usr/bin/env bash
# Times `synthesize TILE --tile --size 3W,3H` on every Hero tile at seeds 1-3 and writes a table.
# Usage: scripts/hero-times.sh TILE_DIR OUT.md [BEFORE_BINARY]
# SHAPEPROC names the binary (default build/tools/shapeproc). With BEFORE_BINARY, each tile is
# also run at seed 1 with it, and the table says whether the two outputs are the same, element
# for element (the SVGs compared without their metadata line, which names the binary).
set -euo pipefail
tiles=$1
out=$2
before=${3:-}
bin=${SHAPEPROC:-build/tools/shapeproc}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
commit=$(git rev-parse --short HEAD)
load_start=$(cut -d' ' -f1 /proc/loadavg)
run() {  # binary tile seed output -> seconds
  local start end
  start=$(date +%s.%N)
  "$1" synthesize "$2" --tile --size 3W,3H --seed "$3" -o "$4" --force -q > /dev/null 2>&1
  end=$(date +%s.%N)
  echo "$start $end" | awk '{printf "%.1f", $2 - $1}'
}
rows=()
for tile in "$tiles"/*.svg; do
  name=$(basename "$tile")
  times=()
  for seed in 1 2 3; do
    times+=("$(run "$bin" "$tile" "$seed" "$work/$seed.svg")")
  done
  median=$(printf '%s\n' "${times[@]}" | sort -g | sed -n 2p)
  row="| $name | ${times[0]} | ${times[1]} | ${times[2]} | $median |"
  if [[ -n $before ]]; then
    old=$(run "$before" "$tile" 1 "$work/before.svg")
    if diff <(sed 3d "$work/1.svg") <(sed 3d "$work/before.svg") > /dev/null; then same=same; else same=differs; fi
    row="$row $old | $same |"
  fi
  rows+=("$row")
  echo "$row" >&2
done
{
  echo "# Hero tiles: synthesis time"
  echo
  echo "Command: \`scripts/hero-times.sh TILES OUT.md${before:+ BEFORE}\` at commit $commit, $(date -u +%Y-%m-%d), $(nproc) cores; load average $load_start at the start and $(cut -d' ' -f1 /proc/loadavg) at the end."
  echo
  echo "Wall-clock seconds of \`shapeproc synthesize TILE --tile --size 3W,3H --seed S\` (fit and sample, defaults), at seeds 1-3, and their median."
  [[ -n $before ]] && echo "The last two columns: seed 1 with the binary before the change, and whether the outputs are the same."
  echo
  if [[ -n $before ]]; then
    echo "| tile | seed 1 (s) | seed 2 (s) | seed 3 (s) | median (s) | before, seed 1 (s) | output |"
    echo "|---|---|---|---|---|---|---|"
  else
    echo "| tile | seed 1 (s) | seed 2 (s) | seed 3 (s) | median (s) |"
    echo "|---|---|---|---|---|"
  fi
  printf '%s\n' "${rows[@]}"
} > "$out"
echo "wrote $out" >&2
