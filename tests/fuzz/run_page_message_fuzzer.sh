#!/bin/sh
# Runs the page message fuzzer for a while from a corpus seeded with one message of each kind
# a page sends, and the headers a browser sends.
# usage: run_page_message_fuzzer.sh FUZZER WORK_DIR SECONDS
set -eu
fuzzer=$1 work=$2 seconds=$3
mkdir -p "$work/corpus" "$work/artifacts"
seed() { printf '%s' "$2" > "$work/corpus/seed-$1"; }
seed ack '{"type":"ack","seq":12}'
seed view-live '{"type":"view","fixed_frame":"odom","time":null}'
seed view-paused '{"type":"view","fixed_frame":"base_link","time":1795334869973768}'
seed joints '{"type":"joints","enabled":true,"positions":{"shoulder":0.5,"elbow":-1.25e-1}}'
seed headers 'http://127.0.0.1:8080
127.0.0.1:8080'
seed headers-ipv6 'https://[::1]
[::1]:443'
exec "$fuzzer" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
  -artifact_prefix="$work/artifacts/" "$work/corpus"
