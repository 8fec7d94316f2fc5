#!/usr/bin/env bash
# spheres3d_tap continued from a saved frame: a run's last frame starts a second run,
# whose tap 0 is that packing to the bit; with continue_count its taps are counted on from
# the saved frame's (a run split over sessions keeps one tap axis); the same file with two
# spheres overlapping is refused naming the pair.
set -euo pipefail
exe=$1 expect=$2 python=$3 work=$4
rm -rf "$work" && mkdir -p "$work"
pipeline=$work/tap3d.json
cat >"$pipeline" <<'JSON'
{"name": "tap3d_saved_start", "seed": 5,
 "source": {"plugin": "spheres3d_tap", "params": {"N": 60, "side": 6, "taps": 2, "epsilon": 0.05}},
 "analyzers": [], "output": {"dir": "out/tap3d_saved_start"}}
JSON
small=(--quiet)
"$exe" "$pipeline" "${small[@]}" --out "$work/first"
"$exe" "$pipeline" "${small[@]}" --set source.params.initial_file="$work/first/frames.h5" \
  --out "$work/second"
"$python" - "$work/first/frames.h5" "$work/second/frames.h5" <<'PY'
import sys, h5py, numpy as np
first, second = (h5py.File(p, "r")["particles/all/position/value"] for p in sys.argv[1:])
assert np.array_equal(first[-1], second[0]), "tap 0 of the continued run is not the saved packing"
print("continued from the saved packing, bit for bit")
PY
"$exe" "$pipeline" --set source.params.initial_file="$work/first/frames.h5" \
  --set source.params.continue_count=true --set source.params.taps=6 --out "$work/continued" \
  2>"$work/continued.log"
# The progress counts the saved taps as done, so that its ETA is that of what is left.
grep -q "tap3d_saved_start: 6/6 taps (100.0%)" "$work/continued.log" ||
  { echo "continued progress does not end at 6/6 taps:"; cat "$work/continued.log"; exit 1; }
"$python" - "$work/first/frames.h5" "$work/continued/frames.h5" <<'PY'
import sys, h5py, numpy as np
first, later = (h5py.File(p, "r")["particles/all/position"] for p in sys.argv[1:])
steps = list(later["step"][:])
assert steps == [2, 3, 4, 6], f"expected the taps 2 (the saved one), 3, 4, 6 (the log schedule), found {steps}"
assert np.array_equal(first["value"][-1], later["value"][0]), "the start is not the saved packing"
assert not np.array_equal(later["value"][1], later["value"][0]), "tap 3 moved nothing"
# The start is the saved tap 2, with its epsilon (it was labelled a deposition's 0).
epsilon = h5py.File(sys.argv[2], "r")["observables/epsilon/value"][0]
assert epsilon == 0.05, f"the continued start's epsilon is {epsilon}, not tap 2's 0.05"
print("continued count: taps 2 to 6 on the log schedule")
PY
cp "$work/first/frames.h5" "$work/overlap.h5"
"$python" - "$work/overlap.h5" <<'PY'
import sys, h5py
with h5py.File(sys.argv[1], "r+") as f:
    x = f["particles/all/position/value"]
    last = x[-1]
    last[7] = last[3] + [0.5, 0.0, 0.0]
    x[-1] = last
PY
"$expect" 2 "source\\.params\\.initial_file(=[^ ]*)?: .*overlap\\.h5: frame [0-9]+: spheres [0-9]+ and [0-9]+ overlap \\(centres [0-9.e-]+ apart, expected at least 2R = 2\\)" \
  -- "$exe" "$pipeline" "${small[@]}" --set source.params.initial_file="$work/overlap.h5" --out "$work/third"
# A NaN centre is named as such (it was "reaches through the bottom or a wall").
cp "$work/first/frames.h5" "$work/nan.h5"
"$python" - "$work/nan.h5" <<'PY'
import sys, h5py
with h5py.File(sys.argv[1], "r+") as f:
    x = f["particles/all/position/value"]
    last = x[-1]
    last[3, 2] = float("nan")
    x[-1] = last
PY
"$expect" 2 "source\\.params\\.initial_file(=[^ ]*)?: .*nan\\.h5: frame [0-9]+: particle 3 \\(id 3\\): expected a finite position, got nan in coordinate z$" \
  -- "$exe" "$pipeline" "${small[@]}" --set source.params.initial_file="$work/nan.h5" --out "$work/nan_out"
