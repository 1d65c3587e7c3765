#!/usr/bin/env bash
# Configures and builds into build/ (programs in build/bin/): everything, or only the targets
# named (`bash deploy/build.sh olympics-server olympics-league`, as the container image does).
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)" ${1:+--target "$@"}
