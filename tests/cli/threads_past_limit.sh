#!/usr/bin/env bash
# threads_past_limit.sh GRANPIPE WORKDIR
# Runs asked to use more threads than the process's address-space limit lets it start
# (prlimit --as 1.5 GB, --threads 1024) aborted: a sweep of 300 points with exit 134
# ("terminate called without an active exception"), one point whose analyzer runs OpenMP
# loops (pores) with exit 1 ("libgomp: Thread creation failed"), each leaving its folder
# marked running. The run now counts the threads it can start and uses half of them, with a
# warning; what the limit then leaves may still be too little for the run: exit 0, or exit 2
# with one line and the folder marked failed.
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
cat >"$work/openmp.json" <<JSON
{"name": "openmp", "source": {"plugin": "lattice", "params": {"lattice": "fcc", "cells": [4, 4, 4]}},
 "analyzers": [{"plugin": "pores", "params": {"probes": 0}}], "output": {"save_frames": false}}
JSON
for pipeline in sweep openmp; do
  out=$work/out_$pipeline
  status=0
  prlimit --as=1500000000 "$exe" "$work/$pipeline.json" --out "$out" --threads 1024 --quiet \
    --no-report 2>"$work/stderr" || status=$?
  case $status in
  0) grep -q '"status":"complete"' "$out/.granpipe-run" || { echo "FAIL: $pipeline: exit 0, run not complete"; exit 1; } ;;
  2) [ "$(wc -l <"$work/stderr")" -eq 1 ] || { echo "FAIL: $pipeline: exit 2 with more than one line: $(cat "$work/stderr")"; exit 1; }
     grep -q '"status":"failed"' "$out/.granpipe-run" || { echo "FAIL: $pipeline: exit 2, folder not marked failed"; exit 1; } ;;
  *) echo "FAIL: $pipeline: exit $status: $(cat "$work/stderr")"; exit 1 ;;
  esac
  grep -Eq "^warning: --threads 1024: this process could start only [0-9]+ threads at once" "$out/run.log" ||
    { echo "FAIL: $pipeline: no warning of the threads it could not start: $(cat "$out/run.log")"; exit 1; }
  echo "$pipeline past the thread limit: exit $status, one line, the folder marked"
done
