#!/usr/bin/env bash
# Writes docs/results/readers.md: the reader benchmarks (benchmarks/io_benchmarks.cpp), among them
# the hostile sizes (style sheets of 5,000 to 20,000 rules, 2,500 to 10,000 nested subpaths),
# whose time per item must not grow with their size. Needs a build (bash scripts/build.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
out=docs/results/readers.md
json=$(mktemp)
trap 'rm -f "$json"' EXIT
./build/benchmarks/io_benchmarks --benchmark_format=json --benchmark_out="$json" \
  --benchmark_out_format=json > /dev/null
{
  echo "# Reader benchmarks"
  echo
  echo "Command: \`bash scripts/reader-benchmarks.sh\` (benchmarks/io_benchmarks.cpp), commit"
  echo "$(git rev-parse --short HEAD), $(date -u +%Y-%m-%d), $(nproc) cores."
  echo
  echo "| benchmark | CPU time | items per second |"
  echo "|---|---|---|"
  python3 - "$json" <<'PY'
import json, sys
for b in json.load(open(sys.argv[1]))["benchmarks"]:
    unit = b.get("time_unit", "ns")
    rate = b.get("items_per_second")
    print(f"| {b['name']} | {b['cpu_time']:.3g} {unit} | {rate:,.0f} |" if rate else
          f"| {b['name']} | {b['cpu_time']:.3g} {unit} | |")
PY
} > "$out"
echo "wrote $out"
