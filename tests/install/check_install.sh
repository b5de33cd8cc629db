#!/usr/bin/env bash
# The installed copy, as a user meets it: `cmake --install` of the build into an empty prefix, the
# command from there, a program outside the source tree built with find_package(shapeproc), the
# same program built with pkg-config, and the Python module imported from the prefix.
# Usage: check_install.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1
source=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix
cmake --install "$build" --prefix "$prefix" > /dev/null
"$prefix/bin/shapeproc" --version
exemplar=$source/data/svg/dots-random.svg
cmake -S "$source/tests/install/consumer" -B "$work/cmake" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" > /dev/null
cmake --build "$work/cmake" > /dev/null
echo "find_package consumer: $("$work/cmake/consumer" "$exemplar")"
# A component the package does not have fails the configuration, naming it.
mkdir -p "$work/unknown"
printf 'cmake_minimum_required(VERSION 3.22)\nproject(unknown LANGUAGES CXX)\nfind_package(shapeproc REQUIRED COMPONENTS gui)\n' \
  > "$work/unknown/CMakeLists.txt"
if cmake -S "$work/unknown" -B "$work/unknown/build" -DCMAKE_PREFIX_PATH="$prefix" \
  > "$work/unknown.log" 2>&1; then
  echo "find_package with COMPONENTS gui succeeded" >&2
  exit 1
fi
grep -q "no component 'gui'" "$work/unknown.log" && echo "unknown component: refused"
pc_dir=$(dirname "$(find "$prefix" -name shapeproc.pc | head -n 1)")
libdir=$(PKG_CONFIG_PATH=$pc_dir pkg-config --variable=libdir shapeproc)
# shellcheck disable=SC2046
c++ -O1 "$source/tests/install/consumer/consumer.cpp" -o "$work/pc-consumer" \
  $(PKG_CONFIG_PATH=$pc_dir pkg-config --cflags --libs shapeproc) -Wl,-rpath,"$libdir"
echo "pkg-config consumer: $("$work/pc-consumer" "$exemplar")"
if [ -d "$prefix/lib/python3/dist-packages" ]; then
  PYTHONPATH=$prefix/lib/python3/dist-packages /usr/bin/python3 -c \
    "import shapeproc, sys; s = shapeproc.read(sys.argv[1]); print('python:', shapeproc.__version__, len(s))" \
    "$exemplar"
fi
