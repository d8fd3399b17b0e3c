#!/bin/sh
# usage: screenshot_tables.sh WRITE_SAMPLE_MESSAGES JAVA CLASSPATH OUT_DIR
# Draws lcm-spy's TF and joint tables under Xvfb into OUT_DIR; exits 77 (skipped) without Xvfb.
set -eu
writer=$1 java=$2 classpath=$3 out=$4
if ! command -v xvfb-run >/dev/null 2>&1; then
  echo "xvfb-run not found (apt-get install xvfb xauth): no screenshot taken"
  exit 77
fi
rm -rf "$out"
mkdir -p "$out/messages"
"$writer" "$out/messages"
xvfb-run -a -s "-screen 0 1024x768x24" "$java" -cp "$classpath" SpyTablesScreenshot \
  "$out/messages" "$out"
