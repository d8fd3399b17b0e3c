#!/bin/sh
# usage: check_launcher.sh LCMTF_SPY LCM_JAR JCHART2D_JAR
set -u
spy=$1 lcm_jar=$2 jchart2d_jar=$3
unset CLASSPATH LCMTF_TYPES_JAR
status=0
fail() { echo "FAIL: $*" >&2; status=1; }

if ! out=$("$spy" --print-command --lcm-url=memq://); then
  echo "FAIL: lcmtf-spy --print-command exited non-zero" >&2
  exit 1
fi
echo "$out"
[ "$(printf '%s\n' "$out" | wc -l)" -eq 2 ] || fail "expected two lines from --print-command"
classpath=$(printf '%s\n' "$out" | sed -n 1p)
command=$(printf '%s\n' "$out" | sed -n 2p)

case $classpath in
  CLASSPATH=*) types_jar=${classpath#CLASSPATH=} ;;
  *) fail "first line is not CLASSPATH=...: $classpath"; types_jar= ;;
esac
[ "$(basename -- "$types_jar")" = lcmtf_types.jar ] || fail "CLASSPATH is not lcmtf_types.jar: $types_jar"
[ -f "$types_jar" ] || fail "CLASSPATH names a missing file: $types_jar"

case $command in java\ *) ;; *) fail "command does not start java: $command" ;; esac
case $command in *" -cp $lcm_jar:$jchart2d_jar "*) ;; *) fail "-cp is not $lcm_jar:$jchart2d_jar" ;; esac
case $command in *" lcm.spy.Spy --lcm-url=memq://") ;; *) fail "lcm.spy.Spy does not get --lcm-url=memq://" ;; esac

kept=$(CLASSPATH=/extra/dir "$spy" --print-command | sed -n 1p)
[ "$kept" = "CLASSPATH=$types_jar:/extra/dir" ] || fail "existing CLASSPATH not kept after the jar: $kept"

help=$("$spy" --help) || fail "--help exited non-zero"
case $help in usage:*) ;; *) fail "--help does not print usage" ;; esac

if err=$(LCMTF_TYPES_JAR=/nonexistent/lcmtf_types.jar "$spy" --print-command 2>&1); then
  fail "missing LCMTF_TYPES_JAR accepted"
fi
case $err in *"/nonexistent/lcmtf_types.jar"*) ;; *) fail "missing jar message does not name it: $err" ;; esac

exit $status
