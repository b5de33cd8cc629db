#!/usr/bin/env bash
# Configures and builds in Release (build/), or with sanitizers (build-sanitize/) when
# SHAPEPROC_SANITIZE=1. Extra arguments go to `cmake --build` (e.g. --target shapeproc).
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${SHAPEPROC_SANITIZE:-0}" = 1 ]; then
  dir=build-sanitize; flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DSHAPEPROC_SANITIZE=ON)
else
  dir=build; flags=(-DCMAKE_BUILD_TYPE=Release)
fi
cmake -S . -B "$dir" -G Ninja "${flags[@]}" > /dev/null
cmake --build "$dir" -j "$(nproc)" "$@"
