#!/usr/bin/env bash
# Checks that the library's modules include only the modules below them (dependencies point one
# way: core and geometry at the bottom, the command line on top). Prints every offending include
# and exits 1; silent and 0 when the layering holds.
set -euo pipefail
cd "$(dirname "$0")/.."
# module: the modules it may include (besides itself)
declare -A allowed=(
  [core]=""
  [geometry]="core"
  [model]="core geometry"
  [synthesis]="core geometry"
  [render]="core geometry model"
  [io]="core geometry model synthesis render"
  [fit]="core geometry model synthesis sample metrics"
  [sample]="core geometry model synthesis"
  [metrics]="core geometry"
  [report]="core geometry model synthesis render io metrics evaluation"
  [evaluation]="core geometry model synthesis render io sample fit metrics"
  [methods]="core geometry model synthesis sample fit metrics"
  [studio]="core geometry model synthesis render io sample fit metrics evaluation"
  [pipeline]="core geometry model synthesis render io sample fit metrics evaluation methods report"
  [distributed]="core geometry model synthesis io sample fit"
)
# The synthesis methods by paper (libshapeproc/methods/): a folder may include, within methods/,
# only itself and the folders listed; the files at the top (the hybrid, the tile baseline) any.
declare -A method_allowed=(
  [common]=""
  [physics]="common"
  [ma2011]="common physics"
  [davison2018]="common"
  [ijiri2008]="common"
)
status=0
# check_layering ROOT ALLOWED: every folder under ROOT includes, of ROOT's folders, only itself
# and those ALLOWED (the name of an array like the ones above) lists for it.
check_layering() {
  local root=$1
  local -n rules=$2
  local dir part line file used
  for dir in "$root"/*/; do
    part=$(basename "$dir")
    if [ -z "${rules[$part]+set}" ]; then
      echo "check-includes: $root/$part has no place in the layering (add it to scripts/check-includes.sh)"
      status=1
      continue
    fi
    while IFS= read -r line; do
      file=${line%%:*}
      used=$(sed -E "s#.*\"$root/([a-z0-9_]+)/.*#\\1#" <<< "$line")
      [ "$used" = "$part" ] && continue
      if ! grep -qw -- "$used" <<< "${rules[$part]}"; then
        echo "check-includes: $file includes $root/$used/ but $part may include only: ${rules[$part]:-nothing}"
        status=1
      fi
    done < <(grep -rHE "^#include \"$root/[a-z0-9_]+/" "$dir" || true)
  done
}
check_layering libshapeproc allowed
check_layering libshapeproc/methods method_allowed
# A module's detail/ headers (a method's: methods/PAPER/detail/) are its own: no other module or
# method, and not the command line, includes them (tests may).
while IFS= read -r line; do
  file=${line%%:*}
  owner=$(sed -E 's#.*"libshapeproc/([a-z0-9_/]+)/detail/.*#\1#' <<< "$line")
  case "$file" in
    libshapeproc/"$owner"/*) ;;
    *) echo "check-includes: $file includes a detail header of $owner: ${line#*:}"; status=1 ;;
  esac
done < <(grep -rHE '^#include "libshapeproc/[a-z0-9_/]+/detail/' libshapeproc tools benchmarks || true)
# The library never includes the command line.
if grep -rqE '^#include "tools/' libshapeproc; then
  grep -rHE '^#include "tools/' libshapeproc | sed 's/^/check-includes: the library includes the CLI: /'
  status=1
fi
exit $status
