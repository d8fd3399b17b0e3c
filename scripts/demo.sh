#!/usr/bin/env bash
# Builds lcmtf (installing what it needs) and runs the demo; arguments go to the demo.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh

cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release
cmake --build build/release -j"${LCMTF_JOBS:-2}" --target lcmtf_round_trip
exec build/release/bin/lcmtf_round_trip "$@"
