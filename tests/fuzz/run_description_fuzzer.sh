#!/bin/sh
# Runs the robot description fuzzer for a while from a corpus seeded with real robots, with a
# dictionary of XML and URDF tokens.
# usage: run_description_fuzzer.sh FUZZER WORK_DIR SECONDS SEED_URDF...
set -eu
fuzzer=$1 work=$2 seconds=$3
shift 3
mkdir -p "$work/corpus" "$work/artifacts"
cp "$@" "$work/corpus/"
# Inputs that once found a bug run first, as part of the corpus.
cp "$(dirname "$0")"/regressions/robot_description-* "$work/corpus/"
exec "$fuzzer" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
  -dict="$(dirname "$0")/robot_description.dict" -artifact_prefix="$work/artifacts/" "$work/corpus"
