#!/usr/bin/env bash
# Configures and builds yamsc in build/ (Release). Extra arguments go to cmake.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/compiler-cache.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release ${compiler_cache[@]+"${compiler_cache[@]}"} "$@" >/dev/null
cmake --build build -j"$(nproc)"
