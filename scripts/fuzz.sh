#!/usr/bin/env bash
# Usage: scripts/fuzz.sh [SECONDS [RUNS [TARGET...]]]
# Builds the libFuzzer targets of tests/fuzz (in build-fuzz/, clang with ASan and UBSan) and runs
# each for SECONDS (default 60), or until RUNS inputs when given (then SECONDS is a cap), from a
# corpus seeded with data/ and tests/fuzz/seeds, with a fixed random seed (FUZZ_SEED, default 1:
# a run of RUNS inputs from the seeds alone is repeatable). Prints one line per target:
# executions, seconds, result. Crash inputs are kept in build-fuzz/crashes/. Exit 1 when any target crashed, timed out
# (10 s per input) or ran out of memory (2 GB).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
runs="${2:-0}"
root="$PWD"
CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DSHAPEPROC_FUZZ=ON -DSHAPEPROC_BUILD_TESTS=OFF -DSHAPEPROC_BUILD_BENCHMARKS=OFF > /dev/null
targets=(svg model csv cli mesh_obj mesh_off mesh_ply mesh_stl)
[ $# -gt 2 ] && targets=("${@:3}")
cmake --build build-fuzz -j "$(nproc)" --target "${targets[@]/#/fuzz_}" > build-fuzz/build.log ||
  { tail -30 build-fuzz/build.log; exit 1; }

# Seeds: the SVG and CSV fuzzers read a first byte of options, so their seeds get one.
seed() {  # seed TARGET PREFIX_BYTE FILES...
  local dir="build-fuzz/corpus/$1" prefix="$2"
  shift 2
  mkdir -p "$dir"
  for f in "$@"; do
    [ -f "$f" ] || continue
    { [ -n "$prefix" ] && printf '%b' "$prefix"; cat "$f"; } > "$dir/seed-$(basename "$f")"
  done
}
seed svg '\x00' data/svg/*.svg data/third-party/hero-patterns/*.svg tests/fuzz/seeds/*.svg
seed svg '\x05' data/third-party/hero-patterns/*.svg
seed model '' tests/fuzz/seeds/*.json
seed csv '\x01' data/points/*.csv tests/fuzz/seeds/*.csv
seed cli '' tests/fuzz/seeds/*.args
seed mesh_obj '' data/mesh/*.obj tests/fuzz/seeds/*.obj
seed mesh_off '' tests/fuzz/seeds/*.off
seed mesh_ply '' tests/fuzz/seeds/*.ply
seed mesh_stl '' tests/fuzz/seeds/*.stl

mkdir -p build-fuzz/crashes
status=0
limit=()
[ "$runs" -gt 0 ] && limit=(-runs="$runs")
printf '%-10s %12s %8s %s\n' target executions seconds result
for t in "${targets[@]}"; do
  log="build-fuzz/fuzz_$t.log"
  mkdir -p "build-fuzz/corpus/$t"
  # The CLI fuzzer runs in an empty directory, so that no argument names an existing input.
  work=$(mktemp -d)
  start=$SECONDS
  if (cd "$work" && "$root/build-fuzz/tests/fuzz/fuzz_$t" -max_total_time="$seconds" "${limit[@]}" \
      -seed="${FUZZ_SEED:-1}" -timeout=10 -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 \
      -artifact_prefix="$root/build-fuzz/crashes/$t-" "$root/build-fuzz/corpus/$t") \
      > "$log" 2>&1; then
    result=ok
  else
    result="FAILED (see $log)"
    status=1
  fi
  rm -rf "$work"
  executed=$(grep -a -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo "?")
  printf '%-10s %12s %8s %s\n' "$t" "$executed" "$((SECONDS - start))" "$result"
done
exit "$status"
