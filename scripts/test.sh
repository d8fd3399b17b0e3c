#!/usr/bin/env bash
# Builds lcmtf and runs the tests: every test in a normal build (the tf2 agreement tests
# included: ROS tf2 is installed for them; the Python package's tests run here only, as the
# sanitizer builds leave the package out), the lookup and insert tests again under Valgrind's
# memcheck, the concurrency tests and the listener's reporter tests under ThreadSanitizer, short
# libFuzzer runs over decode-and-insert, robot descriptions, static transform files and the
# viewer's page messages beside every unit test again in an ASan+UBSan build, where each quick
# lookup is also checked against the walk.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --tests

jobs=${LCMTF_JOBS:-2}
cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release -DLCMTF_REQUIRE_TF2_AGREEMENT=ON \
  -DLCMTF_REQUIRE_PYTHON=ON -DLCMTF_REQUIRE_MEMCHECK=ON
cmake --build build/release -j"$jobs"
ctest --test-dir build/release -j"$jobs" --output-on-failure

cmake -S . -B build/tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DLCMTF_SANITIZE=thread \
  -DLCMTF_BUILD_JAVA=OFF -DLCMTF_BUILD_EXAMPLES=OFF -DLCMTF_BUILD_BENCHMARKS=OFF
cmake --build build/tsan -j"$jobs" --target buffer_core_concurrency_test buffer_core_realtime_test \
  read_mostly_lock_test transform_listener_test listener_reporter_test
ctest --test-dir build/tsan -R "Concurrency|Realtime|ListenerReporter" --output-on-failure

# One clang build serves the fuzzers and the unit tests under ASan+UBSan, at -O1 so that the
# sanitized tests run at a useful speed.
cmake -S . -B build/sanitize -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Debug \
  "-DCMAKE_CXX_FLAGS_DEBUG=-O1 -gline-tables-only" -DLCMTF_SANITIZE=address,undefined \
  -DLCMTF_BUILD_FUZZERS=ON -DLCMTF_REQUIRE_TF2_AGREEMENT=ON \
  -DLCMTF_BUILD_JAVA=OFF -DLCMTF_BUILD_EXAMPLES=OFF -DLCMTF_BUILD_BENCHMARKS=OFF
cmake --build build/sanitize -j"$jobs"
ctest --test-dir build/sanitize -j"$jobs" --output-on-failure
