#!/usr/bin/env bash
# spheres3d_tap's schedule and protocols: the last tap is saved whatever save_every (taps
# 12 in steps of 5 left taps 11 and 12 unsaved); a run that would save no frame, a
# parameter of the other protocol, and a ramp whose top lies between two steps (it turned
# below it) are refused.
set -euo pipefail
exe=$1 expect=$2 python=$3 work=$4
rm -rf "$work" && mkdir -p "$work"
pipeline=$work/tap3d.json
cat >"$pipeline" <<'JSON'
{"name": "tap3d_protocol", "seed": 5,
 "source": {"plugin": "spheres3d_tap", "params": {"N": 40, "side": 6, "sides": "walls"}},
 "analyzers": []}
JSON
"$exe" "$pipeline" --quiet --no-report --set source.params.taps=12 --set source.params.save_every=5 \
  --set source.params.log_frames=false --out "$work/last"
"$python" - "$work/last/frames.h5" <<'PY'
import sys, h5py
taps = list(h5py.File(sys.argv[1], "r")["observables/tap/value"][:])
assert taps == [0, 5, 10, 12], f"expected the taps 0, 5, 10 and the last, 12; found {taps}"
print("the last tap is saved")
PY
"$expect" 2 '^granpipe: --set source\.params\.save_start=false: expected true for a run of no tap \(taps 0\), got false: the run would save no frame$' \
  -- "$exe" validate "$pipeline" --set source.params.taps=0 --set source.params.save_start=false
"$expect" 2 '^granpipe: --set source\.params\.epsilon=0\.3: expected its default 0\.05 \(it acts only with protocol "constant"; here protocol is "ramp"\), got 0\.3$' \
  -- "$exe" validate "$pipeline" --set 'source.params.protocol="ramp"' --set source.params.epsilon=0.3
"$expect" 2 '^granpipe: --set source\.params\.ramp_taps_per_step=7: expected its default 4000 \(it acts only with protocol "ramp"; here protocol is "constant"\), got 7$' \
  -- "$exe" validate "$pipeline" --set source.params.ramp_taps_per_step=7
"$expect" 2 '^granpipe: --set source\.params\.ramp_root_max=0\.25: expected ramp_root_min \+ a whole number of ramp_root_step \(0\.1 \+ k 0\.1\), got 0\.25: the ramp would turn at 0\.2$' \
  -- "$exe" validate "$pipeline" --set 'source.params.protocol="ramp"' --set source.params.ramp_root_min=0.1 \
     --set source.params.ramp_root_step=0.1 --set source.params.ramp_root_max=0.25
# A ramp of 2^62 taps a step counted -2^63 taps in all and ran none, exit 0.
"$expect" 2 '^granpipe: --set source\.params\.ramp_taps_per_step=4611686018427387904: expected fewer than 9007199254740992 taps, got 2\.12138e\+20 \(ramp_taps_per_step x the values of sqrt\(epsilon\) over ramp_legs legs\)$' \
  -- "$exe" validate "$pipeline" --set 'source.params.protocol="ramp"' --set source.params.ramp_taps_per_step=4611686018427387904
# 2^53 + 1 taps is 2^53 in a double, and was let through.
"$expect" 2 '^granpipe: --set source\.params\.taps=9007199254740993: expected fewer than 9007199254740992 taps, got 9\.0072e\+15 \(taps\)$' \
  -- "$exe" validate "$pipeline" --set source.params.taps=9007199254740993
echo "spheres3d_tap: the last tap saved; empty schedules, other protocols' parameters, ramps between steps and uncountable ramps refused"
