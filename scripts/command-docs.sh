#!/usr/bin/env bash
# Writes docs/commands.md: every command's --help, as the built `shapeproc` prints it. Needs a
# build (bash scripts/build.sh --target shapeproc). The test CliHelp.DocsCommandsHoldsEveryCommandsHelp
# fails when the page and the help differ: rerun this script after changing an option.
set -euo pipefail
cd "$(dirname "$0")/.."
shapeproc=./build/tools/shapeproc
commands=$("$shapeproc" --help | sed -n '/^Subcommands:/,$p' | awk 'NR > 1 && NF { print $1 }')
{
  echo "# Commands"
  echo
  echo "Written by \`bash scripts/command-docs.sh\` from each command's \`--help\`. What the commands"
  echo "compute is in the module pages (README.md, \"Documentation\"); the model file is in"
  echo "docs/model-format.md. Every command reads SVG, OBJ, PLY, OFF, STL or CSV exemplars, answers bad"
  echo "input with one line naming the file and exit code 2 (docs/reliability.md), and writes its"
  echo "files atomically."
  echo
  cat <<'EXAMPLES'
## Examples

```sh
shapeproc info data/svg/two-kinds.svg --category-by fill            # what the reader sees
shapeproc info data/points/clusters.csv --window 0,100,0,100         # point patterns need a window
shapeproc convert data/svg/rings.svg --split-subpaths -o rings.csv   # placements x,y,category,shape
shapeproc measure data/svg/dashes-rows.svg --range 10 -o pairs.csv   # i,j,distance,ox,oy,axis
shapeproc fit data/svg/dots-random.svg -o model.json                 # β, γ ± se, goodness of fit
shapeproc fidelity data/svg/dots-random.svg                          # does the fit reproduce it?
shapeproc show model.json --plot interaction.svg                     # parameters and their plot
shapeproc sample model.json --size 400,400 --seed 3 -o synthesis.svg # a new, larger arrangement
shapeproc sample model.json --size 400,400 --domain data/maps/star.svg -o star.svg --png star.png
shapeproc sample model.json --size 800,400 --intensity data/maps/gradient.png --chains 4 -o grad.svg
shapeproc edit model.json -o clustered.json --gamma '0:*:1=3'       # indices as in shapeproc show
shapeproc synthesize data/svg/dashes-rows.svg --size 2W,3H -o rows.svg       # fit, then sample
shapeproc synthesize data/third-party/hero-patterns/bubbles.svg --tile --size 3W,3H -o b.svg
shapeproc synthesize data/svg/dots-random.svg --method tile --size 2W,2H -o tile.svg  # the baseline
shapeproc synthesize data/svg/dashes-rows.svg --method ma-em --size 2W,2H -o em.svg   # Ma et al.
shapeproc synthesize data/svg/dashes-rows.svg --method davison --size 2W,2H -o grown.svg
shapeproc synthesize data/svg/dashes-rows.svg --method ijiri --size 2W,2H -o seeded.svg
shapeproc stats rows.svg --against data/svg/dashes-rows.svg          # collisions, density, W1, G, g
shapeproc report data/svg/dashes-rows.svg rows.svg -o report/        # report/index.html, verdicts
shapeproc compare data/svg/dashes-rows.svg --size 2W,2H -o cmp/      # every method, one page
```
EXAMPLES
  echo
  echo "## shapeproc"
  echo
  echo '```text'
  "$shapeproc" --help
  echo '```'
  for command in $commands; do
    echo
    echo "## $command"
    echo
    echo '```text'
    "$shapeproc" "$command" --help
    echo '```'
  done
} > docs/commands.md
echo "wrote docs/commands.md"
