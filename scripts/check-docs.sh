#!/usr/bin/env bash
# Checks that the reference docs describe the software as it is: no "before → after" comparisons,
# "previous version" columns or commit hashes outside docs/results (measured tables, written by
# scripts with their commit on top) and the CHANGELOG (history). Prints every offending line and
# exits 1; silent and 0 when there is none.
set -euo pipefail
cd "$(dirname "$0")/.."
pattern='before ?(→|->) ?(after|now)|\((before|now)\)|previous version|\b(commit|version) \(?[0-9a-f]{7,40}\b|\([0-9a-f]{7,40}\)'
status=0
while IFS= read -r hit; do
  echo "check-docs: $hit"
  status=1
done < <(git ls-files -z -- README.md 'docs/*.md' ':!docs/results' | xargs -0 grep -nIiE "$pattern" 2>/dev/null || true)
exit $status
