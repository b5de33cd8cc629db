#!/usr/bin/env bash
# The whole test suite: install what is missing, build everything, run ctest.
# SHAPEPROC_SANITIZE=1 runs it under AddressSanitizer and UndefinedBehaviorSanitizer.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
dir=build; [ "${SHAPEPROC_SANITIZE:-0}" = 1 ] && dir=build-sanitize
ctest --test-dir "$dir" --output-on-failure -j "$(nproc)"
