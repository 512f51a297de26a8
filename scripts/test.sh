#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite:
#   1. build/       the Release build and all its tests;
#   2. build-fuzz/  the libFuzzer targets (clang), each for YAMSC_FUZZ_SECONDS (20)
#                   from its seed corpus: a CI-sized run (docs/robustness.md);
#   3. build-asan/  the whole suite again under AddressSanitizer + UndefinedBehavior-
#                   Sanitizer (its build is most of the run's time: about 10 minutes
#                   on 2 cores). YAMSC_SKIP_SANITIZERS=1 skips it for a quick local run.
# With ccache installed (optional), the builds reuse the objects of an earlier
# build of the same sources (scripts/compiler-cache.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)
bash scripts/install-deps.sh
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j"$jobs"

echo "== fuzzing (${YAMSC_FUZZ_SECONDS:-20} s per target)"
source scripts/compiler-cache.sh
cmake -S . -B build-fuzz ${compiler_cache[@]+"${compiler_cache[@]}"} -DCMAKE_BUILD_TYPE=Release -DCMAKE_C_COMPILER=clang \
  -DCMAKE_CXX_COMPILER=clang++ -DYAMSC_FUZZ=ON -DYAMSC_BUILD_TESTS=OFF -DYAMSC_BUILD_BENCH=OFF \
  -DYAMSC_FUZZ_SECONDS="${YAMSC_FUZZ_SECONDS:-20}" >/dev/null
cmake --build build-fuzz --target fuzz_targets -j"$jobs"
ctest --test-dir build-fuzz --output-on-failure -j"$jobs"

if [ "${YAMSC_SKIP_SANITIZERS:-0}" = 1 ]; then exit 0; fi
echo "== sanitizers (ASan + UBSan)"
# -O1: what the sanitizers recommend, and faster to compile than -O3; asserts stay on.
cmake -S . -B build-asan ${compiler_cache[@]+"${compiler_cache[@]}"} -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE=-O1 \
  -DCMAKE_C_FLAGS_RELEASE=-O1 -DYAMSC_SANITIZE=ON -DYAMSC_BUILD_BENCH=OFF >/dev/null
cmake --build build-asan -j"$jobs"
ctest --test-dir build-asan --output-on-failure -j"$jobs"
