#!/usr/bin/env bash
# Writes docs/results/studio-latency.md: the studio's edit-to-picture time on the five exemplars of
# data/svg (benchmarks/studio_latency.cpp): each fitted as `shapeproc fit` fits it by default, then
# 12 edits, each waited for to its final preview, at twice the exemplar's width and height. Needs a
# build (bash scripts/build.sh). A few minutes on 2 cores, most of it the fits.
set -euo pipefail
cd "$(dirname "$0")/.."
out=docs/results/studio-latency.md
bin=./build/tools/shapeproc
bench=./build/benchmarks/studio_latency
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
rows=""
for entry in "dots-random:" "dashes-rows:" "crescents-grid:" "two-kinds:--category-by fill" "rings:"; do
  name=${entry%%:*} flags=${entry#*:}
  # shellcheck disable=SC2086
  "$bin" fit "data/svg/$name.svg" $flags -o "$work/$name.json" -q > /dev/null
  # shellcheck disable=SC2086
  "$bench" "$work/$name.json" "data/svg/$name.svg" $flags > "$work/$name.log"
  line=$(tail -n 1 "$work/$name.log")
  read -r _ _ draft _ _ max_draft _ _ final _ _ max_final _ elements _ ratio _ cut <<< "$line"
  first=$(sed -n 's/^first picture \([0-9.]*\) s.*/\1/p' "$work/$name.log")
  rows+="| $name | $elements | $first | $draft | $max_draft | $ratio | $final | $max_final | $cut |"$'\n'
done
{
  echo "# Studio preview latency"
  echo
  echo "Written by \`bash scripts/studio-latency.sh\` at commit $(git rev-parse --short HEAD) on" \
    "$(date -u +%Y-%m-%d), $(nproc) cores."
  echo
  echo "Each exemplar of data/svg fitted by \`shapeproc fit\` (defaults; two-kinds with" \
    "\`--category-by fill\`), then a studio session on the model with previews of twice the" \
    "exemplar's width and height, and 12 edits one after another (γ of pair 0's first band on" \
    "every axis ×2 and back, β of the first category ×1.25 and back). Seconds from the edit to" \
    "the first picture (a draft: the picture on screen continued under the edited model) and to" \
    "the final one (the chain \`shapeproc sample\` runs from empty, and the verdicts)." \
    "draft/final elements: the median ratio of the draft's element count to the final" \
    "picture's (1: the draft has reached the edited model's density). elements: the last" \
    "final picture's. cut: edits whose final chain was cut short at the studio's 5-s limit" \
    "(their final time is when the cut picture showed; the export samples them in full)."
  echo
  echo "| exemplar | elements | first picture (s) | draft median (s) | draft max (s) | draft/final elements | final median (s) | final max (s) | cut (of 12) |"
  echo "|---|---|---|---|---|---|---|---|---|"
  printf '%s' "$rows"
} > "$out"
cat "$out"
