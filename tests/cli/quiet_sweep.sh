#!/usr/bin/env bash
# quiet_sweep.sh GRANPIPE WORKDIR
# --quiet is quiet: a sweep whose summary has points without an uncertainty (NaN) drew its
# report's plots with matplotlib's "converting a masked element to nan" on stderr.
set -euo pipefail
exe=$1 work=$2
rm -rf "$work"
mkdir -p "$work"
cat >"$work/sweep.json" <<'JSON'
{"name": "quiet", "seed": 3, "source": {"plugin": "lattice", "params": {"lattice": "fcc", "cells": [3, 3, 3]}},
 "analyzers": [{"plugin": "packing"}], "output": {"save_frames": false},
 "sweep": {"parameters": {"source.params.lattice": ["sc", "fcc"]}}}
JSON
"$exe" "$work/sweep.json" --out "$work/run" --threads 1 --quiet 2>"$work/stderr"
[ -f "$work/run/report.html" ] || { echo "FAIL: no report.html"; exit 1; }
[ ! -s "$work/stderr" ] || { echo "FAIL: --quiet printed:"; cat "$work/stderr"; exit 1; }
echo "a quiet sweep and its report printed nothing"
