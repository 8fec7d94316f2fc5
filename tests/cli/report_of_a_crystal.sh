#!/usr/bin/env bash
# report_of_a_crystal.sh GRANPIPE WORKDIR
# report.html of a 3D crystal with an even number of layers along y: the side view's slab
# sat between two layers, held no centre, and the report ended in a traceback (the run
# exit 0 without report.html; `granpipe report` exit 1). The slab is through a layer now.
set -euo pipefail
exe=$1 work=$2
rm -rf "$work"
mkdir -p "$work"
cat >"$work/sc.json" <<'JSON'
{"name": "sc", "seed": 1,
 "source": {"plugin": "lattice", "params": {"lattice": "sc", "cells": [2, 2, 2], "boundary": "walls", "frames": 1}},
 "analyzers": [{"plugin": "packing"}],
 "output": {"dir": "out", "save_frames": true}}
JSON
"$exe" "$work/sc.json" --out "$work/out" --quiet 2>"$work/err"
if grep -q Traceback "$work/err"; then echo "FAIL: the report failed:"; cat "$work/err"; exit 1; fi
grep -q "side view of the slab" "$work/out/report.html" || { echo "FAIL: no side view in report.html"; exit 1; }
"$exe" report "$work/out" >/dev/null
echo "ok: report.html with the side view of a crystal of two layers"
