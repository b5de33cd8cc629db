#!/usr/bin/env bash
# Runs every `shapeproc …` command of the README's sh blocks, in order, as printed, with the
# `shapeproc` on the PATH (an installed copy: scripts/package.sh --install), from the repository
# root. Fails at the first command that fails.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v shapeproc > /dev/null || { echo "readme-commands: no shapeproc on the PATH" >&2; exit 2; }
commands=$(awk '
  /^```sh/ { inside = 1; next }
  /^```/ { inside = 0; next }
  inside && (/^shapeproc / || continued) {
    line = $0; sub(/[ \t]+#.*$/, "", line)
    continued = line ~ /\\$/
    printf "%s%s", line, (continued ? "\n" : "\n\n")
  }' README.md)
[ -n "$commands" ] || { echo "readme-commands: README.md has no shapeproc command" >&2; exit 2; }
mkdir -p out
while IFS= read -r -d '' command; do
  [ -n "${command//[[:space:]]/}" ] || continue
  echo "+ $command"
  bash -euo pipefail -c "$command"
done < <(printf '%s' "$commands" | awk 'BEGIN { RS = ""; ORS = "\0" } { print }')
