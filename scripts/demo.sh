#!/usr/bin/env bash
# Builds lcmtf (installing what it needs) and runs the demo robot of examples/: the joint
# publisher sweeps its joints, the URDF publisher turns them into transforms, a listener
# prints where the gripper is and where an object the camera saw 2 s ago is now, and
# lcmtf-viewer draws it all in a browser at the URL it prints.
#
#   scripts/demo.sh [--duration SECONDS] [--lcm-url URL] [--viewer-port PORT]
#
# Runs until Ctrl-C, or for SECONDS. The URL is --lcm-url, else $LCM_DEFAULT_URL, else one that
# keeps all traffic on this machine (ttl=0). The viewer serves this machine only, on PORT
# (default 8080; 0 picks a free one).
# With LCMTF_DEMO_BIN=DIR it uses the programs built in DIR instead of building.
set -euo pipefail
cd "$(dirname "$0")/.."

duration=0
url=${LCM_DEFAULT_URL:-'udpm://239.255.76.67:7667?ttl=0'}
viewer_port=8080
while [ $# -gt 0 ]; do
  case "$1" in
    --duration) duration=${2:?--duration needs a number of seconds}; shift 2 ;;
    --lcm-url) url=${2:?--lcm-url needs a URL}; shift 2 ;;
    --viewer-port) viewer_port=${2:?--viewer-port needs a port}; shift 2 ;;
    -h | --help) sed -n '2,12p' "$0" | cut -c3-; exit 0 ;;
    *) echo "demo.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
if ! [[ $duration =~ ^([0-9]+\.?[0-9]*|\.[0-9]+)$ ]]; then
  echo "demo.sh: --duration: '$duration' is not a number of seconds (0 runs until Ctrl-C)" >&2
  exit 2
fi

if [ -n "${LCMTF_DEMO_BIN:-}" ]; then
  bin=$LCMTF_DEMO_BIN
else
  scripts/install-deps.sh
  cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release
  cmake --build build/release -j"${LCMTF_JOBS:-2}" \
    --target lcmtf-urdf-publisher lcmtf-joint-publisher lcmtf_demo_listener lcmtf-viewer
  bin=build/release/bin
fi
robot=examples/mobile_manipulator.urdf

declare -A names=()
stop_children() {
  trap - EXIT INT TERM
  for pid in "${!names[@]}"; do kill -TERM "$pid" 2>/dev/null || true; done
  for pid in "${!names[@]}"; do wait "$pid" 2>/dev/null || true; done
}
trap stop_children EXIT
trap 'stop_children; exit 130' INT
trap 'stop_children; exit 143' TERM

start() {
  "$@" &
  names[$!]=$(basename "$1")
}
start "$bin/lcmtf-urdf-publisher" --lcm-url "$url" "$robot"
start "$bin/lcmtf-joint-publisher" --lcm-url "$url" --sweep "$robot"
start "$bin/lcmtf-viewer" --lcm-url "$url" --port "$viewer_port"
start "$bin/lcmtf_demo_listener" --lcm-url "$url" --duration "$duration"
listener=$!

# The first program to stop ends the demo: the listener at the end of --duration, or another
# that failed (its message is above).
status=0
wait -n -p finished "${!names[@]}" || status=$?
if [ "$finished" != "$listener" ]; then
  echo "demo.sh: ${names[$finished]} stopped (status $status); stopping the demo" >&2
  [ "$status" -ne 0 ] || status=1
fi
unset "names[$finished]"
exit "$status"
