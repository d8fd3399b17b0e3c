#!/bin/sh
# usage: check_jar_types.sh JAR_TOOL TYPES_JAR LCMTYPES_DIR
# Every lcmtypes/<type>.lcm must be in the jar as lcmtf/<type>.class.
set -eu
jar_tool=$1 types_jar=$2 lcmtypes_dir=$3

listing=$("$jar_tool" tf "$types_jar")
status=0
count=0
for lcm in "$lcmtypes_dir"/*.lcm; do
  [ -f "$lcm" ] || { echo "FAIL: no .lcm files in $lcmtypes_dir" >&2; exit 1; }
  class="lcmtf/$(basename -- "$lcm" .lcm).class"
  count=$((count + 1))
  if printf '%s\n' "$listing" | grep -qxF "$class"; then
    echo "ok   $class"
  else
    echo "FAIL: $types_jar lacks $class" >&2
    status=1
  fi
done
echo "$count types checked in $types_jar"
exit $status
