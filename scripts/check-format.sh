#!/usr/bin/env bash
# Checks that every C++ file is formatted by .clang-format (clang-format --dry-run -Werror); lists
# the files that are not and exits 1. `bash scripts/check-format.sh --fix` formats them in place.
set -euo pipefail
cd "$(dirname "$0")/.."
mapfile -t files < <(git ls-files --cached --others --exclude-standard 'libshapeproc/*.[ch]pp' 'tools/*.[ch]pp' 'tests/*.[ch]pp' 'benchmarks/*.[ch]pp')
if [ "${1:-}" = "--fix" ]; then
  clang-format -i "${files[@]}"
  exit 0
fi
status=0
for f in "${files[@]}"; do
  if ! clang-format --dry-run -Werror "$f" > /dev/null 2>&1; then
    echo "check-format: $f is not formatted (bash scripts/check-format.sh --fix)"
    status=1
  fi
done
exit $status
