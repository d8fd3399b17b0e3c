#!/bin/sh
# Runs the static transform file fuzzer for a while from a corpus seeded with files of each form
# lcmtf-static-publisher reads.
# usage: run_static_transform_file_fuzzer.sh FUZZER WORK_DIR SECONDS
set -eu
fuzzer=$1 work=$2 seconds=$3
mkdir -p "$work/corpus" "$work/artifacts"
seed() { printf '%s' "$2" > "$work/corpus/seed-$1"; }
seed block-list '- frame_id: base_link
  child_frame_id: camera
  x: 0.1
  z: -0.5
  yaw: 1.5
- frame_id: /base_link
  child_frame_id: imu
  qx: 0
  qy: 0
  qz: 0.7071067811865476
  qw: 0.7071067811865476
'
seed flow-map 'transforms:
  - {frame_id: a, child_frame_id: b, x: 1e-3, roll: -.5, pitch: 0.25}
  - {frame_id: "b", child_frame_id: '"'"'c d'"'"', y: -2}
'
seed anchors '- &mount {frame_id: base, child_frame_id: left, x: 0.2}
- {frame_id: base, child_frame_id: right, x: -0.2}
'
seed escapes '- {frame_id: "caf\u00e9\t", child_frame_id: "\x41\e", z: 3}
'
seed two-documents '- {frame_id: a, child_frame_id: b}
---
- {frame_id: a, child_frame_id: c}
'
seed lone-comma ','
exec "$fuzzer" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
  -artifact_prefix="$work/artifacts/" "$work/corpus"
