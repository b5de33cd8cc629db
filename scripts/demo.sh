#!/usr/bin/env bash
# The main job on a bundled exemplar: install what is missing, build in Release, and write the
# results to out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh --target shapeproc
mkdir -p out
exemplar=data/svg/two-kinds.svg
./build/tools/shapeproc info "$exemplar" --category-by fill | tee out/two-kinds-info.txt
./build/tools/shapeproc info "$exemplar" --category-by fill --json > out/two-kinds-info.json
./build/tools/shapeproc convert "$exemplar" --category-by fill -o out/two-kinds.svg
./build/tools/shapeproc convert "$exemplar" --category-by fill -o out/two-kinds.csv
./build/tools/shapeproc convert data/mesh/pebbles.obj -o out/pebbles.ply
./build/tools/shapeproc measure "$exemplar" --category-by fill --range 20 -o out/two-kinds-pairs.csv \
  --proxy-out out/two-kinds-proxies.svg
./build/tools/shapeproc convert "$exemplar" --category-by fill -o out/two-kinds.png
# The main job: fit the exemplar, then sample an output of four times its area (twice each side);
# the seed and every parameter are recorded in the SVG.
./build/tools/shapeproc synthesize "$exemplar" --category-by fill --model out/two-kinds-model.json \
  --size 2W,2H --seed 1 --force -o out/two-kinds-synthesis.svg --png out/two-kinds-synthesis.png
./build/tools/shapeproc show out/two-kinds-model.json --plot out/two-kinds-interaction.svg
# Exemplar and output side by side, with the metrics: open out/report/index.html.
./build/tools/shapeproc report "$exemplar" out/two-kinds-synthesis.svg --category-by fill \
  --model out/two-kinds-model.json -o out/report
echo "demo outputs are in out/; the report is out/report/index.html"
