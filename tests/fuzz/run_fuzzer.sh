#!/bin/sh
# Runs the fuzzer for a while from a corpus seeded with one valid message of every type.
# usage: run_fuzzer.sh FUZZER SAMPLE_WRITER WORK_DIR SECONDS
set -eu
fuzzer=$1 writer=$2 work=$3 seconds=$4
mkdir -p "$work/corpus" "$work/seeds" "$work/artifacts"
"$writer" "$work/seeds"
# A leading byte tells the fuzzer how to split and route the rest (see the target).
for seed in "$work/seeds"/*.bin; do
  { printf '\000'; cat "$seed"; } > "$work/corpus/seed-$(basename "$seed")"
done
# Inputs that once found a bug run first, as part of the corpus.
for input in "$(dirname "$0")"/regressions/tf_message-*; do
  cp "$input" "$work/corpus/"
done
exec "$fuzzer" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
  -artifact_prefix="$work/artifacts/" "$work/corpus"
