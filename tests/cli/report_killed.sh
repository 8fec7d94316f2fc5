#!/usr/bin/env bash
# report_killed.sh GRANPIPE WORKDIR
# The report's Python stopped by a signal (HDF5 crashing on a corrupt file prints nothing)
# was reported as "failed (exit -1; its message is above)" with no message above: the
# signal is named. A copy of granpipe beside a report.py that kills itself stands for it.
set -eu
exe=$1 work=$2
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"
mkdir -p "$work/bin" "$work/share/granpipe"
cp "$exe" "$work/bin/granpipe"
printf 'import os, signal\nos.kill(os.getpid(), signal.SIGSEGV)\n' >"$work/share/granpipe/report.py"
"$exe" "$here/../../pipelines/lattice_packing.json" --out "$work/run" --no-report --quiet
set +e
message=$("$work/bin/granpipe" report "$work/run" 2>&1)
code=$?
set -e
expected="granpipe: report.html not written: $work/share/granpipe/report.py was stopped by signal 11 (Segmentation fault)"
[ "$code" = 1 ] || { echo "FAIL: exit $code, expected 1"; exit 1; }
[ "$message" = "$expected" ] || { echo "FAIL: '$message', expected '$expected'"; exit 1; }
echo "ok: $message"
