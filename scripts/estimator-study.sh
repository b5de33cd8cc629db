#!/usr/bin/env bash
# Writes docs/results/estimator-study.md: benchmarks/estimator_study.cpp, three point models of
# known θ on the unit torus, each pattern sampled by the project's sampler and fitted by the
# pseudo-likelihood, then by the MCMC maximum likelihood from it (docs/fit.md, "Estimator
# study"). Needs a build (bash scripts/build.sh). Usage: scripts/estimator-study.sh [replicates]
set -euo pipefail
cd "$(dirname "$0")/.."
replicates=${1:-100}
out=docs/results/estimator-study.md
body=$(mktemp)
trap 'rm -f "$body"' EXIT
start=$(date +%s)
./build/benchmarks/estimator_study "$replicates" > "$body"
seconds=$(( $(date +%s) - start ))
{
  echo "# Estimator study: MPLE and MLE on point models of known parameters"
  echo
  echo "Command: \`bash scripts/estimator-study.sh $replicates\` (benchmarks/estimator_study.cpp),"
  echo "commit $(git rev-parse --short HEAD), $(date -u +%Y-%m-%d), $(nproc) cores, $seconds s."
  echo "Columns: docs/fit.md, \"Estimator study\"."
  echo
  cat "$body"
} > "$out"
echo "wrote $out"
