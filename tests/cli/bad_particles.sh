#!/usr/bin/env bash
# bad_particles.sh GRANPIPE EXPECT PYTHON WORKDIR
# Another tool's H5MD files with overlapping and with NaN particles, reprocessed and
# inspected, and a saved frame with a contact partner out of range: exit 2 and one line
# naming the file, the frame and the particles (or the contact row).
set -eu
exe=$1 expect=$2 python=$3 work=$4
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"
mkdir -p "$work"
"$python" "$here/make_bad_particles.py" "$work"
for kind in overlapping nan nan_first; do
  cat >"$work/$kind.json" <<JSON
{"source": {"plugin": "h5md", "params": {"file": "$work/$kind.h5", "radius": 0.5}},
 "analyzers": [{"plugin": "packing"}], "output": {"dir": "$work/out_$kind"}}
JSON
done
"$expect" 2 "overlapping\.h5: frame 0: particles 0 and 1 \(ids 0, 1\) overlap by 1 of the smaller radius" \
  -- "$exe" "$work/overlapping.json"
"$expect" 2 "nan\.h5: frame 0: particle 1 \(id 1\): expected a finite position, got nan in coordinate x$" \
  -- "$exe" "$work/nan.json"
# Walls are placed from the particle centres: the NaN is still the frame check's to name.
"$expect" 2 "nan_first\.h5: frame 0: particle 0 \(id 0\): expected a finite position, got nan in coordinate x$" \
  -- "$exe" "$work/nan_first.json"
"$expect" 2 "^granpipe: $work/nan_first\.h5: frame 0: particle 0 \(id 0\): expected a finite position, got nan in coordinate x$" \
  -- "$exe" inspect "$work/nan_first.h5"
[ ! -e "$work/out_nan/results.h5" ] || { echo "FAIL: a refused run left results.h5"; exit 1; }
# A saved frame whose contact partner is out of range (j = -100, no wall's code): refused,
# not read as a wall contact.
cp "$here/../../data-samples/bnp_t10.h5" "$work/bad_partner.h5"
"$python" -c 'import h5py, sys; h5py.File(sys.argv[1], "r+")["granpipe/contacts/j"][5] = -100' \
  "$work/bad_partner.h5"
cat >"$work/bad_partner.json" <<JSON
{"source": {"plugin": "h5md", "params": {"file": "$work/bad_partner.h5", "max_overlap": 0.05}},
 "analyzers": [{"plugin": "packing"}], "output": {"dir": "$work/out_bad_partner"}}
JSON
"$expect" 2 "bad_partner\.h5: /granpipe/contacts/j: row 5 \(frame 0, contact 5\): expected a particle index in \[0, 7601\) other than i \([0-9]+\) or a wall code -2 \(x_low\) to -8 \(cylinder\), got -100$" \
  -- "$exe" "$work/bad_partner.json"
echo "overlapping and NaN particles refused"
