#!/usr/bin/env bash
# Builds lcmtf and runs every test twice: a normal build, then an ASan+UBSan build of the tests.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh

jobs=${LCMTF_JOBS:-2}
cmake -S . -B build/release -DCMAKE_BUILD_TYPE=RelWithDebInfo
cmake --build build/release -j"$jobs"
ctest --test-dir build/release -j"$jobs" --output-on-failure

cmake -S . -B build/asan -DCMAKE_BUILD_TYPE=Debug -DLCMTF_SANITIZE=address,undefined \
  -DLCMTF_BUILD_JAVA=OFF -DLCMTF_BUILD_EXAMPLES=OFF -DLCMTF_BUILD_BENCHMARKS=OFF
cmake --build build/asan -j"$jobs"
ctest --test-dir build/asan -j"$jobs" --output-on-failure
