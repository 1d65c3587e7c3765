#!/usr/bin/env bash
# Configures and builds into build/ (programs in build/bin/): everything, or only the targets
# named (`bash deploy/build.sh olympics-server olympics-league`, as the container image does).
#
# A new build folder uses Ninja, and ccache when it is installed (deploy/debian-test-packages.txt
# installs it): the Python wheel's own CMake build (tests/python/test_pip_install.py, in
# build-pip-wheel/ beside build/) then compiles the same sources with the same commands, relative
# to the same base directory, so its second compile of the sports and the server is cache hits.
set -euo pipefail
cd "$(dirname "$0")/.."
args=(-DCMAKE_BUILD_TYPE=Release)
if [ ! -f build/CMakeCache.txt ] && command -v ninja >/dev/null; then
  args+=(-G Ninja)
fi
if command -v ccache >/dev/null; then
  args+=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  export CCACHE_BASEDIR="$PWD"
fi
cmake -S . -B build "${args[@]}"
cmake --build build -j"$(nproc)" ${1:+--target "$@"}