# A sphere far above the packing rose with every dilation (the moves could not bring it
# down), and at 1e8 its height sized the search's grid (gigabytes, then a crash).
cp "$work/first/frames.h5" "$work/far.h5"
"$python" - "$work/far.h5" <<'PY'
import sys, h5py
with h5py.File(sys.argv[1], "r+") as f:
    x = f["particles/all/position/value"]
    last = x[-1]
    last[5, 2] = 1e8
    x[-1] = last
PY
"$expect" 2 "source\\.params\\.initial_file(=[^ ]*)?: .*far\\.h5: frame [0-9]+: sphere 5 at z = 100000000: expected a packing at rest on the bottom, no centre higher than a column of all 60 spheres, \\(2N - 1\\) R = 119$" \
  -- "$exe" "$pipeline" "${small[@]}" --set source.params.initial_file="$work/far.h5" --out "$work/far_out"
# The whole packing lifted 50 R off the bottom was read as a saved packing (its tap 0 of no
# density near the bottom, exit 0).
cp "$work/first/frames.h5" "$work/lifted.h5"
"$python" - "$work/lifted.h5" <<'PY'
import sys, h5py
with h5py.File(sys.argv[1], "r+") as f:
    x = f["particles/all/position/value"]
    last = x[-1]
    last[:, 2] += 50.0
    x[-1] = last
PY
"$expect" 2 "source\\.params\\.initial_file(=[^ ]*)?: .*lifted\\.h5: frame [0-9]+: sphere [0-9]+ at z = [0-9.]+, the lowest: expected a packing at rest on the bottom, its lowest centre within a diameter of R = 1 \\(the bottom's contact\\), got a gap of [0-9.]+ R under every sphere$" \
  -- "$exe" "$pipeline" "${small[@]}" --set source.params.initial_file="$work/lifted.h5" --out "$work/lifted_out"
# initial_frame or continue_count without initial_file would change nothing: refused.
"$expect" 2 "source\\.params\\.initial_frame=1: expected it only with initial_file \\(a frame of that file\\), got 1 without one$" \
  -- "$exe" "$pipeline" "${small[@]}" --set source.params.initial_frame=1 --out "$work/fourth"
"$expect" 2 "source\\.params\\.continue_count=true: expected it only with initial_file \\(counting on from a saved frame's tap\\), got true without one$" \
  -- "$exe" "$pipeline" "${small[@]}" --set source.params.continue_count=true --out "$work/fifth"
# continue_count from the last tap or beyond it would run no tap (exit 0 before).
"$expect" 2 "source\\.params\\.initial_file(=[^ ]*)?: .*first/frames\\.h5: frame 2: expected a saved tap from 0 to 1 for continue_count \\(the run counts to tap 2\\), got tap 2$" \
  -- "$exe" "$pipeline" "${small[@]}" --set source.params.initial_file="$work/first/frames.h5" \
  --set source.params.continue_count=true --out "$work/sixth"
# continue_count with another epsilon labelled the saved packing (made at 0.05) with 0.3, and
# parts read as one joined two protocols into one series (exit 0): refused.
"$expect" 2 "source\\.params\\.initial_file(=[^ ]*)?: .*first/frames\\.h5: frame 1: expected the tap continued to have been made by this run's protocol \\(epsilon 0\\.3, leg -1 at tap 1\\), got epsilon 0\\.05, leg -1 \\(continue_count continues a run: give it the parameters it ran with\\)$" \
  -- "$exe" "$pipeline" "${small[@]}" --set source.params.initial_file="$work/first/frames.h5" \
  --set source.params.initial_frame=1 --set source.params.continue_count=true \
  --set source.params.taps=4 --set source.params.epsilon=0.3 --out "$work/other_epsilon"
# A continued part's start frame of an older granpipe, labelled as a deposition (epsilon 0,
# leg -1) at its saved tap, is continued (the chains kept in docs/data/ hold such frames).
cp "$work/first/frames.h5" "$work/old_label.h5"
"$python" - "$work/old_label.h5" <<'PY'
import sys, h5py
with h5py.File(sys.argv[1], "r+") as f:
    f["observables/epsilon/value"][1] = 0.0
    f["observables/leg/value"][1] = -1
