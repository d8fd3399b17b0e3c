#!/bin/sh
# usage: decode_like_spy.sh LCMTF_SPY WRITE_SAMPLE_MESSAGES JAVA CHECKER_CLASSES OUT_DIR
# Writes one message per lcmtf type, then decodes each as lcm-spy would, with the CLASSPATH and
# -cp that lcmtf-spy gives lcm-spy, and no display.
set -eu
spy=$1 writer=$2 java=$3 classes=$4 out=$5
unset CLASSPATH LCMTF_TYPES_JAR DISPLAY

rm -rf "$out"
mkdir -p "$out"
"$writer" "$out"

printed=$("$spy" --print-command)
classpath=$(printf '%s\n' "$printed" | sed -n 's/^CLASSPATH=//p')
spy_cp=$(printf '%s\n' "$printed" | sed -n '2s/.* -cp \([^ ]*\) lcm\.spy\.Spy.*/\1/p')
if [ -z "$classpath" ] || [ -z "$spy_cp" ]; then
  printf 'cannot read CLASSPATH and -cp from lcmtf-spy --print-command:\n%s\n' "$printed" >&2
  exit 1
fi
echo "CLASSPATH=$classpath java -cp $spy_cp:$classes SpyDecodesLcmtf $out"
CLASSPATH=$classpath "$java" -cp "$spy_cp:$classes" SpyDecodesLcmtf "$out"
