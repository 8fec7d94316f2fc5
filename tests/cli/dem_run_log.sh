#!/usr/bin/env bash
# dem_run_log.sh GRANPIPE SOURCE_DIR WORKDIR
# Warnings always reach run.log: the dem source's dt warning, issued while the pipeline is
# checked (before run.log exists), is written there with --quiet too, and without --quiet
# it reaches the terminal once. run.log also says which instruction set the force loops
# ran with (the speeds of docs/benchmarks.md depend on it).
set -euo pipefail
exe=$1 src=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
pipeline=$src/pipelines/dem_speed_vs_error.json
# dt = 3.3e-4 is t_c/15 for the collision's spheres: warned (above t_c/20), not refused.
warning='^warning: source\.params\.dt: dem: dt = 0\.00033 is t_c/15\.[0-9]+ for the shortest contact \(species 0 and species 0, t_c = 0\.00497[0-9]*\): above t_c/20, the contact time and restitution lose accuracy$'
kernels='^dem: force loops for (AVX-512|AVX2|baseline), 2 particles, 1 thread\(s\)$'

"$exe" "$pipeline" --quiet --threads 1 --set source.params.dt=3.3e-4 --out "$work/quiet" 2>"$work/quiet.stderr"
[ ! -s "$work/quiet.stderr" ] || fail "--quiet wrote to stderr: $(cat "$work/quiet.stderr")"
grep -Eq "$warning" "$work/quiet/run.log" || fail "the dt warning is not in run.log: $(cat "$work/quiet/run.log")"
grep -Eq "$kernels" "$work/quiet/run.log" || fail "run.log does not say which kernels ran: $(cat "$work/quiet/run.log")"

"$exe" "$pipeline" --threads 1 --set source.params.dt=3.3e-4 --out "$work/loud" 2>"$work/loud.stderr"
[ "$(grep -Ec "$warning" "$work/loud.stderr")" = 1 ] || fail "expected the dt warning once on stderr: $(cat "$work/loud.stderr")"
[ "$(grep -Ec "$warning" "$work/loud/run.log")" = 1 ] || fail "expected the dt warning once in run.log: $(cat "$work/loud/run.log")"
echo "the dt warning reached run.log with and without --quiet"