PY
"$exe" validate "$pipeline" --set source.params.initial_file="$work/old_label.h5" \
  --set source.params.initial_frame=1 --set source.params.continue_count=true --set source.params.taps=4 >/dev/null
# A frame without a tap (another tool's), or whose step is not its tap, gives no tap to count on
# from; a file that is not HDF5 is refused naming the parameter.
cp "$work/first/frames.h5" "$work/no_tap.h5"
cp "$work/first/frames.h5" "$work/shifted.h5"
"$python" - "$work/no_tap.h5" "$work/shifted.h5" <<'PY'
import sys, h5py
with h5py.File(sys.argv[1], "r+") as f:
    del f["observables/tap"]
    listed = f["granpipe"].attrs["observables"]  # the file lists what it holds
    f["granpipe"].attrs["observables"] = [o for o in listed if o != b"tap"]
with h5py.File(sys.argv[2], "r+") as f:
    step = f["particles/all/position/step"]
    step[...] = step[()] - 10
PY
"$expect" 2 "source\\.params\\.initial_file(=[^ ]*)?: .*no_tap\\.h5: frame 2: expected a frame with a tap observable \\(a frames\\.h5 of spheres3d_tap\\) for continue_count to count on from, got none \\(step 2\\)$" \
  -- "$exe" "$pipeline" "${small[@]}" --set source.params.initial_file="$work/no_tap.h5" \
  --set source.params.continue_count=true --set source.params.taps=6 --out "$work/seventh"
"$expect" 2 "source\\.params\\.initial_file(=[^ ]*)?: .*shifted\\.h5: frame 2: expected the step equal to the tap for continue_count, got tap 2 at step -8$" \
  -- "$exe" "$pipeline" "${small[@]}" --set source.params.initial_file="$work/shifted.h5" \
  --set source.params.continue_count=true --set source.params.taps=6 --out "$work/eighth"
echo "not a packing" >"$work/packing.txt"
"$expect" 2 "source\\.params\\.initial_file(=[^ ]*)?: .*packing\\.txt: not an HDF5 file \\(no HDF5 signature\\)$" \
  -- "$exe" "$pipeline" "${small[@]}" --set source.params.initial_file="$work/packing.txt" --out "$work/ninth"
# The saved packing is read when the source is made: `validate` refuses it too.
"$expect" 2 "source\\.params\\.initial_file(=[^ ]*)?: .*first/frames\\.h5: frame 2: expected a saved tap from 0 to 1 for continue_count \\(the run counts to tap 2\\), got tap 2$" \
  -- "$exe" validate "$pipeline" --set source.params.initial_file="$work/first/frames.h5" \
  --set source.params.continue_count=true
# A frame the file does not hold is refused naming initial_frame.
"$expect" 2 "source\\.params\\.initial_frame(=[^ ]*)?: expected -1 or a frame index below 3 \\(.*first/frames\\.h5 holds 3 frames\\), got 3$" \
  -- "$exe" validate "$pipeline" --set source.params.initial_file="$work/first/frames.h5" \
  --set source.params.initial_frame=3
# A frames file without frames (its writer killed before the first) is refused naming
# initial_file.
cp "$work/first/frames.h5" "$work/no_frames.h5"
"$python" - "$work/no_frames.h5" <<'PY'
import sys, h5py
with h5py.File(sys.argv[1], "r+") as f:
    groups = [f["particles/all"][n] for n in f["particles/all"] if n != "box"]
    groups += [f["observables"][n] for n in f["observables"]]
    for g in groups:
        for k in [k for k in g if k in ("value", "step", "time")]:
            shape, dtype = g[k].shape[1:], g[k].dtype
            del g[k]
            g.create_dataset(k, shape=(0,) + shape, dtype=dtype, maxshape=(None,) + shape)
    f["granpipe"].attrs["complete"] = 0  # as its killed writer left it
PY
"$expect" 2 "source\\.params\\.initial_file(=[^ ]*)?: .*no_frames\\.h5: expected a file with frames, got none$" \
  -- "$exe" validate "$pipeline" --set source.params.initial_file="$work/no_frames.h5"
