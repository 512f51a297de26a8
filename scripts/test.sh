#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite:
#   1. build/       the Release build and its tests (always);
#   2. build-asan/  the same suite under AddressSanitizer + UndefinedBehaviorSanitizer;
#   3. build-fuzz/  the libFuzzer targets (clang), each for YAMSC_FUZZ_SECONDS (30) from
#                   its seed corpus (docs/robustness.md).
# Steps 2 and 3 run with YAMSC_TEST_FULL=1 (not yet in CI: see docs/robustness.md).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j"$(nproc)"
if [ "${YAMSC_TEST_FULL:-0}" != 1 ]; then exit 0; fi

# -O1: what the sanitizers recommend, and faster to compile than -O3; asserts stay on.
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE=-O1 \
  -DCMAKE_C_FLAGS_RELEASE=-O1 -DYAMSC_SANITIZE=ON -DYAMSC_BUILD_BENCH=OFF >/dev/null
cmake --build build-asan -j"$(nproc)"
ctest --test-dir build-asan --output-on-failure -j"$(nproc)"

cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=Release -DCMAKE_C_COMPILER=clang \
  -DCMAKE_CXX_COMPILER=clang++ -DYAMSC_FUZZ=ON -DYAMSC_BUILD_TESTS=OFF -DYAMSC_BUILD_BENCH=OFF \
  -DYAMSC_FUZZ_SECONDS="${YAMSC_FUZZ_SECONDS:-30}" >/dev/null
cmake --build build-fuzz --target fuzz_targets -j"$(nproc)"
ctest --test-dir build-fuzz --output-on-failure -j"$(nproc)"
