#!/usr/bin/env bash
# Builds the Debian package (build/shapeproc_<version>_<arch>.deb) from a Release build; with
# --install, installs it with apt (as root) and runs the installed command from the PATH.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
(cd build && cpack -G DEB > /dev/null)
deb=$(ls build/shapeproc_*.deb | head -n 1)
echo "built $deb"
if [ "${1:-}" = --install ]; then
  export DEBIAN_FRONTEND=noninteractive
  apt-get install -y -qq --no-install-recommends "./$deb" > /dev/null
  command -v shapeproc
  shapeproc --version
  /usr/bin/python3 -c "import shapeproc; print('python module', shapeproc.__version__)"
fi
