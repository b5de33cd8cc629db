#!/usr/bin/env bash
# Installs the Debian packages libshapeproc needs, only those that are missing (idempotent).
set -euo pipefail
packages=(
  cmake g++ ninja-build ccache clang-format
  libeigen3-dev libboost-dev libcgal-dev libopenmesh-dev libpugixml-dev libsvgpp-dev
  libnlopt-dev libnlopt-cxx-dev
  nlohmann-json3-dev libcli11-dev
  libgtest-dev libgmock-dev libbenchmark-dev libcairo2-dev pkgconf
  libbox2d-dev libbullet-dev
  clang libclang-rt-14-dev
  libopenmpi-dev openmpi-bin
  libcpp-httplib-dev chromium chromium-driver python3-selenium
  pybind11-dev python3-pybind11 python3-dev python3-numpy python3-pytest
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
