#!/usr/bin/env bash
# threads_past_limit.sh GRANPIPE WORKDIR
# A sweep asked to run on more threads than the process's address-space limit lets it start
# (prlimit --as 1.5 GB, --threads 1024, 300 points) aborted (exit 134, "terminate called
# without an active exception") and left its folder marked running. It now runs its points
# on the threads it could start, with a warning; what the limit then leaves may still be too
# little for the run: exit 0, or exit 2 with one line and the folder marked failed.
set -eu
exe=$1 work=$2
rm -rf "$work"
mkdir -p "$work"
radii=$(seq -s, 0.30 0.001 0.599)
cat >"$work/sweep.json" <<JSON
{"name": "many_points", "source": {"plugin": "lattice", "params": {"lattice": "sc", "cells": [3, 3, 3]}},
 "analyzers": [{"plugin": "packing"}], "output": {"save_frames": false},
 "sweep": {"parameters": {"source.params.radius": [$radii]}}}
JSON
status=0
MALLOC_ARENA_MAX=2 prlimit --as=1500000000 "$exe" "$work/sweep.json" --out "$work/out" \
  --threads 1024 --quiet --no-report 2>"$work/stderr" || status=$?
case $status in
0) grep -q '"status":"complete"' "$work/out/.granpipe-run" || { echo "FAIL: exit 0, run not complete"; exit 1; } ;;
2) [ "$(wc -l <"$work/stderr")" -eq 1 ] || { echo "FAIL: exit 2 with more than one line: $(cat "$work/stderr")"; exit 1; }
   grep -q '"status":"failed"' "$work/out/.granpipe-run" || { echo "FAIL: exit 2, folder not marked failed"; exit 1; } ;;
*) echo "FAIL: exit $status: $(cat "$work/stderr")"; exit 1 ;;
esac
grep -Eq "^warning: --threads 1024: started [0-9]+ of 300 threads for the points" "$work/out/run.log" ||
  { echo "FAIL: no warning of the threads not started: $(cat "$work/out/run.log")"; exit 1; }
echo "300 points past the thread limit: exit $status, one line, the folder marked"
