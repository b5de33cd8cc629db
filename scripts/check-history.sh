#!/usr/bin/env bash
# Checks that the project speaks only of itself: no development rounds or work items named by
# number, no talk of working periods, no absolute paths of a developer's machine, in tracked text
# files and in the commit messages written since this check began. The words are assembled from
# pieces so that this file does not match itself.
# Prints every offending line and exits 1; silent and 0 when there is none.
set -euo pipefail
cd "$(dirname "$0")/.."
words="st""op|is""sue|ses""sion|round|sprint|ticket"
period="ses""sion"
paths="/(wo""rk|t""mp|ho""me)/[a-z]"
pattern="\\b($words)s? ?#?[0-9]+\\b|\\bth(is|at|e last|e next) (work(ing)? )?$period\\b|$paths"
status=0
# Text files the project ships, except third-party data and fuzz seeds (inputs written by others,
# or hostile bytes).
while IFS= read -r hit; do
  echo "check-history: $hit"
  status=1
done < <(git ls-files -z -- . ':!data/third-party' ':!tests/fuzz/seeds' |
  xargs -0 grep -nIiE "$pattern" 2>/dev/null || true)
# Commit messages from the first commit that carries this check on.
first=$(git log --format=%H --diff-filter=A -- scripts/check-history.sh | tail -1)
if [ -n "$first" ]; then
  while IFS= read -r hit; do
    echo "check-history: a commit message says: $hit"
    status=1
  done < <(git log --format='%h %s%n%b' "$first^..HEAD" 2>/dev/null | grep -iE "$pattern" || true)
fi
exit $status
